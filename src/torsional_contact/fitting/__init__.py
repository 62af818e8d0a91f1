"""Measured loops: friction coefficient, shear modulus and rig compliance from a torque-twist record.

``skeleton`` (the rig's torque-twist curve on a monotonic loading, inverted), ``masing`` (the
memory rules driven by the twist), ``samples`` (checks, noise levels, reversals), ``loop_model``
(the loop's curve and the samples' orthogonal distances from it, errors in both channels),
``profile`` (least squares with a parameter held fixed, profile-likelihood intervals),
``slip_test`` (the critical value of the test of stick, by Davies' bound), ``bootstrap``
(parametric bootstrap, bias-corrected percentile intervals), ``loop_fit`` (``fit_loop`` and its
result) and ``synthetic`` (records of synthetic rigs from the exact solution, for tests and the
coverage study).  Units: SI (N m, rad, m, N, Pa).
"""

from .loop_fit import Estimate, LoopFit, fit_loop
from .samples import MIN_SAMPLES

__all__ = ["fit_loop", "LoopFit", "Estimate", "MIN_SAMPLES"]
