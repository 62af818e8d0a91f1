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

from . import units
from .criteria import GROSS_SLIP_TORQUE, SLIP_ONSET_TORQUE

__all__ = ["Specimen", "PhysicalState", "PhysicalSignal", "SI_UNITS"]

#: Unit of every physical key of a state or a history record.
SI_UNITS = {
    "torque": "N m",
    "stick_radius": "m",
    "slip_fronts": "m",
    "turning_points": "N m",
    "rigid_rotation": "rad",
    "twist": "rad",
    "dissipated_energy": "J",
    "energy": "J",
    "range": "N m",
    "mean": "N m",
    "range_bin": "N m",
    "mean_bin": "N m",
    "bin_width": "N m",
    "gate": "N m",
    "loop_energy": "J",
    "radii": "m",
    "traction": "Pa",
    "slip": "m",
    "residual_traction": "Pa",
}


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
        measured ``twist``, symmetric about the interface; >= 0.  Without it, states have
        no ``twist``.

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

    def __post_init__(self):
        set_ = object.__setattr__
        set_(self, "radius", units.positive_si("radius", self.radius, "length"))
        set_(self, "normal_force", units.positive_si("normal_force", self.normal_force, "force"))
        set_(self, "friction", units.positive_si("friction", self.friction, "dimensionless"))
        set_(self, "shear_modulus", units.positive_si("shear_modulus", self.shear_modulus, "pressure"))
        if self.gauge_length is not None:
            set_(self, "gauge_length", units.positive_si("gauge_length", self.gauge_length, "length", allow_zero=True))

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
        """Torque at which slip starts, T* = 1 (N m)."""
        return SLIP_ONSET_TORQUE * self.torque_scale

    @property
    def gross_slip_torque(self) -> float:
        """Torque at which the cylinders spin, T* = 4/3: 2 f F a / 3 (N m)."""
        return GROSS_SLIP_TORQUE * self.torque_scale

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
        """The factors from normalised to SI units, by quantity (JSON-ready)."""
        return {"torque": self.torque_scale, "length": self.radius, "stress": self.stress_scale,
                "displacement": self.displacement_scale, "rotation": self.rotation_scale,
                "energy": self.energy_scale, "pressure": self.pressure}

    def as_dict(self) -> dict:
        return {"radius": self.radius, "normal_force": self.normal_force, "friction": self.friction,
                "shear_modulus": self.shear_modulus, "gauge_length": self.gauge_length}

    # ---------------------------------------------------------------- conversions
    def normalized_torque(self, torque, name: str = "torque"):
        """T* = 2 T / (f F a) of a torque in N m (float, quantity, string or array of them)."""
        if isinstance(torque, str) or np.ndim(torque) == 0:
            return units.si_value(name, torque, "torque") / self.torque_scale
        return units.si_array(name, torque, "torque") / self.torque_scale

    def _checked_torque(self, name: str, torque) -> float:
        t = self.normalized_torque(torque, name)
        if not math.isfinite(t):
            raise ValueError(f"{name} must be a finite torque (N m), got {torque!r}")
        if abs(t) > GROSS_SLIP_TORQUE * (1 + 4 * np.finfo(float).eps):
            raise ValueError(
                f"{name} must lie in [-{self.gross_slip_torque:.6g}, {self.gross_slip_torque:.6g}] N m (|T*| <= 4/3, "
                f"T_gross = 2 f F a / 3), got {torque!r} (T* = {t:.6g}): beyond it the cylinders spin, there is no "
                "static solution")
        return max(-GROSS_SLIP_TORQUE, min(GROSS_SLIP_TORQUE, t))

    def twist(self, torque_star, rigid_rotation):
        """Twist (rad) over the gauge length: (f p0 / mu)(T* L / a + 2 omega) (module docstring)."""
        if self.gauge_length is None:
            raise ValueError("the twist needs the specimen's gauge_length (distance between the two cross-sections)")
        return self.rotation_scale * (np.asarray(torque_star) * self.gauge_length / self.radius
                                      + 2.0 * np.asarray(rigid_rotation))

    def shaft_compliance(self) -> float:
        """Twist per torque of the elastic shaft over the gauge length, L / (mu J), J = pi a^4 / 2 (rad / (N m))."""
        if self.gauge_length is None:
            raise ValueError("the shaft compliance needs the specimen's gauge_length")
        return self.gauge_length / (self.shear_modulus * 0.5 * math.pi * self.radius**4)

    # ---------------------------------------------------------------- solutions
    def solve(self, torque=None, *, stick_radius=None, method=None, n_terms=None, tolerance=None,
              model=None) -> PhysicalState:
        """The state for a torque (N m) or a stick radius (a length, 0 <= c <= radius): exactly one of the two.

        ``model``: "cylinder" (default) or "half-space" (``models``), as for ``solve``.

        Raises ValueError naming the argument: both or neither, a wrong dimension, |T| above
        the gross-slip torque 2 f F a / 3 (the cylinders spin), a stick radius outside [0, a].
        """
        from .dispatch import solve

        if (torque is None) == (stick_radius is None):
            raise ValueError("give exactly one of torque (N m) and stick_radius (a length in [0, radius])")
        if torque is not None:
            normalized = solve(torque=self._checked_torque("torque", torque), method=method, n_terms=n_terms,
                               tolerance=tolerance, model=model)
        else:
            c = units.si_value("stick_radius", stick_radius, "length")
            if not math.isfinite(c) or not 0.0 <= c <= self.radius:
                raise ValueError(f"stick_radius must lie in [0, {self.radius:g}] m (0 to the radius), got "
                                 f"{stick_radius!r}")
            normalized = solve(stick_radius=c / self.radius, method=method, n_terms=n_terms, tolerance=tolerance,
                               model=model)
        return PhysicalState(self, normalized)

    def history(self, torques, *, method=None, n_terms=None, model=None) -> tuple[PhysicalState, ...]:
        """States after each step of a torque history (N m) from the virgin interface (memory rules).

        Each state has ``dissipated_energy`` (J) besides the keys of ``solve``.
        """
        from .histories import history

        values = self._torque_list("torques", torques)
        return tuple(PhysicalState(self, s) for s in history(values, method=method, n_terms=n_terms, model=model))

    def signal(self, torques, *, method=None, n_terms=None, model=None) -> PhysicalSignal:
        """A long sampled torque signal (N m): turning points, closed cycles and energies (``histories.signal``)."""
        from .histories import analyse_signal

        values = np.asarray(self._torque_list("torques", torques))
        return PhysicalSignal(self, analyse_signal(values, method=method, n_terms=n_terms, model=model,
                                                               name="torques"), values)

    def _torque_list(self, name: str, torques) -> list[float]:
        values = units.si_array(name, torques, "torque") / self.torque_scale
        if values.size == 0:
            raise ValueError(f"{name} must contain at least one torque (N m)")
        return [self._checked_torque(f"{name}[{i}]", float(v) * self.torque_scale) for i, v in enumerate(values)]

    # ---------------------------------------------------------------- cyclic loading
    def regime(self, torque_amplitude, *, model=None) -> str:
        """Slip regime of a torque cycling between -T_a and T_a (after the first loading).

        Cylinders (default): "stick" (T_a <= f F a / 2: the interface shakes down to full
        stick), "partial-slip" (cyclic slip of an annulus) or "gross-slip" (T_a >= 2 f F a / 3:
        the cylinders spin).  ``model="half-space"``: an annulus slips at any T_a > 0.
        """
        from .models import CYLINDER, validated

        model = validated(model)
        t = abs(self.normalized_torque(torque_amplitude, "torque_amplitude"))
        if not math.isfinite(t):
            raise ValueError(f"torque_amplitude must be a finite torque (N m), got {torque_amplitude!r}")
        onset = SLIP_ONSET_TORQUE if model == CYLINDER else 0.0
        return "stick" if t <= onset else "gross-slip" if t >= GROSS_SLIP_TORQUE else "partial-slip"

    def energy_per_cycle(self, torque_amplitude, *, method=None, n_terms=None, model=None) -> float:
        """Energy (J) dissipated per cycle of a torque between -T_a and T_a: W(2 T*_a) (f p0)^2 a^3 / mu.

        Zero for T_a at or below the slip onset; W(A) = 4 W_mono(A/2) (``histories.memory``,
        rule 5).  Raises ValueError at or beyond the gross-slip torque (infinite: the
        cylinders spin).
        """
        from .histories.monotonic import monotonic_model

        t = self._checked_torque("torque_amplitude", torque_amplitude)
        if abs(t) >= GROSS_SLIP_TORQUE:
            raise ValueError(f"torque_amplitude must be below the gross-slip torque {self.gross_slip_torque:.6g} N m "
                             f"for a finite energy per cycle, got {torque_amplitude!r}")
        return float(4.0 * monotonic_model(model, method, n_terms).point(abs(t))[2]) * self.energy_scale


