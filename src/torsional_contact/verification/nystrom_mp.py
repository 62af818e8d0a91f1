r"""Nystrom solution of the Abel-Fredholm equation in arbitrary precision (one solve).

Units (docs/conventions.md): r, t in a; tractions in f p0; slip in f p0 a / mu; omega in
f p0 / mu; T* = 2T/(f F a) (eq. 32).

The reduction of ``fast`` (equations (F1)-(F7) of its docstring), evaluated with
python-flint ``arb`` numbers at any precision: the Fredholm equation (F2) on the stick disc,

    g(t) + (2/(pi t)) int_0^b s g(s) P(t, s) ds = 2 Omega - L(t) - R(t)/t,   R = E_1 - E_b,

the regularity condition g(b) = 0 (F3), the torque identity (F4), omega = Omega - BETA T*
(F5), the traction (F6) and the slip (F7).  The xi-integrals P, E_c, BETA and the
closed-form tail of E_1 are those of ``kernels_mp`` (M1)-(M4), computed at the working
precision (no double-precision tables).

Discretisation
--------------
Nystrom with Gauss-Legendre in theta, t = b cos(theta) on (0, pi/2), as in ``fast``: the
error decays like rho^(-2n), rho the Bernstein parameter of the image singularity
theta = i arccosh((2 - b)/b) of P; ``nodes_for_digits`` scales ``fast.default_nodes``
from 17 to the requested digits (measured: conservative by 5-10 digits).  The Nystrom
interpolant bracket(t) = R(t) + (2/pi) int_0^b s g(s) P(t, s) ds is kept as two xi-profiles,
so that each new t costs one row of A(xi t).  G = g + L = 2 Omega - bracket(t)/t is
expanded in Chebyshev polynomials of x = 2 t^2/b^2 - 1 for (F6) (``chebyshev_points``:
G branches at t = 1 with L and E_1, x = 2/b^2 - 1).  (F7) is integrated over v,
psi = arccos(t) = psi_r + v^2 (which removes the inverse square root at t = r), on panels
graded geometrically toward v = 0 (scale sqrt(2 psi_r), the zero of sin(psi + psi_r)) and
toward t = b (scale set by the log singularity of D at t = 0, which matters for small b).

Profiles at the cost of a few hundred rows
------------------------------------------
The slip quadrature needs D(t) = 2 Omega t - t arcsech(t) - bracket(t) at thousands of t
in [b, 1] (about 250 per radius for small b).  Only the bracket is expensive, and it is
analytic in u = sqrt(1 - t): the xi-integrals of P and E_b converge for Re t < 2 - b, and
E_1 (nodes below X and the closed-form tail (M4)) is analytic plus sqrt(1 - t) times
analytic.  So H(u) = bracket(1 - u^2)/(1 - u^2) is expanded once per solve in Chebyshev
polynomials on the slip annulus, u in [0, sqrt(1 - b)] (``interface_points``: from the
nearest singularity, u = +-i sqrt(1 - b) or sqrt 2; the last coefficients must reach the
rounding floor, else the count is doubled), the arcsech term is added exactly, and the series
is summed at all nodes at once (``_chebyshev_values``: the monomial form in C at extra
precision).  Measured against direct rows at 41-54 working digits, b = 0.02 to 0.98: the
series agrees to the direct evaluation's own rounding (about 10^3 ulp).  G for (F6) stays
sampled by rows (``chebyshev_points`` of them), its transform consistent with the rounded
nodes because (F6) differentiates it.  Rows of A(xi t) for the profiles use
``sinh_excess_matrix(method="cancel")``, each row stopped where the rest of its xi-sum is below
t 2^-(prec + 8) with a rigorous bound on that rest added to the ball (``kernels_mp.xi_sum_truncation``: a row
t needs xi up to about prec ln 2 / (2 - b - t), the quadrature runs to prec ln 2 / (1 - b)), and
the tail without its exp(-X)-small half; the
solve keeps full rows and that half of the tail as a rigorous bound in the ball's radius (the
Hankel expansion's own truncation and exponentially small corrections, below an ulp, are not in
it), and its rows' entries are rigorous balls
(``sinh_excess_matrix(method="sharp")``: Arb's sinh at raised precision on exact products; the
Nystrom nodes t_j are rounded to their midpoints, exact binary numbers like the xi-nodes, so that
the products are exact and the balls as tight as the Taylor series' was, at a fraction of its
cost where xi t < 1/2, i.e. at small b; over runs of equal xi-panels exp(xi t) is factored,
``kernels_mp.XiQuadrature.blocks``).  The
per-node xi-functions and the xi-layer of a (b, precision, layout) are cached (``kernels_mp.xi_layer``):
node sweeps and several radii in one process share them.
"""

