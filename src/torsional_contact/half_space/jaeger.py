r"""Jaeger's superposition for any axisymmetric pressure: rotation, torque, traction and slip by quadrature.

Units (docs/conventions.md): radii in the contact radius a; the pressure p(r) in p-bar = F/(pi a^2)
(mean 1: 2 int_0^1 p r dr = 1); T* = 2T/(f F a); tractions in f p-bar; slip in f p-bar a / mu;
rotations in f p-bar / mu.  Below mu = 1, f p-bar = 1, a = 1.

The superposition (J1)-(J6)
---------------------------
A rigid disc of radius c bonded to a half-space and turned by beta carries the traction
(4 beta / pi) r / sqrt(c^2 - r^2) and the torque (16/3) c^3 beta (Reissner and Sagoci).  Discs
c in [b, 1] turned by d beta(c) >= 0 (a point mass at c = 1 when p ~ c0 / sqrt(1 - r^2) at the
edge) give the traction f p(r) on the slip annulus b < r < 1 when (Abel inversion) the rotation of
the discs with radius >= t is

    R(t) = (1/2) int_t^1 p(x) dx / sqrt(x^2 - t^2),                                      (J1)

the stick disc r < b turns rigidly with all of them: its rotation relative to the remote points
of one elastic body is Omega(b) = R(b) (``rotation``).  The torque, summing the discs and
exchanging the order of integration (int_b^x c^2 dc / sqrt(x^2 - c^2) in closed form),

    T*(b) = (32/(3 pi)) [ b^3 R(b) + (3/4) int_b^1 p(x) (x^2 arccos(b/x) + b sqrt(x^2 - b^2)) dx ],   (J2)

gross slip T*(0) = 4 int_0^1 p r^2 dr, dT*/db = (32/(3 pi)) b^3 R'(b) and so

    dOmega/dT* = 3 pi / (32 b^3)   for every pressure,                                   (J3)

the stick disc's compliance as a bonded disc of radius b.  The stick-zone traction, the same
exchange of order with int (v - r^2)^(-3/2) (x^2 - v)^(-1/2) dv in closed form:

    q(r) = (2 r sqrt(b^2 - r^2) / pi) int_b^1 p(x) dx / (sqrt(x^2 - b^2) (x^2 - r^2)),  r < b,   (J4)

continuous at r = b (q -> p(b)), equal to (2/pi) arctan(r sqrt(1 - b^2) / sqrt(b^2 - r^2)) for the
uniform pressure.  The displacement of one body's face relative to its stick disc on the annulus
(the free-face field of the discs c < r, integrated by parts) is

    u(r) = (4 / (pi r)) int_b^r (R(b) - R(c)) c^2 dc / sqrt(r^2 - c^2),  r > b,          (J5)

and the slip s = n u (n = 2 for two elastically similar bodies, each turning by Omega; n = 1 for a
rigid punch on one elastic body).  The work against friction of the monotonic loading,
2 pi int_b^1 p s r dr, with (J1) after exchanging the order of integration, is

    W_mono(b) = 16 n int_b^1 c^2 R(c) (R(b) - R(c)) dc,                                  (J6)

the same as the loop-area route (pi n / 2) int (T* dOmega - Omega dT*) along the loading path.
Slip starts at T* = (8/3) c0, c0 = lim sqrt(1 - r^2) p(r) (R(1) = pi c0 / 4: 4/3 for the flat punch,
0 for a pressure bounded at the edge); below it the contact is bonded, Omega = 3 pi T* / 32.

Quadrature
----------
Every integral over x in [b, 1] runs in theta with x^2 = b^2 cos^2(theta) + sin^2(theta)
(x^2 - b^2 = k^2 sin^2 theta, 1 - x^2 = k^2 cos^2 theta, k^2 = 1 - b^2): dx / sqrt(x^2 - b^2)
= k cos(theta) dtheta / x removes the inverse square root at x = b, and the pressure enters as
e(x) = p(x) sqrt(1 - x^2) (``weighted``), smooth for p = p_s(r) / sqrt(1 - r^2) or p = p_s(r)
sqrt(1 - r^2) with p_s smooth (the flat punch, Hertz): no edge singularity is left.  The
integrands are near-singular at theta = 0 over a width ~ b / k (1/x; and sqrt(b^2 - r^2) / k in
(J4)): Gauss-Legendre panels (``PANEL_NODES`` nodes) graded geometrically (ratio <= 3) from that
width, and toward theta = pi/2 (ratio 4, for pressures with other algebraic edge behaviour).
For a pressure analytic in this sense the rules are exact to rounding (errors ~1e-16 relative,
checked against mpmath in tests/test_pressure_models.py).
"""

