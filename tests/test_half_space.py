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

from torsional_contact import history, solve
from torsional_contact.criteria import spinning_deficit
from torsional_contact.half_space import closed_form as cf
from torsional_contact.half_space import fields as hs_fields
from torsional_contact.half_space import interface as hs_interface
from torsional_contact.histories import analyse_signal, frictional_work
from torsional_contact.histories.energy import dissipation_from_loop_area as cylinder_loop_area
from torsional_contact.histories.energy import dissipation_per_cycle as cylinder_dissipation
from torsional_contact.histories.loops import loop_work, sample_path
from torsional_contact.io.cli import main
from torsional_contact.quadrature import gauss_legendre

EPS = np.finfo(float).eps
RADII = (0.05, 0.3, 0.6, 0.9, 0.99)
DPS = 25


# --------------------------------------------------------------------------- mpmath references
def _mp_torque(b):
    """T* = (2/pi) int (16/3) c^3 dbeta with dbeta = dc / (2 c sqrt(1 - c^2)) (H2)-(H4), by quadrature
    (c = cos(psi) removes the endpoint singularity at c = 1, which tanh-sinh resolves only to ~1e-15)."""
    return 2 / mp.pi * mp.quad(lambda p: mp.mpf(16) / 3 * mp.cos(p) ** 3 / (2 * mp.cos(p)), [0, mp.acos(b)])


def _mp_rotation(b):
    """Omega = int_b^1 dbeta (H3), by quadrature in c = cos(psi)."""
    return mp.quad(lambda p: 1 / (2 * mp.cos(p)), [0, mp.acos(b)])


def _mp_traction(r, b):
    """q(r) = (4/pi) r int_max(r,b)^1 beta'(c) dc / sqrt(c^2 - r^2), the superposed disc tractions."""
    if r >= b:
        return mp.mpf(1)
    return 4 / mp.pi * r * mp.quad(lambda c: 1 / (2 * c * mp.sqrt(1 - c * c) * mp.sqrt(c * c - r * r)), [b, 1])


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
        assert abs(work_abel - work_area) < mp.mpf(10) ** (-20) * work_abel  # two exact routes agree
    # Elementary functions of one float: measured <= 9e-16 relative (4 eps, 4/3 - T* included); 1e-14 (10x+)
    assert cf.torque(b) == pytest.approx(float(torque), rel=1e-14, abs=0)
    assert cf.rigid_rotation(b) == pytest.approx(float(rotation), rel=1e-14, abs=0)
    assert cf.relative_twist(b) == pytest.approx(2 * float(rotation), rel=1e-14, abs=0)
    with mp.workdps(DPS):
        gap = float(mp.mpf(4) / 3 - torque)
    assert cf.torque_gap(b) == pytest.approx(gap, rel=1e-14, abs=0)
    # (H11): series below psi_b = 0.8, Clausen form above (cancels ~20x): measured <= 6e-16; 1e-13
    assert cf.loading_work_at_radius(b) == pytest.approx(float(work_abel), rel=1e-13, abs=0)


@pytest.mark.parametrize("b", [1e-3, 0.25, 0.6, 0.87, 0.995])
def test_stick_traction_and_slip_against_the_superposition(b):
    stick = b * np.array([0.0, 0.2, 0.7, 0.99])
    annulus = b + (1 - b) * np.array([1e-6, 0.3, 0.8, 0.9999, 1.0])
    with mp.workdps(DPS):
        q_ref = [float(_mp_traction(mp.mpf(r), mp.mpf(b))) for r in stick]
        s_ref = [float(_mp_slip(mp.mpf(r), mp.mpf(b))) for r in annulus]
        sigma_ref = [float(_mp_sigma_rt(mp.mpf(r), mp.mpf(b))) for r in annulus[:-1]]
    # (H7): arctan of a ratio of square roots, ~6 eps; 2e-14 absolute (f p0) is 10x above the worst seen
    np.testing.assert_allclose(hs_interface.interface_traction(stick, b), q_ref, rtol=0, atol=2e-14)
    # (H8) by the slip quadrature of solvers.interface: ~1e-14 of the slip scale; 1e-13 absolute
    scale = max(s_ref)
    np.testing.assert_allclose(hs_interface.interface_slip(annulus, b), s_ref, rtol=0, atol=1e-13 * max(1.0, scale))
    # (H9): graded Gauss on a positive integrand; measured <= 4.4e-16 (sigma_rt up to ~3): 5e-15 absolute
    np.testing.assert_allclose(hs_interface.interface_sigma_rt(annulus[:-1], b), sigma_ref, rtol=0, atol=5e-15)
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
            # tanh-sinh at 20 digits on the log singularity, against double-precision q, Omega and s:
            # measured <= 2e-16
            assert float(u) == pytest.approx(expected, abs=1e-14)


