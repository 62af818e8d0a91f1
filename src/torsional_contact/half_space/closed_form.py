r"""Two elastically similar half-spaces twisted against each other: the closed forms.

Units (docs/conventions.md, the same as the cylinder model): r, z in the contact radius a;
T* = 2T/(f F a) = 2T/(pi a^3 f p0); tractions and stresses in f p0; displacements and slip
in f p0 a / mu; rotations in f p0 / mu; energies in (f p0)^2 a^3 / mu.  Below mu = 1 and
f p0 = 1, a = 1.

The problem
-----------
Two half-spaces of the same material, z > 0 (upper) and z < 0, touch on the disc r < 1
under the uniform pressure p0 (outside it the faces are free); Coulomb friction f; the
upper body is twisted by T about the axis, the lower one by -T.  The torsion problem is
uncoupled from the normal one (elastic similarity), so the pressure stays p0 and the
friction limit is 1 everywhere on the disc.  By antisymmetry u(r, -z) = -u(r, z); the slip
is s = 2 u(r, 0+).  ``rigid_rotation`` Omega is the rotation of the upper body far from the
contact relative to the stick disc (the lower body turns by -Omega): the relative twist of
remote points is phi = 2 Omega.  For the finite cylinders ``rigid_rotation`` omega is the
far-field rotation *beyond the uniform twist T* r z* of a monolithic shaft: 2 omega is
the extra twist that the interface adds (0 in stick), while 2 Omega here contains the whole
elastic compliance of the half-spaces (a bonded contact already gives Omega = 3 pi T*/32).

Derivation (Jaeger's superposition of Reissner-Sagoci rotations)
----------------------------------------------------------------
A rigid disc of radius c bonded to the half-space z > 0 and turned by beta (far field at
rest) gives, in oblate spheroidal coordinates r = c sqrt((1 + xi^2)(1 - eta^2)), z = c xi eta,

    U(r, z; c) = (2 beta / pi) r [arccot xi - xi / (1 + xi^2)],                       (H1)

i.e. beta r under the disc, (2 beta/pi)[r arcsin(c/r) - c sqrt(r^2 - c^2)/r] on the free
face r > c, the traction sigma_zt(r, 0) = -(4 beta/pi) r / sqrt(c^2 - r^2) under it and the
torque (16/3) c^3 beta (Reissner and Sagoci 1944).  Superpose such discs, c in [b, 1],
turned by d beta(c) >= 0, on the upper body (opposite on the lower one) and add a rigid
rotation Omega r:

    u(r, z) = Omega r - int_b^1 U(r, z; c) dbeta(c) / beta.                          (H2)

On the stick disc r < b every disc covers r, so u(r, 0) = (Omega - int_b^1 dbeta) r
vanishes (no slip) exactly when

    Omega = int_b^1 dbeta.                                                           (H3)

The traction is q(r) = (4/pi) r int_max(r,b)^1 beta'(c) dc / sqrt(c^2 - r^2).  Slip on the
annulus at the friction limit, q = 1 on b < r < 1, is an Abel equation for beta':
int_r^1 beta'(c) dc / sqrt(c^2 - r^2) = pi / (4 r), whose solution (Abel inversion, with
int_c^1 dr / sqrt(r^2 - c^2) = arccosh(1/c)) is

    beta'(c) = -(1/2) d/dc arccosh(1/c) = 1 / (2 c sqrt(1 - c^2)).                  (H4)

It leaves no singularity at r = b (the stick-side traction rises continuously to 1) and
none at r = 1 (q stays 1).  Then, with psi_b = arccos b,

    Omega = (1/2) arccosh(1/b) = (1/2) artanh(sqrt(1 - b^2)),   phi = 2 Omega,         (H5)
    T* = (2/pi) int (16/3) c^3 dbeta = (16/(3 pi)) int_b^1 c^2 dc / sqrt(1 - c^2)
       = (8/(3 pi)) (arccos b + b sqrt(1 - b^2)) = (4/(3 pi)) (2 psi_b + sin 2 psi_b), (H6)

so slip starts at any torque (b < 1 for every T* > 0) and the contact spins at T* = 4/3
(b = 0), with 4/3 - T* = (4/(3 pi)) (2 chi_b - sin 2 chi_b) ~ (16/(9 pi)) b^3, chi_b =
pi/2 - psi_b = arcsin b, the same cube law as for the cylinders.  The stick traction,
with c^2 = (r^2 + v^2)/(1 + v^2) (which turns the integral into int dv / (r^2 + v^2)), is

    q(r) = (2/pi) arctan[r sqrt(1 - b^2) / sqrt(b^2 - r^2)],   r < b.                (H7)

The slip follows from (H1) on the free face (discs with c < r do not cover r):
u(r, 0) = (2/pi) int_b^r [r arccos(c/r) + c sqrt(r^2 - c^2)/r] beta'(c) dc, or in the Abel
form of ``solvers.abel_fredholm`` (F7) with D(t) = t (arcsech b - arcsech t) (the
half-space kernel of that method alone: no Fredholm part),

    s(r) = 2 u(r, 0) = (4/(pi r)) int_b^r t^2 (arcsech b - arcsech t) / sqrt(r^2 - t^2) dt,  r > b,  (H8)

zero on the stick disc, positive and growing like (r - b)^(3/2) on the annulus.  Both
forms are integrated numerically (no elementary closed form).  The interface shear
sigma_rt(r, 0) = u' - u/r, from the free-face field of (H1) (or from (H8) with
t = r sin(phi): the boundary term vanishes since D(b) = 0, and t (D/t)' = 1/sqrt(1 - t^2)):

    sigma_rt(r, 0) = (2/pi) int_phi_b^(pi/2) sin^2(phi) dphi / sqrt(1 - r^2 sin^2 phi)
                   = (2/(pi r^2)) [K(r^2) - E(r^2) - F(phi_b|r^2) + E(phi_b|r^2)],     (H9)

phi_b = arcsin(b/r), 0 on the stick disc; it grows like (1/pi) ln(1/(1 - r)) at the contact
edge (the traction steps from 1 to 0 there; the cylinders' free side has sigma_rt = 0).

Fields in the bodies: (H2) with (H1) and (H4), c = cos(psi) (dbeta = dpsi / (2 cos psi)),

    u(r, z) = (r/pi) int_0^psi_b G(xi_c) dpsi / cos(psi),  G(xi) = arctan(xi) + xi/(1 + xi^2),  (H10)

xi_c the spheroidal coordinate of (r/c, z/c); the stresses are sigma_zt = du/dz and
sigma_rt = du/dr - u/r of the same integral, with G' = 2/(1 + xi^2)^2 and
d xi/dz = eta (1 + xi^2) / (c (xi^2 + eta^2)), d xi/dr = r xi / (c^2 (xi^2 + eta^2))
(``half_space.fields``).  No cancellation: G is a sum of positive terms.

Energy
------
The pressure never changes and the traction at every r grows with the torque ((H7) grows as
b falls), so the memory rules of ``histories.memory`` (Cattaneo-Mindlin, Masing) hold as
for the cylinders, with b(tau), Omega(tau) and the work against friction of a monotonic
loading W_mono(tau) = 2 pi int_b^1 s r dr.  With (W2) of ``curves.work``,
W_mono = 8 int_b^1 t D(t) arcsech(t) dt, or by the loop-area route W_mono = pi int
(T* dOmega - Omega dT*) along the loading path, in psi (dOmega = dpsi / (2 cos psi),
dT* = (16/(3 pi)) cos^2(psi) dpsi), and integrating int cos^2(psi) artanh(sin psi) by parts:

    W_mono = (8/3) [ (psi_b - b sqrt(1 - b^2)) Omega + 1 - b
                     - int_0^psi_b artanh(sin t) dt ],                                 (H11)
    int_0^psi artanh(sin t) dt = 2 G - Cl2(pi/2 + psi) - Cl2(pi/2 - psi),

G Catalan's constant, Cl2 the Clausen function (int_0^x ln tan(pi/4 + t/2) dt).  For small
psi_b (1 - b -> 0) the terms cancel to O(psi_b^4) and the Taylor series is used instead:
W_mono = (8/3) sum_m w_m psi^(2m) from the series of artanh(sin psi) (Euler numbers),
(2/3) psi^4 - (2/45) psi^6 + (17/840) psi^8 - ...  W_mono grows like (2 pi/3) ln(2/b) as
b -> 0 (spinning).  A closed loop of torque range A dissipates (Masing, as for the
cylinders, rule 5 of ``histories.memory``)

    W(A) = 4 W_mono(A/2) = pi oint T* dOmega = (pi/2) oint T* dphi,                   (H12)

and the half-space dissipates at every amplitude: with 2 psi + sin 2 psi = 3 pi T*/4,
psi = 3 pi T*/16 + O(T*^3), the series of (H11) gives

    W_mono = (27 pi^4 / 32768) T*^4 [1 + (1539 pi^2 / 34560) T*^2 + O(T*^4)],
    W(A)   = (27 pi^4 / 131072) A^4 [1 + (1539 pi^2 / 138240) A^2 + O(A^4)],         (H13)

a fourth-power law (0.0201 A^4), against the cylinders' zero below A = 2 and
(pi^4/3)(A/2 - 1)^3 above.  The tangent compliance of a monotonic branch is

    dOmega/dT* = (dOmega/db) / (dT*/db) = 3 pi / (32 b^3),                            (H14)

3 pi/32 at T* -> 0 (the bonded Reissner-Sagoci disc of radius a: T = (16/3) mu a^3 Omega).

Independent checks (tests/test_half_space.py): every closed form against mpmath quadrature
of the superposition (H2)-(H4) and of the Abel form, the stick condition of the traction
(H7) through the half-space Green's function (``solvers.kernels.halfspace_kernel``), the
torque balance T* = 4 int q r^2 dr, the Taylor coefficients against the closed form in
mpmath, the fields against mpmath quadrature, the equilibrium equation and the interface.
The interface fields (H7)-(H9) are evaluated in ``half_space.interface``.
"""

