"""Weak-form solutions the statement checks share: solved once per process, fields on the interface.

Units: traction in f p0, displacement in f p0 a / mu, lengths in a.
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
from scipy import special

from ...diagnostics import IllConditioningWarning, ResolutionWarning, UnphysicalResultWarning
from ...solvers.weak_form import solve_series

__all__ = ["quiet_solve", "series_displacement", "series_traction"]


@functools.lru_cache(maxsize=64)
def quiet_solve(b, method, n):
    """``solve_series`` with the project's own accuracy and physics warnings silenced (the checks measure them)."""
    with warnings.catch_warnings():
        for category in (IllConditioningWarning, ResolutionWarning, UnphysicalResultWarning):
            warnings.simplefilter("ignore", category)
        return solve_series(b, method, n)


def series_displacement(sol, r):
    """Eigenfunction part sum_n c_n J1(lam_n r) of the interface displacement (eq. i of ``weak_form``)."""
    return special.j1(np.outer(r, sol.eigenvalues)) @ sol.amplitudes


def series_traction(sol, r):
    """Interface traction T* r - sum_n c_n lam_n J1(lam_n r) (eq. ii of ``weak_form``)."""
    return sol.torque * r - special.j1(np.outer(r, sol.eigenvalues)) @ (sol.amplitudes * sol.eigenvalues)
