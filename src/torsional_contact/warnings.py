"""Warning categories for lost accuracy (never silent wrong numbers)."""

__all__ = ["AccuracyWarning", "ResolutionWarning", "IllConditioningWarning", "TruncationWarning"]


class AccuracyWarning(UserWarning):
    """Base class: a computed number may carry fewer correct digits than usual."""


class ResolutionWarning(AccuracyWarning):
    """The stick disc or slip annulus is too narrow for the number of terms."""


class IllConditioningWarning(AccuracyWarning):
    """The linear system is ill-conditioned; digits are lost to rounding."""


class TruncationWarning(AccuracyWarning):
    """A series was truncated before reaching the requested tolerance."""
