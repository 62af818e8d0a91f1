r"""Asymptotic expansions at both ends of partial slip, and their interface fields.

Units: r, x in a; tractions and stresses in f p0; displacements and slip in f p0 a / mu;
omega in f p0 / mu; T* = 2T/(f F a).  The default method (``solvers.abel_fredholm``) is used
between the switches below; beyond them these expansions are exact to rounding.

Small slip: an edge crack (delta = 1 - b -> 0)
---------------------------------------------
With f = sqrt(r) u the torsion equation u_rr + u_r/r - u/r^2 + u_zz = 0 becomes
f_rr + f_zz = (3/4) f / r^2, whose right side is O(delta^2) relative in the boundary
layer x = 1 - r = O(delta).  Write f = T* r^(3/2) z + delta^2 F(X, Y), X = x/delta,
Y = z/delta.  To first order in delta, F is harmonic in the quarter plane with

    F_X = -(3/2) delta F           on X = 0 (free side: u_r - u/r = 0),
    F = 0                          on Y = 0, X > 1 (stick),
    F_Y = -e + X + delta ((3/2) e_0 X - X^2 / 2)   on Y = 0, 0 < X < 1 (traction 1),

e = (T* - 1)/delta = e_0 + delta e_1.  Reflected about X = 0 this is a crack |X| < 1 in a
half plane with a line source -3 F_0(0, Y) delta(X) at first order.  A bounded traction
at the tip (K_III = 0) is, by Green's identity with the weight function
V = Im (zeta^2 - 1)^(-1/2), zeta = X + iY,

    int_-1^1 F_Y / sqrt(1 - X^2) dX = 3 int_0^inf F_0(0, Y) / sqrt(1 + Y^2) dY.

Order 1: e_0 = 2/pi, and the leading field on the crack is
F_0(X, 0) = (1/pi) [sqrt(1 - X^2) - X^2 arccosh(1/|X|)].  Order delta: the right side is
(6/pi^2) [pi/2 - int_0^inf u^2 sech^3 u du], which gives e_1 = 3/8 - 1/4 = 1/8, so

    T* = 1 + (2/pi) delta + delta^2 / 8 + O(delta^3 ln delta).                      (S1)

The rigid rotation is omega = 2 int s r^2 dr (Betti); Green's identity with the crack
field of unit load, U = sqrt(1 + Y^2) - Y on X = 0, gives the first-order slip integral
(int_0^inf U F_0 dY = 5/(6 pi) - pi/32, by quadrature), and

    omega = (2/3) delta^3 + (pi/16) delta^4 + O(delta^5 ln delta).                  (S2)

The work against friction of a monotonic loading follows from (S1), (S2) alone: by the
loop-area identity of ``histories.energy`` (W_mono = pi int (T* domega - omega dT*) along the
loading path; the memory rules), written along the path x in [0, delta] with e(x) = T*(x) - 1,

    W_mono = pi [omega(delta) + int_0^delta (2 e(x) - e(delta)) omega'(x) dx]
           = (2 pi/3) delta^3 + (pi^2/16 + 2/3) delta^4 + O(delta^5 ln delta),

(the integral is (2/(3 pi)) delta^4 with e = (2/pi) x, omega' = 2 x^2 at leading order), and
with delta = (pi/2) e - (pi^3/64) e^2 + O(e^3 ln e) from (S1):

    W_mono = (pi^4/12) e^3 [1 + (1/2 - 3 pi^2/64) e + O(e^2 ln e)],   e = T* - 1.        (S8)

The coefficient 1/2 - 3 pi^2/64 = 0.0373623 replaces a value fitted to the curve table
(0.04); a fit of (W_mono / ((pi^4/12) e^3) - 1)/e = c + e (alpha ln e + beta) + e^2 (gamma ln e
+ kappa) to the Abel-Fredholm work (W2) on 3e-4 <= delta <= 3e-2 gives c = 0.0373638, 1.5e-6
from (S8), with alpha = -2.8 (tests/test_extremes.py; the 30-digit reference at b = 0.999
gives (W/W_0 - 1)/e = 0.0507474714725929, i.e. (g - c)/(e ln e) = -2.856).  Where (S8) is
used (e < 1.3e-5) its relative error is about 2.8 e^2 |ln e| < 6e-9.

The leading-order inner fields (the same crack with the load T* (1 - x) - 1, whose
bounded solution has delta = pi (T* - 1) / (2 T*)) are, with S = sqrt(delta^2 - x^2),

    q(r) = 1 - (2 T*/pi) x arccos(delta / x)               stick side, x > delta,  (S3)
    s(r) = (2 T*/pi) [delta S - x^2 arccosh(delta / x)]    slip annulus, x < delta, (S4)
    sigma_rt(r, 0) = (2 T*/pi) x arccosh(delta / x) - s / (2 r).                   (S5)

Validation (tests/test_extremes.py): against the Abel-Fredholm method at
1 - b in [1e-5, 1e-3], T* - (S1) = delta^3 (A ln delta + B) with A = 0.197, B = -0.425
(so (S1) is exact to 3e-15 at delta = 1e-5 and 3e-18 below 1e-6), omega - (S2) <= 1e-16,
and (S3) is off by at most 0.28 delta^2 (the first-order inner field it omits).

Small stick disc (b -> 0)
-------------------------
The stick disc is a small inclusion in a face carrying traction 1.  In (F2) the mixed
and E_b terms are O(b^3 ln b), so G(t) = 2 Omega - e(t) with e(t) = E_1(t)/t (eq. A3),
and (F3), g(b) = G(b) - arcsech(b) = 0, gives

    Omega = (arcsech b + e(b)) / 2,   omega = Omega - BETA T*,                        (S6)
    4/3 - T* = (16 / (9 pi)) b^3 (1 + O(b^2)),                                       (S7)

i.e. omega = ln(1/b)/2 + (ln 2 + e(0))/2 - (4/3) BETA + O(b^2) (the spinning asymptote).
The traction on the stick disc is the half-space one, q = (2/pi) arctan(r sqrt(1 - b^2) /
sqrt(b^2 - r^2)) + O(b^2); the slip is (F7) with that D(t) = t (2 Omega - arcsech t - e(t)).
sigma_rt(r, 0) is that of spinning (``kernels.spinning_shear``, eq. K5) minus the part of
the Abel integral over the stick disc, ~(1/pi)(phi_b - sin phi_b cos phi_b), phi_b =
arcsin(b/r) (it vanishes at r = b+; ``AbelFredholmSolution.interface_sigma_rt``).  Validation: (S6)
matches the Abel-Fredholm omega to
1.5e-11 at b = 1e-2 and 1e-15 at b = 1e-3.

Switches
--------
* ``ONSET_SCALARS``: 1 - b below which T*, omega (and b from T*) come from (S1), (S2);
  above 1 - b = 2e-5 the Abel-Fredholm T* is good to ~1e-13, below it degrades to ~1e-12
  at 1e-6 while (S1) is exact to 5e-14 at 2e-5.
* ``ONSET_FIELDS``: 1 - b below which the fields are (S3)-(S5) (error <= 0.28 delta^2 <=
  3e-13); the Abel-Fredholm fields are used above (torque balance to ~1e-13 at 1e-6).
* ``SPINNING_SWITCH``: b below which (S6), (S7) and the inner fields are used (their
  errors are O(b^2) <= 1e-16 there; the Abel-Fredholm method agrees to ~1e-15 at 1e-8).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy import special

from .criteria import GROSS_SLIP_TORQUE
from .quadrature import gauss_legendre, gauss_legendre_panels
from .solvers import kernels
from .solvers.abel_fredholm import AbelFredholmSolution
from .special import integrals
from .special.zeros import bessel_j2_zeros

__all__ = [
    "ONSET_SCALARS",
    "ONSET_FIELDS",
    "SPINNING_SWITCH",
    "onset_torque",
    "onset_rotation",
    "onset_slip_width",
    "onset_work",
    "ONSET_WORK_COEFFICIENT",
    "EdgeCrack",
    "edge_crack",
    "small_stick_disc",
    "SmallStickDisc",
    "spinning_rotation_constant",
    "spinning_sigma_rt",
]

#: 1 - b below which T* and omega come from (S1), (S2).
ONSET_SCALARS = 2e-5
#: 1 - b below which the interface fields come from (S3)-(S5).
ONSET_FIELDS = 1e-6
#: b below which the small-stick-disc expansions (S6), (S7) are used.
SPINNING_SWITCH = 1e-8
#: Phase (rad) of J1(lam_N r) per Gauss panel of the Dini moments.
_DINI_PHASE = 20.0


# -- small slip ---------------------------------------------------------------------------
def onset_torque(delta):
    """T*(b) = 1 + (2/pi) delta + delta^2/8 for delta = 1 - b -> 0, eq. (S1)."""
    delta = np.asarray(delta, dtype=float)
    return 1.0 + (2.0 / np.pi) * delta + 0.125 * delta * delta


def onset_rotation(delta):
    """omega = (2/3) delta^3 + (pi/16) delta^4 for delta = 1 - b -> 0, eq. (S2)."""
    delta = np.asarray(delta, dtype=float)
    return delta**3 * (2.0 / 3.0 + (np.pi / 16.0) * delta)


#: The e coefficient of (S8): W_mono = (pi^4/12) e^3 (1 + ONSET_WORK_COEFFICIENT e + O(e^2 ln e)).
ONSET_WORK_COEFFICIENT = 0.5 - 3.0 * math.pi**2 / 64.0


def onset_work(excess):
    """W_mono = (pi^4/12) e^3 (1 + (1/2 - 3 pi^2/64) e) for e = T* - 1 -> 0, eq. (S8)."""
    excess = np.asarray(excess, dtype=float)
    return (np.pi**4 / 12.0) * excess**3 * (1.0 + ONSET_WORK_COEFFICIENT * excess)


def onset_slip_width(excess):
    """delta = 1 - b for T* - 1 = ``excess``: the positive root of (S1), without cancellation."""
    excess = np.asarray(excess, dtype=float)
    slope = 2.0 / np.pi
    return 2.0 * excess / (slope + np.sqrt(slope * slope + 0.5 * excess))


@dataclass(frozen=True)
class EdgeCrack:
    """Small-slip state 0 < 1 - b < ``ONSET_FIELDS``: scalars (S1), (S2), fields (S3)-(S5).

    The same interface as ``solvers.abel_fredholm.AbelFredholmSolution`` (positive torque).
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    n_nodes: int = 0

    @property
    def slip_width(self) -> float:
        return 1.0 - self.stick_radius

    def interface_traction(self, r):
        """q(r) of (S3) on the stick disc, 1 on the slip annulus."""
        r = np.asarray(r, dtype=float)
        delta, x = self.slip_width, 1.0 - r
        stick = x > delta
        xs = np.where(stick, x, 1.0)
        inner = 1.0 - (2.0 * self.torque / np.pi) * xs * np.arccos(np.minimum(delta / xs, 1.0))
        return np.where(stick, inner, 1.0)

    def interface_slip(self, r):
        """s(r) of (S4) on the slip annulus, 0 on the stick disc."""
        r = np.asarray(r, dtype=float)
        delta, x = self.slip_width, 1.0 - r
        slipping = x < delta
        xs = np.where(slipping, x, 0.0)
        root = np.sqrt((delta - xs) * (delta + xs))
        log_term = np.where(xs > 0, xs * xs * np.log((delta + root) / np.where(xs > 0, xs, 1.0)), 0.0)
        return np.where(slipping, (2.0 * self.torque / np.pi) * (delta * root - log_term), 0.0)

    def interface_displacement(self, r):
        return 0.5 * self.interface_slip(r)

    def interface_sigma_rt(self, r):
        """sigma_rt(r, 0) of (S5): 0 on the stick disc and at the free side r = 1."""
        r = np.asarray(r, dtype=float)
        delta, x = self.slip_width, 1.0 - r
        slipping = (x < delta) & (x > 0)
        xs = np.where(slipping, x, delta)
        strain = (2.0 * self.torque / np.pi) * xs * np.arccosh(delta / xs)
        values = strain - self.interface_slip(np.where(slipping, r, 1.0)) / (2.0 * np.where(slipping, r, 1.0))
        return np.where(slipping, values, 0.0)

    def dini_amplitudes(self, n_terms: int) -> np.ndarray:
        """c_n = -(q, J1(lam_n r)) / (lam_n h_n) of the traction (S3) (see ``AbelFredholmSolution``).

        q = 1 - (2 T*/pi)[(pi/2) x - delta] - (2 T*/pi) rem(x) on the stick disc, with
        rem = x arccos(delta/x) - (pi/2) x + delta = O(delta^3/x^2): the first part in
        closed form (eqs. 35, 51 and int_0^b r^2 J1 dr = b^2 J2(lam b)/lam), rem by
        Gauss-Legendre on x in [delta, min(1, 1e5 delta)] (beyond, < 1e-18).
        """
        lam = bessel_j2_zeros(int(n_terms))
        b, delta, scale = self.stick_radius, self.slip_width, 2.0 * self.torque / np.pi
        stick_first = integrals.load_integral_constant(lam, 0.0) - integrals.load_integral_constant(lam, b)
        smooth = (0.5 * np.pi - delta) * stick_first - 0.5 * np.pi * integrals.stick_moment(lam, b)
        x, w = _tip_rule(delta, float(lam[-1]))
        remainder = x * np.arccos(np.minimum(delta / x, 1.0)) - 0.5 * np.pi * x + delta
        weight = w * remainder * (1.0 - x)
        rem = np.zeros(lam.size)
        block = max(1, 2_000_000 // max(1, x.size))
        for start in range(0, lam.size, block):
            rem[start : start + block] = special.j1(np.outer(lam[start : start + block], 1.0 - x)) @ weight
        moments = integrals.load_integral_constant(lam, 0.0) - scale * (smooth + rem)
        return -moments / (lam * integrals.dini_norm(lam))


def _tip_rule(delta: float, lam_max: float):
    """Gauss rule on x in [delta, min(1, 1e5 delta)] for the remainder of (S3) and J1(lam (1 - x)).

    x = delta + u^2 on [delta, 2 delta] (arccos(delta/x) ~ sqrt(x - delta)), then panels
    doubling in x - delta and at most ``_DINI_PHASE`` rad of lam_max x wide.
    """
    top = min(1.0, 1e5 * delta)
    u_nodes, u_weights = gauss_legendre(32)
    u = 0.5 * math.sqrt(delta) * (u_nodes + 1.0)
    first_x = delta + u * u
    first_w = 0.5 * math.sqrt(delta) * u_weights * 2.0 * u
    if top <= 2.0 * delta:
        return first_x, first_w
    cuts = delta + delta * 2.0 ** np.arange(0, math.ceil(math.log2(top / delta)) + 1)
    nodes, weights = gauss_legendre_panels(2.0 * delta, top, _DINI_PHASE / lam_max, cuts)
    return np.concatenate([first_x, nodes]), np.concatenate([first_w, weights])


def edge_crack(stick_radius: float) -> EdgeCrack:
    """The small-slip state for 1 - ``ONSET_FIELDS`` < b < 1."""
    delta = 1.0 - float(stick_radius)
    return EdgeCrack(float(stick_radius), float(onset_torque(delta)), float(onset_rotation(delta)))


# -- small stick disc ---------------------------------------------------------------------
def _rotation_constant(b: float) -> float:
    """Omega = (arcsech b + e(b)) / 2 of (S6), e(t) = E_1(t)/t."""
    e_b = float(kernels.spinning_transform(np.array([b]))[0]) / b if b > 1e-150 else _spin_slope()
    return 0.5 * (float(kernels.arcsech(np.array([b]))[0]) + e_b)


@functools.lru_cache(maxsize=1)
def _spin_slope() -> float:
    """e(0) = lim E_1(t)/t (the spinning-transform table at t = 0)."""
    t = np.array([1e-8])
    return float(kernels.spinning_transform(t)[0] / t[0])


def spinning_rotation_constant() -> float:
    """lim_{b -> 0} [omega - ln(1/b)/2] = (ln 2 + e(0))/2 - (4/3) BETA, from (S6)."""
    return 0.5 * (math.log(2.0) + _spin_slope()) - GROSS_SLIP_TORQUE * kernels.TORQUE_ROTATION


@dataclass(frozen=True)
class SmallStickDisc(AbelFredholmSolution):
    """0 < b < ``SPINNING_SWITCH``: (S6), (S7), the half-space traction and the slip of (F7).

    A ``AbelFredholmSolution`` without Nystrom nodes: its (F7) slip uses D(t) = t (2 Omega -
    arcsech t - (E_1(t) - E_b(t))/t), the mixed term being O(b^3 ln b).
    """

    def interface_traction(self, r):
        r = np.asarray(r, dtype=float)
        b = self.stick_radius
        stick = r < b
        rs = np.where(stick, r, 0.0)
        height = np.sqrt(np.maximum((b - rs) * (b + rs), 0.0))
        inner = (2.0 / np.pi) * np.arctan2(rs * math.sqrt((1.0 - b) * (1.0 + b)), height)
        return np.where(stick, inner, 1.0)

    def dini_amplitudes(self, n_terms: int) -> np.ndarray:
        """Traction 1 minus the stick-disc deficit int_0^b (1 - q) r J1(lam r) dr (~lam b^3)."""
        lam = bessel_j2_zeros(int(n_terms))
        b = self.stick_radius
        x, w = gauss_legendre(32)
        theta = np.pi / 4.0 * (x + 1.0)  # r = b sin(theta), 1 - q = 1 - 2 theta/pi + O(b^2)
        radius = b * np.sin(theta)
        weight = (np.pi / 4.0) * w * (1.0 - 2.0 * theta / np.pi) * radius * b * np.cos(theta)
        deficit = special.j1(np.outer(lam, radius)) @ weight
        moments = integrals.load_integral_constant(lam, 0.0) - deficit
        return -moments / (lam * integrals.dini_norm(lam))


def small_stick_disc(stick_radius: float) -> SmallStickDisc:
    """The state for 0 < b < ``SPINNING_SWITCH`` (positive torque)."""
    b = float(stick_radius)
    omega_big = _rotation_constant(b)
    deficit = 16.0 / (9.0 * np.pi) * b**3
    torque = GROSS_SLIP_TORQUE - deficit
    xi, w = kernels.xi_grid(1.0 - b)
    return SmallStickDisc.without_nodes(
        stick_radius=b,
        torque=torque,
        rigid_rotation=omega_big - kernels.TORQUE_ROTATION * torque,
        rotation_constant=omega_big,
        torque_deficit=deficit,
        xi=xi,
        xi_weights=w,
    )


def spinning_sigma_rt(r):
    """sigma_rt(r, 0) / (f p0) at spinning (b = 0): eq. (K5), 0 at r = 0 and r = 1."""
    return kernels.spinning_shear(r)
