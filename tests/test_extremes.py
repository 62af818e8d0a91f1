"""The whole input domain: every number right to the method's accuracy, or a warning of the
package's own category, or a ValueError / exit status 2 naming the argument.

Independent checks: torque balance by scipy's adaptive quadrature (not the package's Gauss
rules), the small-slip and small-stick-disc expansions against the Abel-Fredholm method
where both apply, sigma_rt(r, 0) against the Dini series extrapolated to z = 0, the slip
against a direct quadrature of (F7), Gauss-Legendre weights against mpmath.
"""

import json
import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from scipy import integrate
from tolerances import (
    EPS,
    PROFILE_ACCURACY,
    ROTATION_ACCURACY,
    assert_beyond,
    assert_close,
    assert_within,
    onset_remainder,
    profile_accuracy,
    slip_rounding,
    torque_accuracy,
)

from torsional_contact import (
    AccuracyWarning,
    ResolutionWarning,
    TruncationWarning,
    asymptotics,
    fields,
    solve,
    validation,
)
from torsional_contact.diagnostics import TorsionalContactWarning, UnphysicalResultWarning
from torsional_contact.io.cli import build_parser, main
from torsional_contact.solution import with_tolerance
from torsional_contact.solvers import kernels
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.special.zeros import bessel_j2_zeros

EDGE_RADII = [0.0, 5e-324, 1e-200, 1e-10, 1 - 1.1e-16, 1 - 1e-12, 1 - 1e-8, 0.999, 1.0]
SETTINGS = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


#: Rounding of the interface traction (F6): the edge term and a Gauss sum of the Chebyshev series of dG/dY, each
#: of at most 512 + 64 terms of O(1) values: 576 EPS = 1.3e-13 absolute.
TRACTION_ROUNDING = 576 * EPS


def quad_torque(s) -> tuple[float, float]:
    """4 int_0^1 q r^2 dr by scipy's adaptive quadrature (breakpoints at the stick edge), and a bound on its error:
    quadpack's own error estimate plus the traction's rounding integrated (``TRACTION_ROUNDING`` x 4 b^3 / 3)."""
    with warnings.catch_warnings():  # asked for near-rounding accuracy, quadpack says so
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        return _quad_torque(s)


def _quad_torque(s) -> tuple[float, float]:
    b, torque = s.stick_radius, s.torque
    q = lambda r: float(s.traction(np.array([r]))[0])  # noqa: E731
    if b == 0.0:
        return 4.0 / 3.0, 0.0
    delta = 1.0 - b
    if delta < 1e-3:  # the stick traction is T* r but within ~1e4 delta of the edge
        lo = max(0.0, b - 1e4 * delta)
        near, error = integrate.quad(lambda r: (torque * r - q(r)) * r * r, lo, b, limit=400, epsabs=1e-17,
                                     epsrel=1e-12, points=[b - 10 * delta, b - delta] if b - 10 * delta > lo else None)
        stick = torque * b**4 / 4.0 - near
    else:
        points = [x for x in (0.5 * b, b - 0.1 * delta, b - 1e-3 * delta) if 0 < x < b]
        stick, error = integrate.quad(lambda r: q(r) * r * r, 0.0, b, points=points, limit=400, epsabs=1e-16,
                                      epsrel=1e-14)
    return 4.0 * (stick + (1.0 - b**3) / 3.0), 4.0 * error + 4.0 * TRACTION_ROUNDING * b**3 / 3.0


def own_warnings(caught):
    return [w for w in caught if issubclass(w.category, TorsionalContactWarning)]


