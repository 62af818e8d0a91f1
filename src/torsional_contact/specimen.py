r"""A specimen in physical units: the laboratory's front door to the normalised solvers.

``Specimen(radius=, normal_force=, friction=, shear_modulus=, gauge_length=None)`` holds
two elastically similar cylinders of radius a pressed end to end by F, with Coulomb
friction f and shear modulus mu (G), and optionally the gauge length L over which a rig
measures the twist (two cross-sections L/2 either side of the interface).  Every value is
a float in SI units, a pint quantity or a string such as "5 mm" (``units``).

Conversions (docs/conventions.md; p0 = F / (pi a^2), eq. 1; T* = 2T/(f F a), eq. 32):

=================================  =========================  =====================
quantity                           SI value                   normalised by
=================================  =========================  =====================
torque T [N m]                     T* f F a / 2               ``torque_scale``
stick radius, r, z [m]             (b, r, z) a                ``radius``
traction, stresses [Pa]            (...) f p0                 ``stress_scale``
displacement, slip [m]             (...) f p0 a / mu          ``displacement_scale``
rigid rotation omega [rad]         omega f p0 / mu            ``rotation_scale``
twist over L [rad]                 (f p0 / mu)(T* L/a + 2 omega)
energy [J]                         W (f p0)^2 a^3 / mu        ``energy_scale``
=================================  =========================  =====================

The twist: the displacement of the upper cylinder is u_theta = (f p0 a / mu)(T* r z + omega r
+ a Dini series that decays like exp(-lambda_1 z)) in units of a, so far from the interface a
cross-section at height z rotates by u_theta / r = (f p0 / mu)(T* z / a + omega); the lower
cylinder mirrors it, and two sections L/2 either side differ by (f p0 / mu)(T* L / a + 2 omega).
For the elastic shaft alone (omega = 0) this is T L / (mu J) with J = pi a^4 / 2, the
uniform-twist formula.  The Dini series is below 1e-3 of the interface value at z > 1.8 a
(lambda_1 = 5.14), so the formula holds for sections at least about 2 a from the interface.

``solve(torque=)`` (or ``stick_radius=``, a length) gives a ``PhysicalState``; ``history``
the states along a torque history (torques in N m) with their dissipated energy in J;
``signal`` a long sampled torque signal with its closed cycles and their energies.  Each
result keeps the normalised object as ``.normalized``.  The solvers never see a unit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import models, units, validation
from .validation import TORQUE_TOLERANCE

__all__ = ["Specimen", "PhysicalState", "PhysicalSignal", "physical_record"]

@dataclass(frozen=True)
class Specimen:
    """Two elastically similar flat-ended cylinders in physical units (module docstring).

    Parameters
    ----------
    radius : float, quantity or str
        Cylinder radius a (m), > 0.
    normal_force : float, quantity or str
        Normal force F (N), > 0; the pressure p0 = F / (pi a^2) is uniform (eq. 1).
    friction : float or str
        Coulomb friction coefficient f, > 0.
    shear_modulus : float, quantity or str
        Shear modulus mu = G (Pa) of both cylinders, > 0.
    gauge_length : float, quantity or str, optional
        Distance L (m) between the two cross-sections whose relative rotation is the
        measured ``twist``, symmetric about the interface; >= 0.  Without it, states of the
        cylinders have no ``twist``.  Models whose bodies are not shafts (the half-space models)
        take none: their twist is the relative rotation of remote points.
    model : str or ContactModel, optional
        The contact model (``models``; default "cylinder"): what is pressed together, under which
        pressure.  ``radius`` is then the contact radius, ``normal_force`` the load, and the
        pressure scale p-bar = F / (pi a^2) the mean contact pressure.  The methods' own ``model=``
        overrides it for one call.

    Raises
    ------
    ValueError
        Naming the argument: a value of the wrong dimension (naming the dimension it
        needs), a string that is not a quantity, a non-finite or non-positive value.
    """

    radius: float
    normal_force: float
    friction: float
    shear_modulus: float
    gauge_length: float | None = None
    model: object = None

    def __post_init__(self):
        set_ = object.__setattr__
        set_(self, "radius", units.positive_si("radius", self.radius, "length"))
        set_(self, "normal_force", units.positive_si("normal_force", self.normal_force, "force"))
        set_(self, "friction", units.positive_si("friction", self.friction, "dimensionless"))
        set_(self, "shear_modulus", units.positive_si("shear_modulus", self.shear_modulus, "pressure"))
        if self.gauge_length is not None:
            set_(self, "gauge_length", units.positive_si("gauge_length", self.gauge_length, "length", allow_zero=True))
        contact = models.get(self.model)
        set_(self, "model", contact.name)
        set_(self, "_contact", contact)
        if self.gauge_length is not None and not contact.shaft:
            raise ValueError(f"gauge_length does not apply to model {contact.name!r}: {contact.bodies} are not shafts "
                             "(their twist is the relative rotation of remote points; leave it out)")

    @staticmethod
    def hertz_contact_radius(sphere_radius, normal_force, youngs_modulus, poisson_ratio) -> float:
        """Hertz's contact radius a = (3 F R / (4 E*))^(1/3) (m) of a sphere of radius R on a flat of the same material.

        Two elastically similar bodies: 1/E* = (1 - nu^2)/E + (1 - nu^2)/E, E* = E / (2 (1 - nu^2)).
        Arguments as floats in SI units, pint quantities or strings ("5 mm"); ``poisson_ratio`` in (-1, 0.5].
        """
        radius = units.positive_si("sphere_radius", sphere_radius, "length")
        force = units.positive_si("normal_force", normal_force, "force")
        modulus = units.positive_si("youngs_modulus", youngs_modulus, "pressure")
        nu = validation.real_number("poisson_ratio", poisson_ratio, -1.0, 0.5)
        if nu <= -1.0:
            raise ValueError(f"poisson_ratio must lie in (-1, 0.5], got {poisson_ratio!r}")
        effective = modulus / (2.0 * (1.0 - nu * nu))
        return (3.0 * force * radius / (4.0 * effective)) ** (1.0 / 3.0)

    @classmethod
    def from_sphere(cls, sphere_radius, normal_force, friction, youngs_modulus, poisson_ratio) -> Specimen:
        """A sphere of radius R pressed on a flat of the same material by F (model "hertz").

        The contact radius from ``hertz_contact_radius`` (Hertz), the shear modulus mu = E / (2 (1 + nu));
        for a measured contact radius use ``Specimen(radius=a, ..., model="hertz")`` instead.
        """
        nu = validation.real_number("poisson_ratio", poisson_ratio, -1.0, 0.5)
        radius = cls.hertz_contact_radius(sphere_radius, normal_force, youngs_modulus, nu)
        modulus = units.positive_si("youngs_modulus", youngs_modulus, "pressure")
        return cls(radius=radius, normal_force=normal_force, friction=friction,
                   shear_modulus=modulus / (2.0 * (1.0 + nu)), model="hertz")

    @property
    def contact(self):
        """The contact model object (``models``)."""
        return self._contact

    def _model(self, model):
        """The model of one call: ``model`` if given, else the specimen's."""
        return self._contact if model is None else models.get(model)

    # ---------------------------------------------------------------- scales
    @property
    def pressure(self) -> float:
        """p0 = F / (pi a^2) (Pa), eq. (1)."""
        return self.normal_force / (math.pi * self.radius**2)

    @property
    def torque_scale(self) -> float:
        """T / T* = f F a / 2 (N m): the slip-onset torque."""
        return 0.5 * self.friction * self.normal_force * self.radius

    @property
    def slip_onset_torque(self) -> float:
        """Torque at which slip starts (N m): the model's T* onset (1 for the cylinders) times f F a / 2."""
        return self._contact.slip_onset_torque * self.torque_scale

    @property
    def gross_slip_torque(self) -> float:
        """Torque at which the bodies spin (N m): the model's gross-slip T* (4/3 for the cylinders: 2 f F a / 3)."""
        return self._contact.gross_slip_torque * self.torque_scale

    @property
    def stress_scale(self) -> float:
        """f p0 (Pa)."""
        return self.friction * self.pressure

    @property
    def rotation_scale(self) -> float:
        """f p0 / mu (rad): the unit of omega."""
        return self.stress_scale / self.shear_modulus

    @property
    def displacement_scale(self) -> float:
        """f p0 a / mu (m)."""
        return self.rotation_scale * self.radius

    @property
    def energy_scale(self) -> float:
        """(f p0)^2 a^3 / mu (J) = (f F)^2 / (pi^2 mu a)."""
        return self.stress_scale**2 * self.radius**3 / self.shear_modulus

    def scales(self) -> dict:
        """The factors from normalised to SI units, by quantity (``records.QUANTITIES``; JSON-ready)."""
        return {"torque": self.torque_scale, "length": self.radius, "stress": self.stress_scale,
                "displacement": self.displacement_scale, "rotation": self.rotation_scale,
                "energy": self.energy_scale, "pressure": self.pressure}

    def as_dict(self) -> dict:
        return {"radius": self.radius, "normal_force": self.normal_force, "friction": self.friction,
                "shear_modulus": self.shear_modulus, "gauge_length": self.gauge_length, "model": self.model}

    # ---------------------------------------------------------------- conversions
    def normalized_torque(self, torque, name: str = "torque"):
        """T* = 2 T / (f F a) of a torque in N m (float, quantity, string or array of them)."""
        if isinstance(torque, str) or np.ndim(torque) == 0:
            return units.si_value(name, torque, "torque") / self.torque_scale
        return units.si_array(name, torque, "torque") / self.torque_scale

    def _checked_torque(self, name: str, torque, model=None) -> float:
        contact = self._model(model)
        t = self.normalized_torque(torque, name)
        if not math.isfinite(t):
            raise ValueError(f"{name} must be a finite torque (N m), got {torque!r}")
        gross = contact.gross_slip_torque
        if abs(t) > gross * (1 + TORQUE_TOLERANCE):
            limit = gross * self.torque_scale
            raise ValueError(
                f"{name} must lie in [-{limit:.6g}, {limit:.6g}] N m (|T*| <= {contact.gross_slip_text}, the "
                f"gross-slip torque of model {contact.name!r}), got {torque!r} (T* = {t:.6g}): beyond it "
                f"{contact.bodies} spin, there is no static solution")
        return max(-gross, min(gross, t))

    def twist(self, torque_star, rigid_rotation, model=None):
        """Twist (rad): (f p0 / mu) times the model's ``contact_twist`` (module docstring).

        Cylinders: over the gauge length, (f p0 / mu)(T* L / a + 2 omega); half-space models: the
        relative rotation of remote points, (f p-bar / mu) n Omega (n elastic bodies).
        """
        contact = self._model(model)
        if contact.shaft and self.gauge_length is None:
            raise ValueError("the twist needs the specimen's gauge_length (distance between the two cross-sections)")
        length = self.gauge_length / self.radius if contact.shaft else None
        return self.rotation_scale * contact.contact_twist(torque_star, rigid_rotation, length)

    def shaft_compliance(self) -> float:
        """Twist per torque of the elastic shaft over the gauge length, L / (mu J), J = pi a^4 / 2 (rad / (N m))."""
        if self.gauge_length is None:
            raise ValueError("the shaft compliance needs the specimen's gauge_length (cylinders)")
        return self.gauge_length / (self.shear_modulus * 0.5 * math.pi * self.radius**4)

    # ---------------------------------------------------------------- solutions
    def solve(self, torque=None, *, stick_radius=None, method=None, n_terms=None, tolerance=None,
              model=None) -> PhysicalState:
        """The state for a torque (N m) or a stick radius (a length, 0 <= c <= radius): exactly one of the two.

        ``model``: a name of ``models.MODELS`` or a model object (default: the specimen's), as for ``solve``.

        Raises ValueError naming the argument: both or neither, a wrong dimension, |T| above
        the model's gross-slip torque (2 f F a / 3 for the cylinders: they spin), a stick radius
        outside [0, a].
        """
        contact = self._model(model)
        if (torque is None) == (stick_radius is None):
            raise ValueError("give exactly one of torque (N m) and stick_radius (a length in [0, radius])")
        if torque is not None:
            normalized = contact.solve(torque=self._checked_torque("torque", torque, contact), method=method,
                                       n_terms=n_terms, tolerance=tolerance)
        else:
            c = units.si_value("stick_radius", stick_radius, "length")
            if not math.isfinite(c) or not 0.0 <= c <= self.radius:
                raise ValueError(f"stick_radius must lie in [0, {self.radius:g}] m (0 to the radius), got "
                                 f"{stick_radius!r}")
            normalized = contact.solve(stick_radius=c / self.radius, method=method, n_terms=n_terms,
                                       tolerance=tolerance)
        return PhysicalState(self, normalized, contact)

    def history(self, torques, *, method=None, n_terms=None, model=None) -> tuple[PhysicalState, ...]:
        """States after each step of a torque history (N m) from the virgin interface (memory rules).

        Each state has ``dissipated_energy`` (J) besides the keys of ``solve``.
        """
        from .histories import history

        contact = self._model(model)
        values = self._torque_list("torques", torques, contact)
        return tuple(PhysicalState(self, s, contact) for s in history(values, method=method, n_terms=n_terms,
                                                                      model=contact))

    def signal(self, torques, *, method=None, n_terms=None, model=None) -> PhysicalSignal:
        """A long sampled torque signal (N m): turning points, closed cycles and energies (``histories.signal``)."""
        from .histories import analyse_signal

        contact = self._model(model)
        values = np.asarray(self._torque_list("torques", torques, contact))
        return PhysicalSignal(self, analyse_signal(values, method=method, n_terms=n_terms, model=contact,
                                                   name="torques"), values, contact)

    def _torque_list(self, name: str, torques, contact) -> list[float]:
        values = units.si_array(name, torques, "torque") / self.torque_scale
        if values.size == 0:
            raise ValueError(f"{name} must contain at least one torque (N m)")
        return [self._checked_torque(f"{name}[{i}]", float(v) * self.torque_scale, contact)
                for i, v in enumerate(values)]

    # ---------------------------------------------------------------- cyclic loading
    def regime(self, torque_amplitude, *, model=None) -> str:
        """Slip regime of a torque cycling between -T_a and T_a (after the first loading).

        Cylinders (default): "stick" (T_a <= f F a / 2: the interface shakes down to full
        stick), "partial-slip" (cyclic slip of an annulus) or "gross-slip" (T_a >= 2 f F a / 3:
        the cylinders spin); every model by its ``ContactModel.regime`` (the half-space models slip
        at any T_a > 0).
        """
        contact = self._model(model)
        t = abs(self.normalized_torque(torque_amplitude, "torque_amplitude"))
        if not math.isfinite(t):
            raise ValueError(f"torque_amplitude must be a finite torque (N m), got {torque_amplitude!r}")
        return contact.regime(t)

    def energy_per_cycle(self, torque_amplitude, *, method=None, n_terms=None, model=None) -> float:
        """Energy (J) dissipated per cycle of a torque between -T_a and T_a: W(2 T*_a) (f p0)^2 a^3 / mu.

        Zero for T_a at or below the slip onset; W(A) = 4 W_mono(A/2) (the model's
        ``ContactModel.energy_per_cycle``).  Raises ValueError at or beyond the gross-slip torque
        (infinite: the bodies spin).
        """
        contact = self._model(model)
        t = self._checked_torque("torque_amplitude", torque_amplitude, contact)
        if abs(t) >= contact.gross_slip_torque:
            limit = contact.gross_slip_torque * self.torque_scale
            raise ValueError(f"torque_amplitude must be below the gross-slip torque {limit:.6g} N m "
                             f"for a finite energy per cycle, got {torque_amplitude!r}")
        return float(contact.energy_per_cycle(2.0 * abs(t), method=method, n_terms=n_terms)) * self.energy_scale


