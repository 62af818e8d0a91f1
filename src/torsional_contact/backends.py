"""The solution backends behind ``Solution``: one small interface, one class per kind of solution.

Every backend describes the state for a *positive* torque (``Solution`` mirrors it for a
negative one) in the units of the package: r, z in a; tractions and stresses in f p0;
displacements in f p0 a / mu; omega in f p0 / mu.  The interface is

* ``stick_radius``, ``torque`` (T* > 0), ``rigid_rotation`` (omega of the displacement
  field: 0 for the published weak form, which has no such unknown);
* ``traction(r)``, ``displacement(r)``, ``sigma_rt(r)``: the interface values at z = 0
  (eqs. 8, 25, 26 and sigma_rt = du/dr - u/r);
* ``dini(z_min, tolerance)``: the eigenvalues lambda_n (zeros of J2) and amplitudes c_n of
  the corrective field u = T* r z + omega r + sum c_n exp(-lambda_n z) J1(lambda_n r)
  (eqs. 22-24) good for every z >= z_min > 0 to ``tolerance``, or ``None`` when there is
  no corrective field (uniform twist);
* ``metadata()``: resolution parameters for the JSON summary;
* ``dini_is_truncation``: True when the Dini series represents a solution known exactly
  at the interface (its truncation loses accuracy, estimated by ``fields.tail_estimate``),
  False for the weak forms (the truncated series *is* the solution).

written down as the Protocol ``Backend``.

Backends: ``Bilateral`` (stick), ``Series`` (the truncated weak forms: ``Published``, eq. (38)
as printed, and ``Complete``), ``AbelFredholm`` (the default method), ``Asymptotic`` (the
expansions of ``asymptotics`` beyond its switches: slip annuli narrower than 1e-6, stick
discs smaller than 1e-8) and ``Spinning`` (b = 0).

The methods of ``solve``
------------------------
``METHODS`` maps each ``method=`` name to the backend class that implements it, in the
manner of scipy.integrate's ``METHODS``: ``fast`` -> ``AbelFredholm``, ``published`` ->
``Published``, ``complete`` -> ``Complete``.  A method class follows the Protocol ``Method``:
class attributes that say how ``n_terms`` is read and what the solution is (``truncated``,
``default_n_terms``, ``max_n_terms``, ``has_rigid_rotation``) and two constructors of a
partial-slip backend for a positive torque, ``at_stick_radius(b, n_terms)`` (0 <= b < 1) and
``at_torque(torque, n_terms)`` (1 < T* < 4/3).  ``solve``, the memory rules of ``histories`` and
the command line dispatch through this table only: a new method is one class and one entry.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import ClassVar, Protocol, runtime_checkable

import numpy as np
from scipy import special

from . import asymptotics
from .criteria import GROSS_SLIP_TORQUE
from .fields import MAX_FIELD_TERMS, dini_terms
from .inverse import invert_abel_fredholm, invert_series
from .solvers.abel_fredholm import AbelFredholmSolution, solve_abel_fredholm
from .solvers.weak_form import MAX_SERIES_TERMS, SeriesSolution, minimum_inverse_terms, solve_series
from .special.zeros import bessel_j2_zeros

__all__ = ["Backend", "Method", "METHODS", "DEFAULT_METHOD", "DEFAULT_N_TERMS", "Bilateral", "Series", "Published",
           "Complete", "AbelFredholm", "Asymptotic", "Spinning"]

#: The paper's truncation (section 4), the default N of the weak forms.
DEFAULT_N_TERMS = 145


@runtime_checkable
class Backend(Protocol):
    """The state for a positive torque, as ``Solution`` reads it (see the module docstring for units)."""

    stick_radius: float
    torque: float
    rigid_rotation: float
    #: True when the Dini series truncates a solution known exactly at the interface.
    dini_is_truncation: bool

    def traction(self, r) -> np.ndarray: ...

    def displacement(self, r) -> np.ndarray: ...

    def sigma_rt(self, r) -> np.ndarray: ...

    def dini(self, z_min: float, tolerance: float) -> tuple[np.ndarray, np.ndarray] | None: ...

    def metadata(self) -> dict: ...


class Method(Protocol):
    """A method of ``solve`` (an entry of ``METHODS``): a backend class with these class attributes and constructors."""

    #: The solution is a series truncated at ``n_terms`` (weak forms); otherwise its interface values are exact
    #: and ``n_terms`` only caps the Dini terms of the fields at z > 0.
    truncated: ClassVar[bool]
    #: ``n_terms`` when none is given (None: chosen per call from z and the tolerance).
    default_n_terms: ClassVar[int | None]
    #: Largest ``n_terms`` accepted.
    max_n_terms: ClassVar[int]
    #: False when the method has no rigid-rotation unknown (``Solution.rigid_rotation`` is nan).
    has_rigid_rotation: ClassVar[bool]

    @classmethod
    def at_stick_radius(cls, b: float, n_terms: int | None) -> Backend: ...

    @classmethod
    def at_torque(cls, torque: float, n_terms: int | None) -> Backend: ...


@dataclass(frozen=True)
class Bilateral:
    """Uniform twist u = T* r z (eqs. 2-4): the stick state, T* <= 1, b = 1, omega = 0."""

    torque: float
    rigid_rotation: float = 0.0
    stick_radius: float = 1.0
    dini_is_truncation = False

    def traction(self, r):
        return np.minimum(self.torque * r, 1.0)

    def displacement(self, r):
        return np.zeros_like(r)

    def sigma_rt(self, r):
        return np.zeros_like(r)

    def dini(self, z_min, tolerance):
        return None

    def metadata(self) -> dict:
        return {}


class _Scalars:
    """stick_radius, torque and rigid_rotation read off the wrapped solver result ``solution``."""

    @property
    def stick_radius(self) -> float:
        return self.solution.stick_radius

    @property
    def torque(self) -> float:
        return self.solution.torque

    @property
    def rigid_rotation(self) -> float:
        return self.solution.rigid_rotation


@dataclass(frozen=True)
class Series(_Scalars):
    """A truncated weak form at N terms: sums of eqs. (25), (26).  ``Published`` and ``Complete`` are the two."""

    solution: SeriesSolution
    dini_is_truncation = False
    #: ``solve_series``'s name of the weak form (set by the subclasses).
    form: ClassVar[str | None] = None
    truncated: ClassVar[bool] = True
    default_n_terms: ClassVar[int | None] = DEFAULT_N_TERMS
    max_n_terms: ClassVar[int] = MAX_SERIES_TERMS
    has_rigid_rotation: ClassVar[bool] = True

    def __post_init__(self):
        if self.solution.method != self.form:
            expected = "the base of Published and Complete" if self.form is None else f"the {self.form} weak form"
            raise TypeError(f"{type(self).__name__} is {expected}; got a {self.solution.method!r} solution "
                            f"(use the class of METHODS[{self.solution.method!r}])")

    @classmethod
    def at_stick_radius(cls, b: float, n_terms: int) -> Series:
        return cls(solve_series(b, cls.form, n_terms))

    @classmethod
    def at_torque(cls, torque: float, n_terms: int) -> Series:
        minimum = minimum_inverse_terms()
        if n_terms < minimum:
            raise ValueError(
                f"n_terms must be >= {minimum} for method {cls.form!r} with a torque, got {n_terms}: fewer terms "
                "resolve no stick radius (stick disc and slip annulus each need 10 wavelengths of the highest term)"
            )
        return cls(invert_series(torque, cls.form, n_terms))

    @property
    def rigid_rotation(self) -> float:
        return self.solution.rigid_rotation if self.has_rigid_rotation else 0.0

    def _bessel(self, order, r):
        lam = self.solution.eigenvalues
        x = np.multiply.outer(r, lam)
        return special.j1(x) if order == 1 else special.jv(2, x)

    def traction(self, r):
        s = self.solution
        return s.torque * r - self._bessel(1, r) @ (s.amplitudes * s.eigenvalues)

    def displacement(self, r):
        return self.rigid_rotation * r + self._bessel(1, r) @ self.solution.amplitudes

    def sigma_rt(self, r):
        s = self.solution
        return -(self._bessel(2, r) @ (s.amplitudes * s.eigenvalues))

    def dini(self, z_min, tolerance):
        return self.solution.eigenvalues, self.solution.amplitudes

    def metadata(self) -> dict:
        return {"rcond": self.solution.rcond}


@dataclass(frozen=True)
class Published(Series):
    """Eq. (38) exactly as printed: no rigid-rotation unknown (omega reported as nan, 0 in the fields)."""

    form: ClassVar[str] = "published"
    has_rigid_rotation: ClassVar[bool] = False


@dataclass(frozen=True)
class Complete(Series):
    """The same weak form with the missing rigid-rotation mode."""

    form: ClassVar[str] = "complete"


@dataclass(frozen=True)
class AbelFredholm(_Scalars):
    """The Abel-Fredholm solution (``solvers.abel_fredholm``): exact interface values, Dini fields off it.

    The Dini amplitudes for z > 0 are computed from the method's traction with as many
    terms as ``fields.dini_terms`` asks for (powers of two, cached), unless ``n_terms``
    fixes them.
    """

    solution: AbelFredholmSolution
    n_terms: int | None = None
    _cache: dict = field(default_factory=dict, repr=False, compare=False)
    dini_is_truncation = True
    truncated: ClassVar[bool] = False
    default_n_terms: ClassVar[int | None] = None
    max_n_terms: ClassVar[int] = MAX_FIELD_TERMS
    has_rigid_rotation: ClassVar[bool] = True

    @classmethod
    def at_stick_radius(cls, b: float, n_terms: int | None, solution: AbelFredholmSolution | None = None):
        """The default method at 0 <= b < 1: Abel-Fredholm between the switches of ``asymptotics``
        (``Spinning`` at b = 0, ``Asymptotic`` beyond the switches); ``solution``: already solved at b."""
        if b == 0.0:
            return Spinning(solve_abel_fredholm(0.0), n_terms)
        if b < asymptotics.SPINNING_SWITCH:
            return Asymptotic(asymptotics.small_stick_disc(b), n_terms)
        delta = 1.0 - b
        if delta < asymptotics.ONSET_FIELDS:
            return Asymptotic(asymptotics.edge_crack(b), n_terms)
        solution = solve_abel_fredholm(b) if solution is None else solution
        if delta < asymptotics.ONSET_SCALARS:  # (S1), (S2): exact to rounding, the solver to ~1e-12
            torque = float(asymptotics.onset_torque(delta))
            solution = dataclasses.replace(
                solution,
                torque=torque,
                rigid_rotation=float(asymptotics.onset_rotation(delta)),
                torque_deficit=GROSS_SLIP_TORQUE - torque,
            )
        return AbelFredholm(solution, n_terms)

    @classmethod
    def at_torque(cls, torque: float, n_terms: int | None):
        """The same at 1 < T* < 4/3: ``inverse.invert_abel_fredholm``, or the small-slip expansion (S1)
        inverted exactly below the resolved slip annuli (both directions switch at the same place)."""
        solution = None
        if torque - 1.0 > float(asymptotics.onset_torque(asymptotics.ONSET_SCALARS)) - 1.0:
            solution = invert_abel_fredholm(torque)
        if solution is None:
            return cls.at_stick_radius(1.0 - float(asymptotics.onset_slip_width(torque - 1.0)), n_terms)
        return cls.at_stick_radius(solution.stick_radius, n_terms, solution)

    def traction(self, r):
        return self.solution.interface_traction(r)

    def displacement(self, r):
        return self.solution.interface_displacement(r)

    def sigma_rt(self, r):
        """du/dr - u/r of the interface displacement (0 on the stick disc and at r = 1, eq. 9).

        ``AbelFredholmSolution.interface_sigma_rt``: quadratures of (F7) for every stick radius, no
        differences (they were used for b >= 1/2 before: ~1e-9, ~1e-5 next to r = 1).
        """
        return self.solution.interface_sigma_rt(r)

    def dini(self, z_min, tolerance):
        n = self.n_terms if self.n_terms is not None else dini_terms(z_min, tolerance)
        if n not in self._cache:
            self._cache[n] = (bessel_j2_zeros(n), self.solution.dini_amplitudes(n))
        return self._cache[n]

    def metadata(self) -> dict:
        return {"n_nodes": self.solution.n_nodes}


@dataclass(frozen=True)
class Asymptotic(AbelFredholm):
    """A state of ``asymptotics`` (``EdgeCrack`` or ``SmallStickDisc``): its own sigma_rt(r, 0)."""

    def sigma_rt(self, r):
        return self.solution.interface_sigma_rt(r)

    def metadata(self) -> dict:
        kind = "small slip (edge crack)" if self.stick_radius > 0.5 else "small stick disc"
        return {"n_nodes": 0, "asymptote": kind}


@dataclass(frozen=True)
class Spinning(AbelFredholm):
    """b = 0, T* = 4/3: traction 1 everywhere, unbounded relative rotation (omega = +inf).

    Stresses are finite (sigma_rt(r, 0) from eq. K5); the displacement and slip are
    infinite for r > 0.
    """

    def displacement(self, r):
        return np.where(r > 0, math.inf, 0.0)

    def sigma_rt(self, r):
        return asymptotics.spinning_sigma_rt(r)


#: Every method of ``solve``: name -> backend class (``Method``); the first is the default.
METHODS: dict[str, type[Method]] = {"fast": AbelFredholm, "published": Published, "complete": Complete}
DEFAULT_METHOD = "fast"
