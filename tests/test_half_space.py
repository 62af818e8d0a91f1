"""The half-space model (torsional_contact.half_space) against independent routes.

Every closed form of ``half_space.closed_form`` (H5)-(H14) is checked against mpmath
quadrature of Jaeger's superposition of Reissner-Sagoci disc rotations (H1)-(H4) or of the
Abel form, the traction and rotation against the stick condition through the half-space
Green's function (Hankel transform, elliptic integrals: a route that shares nothing with
the superposition), then the physics (torque balance, stick and slip conditions, limits,
mirror symmetry), the memory rules (loop energy = pi x loop area = frictional work, like
the cylinders), the fields in the bodies, the API, the command line and bad input.
"""

import json
import math
import subprocess
import sys

import mpmath as mp
import numpy as np
import pytest
from tolerances import EPS, ROTATION_ACCURACY, assert_close, assert_within

from torsional_contact import history, solve
from torsional_contact.criteria import spinning_deficit
from torsional_contact.half_space import closed_form as cf
from torsional_contact.half_space import fields as hs_fields
from torsional_contact.half_space import interface as hs_interface
from torsional_contact.half_space.model import UNIFORM_HALF_SPACE
from torsional_contact.histories import analyse_signal, frictional_work
from torsional_contact.histories.energy import dissipation_from_loop_area as cylinder_loop_area
from torsional_contact.histories.energy import dissipation_per_cycle as cylinder_dissipation
from torsional_contact.histories.loops import loop_work, sample_path
from torsional_contact.io.cli import main
from torsional_contact.quadrature import gauss_legendre

RADII = (0.05, 0.3, 0.6, 0.9, 0.99)
DPS = 25
#: Rounding of a closed form of a handful of elementary operations on one float: at most ~10 operations, each
#: faithful (<= 1 ulp; numpy's SIMD transcendental functions <= 4 ulp), on terms of one sign (no cancellation):
#: 10 x 4 EPS relative.
CLOSED_FORM_ROUNDING = 40 * EPS
#: Accuracy of a 25-digit tanh-sinh quadrature of a smooth (or endpoint-singular, but substituted) integrand, in
#: double units: the reference's own error (~1e-25) is far below the double rounding of the value it is compared to.
MP_REFERENCE = 1e-20


# --------------------------------------------------------------------------- mpmath references
def _mp_torque(b):
    """T* = (2/pi) int (16/3) c^3 dbeta with dbeta = dc / (2 c sqrt(1 - c^2)) (H2)-(H4), by quadrature
    (c = cos(psi) removes the endpoint singularity at c = 1, which tanh-sinh resolves only to ~1e-15)."""
    return 2 / mp.pi * mp.quad(lambda p: mp.mpf(16) / 3 * mp.cos(p) ** 3 / (2 * mp.cos(p)), [0, mp.acos(b)])


def _mp_rotation(b):
    """Omega = int_b^1 dbeta (H3), by quadrature in c = cos(psi)."""
    return mp.quad(lambda p: 1 / (2 * mp.cos(p)), [0, mp.acos(b)])


def _mp_traction(r, b):
    """q(r) = (4/pi) r int_max(r,b)^1 beta'(c) dc / sqrt(c^2 - r^2), the superposed disc tractions, by quadrature
    in c = cos(psi) (dc / sqrt(1 - c^2) = dpsi removes the endpoint singularity at c = 1, which tanh-sinh resolves
    only to ~1e-15 at 25 digits; the integrand is then smooth since r < b)."""
    if r >= b:
        return mp.mpf(1)
    return 4 / mp.pi * r * mp.quad(lambda p: 1 / (2 * mp.cos(p) * mp.sqrt(mp.cos(p) ** 2 - r * r)), [0, mp.acos(b)])


def _mp_slip(r, b):
    """2 u(r, 0) = 2 int_b^r [r - U(r, 0; c)] dbeta, U of (H1) on the free face (discs c < r)."""
    if r <= b:
        return mp.mpf(0)

    def integrand(c):
        moved = 2 / mp.pi * (r * mp.asin(c / r) - c * mp.sqrt(r * r - c * c) / r)
        return (r - moved) / (2 * c * mp.sqrt(1 - c * c))

    return 2 * mp.quad(integrand, [b, r])


def _mp_sigma_rt(r, b):
    """sigma_rt(r, 0) = -int (dU/dr - U/r) dbeta over the discs c < r: the free-face shear of (H1),
    (4/pi) c^3 / (r^2 sqrt(r^2 - c^2)) per unit rotation, with c = r sin(theta) (no endpoint singularity)
    and breakpoints where 1/sqrt(1 - c^2) peaks (r -> 1)."""
    def integrand(theta):
        c = r * mp.sin(theta)
        return 4 / mp.pi * c**3 / (r * r) / (2 * c * mp.sqrt(1 - c * c))

    gap = mp.sqrt(1 - r * r)
    cuts = [mp.asin(b / r)] + [mp.pi / 2 - k * gap for k in (100, 10, 1) if mp.pi / 2 - k * gap > mp.asin(b / r)]
    return mp.quad(integrand, cuts + [mp.pi / 2])


