"""HalfSpace(pressure=...), "hertz" and "flat-punch" against references computed here (mpmath, exact series).

The references never call the code under test: mpmath quadrature of the Abel integrals of Jaeger's
superposition (R(t) = (1/2) int_t^1 p dx / sqrt(x^2 - t^2), the torque as the sum of the discs'
torques, the traction and slip of the superposed discs), the complete elliptic integrals in mpmath,
and power series in exact rational arithmetic for the small-slip laws.  Tolerances: the quadrature
of ``jaeger`` is exact to rounding for these pressures (terms O(1), sums of ~300 positive terms:
1e-14 is ~50 EPS), the interpolants carry their own error estimate (``MonotonicTable.error_estimate``).
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath as mp
import numpy as np
import pytest
from cli_runner import run_in_process
from tolerances import EPS, assert_close, assert_within

import torsional_contact as tc
from torsional_contact import Specimen, models
from torsional_contact.half_space import closed_form, elliptic
from torsional_contact.half_space.pressure_model import FLAT_PUNCH, HERTZ


@pytest.fixture(autouse=True)
def _mpmath_digits():
    """25 digits for this module's mpmath references (the shared fixture in conftest restores the precision)."""
    mp.mp.dps = 25

#: The quadrature of ``jaeger`` for pressures that are analytic after the theta substitution: ~300 terms of O(1),
#: each to a few EPS: 1e-14 (45 EPS) for rotations, torques and tractions (O(1) numbers).
QUADRATURE = 1e-14
#: The closed forms (E1), (E2) through scipy's K, E (relative ~1e-15) and the uniform closed forms (H5)-(H11).
CLOSED_FORM = 1e-13

#: name -> (p(x, 1 - x^2), n): the pressure given the radius and 1 - r^2 exactly (mpmath), the elastic bodies.
PRESSURES = {
    "uniform": (lambda x, gap: mp.mpf(1), 2),
    "hertz": (lambda x, gap: 1.5 * mp.sqrt(gap), 2),
    "flat-punch": (lambda x, gap: 0.5 / mp.sqrt(gap), 1),
}


def mp_rotation(p, t):
    """R(t) = (1/2) int_t^1 p(x) dx / sqrt(x^2 - t^2); with x^2 = t^2 + (1 - t^2) sin^2(theta) (1 - x^2 =
    (1 - t^2) cos^2(theta) exactly): (1/2) int_0^(pi/2) p sqrt(1 - t^2) cos(theta) / x dtheta."""
    t = mp.mpf(t)
    k2 = 1 - t * t
    if k2 == 0:
        return mp.pi / 8 if p is PRESSURES["flat-punch"][0] else mp.mpf(0)

    def integrand(theta):
        x = mp.sqrt(t * t + k2 * mp.sin(theta) ** 2)
        return p(x, k2 * mp.cos(theta) ** 2) * mp.sqrt(k2) * mp.cos(theta) / x

    return mp.quad(integrand, [0, mp.pi / 2]) / 2


def mp_torque(p, b):
    """T* = (2/pi) sum of the discs' torques (16/3) c^3 dbeta = (32/(3 pi)) [b^3 R(b) + 3 int_b^1 c^2 R(c) dc]."""
    b = mp.mpf(b)
    inner = mp.quad(lambda c: c * c * mp_rotation(p, c), [b, 1])
    return 32 / (3 * mp.pi) * (b**3 * mp_rotation(p, b) + 3 * inner)


def mp_slip(p, n, r, b):
    """s(r) = n (4/(pi r)) int_b^r (R(b) - R(c)) c^2 / sqrt(r^2 - c^2) dc (free-face field of the discs c < r)."""
    r, b = mp.mpf(r), mp.mpf(b)
    rb = mp_rotation(p, b)
    # c = r sin(alpha): dc / sqrt(r^2 - c^2) = dalpha
    return n * 4 * r / mp.pi * mp.quad(lambda a: (rb - mp_rotation(p, r * mp.sin(a))) * mp.sin(a) ** 2,
                                       [mp.asin(b / r), mp.pi / 2])


MODEL_OF = {"uniform": tc.HalfSpace(pressure=1.0), "hertz": HERTZ, "flat-punch": FLAT_PUNCH}


