"""The inverse problem: the stick radius b for a given torque T* (1 < T* < 4/3).

T*(b) decreases monotonically from 4/3 (b = 0) to 1 (b = 1) for the Abel-Fredholm
method and the complete weak form.  Units: b in a, T* = 2T/(f F a).

* Abel-Fredholm (``invert_abel_fredholm``): a table of T*(b) on 33 radii (built once per
  process) brackets the root, Brent's method finds it to ``B_TOLERANCE``.  Torques below
  T*(b_max) of the largest radius the method resolves return None: the caller uses the
  small-slip asymptotes.
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
from .diagnostics import ResolutionWarning, UnphysicalResultWarning
from .solvers.abel_fredholm import MAX_NODES, FastSolution, default_nodes, solve_fast
from .solvers.weak_form import SeriesSolution, resolution_limit, solve_series

__all__ = ["B_TOLERANCE", "largest_resolved_radius", "invert_abel_fredholm", "invert_series"]

#: Accuracy of b in the inverse problem.
B_TOLERANCE = 1e-14
_RELATIVE_TOLERANCE = 4 * np.finfo(float).eps


@functools.lru_cache(maxsize=1)
def largest_resolved_radius() -> float:
    """Largest stick radius the Abel-Fredholm method resolves with at most MAX_NODES nodes (~1 - 1.5e-6)."""
    lo, hi = 0.99, 1.0 - 1e-12
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if default_nodes(mid) <= MAX_NODES else (lo, mid)
    return lo


@functools.lru_cache(maxsize=1)
def _torque_table():
    """T*(b) of the Abel-Fredholm method on 33 radii: brackets for the inverse problem."""
    radii = np.append(np.linspace(0.0, 1.0, 33)[:-1], largest_resolved_radius())
    with warnings.catch_warnings():  # brackets only: T* near the cap is still good to ~1e-12
        warnings.simplefilter("ignore", ResolutionWarning)
        torques = np.array([solve_fast(b).torque for b in radii])
    return radii, torques


def invert_abel_fredholm(target: float) -> FastSolution | None:
    """Stick radius b with T*(b) = target, 1 < target < 4/3 (about 10 solves); None below resolution."""
    radii, torques = _torque_table()
    if target <= torques[-1]:
        return None
    upper = int(np.argmax(torques <= target))  # first radius whose torque is below the target
    lower = max(upper - 1, 0)
    with warnings.catch_warnings():  # the probes; the answer below warns for itself
        warnings.simplefilter("ignore", ResolutionWarning)
        b = optimize.brentq(lambda b: solve_fast(b).torque - target, radii[lower], radii[upper],
                            xtol=B_TOLERANCE, rtol=_RELATIVE_TOLERANCE)
    return solve_fast(b)


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