from __future__ import annotations

import math

import numpy as np

from ..quadrature import gauss_legendre

__all__ = ["PANEL_NODES", "graded_rule", "rotation", "rotation_and_torque", "torque", "torque_deficit",
           "gross_slip_torque", "mean_pressure", "stick_traction", "displacement", "loading_work", "edge_root"]

#: Gauss-Legendre nodes per panel.
PANEL_NODES = 16
#: Panels graded toward the upper end of an interval (ratio 4, down to 4^-8 of the half-length).
_UPPER_PANELS = 8
#: Largest ratio of two neighbouring geometric panels toward a near-singularity.
_RATIO = 3.0
#: Smallest relative width a near-singularity is resolved to (below it: rounding).
_TINY = 1e-300


def graded_rule(lower, upper, width, upper_grading: bool = True):
    """Composite Gauss-Legendre nodes and weights on [lower, upper] per row (arrays of shape (m,)).

    Panels: [lower, lower + w], geometric (ratio <= 3) from lower + w to the midpoint, where w =
    ``width`` (the near-singularity's distance from ``lower``, clipped to half the interval), then
    uniform-by-ratio toward ``upper`` (ratio 4, ``_UPPER_PANELS`` panels) if ``upper_grading``, else
    one panel.  Returns (nodes, weights) of shape (m, n).
    """
    lower, upper = np.broadcast_arrays(np.asarray(lower, dtype=float), np.asarray(upper, dtype=float))
    lower, upper = lower.ravel(), upper.ravel()
    length = upper - lower
    half = 0.5 * length
    w = np.clip(np.broadcast_to(np.asarray(width, dtype=float), lower.shape), _TINY, None)
    s = np.clip(w / np.where(half > 0, half, 1.0), _TINY, 1.0)  # relative width in (0, 1]
    n_left = int(min(200, max(1, math.ceil(math.log(1.0 / float(np.min(s))) / math.log(_RATIO))))) if s.size else 1
    left = s[:, None] ** (1.0 - np.arange(n_left + 1) / n_left)  # s .. 1 of the lower half
    if upper_grading:
        right = 2.0 - 4.0 ** -np.arange(_UPPER_PANELS + 1, dtype=float)
        right = np.concatenate([right[1:], [2.0]])  # 1.5 .. 2
    else:
        right = np.array([2.0])
    edges = np.concatenate([np.zeros((s.size, 1)), left, np.broadcast_to(right, (s.size, right.size))], axis=1)
    edges = lower[:, None] + half[:, None] * edges
    x, wq = gauss_legendre(PANEL_NODES)
    mid = 0.5 * (edges[:, 1:] + edges[:, :-1])
    rad = 0.5 * (edges[:, 1:] - edges[:, :-1])
    nodes = (mid[:, :, None] + rad[:, :, None] * x).reshape(s.size, -1)
    weights = (rad[:, :, None] * wq).reshape(s.size, -1)
    return nodes, weights


def _radius_pair(b, k=None):
    b = np.asarray(b, dtype=float).ravel()
    if k is None:
        k = np.sqrt(np.maximum((1.0 - b) * (1.0 + b), 0.0))
    return b, np.asarray(k, dtype=float).ravel()


def _theta_nodes(b, k, width):
    """theta nodes, weights and x, sqrt(1 - x^2) there, for rows (b, k) (module docstring)."""
    theta, w = graded_rule(np.zeros_like(b), np.full_like(b, 0.5 * math.pi), width)
    s, c = np.sin(theta), np.cos(theta)
    bb, kk = b[:, None], k[:, None]
    x = np.sqrt((bb * c) ** 2 + s * s)
    return theta, w, s, c, x, kk * c