def _mp_green(r, rho):
    """int_0^inf J1(k r) J1(k rho) dk: the surface displacement of a half-space per unit ring traction."""
    m1 = ((r - rho) / (r + rho)) ** 2
    if m1 == 0:
        return mp.mpf(0)  # a single node on the (integrable) logarithmic singularity
    m = 1 - m1
    if m < mp.mpf(10) ** (-mp.mp.dps // 2):  # rho << r or r << rho: G ~ min / (2 max^2) (Legendre Q_1/2)
        return min(r, rho) / (2 * max(r, rho) ** 2)
    if m1 < mp.mpf(10) ** (2 - mp.mp.dps):  # 1 - m1 would round to 1: K, E to O(m1 ln m1)
        big_k, big_e = mp.log(4 / mp.sqrt(m1)), mp.mpf(1)
    else:
        big_k, big_e = mp.ellipk(m), mp.ellipe(m)
    return 2 * ((1 - m / 2) * big_k - big_e) / (mp.pi * mp.sqrt(m * r * rho))


def _mp_work_abel(b):
    """W_mono = 8 int_b^1 t D(t) arcsech(t) dt, D = t (arcsech b - arcsech t) (W2 of curves.work)."""
    level = mp.asech(b)
    return 8 * mp.quad(lambda t: t * t * (level - mp.asech(t)) * mp.asech(t), [b, 1])


def _mp_work_area(b):
    """W_mono = pi [T* Omega - 2 int Omega dT*] along the loading path (no W formula): loop-area route."""
    torque = 8 / (3 * mp.pi) * (mp.acos(b) + b * mp.sqrt(1 - b * b))
    integral = mp.quad(lambda c: mp.asech(c) / 2 * 16 / (3 * mp.pi) * c * c / mp.sqrt(1 - c * c), [b, 1])
    return mp.pi * (torque * mp.asech(b) / 2 - 2 * integral)


# --------------------------------------------------------------------------- closed forms
@pytest.mark.parametrize("b", RADII)
def test_torque_rotation_and_work_against_quadrature_of_the_superposition(b):
    with mp.workdps(DPS):
        bm = mp.mpf(b)
        torque, rotation = _mp_torque(bm), _mp_rotation(bm)
        work_abel, work_area = _mp_work_abel(bm), _mp_work_area(bm)
        # two routes, each a 25-digit quadrature (error ~1e-25): they agree far below double precision
        assert_close(work_abel, work_area, "two 25-digit quadratures", rtol=MP_REFERENCE)
    # elementary functions of one float (+ half an ulp for the reference rounded to double)
    rounding = CLOSED_FORM_ROUNDING + EPS / 2
    assert_close(cf.torque(b), float(torque), "closed-form rounding", rtol=rounding)
    assert_close(cf.rigid_rotation(b), float(rotation), "closed-form rounding", rtol=rounding)
    assert_close(cf.relative_twist(b), 2 * float(rotation), "closed-form rounding", rtol=rounding)
    with mp.workdps(DPS):
        gap = float(mp.mpf(4) / 3 - torque)
    # x - sin x, x = 2 chi: a series below x = 1/2, above it x - sin(x) cancels by x / (x - sin x) <= 24
    assert_close(cf.torque_gap(b), gap, "closed-form rounding x cancellation 24", rtol=24 * rounding)
    # (H11): series below psi_b = 0.8, Clausen form above; its terms cancel up to 20x (largest term / W): 20 x
    # the closed-form rounding
    assert_close(cf.loading_work_at_radius(b), float(work_abel), "closed-form rounding x cancellation 20",
                 rtol=20 * rounding)


@pytest.mark.parametrize("b", [1e-3, 0.25, 0.6, 0.87, 0.995])
def test_stick_traction_and_slip_against_the_superposition(b):
    stick = b * np.array([0.0, 0.2, 0.7, 0.99])
    annulus = b + (1 - b) * np.array([1e-6, 0.3, 0.8, 0.9999, 1.0])
    with mp.workdps(DPS):
        q_ref = [float(_mp_traction(mp.mpf(r), mp.mpf(b))) for r in stick]
        s_ref = [float(_mp_slip(mp.mpf(r), mp.mpf(b))) for r in annulus]
        sigma_ref = [float(_mp_sigma_rt(mp.mpf(r), mp.mpf(b))) for r in annulus[:-1]]
    # (H7) q = (2/pi) arctan2(r sqrt((1 - b)(1 + b)), sqrt((b - r)(b + r))) (factored: no cancellation): each
    # argument is 5 faithful operations (<= 5 EPS relative), which move the angle by <= (5 + 5) EPS / 2; arctan2
    # <= 4 ulp of an angle <= pi/2; times 2/pi, plus 2 EPS for the product and half an ulp for the reference:
    # (2/pi)(5 + 4 pi/2) EPS + 2.5 EPS = 10 EPS absolute (f p0).  The reference integrates in c = cos(psi)
    # (25 digits; in c itself tanh-sinh left ~1e-15 at the endpoint singularity, as large as this bound).
    traction_rounding = (2 / np.pi * (5 + 4 * np.pi / 2) + 2.5) * EPS
    assert_close(hs_interface.interface_traction(stick, b), q_ref, "rounding of (H7)", atol=traction_rounding)
    # (H8) by the Gauss quadrature of solvers.interface in psi (analytic integrand, graded nodes): a sum of at
    # most 64 O(slip) terms, rounding 64 EPS of the slip scale, with a 4x allowance for the libm of the integrand
    scale = max(max(s_ref), 1.0)
    assert_close(hs_interface.interface_slip(annulus, b), s_ref, "rounding of a 64-term Gauss sum",
                 atol=4 * 64 * EPS * scale)
    # (H9): graded composite Gauss (24 panels x 16 nodes) on a positive integrand (no cancellation): relative
    # rounding of a positive sum of 384 terms, each a few faithful operations (<= 4 EPS): 384 x 4 EPS
    assert_close(hs_interface.interface_sigma_rt(annulus[:-1], b), sigma_ref, "rounding of a positive Gauss sum",
                 rtol=4 * 384 * EPS)
    assert hs_interface.interface_sigma_rt(1.0, b) == math.inf  # the step of the traction at the contact edge


@pytest.mark.parametrize("b", [0.3, 0.7])
def test_stick_condition_through_the_green_function(b):
    """u(r, 0) = Omega r - int_0^1 q(rho) rho G(r, rho) drho (Hankel transform route): 0 on the stick
    disc, s/2 on the annulus, with q, Omega and s of (H5), (H7), (H8)."""
    with mp.workdps(20):
        bm = mp.mpf(b)
        omega = mp.mpf(cf.rigid_rotation(b))

        def traction(rho):
            if rho >= bm:
                return mp.mpf(1)
            return 2 / mp.pi * mp.atan(rho * mp.sqrt(1 - bm * bm) / mp.sqrt(bm * bm - rho * rho))

        for r in (0.4 * b, 0.9 * b, b + 0.5 * (1 - b), 0.999):
            rm = mp.mpf(r)
            u = omega * rm - mp.quad(lambda rho, rm=rm: traction(rho) * rho * _mp_green(rm, rho),
                                     sorted({mp.mpf(0), rm, bm, mp.mpf(1)}))
            expected = 0.0 if r < b else 0.5 * float(hs_interface.interface_slip(r, b))
            # 20-digit tanh-sinh (breakpoints at the log singularity rho = r) of double-precision q and Omega,
            # against double s: the doubles' rounding (Omega r, s/2 of O(1): CLOSED_FORM_ROUNDING each) carried
            # through the O(1) integral of q rho G, plus half an ulp of the slip
            assert_close(float(u), expected, "rounding of the double inputs (H5), (H7), (H8)",
                         atol=4 * CLOSED_FORM_ROUNDING)


def test_clausen_function_against_mpmath():
    theta = np.array([0.0, 1e-8, 0.3, 1.0, np.pi / 2, 2.5, np.pi - 1e-6, np.pi])
    with mp.workdps(30):
        ref = np.array([float(mp.clsin(2, mp.mpf(t))) for t in theta])
    got = cf.clausen2(theta)
    # theta - theta ln(theta) + a series of positive terms (the closed form's rounding, relative to the largest
    # term |theta ln theta| + theta <= 2 near pi, where Cl_2 -> 0): absolute; relative where one term dominates
    assert_close(got, ref, "closed-form rounding of terms <= 2", atol=2 * CLOSED_FORM_ROUNDING)
    assert_close(got[1:4], ref[1:4], "closed-form rounding (one dominant term)", rtol=CLOSED_FORM_ROUNDING)


def test_work_series_against_the_closed_form_in_mpmath():
    # (H11) Taylor series (psi_b < 1/2) against the Clausen form evaluated with 40 digits (no cancellation left)
    psi = np.array([1e-4, 0.01, 0.2, 0.45, 0.499999])
    with mp.workdps(40):
        ref = []
        for p in psi:
            pm = mp.mpf(p)
            b, root = mp.cos(pm), mp.sin(pm)
            ref.append(float(mp.mpf(8) / 3 * ((pm - b * root) * mp.atanh(root) / 2 + 1 - b - 2 * mp.catalan
                                              + mp.clsin(2, mp.pi / 2 + pm) + mp.clsin(2, mp.pi / 2 - pm))))
    # through the angle itself (no rounding of b = cos psi): the series is exact to rounding
    got = cf._work_from_angles(psi, np.pi / 2 - psi)  # noqa: SLF001 - the angle form, before b rounds
    # ~30 terms of a series with a dominant first term: 30 faithful sums, each <= 1 ulp of the total
    assert_close(got, ref, "rounding of a 30-term series", rtol=30 * EPS + CLOSED_FORM_ROUNDING)
    # and at the float b = cos(psi) (whose rounding moves psi by ~eps/psi relative), against (W2) in mpmath
    with mp.workdps(40):
        ref_b = [float(_mp_work_abel(mp.mpf(float(np.cos(p))))) for p in psi]
    # the closed form at that float b: the series in psi = arccos b (relative rounding of psi ~ EPS, condition
    # of W in psi ~ 3: W ~ psi^4) and its 30 terms
    assert_close(cf.loading_work_at_radius(np.cos(psi)), ref_b, "rounding of a 30-term series in arccos b",
                 rtol=4 * (30 * EPS + CLOSED_FORM_ROUNDING))


def test_inversion_of_the_torque_curve():
    b = np.concatenate([np.geomspace(1e-6, 0.5, 40), 1 - np.geomspace(1e-9, 0.5, 40)])
    tau = cf.torque(b)
    back = cf.stick_radius(tau)
    # conditioning: db/b = (dT*/T*) (T*/ (b |dT*/db|)); T* has a relative rounding of ~eps
    condition = tau / (b * (16 / (3 * np.pi)) * b**2 / np.sqrt((1 - b) * (1 + b)))
    # two closed forms, each rounded (CLOSED_FORM_ROUNDING): T*(b) forward, then the Newton angle and b = cos back;
    # their relative errors in tau move b by (condition + 1) b each
    assert_close(back, b, "conditioning x 2 closed-form roundings",
                 atol=2 * CLOSED_FORM_ROUNDING * (condition + 1) * b)
    # the Newton solution itself: 2 psi + sin 2 psi = 3 pi tau / 4 to a few ulp of tau, across the switch
    # between the two Newton variables (T*(b) itself is ill-conditioned at b -> 1: dT*/T* = db / (2(1 - b)))
    taus = np.concatenate([np.geomspace(1e-300, 1e-3, 50), np.linspace(1e-3, 4 / 3 - 1e-6, 2001)])
    psi, chi = cf.angles_from_torque(taus)
    # the residual of (H6) at the returned angle is the Newton stop (a few ulp of tau) plus the rounding of the
    # residual's own 5 operations on positive terms
    assert_close(4 / (3 * np.pi) * (2 * psi + np.sin(2 * psi)), taus, "Newton stop + closed-form rounding",
                 rtol=CLOSED_FORM_ROUNDING)
    # chi = pi/2 - psi by one subtraction: one ulp of pi/2
    assert_within(np.max(np.abs(psi + chi - np.pi / 2)), np.spacing(np.pi / 2), "one subtraction: one ulp",
                  exact=True)
    near = 4 / 3 - np.geomspace(1e-14, 1e-3, 30)
    gap = cf.torque_gap(cf.stick_radius(near))
    # b ~ gap^(1/3) keeps the relative accuracy of 4/3 - tau (criteria.spinning_deficit), then T*(b) in chi
    # both keep relative accuracy: (condition of T*(b) in chi: 3) x closed-form rounding x cancellation of
    # x - sin x (<= 24, see above)
    assert_close(gap, spinning_deficit(near), "conditioning 3 x closed-form rounding x 24",
                 rtol=3 * 24 * CLOSED_FORM_ROUNDING)
    with mp.workdps(30):
        for t in (1e-3, 0.7, 1.2, 4 / 3 - 1e-9):
            psi = mp.findroot(lambda p, t=t: 8 / (3 * mp.pi) * (p + mp.sin(p) * mp.cos(p)) - mp.mpf(t), 0.7)
            # b = cos(psi) of a Newton angle accurate to a few ulp, relative condition of b in psi: psi tan psi,
            # <= 2 away from b -> 0 (b = 1.3e-3 at 4/3 - 1e-9: the absolute error is what counts there)
            assert_close(cf.stick_radius(t), float(mp.cos(psi)), "Newton angle rounding x conditioning",
                         rtol=2 * CLOSED_FORM_ROUNDING, atol=CLOSED_FORM_ROUNDING)


def _mp_angle(torque):
    """psi_b of (H6) at an mpmath torque, by root finding (independent of the Newton steps of the module)."""
    return mp.findroot(lambda p: 8 / (3 * mp.pi) * (p + mp.sin(p) * mp.cos(p)) - torque, mp.mpf("0.7"))


def test_compliance_against_differences():
    for tau in (0.2, 0.8, 1.3):
        with mp.workdps(30):
            slope = mp.diff(lambda t: mp.asech(mp.cos(_mp_angle(t))) / 2, mp.mpf(tau))
        # (H14) = 3 pi / (32 b^3): the relative rounding of b(tau) times 3, plus 3 operations; mp.diff at 30
        # digits (step 10^-15, its error ~1e-30) is exact to double precision
        assert_close(cf.compliance(tau), float(slope), "3 x rounding of b(tau) + 3 operations",
                     rtol=3 * 2 * CLOSED_FORM_ROUNDING + 3 * EPS)
    # at tau = 0 (b = 1) the constant 3 pi / 32 itself: two faithful operations
    assert_close(cf.compliance(0.0), 3 * math.pi / 32, "two operations", rtol=2 * EPS)


# --------------------------------------------------------------------------- physics and limits
@pytest.mark.parametrize("b", RADII)
def test_torque_balance_stick_and_slip_conditions(b):
    s = solve(stick_radius=b, model="half-space")
    # torque balance: 4 int q r^2 dr; r = b sin(theta) on the stick disc removes the square root at b
    x, w = gauss_legendre(80)
    theta = np.pi / 4 * (x + 1)
    r = b * np.sin(theta)
    stick = 4 * np.sum(np.pi / 4 * w * s.traction(r) * r**2 * b * np.cos(theta))
    # analytic integrand (no singularity left), 80 Gauss nodes: truncation below rounding; rounding of an 80-term
    # positive sum of closed-form values (80 EPS + CLOSED_FORM_ROUNDING) and of the annulus' term
    assert_close(stick + 4 * (1 - b**3) / 3, s.torque, "rounding of an 80-term Gauss sum of (H7)",
                 rtol=80 * EPS + 2 * CLOSED_FORM_ROUNDING)
    inside = np.linspace(0, b, 200, endpoint=False)
    outside = np.linspace(b, 1, 200)[1:]
    assert np.all(s.slip(inside) == 0)
    assert np.all(s.slip(outside) > 0) and np.all(np.diff(s.slip(outside)) > 0)
    q = s.traction(np.linspace(0, 1, 401))
    assert np.all(np.abs(q) <= 1) and np.all(np.diff(s.traction(inside)) >= 0)
    # continuous at r = b: 1 - q ~ (4/pi) sqrt(2 (1 - r/b) b^2 / (1 - b^2)) / ... <= sqrt(1e-12) x (4/pi) / sqrt(1 -
    # b^2) (the square-root rise of (H7)), 1.3e-5 at b = 0.99 (1 - b^2 = 0.02): bound 1e-4, while a jump would be O(1)
    assert_close(s.traction(b * (1 - 1e-12)), 1.0, "square-root rise over 1e-12 of r",
                 atol=10 * 4 / np.pi * np.sqrt(1e-12 / (1 - b * b)))
    assert s.regime == "partial-slip"


def test_limits_small_torque_and_spinning():
    # b -> 1: psi = 3 pi T*/16 = p, Omega = (3 pi/32) T* (bonded disc), 1 - b = p^2/2, each with its next terms
    # (from inverting (H6): psi = p (1 + p^2/3 + 4 p^4/15 + 0.27 p^6), Omega = (p/2)(1 + p^2/2 + 19 p^4/40 + ...),
    # 1 - b = (p^2/2)(1 + 7 p^2/12 + ...)), so that the truncation bound (the next power, coefficient < 1) lies
    # far below the rounding and the tolerance is the closed form's rounding: a truncation with a tenfold margin
    # would have kept the comparison at the size of the neglected term
    tau = np.array([1e-8, 1e-5, 1e-3])
    angle, _ = cf.angles_from_torque(tau)
    p = 3 * np.pi * tau / 16
    assert_close(angle, p * (1 + p**2 / 3 + 4 * p**4 / 15), "truncation p^6 + closed-form rounding",
                 rtol=p**6 + CLOSED_FORM_ROUNDING)
    # 1 - b cancels: b is off by its closed-form rounding (absolute, b ~ 1)
    assert_close(1 - cf.stick_radius(tau), p**2 / 2 * (1 + 7 * p**2 / 12), "truncation p^4 + rounding of b",
                 rtol=p**4, atol=CLOSED_FORM_ROUNDING)
    assert_close(cf.rotation(tau), p / 2 * (1 + p**2 / 2 + 19 * p**4 / 40), "truncation p^6 + closed-form rounding",
                 rtol=p**6 + CLOSED_FORM_ROUNDING)
    # b -> 0: 4/3 - T* = (16/(9 pi)) b^3 (1 + 3 b^2/10 + 9 b^4/56 + 5 b^6/48 + O(b^8)), Omega - ln(2/b)/2 = -b^2/8
    # - 3 b^4/64 - (5/192) b^6 + ... (series of x - sin x at x = 2 arcsin b, and of arcsech b)
    small = np.array([1e-6, 1e-4, 1e-2])
    assert_close(cf.torque_gap(small),
                 16 / (9 * np.pi) * small**3 * (1 + 0.3 * small**2 + 9 * small**4 / 56 + 5 * small**6 / 48),
                 "truncation b^8 + closed-form rounding (series of x - sin x)", rtol=small**8 + CLOSED_FORM_ROUNDING)
    # the difference cancels: both Omega and ln(2/b)/2 carry the closed-form rounding of their size
    assert_close(cf.rigid_rotation(small) - 0.5 * np.log(2 / small), -small**2 / 8 - 3 * small**4 / 64,
                 "truncation b^6 + rounding of Omega and ln(2/b)/2",
                 atol=small**6 + 2 * CLOSED_FORM_ROUNDING * np.log(2 / small))
    assert solve(torque=4 / 3, model="half-space").regime == "gross-slip"
    assert solve(torque=0.0, model="half-space").regime == "stick"
    assert solve(torque=1e-12, model="half-space").regime == "partial-slip"  # slips at any torque
    spin = solve(stick_radius=0.0, model="half-space")
    assert spin.torque == 4 / 3 and spin.rigid_rotation == math.inf
    assert_close(spin.traction([0.0, 0.5, 1.0]), 1.0, "full slip: q = 1, exact", atol=0.0)
    assert np.all(np.isfinite(spin.stress([0.2, 0.8], [0.3, 0.0])[0]))


def test_small_amplitude_energy_law():
    # (H13): W(A) = c A^4 (1 + k A^2 + O(A^4)); the closed form evaluated in 40-digit mpmath as reference
    amplitudes = np.array([1e-3, 1e-2, 0.1])
    with mp.workdps(40):
        ref = []
        for a in amplitudes:
            psi = mp.findroot(lambda p, a=a: 8 / (3 * mp.pi) * (p + mp.sin(p) * mp.cos(p)) - mp.mpf(a) / 2, 0.01)
            ref.append(4 * _mp_work_abel(mp.cos(psi)))
        ratio = [(w / (mp.mpf(27) * mp.pi**4 / 131072 * mp.mpf(a) ** 4) - 1) / mp.mpf(a) ** 2
                 for w, a in zip(ref, amplitudes, strict=True)]
    k = cf.SMALL_AMPLITUDE_CORRECTION
    for a, rho in zip(amplitudes, ratio, strict=True):
        # (W/(c A^4) - 1)/A^2 = k + O(A^2): the 40-digit reference is exact; the truncation is the next coefficient
        # of the series in psi ~ 3 pi A/32 (coefficients of the series of W in psi are below 1) times A^2
        assert_close(float(rho), k, "truncation O(A^2)", atol=a**2)
    w = UNIFORM_HALF_SPACE.energy_per_cycle(amplitudes)
    # the series in psi (30 terms, dominant first term) and the Newton angle (4 x its rounding, W ~ psi^4)
    assert_close(w, [float(x) for x in ref], "rounding of a 30-term series + 4 x angle rounding",
                 rtol=30 * EPS + 4 * CLOSED_FORM_ROUNDING)
    assert cf.SMALL_AMPLITUDE_EXPONENT == 4


def test_mirror_symmetry():
    up, down = solve(torque=0.9, model="half-space"), solve(torque=-0.9, model="half-space")
    assert down.stick_radius == up.stick_radius and down.rigid_rotation == -up.rigid_rotation
    r, z = np.array([0.1, 0.5, 0.95]), np.array([0.0, 0.2, 0.05])
    np.testing.assert_array_equal(down.traction(r), -up.traction(r))
    np.testing.assert_array_equal(down.slip(r), -up.slip(r))
    np.testing.assert_array_equal(down.displacement(r, z), -up.displacement(r, z))
    for a, b in zip(down.stress(r, z), up.stress(r, z), strict=True):
        np.testing.assert_array_equal(a, -b)


# --------------------------------------------------------------------------- fields in the bodies
def _mp_field(r, z, b):
    """(u, sigma_zt, sigma_rt) of (H10) by mpmath quadrature in c (same integrands, 25 digits)."""
    r, z, b = mp.mpf(r), mp.mpf(z), mp.mpf(b)

    def coords(c):
        rho, zeta = r / c, z / c
        p = rho * rho + zeta * zeta - 1
        xi2 = (p + mp.sqrt(p * p + 4 * zeta * zeta)) / 2
        return mp.sqrt(xi2), zeta / mp.sqrt(xi2)

    def weight(c):
        return 1 / (c * mp.sqrt(1 - c * c))

    def u(c):
        xi, _ = coords(c)
        return (mp.atan(xi) + xi / (1 + xi * xi)) * weight(c)

    def zt(c):
        xi, eta = coords(c)
        return eta / (c * (1 + xi * xi) * (xi * xi + eta * eta)) * weight(c)

    def rt(c):
        xi, eta = coords(c)
        return (r / c) * xi / (c * (1 + xi * xi) ** 2 * (xi * xi + eta * eta)) * weight(c)

    cuts = sorted({b, min(max(r, b), mp.mpf(1)), mp.mpf(1)})
    return (r / mp.pi * mp.quad(u, cuts), 2 * r / mp.pi * mp.quad(zt, cuts), 2 * r / mp.pi * mp.quad(rt, cuts))


def _field_rounding(r, z, b):
    """Relative rounding bound of the (H10) quadrature at (r, z): a sum of the rule's N positive terms (the
    integrands of u, sigma_zt, sigma_rt are positive), each a few faithful operations (<= 4 EPS): 4 N EPS, times
    the cancellation of rho - 1 = r/c - 1 at the nodes next to the disc edge c = r (panels graded down to width z
    there: up to 1 + r/z).  The truncation of the rule (each panel at least its width away from the nearest
    singularity: Bernstein ellipse rho >= 5.8, 20 nodes, rho^-40 < 1e-30) is far below."""
    nodes = hs_fields._rule(float(r), float(z), b)[0].size  # noqa: SLF001 - the rule's node count
    return 4 * nodes * EPS * (1 + float(r) / float(z))


def test_field_quadrature_against_mpmath():
    b = 0.6
    points = [(0.3, 0.01), (0.6, 0.001), (0.8, 0.02), (0.99, 0.3), (0.0, 0.5), (0.5, 3.0)]
    s = solve(stick_radius=b, model="half-space")
    for r, z in points:
        with mp.workdps(DPS):
            u, zt, rt = (float(v) for v in _mp_field(r, z, b))
        sigma_zt, sigma_rt = s.stress(r, z)
        # composite Gauss-Legendre graded at the disc edge: its rounding (the 25-digit reference is exact here)
        rounding = _field_rounding(r, z, b) + EPS / 2
        assert_close(float(s.displacement(r, z)), u, "rounding of the field quadrature", rtol=rounding)
        assert_close(float(sigma_zt), zt, "rounding of the field quadrature", rtol=rounding)
        assert_close(float(sigma_rt), rt, "rounding of the field quadrature", rtol=rounding)


@pytest.mark.parametrize("b", [0.2, 0.6, 0.95])
def test_fields_meet_the_interface_and_the_far_field(b):
    s = solve(stick_radius=b, model="half-space")
    r = np.array([0.1 * b, 0.8 * b, b + 0.3 * (1 - b), b + 0.7 * (1 - b)])
    z = 1e-9
    # the fields at z -> 0 tend to the interface closed forms (H7)-(H9), which share no formula with (H10). The
    # stresses move by O(z): |d sigma / dz| <= 300 at these points (an allowance, not derived: the slope grows
    # next to the stick edge; the quadrature's rounding near c = r, where r/c - 1 cancels, keeps a Richardson
    # extrapolation to z = 0 from reaching the rounding of the closed forms)
    sigma_zt, sigma_rt = s.stress(r, z)
    assert_close(sigma_zt, s.traction(r), "O(z) slope allowance 300", atol=300 * z)
    assert_close(sigma_rt, s.stress(r, 0.0)[1], "O(z) slope allowance 300", atol=300 * z)
    rounding = np.array([_field_rounding(x, z, b) for x in r])
    # the displacement: u(r, z) = u(r, 0) + z q(r) + O(z^2) (the O(z^2) is ~1e-18 here), to the rounding
    assert_close(s.displacement(r, z), s.displacement(r, 0.0) + z * s.traction(r), "rounding of the quadrature",
                 rtol=rounding + CLOSED_FORM_ROUNDING)
    # far field: u -> Omega r - T* r / (8 R^3), the field of a point torque on the face (the same as in
    # test_torque_through_every_plane); the next multipole is (a/R)^2 = 2.5e-5 of that term, bounded with a
    # coefficient up to 100
    far_r = np.array([0.3, 0.9])
    big_r = np.hypot(far_r, 200.0)
    point_torque = cf.torque(b) * far_r / (8 * big_r**3)
    assert_close(s.displacement(far_r, 200.0), s.rigid_rotation * far_r - point_torque,
                 "next multipole 100 (a/R)^2 of the point-torque term", atol=100 * point_torque / big_r**2)


def test_fields_satisfy_equilibrium_and_the_stress_strain_law():
    s = solve(stick_radius=0.5, model="half-space")
    r, z, h = np.array([0.3, 0.7, 0.95]), np.array([0.2, 0.05, 0.3]), 1e-4
    u = lambda rr, zz: s.displacement(rr, zz)  # noqa: E731
    sigma_zt, sigma_rt = s.stress(r, z)
    # the rounding of u at these points (the quadrature: relative _field_rounding, |u| <= 1)
    u_rounding = max(_field_rounding(x, y, 0.5) for x, y in zip(r, z, strict=True))

    def derivatives(step):
        du_dz = (u(r, z + step) - u(r, z - step)) / (2 * step)
        du_dr = (u(r + step, z) - u(r - step, z)) / (2 * step)
        lap = ((u(r + step, z) - 2 * u(r, z) + u(r - step, z)) / step**2 + du_dr / r - u(r, z) / r**2
               + (u(r, z + step) - 2 * u(r, z) + u(r, z - step)) / step**2)
        return du_dz, du_dr, lap

    # central differences are O(h^2): Richardson's (4 D(h) - D(2h)) / 3 is O(h^4), and |D(h) - D(2h)| (three times
    # D(h)'s own truncation, the step-doubling estimate) bounds its truncation; the rounding of the differences is
    # u's rounding over the step: 2 u_rounding / h for first differences and 4 u_rounding / h^2 for second ones,
    # times (4 + 1) / 3 for the extrapolation and 1/r for the terms divided by r
    (zt_h, rt_h, lap_h), (zt_2h, rt_2h, lap_2h) = derivatives(h), derivatives(2 * h)
    extrapolate = lambda fine, coarse: (4 * fine - coarse) / 3  # noqa: E731
    first = 2 * u_rounding / h * 5 / 3 / r.min()
    assert_close(sigma_zt, extrapolate(zt_h, zt_2h), "step-doubling estimate + rounding over h",
                 atol=np.abs(zt_h - zt_2h) + first)
    assert_close(sigma_rt, extrapolate(rt_h, rt_2h) - u(r, z) / r, "step-doubling estimate + rounding over h",
                 atol=np.abs(rt_h - rt_2h) + first + u_rounding / r)
    # the torsion equation u_rr + u_r/r - u/r^2 + u_zz = 0
    second = 2 * 4 * u_rounding / h**2 * 5 / 3 + first
    assert_close(extrapolate(lap_h, lap_2h), 0.0, "step-doubling estimate + rounding over h^2",
                 atol=np.abs(lap_h - lap_2h) + second)


@pytest.mark.parametrize("z", [0.05, 0.5])
def test_torque_through_every_plane(z):
    """4 int_0^inf sigma_zt(r, z) r^2 dr = T* at every depth (the fields module with r > a)."""
    b = 0.6
    x, w = gauss_legendre(40)
    edges = np.concatenate([np.linspace(0, 2, 21), np.geomspace(2, 2e4, 25)[1:]])
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        rr = 0.5 * (hi - lo) * (x + 1) + lo
        sigma_zt, _ = hs_fields.stress(rr, np.full(rr.shape, z), b)
        total += 0.5 * (hi - lo) * np.sum(w * sigma_zt * rr**2)
    # beyond R0 = 2e4 the field is that of a point torque on the face, u = T r / (4 pi R^3), whose
    # sigma_zt = 3 T r z / (4 pi R^5) carries (3 z / 2) int_R0^inf r^3 / (r^2 + z^2)^(5/2) dr of the torque
    # (next multipole: a^2 / R0^2 = 2.5e-9 of that, 1e-13 absolute); the Gauss panels: 44 panels x 40 nodes of
    # the field quadrature, each with its rounding (<= 4 x 400 nodes EPS relative), of one sign: 1760 x that
    r0 = edges[-1]
    tail = 1.5 * z * (3 * r0**2 + 2 * z**2) / (3 * (r0**2 + z**2) ** 1.5)
    multipole = 2.5e-9 * tail * cf.torque(b)
    assert_close(4 * total, cf.torque(b) * (1 - tail), "next multipole + rounding of the panels",
                 atol=multipole + 1760 * 4 * 400 * EPS * cf.torque(b))


# --------------------------------------------------------------------------- memory rules and energy
def _dense_loop(amplitude, model, n=400):
    """States along the closed loop +A/2 -> -A/2 -> +A/2 after the first loading (history of dense points)."""
    half = 0.5 * amplitude
    down = np.linspace(half, -half, n)
    path = np.concatenate([[half], down[1:], down[::-1][1:]])
    states = history(path, model=model)
    return states


def _richardson_area(amplitude, model):
    """pi oint T* d(rigid_rotation) by trapezoids on 200 and 400 steps per half loop, extrapolated (O(h^4)), and
    the step-doubling estimate |A_400 - A_200| / 3 of the finer sum's O(h^2) error (which bounds the extrapolated
    value's error, one order smaller)."""
    areas = []
    for n in (201, 401):
        loop = _dense_loop(amplitude, model, n)
        areas.append(loop_work([s.torque for s in loop], [s.rigid_rotation for s in loop]))
    return (4 * areas[1] - areas[0]) / 3, loop, abs(areas[1] - areas[0]) / 3


@pytest.mark.parametrize("amplitude", [0.4, 1.5, 2.4])
def test_loop_energy_is_pi_times_the_loop_area(amplitude):
    """W(A) = 4 W_mono(A/2) = pi oint T* dOmega, with Omega the model's rigid_rotation: the same factor as
    the cylinders, and the frictional work of the interface fields along the loop."""
    area, loop, estimate = _richardson_area(amplitude, "half-space")  # from +A/2 (first loading) round to +A/2
    energy = loop[-1].dissipated_energy - loop[0].dissipated_energy
    # rule 5: sums of W_mono values (closed forms) up to the total dissipated (~800 half loops' worth): the
    # rounding of 800 additions of the total, and the closed form's rounding; the difference of two totals
    total = loop[-1].dissipated_energy
    assert_close(energy, UNIFORM_HALF_SPACE.energy_per_cycle(amplitude), "rounding of the sums of W_mono",
                 atol=2 * (800 * EPS + CLOSED_FORM_ROUNDING) * total)
    assert_close(area, energy, "step-doubling estimate of the trapezoids", atol=estimate)
    # Gauss in psi (64 terms) for int Omega dT*; the two terms cancel to W (up to 60x at A = 0.4)
    assert_close(cf.dissipation_from_loop_area(amplitude), energy, "rounding x cancellation 60",
                 rtol=60 * (64 * EPS + CLOSED_FORM_ROUNDING))
    # Masing: closed, to the rounding of the superposed rotations (a few terms of size <= max |Omega|)
    largest = max(abs(s.rigid_rotation) for s in loop)
    assert_close(loop[-1].rigid_rotation, loop[0].rigid_rotation, "rounding of the superposition",
                 atol=4 * CLOSED_FORM_ROUNDING * largest)
    if amplitude == 1.5:  # the frictional work of q ds over the interface (energy.frictional_work)
        half = 0.5 * amplitude
        works = []
        for n in (11, 21):
            path = np.concatenate([[half], np.linspace(half, -half, n)[1:], np.linspace(-half, half, n)[1:]])
            works.append(frictional_work(history(path, model="half-space")))
        # trapezoids in time, second order: halving the step divides the error by ~4 (a check of the order, not
        # a tolerance: 0.3 leaves room for the O(h^4) term of these coarse sums)
        assert abs(works[1] / energy - 1) < 0.3 * abs(works[0] / energy - 1)
        # extrapolated: bounded by the step-doubling estimate |w_21 - w_11| / 3 of the finer sum's error
        assert_close((4 * works[1] - works[0]) / 3, energy, "step-doubling estimate of the trapezoids in time",
                     atol=abs(works[1] - works[0]) / 3)
    if amplitude > 2:  # the cylinders: the same identity, with their own loop-area route
        cylinder_area, cylinder, cylinder_estimate = _richardson_area(amplitude, "cylinder")
        cyl_energy = cylinder[-1].dissipated_energy - cylinder[0].dissipated_energy
        # the loop-area route pi [2 A omega_m(A/2) - 8 int omega_m dT*] from the Abel-Fredholm curve: each omega
        # within ROTATION_ACCURACY, weights 2 A + 8 (A/2 - 1) <= 6 A, times pi; and W_mono of the same solver
        accuracy = ROTATION_ACCURACY * 6 * np.pi * amplitude
        assert_close(cyl_energy, cylinder_loop_area(amplitude), "rotation accuracy of the curve x weights",
                     atol=accuracy + 2 * 800 * EPS * cylinder[-1].dissipated_energy)
        assert_close(cyl_energy, cylinder_dissipation(amplitude), "rounding of the sums of W_mono",
                     atol=2 * 800 * EPS * cylinder[-1].dissipated_energy)
        assert_close(cylinder_area, cyl_energy, "step-doubling estimate of the trapezoids", atol=cylinder_estimate)


def test_history_states_by_superposition():
    """A state after reversals is sum w_j mono(tau_j); its traction and slip obey the friction law."""
    states = history([1.2, -0.4, 0.8, 0.1], model="half-space")
    r = np.linspace(0, 1, 301)
    for previous, state in zip(states[:-1], states[1:], strict=True):
        q = state.traction(r)
        # superposed tractions: sums of <= 5 closed forms (H7) of size <= 2 each (the weights w_j are +-1, +-2)
        superposed = 5 * 2 * (CLOSED_FORM_ROUNDING + (2 / np.pi * (5 + 4 * np.pi / 2) + 2.5) * EPS)
        assert_within(max(np.max(np.abs(q)) - 1, 0.0), superposed, "Coulomb limit |q| <= 1, to the rounding")
        # on the reverse-slip annulus the traction is -direction x 1 and the slip moved that way
        slipping = r > state.stick_radius
        assert_close(q[slipping], state.direction * 1.0, "rounding of the superposed tractions", atol=superposed)
        ds = state.slip(r) - previous.slip(r)
        assert np.all(state.direction * ds[slipping] > 0)
        # stick: the superposed slips (each 0 exactly on its own stick disc, and the discs nest) cancel exactly
        assert_close(ds[~slipping], 0.0, "nested stick discs: exact zeros", atol=0.0)
    assert all(s.regime == "partial-slip" for s in states)  # every reversal slips
    assert states[0].model == "half-space" and states[0].method is None


def test_signal_analysis_matches_history():
    signal = np.array([0.0, 1.1, -0.3, 0.6, -0.3, 1.2, -1.0, 0.2])
    result = analyse_signal(signal, model="half-space")
    states = history(signal, model="half-space")
    # the same superposition by the signal engine (vectorised) and by history (per state): the same closed forms,
    # summed in another order: sums of <= 8 terms of size <= the largest |value|, each with its closed-form rounding
    largest = max(abs(s.rigid_rotation) for s in states)
    sums = 8 * (CLOSED_FORM_ROUNDING + EPS)
    assert_close(result.rigid_rotation, [states[i].rigid_rotation for i in result.index], "rounding of the sums",
                 atol=sums * largest)
    assert_close(result.stick_radius, [states[i].stick_radius for i in result.index], "closed-form rounding",
                 atol=2 * CLOSED_FORM_ROUNDING)
    total = states[-1].dissipated_energy
    assert_close(result.total_dissipated_energy, total, "rounding of the sums", atol=sums * total)
    assert result.model == "half-space" and result.method is None
    omega, energy = result.sample_values()
    assert_close(energy[-1], total, "rounding of the sums", atol=sums * total)
    assert_close(omega[-1], states[-1].rigid_rotation, "rounding of the sums", atol=sums * largest)


# --------------------------------------------------------------------------- API, default model, errors
def test_default_model_is_unchanged():
    for kwargs in ({"torque": 1.23}, {"stick_radius": 0.6}, {"torque": 0.5}):
        a, b = solve(**kwargs), solve(**kwargs, model="cylinder")
        assert (a.torque, a.stick_radius, a.rigid_rotation, a.regime) == (b.torque, b.stick_radius,
                                                                          b.rigid_rotation, b.regime)
        assert type(a) is type(b)
    h1, h2 = history([1.2, -1.0, 1.1]), history([1.2, -1.0, 1.1], model="cylinder")
    assert [s.as_dict() for s in h1] == [s.as_dict() for s in h2]
    assert h1[0].as_dict()["model"] == "cylinder"


def test_same_attributes_as_the_cylinder_solution():
    s = solve(torque=1.1, model="half-space")
    for name in ("stick_radius", "torque", "rigid_rotation", "regime", "method", "n_terms", "tolerance"):
        assert hasattr(s, name)
    assert s.as_dict()["model"] == "half-space" and s.method is None
    assert s.torque == 1.1
    # the Newton inverse, forward again: two closed-form roundings (conditioning of T* in psi ~ 1 at 1.1)
    assert_close(cf.torque(s.stick_radius), 1.1, "two closed-form roundings", rtol=2 * CLOSED_FORM_ROUNDING)
    r = np.linspace(0, 1, 7).reshape(7, 1)
    assert s.traction(r).shape == (7, 1) and s.slip(r).shape == (7, 1)
    assert s.stress(r, np.full((7, 1), 0.1))[0].shape == (7, 1)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"stick_radius": 1.5}, "stick_radius must lie in"),
        ({"stick_radius": -0.1}, "stick_radius must lie in"),
        ({"torque": 1.4}, "torque must lie in"),
        ({"torque": float("nan")}, "torque must be finite"),
        ({"stick_radius": float("inf")}, "stick_radius must be finite"),
        ({}, "exactly one"),
        ({"torque": 1.0, "stick_radius": 0.5}, "exactly one"),
        ({"torque": 1.0, "method": "published"}, "method='published' applies to models with solution methods only"),
        ({"torque": 1.0, "method": "complete"}, "model='half-space'"),
        ({"torque": 1.0, "n_terms": 145}, "n_terms=145 applies to models with solution methods only"),
        ({"torque": 1.0, "tolerance": -1.0}, "tolerance must lie in"),
    ],
)
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        solve(**kwargs, model="half-space")


