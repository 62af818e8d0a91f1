"""The project's warning categories: lost accuracy or a result outside the physics, never silent.

Filter them by category (``warnings.simplefilter("ignore", ResolutionWarning)``), never
wholesale; the README lists when each is raised and what to do.
"""

__all__ = [
    "TorsionalContactWarning",
    "AccuracyWarning",
    "ResolutionWarning",
    "IllConditioningWarning",
    "TruncationWarning",
    "UnphysicalResultWarning",
    "NoiseLimitedFitWarning",
]


class TorsionalContactWarning(UserWarning):
    """Base class of every warning this package raises."""


class AccuracyWarning(TorsionalContactWarning):
    """A computed number may carry fewer correct digits than usual."""


class ResolutionWarning(AccuracyWarning):
    """The stick disc or slip annulus is too narrow for the resolution (terms or nodes)."""


class IllConditioningWarning(AccuracyWarning):
    """The linear system is ill-conditioned; digits are lost to rounding."""


class TruncationWarning(AccuracyWarning):
    """A series was truncated before reaching the requested tolerance."""


class UnphysicalResultWarning(TorsionalContactWarning):
    """A formulation returned a value outside the physics (e.g. the published eq. (38): T* > 4/3)."""


class NoiseLimitedFitWarning(AccuracyWarning):
    """A fitted loop's hysteresis is too small against the measurement noise: biased estimates, narrow intervals."""