# ------------------------------------------------------------------------------------------------ the general model
@pytest.mark.parametrize("name", list(PRESSURES))
@pytest.mark.parametrize("b", [0.05, 0.4, 0.85])
def test_rotation_and_torque_against_mpmath_superposition(name, b):
    p, _ = PRESSURES[name]
    model = MODEL_OF[name]
    assert_close(model.rotation_at_radius(b), mp_rotation(p, b), "jaeger quadrature (J1)", rtol=QUADRATURE)
    assert_close(model.torque_at_radius(b), mp_torque(p, b), "jaeger quadrature (J2) vs the discs' torques",
                 rtol=QUADRATURE)


@pytest.mark.parametrize("name", list(PRESSURES))
def test_traction_torque_balance_and_slip(name):
    """T* = 4 int q r^2 dr over the traction the model returns; the slip against mpmath of (J5)."""
    p, n = PRESSURES[name]
    model = MODEL_OF[name]
    b = 0.55
    solution = model.solve(stick_radius=b)
    # torque balance: r = b cos(psi) on the stick disc (q ~ p(b) - C sqrt(b^2 - r^2) at its edge) and r = cos(phi)
    # on the slip annulus (edge singularity of the punch): smooth integrands, 80-point Gauss-Legendre
    x, w = np.polynomial.legendre.leggauss(80)
    psi = 0.25 * math.pi * (x + 1.0)
    r_stick = b * np.cos(psi)
    inner = 0.25 * math.pi * b * np.sum(w * solution.traction(r_stick) * r_stick**2 * np.sin(psi))
    phi = 0.5 * math.acos(b) * (x + 1.0)
    r_slip = np.cos(phi)
    terms = 0.5 * math.acos(b) * w * solution.traction(r_slip) * r_slip**2 * np.sin(phi)
    # r = cos(phi) rounded: an edge-singular traction ~ 1/sqrt(1 - r^2) carries ~2 EPS / (1 - r^2) relative error
    rounding = 4.0 * float(np.sum(np.abs(terms) * 2 * EPS / (1.0 - r_slip**2)))
    assert_within(abs(4.0 * (inner + np.sum(terms)) - solution.torque), 1e-13 + 10 * rounding,
                  "torque balance: 80-point rules of smooth integrands, and the rounding of r next to the edge")
    for r in (0.6, 0.8, 0.97):
        assert_close(solution.slip(r), mp_slip(p, n, r, b), "(J5) nested quadrature", rtol=1e-13, atol=1e-15)
    assert float(solution.slip(0.3)) == 0.0
    # the traction is the friction limit f p on the annulus and below it on the stick disc
    r = np.linspace(0.0, b, 40, endpoint=False)
    assert np.all(solution.traction(r) <= np.array([float(p(mp.mpf(v), 1 - mp.mpf(v) ** 2)) for v in r]) + 1e-13)


def test_stick_traction_against_the_disc_superposition():
    """(J4) against q(r) = (4 r / pi) [R(b)/sqrt(1 - r^2) - int_b^1 (R(c) - R(b)) c dc / (c^2 - r^2)^(3/2)]."""
    for name in ("hertz", "flat-punch"):
        p, _ = PRESSURES[name]
        b = mp.mpf("0.6")
        rb = mp_rotation(p, b)
        for r in (mp.mpf("0.2"), mp.mpf("0.55")):
            integral = mp.quad(lambda c, r=r, p=p, rb=rb: (mp_rotation(p, c) - rb) * c / (c * c - r * r) ** 1.5, [b, 1])
            reference = 4 * r / mp.pi * (rb / mp.sqrt(1 - r * r) - integral)
            assert_close(MODEL_OF[name].solve(stick_radius=0.6).traction(float(r)), reference, "(J4)",
                         rtol=QUADRATURE)