def test_bad_model_and_coordinates():
    with pytest.raises(ValueError, match="model must be one of 'cylinder', 'half-space'"):
        solve(torque=1.0, model="halfspace")
    with pytest.raises(ValueError, match="model must be one of"):
        history([1.0], model=3)
    with pytest.raises(ValueError, match="method='fast' applies to models with solution methods only"):
        history([1.0], model="half-space", method="fast")
    s = solve(torque=1.0, model="half-space")
    with pytest.raises(ValueError, match="r must be finite and lie in"):
        s.traction(1.5)
    with pytest.raises(ValueError, match="z must be finite"):
        s.stress(0.5, -1.0)
    with pytest.raises(ValueError, match=r"torque must lie in \[-4/3, 4/3\].*the half-spaces spin"):
        sample_path(history([1.0], model="half-space")[-1], -1.5)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "torsional_contact", *args], capture_output=True, text=True)


def _main(capsys, *args):
    code = main(list(args))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_command_line(capsys):
    out = _cli("solve", "--torque", "1.0", "--model", "half-space", "--radii", "0.5", "1", "--json")
    assert out.returncode == 0, out.stderr
    record = json.loads(out.stdout)
    assert record["model"] == "half-space" and record["method"] is None
    # JSON carries the shortest repr, which reads back to the same double: the same computation, so exact
    assert_close(record["stick_radius"], cf.stick_radius(1.0), "the same computation, repr round trip", atol=0.0)
    slip = float(hs_interface.interface_slip(1.0, record["stick_radius"]))
    # the slip at r = 1 among the radii [0.5, 1] or alone: the same Gauss sums (bincount per radius)
    assert_close(record["slip"][1], slip, "rounding of a 64-term Gauss sum (see above)", atol=4 * 64 * EPS * slip)
    code, text, _ = _main(capsys, "solve", "--torque", "1.23", "--json")
    assert code == 0 and json.loads(text)["model"] == "cylinder"
    code, text, _ = _main(capsys, "history", "--turning-points", "0", "1.0", "-0.5", "--model", "half-space", "--json")
    states = json.loads(text)
    assert [s["model"] for s in states] == ["half-space"] * 3
    assert_close(states[-1]["dissipated_energy"], history([0, 1.0, -0.5], model="half-space")[-1].dissipated_energy,
                 "the same computation, repr round trip", atol=0.0)
    for args in (("solve", "--torque", "1.0", "--model", "wedge"),
                 ("solve", "--torque", "1.0", "--model", "half-space", "--method", "complete"),
                 ("solve", "--torque", "1.0", "--model", "half-space", "--n-terms", "145"),
                 ("history", "--turning-points", "0", "1.5", "--model", "half-space")):
        code, text, err = _main(capsys, *args)
        assert code == 2 and text == "" and len(err.strip().splitlines()) == 1, args


