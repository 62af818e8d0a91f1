"""The monotonic curves T*(b), omega(b), W_mono(b) and b(tau) as cheap, exact interpolants.

``work`` (frictional work of a monotonic loading from the Abel-Fredholm solution),
``table`` (where the shipped piecewise Chebyshev table is and how it is read), ``piecewise``
(evaluation), ``interpolant`` (the curves by stick radius and by torque, with the end
asymptotes).  ``monotonic_curves()`` loads the shipped table once per process.  The table's
builder, ``_precompute.build_table``, runs at build time only (``python -m torsional_contact.curves``).
"""

from .interpolant import MonotonicCurves, monotonic_curves
from .work import abel_fredholm_loading_work

__all__ = ["MonotonicCurves", "monotonic_curves", "abel_fredholm_loading_work"]