@dataclass(frozen=True)
class PhysicalState:
    """One interface state in SI units; ``normalized`` is the state of the solvers (``Solution`` or
    ``InterfaceState``).  Radii ``r``, ``z`` are lengths (m, quantities or strings), 0 <= r <= a."""

    specimen: Specimen
    normalized: object = field(repr=False)
    contact: object = field(default=None, repr=False)

    def __post_init__(self):
        if self.contact is None:
            object.__setattr__(self, "contact", self.specimen.contact)

    @property
    def torque(self) -> float:
        """T (N m)."""
        return self.normalized.torque * self.specimen.torque_scale

    @property
    def stick_radius(self) -> float:
        """Radius of the stick disc c (m)."""
        return self.normalized.stick_radius * self.specimen.radius

    @property
    def rigid_rotation(self) -> float:
        """omega f p0 / mu (rad): rotation of one body's stick zone relative to its remote points (cylinders: of
        each cylinder far from the interface beyond the uniform twist)."""
        return self.normalized.rigid_rotation * self.specimen.rotation_scale

    @property
    def twist(self) -> float:
        """The twist a rig measures (rad): over the gauge length for the cylinders (ValueError without one), the
        relative rotation of remote points for the half-space models (``Specimen.twist``)."""
        return float(self.specimen.twist(self.normalized.torque, self.normalized.rigid_rotation, self.contact))

    @property
    def regime(self) -> str:
        return self.normalized.regime

    @property
    def dissipated_energy(self) -> float:
        """Work against friction since the virgin state (J); history states only."""
        energy = getattr(self.normalized, "dissipated_energy", None)
        if energy is None:
            raise AttributeError("dissipated_energy belongs to history states (Specimen.history)")
        return energy * self.specimen.energy_scale

    @property
    def slip_fronts(self) -> tuple[float, ...]:
        """Remembered slip fronts (m); history states only."""
        return tuple(b * self.specimen.radius for b in self.normalized.slip_fronts)

    def _radii(self, r, name: str = "r") -> np.ndarray:
        a = self.specimen.radius
        values = units.si_array(name, r, "length")
        if not np.all(np.isfinite(values)) or np.any(values < 0) or np.any(values > a * (1 + 1e-15)):
            raise ValueError(f"{name} must be finite and lie in [0, {a:g}] m (0 to the radius)")
        out = np.minimum(values / a, 1.0)
        return out if not isinstance(r, str) and np.ndim(r) else out[0]

    def traction(self, r):
        """Interface shear traction (Pa) at radii r (m)."""
        return self.normalized.traction(self._radii(r)) * self.specimen.stress_scale

    def slip(self, r):
        """Slip s = 2 u_theta(r, 0+) (m) at radii r (m)."""
        return self.normalized.slip(self._radii(r)) * self.specimen.displacement_scale

    def stress(self, r, z):
        """(sigma_zt, sigma_rt) (Pa) at (r, z) (m), z >= 0 in the upper cylinder."""
        zz = units.si_array("z", z, "length") if np.ndim(z) else units.si_value("z", z, "length")
        s_zt, s_rt = self.normalized.stress(self._radii(r), np.asarray(zz) / self.specimen.radius)
        return s_zt * self.specimen.stress_scale, s_rt * self.specimen.stress_scale

    def displacement(self, r, z):
        """u_theta (m) of the upper cylinder at (r, z) (m), z >= 0."""
        zz = units.si_array("z", z, "length") if np.ndim(z) else units.si_value("z", z, "length")
        u = self.normalized.displacement(self._radii(r), np.asarray(zz) / self.specimen.radius)
        return u * self.specimen.displacement_scale

    def as_dict(self) -> dict:
        """SI values (as the state's record declares them: ``records``), ``units``, and the normalised state under
        ``normalized``."""
        return physical_record(self.normalized.record(), self.specimen, self.contact)