@pytest.mark.parametrize("b", [0.1, 0.5, 0.9])
def test_direct_numerical_solution_of_the_slip_condition(b):
    """Solve the slip condition of the superposition, int_r^1 beta'(c) dc / sqrt(c^2 - r^2) = pi / (4 r) on
    b < r < 1, by collocation (no Abel inversion): beta' = g(c) / sqrt(1 - c^2) with g a Chebyshev series on
    [b, 1]; c^2 = r^2 + (1 - r^2) sin^2(theta) turns the operator into int_0^(pi/2) g(c) / c dtheta."""
    # g = 1/(2c) has its pole at c = 0, x = -1 - 2b/(1 - b): Bernstein rho = 1.9 at b = 0.1, 64 terms ~1e-16
    n = 64
    nodes = np.cos(np.pi * (np.arange(n) + 0.5) / n)  # collocation points in [-1, 1]
    r = b + 0.5 * (1 - b) * (nodes + 1)
    x, w = gauss_legendre(160)
    theta = np.pi / 4 * (x + 1)
    c = np.sqrt(r[:, None] ** 2 + (1 - r[:, None] ** 2) * np.sin(theta[None, :]) ** 2)
    basis = np.polynomial.chebyshev.chebvander(2 * (c - b) / (1 - b) - 1, n - 1)  # (n, 64, n)
    matrix = np.einsum("jqk,q->jk", basis / c[:, :, None], np.pi / 4 * w)
    coefficients = np.linalg.solve(matrix, np.pi / (4 * r))
    # Omega = int_b^1 g / sqrt(1 - c^2) dc and T* = (32/(3 pi)) int_b^1 c^3 g / sqrt(1 - c^2) dc, c = cos(phi)
    phi = 0.5 * np.arccos(b) * (x + 1)
    cc = np.cos(phi)
    g = np.polynomial.chebyshev.chebval(2 * (cc - b) / (1 - b) - 1, coefficients)
    omega = 0.5 * np.arccos(b) * np.sum(w * g)
    torque = 32 / (3 * np.pi) * 0.5 * np.arccos(b) * np.sum(w * cc**3 * g)
    # the forward error of the collocation solve: its matrix entries are 160-term Gauss sums of terms |T_k| / c
    # <= 1/b (relative rounding 160 EPS of the row sums of |entries|), and LU adds n EPS times partial pivoting's
    # growth factor (O(1) for this smooth, well-scaled matrix; not computed), so the coefficients' error is
    # cond_2(matrix) (160 + n) EPS of their norm; g sums n of them
    # (<= sum |a_k| / min |g|, min |g| = 1/2).  The truncation (Bernstein rho >= 1.9 at b = 0.1: rho^-64 < 1e-17)
    # and the 160-point Gauss rules of the analytic integrands are far below.
    coefficient_error = np.linalg.cond(matrix) * (160 + n) * EPS
    g_error = coefficient_error * np.sum(np.abs(coefficients)) / 0.5
    assert_close(g, 0.5 / cc, "cond(matrix) x (160 + n) EPS x sum |a_k| / min g", rtol=g_error)
    # Omega and T* integrate g over 160 Gauss nodes (positive weights): g's relative error plus the sum's rounding
    assert_close(omega, cf.rigid_rotation(b), "g's error + 160-term Gauss sum", rtol=g_error + 160 * EPS)
    assert_close(torque, cf.torque(b), "g's error + 160-term Gauss sum", rtol=g_error + 160 * EPS)


