r"""Sampled branches and closed hysteresis loops of the memory rules (``memory``).

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.  The
torque-twist loop of a range A closes after the first cycle (Masing); ``loop_work``
gives pi times its area, which ``energy`` checks against the frictional work.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from .. import models
from .memory import (
    InterfaceState,
    _closure,
    _compose,
    _memory,
    _origin_torque,
    _reversal,
    _stack,
    advance,
    history,
)

__all__ = ["sample_path", "Loop", "hysteresis_loop", "loop_work", "tangent_compliance", "relaxation_profiles"]


# --------------------------------------------------------------------------- dense paths
def sample_path(state: InterfaceState, torque, n_points: int = 40) -> tuple[InterfaceState, ...]:
    """States along the monotonic path from ``state`` to ``torque`` (start excluded, end included).

    Stick stretches are represented by their end points (there the slip does not change and
    the traction and omega are linear in T*); slipping stretches by ``n_points`` states
    equally spaced in the stick radius (no inversion: the model's monotonic T*(b),
    ``Monotonic.path_torques``).  Closed loops met on the way are erased exactly as in
    ``advance``; every state carries the energy dissipated up to it.
    """
    t = state.contact.checked_torque("torque", torque)
    if t == state.torque:
        return ()
    source = state.source
    onset, gross = state.contact.slip_onset_torque, state.contact.gross_slip_torque
    d = 1 if t > state.torque else -1
    stack = _stack(state)
    position, energy = state.torque, state.dissipated_energy
    out: list[InterfaceState] = []
    for origin, g, end, closure in stack.step(t, _reversal(state)):
        memory = _memory(origin)  # the stack the piece lies on
        origin_torque = _origin_torque(origin)
        tau_a, tau_b = abs(position - origin_torque) / g, min(abs(end - origin_torque) / g, gross)
        (b_a, _, work_a), (b_b, _, work_b) = source.point(tau_a), source.point(tau_b)
        taus = [onset] if tau_a < onset < tau_b else []  # a stick stretch ends at the slip onset
        taus += source.path_torques(b_a, b_b, n_points)
        for tau in taus:
            w = energy + g * (source.point(tau)[2] - work_a)
            out.append(_compose(memory, d, tau, origin_torque + d * g * tau, w, source))
        energy += g * (work_b - work_a)
        position = end
        if closure is None:
            out.append(_compose(memory, d, tau_b, t, energy, source))
        else:
            out.append(_closure(origin, closure, d, end, energy, source))
    return tuple(out)


# --------------------------------------------------------------------------- hysteresis
@dataclass(frozen=True)
class Loop:
    """One closed steady torque-twist loop, starting and ending at ``t_max``.

    Attributes
    ----------
    torque, rigid_rotation : ndarray
        T* and omega (f p0 / mu) along the loop (first and last points equal).
    states : tuple of InterfaceState
        The states behind the points.
    """

    t_min: float
    t_max: float
    torque: np.ndarray
    rigid_rotation: np.ndarray
    states: tuple[InterfaceState, ...] = field(repr=False)


def hysteresis_loop(t_min, t_max, *, n_points: int = 40, method=None, n_terms=None, model=None) -> Loop:
    """Steady loop T_max -> T_min -> T_max after the history 0 -> T_max -> T_min -> T_max.

    By Masing closure the loop is reached in the first cycle.  ``n_points`` states per
    slipping stretch (see ``sample_path``); ``model`` as for ``history``.
    """
    contact = models.get(model)
    t_min = contact.checked_torque("t_min", t_min)
    t_max = contact.checked_torque("t_max", t_max)
    if not t_min < t_max:
        raise ValueError(f"t_min must be below t_max, got t_min={t_min!r}, t_max={t_max!r}")
    start = history([t_max, t_min, t_max], method=method, n_terms=n_terms, model=contact)[-1]
    down = sample_path(start, t_min, n_points)
    up = sample_path(down[-1], t_max, n_points)
    states = (start, *down, *up)
    return Loop(
        t_min,
        t_max,
        np.array([s.torque for s in states]),
        np.array([s.rigid_rotation for s in states]),
        states,
    )


def loop_work(torque, rigid_rotation, *, model=None) -> float:
    """W = (pi n / 2) oint T* d omega by the trapezoidal rule along the path ((f p0)^2 a^3 / mu).

    n is the model's number of elastic bodies (``ContactModel.elastic_bodies``: 2 for the
    cylinders, whose factor is pi): the relative rotation of the bodies is n omega (f p0 / mu) and
    the torque T = (pi a^3 f p0 / 2) T*, so oint T d(n omega) is this in (f p0)^2 a^3 / mu.  For a
    closed path this is the enclosed area in the (omega, T*) plane times pi n / 2.
    """
    factor = 0.5 * math.pi * models.get(model).elastic_bodies
    torque = np.asarray(torque, dtype=float)
    omega = np.asarray(rigid_rotation, dtype=float)
    return float(factor * np.sum(0.5 * (torque[1:] + torque[:-1]) * np.diff(omega)))


def tangent_compliance(state: InterfaceState, *, step: float = 1e-4) -> float:
    """d omega / d T* (f p0 / mu per unit T*) along the current branch at ``state``.

    On a branch omega = omega_k + 2 d omega_m(tau), T* = T_k + 2 d tau, so the slope is
    omega_m'(tau) on every branch and on the virgin curve: the model's ``Monotonic.rotation_slope``
    (for the cylinders zero while the branch sticks; ``step`` is the width of the central
    differences in b of the weak forms).  At a loop-closure point (see ``InterfaceState.front``)
    it is the slope of the outer branch that continues beyond it.
    """
    return state.source.rotation_slope(state.terms[-1][1], step=step)


# --------------------------------------------------------------------------- Fig. 5
def relaxation_profiles(
    t_max: float = 1.23,
    stages: Sequence[float] = (1.23, 0.9, 0.5, 0.0, -0.5, -0.77, -0.9),
    radii=None,
    *,
    method=None,
    n_terms=None,
) -> dict:
    """Fig. 5 in data: load to ``t_max``, relax through ``stages``; traction profiles.

    Returns
    -------
    dict with ``radii``, ``torque`` (stages), ``traction`` (rows per stage),
    ``stick_radius`` and ``regime`` per stage, ``residual_traction`` (at T* = 0),
    ``loading_stick_radius`` b(t_max), ``reverse_slip_onset`` = t_max - 2 (memory rule
    2) and ``min_traction_at_onset``, the least traction at that torque (-1 exactly
    when reverse slip is incipient, at r = 1).
    """
    radii = np.linspace(0.0, 1.0, 201) if radii is None else np.asarray(radii, dtype=float)
    loaded = history([t_max], method=method, n_terms=n_terms)[-1]
    states = history(list(stages), method=method, n_terms=n_terms, start=loaded)
    onset = t_max - loaded.contact.reversal_slip_range
    at_onset = advance(loaded, onset)
    return {
        "t_max": t_max,
        "loading_stick_radius": loaded.stick_radius,
        "radii": radii,
        "torque": np.array([s.torque for s in states]),
        "stick_radius": np.array([s.stick_radius for s in states]),
        "regime": [s.regime for s in states],
        "traction": np.array([s.traction(radii) for s in states]),
        "residual_traction": loaded.residual_traction(radii),
        "reverse_slip_onset": onset,
        "min_traction_at_onset": float(np.min(at_onset.traction(radii))),
    }


