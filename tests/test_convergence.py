"""Convergence with n_terms of T*(0.6), omega(0.6) and the traction (printed in the log)."""

import numpy as np

from torsional_contact.verification.convergence import format_table, n_terms_study


def test_complete_formulation_converges_at_order_about_one(capsys):
    study = n_terms_study(0.6, (145, 290, 580, 1160), radii=(0.3, 0.8, 1.0))
    with capsys.disabled():
        print("\n" + format_table(study))
    # Convergence orders, not tolerances.  T* and omega converge like (a + c ln N) / N (the slip's (r-b)^{3/2} edge
    # is not representable by a smooth series; tests/test_fast.py::test_agrees_with_extrapolated_weak_form): the
    # local order between N and 2N is 1 - log2(1 + ln 2 / ln N) = 0.81 .. 0.85 for N = 145 .. 580 when c dominates,
    # up to 1 when a does: the band 0.75 .. 1.1.  The slip-zone traction at the corner r = 1 converges like 1/N:
    # order 1, to +- 0.1 (its ln N / N^2 corrections at N >= 145).
    assert np.all((study["order_torque"] > 0.75) & (study["order_torque"] < 1.1))
    assert np.all((study["order_rigid_rotation"] > 0.75) & (study["order_rigid_rotation"] < 1.1))
    assert np.all(np.abs(study["order_traction"][:, 2] - 1.0) < 0.1)
    # monotone approach from above, as the Richardson error bar assumes
    assert np.all(np.diff(study["torque"]) < 0) and np.all(np.diff(study["rigid_rotation"]) < 0)
