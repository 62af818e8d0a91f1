"""Convergence with n_terms of T*(0.6), omega(0.6) and the traction (printed in the log)."""

import numpy as np

from torsional_contact.verification.convergence import format_table, n_terms_study


def test_complete_formulation_converges_at_order_about_one(capsys):
    study = n_terms_study(0.6, (145, 290, 580, 1160), radii=(0.3, 0.8, 1.0))
    with capsys.disabled():
        print("\n" + format_table(study))
    # observed orders: ~0.9 for T* and omega (the slip's (r-b)^{3/2} edge is not
    # representable by a smooth series), ~1 for the slip-zone traction at r = 1
    assert np.all((study["order_torque"] > 0.75) & (study["order_torque"] < 1.1))
    assert np.all((study["order_rigid_rotation"] > 0.75) & (study["order_rigid_rotation"] < 1.1))
    assert np.all(np.abs(study["order_traction"][:, 2] - 1.0) < 0.1)
    # monotone approach from above, as the Richardson error bar assumes
    assert np.all(np.diff(study["torque"]) < 0) and np.all(np.diff(study["rigid_rotation"]) < 0)