def test_uniform_pressure_is_the_half_space_model():
    """HalfSpace(pressure=1) against the closed forms (H5)-(H11) of "half-space" at 1e-12."""
    general = tc.HalfSpace(pressure=1)
    b = np.array([1e-4, 0.01, 0.2, 0.5, 0.8, 0.99])
    assert_close(general.rotation_at_radius(b), closed_form.rigid_rotation(b), "(H5)", rtol=CLOSED_FORM)
    assert_close(general.torque_at_radius(b), closed_form.torque(b), "(H6)", rtol=CLOSED_FORM)
    assert_close(general.loading_work_at_radius(b[1:]), closed_form.loading_work_at_radius(b[1:]), "(H11) vs (J6)",
                 rtol=1e-12)
    tau = np.linspace(0.01, 1.3, 37)
    mine, theirs = general.monotonic_points(tau), models.get("half-space").monotonic_points(tau)
    estimate = general.table.error_estimate
    # the interpolants' estimate plus the conditioning of b(tau) near gross slip: eps / |dT*/db| = eps / (1.7 b^2)
    assert_close(mine[0], theirs[0], "b(tau)", atol=10 * estimate["stick_radius"] + 100 * EPS / np.min(theirs[0]) ** 2)
    assert_close(mine[1], theirs[1], "Omega(tau)", rtol=1e-12)
    assert_close(mine[2], theirs[2], "W_mono(tau) (~tau^4: absolute rounding of the loop-area rate)", rtol=1e-12,
                 atol=1e-18)
    assert general.slip_onset_torque == 0.0
    assert_within(abs(general.gross_slip_torque - 4.0 / 3.0), 2 * EPS, "4 int r^2 dr", exact=True)
    r = np.linspace(0, 0.999, 9)
    s = general.solve(stick_radius=0.5)
    u = models.get("half-space").solve(stick_radius=0.5)
    assert_close(s.traction(r), u.traction(r), "(J4) = (H7)", atol=QUADRATURE)
    assert_close(s.slip(r), u.slip(r), "(J5) = (H8)", atol=1e-13)


# ------------------------------------------------------------------------------------------------ closed forms
def test_hertz_closed_forms():
    b = np.array([1e-5, 0.1, 0.4, 0.7, 0.9, 0.999])
    for bb in b:
        m = 1 - mp.mpf(bb) ** 2
        reference = 0.75 * (mp.ellipk(m) - mp.ellipe(m))
        assert_close(elliptic.hertz_rotation(bb), reference, "(E1) in scipy", rtol=CLOSED_FORM)
        assert_close(HERTZ.rotation_at_radius(bb), reference, "(J1) for Hertz", rtol=QUADRATURE)
    # T*(b) = 3 pi/8 - int_0^b (8/pi) c^2 E(1 - c^2) dc (mpmath) against the general model
    for bb in (0.2, 0.6, 0.95):
        reference = 3 * mp.pi / 8 - mp.quad(lambda c: 8 / mp.pi * c * c * mp.ellipe(1 - c * c), [0, bb])
        assert_close(HERTZ.torque_at_radius(bb), reference, "(J2) vs the integral of (E1)", rtol=QUADRATURE)
        assert_close(-elliptic.hertz_torque_slope(bb), 8 / mp.pi * bb**2 * mp.ellipe(1 - mp.mpf(bb) ** 2), "(E1)",
                     rtol=CLOSED_FORM)
    assert_within(abs(HERTZ.gross_slip_torque - 3 * math.pi / 8), 2 * EPS, "4 int (3/2) sqrt(1 - r^2) r^2 dr",
                  exact=True)
    assert HERTZ.slip_onset_torque == 0.0


