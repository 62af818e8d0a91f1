r"""The monotonic solution mono(tau) as the memory rules use it: numbers cheap, fields on demand.

Units: T* = 2T/(f F a); b in a; omega in f p0 / mu; W_mono in (f p0)^2 a^3 / mu.

The memory rules (``histories.memory``) write every state as sum_j w_j mono(tau_j).  The
torque, stick radius, rigid rotation and dissipated energy of a state need only three
numbers per tau: b(tau), omega_m(tau) and the work against friction of the monotonic
loading W_mono(tau) = 2 pi int_b^1 s_m(r; tau) r dr (``curves.work``).  The profiles
(traction, slip, stresses) need the full solution, built only when asked for.

* ``fast`` (default), a method whose interface values are exact (``backends.Method.truncated``
  false): the numbers from the interpolants of ``curves`` (exact to ~1e-14, microseconds), the
  solutions from ``solve_cylinder(torque=tau)`` (a few ms, cached).
* ``complete`` / ``published`` (truncated): the weak form at ``n_terms``; the numbers come from
  the solution itself and W_mono from the quadrature of its slip (panels of 20 / lam_N,
  where the series oscillates), all cached per tau.

``monotonic_model`` returns the monotonic solution of a model (``models``) as the memory rules use
it, the one place of ``histories`` that dispatches on the model (``MONOTONIC_MODELS``): an object
with ``model``, ``method``, ``n_terms`` and

    point(tau)    -> (b, omega_m, W_mono)      at one torque 0 <= tau <= 4/3,
    points(tau)   -> arrays b, omega_m, W_mono  for an array of torques,
    solution(tau) -> the monotonic ``Solution`` mono(tau) (cached),

(``CylinderMonotonic`` here, ``half_space.HalfSpaceMonotonic``).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .. import models, validation
from ..backends import DEFAULT_METHOD, METHODS
from ..criteria import GROSS_SLIP_TORQUE
from ..curves import monotonic_curves
from ..half_space import HalfSpaceMonotonic
from ..quadrature import gauss_legendre_panels
from ..solution import Solution, solve_cylinder

__all__ = ["DEFAULT_METHOD", "resolve", "monotonic_solution", "register", "point", "points", "series_loading_work",
           "CylinderMonotonic", "MONOTONIC_MODELS", "monotonic_model"]

_ONSET_ULPS = 8


def resolve(method=None, n_terms=None) -> tuple[str, int | None]:
    """(method, n_terms) with the defaults of ``backends.METHODS``: ``fast`` (n_terms None) or a weak form
    (n_terms 145)."""
    method = validation.choice("method", DEFAULT_METHOD if method is None else method, METHODS)
    default = METHODS[method].default_n_terms
    if n_terms is None and default is None:
        return method, None
    return method, validation.positive_int("n_terms", default if n_terms is None else n_terms)


def _snap(tau: float) -> float:
    """tau within a few ulps of the slip onset (e.g. (1.23 - (1.23 - 2)) / 2) is the onset itself."""
    return 1.0 if abs(tau - 1.0) <= _ONSET_ULPS * np.finfo(float).eps else min(tau, GROSS_SLIP_TORQUE)


_CACHE_SIZE = 4096
_SOLUTIONS: dict = {}


def _solution(tau: float, method: str, n_terms: int | None) -> Solution:
    key = (tau, method, n_terms)
    if key not in _SOLUTIONS:
        if len(_SOLUTIONS) >= _CACHE_SIZE:
            _SOLUTIONS.clear()
        _SOLUTIONS[key] = solve_cylinder(torque=tau, method=method, n_terms=n_terms)
    return _SOLUTIONS[key]


def register(solution: Solution, tau: float | None = None) -> float:
    """Remember a solution found by its stick radius as mono(tau) (no inversion later); returns tau.

    ``tau`` defaults to the solution's T*; give it when the history will ask for a torque
    that differs from T* by rounding (e.g. (T_1 - (T_1 - 2 T*)) / 2).
    """
    method, n_terms = resolve(solution.method, solution.n_terms)
    tau = solution.torque if tau is None else float(tau)
    if len(_SOLUTIONS) >= _CACHE_SIZE:
        _SOLUTIONS.clear()
    _SOLUTIONS[(tau, method, n_terms)] = solution
    return tau


def monotonic_solution(tau, *, method=None, n_terms=None) -> Solution:
    """mono(tau): the monotonic solution at torque 0 <= tau <= 4/3, friction limit 1 (cached)."""
    tau = validation.torque("tau", tau)
    if tau < 0:
        raise ValueError(f"tau must lie in [0, 4/3], got {tau!r}")
    method, n_terms = resolve(method, n_terms)
    return _solution(_snap(tau), method, n_terms)


def series_loading_work(solution: Solution) -> float:
    """W_mono = 2 pi int_b^1 s(r) r dr of a weak-form solution (quadrature, panels of 20 / lam_N)."""
    if solution.regime == "stick":
        return 0.0
    if solution.regime == "gross-slip":
        return math.inf
    width = 20.0 / solution.backend.solution.eigenvalues[-1]
    nodes, weights = gauss_legendre_panels(solution.stick_radius, 1.0, width, ())
    return float(2.0 * math.pi * np.sum(np.abs(solution.slip(nodes)) * nodes * weights))


@functools.lru_cache(maxsize=4096)
def _series_point(tau: float, method: str, n_terms: int) -> tuple[float, float, float]:
    solution = _solution(tau, method, n_terms)
    return solution.stick_radius, solution.rigid_rotation, series_loading_work(solution)


def point(tau: float, method: str, n_terms: int | None) -> tuple[float, float, float]:
    """(b, omega_m, W_mono) at 0 <= tau <= 4/3 for a resolved (method, n_terms)."""
    tau = _snap(tau)
    if not METHODS[method].truncated:
        return monotonic_curves().state(tau)
    return _series_point(tau, method, n_terms)


def points(tau, method: str, n_terms: int | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vectorised ``point``: arrays b, omega_m, W_mono for an array of tau."""
    tau = np.asarray(tau, dtype=float)
    tau = np.where(np.abs(tau - 1.0) <= _ONSET_ULPS * np.finfo(float).eps, 1.0, np.minimum(tau, GROSS_SLIP_TORQUE))
    if not METHODS[method].truncated:
        curves = monotonic_curves()
        return curves.stick_radius(tau), curves.rotation(tau), curves.work(tau)
    rows = np.array([_series_point(float(t), method, n_terms) for t in tau.ravel()]).reshape(*tau.shape, 3)
    return rows[..., 0], rows[..., 1], rows[..., 2]


