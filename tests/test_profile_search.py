"""The search for a profile-likelihood interval's end (fitting.profile.profile_end) on profiles made to order.

The constrained fits are replaced by a known profile r(delta) (signed root of the likelihood-ratio
statistic at distance delta from the estimate), so that what the search returns can be checked
against where the end is: on a smooth profile the point where r = sqrt(F) to ``ROOT_TOLERANCE``; on
a profile that jumps across sqrt(F) (a constrained fit past the jump lands in another valley) the
jump itself, from above and within ``ROOT_TOLERANCE`` of it, before the fits run out.
"""

import math

import numpy as np
import pytest

from torsional_contact.fitting import profile

CRITICAL = 4.0  # F: the end lies where r = 2
P_HAT = np.array([1.0, 0.3, 1.0, 0.0])  # slip torque, kappa, compliance, twist offset


def _install(monkeypatch, r_of_delta, slope_of_delta):
    calls = []

    def fake_fit(model, start, lower, upper, constraint=None, kappa_max=np.inf):
        delta = constraint.value - P_HAT[0]
        calls.append(delta)
        p = np.array(start, dtype=float)
        return p, r_of_delta(delta) ** 2, None

    def fake_slope(model, p, kind):  # dS/dpsi with S = r^2 (scale2 = 1)
        return slope_of_delta(p[0] - P_HAT[0])

    monkeypatch.setattr(profile, "fit", fake_fit)
    monkeypatch.setattr(profile, "_slope", fake_slope)
    return calls


def _end(first_step=0.1):
    return profile.profile_end(None, P_HAT, 0.0, 1.0, "slip_torque", 1, first_step, CRITICAL, None, None, 2.0)


@pytest.mark.parametrize("jump", [0.7, 1.3, 2.9])
def test_a_jump_across_the_critical_value_ends_at_the_bracket_just_above_it(monkeypatch, jump):
    """r = 0.5 delta below the jump (below sqrt(F) = 2 there), 20 above: no point comes within the tolerance."""
    calls = _install(monkeypatch, lambda d: 0.5 * d if d < jump else 20.0,
                     lambda d: 0.5 * d if d < jump else 0.0)
    end = _end()
    distance = end.value - P_HAT[0]
    assert jump <= distance <= jump / (1.0 - profile.ROOT_TOLERANCE), (distance, calls)
    assert end.steps == len(calls) < profile.MAX_PROFILE_STEPS + profile.BRACKETED_STEPS, calls


def test_a_smooth_profile_ends_where_r_reaches_the_critical_value(monkeypatch):
    """r = 1.5 delta^1.5: the end at delta = (2 / 1.5)^(2/3); the search stops within the tolerance on r."""
    calls = _install(monkeypatch, lambda d: 1.5 * max(d, 0.0) ** 1.5, lambda d: 2 * 2.25 * 1.5 * max(d, 0.0) ** 2)
    end = _end()
    r = 1.5 * (end.value - P_HAT[0]) ** 1.5
    assert abs(r - math.sqrt(CRITICAL)) <= profile.ROOT_TOLERANCE * math.sqrt(CRITICAL), (r, calls)