def test_flat_punch_closed_forms():
    for bb in (1e-5, 0.1, 0.5, 0.9, 0.999):
        reference = mp.ellipk(1 - mp.mpf(bb) ** 2) / 4
        assert_close(elliptic.punch_rotation(bb), reference, "(E2)", rtol=CLOSED_FORM)
        assert_close(FLAT_PUNCH.rotation_at_radius(bb), reference, "(J1) for the punch", rtol=QUADRATURE)
    for bb in (0.3, 0.8, 0.99):
        slope = lambda c: 8 / (3 * mp.pi) * c * c * (mp.ellipe(1 - c * c) - c * c * mp.ellipk(1 - c * c)) / (1 - c * c)  # noqa: E731
        reference = mp.pi / 2 - mp.quad(slope, [0, bb])
        assert_close(FLAT_PUNCH.torque_at_radius(bb), reference, "(J2) vs the integral of (E2)", rtol=QUADRATURE)
        assert_close(-elliptic.punch_torque_slope(bb), slope(mp.mpf(bb)), "(E2)", rtol=CLOSED_FORM)
    # bonded to 4/3 with Omega = 3 pi T*/32, gross slip at pi/2
    assert_within(abs(FLAT_PUNCH.slip_onset_torque - 4.0 / 3.0), EPS, "(8/3) c0, c0 = 1/2", exact=True)
    assert_within(abs(FLAT_PUNCH.gross_slip_torque - math.pi / 2), 2 * EPS, "4 int r^2 / (2 sqrt(1 - r^2)) dr",
                  exact=True)
    s = FLAT_PUNCH.solve(torque=1.2)
    assert s.stick_radius == 1.0 and s.regime == "stick"
    assert_close(s.rigid_rotation, 3 * math.pi * 1.2 / 32, "bonded disc", rtol=EPS)
    assert float(s.slip(0.99)) == 0.0
    r = np.array([0.3, 0.9])
    assert_close(s.traction(r), 0.375 * 1.2 * r / np.sqrt(1 - r * r), "Reissner-Sagoci bonded traction", rtol=EPS)
    assert_close(FLAT_PUNCH.rotation_at_radius(1.0), math.pi / 8, "R(1) = pi c0 / 4", rtol=EPS)


# ------------------------------------------------------------------------------------------------ limits
def _series(coefficients, n):
    return [Fraction(c) for c in coefficients[:n]] + [Fraction(0)] * max(0, n - len(coefficients))


def _mul(a, b, n):
    return [sum((a[i] * b[k - i] for i in range(k + 1)), Fraction(0)) for k in range(n)]


def _hyper(a, n):
    """(a)_k (1/2)_k / (k!)^2 (K: a = 1/2, E: a = -1/2; times pi/2)."""
    out, term = [], Fraction(1)
    for k in range(n):
        out.append(term)
        term = term * (a + k) * (Fraction(1, 2) + k) / (k + 1) ** 2
    return out


def _sqrt_one_minus(n):
    out, term = [], Fraction(1)
    for k in range(n):
        out.append(term)
        term = term * (k - Fraction(1, 2)) / (k + 1)
    return out


def _compose(f, g, n):
    """f(g(x)) for g(0) = 0, truncated to n terms."""
    out, power = [Fraction(0)] * n, [Fraction(1)] + [Fraction(0)] * (n - 1)
    for c in f[:n]:
        out = [o + c * p for o, p in zip(out, power, strict=True)]
        power = _mul(power, g, n)
    return out


def _invert(f, n):
    """g with f(g(x)) = x for f(0) = 0, f'(0) != 0 (fixed-point iteration on the series)."""
    g = [Fraction(0), 1 / f[1]] + [Fraction(0)] * (n - 2)
    for _ in range(n):
        fg = _compose(f, g, n)
        g = [gi + (xi - fi) / f[1] for gi, xi, fi in zip(g, [Fraction(0), Fraction(1)] + [Fraction(0)] * (n - 2), fg,
                                                         strict=True)]
    return g


def _integrate(a):
    return [Fraction(0)] + [c / (k + 1) for k, c in enumerate(a[:-1])]