from __future__ import annotations

import cmath
import math
import time
import warnings
from dataclasses import dataclass, field
from functools import cached_property

import flint

from ..diagnostics import AccuracyWarning
from .arbitrary_precision import gauss_legendre, mp_to_arb, parse_decimal, working_digits
from .kernels_mp import (
    FIRST_PANEL,
    WIDTH_DECAYS,
    panel_nodes,
    spinning_tail,
    torque_rotation,
    xi_layer,
    xi_sum_truncation,
)
from .sinh_excess_mp import sinh_excess_matrix, sinh_excess_values

__all__ = ["AbelFredholmState", "nodes_for_digits", "chebyshev_points", "interface_points", "solve_state"]


def _bernstein_log(b: float, singular_t_over_b: float) -> float:
    """ln(rho) of the image point theta_s = i arccosh(singular_t_over_b) for theta in [0, pi/2]."""
    height = math.acosh(singular_t_over_b) / (math.pi / 4.0)
    z = complex(-1.0, height)
    root = (z * z - 1.0) ** 0.5
    return math.log(max(abs(z + root), abs(z - root)))


def nodes_for_digits(stick_radius, digits: int) -> int:
    """Nystrom nodes for an error 10^-digits in T* and omega at stick radius b.

    ``fast.default_nodes`` scaled to ``digits``: Gauss-Legendre in theta converges like
    rho^(-2n) with rho the Bernstein parameter of theta_s = i arccosh((2 - b)/b) (the
    image singularity of P); n = 1.15 digits ln 10 / (2 ln rho) + 6.
    """
    b = float(stick_radius)
    n = math.ceil(1.15 * digits * math.log(10.0) / (2.0 * _bernstein_log(b, (2.0 - b) / b))) + 6
    return max(16, n)


def chebyshev_points(stick_radius, digits: int) -> int:
    """Chebyshev points in x = 2 t^2/b^2 - 1 for a 10^-digits series of G = g + L.

    G branches at t = 1 (L and E_1 do), x_s = 2/b^2 - 1: coefficients decay like
    (x_s + sqrt(x_s^2 - 1))^-k.
    """
    b = float(stick_radius)
    x_s = 2.0 / (b * b) - 1.0
    rho = x_s + math.sqrt(x_s * x_s - 1.0)
    return math.ceil(digits * math.log(10.0) / math.log(rho)) + 8


def _bernstein(point: complex, lo: float, hi: float) -> float:
    """Bernstein parameter rho of ``point`` for the interval [lo, hi]: Chebyshev series on
    [lo, hi] of a function singular there converge like rho^-k."""
    z = (2.0 * point - lo - hi) / (hi - lo)
    root = cmath.sqrt(z - 1.0) * cmath.sqrt(z + 1.0)
    return max(abs(z + root), abs(z - root))


def interface_points(stick_radius, lo: float, hi: float, digits: float) -> int:
    """Chebyshev points in u = sqrt(1 - t) on [lo, hi] for a 10^-digits series of H = bracket/t.

    H is singular at u = +-i sqrt(1 - b) (t = 2 - b, where the xi-integrals of P and E_b stop
    converging) and u = +-sqrt(2) (t = -1, E_1); the nearer one's Bernstein parameter sets the
    count, plus 10.  Measured decay of the coefficients at b = 0.02 (nearest u = sqrt 2, rho = 3.4)
    and the errors against direct evaluation: 1e-50 with 100 points at 49 digits.
    """
    b = float(stick_radius)
    rho = min(_bernstein(point, lo, hi) for point in (complex(0.0, math.sqrt(1.0 - b)), complex(math.sqrt(2.0))))
    return math.ceil(digits * math.log(10.0) / math.log(rho)) + 10