class CylinderMonotonic:
    """The cylinders' monotonic solution for one (method, n_terms), behind the interface of
    ``histories.monotonic.monotonic_model``: ``point``, ``points``, ``solution`` (the functions above)."""

    model = "cylinder"

    def __init__(self, method: str, n_terms: int | None):
        self.method, self.n_terms = method, n_terms

    def __repr__(self) -> str:
        return f"CylinderMonotonic(method={self.method!r}, n_terms={self.n_terms!r})"

    def point(self, tau: float) -> tuple[float, float, float]:
        return point(tau, self.method, self.n_terms)

    def points(self, tau):
        return points(tau, self.method, self.n_terms)

    def solution(self, tau) -> Solution:
        return monotonic_solution(tau, method=self.method, n_terms=self.n_terms)


#: model name -> the class of its monotonic solution, built from the resolved (method, n_terms) of the cylinder
#: model (``None, None`` for the closed-form half-space).
MONOTONIC_MODELS = {models.CYLINDER: CylinderMonotonic, models.HALF_SPACE: HalfSpaceMonotonic}


def monotonic_model(model=None, method=None, n_terms=None):
    """The monotonic solution of ``model`` for the memory rules (see the module docstring).

    ``method`` and ``n_terms`` as for ``history`` (cylinder only); the objects are shared
    (cached) per resolved (model, method, n_terms).

    Raises
    ------
    ValueError
        For an unknown model, a method or n_terms with the half-space model, or a bad
        method / n_terms of the cylinder model.
    """
    model = models.validated(model, method, n_terms)
    options = resolve(method, n_terms) if model == models.CYLINDER else ()
    return _monotonic_model(model, *options)


@functools.lru_cache(maxsize=64)
def _monotonic_model(model: str, *options):
    return MONOTONIC_MODELS[model](*options)
