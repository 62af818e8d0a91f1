"""Property-based tests over random stick radii and torques (hypothesis)."""

import warnings

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from tolerances import EPS, assert_within, slip_rounding

from torsional_contact import ResolutionWarning, solve

N_TERMS = 145
#: Rounding of the interface traction (F6): the edge term and a Gauss sum of the Chebyshev series of dG/dY, each
#: of at most 512 + 64 terms of O(1) values: 576 EPS = 1.3e-13 absolute.
TRACTION_ROUNDING = 576 * EPS
R = np.linspace(0.0, 1.0, 801)
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

resolved_radii = st.floats(min_value=0.03, max_value=0.97)
torques = st.floats(min_value=-4 / 3, max_value=4 / 3, allow_nan=False)


@SETTINGS
@given(b=resolved_radii)
def test_torque_balance_stick_bound_and_slip_sign(b):
    s = solve(stick_radius=b, n_terms=N_TERMS)
    assert 1.0 < s.torque < 4 / 3
    # torque balance with the slip-zone traction replaced by its exact value 1; the stick part by Gauss-Legendre in
    # theta, r = b cos(theta), where the traction (F6) is analytic (its square-root edge at r = b included): the
    # rule is exact to rounding, so the bound is the rounding of (F6) integrated, and of (F4)
    x, w = np.polynomial.legendre.leggauss(200)
    theta, w_theta = np.pi / 4 * (x + 1), np.pi / 4 * w
    rho = b * np.cos(theta)
    stick_torque = np.sum(b * np.sin(theta) * w_theta * rho**2 * s.traction(rho))
    assert_within(abs(4 * (stick_torque + (1 - b**3) / 3) - s.torque), 4 * TRACTION_ROUNDING * b**3 / 3 + 1e3 * EPS,
                  "rounding of (F6) integrated + (F4)")
    traction, slip = s.traction(R), s.slip(R)
    assert_within(max(0.0, float(np.max(traction[R <= b])) - 1.0), TRACTION_ROUNDING, "stick bound: rounding of (F6)")
    # slip has the sign of the traction, to the slip's rounding
    assert_within(max(0.0, -float(np.min(slip[R >= b]))), float(slip_rounding(s.backend.solution)), "slip rounding")
    assert s.rigid_rotation > 0


@SETTINGS
@given(t=torques)
def test_any_admissible_torque_mirror_and_no_nan(t):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)  # torques within 1e-4 of 1 or 4/3
        pos, neg = solve(torque=abs(t), n_terms=N_TERMS), solve(torque=-abs(t), n_terms=N_TERMS)
    assert pos.stick_radius == neg.stick_radius
    assert 0.0 <= pos.stick_radius <= 1.0
    for field in ("traction", "slip"):
        a, b = getattr(pos, field)(R), getattr(neg, field)(R)
        assert not np.any(np.isnan(a))
        np.testing.assert_array_equal(a, -b)
    sigma = pos.stress(R, 0.25)
    assert all(np.all(np.isfinite(c)) for c in sigma)
    if pos.regime != "gross-slip":
        assert np.isfinite(pos.rigid_rotation) and pos.rigid_rotation == -neg.rigid_rotation
        assert np.all(np.isfinite(pos.displacement(R, 0.25)))


@SETTINGS
@given(b1=resolved_radii, b2=resolved_radii)
def test_torque_is_monotonic_in_stick_radius(b1, b2):
    if abs(b1 - b2) < 1e-3:  # closer radii differ in T* by less than ~1e-4 |b1 - b2|: far above the noise anyway
        return
    t1, t2 = solve(stick_radius=b1, n_terms=N_TERMS).torque, solve(stick_radius=b2, n_terms=N_TERMS).torque
    assert (t1 - t2) * (b1 - b2) < 0
