"""Torque histories: the Cattaneo-Mindlin / Masing memory rules on the monotonic solution.

``memory`` (states, reversals, the rainflow stack, dissipated energy; the monotonic solution of each
contact model comes from its ``ContactModel.monotonic``), ``signal`` (long sampled signals as arrays),
``loops`` (sampled branches, hysteresis loops, compliance, the unloading experiment of
Fig. 5) and ``energy`` (frictional work and dissipation).  Default method: the
Abel-Fredholm method (``fast``) through the interpolants of ``curves``.
"""

from .energy import (
    cumulative_slip,
    dissipation_from_loop_area,
    dissipation_per_cycle,
    frictional_work,
    loading_work,
    slip_increments,
    threshold_asymptotics,
)
from .loops import Loop, hysteresis_loop, loop_work, relaxation_profiles, sample_path, tangent_compliance
from .memory import (
    CYCLIC_SLIP_RANGE,
    DEFAULT_METHOD,
    InterfaceState,
    TurningPoint,
    advance,
    history,
    initial_state,
    monotonic_solution,
    turning_points,
)
from .signal import SignalHistory, analyse_signal, turning_point_indices

__all__ = [
    "CYCLIC_SLIP_RANGE",
    "DEFAULT_METHOD",
    "InterfaceState",
    "TurningPoint",
    "Loop",
    "SignalHistory",
    "advance",
    "history",
    "initial_state",
    "monotonic_solution",
    "turning_points",
    "turning_point_indices",
    "analyse_signal",
    "sample_path",
    "hysteresis_loop",
    "loop_work",
    "tangent_compliance",
    "relaxation_profiles",
    "slip_increments",
    "cumulative_slip",
    "frictional_work",
    "loading_work",
    "dissipation_per_cycle",
    "dissipation_from_loop_area",
    "threshold_asymptotics",
]