from __future__ import annotations

import functools
import math
from fractions import Fraction

import numpy as np

from ..criteria import GROSS_SLIP_TORQUE, spinning_deficit
from ..quadrature import gauss_legendre
from ..validation import TORQUE_TOLERANCE as SPIN_TOLERANCE

__all__ = [
    "BONDED_COMPLIANCE",
    "SMALL_AMPLITUDE_COEFFICIENT",
    "SMALL_AMPLITUDE_EXPONENT",
    "SMALL_AMPLITUDE_CORRECTION",
    "clausen2",
    "angles_from_radius",
    "angles_from_torque",
    "torque",
    "torque_gap",
    "rigid_rotation",
    "relative_twist",
    "stick_radius",
    "rotation",
    "loading_work",
    "loading_work_at_radius",
    "dissipation_from_loop_area",
    "compliance",
    "points",
    "state",
]

#: dOmega/dT* of the bonded contact (T* -> 0), eq. (H14) at b = 1.
BONDED_COMPLIANCE = 3.0 * math.pi / 32.0
#: W(A) ~ c A^k as A -> 0, eq. (H13).
SMALL_AMPLITUDE_COEFFICIENT = 27.0 * math.pi**4 / 131072.0
SMALL_AMPLITUDE_EXPONENT = 4
#: Relative correction of (H13): W(A) = c A^4 (1 + k2 A^2 + O(A^4)).
SMALL_AMPLITUDE_CORRECTION = 1539.0 * math.pi**2 / 138240.0