def _near_width(b, k):
    with np.errstate(divide="ignore"):
        return np.where(k > 0, b / np.where(k > 0, k, 1.0), np.inf)


def rotation(weighted, b, k=None):
    """R(b) of (J1) for an array 0 < b <= 1 (``weighted(x, root)`` = p(x) sqrt(1 - x^2), root = sqrt(1 - x^2)).

    At b = 1 (k = 0) the limit pi c0 / 4 is taken from ``weighted`` at x = 1, root = 0.
    """
    b, k = _radius_pair(b, k)
    _, w, _, _, x, root = _theta_nodes(b, k, _near_width(b, k))
    return 0.5 * np.sum(w * weighted(x, root) / x, axis=1)


def rotation_and_torque(weighted, b, k=None):
    """(R(b), T*(b)) of (J1), (J2) for an array 0 <= b <= 1, on the same nodes (R = +inf at b = 0)."""
    b, k = _radius_pair(b, k)
    _, w, s, _, x, root = _theta_nodes(b, k, _near_width(b, k))
    e = weighted(x, root)
    rotations = 0.5 * np.sum(w * e / x, axis=1)
    ks = k[:, None] * s
    kernel = x * x * np.arctan2(ks, b[:, None]) + b[:, None] * ks
    tail = 0.75 * k * np.sum(w * e * s * kernel / x, axis=1)
    cubed = np.where(b > 0, b**3 * np.where(b > 0, rotations, 0.0), 0.0)
    return np.where(b > 0, rotations, np.inf), (32.0 / (3.0 * math.pi)) * (cubed + tail)


def torque(weighted, b, k=None):
    """T*(b) of (J2) for an array 0 <= b <= 1."""
    return rotation_and_torque(weighted, b, k)[1]


#: 2 C(2n, n) 4^-n / (2n + 3), n = 0..27: f(s) = s^3 sum_n c_n s^(2n) (ratio <= 1/4 below s = 1/2: 4^-28 < eps / 10)
_EXCESS_SERIES = [2.0 * math.comb(2 * n, n) / 4.0**n / (2 * n + 3) for n in range(28)]


def _arcsin_excess(s):
    """f(s) = arcsin(s) - s sqrt(1 - s^2) = 2 sum_n C(2n, n) 4^-n s^(2n+3) / (2n + 3) (series below s = 1/2)."""
    s = np.asarray(s, dtype=float)
    out = np.empty_like(s)
    small = s < 0.5
    t = s[small]
    t2, total = t * t, np.zeros_like(t)
    for c in reversed(_EXCESS_SERIES):
        total = total * t2 + c
    out[small] = total * t * t2
    big = s[~small]
    out[~small] = np.arcsin(np.minimum(big, 1.0)) - big * np.sqrt(np.maximum((1.0 - big) * (1.0 + big), 0.0))
    return out


def torque_deficit(weighted, b, k=None):
    """T*(0) - T*(b) for an array 0 <= b < 1 without cancellation (J2 with the order of integration exchanged):

        (32/(3 pi)) [ (3 pi/8) int_0^b p x^2 dx + (3/4) int_b^1 p x^2 f(b/x) dx - b^3 R(b) ],

    f(s) = arcsin(s) - s sqrt(1 - s^2) ~ (2/3) s^3; ~ (16/(9 pi)) p(0) b^3 for small b.
    """
    b, k = _radius_pair(b, k)
    _, w, s, _, x, root = _theta_nodes(b, k, _near_width(b, k))
    e = weighted(x, root)
    rotations = 0.5 * np.sum(w * e / x, axis=1)
    outer = 0.75 * k * np.sum(w * e * s * x * _arcsin_excess(b[:, None] / x), axis=1)
    alpha, wa = graded_rule(np.zeros_like(b), np.full_like(b, 0.5 * math.pi), np.full_like(b, 0.5 * math.pi))
    sa = np.sin(alpha)
    xa = b[:, None] * sa
    ra = np.sqrt(np.maximum((1.0 - xa) * (1.0 + xa), 0.0))
    inner = b**3 * np.sum(wa * weighted(xa, ra) / ra * sa * sa * np.cos(alpha), axis=1)
    return (32.0 / (3.0 * math.pi)) * (0.375 * math.pi * inner + outer - b**3 * rotations)