def test_hertz_small_slip_laws_with_next_terms():
    """T* -> 0, series of (E1) in exact arithmetic: Omega = (3 pi/32) T (1 + 3T/8 + ...), W = (3 pi^2/256) T^3 (...)."""
    n = 6
    k, e = _hyper(Fraction(1, 2), n), _hyper(Fraction(-1, 2), n)
    torque_of_m = _integrate([2 * c for c in _mul(_sqrt_one_minus(n), e, n)])  # dT/dm = 2 sqrt(1 - m) e(m)
    m_of_t = _invert(torque_of_m, n)
    rotation = _compose([Fraction(3, 8) * (a - b) for a, b in zip(k, e, strict=True)], m_of_t, n)  # / pi
    assert rotation[1] == Fraction(3, 32) and rotation[2] == Fraction(9, 256)
    # W_mono / pi^2 = int (t Omega' - Omega) dt / pi (pi n / 2 = pi for two bodies)
    rate = [(j - 1) * c for j, c in enumerate(rotation)]
    work = _integrate(rate)
    assert work[3] == Fraction(3, 256)
    for t in (1e-3, 1e-2):
        omega = math.pi * sum(float(c) * t**j for j, c in enumerate(rotation))
        b, om, w = HERTZ.monotonic_points(np.array([t]))
        assert_within(abs(om[0] - omega), 10 * float(abs(rotation[-1])) * math.pi * t**n + 1e-14 * om[0],
                      "series truncated after T^5 (next term ~ T^6), interpolant 1e-14")
        assert_close(w[0], math.pi**2 * sum(float(c) * t**j for j, c in enumerate(work)), "W_mono series",
                     rtol=10 * t**3 + 1e-11)
    amplitude = 2e-3
    assert_close(HERTZ.energy_per_cycle(amplitude), elliptic.HERTZ_CYCLE_COEFFICIENT * amplitude**3
                 * (1 + float(work[4] / work[3]) * amplitude / 2), "Mindlin's cubic law with its next term",
                 rtol=20 * amplitude**2)


def test_flat_punch_onset_and_both_gross_slip_laws():
    """Punch above T* = 4/3: Omega = pi/8 + (3 pi/32) d + (27 pi/128) d^2, W = (9 pi^2/64) d^2 (exact series)."""
    n = 6
    k, e = _hyper(Fraction(1, 2), n + 1), _hyper(Fraction(-1, 2), n + 1)
    # (E - (1 - m) K) / m and dT/dm = (2/3) sqrt(1 - m) (E - (1 - m) K) / m
    combined = [a - b + (k[j - 1] if j else 0) for j, (a, b) in enumerate(zip(e, k, strict=True))][1:]
    torque_of_m = _integrate([Fraction(2, 3) * c for c in _mul(_sqrt_one_minus(n), combined[:n], n)])
    m_of_d = _invert(torque_of_m, n)
    rotation = _compose([c / 8 for c in k[:n]], m_of_d, n)  # / pi
    assert rotation[:3] == [Fraction(1, 8), Fraction(3, 32), Fraction(27, 128)]
    for d in (1e-3, 1e-2):
        _, om, w = FLAT_PUNCH.monotonic_points(np.array([4.0 / 3.0 + d]))
        assert_within(abs(om[0] - math.pi * sum(float(c) * d**j for j, c in enumerate(rotation))),
                      100 * d**n + 1e-14, "series to d^5")
        assert_close(w[0], 9 * math.pi**2 / 64 * d**2, "leading W_mono", rtol=30 * d)
    # gross slip, every model: T*(0) - T*(b) ~ (16/(9 pi)) p(0) b^3 (relative correction O(b^2 ln b))
    for model, p0 in ((FLAT_PUNCH, 0.5), (HERTZ, 1.5), (MODEL_OF["uniform"], 1.0)):
        for b in (1e-3, 1e-2):
            deficit = model.gross_slip_torque - model.torque_at_radius(b)
            assert_close(deficit, 16 / (9 * math.pi) * p0 * b**3, "cube law", rtol=10 * b * b * math.log(1 / b)
                         + 10 * EPS / b**3)


