"""Records of a torsion rig for the fit's tests, made independently of the fitting code.

The contact's rotation comes from the model's monotonic solution (``ContactModel.monotonic().points``, the
curves or the closed forms, not the fit's inverted skeleton) and the history from a Masing composition written
out here for symmetric cycling (the virgin curve to the first reversal, then each branch from the last reversal
with the factor 2): omega = omega_r + d 2 omega_m(|T* - T*_r| / 2).  A twist-controlled record inverts each
branch by bisection.  The rig: twist = C_rig T + (f p-bar / G)(elastic_bodies omega + T* L / a for shafts).
Units SI: torque N m, twist rad, time s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from torsional_contact import models


@dataclass(frozen=True)
class Rig:
    """A rig and its specimen (SI), with the defects of its record."""

    radius: float = 0.005
    normal_force: float = 1000.0
    friction: float = 0.6
    shear_modulus: float = 80e9
    gauge_length: float = 0.02
    rig_compliance: float = 2e-4
    offset: float = 1e-4
    model: str | object = "cylinder"
    frequency: float = 1.0
    # defects
    lag: float = 0.0            # s: the twist is sampled this long after the torque
    drift: float = 0.0          # rad/s
    torque_offset: float = 0.0  # N m
    spikes: tuple = field(default_factory=tuple)  # (index, size in rad) of twist spikes
    start_phase: float = 0.0    # cycles skipped at the start (0.5: the first half-cycle missing)
    twist_sign: float = 1.0

    @property
    def contact(self):
        return models.get(self.model)

    @property
    def slip_torque(self) -> float:
        return 0.5 * self.friction * self.normal_force * self.radius

    @property
    def unit_twist(self) -> float:
        """f p-bar / G (rad)."""
        return self.friction * self.normal_force / (math.pi * self.radius**2) / self.shear_modulus

    @property
    def shaft_compliance(self) -> float:
        """L / (G J) of the two shafts over the gauge length (0 for bodies that are not shafts)."""
        if not self.contact.shaft:
            return 0.0
        return self.gauge_length / (self.shear_modulus * 0.5 * math.pi * self.radius**4)

    @property
    def compliance(self) -> float:
        return self.rig_compliance + self.shaft_compliance

    def with_(self, **changes) -> Rig:
        return replace(self, **changes)


def _omega_m(rig: Rig, tau):
    tau = np.clip(np.asarray(tau, dtype=float), 0.0, rig.contact.gross_slip_torque)
    return rig.contact.monotonic().points(tau)[1]


def _branch_twist(rig: Rig, x):
    """Twist increment (rad) of the virgin curve to T* = x >= 0 (the rig's linear part and the contact's)."""
    return rig.compliance * rig.slip_torque * x + rig.unit_twist * rig.contact.elastic_bodies * _omega_m(rig, x)


def _torque_star(phase, amplitude):
    return amplitude * np.sin(2.0 * np.pi * phase)


def _history_twist(rig: Rig, phase, amplitude: float):
    """Twist (rad, without offsets) at the phases (cycles, >= 0) of T* = amplitude sin(2 pi phase)."""
    phase = np.asarray(phase, dtype=float)
    t_star = _torque_star(phase, amplitude)
    out = np.empty_like(t_star)
    virgin = phase <= 0.25
    out[virgin] = np.sign(t_star[virgin]) * _branch_twist(rig, np.abs(t_star[virgin]))
    later = ~virgin
    m = np.floor((phase[later] - 0.25) * 2.0)
    sign = np.where(m % 2 == 0, 1.0, -1.0)  # + after a maximum: the branch goes down
    peak = _branch_twist(rig, amplitude)
    out[later] = sign * peak - sign * 2.0 * _branch_twist(rig, np.abs(t_star[later] - sign * amplitude) / 2.0)
    return out


def torque_controlled(rig: Rig, amplitude: float, cycles: float = 2.0, samples_per_cycle: int = 200,
                      torque_noise: float = 0.0, twist_noise: float = 0.0, seed: int = 0):
    """(time, torque, twist) of T* = amplitude sin(2 pi f t) with noise and the rig's defects."""
    rng = np.random.default_rng(seed)
    n = int(round(cycles * samples_per_cycle))
    phase = rig.start_phase + np.arange(n + 1) / samples_per_cycle
    time = phase / rig.frequency
    torque = _torque_star(phase, amplitude) * rig.slip_torque
    lagged = np.maximum(phase - rig.lag * rig.frequency, 0.0)
    twist = _history_twist(rig, lagged, amplitude) + rig.offset + rig.drift * time
    return _measured(rig, time, torque, twist, torque_noise, twist_noise, rng)


def twist_controlled(rig: Rig, amplitude: float, cycles: float = 2.0, samples_per_cycle: int = 200,
                     torque_noise: float = 0.0, twist_noise: float = 0.0, seed: int = 0):
    """(time, torque, twist) of theta - theta_0 = amplitude sin(2 pi f t) (rad): each branch inverted by bisection."""
    rng = np.random.default_rng(seed)
    n = int(round(cycles * samples_per_cycle))
    phase = rig.start_phase + np.arange(n + 1) / samples_per_cycle
    time = phase / rig.frequency
    drive = amplitude * np.sin(2.0 * np.pi * phase)
    gross = rig.contact.gross_slip_torque

    def invert(increment):  # T* >= 0 with _branch_twist(T*) = increment >= 0
        lo, hi = np.zeros_like(increment), np.full_like(increment, gross)
        for _ in range(70):
            mid = 0.5 * (lo + hi)
            above = _branch_twist(rig, mid) > increment
            hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
        return 0.5 * (lo + hi)

    t_star = np.empty_like(drive)
    virgin = phase <= 0.25
    t_star[virgin] = np.sign(drive[virgin]) * invert(np.abs(drive[virgin]))
    peak = float(invert(np.array([amplitude]))[0])
    later = ~virgin
    m = np.floor((phase[later] - 0.25) * 2.0)
    sign = np.where(m % 2 == 0, 1.0, -1.0)
    t_star[later] = sign * peak - sign * 2.0 * invert(np.abs(drive[later] - sign * amplitude) / 2.0)
    torque = t_star * rig.slip_torque
    twist = drive + rig.offset + rig.drift * time
    return _measured(rig, time, torque, twist, torque_noise, twist_noise, rng)


def _measured(rig, time, torque, twist, torque_noise, twist_noise, rng):
    torque = torque + rig.torque_offset + torque_noise * rng.standard_normal(torque.size)
    twist = twist + twist_noise * rng.standard_normal(twist.size)
    for index, size in rig.spikes:
        twist[index] += size
    return time, torque, rig.twist_sign * twist
