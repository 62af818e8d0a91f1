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
from torsional_contact.solvers.abel_fredholm import solve_fast
from torsional_contact.special.zeros import bessel_j2_zeros

EDGE_RADII = [0.0, 5e-324, 1e-200, 1e-10, 1 - 1.1e-16, 1 - 1e-12, 1 - 1e-8, 0.999, 1.0]
SETTINGS = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def quad_torque(s) -> float:
    """4 int_0^1 q r^2 dr by scipy's adaptive quadrature (breakpoints at the stick edge)."""
    with warnings.catch_warnings():  # asked for near-rounding accuracy, quadpack says so
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        return _quad_torque(s)


def _quad_torque(s) -> float:
    b, torque = s.stick_radius, s.torque
    q = lambda r: float(s.traction(np.array([r]))[0])  # noqa: E731
    if b == 0.0:
        return 4.0 / 3.0
    delta = 1.0 - b
    if delta < 1e-3:  # the stick traction is T* r but within ~1e4 delta of the edge
        lo = max(0.0, b - 1e4 * delta)
        near = integrate.quad(lambda r: (torque * r - q(r)) * r * r, lo, b, limit=400, epsabs=1e-17, epsrel=1e-12,
                              points=[b - 10 * delta, b - delta] if b - 10 * delta > lo else None)[0]
        stick = torque * b**4 / 4.0 - near
    else:
        points = [x for x in (0.5 * b, b - 0.1 * delta, b - 1e-3 * delta) if 0 < x < b]
        stick = integrate.quad(lambda r: q(r) * r * r, 0.0, b, points=points, limit=400, epsabs=1e-16,
                               epsrel=1e-14)[0]
    return 4.0 * (stick + (1.0 - b**3) / 3.0)


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
        assert np.all(np.abs(traction[r < b]) <= 1.0 + 1e-14)  # stick bound
        assert np.all(traction[r > b] == 1.0)
        if b > 0:
            assert np.all(np.isfinite(slip)) and np.all(slip >= -1e-15) and np.all(slip[r < b] == 0)
        scene = with_tolerance(s, 1e-4)  # a plot's tolerance keeps z = 1e-2 at 512 Dini terms
        for z in (0.0, 1e-2, 0.5):
            sigma_zt, sigma_rt = scene.stress(r, z)
            assert np.all(np.isfinite(sigma_zt)) and np.all(np.isfinite(sigma_rt))
            if b > 0:
                assert np.all(np.isfinite(scene.displacement(r, z)))
    assert abs(quad_torque(s) - s.torque) < 5e-12
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
            assert abs(forward - m) < 2e-13  # the same T*(b) both ways
        assert s.regime == ("stick" if m <= 1 else "gross-slip" if s.stick_radius == 0 else "partial-slip")
        assert np.all(np.isfinite(s.traction(np.linspace(0, 1, 51))))