def gross_slip_torque(weighted) -> float:
    """T*(0) = 4 int_0^1 p r^2 dr (r = sin theta: 4 int e(sin theta) sin^2 theta dtheta)."""
    theta, w = graded_rule(np.zeros(1), np.full(1, 0.5 * math.pi), np.full(1, 0.5 * math.pi))
    s, c = np.sin(theta), np.cos(theta)
    return float(4.0 * np.sum(w * weighted(s, c) * s * s))


def mean_pressure(weighted) -> float:
    """2 int_0^1 p r dr (r = sin theta: 2 int e(sin theta) sin theta dtheta); 1 for a normalised pressure."""
    theta, w = graded_rule(np.zeros(1), np.full(1, 0.5 * math.pi), np.full(1, 0.5 * math.pi))
    s, c = np.sin(theta), np.cos(theta)
    return float(2.0 * np.sum(w * weighted(s, c) * s))


def edge_root(r):
    """sqrt(1 - r^2) without cancellation near r = 1."""
    r = np.asarray(r, dtype=float)
    return np.sqrt(np.maximum((1.0 - r) * (1.0 + r), 0.0))


def stick_traction(weighted, r, b: float) -> np.ndarray:
    """q(r) of (J4) on the stick disc, for an array 0 <= r < b (0 < b < 1)."""
    r = np.asarray(r, dtype=float).ravel()
    k = math.sqrt(max((1.0 - b) * (1.0 + b), 0.0))
    d2 = (b - r) * (b + r)
    d = np.sqrt(d2)
    bb = np.full_like(r, b)
    kk = np.full_like(r, k)
    width = np.minimum(d, b) / k
    _, w, s, _, x, root = _theta_nodes(bb, kk, width)
    e = weighted(x, root)
    denominator = d2[:, None] + (kk[:, None] * s) ** 2  # x^2 - r^2
    return (2.0 / math.pi) * r * d * np.sum(w * e / (x * denominator), axis=1)


def displacement(rotation_of, r, b: float, rotation_b: float) -> np.ndarray:
    """u(r) of (J5) on the slip annulus, for an array b < r <= 1 (``rotation_of(c)``: R at an array of c).

    c = r sin(alpha), alpha from arcsin(b/r) to pi/2 (dc / sqrt(r^2 - c^2) = dalpha), panels graded
    from both ends (R is near-singular at c = 0 when b is small, and at c = 1 when r is near 1).
    """
    r = np.asarray(r, dtype=float).ravel()
    alpha_b = np.arcsin(np.clip(b / r, 0.0, 1.0))
    width = np.full_like(r, max(b, 1e-300))
    alpha, w = graded_rule(alpha_b, np.full_like(r, 0.5 * math.pi), width)
    c = r[:, None] * np.sin(alpha)
    values = rotation_of(c.ravel()).reshape(c.shape)
    sin2 = np.sin(alpha) ** 2
    return (4.0 * r / math.pi) * np.sum(w * (rotation_b - values) * sin2, axis=1)


def loading_work(rotation_of, b, bodies: int) -> np.ndarray:
    """W_mono(b) of (J6) for an array 0 < b < 1 (c = cos(phi), phi in [0, arccos b], graded at both ends)."""
    b = np.asarray(b, dtype=float).ravel()
    psi = np.arccos(b)
    phi, w = graded_rule(np.zeros_like(b), psi, np.full_like(b, 0.5) * psi, upper_grading=True)
    c = np.cos(phi)
    values = rotation_of(c.ravel()).reshape(c.shape)
    own = rotation_of(b)
    return 16.0 * bodies * np.sum(w * np.sin(phi) * c * c * values * (own[:, None] - values), axis=1)