_SCALE = 4.0 / (3.0 * math.pi)  # T* = _SCALE (2 psi + sin 2 psi)
_CATALAN = 0.915965594177219015054603514932384110774
#: psi_b below which W_mono comes from its Taylor series (terms ~ (psi / (pi/2))^(2m) <= 0.26^m);
#: above it the Clausen form cancels by at most ~20x (measured: 5e-15 relative at the switch).
_SERIES_ANGLE = 0.8
_SERIES_TERMS = 44
#: x = 2 psi above which b(tau) is solved in e = pi - x (near spinning).
_SPLIT_X = 0.5 * math.pi
_NEWTON_STEPS = 12


# --------------------------------------------------------------------------- special functions
@functools.lru_cache(maxsize=1)
def _clausen_coefficients() -> np.ndarray:
    """|B_2k| / (2k (2k + 1)!) for k = 1..40 (exact Bernoulli numbers, then float)."""
    bernoulli = [Fraction(1)]
    for m in range(1, 82):  # B_m from sum_{j<=m} C(m+1, j) B_j = 0
        bernoulli.append(-sum(math.comb(m + 1, j) * bernoulli[j] for j in range(m)) / (m + 1))
    return np.array([float(abs(bernoulli[2 * k]) / (2 * k * math.factorial(2 * k + 1))) for k in range(1, 41)])


