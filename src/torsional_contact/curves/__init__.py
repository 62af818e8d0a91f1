"""The monotonic curves T*(b), omega(b), W_mono(b) and b(tau) as cheap, exact interpolants.

``work`` (frictional work of a monotonic loading from the Abel-Fredholm solution),
``table`` (building and storing the piecewise Chebyshev table), ``piecewise`` (evaluation),
``interpolant`` (the curves by stick radius and by torque, with the end asymptotes).
``monotonic_curves()`` loads the shipped table once per process.
"""

from .interpolant import MonotonicCurves, monotonic_curves
from .work import loading_work

__all__ = ["MonotonicCurves", "monotonic_curves", "loading_work"]
