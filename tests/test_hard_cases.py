"""Hard cases: many terms, z near 0, the limits of the inverse problem.

Speed is measured by workflow/scripts/benchmark_speed_error.py, not here.
"""

import math
import warnings

import numpy as np
import pytest

from torsional_contact import IllConditioningWarning, TruncationWarning, solve
from torsional_contact.diagnostics import TorsionalContactWarning, UnphysicalResultWarning
from torsional_contact.solution import with_tolerance
from torsional_contact.solvers.weak_form import solve_series

CONVERGED = {0.6: 1.2317268745666}  # fast method; checked against the direct method in test_fast


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
@pytest.mark.parametrize("method", ["complete", "published"])
def test_five_thousand_terms_no_nan_and_well_conditioned(method):
    with warnings.catch_warnings():
        warnings.simplefilter("error", IllConditioningWarning)  # would be raised, not hidden
        warnings.simplefilter("ignore", UnphysicalResultWarning)
        s = solve_series(0.6, method, 5000)
    assert np.all(np.isfinite(s.amplitudes)) and math.isfinite(s.torque)
    assert s.rcond > 1e-8
    if method == "complete":  # order-0.9 convergence: about 1e-4 left at N = 5000
        assert abs(s.torque - CONVERGED[0.6]) < 1.5e-4


def test_fields_at_the_interface_are_exact_and_near_it_flagged():
    s = solve(stick_radius=0.6)
    r = np.array([0.6 - 1e-9, 0.6, 0.6 + 1e-9, 1.0 - 1e-9, 1.0])
    traction = s.stress(r, 0.0)[0]
    # 1 on the annulus and at b; just inside, 1 - C sqrt(b - r) (regularity), C = O(1)
    np.testing.assert_allclose(traction[1:], 1.0, atol=1e-12)
    assert 0 < 1.0 - traction[0] < 1e-4
    assert np.all(np.abs(s.slip(r[:3])) < 1e-10)
    with pytest.warns(TruncationWarning, match="Dini terms"):
        sigma_zt, sigma_rt = s.stress(r, 1e-6)
    assert np.all(np.isfinite(sigma_zt)) and np.all(np.isfinite(sigma_rt))
    # at a plot tolerance z = 1e-3 is within reach and needs no warning
    s = with_tolerance(s, 1e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("error", TruncationWarning)
        near = s.stress(r, 1e-3)[0]
    assert np.max(np.abs(near - traction)) < 0.05  # the field is continuous up to the interface


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
    assert abs(solve(stick_radius=s.stick_radius).torque - torque) < 1e-12
    near_onset = torque < 1.1
    # the asymptotes of the fast method: T* - 1 ~ (2/pi)(1 - b), 4/3 - T* ~ (16/(9 pi)) b^3
    if near_onset:
        assert (1 - s.stick_radius) == pytest.approx((torque - 1) * math.pi / 2, rel=max(1e-3, 3 * (torque - 1)))
    else:
        assert s.stick_radius**3 == pytest.approx((4 / 3 - torque) * 9 * math.pi / 16, rel=0.05)


def test_torque_at_spinning_to_rounding_is_gross_slip():
    s = solve(torque=4 / 3 - 2e-16)  # within 4 ulp of 4/3
    assert s.regime == "gross-slip" and s.stick_radius == 0.0 and s.rigid_rotation == math.inf