def test_clausen_function_against_mpmath():
    theta = np.array([0.0, 1e-8, 0.3, 1.0, np.pi / 2, 2.5, np.pi - 1e-6, np.pi])
    with mp.workdps(30):
        ref = np.array([float(mp.clsin(2, mp.mpf(t))) for t in theta])
    got = cf.clausen2(theta)
    # theta - theta ln(theta) + positive series: rounding ~eps |theta ln theta| <= 2e-16 absolute near pi,
    # relative ~ a few eps for small theta (single terms dominate); 10x margins
    np.testing.assert_allclose(got, ref, rtol=0, atol=3e-15)
    np.testing.assert_allclose(got[1:4], ref[1:4], rtol=2e-15)


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
    np.testing.assert_allclose(got, ref, rtol=1e-14)  # ~30 positive-ish terms; measured 2e-16
    # and at the float b = cos(psi) (whose rounding moves psi by ~eps/psi relative), against (W2) in mpmath
    with mp.workdps(40):
        ref_b = [float(_mp_work_abel(mp.mpf(float(np.cos(p))))) for p in psi]
    np.testing.assert_allclose(cf.loading_work_at_radius(np.cos(psi)), ref_b, rtol=1e-13)


def test_inversion_of_the_torque_curve():
    b = np.concatenate([np.geomspace(1e-6, 0.5, 40), 1 - np.geomspace(1e-9, 0.5, 40)])
    tau = cf.torque(b)
    back = cf.stick_radius(tau)
    # conditioning: db/b = (dT*/T*) (T*/ (b |dT*/db|)); T* has a relative rounding of ~eps
    condition = tau / (b * (16 / (3 * np.pi)) * b**2 / np.sqrt((1 - b) * (1 + b)))
    # measured <= 6.7 eps x (condition + 1) b; 100 eps
    assert np.all(np.abs(back - b) <= 100 * EPS * (condition * b + b))
    # the Newton solution itself: 2 psi + sin 2 psi = 3 pi tau / 4 to a few ulp of tau, across the switch
    # between the two Newton variables (T*(b) itself is ill-conditioned at b -> 1: dT*/T* = db / (2(1 - b)))
    taus = np.concatenate([np.geomspace(1e-300, 1e-3, 50), np.linspace(1e-3, 4 / 3 - 1e-6, 2001)])
    psi, chi = cf.angles_from_torque(taus)
    np.testing.assert_allclose(4 / (3 * np.pi) * (2 * psi + np.sin(2 * psi)), taus, rtol=4 * EPS)
    np.testing.assert_allclose(psi + chi, np.pi / 2, rtol=EPS)
    near = 4 / 3 - np.geomspace(1e-14, 1e-3, 30)
    gap = cf.torque_gap(cf.stick_radius(near))
    # b ~ gap^(1/3) keeps the relative accuracy of 4/3 - tau (criteria.spinning_deficit), then T*(b) in chi
    np.testing.assert_allclose(gap, spinning_deficit(near), rtol=1e-13)
    with mp.workdps(30):
        for t in (1e-3, 0.7, 1.2, 4 / 3 - 1e-9):
            psi = mp.findroot(lambda p, t=t: 8 / (3 * mp.pi) * (p + mp.sin(p) * mp.cos(p)) - mp.mpf(t), 0.7)
            assert cf.stick_radius(t) == pytest.approx(float(mp.cos(psi)), rel=1e-14, abs=0)  # measured <= 2.2e-16


def _mp_angle(torque):
    """psi_b of (H6) at an mpmath torque, by root finding (independent of the Newton steps of the module)."""
    return mp.findroot(lambda p: 8 / (3 * mp.pi) * (p + mp.sin(p) * mp.cos(p)) - torque, mp.mpf("0.7"))


