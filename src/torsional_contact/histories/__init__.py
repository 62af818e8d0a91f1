"""Torque histories: the Cattaneo-Mindlin / Masing memory rules on the monotonic solution.

``memory`` (states, reversals, the rainflow stack), ``loops`` (sampled branches, hysteresis
loops, compliance, the unloading experiment of Fig. 5) and ``energy`` (frictional work and
dissipation).  The main entry point is ``histories``.
"""

from .energy import cumulative_slip, dissipation_per_cycle, frictional_work, slip_increments, threshold_asymptotics
from .loops import Loop, hysteresis_loop, loop_work, relaxation_profiles, sample_path, tangent_compliance
from .memory import (
    CYCLIC_SLIP_RANGE,
    DEFAULT_METHOD,
    InterfaceState,
    TurningPoint,
    advance,
    history,
    initial_state,
    monotonic,
    turning_points,
)

__all__ = [
    "CYCLIC_SLIP_RANGE",
    "DEFAULT_METHOD",
    "InterfaceState",
    "TurningPoint",
    "Loop",
    "advance",
    "history",
    "initial_state",
    "monotonic",
    "turning_points",
    "sample_path",
    "hysteresis_loop",
    "loop_work",
    "tangent_compliance",
    "relaxation_profiles",
    "slip_increments",
    "cumulative_slip",
    "frictional_work",
    "dissipation_per_cycle",
    "threshold_asymptotics",
]
