"""The truth of the solver-based checks: the Abel-Fredholm solution, cached per stick radius.

``exact(b)`` is ``torsional_contact.solve(stick_radius=b)`` with its default method (the
Abel-Fredholm method, T* and omega to ~1e-14, interface traction and slip to ~1e-12;
verified elsewhere against a 30-digit reference to ~1e-13).  ``exact_amplitudes(b, n)``
are its Dini amplitudes c_n (n = 1..n) in the normalisation of ``solvers.weak_form``
(c_n = lambda_n A~_n, units f p0 a / mu), comparable with the weak-form coefficients.
"""

from __future__ import annotations

import functools

from ...solution import solve_cylinder
from ...solvers.abel_fredholm import solve_abel_fredholm

__all__ = ["exact", "exact_amplitudes"]


@functools.lru_cache(maxsize=32)
def exact(stick_radius: float):
    """The Abel-Fredholm ``Solution`` for b = ``stick_radius`` (default method of ``solve``)."""
    return solve_cylinder(stick_radius=stick_radius)


@functools.lru_cache(maxsize=16)
def exact_amplitudes(stick_radius: float, n_terms: int):
    """Dini amplitudes c_1..c_n of the Abel-Fredholm solution (read-only array)."""
    amplitudes = solve_abel_fredholm(stick_radius).dini_amplitudes(n_terms)
    amplitudes.setflags(write=False)
    return amplitudes
