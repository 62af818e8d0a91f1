r"""The cylinder model: two elastically similar flat-ended cylinders pressed end to end (the paper's problem).

``CYLINDER`` (``Cylinder``) is the entry "cylinder" of ``models.MODELS``, the default model: uniform
pressure p0 = F/(pi a^2) (eq. 1), slip onset at T* = 1, spinning at T* = 4/3, solutions by the
methods of ``backends.METHODS`` (``solution.solve_cylinder``), the twist over a gauge length L of the
two shafts (f p0 / mu)(T* L / a + 2 omega) (``specimen``).

Units: T* = 2T/(f F a); b in a; omega in f p0 / mu; W_mono in (f p0)^2 a^3 / mu.

The monotonic solution mono(tau) as the memory rules use it: numbers cheap, fields on demand.

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

``Cylinder.monotonic(method, n_terms)`` returns ``CylinderMonotonic`` (the ``contact_models.base.Monotonic``
interface: ``point``, ``points``, ``solution``), one shared object per resolved (method, n_terms).
"""

from __future__ import annotations

import functools
import math
import warnings

import numpy as np

from .. import asymptotics, validation
from ..backends import DEFAULT_METHOD, METHODS
from ..criteria import GROSS_SLIP_TORQUE, SLIP_ONSET_TORQUE
from ..curves import monotonic_curves
from ..curves.interpolant import ONSET_DELTA
from ..diagnostics import ResolutionWarning
from ..quadrature import gauss_legendre_panels
from ..solution import Solution, solve_cylinder
from ..solvers.weak_form import resolution_limit
from .base import FIELDS, ContactModel, stick_radius_grid

__all__ = ["CYLINDER", "Cylinder", "DEFAULT_METHOD", "resolve", "monotonic_solution", "register", "point", "points",
           "series_loading_work", "CylinderMonotonic"]

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
    """The cylinders' monotonic solution for one (method, n_terms) (the ``contact_models.base.Monotonic``
    interface: ``point``, ``points``, ``solution``, the functions above)."""

    def __init__(self, contact: Cylinder, method: str, n_terms: int | None):
        self.contact, self.method, self.n_terms = contact, method, n_terms

    def __repr__(self) -> str:
        return f"CylinderMonotonic(method={self.method!r}, n_terms={self.n_terms!r})"

    def point(self, tau: float) -> tuple[float, float, float]:
        return point(tau, self.method, self.n_terms)

    def points(self, tau):
        return points(tau, self.method, self.n_terms)

    def solution(self, tau) -> Solution:
        return monotonic_solution(tau, method=self.method, n_terms=self.n_terms)

    def path_torques(self, b_start: float, b_end: float, n_points: int) -> list[float]:
        """Monotonic torques at ``n_points`` stick radii equally spaced from b_start down to b_end (both
        excluded), those the method resolves: T*(b) from ``curves`` (down from 1 - ``ONSET_DELTA``) for the
        default method; solved (and remembered, ``register``) for the weak forms, up to their resolved limit."""
        if not METHODS[self.method].truncated:
            radii = stick_radius_grid(b_start, b_end, n_points, 1.0 - ONSET_DELTA)  # annuli the solver resolves
            return [float(t) for t in np.atleast_1d(monotonic_curves().torque(radii))] if radii.size else []
        out = []
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResolutionWarning)  # only resolved radii are requested
            for b in stick_radius_grid(b_start, b_end, n_points, resolution_limit(self.n_terms)[1]):
                out.append(register(solve_cylinder(stick_radius=float(b), method=self.method, n_terms=self.n_terms)))
        return out

    def rotation_slope(self, tau: float, *, step: float = 1e-4) -> float:
        """d omega_m / d T* at the monotonic torque tau (f p0 / mu per unit T*): 0 in stick, +inf at spinning.

        omega'(b) / T*'(b) from the derivatives of the interpolants of ``curves`` for the default
        method (the small-slip form (pi^3/4)(T* - 1)^2 below their range), by central differences of
        width ``step`` in b for the weak forms.
        """
        b = self.point(tau)[0]
        if b >= 1.0:
            return 0.0
        if b <= 0.0:
            return math.inf
        if not METHODS[self.method].truncated:
            curves = monotonic_curves()
            if b > curves.b_high:
                return math.pi**3 / 4.0 * (tau - 1.0) ** 2
            rotation, torque = curves.by_radius["rigid_rotation"], curves.by_radius["torque"]
            return float(rotation.derivative(b) / torque.derivative(b))
        h = min(step, b / 2, (1 - b) / 2)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResolutionWarning)
            lo = solve_cylinder(stick_radius=b - h, method=self.method, n_terms=self.n_terms)
            hi = solve_cylinder(stick_radius=b + h, method=self.method, n_terms=self.n_terms)
        return float((hi.rigid_rotation - lo.rigid_rotation) / (hi.torque - lo.torque))

    def rotation_integral(self, tau: float) -> float:
        """int_0^tau omega_m(t) dt (the loop-area route of the energy): exact from ``curves`` for the default
        method, Gauss-Legendre panels of the weak form's omega_m otherwise (``ContactModel.rotation_integral``)."""
        if not METHODS[self.method].truncated:
            return 0.0 if tau <= 1.0 else float(monotonic_curves().rotation_integral(tau))
        return self.contact.quadrature_rotation_integral(tau, self)