def physical_record(record, specimen: Specimen, contact=None) -> dict:
    """A result record (``records.Record``, or a list of them merged at one level) in SI units.

    Every field converts as its record declares it (``records``: no key is converted by its name);
    a record with a torque and a rigid rotation gains the ``twist`` a rig measures (cylinders: when
    the specimen has a gauge length; half-space models: always, the relative rotation of remote
    points); a cycle gains its ``energy``.  The result has a ``units`` object for the keys it
    converted and the normalised record under ``normalized``.
    """
    contact = specimen.contact if contact is None else contact
    parts = [r for r in (record if isinstance(record, (list, tuple)) else [record]) if r is not None]
    twist = None
    if specimen.gauge_length is not None or not contact.shaft:
        def twist(torque, rotation):
            return float(specimen.twist(torque, rotation, contact))
    scales = specimen.scales()
    units: dict = {}
    out: dict = {}
    normalized: dict = {}
    for part in parts:
        out.update(part.si_dict(scales, units, twist))
        normalized.update(part.as_dict())
    out["units"] = units
    out["normalized"] = normalized
    return out


@dataclass(frozen=True)
class PhysicalSignal:
    """A sampled torque signal analysed by the memory rules, in SI units (``normalized``: ``SignalHistory``)."""

    specimen: Specimen
    normalized: object = field(repr=False)
    torque_star: np.ndarray = field(repr=False, default=None)
    contact: object = field(default=None, repr=False)

    def __post_init__(self):
        if self.contact is None:
            object.__setattr__(self, "contact", self.specimen.contact)

    @property
    def dissipated_energy(self) -> float:
        """Total work against friction (J)."""
        return self.normalized.total_dissipated_energy * self.specimen.energy_scale

    def cycles(self) -> list[dict]:
        """Every closed cycle (and half cycle) in order: ``range``, ``mean`` (N m), ``count``, ``energy`` (J)."""
        s, h = self.specimen, self.normalized
        return [{"range": float(a) * s.torque_scale, "mean": float(m) * s.torque_scale, "count": float(c),
                 "energy": float(w) * s.energy_scale}
                for a, m, c, w in zip(h.cycle_range, h.cycle_mean, h.cycle_count, h.cycle_energy, strict=True)]

    def sample_values(self) -> dict:
        """Per sample: ``rigid_rotation`` (rad), ``dissipated_energy`` (J) and, with a gauge length, ``twist`` (rad)."""
        omega, energy = self.normalized.sample_values()
        s = self.specimen
        out = {"rigid_rotation": omega * s.rotation_scale, "dissipated_energy": energy * s.energy_scale}
        if s.gauge_length is not None or not self.contact.shaft:
            out["twist"] = s.twist(self.torque_star, omega, self.contact)
        return out