def test_compliance_against_differences():
    for tau in (0.2, 0.8, 1.3):
        with mp.workdps(30):
            slope = mp.diff(lambda t: mp.asech(mp.cos(_mp_angle(t))) / 2, mp.mpf(tau))
        # (H14) = 3 pi / (32 b^3): the rounding of b(tau) times 3; measured <= 1e-15
        assert cf.compliance(tau) == pytest.approx(float(slope), rel=1e-13, abs=0)
    assert cf.compliance(0.0) == pytest.approx(3 * math.pi / 32, rel=1e-15, abs=0)


# --------------------------------------------------------------------------- physics and limits
@pytest.mark.parametrize("b", RADII)
def test_torque_balance_stick_and_slip_conditions(b):
    s = solve(stick_radius=b, model="half-space")
    # torque balance: 4 int q r^2 dr; r = b sin(theta) on the stick disc removes the square root at b
    x, w = gauss_legendre(80)
    theta = np.pi / 4 * (x + 1)
    r = b * np.sin(theta)
    stick = 4 * np.sum(np.pi / 4 * w * s.traction(r) * r**2 * b * np.cos(theta))
    assert stick + 4 * (1 - b**3) / 3 == pytest.approx(s.torque, rel=1e-13, abs=0)  # analytic integrand: rounding
    inside = np.linspace(0, b, 200, endpoint=False)
    outside = np.linspace(b, 1, 200)[1:]
    assert np.all(s.slip(inside) == 0)
    assert np.all(s.slip(outside) > 0) and np.all(np.diff(s.slip(outside)) > 0)
    q = s.traction(np.linspace(0, 1, 401))
    assert np.all(np.abs(q) <= 1) and np.all(np.diff(s.traction(inside)) >= 0)
    assert s.traction(b * (1 - 1e-12)) == pytest.approx(1.0, abs=1e-5)  # continuous at r = b (sqrt rise)
    assert s.regime == "partial-slip"


def test_limits_small_torque_and_spinning():
    # b -> 1: psi = 3 pi T*/16, Omega = (3 pi/32) T* (bonded disc), 1 - b = psi^2/2
    tau = np.array([1e-8, 1e-5, 1e-3])
    angle, _ = cf.angles_from_torque(tau)
    psi = 3 * np.pi * tau / 16
    np.testing.assert_allclose(angle, psi, rtol=1e-6)  # psi = 3 pi T*/16 (1 + psi^2/3 + ...): < 4e-7 here
    np.testing.assert_allclose(1 - cf.stick_radius(tau[1:]), psi[1:] ** 2 / 2, rtol=1e-5)
    np.testing.assert_allclose(cf.rotation(tau), 3 * np.pi * tau / 32, rtol=1e-5)
    # b -> 0: 4/3 - T* ~ (16/(9 pi)) b^3, Omega - ln(2/b)/2 -> 0, W_mono ~ (2 pi/3) ln(2/b)
    small = np.array([1e-6, 1e-4, 1e-2])
    np.testing.assert_allclose(cf.torque_gap(small), 16 / (9 * np.pi) * small**3, rtol=1e-3)  # O(b^2) relative
    np.testing.assert_allclose(cf.rigid_rotation(small) - 0.5 * np.log(2 / small), -small**2 / 8, rtol=1e-3,
                               atol=1e-15)
    assert solve(torque=4 / 3, model="half-space").regime == "gross-slip"
    assert solve(torque=0.0, model="half-space").regime == "stick"
    assert solve(torque=1e-12, model="half-space").regime == "partial-slip"  # slips at any torque
    spin = solve(stick_radius=0.0, model="half-space")
    assert spin.torque == 4 / 3 and spin.rigid_rotation == math.inf
    np.testing.assert_allclose(spin.traction([0.0, 0.5, 1.0]), 1.0)
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
        assert float(rho) == pytest.approx(k, abs=0.2 * a**2)  # the O(A^4) term: measured 0.0123 A^2
    w = cf.dissipation_per_cycle(amplitudes)
    np.testing.assert_allclose(w, [float(x) for x in ref], rtol=1e-14)  # series in psi: measured 6e-16
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


