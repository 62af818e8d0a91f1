"""Hard cases: many terms, z near 0, the limits of the inverse problem.

Speed is measured by workflow/scripts/benchmark_speed_error.py, not here.
"""

import math
import warnings

import numpy as np
import pytest
from tolerances import EPS, assert_within, onset_remainder, torque_accuracy

from torsional_contact import IllConditioningWarning, TruncationWarning, asymptotics, solve
from torsional_contact.criteria import spinning_deficit
from torsional_contact.diagnostics import TorsionalContactWarning, UnphysicalResultWarning
from torsional_contact.solution import with_tolerance
from torsional_contact.solvers.weak_form import solve_series


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
@pytest.mark.parametrize("method", ["complete", "published"])
def test_five_thousand_terms_no_nan_and_well_conditioned(method):
    with warnings.catch_warnings():
        warnings.simplefilter("error", IllConditioningWarning)  # would be raised, not hidden
        warnings.simplefilter("ignore", UnphysicalResultWarning)
        s = solve_series(0.6, method, 5000)
    assert np.all(np.isfinite(s.amplitudes)) and math.isfinite(s.torque)
    assert s.rcond > 1e-8  # well conditioned: at most 8 of 16 digits lost
    if method == "complete":  # the truncation error at N = 5000 against the exact T*(0.6), which converges like
        # ln N / N (test_fast::test_agrees_with_extrapolated_weak_form): below its change from N = 145 (19 times it)
        exact = solve(stick_radius=0.6).torque
        coarse = solve_series(0.6, method, 145).torque
        assert_within(abs(s.torque - exact), abs(coarse - s.torque), "ln N / N truncation: the change from N = 145")


def test_fields_at_the_interface_are_exact_and_near_it_flagged():
    s = solve(stick_radius=0.6)
    r = np.array([0.6 - 1e-9, 0.6, 0.6 + 1e-9, 1.0 - 1e-9, 1.0])
    traction = s.stress(r, 0.0)[0]
    # 1 on the annulus and at b (set exactly); just inside, 1 - C sqrt(b - r) (regularity), C = O(1): below 10
    assert np.all(traction[1:] == 1.0)
    assert 0 < 1.0 - traction[0]
    assert_within(1.0 - traction[0], 10 * math.sqrt(1e-9), "regular edge: 1 - C sqrt(b - r), C < 10")
    # no slip on the stick disc; just outside, C (r - b)^(3/2) with C = O(1): below 20; plus the profile accuracy
    # of the tiny slip there (its rounding: D ~ sqrt(r - b) near the edge)
    assert_within(float(np.max(np.abs(s.slip(r[:3])))), 20 * 1e-9**1.5 + 64 * EPS * 1e-9**0.5,
                  "C (r - b)^(3/2), C < 20, + rounding")
    with pytest.warns(TruncationWarning, match="Dini terms"):
        sigma_zt, sigma_rt = s.stress(r, 1e-6)
    assert np.all(np.isfinite(sigma_zt)) and np.all(np.isfinite(sigma_rt))
    # at a plot tolerance z = 1e-3 is within reach and needs no warning
    s = with_tolerance(s, 1e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("error", TruncationWarning)
        near = s.stress(r, 1e-3)[0]
    # the field is continuous up to the interface: it moves by O(sqrt(z)) next to the front (C < 10 as above)
    assert_within(float(np.max(np.abs(near - traction))), 10 * math.sqrt(1e-3), "O(sqrt(z)) next to the front")


@pytest.mark.parametrize("torque", [1 + 1e-12, 1 + 1e-8, 1 + 3e-6, 1.0001, 4 / 3 - 1e-6, 4 / 3 - 1e-12])
def test_inverse_problem_near_slip_onset_and_spinning(torque):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        s = solve(torque=torque)
    assert s.regime == "partial-slip" and 0.0 < s.stick_radius < 1.0
    assert math.isfinite(s.rigid_rotation) and s.rigid_rotation > 0
    r = np.linspace(0, 1, 11)
    assert np.all(np.isfinite(s.traction(r))) and np.all(np.isfinite(s.slip(r)))
    # exact everywhere (the small-slip expansion near T* = 1): no warning, and the round trip holds
    assert not [w for w in caught if issubclass(w.category, TorsionalContactWarning)]
    b = s.stick_radius
    assert_within(abs(solve(stick_radius=b).torque - torque), 2 * torque_accuracy(b), "round trip: 2 x T* accuracy")
    near_onset = torque < 1.1
    # the asymptotes of the fast method near onset: 1 - b from (S1) inverted, within (S1)'s remainder over its
    # slope 2/pi and the solver's accuracy, and b = 1 - delta rounded (an ulp of 1)
    if near_onset:
        delta = float(asymptotics.onset_slip_width(torque - 1))
        bound = (math.pi / 2 * (onset_remainder(delta) + torque_accuracy(b)) + 2 * EPS) / delta
        assert_within(abs((1 - b) / delta - 1), bound, "(S1) inverted: remainder + accuracy + rounding of b")
    else:
        # 4/3 - T* = (16/(9 pi)) b^3 (1 + O(b^2)) (S7): relative O(b^2) with coefficient -0.48: 10 b^2; the deficit
        # of the double torque formed exactly (``criteria.spinning_deficit``)
        expected = float(spinning_deficit(torque)) * 9 * math.pi / 16
        assert_within(abs(b**3 / expected - 1), 10 * b**2 + 2 * torque_accuracy(b) / expected, "(S7): 10 b^2")


def test_torque_at_spinning_to_rounding_is_gross_slip():
    s = solve(torque=4 / 3 - 2e-16)  # within 4 ulp of 4/3
    assert s.regime == "gross-slip" and s.stick_radius == 0.0 and s.rigid_rotation == math.inf
