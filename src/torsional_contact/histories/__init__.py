"""Torque histories: the Cattaneo-Mindlin / Masing memory rules on the monotonic solution.

``memory`` (states, reversals, the rainflow stack, dissipated energy; the monotonic solution of each
contact model comes from its ``ContactModel.monotonic``), ``signal`` (long sampled signals as arrays),
``loops`` (sampled branches, hysteresis loops, compliance, the unloading experiment of
Fig. 5) and ``energy`` (frictional work and dissipation).  Default method: the
Abel-Fredholm method (``fast``) through the interpolants of ``curves``.
"""

from . import energy, loops, memory, signal
from .energy import *  # noqa: F403 - the public names of each module, listed in its own __all__
from .loops import *  # noqa: F403
from .memory import *  # noqa: F403
from .signal import *  # noqa: F403

__all__ = [*memory.__all__, *loops.__all__, *signal.__all__, *energy.__all__]