def clausen2(theta):
    """Cl2(theta) = -int_0^theta ln|2 sin(t/2)| dt for 0 <= theta <= pi (vectorised).

    Cl2(theta) = theta - theta ln(theta) + sum_k |B_2k| theta^(2k+1) / (2k (2k + 1)!): positive
    terms, ratio (theta / (2 pi))^2 <= 1/4, 40 terms (<= 1e-24 relative at theta = pi).  Relative
    accuracy for small theta; absolute ~3e-16 near pi, where Cl2 -> 0 (for Cl2(pi - x) with
    small x use the duplication formula: Cl2(pi - x) = Cl2(x) - Cl2(2x)/2).
    """
    theta = np.asarray(theta, dtype=float)
    x2 = theta * theta
    total = np.zeros_like(theta)
    for c in _clausen_coefficients()[::-1]:
        total = (total + c) * x2
    with np.errstate(divide="ignore", invalid="ignore"):
        log_term = np.where(theta > 0, theta * np.log(np.where(theta > 0, theta, 1.0)), 0.0)
    return theta - log_term + theta * total


def _x_minus_sin(x):
    """x - sin(x) without cancellation for small x (series below 1/2), vectorised."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 0.5
    xs = np.where(small, x, 0.0)
    term, total = xs**3 / 6.0, np.zeros_like(xs)
    for k in range(1, 14):  # x^3/3! - x^5/5! + ...; 13 terms: (1/2)^26 / 27! far below rounding
        total = total + term
        term = -term * xs * xs / ((2 * k + 2) * (2 * k + 3))
    return np.where(small, total, x - np.sin(x))


@functools.lru_cache(maxsize=1)
def _work_series() -> np.ndarray:
    """w_m of W_mono = sum_m w_m psi^(2m), m = 0.._SERIES_TERMS (exact rationals, then float).

    From (H11): artanh(sin psi) = sum_n |E_2n| psi^(2n+1) / (2n+1)! (Euler numbers),
    psi - sin psi cos psi = sum_(n>=1) (-1)^(n+1) 4^n psi^(2n+1) / (2n+1)!,
    1 - cos psi = sum_(m>=1) (-1)^(m+1) psi^(2m) / (2m)!.
    """
    euler = [1]
    for m in range(1, _SERIES_TERMS + 2):
        euler.append(-sum(math.comb(2 * m, 2 * k) * euler[k] for k in range(m)))
    a = [Fraction(abs(e), math.factorial(2 * n + 1)) for n, e in enumerate(euler)]
    p = [Fraction(0)] + [Fraction((-1) ** (n + 1) * 4**n, math.factorial(2 * n + 1)) for n in range(1, len(a))]
    out = [0.0]
    for m in range(1, _SERIES_TERMS + 1):
        product = sum((p[n] * a[m - 1 - n] for n in range(1, m)), Fraction(0))
        value = Fraction(8, 3) * (product / 2 - a[m - 1] / (2 * m) + Fraction((-1) ** (m + 1), math.factorial(2 * m)))
        out.append(float(value))
    return np.array(out)


# --------------------------------------------------------------------------- angles
def angles_from_radius(b):
    """(psi_b, chi_b) = (arccos b, arcsin b), each to full relative accuracy (vectorised)."""
    b = np.asarray(b, dtype=float)
    upper = b > 0.5
    psi = np.where(upper, 2.0 * np.arcsin(np.sqrt(np.maximum(1.0 - b, 0.0) / 2.0)), 0.5 * np.pi - np.arcsin(b))
    chi = np.where(upper, 0.5 * np.pi - psi, np.arcsin(np.clip(b, 0.0, 1.0)))
    return psi, chi


def angles_from_torque(tau):
    """(psi_b, chi_b) of the stick radius at torque 0 <= tau <= 4/3: (H6) inverted.

    x = 2 psi solves x + sin x = 3 pi tau / 4 (Newton from x = y/2, monotone from the left
    since the function is concave); near spinning, e = pi - x = 2 chi solves
    e - sin e = (3 pi / 4)(4/3 - tau) (Newton from cbrt(6 d); convex, one overshoot, then
    monotone), with 4/3 - tau from ``criteria.spinning_deficit`` so that b keeps its
    relative accuracy next to 4/3.  Within 4 ulp of 4/3 (``validation.TORQUE_TOLERANCE``)
    the torque is spinning (chi = 0, b = 0), as in ``solve``.
    """
    tau = np.clip(np.asarray(tau, dtype=float), 0.0, GROSS_SLIP_TORQUE)
    y = tau / _SCALE
    near = y > _SPLIT_X + 1.0  # x > pi/2
    psi, chi = np.empty_like(tau), np.empty_like(tau)
    far = ~near
    if far.any():  # each branch on its own elements only
        yf = y[far]
        x = 0.5 * yf
        for _ in range(_NEWTON_STEPS):
            step = (x + np.sin(x) - yf) / (1.0 + np.cos(x))
            x = x - step
            if np.all(np.abs(step) <= 1e-16 * np.abs(x)):
                break
        psi[far], chi[far] = 0.5 * x, 0.5 * np.pi - 0.5 * x
    if near.any():
        gap = np.asarray(spinning_deficit(tau[near]), dtype=float)
        spinning = gap <= SPIN_TOLERANCE * GROSS_SLIP_TORQUE  # as ``solve``: within 4 ulp of 4/3
        d = np.where(spinning, 0.0, np.maximum(gap, 0.0) / _SCALE)
        e = np.cbrt(6.0 * d)
        for _ in range(_NEWTON_STEPS):
            slope = 2.0 * np.sin(0.5 * e) ** 2
            step = np.divide(_x_minus_sin(e) - d, slope, out=np.zeros_like(e), where=slope > 0)
            e = e - step
            if np.all(np.abs(step) <= 1e-16 * np.abs(e)):
                break
        psi[near], chi[near] = 0.5 * np.pi - 0.5 * e, 0.5 * e
    return psi, chi


def _scalar(value, like):
    return float(value) if np.ndim(like) == 0 else value


# --------------------------------------------------------------------------- curves by radius
def torque(b):
    """T*(b) = (8/(3 pi)) (arccos b + b sqrt(1 - b^2)), eq. (H6); 0 at b = 1, 4/3 at b = 0."""
    psi, _ = angles_from_radius(b)
    return _scalar(_SCALE * (2.0 * psi + np.sin(2.0 * psi)), b)


def torque_gap(b):
    """4/3 - T*(b) = (4/(3 pi)) (2 chi - sin 2 chi), chi = arcsin b, with relative accuracy near b = 0."""
    _, chi = angles_from_radius(b)
    return _scalar(_SCALE * _x_minus_sin(2.0 * chi), b)


def _rotation_from_angles(psi, chi):
    """Omega = artanh(sin psi) / 2 = asinh(tan psi) / 2 (tan psi = 1/tan chi near spinning)."""
    with np.errstate(divide="ignore"):
        tangent = np.where(psi < 0.25 * np.pi, np.tan(psi), 1.0 / np.tan(chi))
    return 0.5 * np.arcsinh(tangent)


def rigid_rotation(b):
    """Omega(b) = arccosh(1/b) / 2 (f p0 / mu), eq. (H5): each body's far-field rotation; +inf at b = 0."""
    psi, chi = angles_from_radius(b)
    return _scalar(_rotation_from_angles(psi, chi), b)


