"""The half-space model behind ``solve(..., model="half-space")`` and ``history(..., model="half-space")``.

Units: those of the package (docs/conventions.md).  Closed forms in ``half_space.closed_form``
(equations (H1)-(H14)), fields in the bodies in ``half_space.fields``.

* ``HalfSpaceState``: the positive-torque state for one stick radius, with the interface
  of ``backends`` (stick_radius, torque, rigid_rotation, traction, displacement, sigma_rt,
  metadata).
* ``HalfSpaceSolution``: a ``solution.Solution`` (same attributes) whose fields off the
  interface come from ``half_space.fields`` instead of the cylinders' Dini series.
* ``solve_half_space``: what ``solve`` calls for the half-space model.
* ``HalfSpaceMonotonic``: the monotonic solution as the memory rules use it (``point``,
  ``points``, ``solution``), the half-space sibling of ``histories.monotonic.CylinderMonotonic``.

Regimes: "stick" only at T* = 0 (b = 1), "partial-slip" for 0 < |T*| < 4/3 (the half-space
slips at any torque), "gross-slip" at |T*| = 4/3 (b = 0, Omega = +inf).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .. import fields as cylinder_fields
from .. import validation
from ..criteria import GROSS_SLIP_TORQUE
from ..models import HALF_SPACE as MODEL
from ..models import validated
from ..solution import Solution, _flat_points
from . import closed_form, fields, interface

__all__ = ["MODEL", "HalfSpaceState", "HalfSpaceSolution", "solve_half_space", "HalfSpaceMonotonic"]



@dataclass(frozen=True)
class HalfSpaceState:
    """Half-space contact at stick radius b for a positive torque (the ``backends`` interface)."""

    stick_radius: float
    torque: float
    rigid_rotation: float
    dini_is_truncation = False

    def traction(self, r):
        """sigma_zt(r, 0) / (f p0), eq. (H7); 1 on the slip annulus."""
        return interface.interface_traction(r, self.stick_radius)

    def displacement(self, r):
        """u_theta(r, 0+) = s(r)/2 (f p0 a / mu), eq. (H8)."""
        return 0.5 * interface.interface_slip(r, self.stick_radius)

    def sigma_rt(self, r):
        """sigma_rt(r, 0) / (f p0), eq. (H9) (log-singular at the contact edge r = 1)."""
        return interface.interface_sigma_rt(r, self.stick_radius)

    def dini(self, z_min, tolerance):
        return None  # no Dini series: the fields come from ``half_space.fields``

    def metadata(self) -> dict:
        return {"model": MODEL}


@dataclass(frozen=True)
class HalfSpaceSolution(Solution):
    """``solve(..., model="half-space")``: the attributes of ``Solution`` for two half-spaces.

    ``rigid_rotation`` is Omega = arccosh(1/b)/2 (f p0 / mu), the far-field rotation of the
    upper body relative to the stick disc (the relative twist of remote points is 2 Omega);
    ``method`` and ``n_terms`` are None (the model is closed-form); ``tolerance`` is kept
    for the interface of ``Solution`` (the fields are computed to about 1e-13 regardless).
    """

    model: str = MODEL

    def stress(self, r, z):
        """(sigma_zt, sigma_rt) / (f p0) at (r, z), z >= 0: (H7), (H9) on z = 0, quadrature (H10) inside."""
        r, z, shape = _flat_points(r, z)
        b = self.backend.stick_radius
        sigma_zt, sigma_rt = np.zeros(r.shape), np.zeros(r.shape)
        inside = z > 0
        if inside.any():
            sigma_zt[inside], sigma_rt[inside] = fields.stress(r[inside], z[inside], b)
        face = ~inside
        if face.any():
            sigma_zt[face] = self.backend.traction(r[face])
            sigma_rt[face] = self.backend.sigma_rt(r[face])
        return self.sign * sigma_zt.reshape(shape), self.sign * sigma_rt.reshape(shape)

    def displacement(self, r, z):
        """u_theta(r, z) of the upper half-space (f p0 a / mu), z >= 0, eq. (H10); +inf at spinning."""
        r, z, shape = _flat_points(r, z)
        out = np.zeros(r.shape)
        inside = z > 0
        if inside.any():
            out[inside] = fields.displacement(r[inside], z[inside], self.backend.stick_radius)
        face = ~inside
        if face.any():
            out[face] = self.backend.displacement(r[face])
        return self.sign * out.reshape(shape)

    def as_dict(self) -> dict:
        record = super().as_dict()
        record["model"] = MODEL
        return record


def _validated_options(method, n_terms, tolerance) -> float:
    """The half-space model has no method and no n_terms; ``tolerance`` as for the cylinders."""
    validated(MODEL, method, n_terms)
    return validation.real_number(
        "tolerance", cylinder_fields.DEFAULT_TOLERANCE if tolerance is None else tolerance, 0.0, 1.0)


def _solution(b: float, torque: float, sign: float, regime: str, tolerance: float) -> HalfSpaceSolution:
    omega = float(closed_form.rigid_rotation(b))
    backend = HalfSpaceState(stick_radius=b, torque=torque, rigid_rotation=omega)
    return HalfSpaceSolution(
        stick_radius=b, torque=sign * torque + 0.0, rigid_rotation=sign * omega + 0.0, regime=regime, method=None,
        n_terms=None, tolerance=tolerance, backend=backend)


def solve_half_space(stick_radius=None, torque=None, *, method=None, n_terms=None, tolerance=None) -> HalfSpaceSolution:
    """The half-space contact for a stick radius or a torque (see ``solve``; same arguments and errors).

    Raises
    ------
    ValueError
        As ``solve`` for the stick radius, the torque (|T*| > 4/3: the bodies spin) and the
        tolerance; for a ``method`` or ``n_terms`` (they apply to the cylinder model only).
    """
    tolerance = _validated_options(method, n_terms, tolerance)
    if (stick_radius is None) == (torque is None):
        raise ValueError("give exactly one of stick_radius (in [0, 1]) and torque (in [-4/3, 4/3])")
    if stick_radius is not None:
        b = validation.real_number("stick_radius", stick_radius, 0.0, 1.0)
        regime = "stick" if b == 1.0 else "gross-slip" if b == 0.0 else "partial-slip"
        return _solution(b, float(closed_form.torque(b)), 1.0, regime, tolerance)
    try:
        t = validation.torque("torque", torque)
    except ValueError as error:  # the same message, about these bodies
        raise ValueError(str(error).replace("the cylinders spin", "the half-spaces spin")) from None
    magnitude, sign = abs(t), (-1.0 if t < 0 else 1.0)
    if magnitude == 0.0:
        return _solution(1.0, 0.0, 1.0, "stick", tolerance)
    if magnitude >= GROSS_SLIP_TORQUE * (1 - validation.TORQUE_TOLERANCE):
        return _solution(0.0, GROSS_SLIP_TORQUE, sign, "gross-slip", tolerance)
    b = float(closed_form.stick_radius(magnitude))
    return _solution(b, magnitude, sign, "partial-slip", tolerance)


_CACHE_SIZE = 4096


@dataclass(frozen=True)
class HalfSpaceMonotonic:
    """The monotonic solution mono(tau) of the half-space, as the memory rules use it.

    The interface every model offers to ``histories`` (``histories.monotonic.monotonic_model`` picks it):
    ``point(tau)`` -> (b, Omega_m, W_mono), ``points(tau)`` the same for arrays, ``solution(tau)``
    the full state (cached), and the attributes ``model``, ``method``, ``n_terms``.
    """

    model: str = MODEL
    method: None = None
    n_terms: None = None
    _solutions: dict = field(default_factory=dict, repr=False, compare=False)

    def point(self, tau: float) -> tuple[float, float, float]:
        """(b, Omega_m, W_mono) at 0 <= tau <= 4/3."""
        return closed_form.state(min(max(float(tau), 0.0), GROSS_SLIP_TORQUE))

    def points(self, tau):
        """Arrays b, Omega_m, W_mono for an array of 0 <= tau <= 4/3."""
        tau = np.clip(np.asarray(tau, dtype=float), 0.0, GROSS_SLIP_TORQUE)
        b, omega, work = closed_form.points(tau.ravel())
        return b.reshape(tau.shape), omega.reshape(tau.shape), work.reshape(tau.shape)

    def solution(self, tau: float) -> HalfSpaceSolution:
        """mono(tau) for 0 <= tau <= 4/3 (cached)."""
        tau = validation.torque("tau", tau)
        if tau < 0:
            raise ValueError(f"tau must lie in [0, 4/3], got {tau!r}")
        if tau not in self._solutions:
            if len(self._solutions) >= _CACHE_SIZE:
                self._solutions.clear()
            self._solutions[tau] = solve_half_space(torque=tau)
        return self._solutions[tau]