# ------------------------------------------------------------------------------------------------ energies
@pytest.mark.parametrize("name", ["hertz", "flat-punch"])
def test_energy_per_cycle_masing_and_loop_area_in_mpmath(name):
    """W(A) = 4 W_mono(A/2) against (pi n / 2) [2 A Omega(A/2) - 8 int_0^(A/2) Omega dt] from the closed forms alone."""
    model = models.get(name)
    n = model.elastic_bodies
    if name == "hertz":
        rot = lambda c: 0.75 * (mp.ellipk(1 - c * c) - mp.ellipe(1 - c * c))  # noqa: E731
        slope = lambda c: 8 / mp.pi * c * c * mp.ellipe(1 - c * c)  # noqa: E731
        gross, bonded = 3 * mp.pi / 8, mp.mpf(0)
    else:
        rot = lambda c: mp.ellipk(1 - c * c) / 4  # noqa: E731
        slope = lambda c: 8 / (3 * mp.pi) * c * c * (mp.ellipe(1 - c * c) - c * c * mp.ellipk(1 - c * c)) / (1 - c * c)  # noqa: E731
        gross, bonded = mp.pi / 2, mp.mpf(4) / 3
    for fraction in (0.3, 0.9):
        amplitude = float(2 * bonded + fraction * 2 * (gross - bonded))
        tau = mp.mpf(amplitude) / 2
        # (K(1 - c^2) of mpmath is inf once c^2 drops below its precision: start at c = 1e-10, int_0^1e-10 < 1e-30)
        b = mp.findroot(lambda c, tau=tau: gross - mp.quad(slope, [mp.mpf(10) ** -10, c]) - tau,
                        (mp.mpf("0.001"), mp.mpf("0.999")), solver="anderson")
        # int_0^tau Omega dT = bonded part + int_b^1 R(c) |dT*/dc| dc
        # (the punch's slope is 0/0 at c = 1, finite: stop 1e-20 short of it)
        integral = 3 * mp.pi * bonded**2 / 64 + mp.quad(lambda c: rot(c) * slope(c), [b, 1 - mp.mpf(10) ** -20])
        reference = mp.pi * n / 2 * (2 * amplitude * rot(b) - 8 * integral)
        assert_close(model.energy_per_cycle(amplitude), reference, "Masing vs loop area", rtol=1e-11)


@pytest.mark.parametrize("name", ["half-space", "hertz", "flat-punch"])
def test_loading_work_interpolant_against_nested_quadrature(name):
    model = models.get(name)
    general = model if isinstance(model, tc.HalfSpace) else tc.HalfSpace(pressure=1)
    for b in (0.1, 0.5, 0.9):
        tau = general.torque_at_radius(b)
        _, _, work = general.monotonic_points(np.array([tau]))
        assert_close(work[0], general.loading_work_at_radius(b), "(J6) vs the table's loop-area integral",
                     rtol=1e-12)


# ------------------------------------------------------------------------------------------------ every model
@pytest.mark.parametrize("name", list(models.MODELS))
def test_residual_traction_of_the_loaded_state_is_the_unloaded_traction(name):
    model = models.get(name)
    r = np.linspace(0.0, 0.98, 25)
    for peak in sorted({1.1, 0.5 * (model.slip_onset_torque + model.gross_slip_torque)}):
        if peak >= model.gross_slip_torque:
            continue
        states = tc.history([0.0, peak, 0.0], model=name)
        assert_close(states[1].residual_traction(r), states[2].traction(r), "the same memory-rule state",
                     atol=1e-13)
        # Masing: unloaded = q(peak) - 2 q(peak / 2) (or the elastic unloading below twice the onset)
        loaded = model.solve(torque=peak).traction(r)
        expected = loaded - 2 * model.solve(torque=peak / 2).traction(r)
        assert_close(states[2].traction(r), expected, "Masing unloading", atol=1e-12)


def test_hertz_specimen_from_sphere():
    radius, force, modulus, nu = 0.01, 50.0, 210e9, 0.3
    specimen = Specimen.from_sphere("10 mm", "50 N", 0.3, "210 GPa", nu)
    effective = 1.0 / (2 * (1 - nu**2) / modulus)
    assert_close(specimen.radius, (3 * force * radius / (4 * effective)) ** (1 / 3), "Hertz", rtol=4 * EPS)
    assert_close(specimen.shear_modulus, modulus / (2 * (1 + nu)), "G = E / (2 (1 + nu))", rtol=EPS)
    assert specimen.model == "hertz"
    assert_close(specimen.gross_slip_torque, 3 * math.pi / 16 * 0.3 * force * specimen.radius, "T = (3 pi/16) f F a",
                 rtol=4 * EPS)
    with pytest.raises(ValueError, match="poisson_ratio"):
        Specimen.from_sphere("10 mm", "50 N", 0.3, "210 GPa", 0.7)


# ------------------------------------------------------------------------------------------------ a toy model
def _parabolic(r):
    return 2.0 * (1.0 - np.asarray(r, dtype=float) ** 2)  # mean 2 int 2 (1 - r^2) r dr = 1


