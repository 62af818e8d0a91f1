r"""Kernels of the semi-infinite cylinder in torsion and their Abel transforms.

Units (docs/conventions.md): lengths in a, tractions in f p0, displacements in f p0 a / mu.
All functions are vectorised over their array arguments.

Neumann-to-Dirichlet map of the cylinder
----------------------------------------
For a face traction q(r) = du/dz (r, 0) on the cylinder z >= 0, 0 <= r <= 1 with a
traction-free side (eq. 9), write q = T* r + q_C with the torque-free part q_C
(int_0^1 q_C r^2 dr = 0).  The Dini series of ``solvers.weak_form`` (c_n lam_n h_n =
-(q_C, J1(lam_n r)), h_n = J1(lam_n)^2 / 2, eq. 26, 34, 35) gives

    u(r, 0) = omega r - int_0^1 G(r, rho) q_C(rho) rho drho,
    G(r, rho) = sum_n J1(lam_n r) J1(lam_n rho) / (lam_n h_n).                  (K1)

Extending u evenly to z < 0 turns the face load into a ring source 2 q(r) delta(z)
in an infinite cylinder.  A Hankel transform (whole space) plus a Fourier cosine
transform in z for the correction that frees the side r = 1 (using
(d/dr - 1/r) I1(xi r) = xi I2(xi r) and (d/dr - 1/r) K1(xi r) = -xi K2(xi r)) gives,
for torque-free loads, the same displacement with G replaced by K = G_hs + G_c:

    G_hs(r, rho) = int_0^inf J1(k r) J1(k rho) dk
                 = 2 [(1 - m/2) K(m) - E(m)] / (pi sqrt(m r rho)),  m = 4 r rho / (r + rho)^2,   (K2)
    G_c(r, rho)  = (2/pi) int_0^inf [I1(xi r) I1(xi rho) - xi^2 r rho / 4] K2(xi)/I2(xi) dxi.  (K3)

The subtraction in (K3) is the infinite twist of a torque-carrying load; for the
torque load q = rho itself, int_0^1 K(r, rho) rho^2 drho = BETA r exactly (a pure
rotation; BETA = 0.6053..., ``TORQUE_ROTATION``).  G is K with the rigid-rotation
component projected out on both sides, G = P K P with P f = f - 4 r int_0^1 f s^2 ds,
which with the previous identity gives

    G(r, rho) = G_hs(r, rho) + G_c(r, rho) - 4 BETA r rho                        (K4)

(checked against the Dini series at sample points in ``tests/test_fast.py``).

Abel transforms (Copson's method for the Reissner-Sagoci problem)
-----------------------------------------------------------------
With J1(k r) = (2 / (pi r)) int_0^r t sin(k t) / sqrt(r^2 - t^2) dt and the analogue
for I1 with sinh, define the Abel transform of the traction

    Gq(t) = int_t^1 q(rho) / sqrt(rho^2 - t^2) drho        (0 < t < 1)          (A1)

and the operator S[phi](r) = (2/(pi r)) int_0^r t phi(t) / sqrt(r^2 - t^2) dt.  Then

    int_0^1 G_hs(r, rho) q(rho) rho drho = S[t Gq(t)](r),
    int_0^1 G_c(r, rho) q(rho) rho drho  = S[(2/pi) int_0^1 s Gq(s) P(t, s) ds](r),
    P(t, s) = (2/pi) int_0^inf [sinh(xi t) sinh(xi s) - xi^2 t s] K2(xi)/I2(xi) dxi,   (A2)

and for the load 1 on c' < rho < c, int_{c'}^c M(t, rho) rho drho = E_c(t) - E_{c'}(t) with

    E_c(t) = (2/pi) int_0^inf [sinh(xi t) F(c xi) / xi^2 - xi^2 t c^3 / 6] K2(xi)/I2(xi) dxi,
    F(x)   = int_0^x y I1(y) dy = x^3/6 1F2(3/2; 2, 5/2; x^2/4),                (A3)

(M(t, rho) = S^{-1} applied to G_c(., rho); F is the modified-Bessel twin of the 1F2 of
eq. 51).  P and E_c are analytic for t + s < 2 and t < 1 (the image point of the
side r = 1); near t + s = 2, P ~ 1 / (2 (2 - t - s)).

Numerics
--------
xi-integrals use composite 16-point Gauss-Legendre on panels [0, 1/4], [1/4, 1/2],
then doubling, up to 38 / (decay rate); the integrands are evaluated in scaled form
(``kve``, ``ive`` and exp(-xi) factors; large-argument asymptotic series above 1e4,
where scipy returns nan) and the cancelling small-xi parts through power series:
sinh(x) - x and F(x) - x^3/6.  E_1(t) up to t = 1 (needed for the slip near r = 1)
is tabulated once per process as a Chebyshev series in psi = arccos(t), in which it is
analytic (its singular part is a series in (1 - t)^(k + 1/2)).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.polynomial import chebyshev, legendre
from scipy import special

__all__ = [
    "TORQUE_ROTATION",
    "xi_grid",
    "bessel_ratio_scaled",
    "integral_x_i1_scaled",
    "abel_kernel",
    "sinh_excess_scaled",
    "sinh_excess_slope",
    "linear_scaled",
    "load_transform",
    "load_profiles",
    "spinning_transform",
    "spinning_shear",
    "spinning_shear_kernel",
    "torque_transform",
    "halfspace_kernel",
    "cylinder_kernel",
    "arcsech",
]

#: int_0^1 K(r, rho) rho^2 drho = TORQUE_ROTATION * r: the rigid rotation that the
#: regularised kernel K = G_hs + G_c assigns to the torque load q = rho, i.e.
#: 1/2 + (1/pi) int_0^inf K2(xi) [1 - xi^2 / (8 I2(xi))] dxi (computed with mpmath at
#: 40 digits, checked in tests/test_fast.py).
TORQUE_ROTATION = 0.6053151262232325

_PANEL_NODES = 16
_GL_X, _GL_W = legendre.leggauss(_PANEL_NODES)
_EXP_RANGE = 38.0  # exp(-38) = 3e-17
_ASYMPTOTIC = 1e4
_SERIES_LIMIT = 40.0


def xi_grid(decay_rate: float, exp_range: float = _EXP_RANGE, nodes: int = _PANEL_NODES):
    """Composite Gauss-Legendre nodes and weights on [0, exp_range / decay_rate].

    Panels [0, 1/4], [1/4, 1/2], [1/2, 1], [1, 2], ... doubling until the last panel
    passes ``exp_range / decay_rate``.  Suited to smooth integrands decaying like
    exp(-decay_rate xi) (times powers of xi).

    Returns
    -------
    xi, weights : ndarray
    """
    xmax = exp_range / decay_rate
    edges = [0.0, 0.25, 0.5]
    while edges[-1] < xmax:
        edges.append(2.0 * edges[-1])
    e = np.asarray(edges)
    lo, hi = e[:-1], e[1:]
    if nodes == _PANEL_NODES:
        x, w = _GL_X, _GL_W
    else:
        x, w = legendre.leggauss(nodes)
    xi = (0.5 * (hi - lo)[:, None] * (x[None, :] + 1.0) + lo[:, None]).ravel()
    weights = (0.5 * (hi - lo)[:, None] * w[None, :]).ravel()
    return xi, weights


def _asymptotic_sum(x, coefficients, sign):
    total = np.ones_like(x)
    power = np.ones_like(x)
    for a in coefficients:
        power = power * (sign / x)
        total = total + a * power
    return total


# Hankel coefficients a_k(nu) = prod_{j=1..k} (4 nu^2 - (2j - 1)^2) / (k! 8^k)
def _hankel_coefficients(nu: int, terms: int = 5):
    mu = 4.0 * nu * nu
    out, acc = [], 1.0
    for k in range(1, terms + 1):
        acc *= (mu - (2 * k - 1) ** 2) / (k * 8.0)
        out.append(acc)
    return out


_A0 = _hankel_coefficients(0)
_A2 = _hankel_coefficients(2)


def _ive(order, x):
    """exp(-x) I_order(x) (order 0 or 2), asymptotic series above 1e4 (scipy gives nan beyond ~1e9)."""
    x = np.asarray(x, dtype=float)
    big = x > _ASYMPTOTIC
    xb = np.where(big, x, 1.0)
    asym = _asymptotic_sum(xb, _A0 if order == 0 else _A2, -1.0) / np.sqrt(2.0 * np.pi * xb)
    return np.where(big, asym, special.ive(order, np.where(big, 1.0, x)))


def _ive0(x):
    """exp(-x) I0(x) (``_ive``)."""
    return _ive(0, x)


def bessel_ratio_scaled(xi):
    """exp(2 xi) K2(xi) / I2(xi) = kve(2, xi) / ive(2, xi); -> pi as xi -> inf."""
    xi = np.asarray(xi, dtype=float)
    big = xi > _ASYMPTOTIC
    xb = np.where(big, xi, 1.0)
    asym = np.pi * _asymptotic_sum(xb, _A2, 1.0) / _asymptotic_sum(xb, _A2, -1.0)
    xs = np.where(big, 1.0, xi)
    return np.where(big, asym, special.kve(2, xs) / special.ive(2, xs))


def _integral_x_i1_series(x, drop_first: bool = False):
    """F(x) = sum_k x^(2k+3) / ((2k+3) 2^(2k+1) k! (k+1)!): positive terms, x <= 40.

    Summed until the last term is below 1e-17 of the sum (at most 90 terms).
    """
    x = np.asarray(x, dtype=float)
    term = x**3 / 2.0
    total = np.zeros_like(x) if drop_first else term / 3.0
    x2 = x * x
    for k in range(1, 90):
        term = term * x2 / (4.0 * k * (k + 1))
        piece = term / (2 * k + 3)
        total = total + piece
        if k % 8 == 0 and np.all(piece <= 1e-17 * total):
            break
    return total


def _integral_i0_coefficients(terms: int = 40):
    """beta_j of exp(-x) int_0^x I0 ~ (2 pi x)^(-1/2) sum_j beta_j x^(-j) (x -> inf).

    beta_j = sum_k alpha_k (k + 1/2)_(j - k) with alpha_k = ((2k - 1)!!)^2 / (k! 8^k), the
    coefficients of I0 (DLMF 10.40.1), integrated term by term (Watson's lemma).
    """
    alpha = [1.0]
    for k in range(1, terms):
        alpha.append(alpha[-1] * (2 * k - 1) ** 2 / (8.0 * k))
    beta = []
    for j in range(terms):
        total = 0.0
        for k in range(j + 1):
            rising = 1.0
            for m in range(j - k):
                rising *= k + 0.5 + m
            total += alpha[k] * rising
        beta.append(total)
    return np.asarray(beta)


_I0_INTEGRAL = _integral_i0_coefficients()


def integral_x_i1_scaled(x):
    """exp(-x) F(x), F(x) = int_0^x y I1(y) dy (eq. A3), relative accuracy ~1e-15.

    Power series (positive terms) for x <= 40; above, F = x I0(x) - int_0^x I0 with the
    asymptotic series of exp(-x) int_0^x I0 (40 terms; last term < 1e-17 at x = 40).
    """
    x = np.asarray(x, dtype=float)
    out = np.empty_like(x)
    small = x <= _SERIES_LIMIT
    out[small] = _integral_x_i1_series(x[small]) * np.exp(-x[small])
    xl = x[~small]
    if xl.size:
        inverse = 1.0 / xl
        series = np.zeros_like(xl)
        for coefficient in _I0_INTEGRAL[::-1]:
            series = series * inverse + coefficient
        out[~small] = xl * _ive0(xl) - series / np.sqrt(2.0 * np.pi * xl)
    return out


def sinh_excess_scaled(xi, t, gap=None):
    """exp(-xi) (sinh(xi t) - xi t), shape (len(t), len(xi)); series for xi t < 1/2.

    ``gap``: 1 - t if known more accurately than from t (t within ~1e-6 of 1, where
    exp(-xi (1 - t)) at xi ~ 1 / (1 - t) would inherit the rounding of t, 1e-16 / (1 - t)).
    """
    t = np.asarray(t, dtype=float)[:, None]
    xi = np.asarray(xi, dtype=float)[None, :]
    x = xi * t
    decay = np.exp(-xi)
    gap = 1.0 - t if gap is None else np.asarray(gap, dtype=float)[:, None]
    near = np.exp(-xi * gap)
    out = 0.5 * (near - near * np.exp(-2.0 * x)) - x * decay
    small = x < 0.5
    if np.any(small):
        xs = x[small]
        term = xs**3 / 6.0
        series = term
        x2 = xs * xs
        for k in range(2, 12):
            term = term * x2 / ((2 * k) * (2 * k + 1))
            series = series + term
        out[small] = series * np.broadcast_to(decay, x.shape)[small]
    return out


#: Taylor coefficients of (sinh x - x cosh x) / x^3 = -sum_k 2k x^(2k-2) / (2k+1)!, k = 1..9.
_SLOPE_SERIES = np.array([-2.0 * k / math.factorial(2 * k + 1) for k in range(1, 10)])


def sinh_excess_slope(xi, t, gap=None):
    """-(d/dt)[A_t / t] = xi^2 exp(-xi) (sinh(xi t) - xi t cosh(xi t)) / (xi t)^2, shape (len(t), len(xi)).

    A_t = ``sinh_excess_scaled``; its linear part xi t / t is constant in t.  Taylor
    series (x^3 Horner form, 9 terms) for x = xi t < 1/2, where the difference cancels;
    ``gap`` as for ``sinh_excess_scaled``.
    """
    t = np.asarray(t, dtype=float)[:, None]
    xi = np.asarray(xi, dtype=float)[None, :]
    x = xi * t
    gap = 1.0 - t if gap is None else np.asarray(gap, dtype=float)[:, None]
    near, far = np.exp(-xi * gap), np.exp(-xi * (1.0 + t))
    big = x >= 0.5
    xb = np.where(big, x, 1.0)
    direct = xi * xi * (0.5 * ((1.0 - xb) * near - (1.0 + xb) * far)) / (xb * xb)
    x2 = x * x
    series = np.zeros_like(x)
    for coefficient in _SLOPE_SERIES[::-1]:
        series = series * x2 + coefficient
    return np.where(big, direct, xi * xi * np.exp(-xi) * x * series)


def linear_scaled(xi, t):
    """exp(-xi) xi t, shape (len(t), len(xi))."""
    return np.asarray(t, dtype=float)[:, None] * (xi * np.exp(-xi))[None, :]


def abel_kernel(t, s, xi, weights):
    """P(t, s) of eq. (A2) as a matrix (len(t), len(s)); t + s < 2.

    ``xi, weights`` from ``xi_grid(2 - max(t) - max(s))`` (or a smaller rate).
    sinh(xi t) sinh(xi s) - xi^2 t s = A_t A_s + A_t Y_s + Y_t A_s with A = sinh - linear,
    Y = linear: no cancellation at small xi.
    """
    a_t, a_s = sinh_excess_scaled(xi, t), sinh_excess_scaled(xi, s)
    y_t, y_s = linear_scaled(xi, t), linear_scaled(xi, s)
    w = weights * bessel_ratio_scaled(xi)
    return (2.0 / np.pi) * ((a_t * w) @ (a_s + y_s).T + (y_t * w) @ a_s.T)


@functools.lru_cache(maxsize=8)
def _unit_profiles(key: bytes):
    full, excess = _load_profiles(1.0, np.frombuffer(key, dtype=float))
    full.flags.writeable = False
    excess.flags.writeable = False
    return full, excess


def load_profiles(c, xi):
    """The xi-profiles of E_c (eq. A3); see ``_load_profiles``.  Cached for c = 1."""
    xi = np.ascontiguousarray(xi, dtype=float)
    if c == 1.0:
        return _unit_profiles(xi.tobytes())
    return _load_profiles(c, xi)


def _load_profiles(c, xi):
    """The xi-profiles of E_c (eq. A3), scaled by exp(-2 xi) / exp(-xi) per factor.

    Returns ``(full, excess)`` with full = exp(-xi) F(c xi) / xi^2 and excess =
    exp(-xi) (F(c xi) - (c xi)^3 / 6) / xi^2, so that
    E_c(t) = (2/pi) sum_k w_k ratio_k [A_t,k full_k + Y_t,k excess_k] with
    A_t = exp(-xi) (sinh(xi t) - xi t), Y_t = exp(-xi) xi t, ratio = kve2 / ive2.
    """
    xi = np.asarray(xi, dtype=float)
    cx = c * xi
    full = integral_x_i1_scaled(cx) * np.exp(-(1.0 - c) * xi)
    series = cx <= _SERIES_LIMIT
    cs = np.where(series, cx, 0.0)
    excess = np.where(
        series, _integral_x_i1_series(cs, drop_first=True) * np.exp(-xi), full - cx**3 * np.exp(-xi) / 6.0
    )
    return full / xi**2, excess / xi**2


def load_transform(t, c, xi, weights):
    """E_c(t) of eq. (A3) for 0 < c <= 1: int_0^c M(t, rho) rho drho (odd in t).

    ``xi, weights`` from ``xi_grid(1 - max(t) + 1 - c)`` (or a smaller rate).
    """
    xi = np.asarray(xi, dtype=float)
    a_t, y_t = sinh_excess_scaled(xi, t), linear_scaled(xi, t)
    full, excess = load_profiles(c, xi)
    w = weights * bessel_ratio_scaled(xi)
    return (2.0 / np.pi) * (a_t @ (w * full) + y_t @ (w * excess))


def torque_transform(t, xi, weights):
    """int_0^1 M(t, rho) rho^2 drho = (2/pi) int [sinh(xi t) I2/xi - xi^2 t/8] K2/I2 dxi.

    Equals 2 BETA t - t sqrt(1 - t^2) (the rigid rotation of the torque load; tested).
    """
    xi = np.asarray(xi, dtype=float)
    a_t, y_t = sinh_excess_scaled(xi, t), linear_scaled(xi, t)
    small = xi < 1.0
    xs = np.where(small, xi, 0.0)
    term = (xs / 2.0) ** 2 / 2.0
    series = np.zeros_like(xi)
    for k in range(1, 15):
        term = term * (xs / 2.0) ** 2 / (k * (k + 2))
        series = series + term
    excess = np.where(small, series * np.exp(-xi), special.ive(2, np.where(small, 1.0, xi)) - xi**2 * np.exp(-xi) / 8)
    w = weights * bessel_ratio_scaled(xi)
    return (2.0 / np.pi) * (a_t @ (w * special.ive(2, xi) / xi) + y_t @ (w * excess / xi))


_SPIN_POINTS = 96


@functools.lru_cache(maxsize=1)
def _spinning_chebyshev():
    """Chebyshev coefficients of E_1(cos psi) / cos psi on psi in [0, pi/2]."""
    j = np.arange(_SPIN_POINTS)
    x = np.cos(np.pi * (j + 0.5) / _SPIN_POINTS)
    t = np.cos(np.pi / 4.0 * (x + 1.0))
    xi, w = xi_grid(float(np.min(1.0 - t)))
    values = load_transform(t, 1.0, xi, w) / t
    coefficients = chebyshev.chebfit(x, values, _SPIN_POINTS - 1)
    coefficients.flags.writeable = False
    return coefficients


def spinning_shear_kernel(t):
    """k(t) = 1/sqrt(1 - t^2) - t e'(t), e = E_1(t)/t, for 0 <= t <= 0.9 (sigma_rt of F7).

    sigma_rt(r, 0) of the load D(t) = -t arcsech t - E_1(t) (traction 1) is
    (2/pi) int_0^(pi/2) sin^2(phi) k(r sin phi) dphi; e' from the derivative of the
    Chebyshev table of ``spinning_transform`` (~1e-13 for t <= 0.9; near t = 1 the two
    terms cancel and ``spinning_shear`` (K5) must be used instead).
    """
    t = np.asarray(t, dtype=float)
    root = np.sqrt((1.0 - t) * (1.0 + t))
    x = np.arccos(np.clip(t, 0.0, 1.0)) / (np.pi / 4.0) - 1.0
    e_psi = chebyshev.chebval(x, chebyshev.chebder(_spinning_chebyshev())) / (np.pi / 4.0)
    return (1.0 + t * e_psi) / root  # e'(t) = -e_psi / sqrt(1 - t^2)


def spinning_transform(t):
    """E_1(t) = int_0^1 M(t, rho) rho drho for 0 <= t <= 1 (response to traction 1).

    Chebyshev interpolant in psi = arccos t (96 points, tabulated on first use,
    about 1e-15 absolute; ``tests/test_fast.py`` compares it with direct quadrature).
    """
    t = np.asarray(t, dtype=float)
    x = np.arccos(np.clip(t, 0.0, 1.0)) / (np.pi / 4.0) - 1.0
    return t * chebyshev.chebval(x, _spinning_chebyshev())


def _ive2(x):
    """exp(-x) I2(x) (``_ive``)."""
    return _ive(2, x)


def _halfspace_shear(m):
    """(2/pi) (K(m) - E(m)) / m, m = r^2 in [0, 1): power series below m = 1/2."""
    m = np.asarray(m, dtype=float)
    out = np.empty_like(m)
    small = m < 0.5
    ms = m[small]
    coefficient, total, power = 0.25, np.zeros_like(ms), np.ones_like(ms)
    for n in range(1, 60):  # (K - E)/m = (pi/2) sum_n a_n^2 (2n/(2n - 1)) m^(n-1), a_n = (2n)!/(4^n n!^2)
        total = total + coefficient * (2.0 * n / (2.0 * n - 1.0)) * power
        coefficient *= ((2.0 * n + 1.0) / (2.0 * n + 2.0)) ** 2
        power = power * ms
    out[small] = total
    ml = m[~small]
    out[~small] = (special.ellipkm1(1.0 - ml) - special.ellipe(ml)) / (np.pi / 2.0 * ml)
    return out


def spinning_shear(r):
    """sigma_rt(r, 0+) / (f p0) under traction 1 on the whole face (spinning), 0 <= r < 1.

    With u(r, 0) = omega r + v(r) and sigma_rt = u' - u/r (the rigid rotation drops out),
    the Neumann-to-Dirichlet map (K1)-(K4) with (d/dr - 1/r) J1(k r) = -k J2(k r) and
    (d/dr - 1/r) I1(xi r) = xi I2(xi r) gives a half-space part (Abel form of F7 with
    D = -t arcsech t: (2/pi) int_0^(pi/2) sin^2 phi / sqrt(1 - r^2 sin^2 phi) dphi) and
    the side correction of (K3):

        sigma_rt(r, 0) = (2/pi) (K(r^2) - E(r^2)) / r^2
                         - (2/pi) int_0^inf [I2(xi r) / I2(xi)] K2(xi) F(xi) / xi dxi.     (K5)

    Both terms grow like ln(1/(1 - r)) towards the corner and the logarithms cancel
    (sigma_rt -> 0 at the free side r = 1); sigma_rt -> 1/2 as r -> 0+ (the uniform
    circumferential traction winds around the axis: u ~ (r ln r)/2).  Checked against
    the Dini series (eq. 24) at small z in the tests.
    """
    r = np.asarray(r, dtype=float)
    flat = r.ravel()
    out = np.zeros_like(flat)
    inside = (flat > 0.0) & (flat < 1.0)
    x = flat[inside]
    if x.size:
        xi, w = xi_grid(float(1.0 - np.max(x)))
        scaled = _ive2(np.outer(x, xi)) * np.exp(-np.outer(1.0 - x, xi))  # I2(xi r) exp(-xi)
        profile = w * bessel_ratio_scaled(xi) * integral_x_i1_scaled(xi) / xi  # exp(2 xi) K2/I2 * exp(-xi) F / xi
        out[inside] = _halfspace_shear(x * x) - (2.0 / np.pi) * (scaled @ profile)
    return out.reshape(r.shape)


def arcsech(s):
    """ln((1 + sqrt(1 - s^2)) / s): the Abel transform (A1) of q = 1 on (s, 1)."""
    s = np.asarray(s, dtype=float)
    return np.log1p(np.sqrt((1.0 - s) * (1.0 + s))) - np.log(s)


def halfspace_kernel(r, rho):
    """G_hs(r, rho) = int_0^inf J1(k r) J1(k rho) dk, eq. (K2); log-singular at r = rho."""
    r, rho = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(rho, dtype=float))
    m1 = ((r - rho) / (r + rho)) ** 2  # 1 - m, m = 4 r rho / (r + rho)^2, exact near r = rho
    m = 1.0 - m1
    return 2.0 * ((1.0 - m / 2.0) * special.ellipkm1(m1) - special.ellipe(m)) / (np.pi * np.sqrt(m * r * rho))


def _i1_excess_scaled(x, xi):
    """exp(-xi) (I1(x) - x/2) for x = xi * (point) <= xi (series below 1/2).

    Each branch is evaluated only where it applies (the same numbers as evaluating both and
    selecting, at half the cost).
    """
    x, xi = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(xi, dtype=float))
    small = x < 0.5
    out = np.empty(x.shape)
    xs = x[small]
    term = xs / 2.0
    series = np.zeros_like(xs)
    for k in range(1, 12):
        term = term * (xs / 2.0) ** 2 / (k * (k + 1))
        series = series + term
    out[small] = series * np.exp(-xi[small])
    large = ~small
    xl, xil = x[large], xi[large]
    out[large] = special.i1e(xl) * np.exp(xl - xil) - xl * np.exp(-xil) / 2.0  # i1e = ive(1, .), Cephes: 5x faster
    return out


def cylinder_kernel(r, rho):
    """G_c(r, rho) of eq. (K3) for r, rho in [0, 1), r + rho < 2 (vectorised, broadcast).

    A reference implementation (no scaling tricks beyond splitting I1 = x/2 + excess);
    for tests and documentation, not used by the solver.  The Bessel factors are evaluated
    on r and rho as given (a scalar r against a vector rho costs one row, not one per rho)
    and broadcast in the product.
    """
    r, rho = np.asarray(r, dtype=float), np.asarray(rho, dtype=float)
    xi, w = xi_grid(float(2.0 - np.max(r) - np.max(rho)))
    xr = np.multiply.outer(r, xi)
    xp = np.multiply.outer(rho, xi)
    er, ep = _i1_excess_scaled(xr, xi), _i1_excess_scaled(xp, xi)
    # I1 I1 - xr xp / 4 = er ep + er xp/2 + xr/2 ep, all scaled by exp(-2 xi)
    scale = np.exp(-xi)
    product = er * ep + er * (xp * scale / 2) + (xr * scale / 2) * ep
    return (2.0 / np.pi) * product @ (w * bessel_ratio_scaled(xi))