def _scaled(value, factor):
    if value is None:
        return None
    if isinstance(value, (list, tuple)):
        return [_scaled(v, factor) for v in value]
    return float(value) * factor


@dataclass(frozen=True)
class PhysicalState:
    """One interface state in SI units; ``normalized`` is the state of the solvers (``Solution`` or
    ``InterfaceState``).  Radii ``r``, ``z`` are lengths (m, quantities or strings), 0 <= r <= a."""

    specimen: Specimen
    normalized: object = field(repr=False)

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
        """omega f p0 / mu (rad): rotation of each cylinder far from the interface beyond the uniform twist."""
        return self.normalized.rigid_rotation * self.specimen.rotation_scale

    @property
    def twist(self) -> float:
        """Twist over the gauge length (rad) of the cylinders; ValueError without a gauge length, and for the
        half-space model (a half-space has no cross-sections: its ``rigid_rotation`` is the far-field rotation)."""
        if getattr(self.normalized, "model", "cylinder") != "cylinder":
            raise ValueError("twist is defined for model='cylinder' only (two half-spaces have no cross-sections at a "
                             "gauge length; use rigid_rotation, the far-field rotation of each body)")
        return float(self.specimen.twist(self.normalized.torque, self.normalized.rigid_rotation))

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
        """SI values (keys of ``SI_UNITS``), ``units``, and the normalised state under ``normalized``."""
        return physical_record(self.normalized.as_dict(), self.specimen)


