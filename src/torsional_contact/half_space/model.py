"""The uniform-pressure half-space model: ``UNIFORM_HALF_SPACE``, the entry "half-space" of ``models.MODELS``.

Two elastically similar half-spaces pressed together over the disc r < a by a uniform pressure
p-bar = F/(pi a^2), twisted against each other.  Units: those of the package (docs/conventions.md).
Closed forms in ``half_space.closed_form`` (equations (H1)-(H14)), fields in the bodies in
``half_space.fields``.

* ``HalfSpaceState``: the positive-torque state for one stick radius, with the interface
  of ``backends`` (stick_radius, torque, rigid_rotation, traction, displacement, sigma_rt,
  metadata).
* ``HalfSpaceSolution``: a ``solution.Solution`` (same attributes) whose fields off the
  interface come from ``half_space.fields`` instead of the cylinders' Dini series.
* ``UniformHalfSpace`` (the object ``UNIFORM_HALF_SPACE``): the contact model (``contact_models.base``).
  Its monotonic numbers b(tau), Omega(tau), W_mono(tau) are the closed forms (H5), (H6), (H11).

Regimes: "stick" only at T* = 0 (b = 1), "partial-slip" for 0 < |T*| < 4/3 (the half-space
slips at any torque), "gross-slip" at |T*| = 4/3 (b = 0, Omega = +inf).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..contact_models.base import FIELDS, ContactModel
from ..criteria import GROSS_SLIP_TORQUE
from ..solution import Solution, _flat_points
from ..validation import TORQUE_TOLERANCE
from . import closed_form, fields, interface

__all__ = ["MODEL", "HalfSpaceState", "HalfSpaceSolution", "UniformHalfSpace", "UNIFORM_HALF_SPACE"]

#: The model's name in ``models.MODELS``.
MODEL = "half-space"



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
        return {}


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


def _solution(b: float, torque: float, sign: float, regime: str, tolerance: float, omega=None) -> HalfSpaceSolution:
    omega = float(closed_form.rigid_rotation(b)) if omega is None else omega
    backend = HalfSpaceState(stick_radius=b, torque=torque, rigid_rotation=omega)
    return HalfSpaceSolution(
        stick_radius=b, torque=sign * torque + 0.0, rigid_rotation=sign * omega + 0.0, regime=regime, method=None,
        n_terms=None, tolerance=tolerance, backend=backend)


class UniformHalfSpace(ContactModel):
    """Two elastically similar half-spaces under a uniform pressure over r < a (module docstring).

    ``rigid_rotation`` is Omega = arccosh(1/b)/2 (f p-bar / mu), the far-field rotation of the
    upper body relative to the stick disc (the relative twist of remote points is 2 Omega);
    slip starts at any torque, the bodies spin at T* = 4/3.
    """

    name = MODEL
    description = "two elastically similar half-spaces, uniform pressure over the contact disc"
    bodies = "the half-spaces"
    slip_onset_torque = 0.0
    gross_slip_torque = GROSS_SLIP_TORQUE
    gross_slip_text = "4/3"
    elastic_bodies = 2
    shaft = False
    fields = FIELDS

    def solution_at_radius(self, b: float, tolerance: float) -> HalfSpaceSolution:
        regime = "stick" if b == 1.0 else "gross-slip" if b == 0.0 else "partial-slip"
        return _solution(b, float(closed_form.torque(b)), 1.0, regime, tolerance)

    def solution_at_torque(self, magnitude: float, sign: float, tolerance: float) -> HalfSpaceSolution:
        if magnitude == 0.0:
            return _solution(1.0, 0.0, 1.0, "stick", tolerance)
        if magnitude >= GROSS_SLIP_TORQUE * (1 - TORQUE_TOLERANCE):
            return _solution(0.0, GROSS_SLIP_TORQUE, sign, "gross-slip", tolerance)
        b, omega, _ = closed_form.state(magnitude)  # scalar arithmetic: microseconds
        return _solution(b, magnitude, sign, "partial-slip", tolerance, omega)

    def monotonic_points(self, tau):
        """(H5), (H6), (H11): b, Omega_m, W_mono for an array of 0 <= tau <= 4/3."""
        return closed_form.points(np.asarray(tau, dtype=float))


#: The model object of the table ``models.MODELS``.
UNIFORM_HALF_SPACE = UniformHalfSpace()