def relative_twist(b):
    """phi(b) = 2 Omega = arccosh(1/b) (f p0 / mu): rotation of the upper body's far field relative to the lower's."""
    return _scalar(2.0 * np.asarray(rigid_rotation(b)), b)


def _work_from_angles(psi, chi):
    """W_mono of (H11) from (psi_b, chi_b): Taylor series below psi_b = 0.8, Clausen form above."""
    psi, chi = np.asarray(psi, dtype=float), np.asarray(chi, dtype=float)
    small = psi < _SERIES_ANGLE
    p2 = np.where(small, psi, 0.0) ** 2
    series = np.zeros_like(p2)
    for c in _work_series()[::-1]:
        series = series * p2 + c
    b, root = np.sin(chi), np.cos(chi)
    omega = _rotation_from_angles(psi, chi)
    with np.errstate(invalid="ignore"):
        # Cl2(pi/2 + psi) + Cl2(pi/2 - psi) = Cl2(pi - chi) + Cl2(chi) = 2 Cl2(chi) - Cl2(2 chi)/2
        # (duplication formula Cl2(2x) = 2 Cl2(x) - 2 Cl2(pi - x)): small arguments only, relative accuracy
        closed = (8.0 / 3.0) * ((psi - b * root) * omega + 2.0 * np.sin(0.5 * psi) ** 2
                               - 2.0 * _CATALAN + 2.0 * clausen2(chi) - 0.5 * clausen2(2.0 * chi))
    closed = np.where(chi <= 0.0, np.inf, closed)
    return np.where(small, series, closed)