def test_apparent_friction_of_a_half_space_fit():
    """kappa = f_fit / f solves kappa^2 W_hs(A / kappa) = W_cyl(A) (comparison.(C1)); > 1, falling with A."""
    from torsional_contact.model_comparison import apparent_friction_ratio, energy_per_cycle

    ranges = np.array([2.01, 2.2, 2.4, 2.6, 2.66])
    kappa = np.array([apparent_friction_ratio(a) for a in ranges])
    for a, k in zip(ranges, kappa, strict=True):
        fitted = k * k * energy_per_cycle(a / k, "half-space")
        # Brent to xtol 1e-14 in ln kappa: the residual moves by (slope - 2) x 1e-14 (slope = d ln W_hs / d ln A at
        # A / kappa, by a central difference), plus the rounding of W_hs (a closed form) and of the cylinders' W
        # (sums of W_mono: 64 EPS as in tests/test_history.py)
        h = 1e-4
        up, down = (UNIFORM_HALF_SPACE.energy_per_cycle(a / k * (1 + h)),
                    UNIFORM_HALF_SPACE.energy_per_cycle(a / k * (1 - h)))
        slope = math.log(up / down) / (math.log1p(h) - math.log1p(-h))
        assert_close(fitted, energy_per_cycle(a, "cylinder"), "Brent's xtol x slope + rounding",
                     rtol=abs(slope - 2) * 1e-14 * 2 + 2 * CLOSED_FORM_ROUNDING + 64 * EPS)
    assert np.all(kappa > 1) and np.all(np.diff(kappa) < 0)
    assert apparent_friction_ratio(1.5) == math.inf and apparent_friction_ratio(2.0) == math.inf
    assert apparent_friction_ratio(8 / 3) == 1.0
    # the uniqueness argument: the logarithmic slope of W_hs is >= 4 (its small-amplitude value)
    x = np.linspace(1e-3, 8 / 3 - 1e-6, 4000)
    slope = np.gradient(np.log(UNIFORM_HALF_SPACE.energy_per_cycle(x)), np.log(x))
    # centred differences on the grid (step h ~ 2e-3 in ln x, nonuniform): O(h^2) |d^3 ln W / d(ln x)^3| / 6, the
    # third derivative bounded by 100 (an allowance: ln W is smooth on the grid and its slope rises only near 8/3)
    assert_within(max(4 - float(np.min(slope)), 0.0), 100 * 2e-3**2 / 6, "O(h^2) of the centred differences")
    with pytest.raises(ValueError, match="torque_range must lie in"):
        apparent_friction_ratio(3.0)
    with pytest.raises(ValueError, match="model must be one of"):
        energy_per_cycle(1.0, "wedge")
