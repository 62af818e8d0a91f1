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

Backends: ``Bilateral`` (stick), ``Series`` (the published and complete weak forms),
``AbelFredholm`` (the default method), ``Asymptotic`` (the expansions of ``asymptotics``
beyond its switches: slip annuli narrower than 1e-6, stick discs smaller than 1e-8) and
``Spinning`` (b = 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import special

from . import asymptotics
from .fields import dini_terms
from .solvers.abel_fredholm import AbelFredholmSolution
from .solvers.weak_form import SeriesSolution
from .special.zeros import bessel_j2_zeros

__all__ = ["Bilateral", "Series", "AbelFredholm", "Asymptotic", "Spinning"]


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
    """The truncated weak form (published or complete) at N terms: sums of eqs. (25), (26)."""

    solution: SeriesSolution
    dini_is_truncation = False

    @property
    def rigid_rotation(self) -> float:
        omega = self.solution.rigid_rotation
        return 0.0 if self.solution.method == "published" else omega

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