def test_a_registered_toy_model_runs_everywhere(tmp_path):
    toy = models.register(tc.HalfSpace(pressure=_parabolic, name="toy-parabolic",
                                       description="two similar half-spaces, parabolic pressure"))
    try:
        p = lambda x, gap: 2 * gap  # noqa: E731
        assert_within(abs(toy.gross_slip_torque - 4 * 2 * (1 / 3 - 1 / 5)), 4 * EPS, "4 int p r^2 dr", exact=True)
        assert_close(toy.torque_at_radius(0.5), mp_torque(p, 0.5), "(J2)", rtol=QUADRATURE)
        s = tc.solve(torque=0.9, model="toy-parabolic")
        assert s.model == "toy-parabolic" and 0 < s.stick_radius < 1
        states = tc.history([0, 0.9, -0.5, 0.9], model="toy-parabolic")
        assert_close(states[-1].rigid_rotation, states[1].rigid_rotation, "Masing closure", atol=1e-13)
        specimen = Specimen(radius="1 mm", normal_force="10 N", friction=0.4, shear_modulus="30 GPa",
                            model="toy-parabolic")
        assert specimen.energy_per_cycle(0.5 * specimen.gross_slip_torque) > 0
        status, out, err = run_in_process(["solve", "--torque", "0.9", "--model", "toy-parabolic"])
        assert status == 0 and "toy-parabolic" in out, err
        signal = tmp_path / "signal.txt"
        signal.write_text("\n".join(str(0.9 * math.sin(t / 7.0)) for t in range(200)))
        status, out, err = run_in_process(["history", "--signal", str(signal), "--model", "toy-parabolic",
                                           "--json"])
        assert status == 0, err
    finally:
        models.unregister("toy-parabolic")
    assert "toy-parabolic" not in models.MODELS


@pytest.mark.parametrize("pressure, match", [
    (2.0, "mean 1"),
    (lambda r: 2.0 * np.ones_like(r), "mean 1"),
    (lambda r: 4.0 * (r - 0.5), "finite and >= 0"),
    (lambda r: np.where(r > 0.5, np.nan, 1.0), "finite and >= 0"),
    ("uniform", "callable"),
])
def test_bad_pressure(pressure, match):
    with pytest.raises(ValueError, match=f"pressure.*{match}|{match}.*pressure"):
        tc.HalfSpace(pressure=pressure)


def test_bodies_and_fields():
    with pytest.raises(ValueError, match="bodies"):
        tc.HalfSpace(pressure=1, bodies="three")
    s = HERTZ.solve(torque=1.0)
    with pytest.raises(ValueError, match="offers the fields traction, slip"):
        s.stress(0.5, 0.1)
    assert HERTZ.fields == ("traction", "slip")
    # a rigid punch slips u, two similar bodies 2u: the same pressure, the slip halves, the stick radius stays
    rigid = tc.HalfSpace(pressure=_parabolic, bodies="rigid-punch")
    similar = tc.HalfSpace(pressure=_parabolic)
    a, b = rigid.solve(stick_radius=0.4), similar.solve(stick_radius=0.4)
    assert_close(2 * a.slip(0.8), b.slip(0.8), "s = n u", rtol=EPS)
    assert_close(2 * rigid.energy_per_cycle(1.0), similar.energy_per_cycle(1.0), "W proportional to n", rtol=1e-13)


@pytest.mark.parametrize("name", list(models.MODELS))
def test_masing_energy_equals_the_loop_area_for_every_model(name):
    """W(A) = 4 W_mono(A/2) against (pi n / 2) x the area of the loop (2 A Omega(A/2) - 8 int_0^(A/2) Omega dt, the
    integral by Gauss-Legendre panels of Omega alone): the interpolants' ~1e-13 times the cancellation of the two
    area terms (up to 10^3 at 10 % of the partial-slip range): rtol 1e-9."""
    from torsional_contact.histories.energy import dissipation_from_loop_area

    model = models.get(name)
    for fraction in (0.1, 0.4, 0.8, 0.99):
        amplitude = 2 * (model.slip_onset_torque + fraction * (model.gross_slip_torque - model.slip_onset_torque))
        assert_close(model.energy_per_cycle(amplitude), dissipation_from_loop_area(amplitude, model=name),
                     "Masing vs loop area", rtol=1e-9)
