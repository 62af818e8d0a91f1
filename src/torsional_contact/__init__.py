"""Frictional torsional contact of two elastically similar flat-ended cylinders.

Public interface (see CONTRACT.md): ``solve`` returns a ``Solution`` with the stick
radius, the torque T* = 2T/(f F a), the rigid rotation, the regime and the fields.
"""

from .criteria import GROSS_SLIP_TORQUE, SLIP_ONSET_TORQUE
from .direct import solve_direct
from .fast import FastSolution, solve_fast
from .solution import DEFAULT_METHOD, DEFAULT_N_TERMS, METHODS, Solution, solve, torque_curve
from .warnings import AccuracyWarning, IllConditioningWarning, ResolutionWarning, TruncationWarning

__version__ = "0.1.0"

__all__ = [
    "solve",
    "Solution",
    "torque_curve",
    "solve_fast",
    "FastSolution",
    "solve_direct",
    "METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_N_TERMS",
    "SLIP_ONSET_TORQUE",
    "GROSS_SLIP_TORQUE",
    "AccuracyWarning",
    "IllConditioningWarning",
    "ResolutionWarning",
    "TruncationWarning",
    "__version__",
]
