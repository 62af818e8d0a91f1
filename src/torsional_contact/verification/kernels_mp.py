r"""The xi-integrals of the Abel-Fredholm method in arbitrary precision.

Units (as in ``kernels``): lengths in a, tractions in f p0, displacements in f p0 a / mu.
Everything is computed with python-flint ``arb`` numbers at flint's working precision
(set it with ``arbitrary_precision.working_digits``); the same code runs at any precision.

Integrals
---------
With the Bessel ratio rho(xi) = K2(xi)/I2(xi), A(x) = sinh(x) - x and
F(x) = int_0^x y I1(y) dy (eq. A3 of ``kernels``), the kernel (A2), the load transform
(A3) and the torque constant are

    P(t, s) = (2/pi) int_0^inf [A(xi t) A(xi s) + A(xi t) xi s + xi t A(xi s)] rho dxi,   (M1)
    E_c(t)  = (2/pi) int_0^inf [A(xi t) F(c xi) + xi t (F(c xi) - (c xi)^3/6)] rho / xi^2 dxi,   (M2)
    BETA    = 1/2 + (1/pi) int_0^inf rho(xi) [I2(xi) - xi^2/8] dxi                 (M3)

(every bracket is a sum of positive terms: no cancellation at small xi; (M3) is
``kernels.TORQUE_ROTATION`` = 1/2 + (1/pi) int K2 [1 - xi^2/(8 I2)] dxi written
without cancellation).

Quadrature in xi
----------------
rho(xi) = K2/I2 = (an even Laurent series, 16/xi^4 + ...) - ln(xi/2) (DLMF 10.31.1), so
the integrands are analytic on (0, inf) with an xi^4 ln(xi) end-point singularity.
``xi_quadrature``: the first panel [0, 1/4] is mapped by xi = u^q / 4 with q = 4 up to
48 working digits, ceil(d/12) above (the singular part becomes u^(5q-1) ln u), then
Gauss-Legendre panels [1/4, 1/2], [1/2, 1], ... doubling
until their width reaches 16 / rate (rounded to 16 significant bits: the edges are exact sums
and the capped panels share their node offsets, ``XiQuadrature.blocks``), then panels of that width, up to
(d ln 10 + 12) / rate, where rate is the slowest exponential decay of the integrands
(2 - t - s for (M1), 2 - t - c for (M2), 1 for (M3)) and d the working digits.  The
nodes per panel grow linearly with d (``panel_nodes``).

E_1(t) up to t = 1
------------------
E_1 decays only like exp(-(1 - t) xi) xi^(-3/2): it is integrated numerically up to a
panel edge X >= d ln 10 + 12 and the rest in closed form,

    (2/pi) int_X^inf ... dxi = (2 pi)^(-1/2) sum_k c_k [J_k(1 - t) - J_k(1 + t)],
    J_k(eps) = int_X^inf exp(-eps xi) xi^(-k-3/2) dxi = eps^(k+1/2) Gamma(-k-1/2, eps X),   (M4)

where pi sum_k c_k xi^(-k) is the large-xi expansion of exp(-xi) F(xi) exp(2 xi) rho(xi)
sqrt(2 pi xi) / xi (products of the expansions of I0, int I0, K2 and I2, exact rationals;
``special_mp``), accurate to exp(-X) relative beyond X >= prec ln 2 + 12.  J_k follows
from one incomplete gamma function and the recurrence
J_k = [exp(-eps X) X^(-k-1/2) - eps J_(k-1)] / (k + 1/2), run upward above
k = eps X and downward below (the stable directions).  This gives E_1(t) for every
0 <= t <= 1, including its (1 - t)^(k+1/2) terms.
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

import flint
import numpy as np

from ..diagnostics import AccuracyWarning
from .arbitrary_precision import gauss_legendre, precision_bits
from .special_mp import (
    EXTRA_DECAYS,
    asymptotic_threshold,
    bessel_ratio,
    expansion_terms,
    i2_excess,
    integral_x_i1_pair,
    sinh_excess,
    sinh_excess_matrix,
    tail_coefficients,
    tail_integrals,
)

__all__ = [
    "FIRST_PANEL",
    "WIDTH_DECAYS",
    "XiQuadrature",
    "panel_nodes",
    "xi_quadrature",
    "load_profiles",
    "spinning_tail",
    "torque_rotation",
    "abel_kernel",
    "load_transform",
    "xi_layer",
    "xi_sum_truncation",
    "TRUNCATION_GUARD_BITS",
]

#: Length of the first xi-panel, on which xi = FIRST_PANEL * u^q (``first_panel_power``).
FIRST_PANEL = 0.25
#: Panels stop doubling at a width of WIDTH_DECAYS / rate (exp(-rate xi) varies by e^16).
WIDTH_DECAYS = 16.0


def first_panel_power(digits: int) -> int:
    """q of the first panel's map xi = FIRST_PANEL u^q: the xi^4 ln(xi) end-point term
    becomes u^(5q - 1) ln u, whose Gauss-Legendre error falls like m^-(10 q); q = 4 held
    the torque constant to 1e-61 at 120 digits, q = ceil(d / 12) to 1e-118 (measured)."""
    return max(4, math.ceil(digits / 12))


def first_panel_nodes(digits: int) -> int:
    """Gauss-Legendre nodes in u on the first panel: the poles of K2/I2 at xi = i j_(2,k)
    come to u = (4 j_(2,1))^(1/q) exp(i pi/(2q)) ~ 1.3 for q ~ 10, slower than the other
    panels (measured: d + 10 nodes reach 1e-118 at 120 digits, 0.75 d + 10 only 1e-91)."""
    return digits + 10


def panel_nodes(digits: int) -> int:
    """Gauss-Legendre nodes per xi-panel for ``digits`` working digits.

    A panel [L, 2L] sees the end-point singularity at xi = 0 at the Bernstein parameter
    3 + sqrt(8), i.e. 2 ln(5.83) = 3.5 e-folds per node; the count below leaves a margin
    (checked by the convergence tests in ``tests/test_reference_abel_fredholm.py``).
    """
    return math.ceil(0.75 * digits) + 10


@dataclass(frozen=True)
class XiQuadrature:
    """Nodes and weights for int_0^inf d xi (see the module docstring).

    Attributes
    ----------
    nodes, weights : tuple of arb
    asymptotic_start : float
        X, a panel edge (exact binary number): nodes[:n_below] lie below X.
    n_below : int
    decay_rate : float
        Slowest exponential decay rate the quadrature resolves.
    digits : int
        Working digits the quadrature was built for.
    blocks : tuple of (int, tuple of arb, tuple of arb)
        Runs of at least ``MIN_BLOCK_PANELS`` panels of equal width (the capped ones): (index of
        their first node, the panels' midpoints c_p, the offsets d_j), their nodes being exactly
        c_p + d_j in that order (``sinh_excess_mp.sinh_excess_matrix`` factors exp(xi t) over them).
    """

    nodes: tuple
    weights: tuple
    asymptotic_start: float
    n_below: int
    decay_rate: float
    digits: int
    blocks: tuple = ()


#: Fewest panels of equal width that ``XiQuadrature.blocks`` lists (fewer gain nothing by factoring).
MIN_BLOCK_PANELS = 3


def _panel_edges(decay_rate: float, digits: int, first_panel: float, width_decays: float):
    end = (digits * math.log(10.0) + EXTRA_DECAYS) / decay_rate
    x_needed = asymptotic_threshold(precision_bits(digits))
    mantissa, exponent = math.frexp(width_decays / decay_rate)  # 16 significant bits: the edges stay exact
    width_cap = math.ldexp(round(math.ldexp(mantissa, 16)), exponent - 16)  # sums, the capped widths equal
    edges = [0.0, first_panel]
    while edges[-1] < max(end, x_needed):
        width = edges[-1] if edges[-1] < width_cap else width_cap
        edges.append(edges[-1] + width)
    start = next(e for e in edges if e >= x_needed)
    return edges, start


def xi_quadrature(
    decay_rate: float, digits: int, first_panel: float = FIRST_PANEL, width_decays: float = WIDTH_DECAYS
) -> XiQuadrature:
    """Composite Gauss-Legendre quadrature on [0, inf) for the xi-integrals (M1)-(M4).

    Parameters
    ----------
    decay_rate : float
        Slowest exponential decay of the integrands, > 0 (e.g. 1 - b).
    digits : int
        Working decimal digits (also flint's working precision when called).
    first_panel, width_decays : float
        Length of the mapped first panel and the cap on the panel width (in units of
        1/rate); varied by the error estimate of ``abel_fredholm_mp`` so that its two
        solves share no panel edges.  All edges are exact binary numbers.
    """
    if not decay_rate > 0.0:
        raise ValueError(f"decay_rate must be > 0, got {decay_rate!r}")
    edges, start = _panel_edges(float(decay_rate), int(digits), float(first_panel), float(width_decays))
    x, w = gauss_legendre(panel_nodes(digits))
    nodes, weights = [], []
    first = flint.arb(float(first_panel))
    power = first_panel_power(digits)
    for xj, wj in zip(*gauss_legendre(first_panel_nodes(digits)), strict=True):  # xi = first u^power
        u = (xj + 1) / 2
        nodes.append(first * u**power)
        weights.append(first * power * u ** (power - 1) * wj / 2)
    nodes = [v.mid() for v in nodes]  # exact binary nodes: functions of them stay sharp
    runs = []  # [width, index of the first node, midpoints, offsets] of panels of equal width
    prec = flint.ctx.prec
    for lo, hi in zip(edges[1:-1], edges[2:], strict=True):
        lo_exact, hi_exact = flint.arb(lo), flint.arb(hi)  # exact: no float rounding of hi + lo
        half, mid = (hi_exact - lo_exact) / 2, (hi_exact + lo_exact) / 2
        offsets = [(half * xj).mid() for xj in x]
        flint.ctx.prec = prec + 64  # c + d exactly (no rounding: the nodes are c_p + d_j, shared d_j)
        nodes.extend(mid + d for d in offsets)
        flint.ctx.prec = prec
        weights.extend(half * wj for wj in w)
        if runs and runs[-1][0] == hi - lo:
            runs[-1][2].append(mid)
        else:
            runs.append([hi - lo, len(nodes) - len(x), [mid], offsets])
    blocks = tuple((first_index, tuple(mids), tuple(offsets)) for _, first_index, mids, offsets in runs
                   if len(mids) >= MIN_BLOCK_PANELS)
    n_first = first_panel_nodes(digits)
    n_below = n_first + sum(1 for e_lo in edges[1:-1] if e_lo < start) * len(x)  # nodes below X
    return XiQuadrature(tuple(nodes), tuple(weights), start, n_below, float(decay_rate), int(digits), blocks)


# --------------------------------------------------------------------------- (M1)-(M4)


def spinning_tail(t, start: float, far=True):
    """(2/pi) int_X^inf [sinh(xi t) F(xi)/xi^2 - xi^2 t/6] rho d xi for 0 <= t <= 1, eq. (M4).

    ``start`` = X >= ``asymptotic_threshold()`` (a panel edge of the xi-quadrature).
    The neglected part (the xi^2 t/6 term and the exponentially small corrections of the
    expansions) is below exp(-2 X) X^2 t.  The J_k(1 + t) terms (the exp(-xi t) half of sinh)
    are below (2 pi)^(-1/2) sum_k |c_k| X^(-k-1/2)/(k + 1/2) exp(-(1 + t) X) (J_k(eps) <=
    exp(-eps X) X^(-k-1/2)/(k + 1/2)), about (2 pi X)^(-1/2) 2 exp(-(1 + t) X) < exp(-X) <
    2^-prec e^-12 in all (c_0 = 1).  ``far=True`` (the solve) adds that bound to the ball's radius
    instead of computing them (half the cost; that bound is rigorous, its midpoint moves by less
    than e^-12 ulp; as before, the expansion's truncation and its exponentially small corrections,
    both below an ulp, are not in the radius); ``far="exact"`` computes them (the check of that
    bound); ``far=False`` leaves them out (the profiles, where the last bits need not be those of the solve).

    Warns
    -----
    AccuracyWarning
        If the expansion's terms at X do not fall below 2^-prec before they diverge.
    """
    if far not in (True, False, "exact"):
        raise ValueError(f"far must be True, False or 'exact', got {far!r}")
    if start < asymptotic_threshold() - 1e-9:
        raise ValueError(f"start must be >= {asymptotic_threshold():.1f} at this precision, got {start!r}")
    count, coefficients, last, far_sum = _tail_setup(float(start), flint.ctx.prec)
    if last > 2.0 ** (-flint.ctx.prec + 10):
        warnings.warn(f"the Hankel expansion of E_1 at xi = {start} stops at {last:.1e}", AccuracyWarning, stacklevel=2)
    near = tail_integrals(1 - t, start, count)
    total = flint.arb(0)
    if far == "exact":
        for c, jn, jf in zip(coefficients, near, tail_integrals(1 + t, start, count), strict=True):
            total += c * (jn - jf)
    else:
        for c, jn in zip(coefficients, near, strict=True):
            total += c * jn
        if far:
            total += flint.arb(0, (far_sum * (-(1 + t.lower()) * flint.arb(start)).exp()).upper())
    return total / (2 * flint.arb.pi()).sqrt()


@functools.lru_cache(maxsize=64)
def _tail_setup(start: float, prec: int) -> tuple:
    """(count, the c_k as arb at ``prec`` bits, the last term's size, an upper bound of
    sum_k |c_k| X^(-k-1/2)/(k + 1/2)) of ``spinning_tail`` at X = ``start`` (the same for every t: cached)."""
    count = expansion_terms(start)
    exact = tail_coefficients(count)
    x = flint.arb(start)
    last = float(abs(flint.arb(exact[-1])) * x ** (-count))
    half = flint.arb(1) / 2
    far_sum = sum((abs(flint.arb(c)) * x ** (-k - half) / (k + half) for k, c in enumerate(exact)), flint.arb(0))
    return count, tuple(flint.arb(c) for c in exact), last, far_sum.upper()


def load_profiles(c, xi):
    """The xi-profiles of E_c (M2): F(c xi) / xi^2 and (F(c xi) - (c xi)^3/6) / xi^2."""
    full, excess = [], []
    for x in xi:
        cx = c * x
        inverse = 1 / (x * x)
        value, value_excess = integral_x_i1_pair(cx)  # F and F - x^3/6 together (overlapping the separate series)
        full.append(value * inverse)
        excess.append(value_excess * inverse)
    return full, excess


@functools.lru_cache(maxsize=16)
def _torque_rotation_cached(prec: int, digits: int):
    quadrature = xi_quadrature(1.0, digits)
    ratio = _per_node("ratio", bessel_ratio, quadrature.nodes)  # its first panels are those of the solves
    total = flint.arb(0)
    for x, w, r in zip(quadrature.nodes, quadrature.weights, ratio, strict=True):
        total += w * r * i2_excess(x)
    return flint.arb(1) / 2 + total / flint.arb.pi()


def torque_rotation(digits: int):
    """BETA (``kernels.TORQUE_ROTATION``) by (M3) at flint's working precision (cached).

    ``digits``: the working digits flint is set to (they fix the quadrature).
    """
    return _torque_rotation_cached(flint.ctx.prec, int(digits))


def abel_kernel(t_points, s_points, quadrature: XiQuadrature) -> flint.arb_mat:
    """P(t_i, s_j) of (M1) as an ``arb_mat``; the quadrature's rate <= 2 - max t - max s."""
    xi, w = quadrature.nodes, quadrature.weights
    scale = [wk * rk for wk, rk in zip(w, bessel_ratio(xi), strict=True)]
    a_t = sinh_excess_matrix(t_points, xi)
    a_s = sinh_excess_matrix(s_points, xi)
    weighted_s = flint.arb_mat(len(xi), len(s_points), [scale[k] * a_s[j, k] for k in range(len(xi))
                                                        for j in range(len(s_points))])
    product = a_t * weighted_s
    moment_t = a_t * flint.arb_mat(len(xi), 1, [scale[k] * xi[k] for k in range(len(xi))])
    moment_s = flint.arb_mat(1, len(xi), list(xi)) * weighted_s
    two_over_pi = 2 / flint.arb.pi()
    out = flint.arb_mat(len(t_points), len(s_points))
    for i, t in enumerate(t_points):
        for j, s in enumerate(s_points):
            out[i, j] = two_over_pi * (product[i, j] + moment_t[i, 0] * s + t * moment_s[0, j])
    return out


def load_transform(t_points, c, quadrature: XiQuadrature):
    """E_c(t) of (M2) for 0 < c <= 1, with the closed-form tail (M4) when c = 1.

    The quadrature's rate must be <= 2 - max t - c for c < 1, and any rate for c = 1
    (then only the nodes below X are used).
    """
    xi, w = quadrature.nodes, quadrature.weights
    if float(c) == 1.0:
        xi, w = xi[: quadrature.n_below], w[: quadrature.n_below]
    full, excess = load_profiles(c, xi)
    ratio = bessel_ratio(xi)
    two_over_pi = 2 / flint.arb.pi()
    out = []
    for t in t_points:
        total = flint.arb(0)
        for x, wk, rk, f, e in zip(xi, w, ratio, full, excess, strict=True):
            total += wk * rk * (sinh_excess(x * t) * f + x * t * e)
        value = two_over_pi * total
        if float(c) == 1.0:
            value += spinning_tail(t, quadrature.asymptotic_start)
        out.append(value)
    return out


# --------------------------------------------------------------------------- shared by the solves


#: Per-node xi-functions (rho = K2/I2 and the c = 1 load profiles), keyed by precision and node:
#: the xi-quadratures of different stick radii share their first panels.
_NODE_CACHE: dict = {}
_NODE_CACHE_LIMIT = 200_000


def _per_node(kind: str, function, xi) -> list:
    """``function(nodes)`` (elementwise, deterministic) for the nodes ``xi``, computed once per node and precision."""
    if len(_NODE_CACHE) > _NODE_CACHE_LIMIT:
        _NODE_CACHE.clear()
    prec = flint.ctx.prec
    keys = [(kind, prec, *(int(v) for v in x.man_exp())) for x in xi]
    missing = [k for k, key in enumerate(keys) if key not in _NODE_CACHE]
    if missing:
        for k, value in zip(missing, function([xi[k] for k in missing]), strict=True):
            _NODE_CACHE[keys[k]] = value
    return [_NODE_CACHE[key] for key in keys]


@dataclass(frozen=True)
class _XiLayer:
    """What a solve needs of the xi-quadrature, independent of the Nystrom nodes (``xi_layer``)."""

    xi: tuple
    scale: tuple
    side_full: tuple
    side_excess: tuple
    tail_start: float
    blocks: tuple = ()


@functools.lru_cache(maxsize=8)
def _xi_layer_cached(b_key, prec: int, work_digits: int, first_panel: float, width_decays: float) -> _XiLayer:
    b = flint.arb(b_key)
    quadrature = xi_quadrature(float(1 - b), work_digits, first_panel, width_decays)
    xi = quadrature.nodes
    scale = [w * r for w, r in zip(quadrature.weights, _per_node("ratio", bessel_ratio, xi), strict=True)]
    below = quadrature.n_below
    profiles_1 = _per_node("load_1", lambda nodes: list(zip(*load_profiles(flint.arb(1), nodes), strict=True)),
                           xi[:below])
    full_1, excess_1 = [f for f, _ in profiles_1], [e for _, e in profiles_1]
    full_b, excess_b = load_profiles(b, xi)
    zero = flint.arb(0)
    side_full = [(full_1[k] if k < below else zero) - full_b[k] for k in range(len(xi))]
    side_excess = [(excess_1[k] if k < below else zero) - excess_b[k] for k in range(len(xi))]
    return _XiLayer(tuple(xi), tuple(scale), tuple(side_full), tuple(side_excess), quadrature.asymptotic_start,
                    quadrature.blocks)


def xi_layer(b, work_digits: int, first_panel: float, width_decays: float) -> _XiLayer:
    """xi-nodes, weights times K2/I2, and the load profiles F(xi)/xi^2 - F(b xi)/xi^2 (and the
    excess forms) of one (b, working precision, layout): shared by the solves of a node sweep."""
    man, exp = b.mid().man_exp()
    return _xi_layer_cached((int(man), int(exp)), flint.ctx.prec, int(work_digits), float(first_panel),
                            float(width_decays))


#: Rows of xi-sums stop where their rest is below t 2^-(prec + TRUNCATION_GUARD_BITS) (``xi_sum_truncation``).
TRUNCATION_GUARD_BITS = 8


def xi_sum_truncation(t_points, xi, coefficients) -> tuple:
    """Where the sums S(t) = sum_k A(xi_k t) c_k of rows 0 < t <= T may stop, and rigorous bounds on the rest.

    The coefficients c_k of the Nystrom interpolant decay like exp(-(2 - b) xi) (its xi-profiles
    carry K2/I2 ~ pi exp(-2 xi)), so a row t needs xi only up to about (prec ln 2)/(2 - b - t),
    not to the end of the quadrature, which the slowest rate 1 - b (E_1 at t = 1) sets.  With
    A(x) = sinh x - x <= exp(x)/2 (x >= 0) and xi ascending, for every K

        |sum_(k >= K) A(xi_k t) c_k| <= exp(-xi_K (T - t)) Q_K,   Q_K = sum_(k >= K) |c_k| exp(xi_k T)/2,

    T = max t.  Per row: the smallest K whose bound (floats, from the logarithms of Q_K) is below
    t 2^-(prec + TRUNCATION_GUARD_BITS), then the bound at that K in ball arithmetic (an upper bound at
    64 bits).  Returns (lengths, rests): K per row and the bound (arb) or None where K = len(xi).
    """
    n_xi = len(xi)
    xi_float = np.array([float(x) for x in xi])
    if n_xi == 0 or np.any(np.diff(xi_float) < 0):
        raise ValueError("xi must be a non-empty ascending sequence")
    prec = flint.ctx.prec
    flint.ctx.prec = 64
    try:
        top = max(t.upper() for t in t_points)  # T >= every t (rigorous)
        suffix = [flint.arb(0)] * (n_xi + 1)
        for k in range(n_xi - 1, -1, -1):
            suffix[k] = suffix[k + 1] + coefficients[k].abs_upper() * (xi[k] * top).exp() / 2
        log_suffix = np.array([float(q.log().upper()) if q > 0 else -math.inf for q in suffix[:n_xi]])
        lengths, rests = [], []
        for t in t_points:
            gap = float((top - t).lower())  # T - t >= gap >= 0
            target = math.log(float(t.lower())) - (prec + TRUNCATION_GUARD_BITS) * math.log(2.0)
            below = np.nonzero(log_suffix - xi_float * max(gap, 0.0) <= target)[0]
            if len(below) == 0:
                lengths.append(n_xi)
                rests.append(None)
                continue
            k = int(below[0])
            lengths.append(k)
            rests.append(suffix[k] * (-xi[k] * (top - t).nonnegative_part()).exp())
    finally:
        flint.ctx.prec = prec
    return lengths, rests