# -- the whole domain ------------------------------------------------------------------------
@SETTINGS
@given(b=st.floats(min_value=0.0, max_value=1.0, allow_nan=False))
@example(b=EDGE_RADII[0])
@example(b=EDGE_RADII[1])
@example(b=EDGE_RADII[2])
@example(b=EDGE_RADII[3])
@example(b=EDGE_RADII[4])
@example(b=EDGE_RADII[5])
@example(b=EDGE_RADII[6])
@example(b=EDGE_RADII[7])
@example(b=EDGE_RADII[8])
def test_every_stick_radius_balances_and_stays_physical(b):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        s = solve(stick_radius=b)
        assert 0.0 <= s.stick_radius <= 1.0 and 1.0 <= s.torque <= 4.0 / 3.0
        assert s.regime == ("stick" if b == 1 else "gross-slip" if b == 0 else "partial-slip")
        assert math.isfinite(s.rigid_rotation) or b == 0.0
        r = np.unique(np.concatenate([np.linspace(0, 1, 401), b * (1 - np.geomspace(1e-12, 0.5, 12)),
                                      b + (1 - b) * np.geomspace(1e-12, 1, 12)]))
        traction, slip = s.traction(r), s.slip(r)
        stick = traction[r < b]
        if stick.size:  # stick bound |q| <= 1, to the traction's rounding
            assert_within(max(0.0, float(np.max(np.abs(stick))) - 1.0), TRACTION_ROUNDING, "rounding of (F6)")
        assert np.all(traction[r > b] == 1.0)
        if b > 0:
            assert np.all(np.isfinite(slip)) and np.all(slip[r < b] == 0)
            # slip >= 0, to its rounding (none at all in the small-slip and small-disc forms)
            solver = getattr(s.backend, "solution", None)  # a AbelFredholmSolution, or a closed form (S4, small disc)
            rounding = slip_rounding(solver) if getattr(solver, "n_nodes", 0) else 64 * EPS
            assert_within(max(0.0, -float(np.min(slip))), rounding, "rounding of the slip (F7)")
        scene = with_tolerance(s, 1e-4)  # a plot's tolerance keeps z = 1e-2 at 512 Dini terms
        for z in (0.0, 1e-2, 0.5):
            sigma_zt, sigma_rt = scene.stress(r, z)
            assert np.all(np.isfinite(sigma_zt)) and np.all(np.isfinite(sigma_rt))
            if b > 0:
                assert np.all(np.isfinite(scene.displacement(r, z)))
    balance, quadrature = quad_torque(s)
    # (F4) against the traction (F6): the same solution, so the rounding of both and the quadrature's error
    assert_within(abs(balance - s.torque), quadrature + 1e3 * EPS, "quadpack's estimate + rounding of (F6), (F4)")
    # nothing to report: the default method is exact to its accuracy everywhere, z = 0 included
    assert not caught, [str(w.message) for w in caught]


@SETTINGS
@given(t=st.floats(min_value=-4 / 3, max_value=4 / 3, allow_nan=False))
@example(t=1 + 2.2e-16)
@example(t=1 + 1e-12)
@example(t=1 + 1e-6)
@example(t=1.0006)
@example(t=-1.2)
@example(t=4 / 3 - 2.2e-16)
@example(t=4 / 3 - 1e-12)
@example(t=4 / 3)
def test_every_torque_is_inverted_consistently(t):
    with warnings.catch_warnings():
        warnings.simplefilter("error", TorsionalContactWarning)  # none expected for the default method
        s = solve(torque=t)
        assert 0.0 <= s.stick_radius <= 1.0
        assert s.torque == t or (s.regime == "gross-slip" and abs(s.torque) == 4 / 3)  # within 4 ulp of 4/3
        m = abs(t)
        if s.regime == "partial-slip":
            assert 1.0 < m < 4.0 / 3.0
            forward = solve(stick_radius=s.stick_radius).torque
            # the same T*(b) both ways: the round trip moves T* by at most the solver's accuracy, twice
            assert_within(abs(forward - m), 2 * torque_accuracy(s.stick_radius), "2 x solver T* accuracy")
        assert s.regime == ("stick" if m <= 1 else "gross-slip" if s.stick_radius == 0 else "partial-slip")
        assert np.all(np.isfinite(s.traction(np.linspace(0, 1, 51))))