def loading_work_at_radius(b):
    """W_mono(b): work against friction of the monotonic loading to stick radius b, eq. (H11)."""
    psi, chi = angles_from_radius(b)
    return _scalar(_work_from_angles(psi, chi), b)


# --------------------------------------------------------------------------- curves by torque
def points(tau):
    """(b, Omega, W_mono) at torques 0 <= tau <= 4/3 (arrays): what the memory rules need."""
    psi, chi = angles_from_torque(tau)
    return np.sin(chi), _rotation_from_angles(psi, chi), _work_from_angles(psi, chi)


def state(tau: float) -> tuple[float, float, float]:
    """(b, Omega, W_mono) at one torque 0 <= tau <= 4/3 (floats): ``points`` in scalar arithmetic.

    The same steps as ``angles_from_torque`` and ``_work_from_angles`` with the ``math``
    module (a few microseconds instead of numpy's per-call overhead on one element);
    tests/test_half_space.py checks that both agree to rounding.
    """
    tau = min(max(float(tau), 0.0), GROSS_SLIP_TORQUE)
    gap = float(spinning_deficit(tau))
    if gap <= SPIN_TOLERANCE * GROSS_SLIP_TORQUE:
        return 0.0, math.inf, math.inf
    y = tau / _SCALE
    if y > _SPLIT_X + 1.0:
        d = gap / _SCALE
        e = (6.0 * d) ** (1.0 / 3.0)
        for _ in range(_NEWTON_STEPS):
            slope = 2.0 * math.sin(0.5 * e) ** 2
            if slope <= 0.0:
                break
            e -= (_x_minus_sin_scalar(e) - d) / slope
        psi, chi = 0.5 * math.pi - 0.5 * e, 0.5 * e
    else:
        x = 0.5 * y
        for _ in range(_NEWTON_STEPS):
            x -= (x + math.sin(x) - y) / (1.0 + math.cos(x))
        psi, chi = 0.5 * x, 0.5 * math.pi - 0.5 * x
    omega = 0.5 * math.asinh(math.tan(psi) if psi < 0.25 * math.pi else 1.0 / math.tan(chi))
    if psi < _SERIES_ANGLE:
        p2, work = psi * psi, 0.0
        for c in _work_series_list()[::-1]:
            work = work * p2 + c
    else:
        b, root = math.sin(chi), math.cos(chi)
        work = (8.0 / 3.0) * ((psi - b * root) * omega + 2.0 * math.sin(0.5 * psi) ** 2 - 2.0 * _CATALAN
                              + 2.0 * _clausen2_scalar(chi) - 0.5 * _clausen2_scalar(2.0 * chi))
    return math.sin(chi), omega, work


