r"""The names of the loop model's parameters: where each sits in the parameter vector p, and its unit.

p = [T_s, kappa, C, theta_0, U_1, ..., U_M] (``fitting.loop_model``), by index:

* ``SLIP_TORQUE`` (0): the slip-onset torque T_s = f F a / 2, N m (friction f = 2 T_s / (F a));
* ``KAPPA`` (1): contact over rig twist kappa = k / (C T_s), dimensionless (k = 2 f p0 / G, ``loop_fit``);
* ``COMPLIANCE`` (2): the compliance C, rad / (N m) (the shaft's and the rig's twist linear in the torque);
* ``OFFSET`` (3): the twist theta_0 of the virgin state, rad (the zero of the twist);
* ``TURNING`` (4 on, ``FIRST_TURNING`` = 4): the twist U_j at each reversal of the loop, rad, j = 1 .. M.

``CORE`` = (T_s, kappa, C), the skeleton's parameters (the columns of a branch's gradient) and those the
intervals are on; ``LOOP`` = (T_s, kappa, C, theta_0), the parameters the whole loop shares, P = 4 + M in all.
The shear modulus is not a parameter: it is profiled through the product y = kappa C = k / T_s (rad / (N m);
1/G = pi a^3 y / (2 e) for e elastic bodies, ``profile.Constraint("product", y)``).

``fitting.masing`` lays out the Jacobian's columns in the same order from a branch's gradient (its q columns, the
CORE, then theta_0 in column q and U_j in column q + 1 + j), without naming them.

The straight loop of a record in stick, theta = theta_0 + C T, has the parameters (C, theta_0):
``LINE_COMPLIANCE`` (rad / (N m)) and ``LINE_OFFSET`` (rad).
"""

from __future__ import annotations

import numpy as np

__all__ = ["SLIP_TORQUE", "KAPPA", "COMPLIANCE", "OFFSET", "FIRST_TURNING", "CORE", "LOOP", "TURNING",
           "PARAMETER_NAMES", "UNITS", "LINE_COMPLIANCE", "LINE_OFFSET", "KAPPA_MAX", "KAPPA_MIN", "REVERSAL_REACH",
           "turning_twists", "vector"]

#: Index of the slip-onset torque T_s (N m).
SLIP_TORQUE = 0
#: Index of kappa = k / (C T_s) (dimensionless).
KAPPA = 1
#: Index of the compliance C (rad / (N m)).
COMPLIANCE = 2
#: Index of the twist of the virgin state theta_0 (rad).
OFFSET = 3
#: Index of the first turning point's twist U_1 (rad); also the number of parameters the whole loop shares.
FIRST_TURNING = 4
#: T_s, kappa, C: the skeleton's parameters, those the intervals are on.
CORE = slice(SLIP_TORQUE, COMPLIANCE + 1)
#: T_s, kappa, C, theta_0: the parameters the whole loop shares.
LOOP = slice(SLIP_TORQUE, FIRST_TURNING)
#: The twists U_j at the reversals (rad), one per reversal.
TURNING = slice(FIRST_TURNING, None)
#: The names of the shared parameters, in their order in p (``profile.Constraint``'s kinds among them).
PARAMETER_NAMES = ("slip_torque", "kappa", "compliance", "twist_offset")
#: Their units, in the same order (the turning points' twists are in rad).
UNITS = ("N m", "1", "rad / (N m)", "rad")

#: Largest kappa = k / (C T_s): C holds at least the shaft over the gauge length L, L / (G J), so kappa <= 2 a / L,
#: and the twist formula needs sections about 2 a or more from the interface (L >= 4 a, kappa <= 0.5); 2 leaves room.
KAPPA_MAX = 2.0
#: Smallest kappa: the contact's twist rounds the knee of a gross-slip loop over a width that grows like kappa
#: log(1/kappa), so that the residuals have an infinite derivative at kappa = 0, where a fit would stop as at a
#: minimum.  At 1e-4 (G about 3e5 times its value for kappa = 0.3) the modulus is infinite for any purpose.
KAPPA_MIN = 1e-4
#: How far (in noise levels of the twist) the twist at a reversal may lie from the extreme sample.
REVERSAL_REACH = 6.0

#: Index of the straight loop's compliance C (rad / (N m)) in its parameters (C, theta_0).
LINE_COMPLIANCE = 0
#: Index of the straight loop's twist offset theta_0 (rad).
LINE_OFFSET = 1


def turning_twists(p):
    """The twists U_j at the reversals (rad): a view of p."""
    return p[TURNING]


def vector(slip_torque, kappa, compliance, offset, turning) -> np.ndarray:
    """The parameter vector p from T_s (N m), kappa, C (rad / (N m)), theta_0 (rad) and the U_j (rad)."""
    return np.concatenate([[slip_torque, kappa, compliance, offset], turning])