# -- near slip onset ---------------------------------------------------------------------------
@pytest.mark.parametrize("b", [0.999, 0.9999, 0.99999])
def test_default_method_near_onset_balances_torque(b):
    """The traction (F6) integrates to T*: was off by 2e-6 at 0.9999 and 3e-5 at 0.99999."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", TorsionalContactWarning)
        s = solve(stick_radius=b)
    balance, quadrature = quad_torque(s)
    assert_within(abs(balance - s.torque), quadrature + 1e3 * EPS, "quadpack's estimate + rounding of (F6), (F4)")
    r = b * (1 - np.geomspace(1e-14, 1e-2, 60))
    assert_within(max(0.0, float(np.max(s.traction(r))) - 1.0), TRACTION_ROUNDING, "stick bound, rounding of (F6)")
    back = solve(torque=s.torque)
    assert_within(abs(back.stick_radius - b), 2 * torque_accuracy(b) / (2 / math.pi),
                  "round trip: 2 x solver T* accuracy over |dT*/db| = 2/pi")


@pytest.mark.parametrize("delta", [1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6])
def test_onset_expansion_against_abel_fredholm(delta):
    """(S1), (S2) against the Abel-Fredholm method: the residual is O(delta^3 ln delta).

    Bounds: the remainder of (S1) with ten times its coefficients (``tolerances.onset_remainder``) plus the
    solver's T* accuracy; omega: the remainder of (S2), O(delta^5 ln delta), plus the rounding of
    omega = Omega - BETA T* (8 ulp of its O(1) terms).  Below 1 - b = 2e-5 (S1) is exact to rounding, so this
    verifies the growth of ``tolerances.torque_accuracy`` next to slip onset.
    """
    b = 1.0 - delta
    fast = solve_abel_fredholm(b)
    delta = 1.0 - fast.stick_radius
    residual = fast.torque - float(asymptotics.onset_torque(delta))
    assert_within(abs(residual), onset_remainder(delta) + torque_accuracy(b), "(S1) remainder + solver accuracy")
    if delta >= 1e-4:  # the delta^3 ln delta term is resolved above the solver's noise: it is there
        assert_beyond(abs(residual), onset_remainder(delta) / 300, "the (S1) remainder is resolved")
    omega_rounding = 8 * EPS * (abs(fast.rotation_constant) + kernels.TORQUE_ROTATION * fast.torque)
    assert_within(abs(fast.rigid_rotation - float(asymptotics.onset_rotation(delta))),
                  omega_rounding + delta**5 * (1 + math.log(1 / delta)), "(S2) remainder + rounding of omega")
    # leading order alone would be off by delta^2/8 (where that is far above the solver's noise)
    if delta**2 / 8 > 100 * torque_accuracy(b):
        assert_beyond(abs(fast.torque - 1 - 2 / math.pi * delta), delta**2 / 100, "the delta^2/8 term matters")


@pytest.mark.parametrize("delta", [1e-6, 3e-6])
def test_onset_fields_against_abel_fredholm(delta):
    """(S3), (S4) against the Abel-Fredholm traction and slip at the switch.

    (S3) omits the first-order inner field: O(delta^2), coefficient 0.28 from the solver (``asymptotics``); bound
    3 delta^2 plus the traction's accuracy.  (S4): O(delta^3) (the slip itself is O(delta^2)); bound 10 delta^3
    plus the slip's rounding (``tolerances.slip_rounding``).
    """
    b = 1.0 - delta
    fast, crack = solve_abel_fredholm(b), asymptotics.edge_crack(b)
    r = 1 - delta * np.array([1.5, 2, 5, 10, 100, 1e3, 1e4])
    assert_close(fast.interface_traction(r), crack.interface_traction(r), "(S3) remainder 3 delta^2 + accuracy",
                 atol=3 * delta**2 + profile_accuracy(b))
    r = 1 - delta * np.linspace(0, 1, 11)
    assert_close(fast.interface_slip(r), crack.interface_slip(r), "(S4) remainder 10 delta^3 + slip rounding",
                 atol=10 * delta**3 + slip_rounding(fast))


@pytest.mark.parametrize("text, delta", [("0.999999999999", 1e-12), (repr(1 - 1e-10), 1e-10),
                                         (repr(1 - 1.1e-16), 1.1e-16), (repr(1 - 1e-8), 1e-8)])
def test_thin_slip_annulus_cli_and_api(text, delta, capsys):
    """Was T* = 14.35, 0.96, -0.09 and T* - 1 = 2.1e-6 (true ~6.4e-9), exit status 0."""
    assert main(["solve", "--stick-radius", text, "--json"]) == 0
    out, err = capsys.readouterr()
    record = json.loads(out)
    delta = 1.0 - float(text)
    assert err == ""
    # (S1): T* - 1 = (2/pi) delta (1 + (pi/16) delta); T* is a double next to 1, correctly rounded to half an ulp
    assert_within(abs(record["torque"] - 1 - 2 / math.pi * delta), 10 * math.pi / 16 * delta**2 + EPS,
                  "the delta^2/8 term (ten times) + one ulp of 1", exact=True)
    assert 0 <= record["rigid_rotation"] <= delta**3  # (S2): (2/3) delta^3 (1 + (3 pi/32) delta) < delta^3
    s = solve(stick_radius=float(text))
    # (S1) inverted without cancellation (onset_slip_width), then b = 1 - delta rounded: one ulp of 1
    assert_within(abs(solve(torque=s.torque).stick_radius - s.stick_radius), EPS, "one ulp of 1", exact=True)


def test_onset_switches_agree_in_both_directions():
    """Each side of a switch is within its bound of the truth: (S1) its remainder, the solver its accuracy; the
    fields: (S3)'s 3 delta^2 (test_onset_fields_against_abel_fredholm) and the traction's accuracy."""
    for delta in (asymptotics.ONSET_SCALARS, asymptotics.ONSET_FIELDS):
        torque_bound = onset_remainder(delta) + torque_accuracy(1 - delta)
        for b in (1 - delta * (1 + 1e-9), 1 - delta * (1 - 1e-9)):
            s = solve(stick_radius=b)
            assert_within(abs(solve(torque=s.torque).stick_radius - b), 2 * torque_bound / (2 / math.pi),
                          "round trip: twice the T* bound over |dT*/db| = 2/pi")
        below, above = solve(stick_radius=1 - delta * (1 + 1e-9)), solve(stick_radius=1 - delta * (1 - 1e-9))
        assert_within(abs(below.torque - above.torque), 2 * torque_bound + 2 / math.pi * 2e-9 * delta,
                      "both sides' T* bounds + the step 2e-9 delta times 2/pi")
        r = np.linspace(0, 1, 201)
        assert_close(below.traction(r), above.traction(r), "(S3) remainder + traction accuracy",
                     atol=3 * delta**2 + profile_accuracy(1 - delta))


# -- near spinning -------------------------------------------------------------------------------
@pytest.mark.parametrize("b", [1e-2, 1e-3, 1e-5, 1e-8])
def test_spinning_expansion_against_abel_fredholm(b):
    """omega of (S6), 4/3 - T* of (S7) and the fields of the small disc against the solver.

    (S6) drops the mixed and E_b terms of (F2), O(b^3 ln b); (S7) and the fields have O(b^2) relative
    corrections whose coefficients are below 1 (the solver gives -0.48 for (S7), 0.36 for the traction): bounds
    10 b^2; plus the solver's accuracy.
    """
    fast, small = solve_abel_fredholm(b), asymptotics.small_stick_disc(b)
    assert_within(abs(fast.rigid_rotation - small.rigid_rotation), ROTATION_ACCURACY + b**3 * math.log(1 / b),
                  "(S6) remainder O(b^3 ln b) + solver accuracy")
    assert_close(fast.torque_deficit, small.torque_deficit, "(S7): 10 b^2 relative + 512 EPS (n-term sums)",
                 rtol=10 * b * b + 512 * EPS)
    r = b * np.array([0.1, 0.5, 0.9, 0.999])
    assert_close(fast.interface_traction(r), small.interface_traction(r), "10 b^2 + traction accuracy",
                 atol=PROFILE_ACCURACY + 10 * b * b)
    r = np.array([1.5 * b, 3 * b, 0.01, 0.3, 0.9, 1.0])
    assert_close(fast.interface_slip(r), small.interface_slip(r), "10 b^2 relative + the slip's rounding",
                 rtol=10 * b**2, atol=slip_rounding(fast, r))


@pytest.mark.parametrize("b", [1e-200, 5e-324])
def test_tiny_stick_discs_cli_and_api(b, capsys):
    """Was OverflowError (1e-200) and torque nan (5e-324)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", TorsionalContactWarning)
        s = solve(stick_radius=b)
    assert s.torque == 4 / 3 and s.regime == "partial-slip"
    # (S6) with b^2 = 0 in double precision: the rounding of ln b and of the sum, 16 ulp of (1/2) |ln b| + 1
    expected = -0.5 * math.log(b) + asymptotics.spinning_rotation_constant()
    assert_within(abs(s.rigid_rotation - expected), 16 * EPS * (0.5 * abs(math.log(b)) + 1), "rounding of ln b")
    r = np.linspace(0, 1, 11)
    assert np.all(np.isfinite(s.slip(r))) and np.all(s.traction(r[1:]) == 1.0)
    assert main(["solve", "--stick-radius", repr(b), "--json"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["torque"] == 4 / 3 and math.isfinite(record["rigid_rotation"])


def test_spinning_constant_matches_the_solver():
    b = 1e-8  # the next term is ~0.2 b^2 (tests/test_curves.py: c2 = e2/2 - 1/8)
    omega = solve_abel_fredholm(b).rigid_rotation
    assert_within(abs(omega - 0.5 * math.log(1 / b) - asymptotics.spinning_rotation_constant()),
                  ROTATION_ACCURACY + b**2, "solver accuracy + the b^2 term (coefficient 0.2 < 1)")


@pytest.mark.parametrize("b", [0.01, 1e-3])
def test_slip_of_small_stick_discs_against_direct_quadrature(b):
    """(F7) integrated by scipy with D evaluated directly (the interpolated D was off by 7e-6 at b = 1e-3).

    Bound: quadpack's error estimate and the rounding of D in both routes (``tolerances.slip_rounding``, halved:
    a displacement), whose interpolant the library integrates.
    """
    fast = solve_abel_fredholm(b)
    for r in (2 * b, 0.1, 0.5, 1.0):
        phi_b = math.asin(b / r)
        integrand = lambda p, r=r: math.sin(p) * float(fast._d_function(np.array([r * math.sin(p)]))[0])  # noqa: E731
        points = [phi_b + (math.pi / 2 - phi_b) * x for x in (1e-4, 1e-2, 0.1, 0.5)]
        value, error = integrate.quad(integrand, phi_b, math.pi / 2, points=points, limit=400, epsabs=1e-17,
                                      epsrel=1e-13)
        assert_within(abs(fast.interface_displacement(np.array([r]))[0] - 2 / math.pi * value),
                      2 / math.pi * error + slip_rounding(fast, r) / 2, "quadpack's estimate + rounding of D")


@pytest.mark.parametrize("b", [0.0, 0.1])
def test_sigma_rt_on_the_face_against_the_dini_series(b):
    """sigma_rt(r, 0) (K5; spinning was a 4096-term sum at z = 0, off by 2e-6) against the Dini series.

    The series at z = 1.6e-3 .. 0.4e-3 (16384 terms: lam_N z >= 20) is extrapolated to z = 0 by a cubic.  Bound:
    the cubic's error, below |cubic - quadratic| (the quadratic through the three smallest z is the less accurate),
    plus the truncation of the series, below the change from 8192 to 16384 terms, times 15 (the sum of the
    cubic's extrapolation weights |l_k(0)| = 4 + 6 + 4 + 1).
    """
    s = solve(stick_radius=b) if b > 0 else solve(torque=4 / 3)
    r = np.array([0.3, 0.5, 0.7, 0.9])
    face = s.stress(r, 0.0)[1]
    fast = solve_abel_fredholm(b)
    lam = bessel_j2_zeros(16384)
    weights = fast.dini_amplitudes(16384) * lam
    z = np.array([1.6e-3, 1.2e-3, 0.8e-3, 0.4e-3])
    values = np.array([-fields.series_sum(2, lam, weights, r, zi, 0.0) for zi in z])
    half = -fields.series_sum(2, lam[:8192], weights[:8192], r, z[-1], 0.0)
    cubic = np.array([np.polyfit(z, values[:, j], 3)[-1] for j in range(r.size)])
    quadratic = np.array([np.polyfit(z[1:], values[1:, j], 2)[-1] for j in range(r.size)])
    assert np.all(np.isfinite(face))
    assert_close(face, cubic, "extrapolation (cubic - quadratic) + 15 x truncation (8192 vs 16384 terms)",
                 atol=np.abs(cubic - quadratic) + 15 * np.abs(values[-1] - half))


# -- weak forms and the reference -------------------------------------------------------------------
def test_weak_form_inverse_refuses_too_few_terms(capsys):
    """Was b = 1.17 (> 1) with the advice 'use n_terms >= -18'."""
    with pytest.raises(ValueError, match=r"n_terms must be >= 6"):
        solve(torque=1.2, method="complete", n_terms=2)
    assert main(["solve", "--torque", "1.2", "--method", "complete", "--n-terms", "2", "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "n_terms" in err
    with pytest.warns(ResolutionWarning, match=r"use n_terms >= \d"):
        s = solve(stick_radius=0.5, method="complete", n_terms=2)
    assert 0 <= s.stick_radius <= 1
    s = solve(torque=1.2, method="complete", n_terms=6)
    assert 0 < s.stick_radius < 1


def test_weak_form_outside_the_physics_warns():
    with pytest.warns(UnphysicalResultWarning, match="outside"):
        s = solve(stick_radius=1e-3, method="complete", n_terms=20)
    assert not 1 <= s.torque <= 4 / 3


@pytest.mark.parametrize("args", [
    ["solve", "--stick-radius", "0.6", "--n-terms", "10000000"],
    ["solve", "--stick-radius", "0.6", "--method", "complete", "--n-terms", "10000000"],
    ["reference", "--stick-radius", "0.6", "--n-terms", "10000000"],
    ["reference", "--stick-radius", "0.6", "--digits", "1001"],
    ["reference", "--stick-radius", "1.00000000000000000001"],
    ["reference", "--stick-radius", "0"],
    ["reference", "--stick-radius", "nan"],
    ["solve", "--torque", "nan"],
    ["solve", "--torque", "-inf"],
])
def test_cli_refuses_with_exit_status_2(args, capsys):
    """Was a MemoryError after 11 s (10**7 terms), a hang (reference), a float-rounded radius."""
    assert main(args) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1


def test_n_terms_has_a_documented_maximum():
    with pytest.raises(ValueError, match="n_terms must be an integer >= 1 and <= 10000"):
        solve(stick_radius=0.6, method="complete", n_terms=10**7)
    with pytest.raises(ValueError, match="n_terms must be an integer >= 1 and <= 4096"):
        solve(stick_radius=0.6, n_terms=10**7)


def test_reference_warns_when_n_terms_cannot_resolve_b(capsys):
    """Was torque 4.4e296 at b = 1e-300 (N = 5) and omega 1.1e6 at b = 1e-3, silently."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert main(["reference", "--stick-radius", "1e-300", "--n-terms", "5", "--digits", "10", "--json"]) == 0
    categories = {w.category for w in caught}
    assert ResolutionWarning in categories and UnphysicalResultWarning in categories
    json.loads(capsys.readouterr().out)
    # a decimal radius is read exactly: float() would round this one to 1.0
    assert main(["reference", "--stick-radius", "0.99999999999999999999", "--n-terms", "5", "--digits", "10",
                 "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["stick_radius"] == "0.99999999999999999999"


# -- command line numbers ------------------------------------------------------------------------
@pytest.mark.parametrize("text", ["-1e-1", "-1E-1", "-.1", "-0.1"])
def test_cli_takes_negative_numbers_in_exponent_form(text, capsys):
    assert main(["solve", "--torque", text, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["torque"] == -0.1


def test_history_parser_takes_negative_exponents():
    args = build_parser().parse_args(["history", "--turning-points", "0", "1.23", "-1e0", "--json"])
    assert args.turning_points == [0.0, 1.23, -1.0]


# -- fields -------------------------------------------------------------------------------------
def test_no_nan_fields():
    s = solve(torque=0.5, method="published")
    assert np.all(np.isfinite(s.displacement([0.5, 1.0], 1.0)))
    sigma = solve(torque=4 / 3).stress(0.5, 0.0)
    assert all(math.isfinite(float(c)) for c in sigma)


def test_truncation_warning_once_per_call_and_close_to_the_real_error():
    s = solve(stick_radius=0.6)
    r = np.linspace(0, 1, 51)
    for call in (lambda: s.stress(r, 1e-6), lambda: s.displacement(r, 1e-6)):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            call()
        assert len(own_warnings(caught)) == 1 and caught[0].category is TruncationWarning
    # the estimate from the amplitudes' decay against the real tail of 256 -> 1024 terms
    fast = solve_abel_fredholm(0.6)
    lam, c = bessel_j2_zeros(1024), fast.dini_amplitudes(1024)
    r = np.linspace(0.0005, 0.9995, 1999)
    for z in (1e-2, 3e-3, 1e-3):
        real = np.max(np.abs(fields.series_sum(1, lam, c * lam, r, z, 0.0)
                             - fields.series_sum(1, lam[:256], c[:256] * lam[:256], r, z, 0.0)))
        estimate = (fields.tail_estimate(lam[:256], c[:256], 1, z, 0.6) - fields.tail_estimate(lam, c, 1, z, 0.6))
        # not a tolerance but what the estimator promises (~1.4 times the real error, ``fields.tail_estimate``):
        # an estimate within a factor of a few of the truth, never far below it
        assert 0.7 < estimate / real < 3.0


def test_coordinates_must_be_real_numbers():
    s = solve(stick_radius=0.6)
    for bad in ("0.5", True, [0.5, "x"], [True, 0.5]):
        with pytest.raises(ValueError, match="r must be a real number"):
            s.traction(bad)
    with pytest.raises(ValueError, match="z must be a real number"):
        s.stress(0.5, "0")
    assert s.traction([0, 0.5, 1]).shape == (3,) and s.traction(np.float32(0.5)).shape == ()


def test_torque_sequences_are_flat():
    with pytest.raises(ValueError, match=r"turning_points\[0\]"):
        validation.torque_sequence("turning_points", [[0, 1.2], [1.3, 0]])
    with pytest.raises(ValueError, match="turning_points must be a flat"):
        validation.torque_sequence("turning_points", np.zeros((2, 2)))
    assert validation.torque_sequence("turning_points", (0, 1.2, -1)) == [0.0, 1.2, -1.0]


def test_gauss_legendre_weights_to_rounding():
    """numpy's leggauss weights are off by ~2e-10 at n = 450; the polished ones by ~1e-16."""
    mpmath = pytest.importorskip("mpmath")
    from torsional_contact.quadrature import gauss_legendre

    n = 300
    x, w = gauss_legendre(n)

    def legendre_and_slope(node):
        p0, p1 = mpmath.mpf(1), node
        for k in range(2, n + 1):
            p0, p1 = p1, ((2 * k - 1) * node * p1 - (k - 1) * p0) / k
        return p1, n * (node * p1 - p0) / (node * node - 1)

    with mpmath.workdps(40):
        for i in (0, 7, n // 2):
            exact = mpmath.mpf(x[i])
            for _ in range(3):  # Newton in 40 digits: the zero of P_n to ~1e-34
                p, slope = legendre_and_slope(exact)
                exact -= p / slope
            # the node is P_n's zero correctly rounded (half an ulp; one allowed)
            assert_within(float(abs(exact - mpmath.mpf(x[i]))), np.spacing(abs(x[i])), "one ulp", exact=True)
            # the weight of the exact node, 2 / ((1 - x^2) P_n'(x)^2), to a few ulp of the double formula
            weight = float(2 / ((1 - exact**2) * legendre_and_slope(exact)[1] ** 2))
            assert_close(w[i], weight, "32 ulp: rounding of the polished weight", rtol=32 * EPS)


def test_accuracy_warnings_are_of_the_package():
    assert issubclass(TruncationWarning, AccuracyWarning) and issubclass(ResolutionWarning, AccuracyWarning)