def physical_record(record: dict, specimen: Specimen) -> dict:
    """A normalised JSON record (``as_dict`` of a state, a history summary) in SI units.

    Keys of ``SI_UNITS`` found at any depth are converted; a state with ``torque`` and
    ``rigid_rotation`` gains ``twist`` when the specimen has a gauge length; a record with
    ``dissipated_energy`` inside a list of cycles gains ``energy``.  The result has a
    ``units`` object for the keys it converted and the input under ``normalized``.
    """
    converted, seen = _convert(record, specimen, set())
    out = {**converted, "units": {k: SI_UNITS[k] for k in SI_UNITS if k in seen}}
    out["normalized"] = record
    return out


def _factor(key: str, specimen: Specimen) -> float:
    torque, energy = specimen.torque_scale, specimen.energy_scale
    return {"torque": torque, "turning_points": torque, "range": torque, "mean": torque, "range_bin": torque,
            "mean_bin": torque, "bin_width": torque, "gate": torque, "loop_energy": energy,
            "stick_radius": specimen.radius, "slip_fronts": specimen.radius, "radii": specimen.radius,
            "rigid_rotation": specimen.rotation_scale, "dissipated_energy": energy, "energy": energy,
            "traction": specimen.stress_scale, "residual_traction": specimen.stress_scale,
            "slip": specimen.displacement_scale}[key]


def _convert(value, specimen: Specimen, seen: set, in_cycles: bool = False):
    if isinstance(value, list):
        items = [_convert(v, specimen, seen, in_cycles)[0] for v in value]
        return items, seen
    if not isinstance(value, dict):
        return value, seen
    out = {}
    for key, item in value.items():
        counts = key in ("turning_points", "slip_fronts") and not isinstance(item, list)  # a summary's count
        if key in SI_UNITS and not counts and (item is None or isinstance(item, (int, float, list))) \
                and not isinstance(item, bool):
            try:
                out[key] = _scaled(item, _factor(key, specimen))
                seen.add(key)
            except (TypeError, ValueError):
                out[key] = item
        elif key == "regime" or not isinstance(item, (dict, list)):
            out[key] = item
        else:
            out[key] = _convert(item, specimen, seen, in_cycles or key == "cycles")[0]
    if in_cycles and "dissipated_energy" in out and "energy" not in out:
        out["energy"] = out["dissipated_energy"]
        seen.add("energy")
    if specimen.gauge_length is not None and "torque" in value and "rigid_rotation" in value and "twist" not in out \
            and value.get("model", "cylinder") == "cylinder":  # a half-space has no cross-sections
        torque, omega = value["torque"], value["rigid_rotation"]
        if isinstance(torque, (int, float)) and isinstance(omega, (int, float)) and not isinstance(torque, bool):
            out["twist"] = float(specimen.twist(torque, omega))
            seen.add("twist")
        elif isinstance(torque, (int, float)) and omega is None:  # spinning: unbounded
            out["twist"] = None
            seen.add("twist")
    return out, seen


@dataclass(frozen=True)
class PhysicalSignal:
    """A sampled torque signal analysed by the memory rules, in SI units (``normalized``: ``SignalHistory``)."""

    specimen: Specimen
    normalized: object = field(repr=False)
    torque_star: np.ndarray = field(repr=False, default=None)

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
        if s.gauge_length is not None:
            out["twist"] = s.twist(self.torque_star, omega)
        return out