def _chebyshev_coefficients(values, angles=None) -> list:
    """Coefficients c_k of sum_k c_k T_k(x) through values at x_j = cos(pi (j + 1/2)/n) (arb).

    Without ``angles``: the cosines cos(pi k (2j + 1)/(2n)) take only 4n values, one table, then a
    product in C; consistent with the nodes to about k ulp.  With ``angles`` (the rounded
    theta_j at which the values were taken, x_j = cos(theta_j)): cos(k theta_j) entry by entry,
    consistent with the actual nodes to an ulp, for a series that is then differentiated (the
    k-ulp inconsistency, times k^2 in the derivative, made the traction's error estimate 2-12
    times larger).
    """
    n = len(values)
    if angles is None:
        pi = flint.arb.pi()
        table = [(pi * m / (2 * n)).cos() for m in range(4 * n)]
        entries = [table[(k * (2 * j + 1)) % (4 * n)] for k in range(n) for j in range(n)]
    else:
        entries = [(k * a).cos() for k in range(n) for a in angles]
    coefficients = [2 * c / n for c in _entries(flint.arb_mat(n, n, entries) * _column(values))]
    coefficients[0] = coefficients[0] / 2
    return coefficients


def chebyshev_nodes(n: int) -> list:
    """x_j = cos(pi (j + 1/2)/n), j < n (arb, working precision): the nodes of ``_chebyshev_coefficients``."""
    pi = flint.arb.pi()
    return [(pi * (2 * j + 1) / (2 * n)).cos() for j in range(n)]


def _chebyshev_values(coefficients, x_points) -> list:
    """sum_k c_k T_k(x) at many x in [-1, 1] (arb list, working precision).

    The series (coefficients rounded to their midpoints) is converted to the monomial basis by
    Clenshaw's recurrence in polynomial arithmetic and summed by Horner's rule in C, both with
    log2(1 + sqrt 2) bits per term more than the working precision: the monomial coefficients
    grow like (1 + sqrt 2)^k, and Arb's balls bound the cancellation.  The points are taken
    at their midpoints (as the Clenshaw sum of the derivative series did).
    """
    prec = flint.ctx.prec
    extra = math.ceil(len(coefficients) * math.log2(1.0 + math.sqrt(2.0))) + 16
    flint.ctx.prec = prec + extra
    try:
        x = flint.arb_poly([0, 1])
        b1, b2 = flint.arb_poly([]), flint.arb_poly([])
        for c in reversed(coefficients[1:]):
            b1, b2 = 2 * x * b1 - b2 + c.mid(), b1
        polynomial = x * b1 - b2 + coefficients[0].mid()
        values = polynomial.evaluate([p.mid() for p in x_points], algorithm="iter")
    finally:
        flint.ctx.prec = prec
    return [+v for v in values]


def _position(r, b) -> int:
    """-1, 0, 1 for r below, at (within 2^(8 - prec)), or above the stick radius b (arb)."""
    tolerance = flint.arb(2) ** (8 - flint.ctx.prec)
    if r < b - tolerance:
        return -1
    if r > b + tolerance:
        return 1
    return 0


def _arcsech(t):
    """ln((1 + sqrt(1 - t^2)) / t) for 0 < t <= 1 (arb)."""
    return ((1 + (1 - t * t).sqrt()) / t).log()


def _column(values) -> flint.arb_mat:
    values = list(values)
    return flint.arb_mat(len(values), 1, values)


def _row(values) -> flint.arb_mat:
    values = list(values)
    return flint.arb_mat(1, len(values), values)


def _entries(matrix) -> list:
    return [matrix[i, 0] for i in range(matrix.nrows())]