def _clausen2_scalar(theta: float) -> float:
    """``clausen2`` for one float (the same series, Python arithmetic)."""
    x2, total = theta * theta, 0.0
    for c in _clausen_list()[::-1]:
        total = (total + c) * x2
    return theta - (theta * math.log(theta) if theta > 0 else 0.0) + theta * total


def _x_minus_sin_scalar(x: float) -> float:
    """``_x_minus_sin`` for one float."""
    if abs(x) >= 0.5:
        return x - math.sin(x)
    term, total = x**3 / 6.0, 0.0
    for k in range(1, 14):
        total += term
        term = -term * x * x / ((2 * k + 2) * (2 * k + 3))
    return total


@functools.lru_cache(maxsize=1)
def _clausen_list() -> list:
    return _clausen_coefficients().tolist()


@functools.lru_cache(maxsize=1)
def _work_series_list() -> list:
    return _work_series().tolist()


def stick_radius(tau):
    """b(T*) for 0 <= T* <= 4/3: (H6) inverted (1 at T* = 0, 0 at 4/3)."""
    _, chi = angles_from_torque(tau)
    return _scalar(np.sin(chi), tau)


def rotation(tau):
    """Omega(T*) of a monotonic loading (f p0 / mu), eq. (H5); +inf at 4/3."""
    psi, chi = angles_from_torque(tau)
    return _scalar(_rotation_from_angles(psi, chi), tau)


def loading_work(tau):
    """W_mono(T*) ((f p0)^2 a^3 / mu), eq. (H11); ~ (27 pi^4/32768) T*^4 for small T*, +inf at 4/3."""
    psi, chi = angles_from_torque(tau)
    return _scalar(_work_from_angles(psi, chi), tau)


def dissipation_from_loop_area(torque_range, nodes: int = 64) -> float:
    """pi times the loop area in the (T*, Omega) plane for range A (the torque-twist route of (H12)).

    pi [2 A Omega(A/2) - 8 int_0^(A/2) Omega dt], the integral as int_b^1 Omega(c) |dT*/dc| dc
    = (8/(3 pi)) int_0^psi_b artanh(sin psi) cos^2(psi) dpsi by Gauss-Legendre in psi (the
    integrand is analytic for psi_b < pi/2): no W_mono formula is used.  Independent of
    (H11) except for (H5), (H6).
    """
    a = float(torque_range)
    tau = 0.5 * a
    if tau <= 0.0:
        return 0.0
    psi_b, chi_b = angles_from_torque(tau)
    psi_b, chi_b = float(psi_b), float(chi_b)
    if chi_b <= 0.0:
        return math.inf
    x, w = gauss_legendre(nodes)
    psi = 0.5 * psi_b * (x + 1.0)
    integral = (8.0 / (3.0 * math.pi)) * 0.5 * psi_b * float(np.sum(w * np.arctanh(np.sin(psi)) * np.cos(psi) ** 2))
    omega = float(_rotation_from_angles(np.array(psi_b), np.array(chi_b)))
    return math.pi * (2.0 * a * omega - 8.0 * integral)


def compliance(tau):
    """dOmega/dT* = 3 pi / (32 b^3) on a monotonic branch at torque tau, eq. (H14); +inf at 4/3."""
    b = np.asarray(stick_radius(tau), dtype=float)
    with np.errstate(divide="ignore"):
        return _scalar(BONDED_COMPLIANCE / b**3, tau)