def test_field_quadrature_against_mpmath():
    b = 0.6
    points = [(0.3, 0.01), (0.6, 0.001), (0.8, 0.02), (0.99, 0.3), (0.0, 0.5), (0.5, 3.0)]
    s = solve(stick_radius=b, model="half-space")
    for r, z in points:
        with mp.workdps(DPS):
            u, zt, rt = (float(v) for v in _mp_field(r, z, b))
        sigma_zt, sigma_rt = s.stress(r, z)
        # composite Gauss-Legendre graded at the disc edge: measured 1e-15; 1e-13 absolute
        assert float(s.displacement(r, z)) == pytest.approx(u, abs=1e-13)
        assert float(sigma_zt) == pytest.approx(zt, abs=1e-13)
        assert float(sigma_rt) == pytest.approx(rt, abs=1e-13)


@pytest.mark.parametrize("b", [0.2, 0.6, 0.95])
def test_fields_meet_the_interface_and_the_far_field(b):
    s = solve(stick_radius=b, model="half-space")
    r = np.array([0.1 * b, 0.8 * b, b + 0.3 * (1 - b), b + 0.7 * (1 - b)])
    z = 1e-9
    sigma_zt, sigma_rt = s.stress(r, z)
    # the fields at z -> 0 tend to the interface closed forms (H7)-(H9), which share no formula with (H10):
    # stresses to O(z) (measured |d sigma / dz| <= 26 at these points, next to the stick edge), the
    # displacement to O(z^2) beyond u(r, 0) + z q(r) (measured 3e-16 at z = 1e-9)
    np.testing.assert_allclose(sigma_zt, s.traction(r), rtol=0, atol=300 * z)
    np.testing.assert_allclose(sigma_rt, s.stress(r, 0.0)[1], rtol=0, atol=300 * z)
    np.testing.assert_allclose(s.displacement(r, z), s.displacement(r, 0.0) + z * s.traction(r), rtol=0, atol=1e-14)
    # far field: u -> Omega r; each disc's field decays like (c/R)^3, relative <= (1/200)^3 = 1.3e-7
    far = s.displacement(np.array([0.3, 0.9]), 200.0)
    np.testing.assert_allclose(far, s.rigid_rotation * np.array([0.3, 0.9]), rtol=1.3e-6)


def test_fields_satisfy_equilibrium_and_the_stress_strain_law():
    s = solve(stick_radius=0.5, model="half-space")
    r, z, h = np.array([0.3, 0.7, 0.95]), np.array([0.2, 0.05, 0.3]), 1e-4
    u = lambda rr, zz: s.displacement(rr, zz)  # noqa: E731
    sigma_zt, sigma_rt = s.stress(r, z)
    du_dz = (u(r, z + h) - u(r, z - h)) / (2 * h)
    du_dr = (u(r + h, z) - u(r - h, z)) / (2 * h)
    # central differences: h^2 u_zzz / 6 ~ 1e-8 (u_zzz ~ 1/z^3 at z = 0.05; measured 7e-9), rounding 1e-12
    np.testing.assert_allclose(sigma_zt, du_dz, atol=1e-7)
    np.testing.assert_allclose(sigma_rt, du_dr - u(r, z) / r, atol=1e-7)
    # the torsion equation u_rr + u_r/r - u/r^2 + u_zz = 0
    lap = ((u(r + h, z) - 2 * u(r, z) + u(r - h, z)) / h**2 + du_dr / r - u(r, z) / r**2
           + (u(r, z + h) - 2 * u(r, z) + u(r, z - h)) / h**2)
    # second differences: rounding ~4 eps |u| / h^2 ~ 4e-8 (measured 6.5e-8), truncation h^2 u_zzzz ~ 1e-8
    np.testing.assert_allclose(lap, 0.0, atol=1e-6)


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
    # (next multipole: a^2 / R0^2 = 2.5e-9 of that, 1e-13); Gauss panels: measured <= 5e-14
    r0 = edges[-1]
    tail = 1.5 * z * (3 * r0**2 + 2 * z**2) / (3 * (r0**2 + z**2) ** 1.5)
    assert 4 * total == pytest.approx(cf.torque(b) * (1 - tail), abs=1e-12)


# --------------------------------------------------------------------------- memory rules and energy
def _dense_loop(amplitude, model, n=400):
    """States along the closed loop +A/2 -> -A/2 -> +A/2 after the first loading (history of dense points)."""
    half = 0.5 * amplitude
    down = np.linspace(half, -half, n)
    path = np.concatenate([[half], down[1:], down[::-1][1:]])
    states = history(path, model=model)
    return states


