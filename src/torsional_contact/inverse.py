"""The inverse problem: the stick radius b for a given torque T* (1 < T* < 4/3).

T*(b) decreases monotonically from 4/3 (b = 0) to 1 (b = 1) for the Abel-Fredholm
method and the complete weak form.  Units: b in a, T* = 2T/(f F a).

* Abel-Fredholm (``invert_abel_fredholm``): the interpolant b(tau) of ``curves`` (shipped
  table, about 1e-14) gives b; Newton steps with the solver polish it to ``B_TOLERANCE``
  (no or one step: one or two solves, a few ms).  Torques below T*(b_max) of the largest
  radius the method resolves return None: the caller uses the small-slip asymptotes.
* Weak forms (``invert_series``): the bracket is [b_lo, 1], b_lo the smallest stick disc
  the N terms resolve; a torque above T*_N(b_lo) warns (``ResolutionWarning``) and is
  bracketed down to b = 1e-6.
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
from scipy import optimize

from .criteria import GROSS_SLIP_TORQUE
from .curves import monotonic_curves, torque_gap_of
from .curves.table import torque_gap
from .diagnostics import ResolutionWarning, UnphysicalResultWarning
from .solvers.abel_fredholm import RESOLUTION_TOLERANCE, FastSolution, solve_fast
from .solvers.weak_form import SeriesSolution, resolution_limit, solve_series

__all__ = ["B_TOLERANCE", "largest_resolved_radius", "invert_abel_fredholm", "invert_series"]

#: Accuracy of b in the inverse problem.
B_TOLERANCE = 1e-14
_RELATIVE_TOLERANCE = 4 * np.finfo(float).eps
#: Newton steps with the solver before falling back to Brent's method.
_NEWTON_STEPS = 4


@functools.lru_cache(maxsize=1)
def largest_resolved_radius() -> float:
    """Largest stick radius the Abel-Fredholm method resolves with at most MAX_NODES nodes (~1 - 1.5e-6)."""
    return monotonic_curves().b_high


def _residual(solution: FastSolution, target: float, near_spinning: bool) -> float:
    """T*(b) - target, or -(gap(b) - gap(target)) next to 4/3, where T* itself has too few digits."""
    if near_spinning:
        return -(torque_gap(solution) - float(torque_gap_of(target)))
    return solution.torque - target


def invert_abel_fredholm(target: float) -> FastSolution | None:
    """Stick radius b with T*(b) = target, 1 < target < 4/3; None below the resolved slip annuli.

    The interpolant b(tau) of ``curves`` (about 1e-14) is the first guess; Newton steps with
    the Abel-Fredholm solver and the interpolated slope dT*/db polish it to ``B_TOLERANCE``
    (usually no step or one: one or two solves).  Should the table and the solver ever
    disagree by more than a few steps can mend, Brent's method on the solver alone decides.
    """
    curves = monotonic_curves()
    if target <= curves.onset_torque:
        return None
    near_spinning = target > curves.t_split
    slope = curves.by_radius["torque"].derivative
    b = float(curves.stick_radius(target))
    with warnings.catch_warnings():  # the probes; the answer below warns for itself
        warnings.simplefilter("ignore", ResolutionWarning)
        for _ in range(_NEWTON_STEPS):
            solution = solve_fast(b)
            step = _residual(solution, target, near_spinning) / float(slope(b))
            if abs(step) <= B_TOLERANCE:
                break
            b = min(max(b - step, curves.b_low), curves.b_high)
        else:
            b = optimize.brentq(lambda c: _residual(solve_fast(c), target, near_spinning), curves.b_low,
                                curves.b_high, xtol=B_TOLERANCE, rtol=_RELATIVE_TOLERANCE)
            solution = None
    return solve_fast(b) if solution is None or solution.resolution_estimate > RESOLUTION_TOLERANCE else solution


def invert_series(target: float, method: str, n_terms: int) -> SeriesSolution:
    """Stick radius b with T*_N(b) = target for 1 < target < 4/3 (weak form ``method`` at ``n_terms``)."""
    b_lo, _ = resolution_limit(n_terms)

    def residual(b):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResolutionWarning)
            warnings.simplefilter("ignore", UnphysicalResultWarning)
            return solve_series(b, method, n_terms).torque - target

    lower = b_lo
    if residual(lower) < 0:
        # Resolve downward: the torque needs a stick disc smaller than N terms resolve.
        lower = 1e-6
        if residual(lower) < 0:
            raise ValueError(
                f"torque={target:.17g} is within {GROSS_SLIP_TORQUE - target:.2e} of spinning "
                f"(4/3): its stick disc is below b = 1e-6, beyond what n_terms={n_terms} resolves"
            )
        warnings.warn(
            f"torque={target:.12g} needs a stick disc smaller than n_terms={n_terms} resolves "
            f"(b < {b_lo:.3g}); the stick radius and fields are inaccurate",
            ResolutionWarning,
            stacklevel=4,
        )
    b = optimize.brentq(residual, lower, 1.0, xtol=B_TOLERANCE, rtol=_RELATIVE_TOLERANCE)
    if lower == b_lo:  # otherwise the warning above has been given
        return solve_series(b, method, n_terms)  # warns if the slip annulus is unresolved
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        return solve_series(b, method, n_terms)
