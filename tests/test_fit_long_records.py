"""Records of many cycles that cannot be smoothed: the loop fit says that its intervals may not hold there
(``record_checks``, "Many cycles").

The bias is measured, not assumed (docs/fitting.md): on torque-controlled partial-slip records of the library's
synthetic rig at 100 samples per cycle (too few for the torque to be fitted as a smooth function of time,
``fitting.smoothing``) the functional estimator's bias does not fall with the number of cycles while the intervals
do; the warning must be there over more than ``MANY_REVERSALS`` reversals, and absent on a two-cycle record (whose
intervals were found to cover) and on a long record whose torque was smoothed (``tests/test_fit_smoothing.py``).
"""

from __future__ import annotations

import numpy as np
import pytest

from torsional_contact import fit_loop
from torsional_contact.fitting.record_checks import MANY_REVERSALS
from torsional_contact.fitting.synthetic import Rig, noisy, torque_controlled

RIG = Rig(radius=0.005, normal_force=1000.0, friction=0.6, shear_modulus=80e9, compliance=4e-4, offset=0.0)


def _fit(cycles: int, seed: int = 4):
    torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=cycles, samples_per_cycle=100)
    t, w = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(seed))
    return fit_loop(t, w, radius=RIG.radius, normal_force=RIG.normal_force)


def test_two_cycles_no_warning():
    fit = _fit(2)
    assert fit.friction.value is not None
    assert not any(w.startswith("many cycles") for w in fit.warnings)


@pytest.mark.parametrize("cycles", [MANY_REVERSALS // 2 + 1, 20])
def test_many_cycles_are_said(cycles):
    fit = _fit(cycles)
    assert fit.friction.value is not None  # a value is given: the warning must say what it is worth
    notes = [w for w in fit.warnings if w.startswith("many cycles")]
    assert len(notes) == 1 and f"{2 * cycles} reversals" in notes[0]