class Cylinder(ContactModel):
    """Two elastically similar flat-ended cylinders of radius a under uniform pressure (module docstring)."""

    name = "cylinder"
    description = "two elastically similar flat-ended cylinders pressed end to end, uniform pressure"
    bodies = "the cylinders"
    slip_onset_torque = SLIP_ONSET_TORQUE
    gross_slip_torque = GROSS_SLIP_TORQUE
    gross_slip_text = "4/3"
    elastic_bodies = 2
    shaft = True
    fields = FIELDS
    methods = {name: (kind.__doc__ or name).strip().splitlines()[0] for name, kind in METHODS.items()}
    default_method = DEFAULT_METHOD
    units = {**ContactModel.units,
             "rigid_rotation": "f p0 / mu: far-field rotation of the upper cylinder beyond the uniform twist "
                               "(p0 = p-bar: the pressure is uniform)"}

    def options(self, method=None, n_terms=None) -> tuple[str, int | None]:
        """(method, n_terms) with the defaults of ``backends.METHODS`` (``resolve``)."""
        return resolve(method, n_terms)

    def solve(self, stick_radius=None, torque=None, *, method=None, n_terms=None, tolerance=None) -> Solution:
        """``solution.solve_cylinder`` (the arguments and errors of ``torsional_contact.solve``)."""
        return solve_cylinder(stick_radius, torque, method=method, n_terms=n_terms, tolerance=tolerance)

    def monotonic(self, method=None, n_terms=None) -> CylinderMonotonic:
        return _monotonic(self, *resolve(method, n_terms))

    def skeleton_nodes(self):
        """(T*, omega_m, d omega_m / d T*) on nodes from the slip onset to spinning, exact for cubic Hermite
        interpolation to 1e-10 (the curves' Chebyshev nodes, the onset expansion): ``fitting.skeleton``."""
        return _skeleton_nodes()


@functools.lru_cache(maxsize=64)
def _monotonic(contact: Cylinder, method: str, n_terms: int | None) -> CylinderMonotonic:
    return CylinderMonotonic(contact, method, n_terms)


_NODES_PER_PANEL = 12
#: Extra nodes per unit width in b (the table's panels above b = 0.26 are up to 0.24 wide).
_NODES_PER_UNIT_RADIUS = 600
#: Nodes with 1 - b below this take omega and omega' from the small-slip expansion (S2) of ``asymptotics``
#: (omega = (2/3) delta^3 + (pi/16) delta^4, within 1e-16 there), where the table's omega is rounding noise.
_ONSET_NODES = 1e-3


@functools.lru_cache(maxsize=1)
def _skeleton_nodes() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(T*, omega_m, d omega_m / d T*) on the fixed nodes, T* increasing from 1 to 4/3 (exclusive): 12 Chebyshev
    points per panel of the curves table and more per unit of b, the onset from the expansion (S2)
    (``fitting.skeleton``)."""
    curves = monotonic_curves()
    torque, rotation = curves.by_radius["torque"], curves.by_radius["rigid_rotation"]
    edges = torque.edges
    def lobatto(n):  # Chebyshev-Lobatto points on [0, 1]
        return 0.5 * (1.0 - np.cos(np.pi * np.arange(n) / (n - 1)))

    radii = np.unique(np.concatenate([
        lo + (hi - lo) * lobatto(_NODES_PER_PANEL + int(_NODES_PER_UNIT_RADIUS * (hi - lo)))
        for lo, hi in zip(edges[:-1], edges[1:], strict=True)]))
    gap = np.asarray(curves.torque_gap(radii), dtype=float)  # 4/3 - T*, accurate next to spinning
    t = GROSS_SLIP_TORQUE - gap
    omega = np.asarray(rotation(radii), dtype=float)
    gap_slope = np.asarray(curves.by_radius["torque_gap"].derivative(radii), dtype=float)  # = -dT*/db > 0
    slope = np.asarray(rotation.derivative(radii), dtype=float) / -gap_slope
    onset = 1.0 - radii < _ONSET_NODES  # the table's omega is rounding noise (~1e-15) there: (S2)
    delta = 1.0 - radii[onset]
    omega[onset] = asymptotics.onset_rotation(delta)
    slope[onset] = (2.0 * delta**2 + 0.25 * np.pi * delta**3) / gap_slope[onset]
    closest = 1.0 - radii < asymptotics.ONSET_SCALARS  # T* from (S1), as ``solve`` does
    t[closest] = asymptotics.onset_torque(1.0 - radii[closest])
    order = np.argsort(-radii)  # T* and omega increase as b decreases (T* may round to 4/3 near b = 1e-6)
    t, omega, slope = t[order], omega[order], slope[order]
    # the slip onset T* = 1 (b = 1): omega_m = omega_m' = 0 (omega_m ~ (2/3)(pi/2)^3 (T* - 1)^3)
    return np.concatenate([[1.0], t]), np.concatenate([[0.0], omega]), np.concatenate([[0.0], slope])



#: The model object of the table ``models.MODELS``.
CYLINDER = Cylinder()