def _richardson_area(amplitude, model):
    """pi oint T* d(rigid_rotation) by trapezoids on 200 and 400 steps per half loop, extrapolated (O(h^4))."""
    areas = []
    for n in (201, 401):
        loop = _dense_loop(amplitude, model, n)
        areas.append(loop_work([s.torque for s in loop], [s.rigid_rotation for s in loop]))
    return (4 * areas[1] - areas[0]) / 3, loop


@pytest.mark.parametrize("amplitude", [0.4, 1.5, 2.4])
def test_loop_energy_is_pi_times_the_loop_area(amplitude):
    """W(A) = 4 W_mono(A/2) = pi oint T* dOmega, with Omega the model's rigid_rotation: the same factor as
    the cylinders, and the frictional work of the interface fields along the loop."""
    area, loop = _richardson_area(amplitude, "half-space")  # from +A/2 (first loading) round to +A/2
    energy = loop[-1].dissipated_energy - loop[0].dissipated_energy
    assert energy == pytest.approx(cf.dissipation_per_cycle(amplitude), rel=1e-13, abs=0)  # rule 5: sums of W_mono
    assert area == pytest.approx(energy, rel=1e-7, abs=0)  # extrapolated trapezoids: measured <= 8e-10
    # Gauss in psi for int Omega dT*; the two terms cancel to W (~60x at A = 0.4): measured 2e-14
    assert cf.dissipation_from_loop_area(amplitude) == pytest.approx(energy, rel=1e-12, abs=0)
    assert loop[-1].rigid_rotation == pytest.approx(loop[0].rigid_rotation, abs=1e-15)  # Masing: closed
    if amplitude == 1.5:  # the frictional work of q ds over the interface (energy.frictional_work)
        half = 0.5 * amplitude
        works = []
        for n in (11, 21):
            path = np.concatenate([[half], np.linspace(half, -half, n)[1:], np.linspace(-half, half, n)[1:]])
            works.append(frictional_work(history(path, model="half-space")))
        # trapezoids in time, second order (measured errors -1.1e-2, -2.7e-3); extrapolated: 3e-6
        assert abs(works[1] / energy - 1) < 0.3 * abs(works[0] / energy - 1)
        assert (4 * works[1] - works[0]) / 3 == pytest.approx(energy, rel=5e-5, abs=0)
    if amplitude > 2:  # the cylinders: the same identity, with their own loop-area route
        cylinder_area, cylinder = _richardson_area(amplitude, "cylinder")
        cyl_energy = cylinder[-1].dissipated_energy - cylinder[0].dissipated_energy
        assert cyl_energy == pytest.approx(cylinder_loop_area(amplitude), rel=1e-9, abs=0)  # measured 3e-14
        assert cyl_energy == pytest.approx(cylinder_dissipation(amplitude), rel=1e-12, abs=0)
        assert cylinder_area == pytest.approx(cyl_energy, rel=1e-7, abs=0)  # measured 4e-9


def test_history_states_by_superposition():
    """A state after reversals is sum w_j mono(tau_j); its traction and slip obey the friction law."""
    states = history([1.2, -0.4, 0.8, 0.1], model="half-space")
    r = np.linspace(0, 1, 301)
    for previous, state in zip(states[:-1], states[1:], strict=True):
        q = state.traction(r)
        assert np.all(np.abs(q) <= 1 + 1e-12)
        # on the reverse-slip annulus the traction is -direction x 1 and the slip moved that way
        slipping = r > state.stick_radius
        np.testing.assert_allclose(q[slipping], state.direction * 1.0, atol=1e-12)
        ds = state.slip(r) - previous.slip(r)
        assert np.all(state.direction * ds[slipping] > 0)
        np.testing.assert_allclose(ds[~slipping], 0.0, atol=1e-14)
    assert all(s.regime == "partial-slip" for s in states)  # every reversal slips
    assert states[0].model == "half-space" and states[0].method is None


