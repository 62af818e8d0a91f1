"""The ``Solution`` of ``solve`` and the cylinders' solve (``solve_cylinder``): regimes, methods, fields anywhere.

``solve`` itself (``dispatch``) asks the contact model (``models``) to solve: ``solve_cylinder`` here is the
cylinders' (``contact_models.cylinder``).

Units: r, z in the cylinder radius a; T* = 2T/(f F a) (eq. 32); tractions and stresses in
f p0 (p0 = F / (pi a^2)); displacements and slip in f p0 a / mu; omega (rigid rotation of
the upper cylinder beyond uniform twist) in f p0 / mu.

Regimes
-------
* ``stick``: |T*| <= 1.  b = 1, the bilateral field (eqs. 2-4) is exact, omega = 0.
* ``partial-slip``: 1 < |T*| < 4/3.  Stick disc 0 <= r < b, slip annulus b < r <= 1.
* ``gross-slip``: |T*| = 4/3.  b = 0, traction f p0 everywhere (spinning); the
  stresses are finite but the relative rotation is unbounded (omega ~ ln(1/b)/2 as
  b -> 0), so ``rigid_rotation``, ``slip`` and ``displacement`` are infinite there.

Negative torque mirrors positive torque: T*, omega, tractions, stresses, slip and
displacements change sign, b does not.

Methods
-------
* ``fast`` (default): the Abel-Fredholm method (``solvers.abel_fredholm``; T*, omega to
  ~1e-14, interface traction and slip to ~1e-12, about 1 ms per stick radius).  Interface
  values (z = 0) are the method's own; fields at z > 0 are summed from Dini amplitudes
  computed from its traction, with as many terms as the smallest requested z > 0 and the
  ``tolerance`` need (``fields.dini_terms``, at most ``fields.MAX_FIELD_TERMS``; what the
  cap omits is estimated and warned about once per call).  At the ends of partial slip it
  switches to the expansions of ``asymptotics`` (exact to rounding there): T* and omega
  for 1 - b < 2e-5, everything for 1 - b < 1e-6 and for b < 1e-8.  ``solve(torque=)``
  inverts the same T*(b), so both directions switch at the same place.
* ``complete`` / ``published``: the weak forms of ``solvers.weak_form`` at ``n_terms``
  (1 to ``MAX_SERIES_TERMS``).

Each kind of solution is a backend of ``backends`` with one small interface (``backends.Backend``);
each method is a backend class in the table ``METHODS`` (``backends.Method``), through which
``solve`` dispatches.  ``Solution`` adds the sign, the regime and the fields off the interface.  The inverse problem
(torque -> b) is in ``inverse``.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from . import fields, validation
from .backends import DEFAULT_METHOD, DEFAULT_N_TERMS, METHODS, Bilateral, Series
from .criteria import GROSS_SLIP_TORQUE
from .diagnostics import TruncationWarning, UnphysicalResultWarning
from .records import SolutionRecord
from .solvers.weak_form import MAX_SERIES_TERMS

__all__ = [
    "Solution",
    "solve_cylinder",
    "with_tolerance",
    "METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_N_TERMS",
    "MAX_SERIES_TERMS",
    "torque_curve",
]


@dataclass(frozen=True)
class Solution:
    """State of the interface and the fields for one torque (see the module docstring).

    Attributes
    ----------
    stick_radius : float
        b/a in [0, 1].
    torque : float
        T* = 2T/(f F a), signed.
    rigid_rotation : float
        omega in f p0 / mu, signed; 0 in stick, +-inf at gross slip, nan for the
        ``published`` formulation (it has no such unknown).
    regime : str
        "stick", "partial-slip" or "gross-slip".
    method : str
    n_terms : int or None
        Series methods: the N of the weak form.  ``fast``: the number of Dini terms for
        fields at z > 0 if given, else None (chosen per call from z and ``tolerance``).
    tolerance : float
        Absolute accuracy asked of the fields off the interface (f p0, f p0 a / mu).
    backend
        The solution for positive torque (``backends``).
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    regime: str
    method: str
    n_terms: int | None
    tolerance: float = fields.DEFAULT_TOLERANCE
    backend: object = field(default=None, repr=False, compare=False)

    #: The name of the contact model (``models.MODELS``) whose solution this is.
    model = "cylinder"

    @property
    def sign(self) -> float:
        return -1.0 if self.torque < 0 else 1.0

    # -- interface ----------------------------------------------------------------------
    def traction(self, r):
        """Interface shear traction sigma_zt(r, 0) / (f p0), eqs. (8), (26)."""
        r = validation.coordinates(r)
        return self.sign * self._physical(self.backend.traction(r), r, "traction")

    def slip(self, r):
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu (0 on the stick disc up to the method's error)."""
        r = validation.coordinates(r)
        return 2.0 * self.sign * self._physical(self.backend.displacement(r), r, "slip")

    def _physical(self, values, r, kind):
        """``values`` (positive torque), with an UnphysicalResultWarning once if a truncated weak form
        puts the traction above the friction limit or the slip below 0 (its Gibbs oscillation)."""
        if not isinstance(self.backend, Series) or not values.size:
            return values
        if kind == "traction":
            worst = float(np.max(np.abs(values)))
            bad = worst > 1.0 + 1e-12
            text = f"|traction| up to {worst:.8g}, above the friction limit 1"
        else:
            slipping = r > self.stick_radius
            worst = float(np.min(values[slipping])) if slipping.any() else 0.0
            bad = worst < -1e-12 * max(1.0, float(np.max(np.abs(values))))
            text = f"slip down to {2 * worst:.3g} < 0 on the slip annulus"
        if bad:
            warnings.warn(
                f"the {self.method} weak form at n_terms={self.n_terms} gives {text}: the truncated series "
                "oscillates (Gibbs) near r = b and r = 1; raise n_terms or use the default method",
                UnphysicalResultWarning,
                stacklevel=3,
            )
        return values

    # -- fields anywhere -----------------------------------------------------------------
    def _series(self, z, weight_power):
        """(lam_n, c_n) for the points z > 0, or None without a corrective field.

        Warns once (``TruncationWarning``) when the terms a solution known at the interface
        can afford (``fields.MAX_FIELD_TERMS``, or the user's ``n_terms``) leave a tail
        above ``tolerance`` at the smallest z > 0, with the estimate of ``fields.tail_estimate``.
        """
        positive = z[z > 0]
        if not positive.size:
            return None
        z_min = float(positive.min())
        series = self.backend.dini(z_min, self.tolerance)
        if series is None:
            return None
        lam, amplitudes = series
        if self.backend.dini_is_truncation and fields.required_terms(z_min, self.tolerance) > lam.size:
            b = self.backend.stick_radius
            radius = b if b > 0 else None  # where the terms add in phase; spinning: a bound (the axis)
            bound = fields.tail_estimate(lam, amplitudes, weight_power, z_min, radius)
            if bound > self.tolerance:
                what = "stresses" if weight_power else "displacements"
                warnings.warn(
                    f"{what} at z down to {z_min:.3g} are summed with {lam.size} Dini terms: the omitted tail "
                    f"is estimated at {bound:.1e} (tolerance={self.tolerance:g}; from the decay of the computed "
                    f"amplitudes); interface values (z = 0) are exact and the error falls like "
                    f"exp(-{lam[-1]:.0f} z) away from it",
                    TruncationWarning,
                    stacklevel=3,
                )
        return lam, amplitudes

    def stress(self, r, z):
        """(sigma_zt, sigma_rt) / (f p0) at (r, z), z >= 0; eqs. (2), (3), (23), (24)."""
        r, z, shape = _flat_points(r, z)
        backend = self.backend
        sigma_zt = backend.torque * r
        sigma_rt = np.zeros(r.shape)
        inside = z > 0
        series = self._series(z, 1)
        if series is not None:
            lam, amplitudes = series
            ri, zi = r[inside], z[inside]
            weights = amplitudes * lam
            sigma_zt[inside] -= fields.series_sum(1, lam, weights, ri, zi, self.tolerance)
            sigma_rt[inside] = -fields.series_sum(2, lam, weights, ri, zi, self.tolerance)
        face = ~inside
        if face.any():
            sigma_zt[face] = self._physical(backend.traction(r[face]), r[face], "traction")
            sigma_rt[face] = backend.sigma_rt(r[face])
        return self.sign * sigma_zt.reshape(shape), self.sign * sigma_rt.reshape(shape)

    def displacement(self, r, z):
        """u_theta(r, z) of the upper cylinder in f p0 a / mu, z >= 0; eqs. (4), (22)."""
        r, z, shape = _flat_points(r, z)
        backend = self.backend
        out = backend.torque * r * z + backend.rigid_rotation * r
        inside = z > 0
        series = self._series(z, 0)
        if series is not None:
            lam, amplitudes = series
            out[inside] += fields.series_sum(1, lam, amplitudes, r[inside], z[inside], self.tolerance)
        face = ~inside
        if face.any():
            out[face] = backend.displacement(r[face])
        return self.sign * out.reshape(shape)

    def record(self) -> SolutionRecord:
        """The solution's result record (``records``: keys and their quantities)."""
        return SolutionRecord(self.stick_radius, self.torque, self.rigid_rotation, self.regime, self.method,
                              self.n_terms, self.model, self.backend.metadata())

    def as_dict(self) -> dict:
        """JSON-ready summary (a non-finite rigid rotation becomes None)."""
        return self.record().as_dict()


def _flat_points(r, z):
    """Validated coordinates broadcast together and flattened: (r, z, shape)."""
    r, z = np.broadcast_arrays(*validation.coordinates(r, z))
    return r.ravel(), z.ravel(), r.shape


def _solution(backend, sign, regime, method, n_terms, tolerance, torque=None) -> Solution:
    """A Solution from a positive-torque backend; ``torque`` overrides the reported T* (inverse problem)."""
    omega = backend.rigid_rotation if METHODS[method].has_rigid_rotation else math.nan
    return Solution(
        stick_radius=backend.stick_radius,
        torque=sign * backend.torque if torque is None else torque,
        rigid_rotation=sign * omega + 0.0,  # no -0.0 in stick
        regime=regime,
        method=method,
        n_terms=n_terms,
        tolerance=tolerance,
        backend=backend,
    )


def _for_stick_radius(b: float, method: str, n_terms) -> tuple:
    """(backend, regime) for 0 <= b < 1, positive torque."""
    regime = "gross-slip" if b == 0.0 else "partial-slip"
    return METHODS[method].at_stick_radius(b, n_terms), regime


def solve_cylinder(stick_radius=None, torque=None, *, method=None, n_terms=None, tolerance=None) -> Solution:
    """``solve`` for the cylinders (model "cylinder"); the arguments, errors and warnings are those of
    ``dispatch.solve``, which also validates the model."""
    method = validation.choice("method", DEFAULT_METHOD if method is None else method, METHODS)
    kind = METHODS[method]
    if n_terms is not None or kind.default_n_terms is not None:
        n_terms = validation.positive_int(
            "n_terms", kind.default_n_terms if n_terms is None else n_terms, kind.max_n_terms,
            note=f" (method {method!r}; memory and time grow like n_terms^2)")
    tolerance = validation.real_number(
        "tolerance", fields.DEFAULT_TOLERANCE if tolerance is None else tolerance, 0.0, 1.0)
    if (stick_radius is None) == (torque is None):
        raise ValueError("give exactly one of stick_radius (in [0, 1]) and torque (in [-4/3, 4/3])")

    if stick_radius is not None:
        b = validation.real_number("stick_radius", stick_radius, 0.0, 1.0)
        if b == 1.0:
            return _solution(Bilateral(1.0), 1.0, "stick", method, n_terms, tolerance)
        backend, regime = _for_stick_radius(b, method, n_terms)
        return _solution(backend, 1.0, regime, method, n_terms, tolerance)

    t = validation.torque("torque", torque)
    magnitude, sign = abs(t), (-1.0 if t < 0 else 1.0)
    if magnitude <= 1.0:
        return _solution(Bilateral(magnitude), sign, "stick", method, n_terms, tolerance)
    if magnitude >= GROSS_SLIP_TORQUE * (1 - validation.TORQUE_TOLERANCE):
        backend, _ = _for_stick_radius(0.0, method, n_terms)
        return _solution(backend, sign, "gross-slip", method, n_terms, tolerance)
    backend = kind.at_torque(magnitude, n_terms)
    # Report the torque asked for; the fields use the backend's own T*(b), which differs
    # from it by the root-finding tolerance (about 1e-12 or less).
    return _solution(backend, sign, "partial-slip", method, n_terms, tolerance, torque=t)


def torque_curve(stick_radii, *, method=None, n_terms=None) -> np.ndarray:
    """T*(b) for an array of stick radii (Fig. 3), one solve per radius."""
    radii = np.asarray(stick_radii, dtype=float)
    torques = [solve_cylinder(stick_radius=float(b), method=method, n_terms=n_terms).torque for b in radii.ravel()]
    return np.array(torques).reshape(radii.shape)


def with_tolerance(solution: Solution, tolerance: float) -> Solution:
    """The same solution with another field tolerance (the backend and its cached amplitudes are shared)."""
    return dataclasses.replace(solution, tolerance=validation.real_number("tolerance", tolerance, 0.0, 1.0))
