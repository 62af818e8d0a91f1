"""The inverse problem: the stick radius b for a given torque T* (1 < T* < 4/3).

T*(b) decreases monotonically from 4/3 (b = 0) to 1 (b = 1) for the Abel-Fredholm
method and the complete weak form.  Units: b in a, T* = 2T/(f F a).

* Abel-Fredholm (``invert_abel_fredholm``): the interpolant b(tau) of ``curves`` (shipped
  table, about 1e-14) gives b; Newton steps with the solver and the interpolated slope
  dT*/db polish it to ``B_TOLERANCE`` (usually no step or one: one or two solves, a few ms).
  Next to 4/3 the residual is the torque deficit 4/3 - T* (exact for the target,
  ``criteria.spinning_deficit``; cancellation-free for the solver), so that b keeps its
  relative accuracy where 4/3 - T* is a few ulp.  Torques below T*(b_max),
  b_max = 1 - ``asymptotics.ONSET_SCALARS``, return None: the caller inverts the small-slip
  expansion (S1) there, exactly as ``solve(stick_radius=)`` evaluates it.
* Weak forms (``invert_series``): the bracket is [b_lo, 1], b_lo the smallest stick disc
  the N terms resolve; a torque above T*_N(b_lo) warns (``ResolutionWarning``) and is
  bracketed down to b = 1e-6.
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
from scipy import optimize

from . import asymptotics
from .criteria import GROSS_SLIP_TORQUE, spinning_deficit
from .curves import monotonic_curves
from .diagnostics import ResolutionWarning, UnphysicalResultWarning
from .solvers.abel_fredholm import RESOLUTION_TOLERANCE, AbelFredholmSolution, solve_abel_fredholm
from .solvers.weak_form import SeriesSolution, resolution_limit, solve_series

__all__ = ["B_TOLERANCE", "largest_resolved_radius", "invert_abel_fredholm", "invert_series"]

#: Accuracy of b in the inverse problem.
B_TOLERANCE = 1e-14
_RELATIVE_TOLERANCE = 4 * np.finfo(float).eps
#: Newton steps with the solver before falling back to Brent's method.
_NEWTON_STEPS = 4


@functools.lru_cache(maxsize=1)
def largest_resolved_radius() -> float:
    """Largest stick radius whose T* comes from the Abel-Fredholm method: 1 - ``asymptotics.ONSET_SCALARS``."""
    return 1.0 - asymptotics.ONSET_SCALARS


def _residual(solution: AbelFredholmSolution, target: float, near_spinning: bool) -> float:
    """T*(b) - target, or its exact form (4/3 - target) - (4/3 - T*(b)) next to 4/3."""
    if near_spinning:
        return spinning_deficit(target) - solution.torque_deficit
    return solution.torque - target


def invert_abel_fredholm(target: float) -> AbelFredholmSolution | None:
    """Stick radius b with T*(b) = target, 1 < target < 4/3; None below the resolved slip annuli.

    The interpolant b(tau) of ``curves`` is the first guess; Newton steps with the
    Abel-Fredholm solver and the interpolated slope dT*/db polish it to ``B_TOLERANCE``
    (relative to b next to spinning).  Should the table and the solver ever disagree by more
    than a few steps can mend, Brent's method on the solver alone decides.
    """
    b_max = largest_resolved_radius()
    if target <= float(asymptotics.onset_torque(1.0 - b_max)):
        return None
    curves = monotonic_curves()
    near_spinning = target > curves.t_split
    slope = curves.by_radius["torque"].derivative
    b = min(float(curves.stick_radius(target)), b_max)
    solution = None
    with warnings.catch_warnings():  # the probes; the answer below warns for itself
        warnings.simplefilter("ignore", ResolutionWarning)
        for _ in range(_NEWTON_STEPS):
            solution = solve_abel_fredholm(b)
            step = _residual(solution, target, near_spinning) / float(slope(b))
            if abs(step) <= B_TOLERANCE * (b if near_spinning else 1.0):
                break
            b = min(max(b - step, 0.5 * b), b_max)
        else:
            edge = solve_abel_fredholm(b_max)
            if _residual(edge, target, near_spinning) >= 0.0:
                # within the solver's noise (~1e-12) of the switch to (S1), where T*(b_max) of the
                # solver and of the expansion differ by that much: the switch itself is the root
                return edge
            scale = min(1.0, float(curves.stick_radius(target)) * 2.0)
            b = optimize.brentq(lambda c: _residual(solve_abel_fredholm(c), target, near_spinning), 0.0, b_max,
                                xtol=B_TOLERANCE * scale, rtol=_RELATIVE_TOLERANCE)
            solution = None
    if solution is None or solution.stick_radius != b or solution.resolution_estimate > RESOLUTION_TOLERANCE:
        solution = solve_abel_fredholm(b)
    return solution


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
            stacklevel=5,  # solve -> the method class (backends) -> here
        )
    b = optimize.brentq(residual, lower, 1.0, xtol=B_TOLERANCE, rtol=_RELATIVE_TOLERANCE)
    if lower == b_lo:  # otherwise the warning above has been given
        return solve_series(b, method, n_terms)  # warns if the slip annulus is unresolved
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        return solve_series(b, method, n_terms)