@dataclass(frozen=True)
class AbelFredholmState:
    """One Nystrom solve at fixed nodes and working precision (all numbers ``arb``).

    Attributes
    ----------
    stick_radius : arb
        b (exact binary value of the decimal input at the working precision).
    n_nodes, work_digits : int
    torque, rigid_rotation, rotation_constant : arb
        T* (F4), omega (F5), Omega = omega + BETA T* (F1).
    nodes, weights, density : tuple of arb
        t_j = b cos(theta_j) (rounded to its midpoint: an exact binary number), weights for
        int_0^b dt, g(t_j) (F2).
    chebyshev : tuple of arb
        Coefficients of G = g + L in T_k(2 t^2/b^2 - 1) (for F6); computed on first use.
    seconds : float
        Wall-clock time of the solve (T*, omega; not the xi-profiles of the Nystrom interpolant
        nor the series of the profiles, which are computed when a profile is first asked for).
    """

    stick_radius: object
    n_nodes: int
    work_digits: int
    torque: object
    rigid_rotation: object
    rotation_constant: object
    nodes: tuple = field(repr=False)
    weights: tuple = field(repr=False)
    density: tuple = field(repr=False)
    seconds: float = 0.0
    _xi: tuple = field(repr=False, default=())
    _xi_blocks: tuple = field(repr=False, default=())
    _interpolant: tuple = field(repr=False, default=())
    _tail_start: float = field(repr=False, default=0.0)

    # -- the xi-profiles of the interpolant (only the profiles need them: node sweeps skip them) ---------
    @cached_property
    def _profiles(self) -> tuple:
        """(a_k, y_k): bracket(t) = (2/pi) sum_k [A(xi_k t) a_k + t y_k] + tail, from the solve's A(xi_k t_j).

        sum_j w_j g_j A(xi_k t_j) as a row vector times the solve's matrix of A(xi_k t_j) (its edge row t = b
        weighted by an exact zero): each entry the same dot product, in the same order, as with the transposed
        matrix, so the same ball, without building that transpose again.
        """
        a_points, scale, xi, side_full, side_excess, column = self._interpolant
        n_xi = len(xi)
        with working_digits(self.work_digits):
            zero = flint.arb(0)
            two_over_pi = 2 / flint.arb.pi()
            weights_g = [c * g for c, g in zip(column, self.density, strict=True)]
            sums = _row(weights_g + [zero]) * a_points  # A(xi_k t_j) at (j, k), j <= n (the last row: t = b)
            sum_a = [sums[0, k] for k in range(n_xi)]
            sum_c = sum((c * tj for c, tj in zip(weights_g, self.nodes, strict=True)), zero)
            profile_a = tuple(s * (two_over_pi * (sa + x * sum_c) + f)
                              for s, x, sa, f in zip(scale, xi, sum_a, side_full, strict=True))
            profile_y = tuple(s * x * (two_over_pi * sa + e)
                              for s, x, sa, e in zip(scale, xi, sum_a, side_excess, strict=True))
        return profile_a, profile_y

    @property
    def _profile_a(self) -> tuple:
        return self._profiles[0]

    @property
    def _profile_y(self) -> tuple:
        return self._profiles[1]

    # -- the Nystrom interpolant --------------------------------------------------------
    def _bracket(self, t_points) -> list:
        """R(t) + (2/pi) int_0^b s g(s) P(t, s) ds for 0 < t <= 1 (arb list), see (F2), (F7).

        Each row's xi-sum stops where its rest is below t 2^-(prec + TRUNCATION_GUARD_BITS), and a
        rigorous bound on the rest is added to the ball (``kernels_mp.xi_sum_truncation``).
        """
        lengths, rests = xi_sum_truncation(t_points, self._xi, self._profile_a)
        a_matrix = sinh_excess_matrix(t_points, self._xi, method="cancel", lengths=lengths, blocks=self._xi_blocks)
        part_a = [value + flint.arb(0, rest) if rest is not None else value
                  for value, rest in zip(_entries(a_matrix * _column(self._profile_a)), rests, strict=True)]
        total_y = sum(self._profile_y, flint.arb(0))
        two_over_pi = 2 / flint.arb.pi()
        return [  # the J_k(1 + t) half of the tail is below exp(-X) < 2^-prec (kernels_mp.spinning_tail)
            two_over_pi * (pa + t * total_y) + spinning_tail(t, self._tail_start, far=False)
            for t, pa in zip(t_points, part_a, strict=True)
        ]

    # -- (F6) -----------------------------------------------------------------------------
    @cached_property
    def chebyshev(self) -> tuple:
        """Coefficients of G = 2 Omega - bracket(t)/t in T_k(x), x = 2 t^2/b^2 - 1 (for F6).

        G at the Chebyshev points by rows of A(xi t) (a series of H on the stick disc would
        need as many rows over the precision ladder), transformed consistently with the
        rounded nodes (``_chebyshev_coefficients`` with angles): (F6) differentiates the series.
        """
        with working_digits(self.work_digits):
            b = self.stick_radius
            n = chebyshev_points(float(b), self.work_digits)
            pi = flint.arb.pi()
            angles = [pi * (2 * j + 1) / (2 * n) for j in range(n)]
            t_cheb = [b * ((1 + a.cos()) / 2).sqrt() for a in angles]
            omega2 = 2 * self.rotation_constant
            values = [omega2 - br / tc for br, tc in zip(self._bracket(t_cheb), t_cheb, strict=True)]
            return tuple(_chebyshev_coefficients(values, angles))

    @cached_property
    def _chebyshev_derivative(self) -> tuple:
        with working_digits(self.work_digits):
            c = list(self.chebyshev)
            n = len(c)
            d = [flint.arb(0)] * (n + 1)
            for k in range(n - 1, 0, -1):
                d[k - 1] = (d[k + 1] + 2 * k * c[k]).mid()
            d[0] = d[0] / 2
            return tuple(v.mid() for v in d[: n - 1])

    def interface_traction(self, radii) -> list:
        """sigma_zt(r, 0)/(f p0) at exact radii in [0, 1] (arb list), eq. (F6); 1 for r >= b."""
        derivative = self._chebyshev_derivative
        with working_digits(self.work_digits):
            b = self.stick_radius
            m = len(derivative) + 2
            y_nodes, y_weights = gauss_legendre(m)
            edge_factor = (1 - b * b).sqrt()
            inside = [(index, r) for index, r in enumerate(radii) if _position(r, b) < 0]
            heights = [((b - r) * (b + r)).sqrt() for _, r in inside]
            x_points = [2 * (r * r + (height * (yj + 1) / 2) ** 2) / (b * b) - 1
                        for (_, r), height in zip(inside, heights, strict=True) for yj in y_nodes]
            values = _chebyshev_values(derivative, x_points) if x_points else []
            out = [flint.arb(1)] * len(radii)
            for position, ((index, r), height) in enumerate(zip(inside, heights, strict=True)):
                total = flint.arb(0)
                for wj, value in zip(y_weights, values[position * m:(position + 1) * m], strict=True):
                    total += wj * value
                integral = height * total / 2
                edge = 2 * flint.arb.atan2(r * edge_factor, height) / flint.arb.pi()
                out[index] = edge - 8 * r * integral / (flint.arb.pi() * b * b)
            return [+v for v in out]

    # -- (F7) ------------------------------------------------------------------------------
    def _h_series(self, lo, hi) -> tuple:
        """Chebyshev coefficients of H(u) = bracket(1 - u^2)/(1 - u^2) on [lo, hi] (arb, 0 <= lo < hi <= 1).

        To the working precision (2^-prec, not only 10^-work_digits: the profile error estimate
        of ``abel_fredholm_mp`` compares two solves down to their rounding).  The count from
        ``interface_points``; doubled (at most twice) while the last coefficients exceed 2^(8 - prec)
        of the largest (their rounding floor is about sqrt(n) 2^-prec), then an AccuracyWarning.
        """
        prec = flint.ctx.prec
        n = interface_points(float(self.stick_radius), float(lo), float(hi), prec * math.log10(2.0))
        for attempt in range(3):
            u_points = [lo + (hi - lo) * (1 + x) / 2 for x in chebyshev_nodes(n)]
            t_points = [(1 - u) * (1 + u) for u in u_points]
            values = [br / t for br, t in zip(self._bracket(t_points), t_points, strict=True)]
            coefficients = _chebyshev_coefficients(values)
            tail = max(abs(float(c)) for c in coefficients[-4:])
            scale = max(1.0, max(abs(float(c)) for c in coefficients))
            if tail <= 2.0 ** (8 - prec) * scale:
                return tuple(coefficients)
            if attempt < 2:
                n *= 2
        warnings.warn(f"stick_radius={float(self.stick_radius)}: the series of the Nystrom interpolant on "
                      f"u in [{float(lo):.3g}, {float(hi):.3g}] ends at {tail:.1e}, above 2^{8 - prec}; "
                      "the profiles may lose digits", AccuracyWarning, stacklevel=3)
        return tuple(coefficients)

    @cached_property
    def _slip_zone(self) -> tuple:
        """(sqrt(1 - b), the series of H on the slip annulus u in [0, sqrt(1 - b)])."""
        with working_digits(self.work_digits):
            edge = (1 - self.stick_radius).sqrt()
            return edge, self._h_series(flint.arb(0), edge)

    def _d_function(self, t_points, psi_points) -> list:
        """D(t) = 2 Omega t - t arcsech(t) - bracket(t) on [b, 1] (F7), t = cos(psi); bracket from its series."""
        edge, coefficients = self._slip_zone
        two_root2 = 2 * flint.arb(2).sqrt()
        x_points = [two_root2 * (psi / 2).sin() / edge - 1 for psi in psi_points]  # u = sqrt(1 - t) = sqrt2 sin(psi/2)
        series = _chebyshev_values(coefficients, x_points)
        omega2 = 2 * self.rotation_constant
        return [t * (omega2 - _arcsech(t) - h) for t, h in zip(t_points, series, strict=True)]

    def interface_slip(self, radii) -> list:
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu at exact radii in [0, 1], eq. (F7)."""
        with working_digits(self.work_digits):
            b = self.stick_radius
            psi_b = b.acos()
            half_pi = flint.arb.pi() / 2
            m = panel_nodes(self.work_digits)
            x_nodes, x_weights = gauss_legendre(m)
            t_all, psi_all, w_all, owner = [], [], [], []
            for index, r in enumerate(radii):
                if _position(r, b) <= 0:
                    continue
                psi_r = r.acos() if r < 1 else flint.arb(0)
                length = (psi_b - psi_r).sqrt()
                # no near singularity at v = 0 when r = 1 (sin(psi + psi_r) = sin(psi) cancels)
                left = float((2 * psi_r).sqrt()) if r < 1 else float(length)
                right = float((half_pi - psi_r).sqrt() - length)
                two_psi_r = 2 * psi_r
                for lo, hi in _graded_panels(float(length), left, right, length):
                    half, mid = (hi - lo) / 2, (hi + lo) / 2
                    for xj, half_wj in zip(x_nodes, [half * wj for wj in x_weights], strict=True):
                        v = mid + half * xj
                        v2 = v * v
                        psi = psi_r + v2
                        s_psi, c_psi = psi.sin(), psi.cos()
                        factor = 2 * v * c_psi * s_psi / (v2.sin() * (two_psi_r + v2).sin()).sqrt()
                        t_all.append(c_psi)
                        psi_all.append(psi)
                        w_all.append(half_wj * factor)
                    owner.extend([index] * m)
            sums = [flint.arb(0)] * len(radii)
            if t_all:
                values = self._d_function(t_all, psi_all)
                for k, w, dv in zip(owner, w_all, values, strict=True):
                    sums[k] += w * dv
            two_over_pi = 2 / flint.arb.pi()
            return [+(2 * two_over_pi * s / r) if _position(r, b) > 0 else flint.arb(0)
                    for s, r in zip(sums, radii, strict=True)]


def _graded_panels(length: float, left_scale: float, right_scale: float, exact_length):
    """Panels [lo, hi] (arb) of [0, length], halving toward 0 down to ``left_scale`` and
    toward ``length`` down to ``right_scale`` (geometric meshes for near end singularities)."""
    edges = {0.0}
    e = length / 2.0
    while e > left_scale and e > length * 1e-30:
        edges.add(e)
        e /= 2.0
    d = right_scale
    while d < length / 2.0:
        edges.add(length - d)
        d *= 2.0
    edges = sorted(edges)
    edges = [flint.arb(e) for e in edges] + [exact_length]
    return list(zip(edges[:-1], edges[1:], strict=True))


def solve_state(stick_radius, n_nodes: int, work_digits: int, *, first_panel: float = FIRST_PANEL,
                width_decays: float = WIDTH_DECAYS) -> AbelFredholmState:
    """Solve (F2)-(F5) with ``n_nodes`` Nystrom nodes at ``work_digits`` working digits.

    Parameters
    ----------
    stick_radius : mpf, str or Decimal
        b in (0, 1), exact (see ``arbitrary_precision.parse_decimal``).
    n_nodes : int
        Gauss-Legendre nodes in theta, >= 4.
    work_digits : int
        Working decimal digits of every operation.
    first_panel, width_decays : float
        Layout of the xi-quadrature (``kernels_mp.xi_quadrature``).
    """
    if isinstance(n_nodes, bool) or not isinstance(n_nodes, int) or n_nodes < 4:
        raise ValueError(f"n_nodes must be an integer >= 4, got {n_nodes!r}")
    start = time.perf_counter()
    with working_digits(work_digits):
        b = mp_to_arb(parse_decimal("stick_radius", stick_radius, 0, 1, closed=False))
        n = n_nodes
        pi = flint.arb.pi()
        two_over_pi = 2 / pi
        theta_x, theta_w = gauss_legendre(n)
        theta = [pi / 4 * (x + 1) for x in theta_x]
        t = [(b * th.cos()).mid() for th in theta]  # exact binary nodes (as the xi-nodes): A(xi t) stays sharp
        wt = [b * th.sin() * pi / 4 * w for th, w in zip(theta, theta_w, strict=True)]
        layer = xi_layer(b, work_digits, first_panel, width_decays)
        xi, scale, side_full, side_excess = layer.xi, layer.scale, layer.side_full, layer.side_excess
        zero = flint.arb(0)

        # A(xi_k t_i) at the nodes and at t = b; weighted transpose for the products
        points = t + [b]
        n_xi = len(xi)
        a_values = sinh_excess_values(points, xi, method="sharp", blocks=layer.blocks)  # A(xi_k t_j) at j n_xi + k
        a_points = flint.arb_mat(n + 1, n_xi, a_values)
        weighted = flint.arb_mat(n_xi, n, [s * v for k, s in enumerate(scale) for v in a_values[k:n * n_xi:n_xi]])
        moment_row = _row(xi) * weighted  # sum_k scale_k xi_k A(xi_k t_j)
        moment_nodes = [moment_row[0, j] for j in range(n)]
        moment_points = _entries(a_points * _column(s * x for s, x in zip(scale, xi, strict=True)))
        product = a_points * weighted
        side_a = _entries(a_points * _column(s * f for s, f in zip(scale, side_full, strict=True)))
        side_y = sum((s * x * e for s, x, e in zip(scale, xi, side_excess, strict=True)), zero)
        tail_start = layer.tail_start
        r_side = [two_over_pi * (sa + p * side_y) + spinning_tail(p, tail_start)
                  for p, sa in zip(points, side_a, strict=True)]
        # P(t_i, t_j) for i < n and the edge row i = n (t = b)
        product_entries = product.entries()
        kernel = [[two_over_pi * (product_entries[i * n + j] + moment_points[i] * t[j] + points[i] * moment_nodes[j])
                   for j in range(n)] for i in range(n + 1)]
        column = [w * tj for w, tj in zip(wt, t, strict=True)]
        matrix = flint.arb_mat(n, n, [(1 if i == j else 0) + two_over_pi * kernel[i][j] / t[i] * column[j]
                                      for i in range(n) for j in range(n)])
        log_l = [((1 + (1 - tj * tj).sqrt()) / (b + b * th.sin())).log() for tj, th in zip(t, theta, strict=True)]
        rhs = flint.arb_mat(n, 2, [v for i in range(n) for v in (flint.arb(2), -log_l[i] - r_side[i] / t[i])])
        solution = matrix.solve(rhs)
        g1 = [solution[i, 0] for i in range(n)]
        g0 = [solution[i, 1] for i in range(n)]
        edge = [two_over_pi * kernel[n][j] * column[j] / b for j in range(n)]
        g_b1 = 2 - sum((e * g for e, g in zip(edge, g1, strict=True)), zero)
        g_b0 = -_arcsech(b) - r_side[n] / b - sum((e * g for e, g in zip(edge, g0, strict=True)), zero)
        omega_big = -g_b0 / g_b1
        density = [omega_big * a + c for a, c in zip(g1, g0, strict=True)]
        torque = 4 * (1 - b**3) / 3 + 16 / pi * sum((w * tj * tj * g for w, tj, g in zip(wt, t, density, strict=True)),
                                                     zero)
        rotation = omega_big - torque_rotation(work_digits) * torque

        # the xi-profiles of the interpolant are formed from these on first use (AbelFredholmState._profiles)
        interpolant = (a_points, scale, xi, side_full, side_excess, column)
    return AbelFredholmState(
        stick_radius=b, n_nodes=n, work_digits=work_digits, torque=torque, rigid_rotation=rotation,
        rotation_constant=omega_big, nodes=tuple(t), weights=tuple(wt), density=tuple(density),
        seconds=time.perf_counter() - start, _xi=xi, _xi_blocks=layer.blocks, _interpolant=interpolant,
        _tail_start=tail_start,
    )
