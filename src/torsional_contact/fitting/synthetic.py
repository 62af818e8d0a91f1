r"""Synthetic torsion tests from the exact solution: what a rig would record, with known f, G and C.

Units: torque N m, twist rad, lengths m, forces N, moduli Pa.

A rig records the torque T and the twist theta = C T + 2 (f p0 / mu) omega + theta_0 between
two cross-sections, where C lumps the elastic shaft over the gauge length and the rig's own
compliance (``fitting.loop_fit``), omega is the contact's rigid rotation (f p0 / mu) along the
history and theta_0 the arbitrary zero of the twist.  Two rigs:

* ``torque_controlled``: T = A sin(2 pi t) from the virgin state; omega at every sample from
  ``histories.analyse_signal`` (the torque-driven memory rules, independent of the
  twist-driven ones the fit uses).  A < 2 f F a / 3 (below gross slip).
* ``twist_controlled``: theta - theta_0 = A sin(2 pi t) from the virgin state; any amplitude,
  gross-slip plateaus included.  The torque on each branch solves C T + k omega_m = the twist
  increment by Brent's method on the curves of ``curves`` (one root per sample, to 1e-15),
  with the branches of symmetric cycling written out: the virgin curve to the first reversal,
  then T = T_r + d 2 F(|theta - theta_r| / 2) from each reversal (theta_r, T_r = +-T_1).

``noisy`` adds white Gaussian noise of given standard deviations to both channels.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..criteria import GROSS_SLIP_TORQUE
from ..curves import monotonic_curves

__all__ = ["Rig", "torque_controlled", "twist_controlled", "noisy"]


@dataclass(frozen=True)
class Rig:
    """Specimen and rig of a synthetic test (SI): radius a, normal force F, friction f, shear modulus G,
    compliance C (rad per N m) and the twist offset theta_0 (rad)."""

    radius: float
    normal_force: float
    friction: float
    shear_modulus: float
    compliance: float
    offset: float = 0.0

    @property
    def slip_torque(self) -> float:
        """T_s = f F a / 2 (N m): slip onset."""
        return 0.5 * self.friction * self.normal_force * self.radius

    @property
    def contact_twist(self) -> float:
        """k = 2 f p0 / G (rad): twist of the contact per unit omega."""
        return 2.0 * self.friction * self.normal_force / (math.pi * self.radius**2) / self.shear_modulus

    def skeleton_torque(self, twist: float) -> float:
        """T >= 0 on the virgin curve at twist increment ``twist`` >= 0: C T + k omega_m(T / T_s) = twist."""
        curves = monotonic_curves()
        ts, c, k = self.slip_torque, self.compliance, self.contact_twist
        if twist <= c * ts:  # stick
            return twist / c
        top = GROSS_SLIP_TORQUE - float(curves.torque_gap(2e-5))  # 4/3 - 4.5e-15: omega_m finite (5.08)

        def excess(t_star):
            return c * ts * t_star + k * curves.state(t_star)[1] - twist

        if excess(top) <= 0:  # spinning to 3e-15 relative: the plateau
            return GROSS_SLIP_TORQUE * ts
        return ts * brentq(excess, 1.0, top, xtol=1e-15, rtol=4 * np.finfo(float).eps)


def torque_controlled(rig: Rig, amplitude: float, cycles: float = 2.0, samples_per_cycle: int = 200):
    """(torque, twist) of T = amplitude sin(2 pi t), t from 0 to ``cycles``, noise-free (module docstring)."""
    from ..histories import analyse_signal

    if not 0 < amplitude < GROSS_SLIP_TORQUE * rig.slip_torque:
        raise ValueError(f"amplitude must lie in (0, {GROSS_SLIP_TORQUE * rig.slip_torque:g}) N m (below gross slip), "
                         f"got {amplitude!r}")
    n = int(round(cycles * samples_per_cycle))
    torque = amplitude * np.sin(2.0 * np.pi * np.arange(n + 1) / samples_per_cycle)
    omega, _ = analyse_signal(torque / rig.slip_torque).sample_values()
    return torque, rig.compliance * torque + rig.contact_twist * omega + rig.offset


def twist_controlled(rig: Rig, amplitude: float, cycles: float = 2.0, samples_per_cycle: int = 200):
    """(torque, twist) of theta - theta_0 = amplitude sin(2 pi t), t from 0 to ``cycles``, noise-free."""
    if not amplitude > 0:
        raise ValueError(f"amplitude must be > 0 (rad), got {amplitude!r}")
    n = int(round(cycles * samples_per_cycle))
    phase = np.arange(n + 1) / samples_per_cycle
    drive = amplitude * np.sin(2.0 * np.pi * phase)
    torque = np.empty_like(drive)
    quarter = phase <= 0.25
    torque[quarter] = [math.copysign(rig.skeleton_torque(abs(v)), v) for v in drive[quarter]]
    peak = rig.skeleton_torque(amplitude)
    for i in np.flatnonzero(~quarter):
        # the last reversal: at t = 1/4 + m/2, theta_r = +-amplitude, T_r = +-peak
        m = math.floor((phase[i] - 0.25) * 2.0)
        sign = 1.0 if m % 2 == 0 else -1.0  # + after a maximum (the branch goes down)
        theta_r, t_r = sign * amplitude, sign * peak
        torque[i] = t_r - sign * 2.0 * rig.skeleton_torque(abs(drive[i] - theta_r) / 2.0)
    return torque, drive + rig.offset


def noisy(torque, twist, torque_noise: float, twist_noise: float, rng):
    """The channels with white Gaussian noise of standard deviations ``torque_noise`` (N m), ``twist_noise`` (rad)."""
    torque = np.asarray(torque, dtype=float)
    twist = np.asarray(twist, dtype=float)
    return (torque + torque_noise * rng.standard_normal(torque.size),
            twist + twist_noise * rng.standard_normal(twist.size))