def test_signal_analysis_matches_history():
    signal = np.array([0.0, 1.1, -0.3, 0.6, -0.3, 1.2, -1.0, 0.2])
    result = analyse_signal(signal, model="half-space")
    states = history(signal, model="half-space")
    np.testing.assert_allclose(result.rigid_rotation, [states[i].rigid_rotation for i in result.index], rtol=1e-14)
    np.testing.assert_allclose(result.stick_radius, [states[i].stick_radius for i in result.index], rtol=1e-14)
    assert result.total_dissipated_energy == pytest.approx(states[-1].dissipated_energy, rel=1e-13, abs=0)
    assert result.model == "half-space" and result.method is None
    omega, energy = result.sample_values()
    assert energy[-1] == pytest.approx(states[-1].dissipated_energy, rel=1e-13, abs=0)
    assert omega[-1] == pytest.approx(states[-1].rigid_rotation, rel=1e-13, abs=0)


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
    assert s.torque == 1.1 and cf.torque(s.stick_radius) == pytest.approx(1.1, rel=4 * EPS, abs=0)
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
        ({"torque": 1.0, "method": "published"}, "method='published' applies to model='cylinder' only"),
        ({"torque": 1.0, "method": "complete"}, "model='half-space'"),
        ({"torque": 1.0, "n_terms": 145}, "n_terms=145 applies to model='cylinder' only"),
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
    with pytest.raises(ValueError, match="method='fast' applies to model='cylinder' only"):
        history([1.0], model="half-space", method="fast")
    s = solve(torque=1.0, model="half-space")
    with pytest.raises(ValueError, match="r must be finite and lie in"):
        s.traction(1.5)
    with pytest.raises(ValueError, match="z must be finite"):
        s.stress(0.5, -1.0)
    with pytest.raises(ValueError, match="cylinder"):
        sample_path(history([1.0], model="half-space")[-1], -1.0)


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
    assert record["stick_radius"] == pytest.approx(cf.stick_radius(1.0), rel=1e-15, abs=0)
    slip = float(hs_interface.interface_slip(1.0, record["stick_radius"]))
    assert record["slip"][1] == pytest.approx(slip, rel=1e-14, abs=0)
    code, text, _ = _main(capsys, "solve", "--torque", "1.23", "--json")
    assert code == 0 and json.loads(text)["model"] == "cylinder"
    code, text, _ = _main(capsys, "history", "--turning-points", "0", "1.0", "-0.5", "--model", "half-space", "--json")
    states = json.loads(text)
    assert [s["model"] for s in states] == ["half-space"] * 3
    assert states[-1]["dissipated_energy"] == pytest.approx(history([0, 1.0, -0.5], model="half-space")[-1]
                                                             .dissipated_energy, rel=1e-15, abs=0)
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
    # measured <= 1e-14 (conditioning of the collocation matrix times eps); 1e-12
    assert omega == pytest.approx(cf.rigid_rotation(b), rel=1e-12, abs=0)
    assert torque == pytest.approx(cf.torque(b), rel=1e-12, abs=0)
    np.testing.assert_allclose(g, 0.5 / cc, rtol=1e-12)


def test_apparent_friction_of_a_half_space_fit():
    """kappa = f_fit / f solves kappa^2 W_hs(A / kappa) = W_cyl(A) (comparison.(C1)); > 1, falling with A."""
    from torsional_contact.half_space.comparison import apparent_friction_ratio, energy_per_cycle

    ranges = np.array([2.01, 2.2, 2.4, 2.6, 2.66])
    kappa = np.array([apparent_friction_ratio(a) for a in ranges])
    for a, k in zip(ranges, kappa, strict=True):
        fitted = k * k * energy_per_cycle(a / k, "half-space")
        assert fitted == pytest.approx(energy_per_cycle(a, "cylinder"), rel=1e-12, abs=0)  # Brent to xtol 1e-14 in ln
    assert np.all(kappa > 1) and np.all(np.diff(kappa) < 0)
    assert apparent_friction_ratio(1.5) == math.inf and apparent_friction_ratio(2.0) == math.inf
    assert apparent_friction_ratio(8 / 3) == 1.0
    # the uniqueness argument: the logarithmic slope of W_hs is >= 4 (its small-amplitude value)
    x = np.linspace(1e-3, 8 / 3 - 1e-6, 4000)
    slope = np.gradient(np.log(cf.dissipation_per_cycle(x)), np.log(x))
    assert np.min(slope) > 4 - 1e-4  # centred differences on the grid: O(h^2) ~ 1e-5
    with pytest.raises(ValueError, match="torque_range must lie in"):
        apparent_friction_ratio(3.0)
    with pytest.raises(ValueError, match="model must be one of"):
        energy_per_cycle(1.0, "wedge")
