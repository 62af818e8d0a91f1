"""Measured loops: friction coefficient, shear modulus and rig compliance from a torque-twist record.

``skeleton`` (the rig's torque-twist curve on a monotonic loading, inverted), ``masing`` (the
memory rules driven by the twist), ``samples`` (checks, noise levels, reversals), ``loop_fit``
(``fit_loop`` and its result) and ``synthetic`` (records of synthetic rigs from the exact
solution, for tests and the coverage study).  Units: SI (N m, rad, m, N, Pa).
"""

from .loop_fit import Estimate, LoopFit, fit_loop
from .samples import MIN_SAMPLES

__all__ = ["fit_loop", "LoopFit", "Estimate", "MIN_SAMPLES"]