# -- near slip onset ---------------------------------------------------------------------------
@pytest.mark.parametrize("b", [0.999, 0.9999, 0.99999])
def test_default_method_near_onset_balances_torque(b):
    """The traction (F6) integrates to T*: was off by 2e-6 at 0.9999 and 3e-5 at 0.99999."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", TorsionalContactWarning)
        s = solve(stick_radius=b)
    assert abs(quad_torque(s) - s.torque) < 2e-13
    r = b * (1 - np.geomspace(1e-14, 1e-2, 60))
    assert np.all(s.traction(r) <= 1.0 + 1e-15)
    back = solve(torque=s.torque)
    assert abs(back.stick_radius - b) < 1e-12


@pytest.mark.parametrize("delta", [1e-3, 3e-4, 1e-4, 3e-5, 1e-5])
def test_onset_expansion_against_abel_fredholm(delta):
    """(S1), (S2) against the Abel-Fredholm method: the residual is O(delta^3 ln delta)."""
    fast = solve_fast(1.0 - delta)
    delta = 1.0 - fast.stick_radius
    residual = fast.torque - float(asymptotics.onset_torque(delta))
    bound = delta**3 * (0.2 * math.log(1 / delta) + 0.5)
    assert abs(residual) < bound + 2e-13
    assert abs(residual) > 0.5 * bound or delta < 1e-4  # the delta^2/8 term is needed and right
    assert abs(fast.rigid_rotation - float(asymptotics.onset_rotation(delta))) < 3e-16 + 0.1 * delta**5
    # leading order alone would be off by delta^2/8
    assert abs(fast.torque - 1 - 2 / math.pi * delta) > 0.1 * delta**2 - 2e-13


@pytest.mark.parametrize("delta", [1e-6, 3e-6])
def test_onset_fields_against_abel_fredholm(delta):
    """(S3), (S4) within 0.35 delta^2 of the Abel-Fredholm traction and slip at the switch."""
    b = 1.0 - delta
    fast, crack = solve_fast(b), asymptotics.edge_crack(b)
    r = 1 - delta * np.array([1.5, 2, 5, 10, 100, 1e3, 1e4])
    assert np.max(np.abs(fast.interface_traction(r) - crack.interface_traction(r))) < 0.35 * delta**2 + 2e-12
    r = 1 - delta * np.linspace(0, 1, 11)
    assert np.max(np.abs(fast.interface_slip(r) - crack.interface_slip(r))) < delta**3 + 2e-16


@pytest.mark.parametrize("text, delta", [("0.999999999999", 1e-12), (repr(1 - 1e-10), 1e-10),
                                         (repr(1 - 1.1e-16), 1.1e-16), (repr(1 - 1e-8), 1e-8)])
def test_thin_slip_annulus_cli_and_api(text, delta, capsys):
    """Was T* = 14.35, 0.96, -0.09 and T* - 1 = 2.1e-6 (true ~6.4e-9), exit status 0."""
    assert main(["solve", "--stick-radius", text, "--json"]) == 0
    out, err = capsys.readouterr()
    record = json.loads(out)
    delta = 1.0 - float(text)
    assert err == ""
    assert record["torque"] - 1 == pytest.approx(2 / math.pi * delta, rel=1e-6, abs=3e-16)
    assert 0 <= record["rigid_rotation"] <= delta**3
    s = solve(stick_radius=float(text))
    assert solve(torque=s.torque).stick_radius == pytest.approx(s.stick_radius, abs=1e-15)


def test_onset_switches_agree_in_both_directions():
    for delta in (asymptotics.ONSET_SCALARS, asymptotics.ONSET_FIELDS):
        for b in (1 - delta * (1 + 1e-9), 1 - delta * (1 - 1e-9)):
            s = solve(stick_radius=b)
            assert abs(solve(torque=s.torque).stick_radius - b) < 1e-12
        below, above = solve(stick_radius=1 - delta * (1 + 1e-9)), solve(stick_radius=1 - delta * (1 - 1e-9))
        assert abs(below.torque - above.torque) < 3e-12
        r = np.linspace(0, 1, 201)
        assert np.max(np.abs(below.traction(r) - above.traction(r))) < 3e-12


# -- near spinning -------------------------------------------------------------------------------
@pytest.mark.parametrize("b", [1e-2, 1e-3, 1e-5, 1e-8])
def test_spinning_expansion_against_abel_fredholm(b):
    """omega of (S6) and 4/3 - T* of (S7) against the solver; error O(b^3 ln b) and O(b^5)."""
    fast, small = solve_fast(b), asymptotics.small_stick_disc(b)
    assert abs(fast.rigid_rotation - small.rigid_rotation) < 1e-13 + b**3 * math.log(1 / b)
    assert fast.torque_deficit == pytest.approx(small.torque_deficit, rel=2 * b * b + 1e-12)
    r = b * np.array([0.1, 0.5, 0.9, 0.999])
    assert np.max(np.abs(fast.interface_traction(r) - small.interface_traction(r))) < 1e-12 + 2 * b * b
    r = np.array([1.5 * b, 3 * b, 0.01, 0.3, 0.9, 1.0])
    assert np.allclose(fast.interface_slip(r), small.interface_slip(r), rtol=1e-12 + b**2, atol=1e-15)


@pytest.mark.parametrize("b", [1e-200, 5e-324])
def test_tiny_stick_discs_cli_and_api(b, capsys):
    """Was OverflowError (1e-200) and torque nan (5e-324)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", TorsionalContactWarning)
        s = solve(stick_radius=b)
    assert s.torque == 4 / 3 and s.regime == "partial-slip"
    assert s.rigid_rotation == pytest.approx(-0.5 * math.log(b) + asymptotics.spinning_rotation_constant(), abs=1e-12)
    r = np.linspace(0, 1, 11)
    assert np.all(np.isfinite(s.slip(r))) and np.all(s.traction(r[1:]) == 1.0)
    assert main(["solve", "--stick-radius", repr(b), "--json"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["torque"] == 4 / 3 and math.isfinite(record["rigid_rotation"])


def test_spinning_constant_matches_the_solver():
    b = 1e-8  # the next term is ~0.2 b^2
    assert solve_fast(b).rigid_rotation - 0.5 * math.log(1 / b) == pytest.approx(
        asymptotics.spinning_rotation_constant(), abs=1e-13)


@pytest.mark.parametrize("b", [0.01, 1e-3])
def test_slip_of_small_stick_discs_against_direct_quadrature(b):
    """(F7) integrated by scipy with D evaluated directly (the interpolated D was off by 7e-6 at b = 1e-3)."""
    fast = solve_fast(b)
    for r in (2 * b, 0.1, 0.5, 1.0):
        phi_b = math.asin(b / r)
        integrand = lambda p, r=r: math.sin(p) * float(fast._d_function(np.array([r * math.sin(p)]))[0])  # noqa: E731
        points = [phi_b + (math.pi / 2 - phi_b) * x for x in (1e-4, 1e-2, 0.1, 0.5)]
        reference = 2 / math.pi * integrate.quad(integrand, phi_b, math.pi / 2, points=points, limit=400,
                                                 epsabs=1e-17, epsrel=1e-13)[0]
        assert fast.interface_displacement(np.array([r]))[0] == pytest.approx(reference, rel=1e-12, abs=1e-16)


@pytest.mark.parametrize("b", [0.0, 0.1])
def test_sigma_rt_on_the_face_against_the_dini_series(b):
    """sigma_rt(r, 0) (K5; spinning was a 4096-term sum at z = 0, off by 2e-6) against the Dini series."""
    s = solve(stick_radius=b) if b > 0 else solve(torque=4 / 3)
    r = np.array([0.3, 0.5, 0.7, 0.9])
    face = s.stress(r, 0.0)[1]
    fast = solve_fast(b)
    lam = bessel_j2_zeros(8192)
    weights = fast.dini_amplitudes(8192) * lam
    z = np.array([1.2e-3, 0.8e-3, 0.4e-3])  # converged with 8192 terms; quadratic in z
    values = np.array([-fields.series_sum(2, lam, weights, r, zi, 0.0) for zi in z])
    extrapolated = np.array([np.polyfit(z, values[:, j], 2)[-1] for j in range(r.size)])
    assert np.all(np.isfinite(face))
    np.testing.assert_allclose(face, extrapolated, atol=2e-8)


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
    fast = solve_fast(0.6)
    lam, c = bessel_j2_zeros(1024), fast.dini_amplitudes(1024)
    r = np.linspace(0.0005, 0.9995, 1999)
    for z in (1e-2, 3e-3, 1e-3):
        real = np.max(np.abs(fields.series_sum(1, lam, c * lam, r, z, 0.0)
                             - fields.series_sum(1, lam[:256], c[:256] * lam[:256], r, z, 0.0)))
        estimate = (fields.tail_estimate(lam[:256], c[:256], 1, z, 0.6) - fields.tail_estimate(lam, c, 1, z, 0.6))
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
    with mpmath.workdps(30):
        for i in (0, 7, n // 2):
            node = mpmath.mpf(x[i])
            p0, p1 = mpmath.mpf(1), node
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * node * p1 - (k - 1) * p0) / k
            derivative = n * (node * p1 - p0) / (node * node - 1)
            assert abs(p1 / derivative) < 2e-16  # the node is P_n's zero to rounding
            assert float(2 / ((1 - node**2) * derivative**2)) == pytest.approx(w[i], rel=1e-15)


def test_accuracy_warnings_are_of_the_package():
    assert issubclass(TruncationWarning, AccuracyWarning) and issubclass(ResolutionWarning, AccuracyWarning)
