r"""Sampled branches and closed hysteresis loops of the memory rules (``memory``).

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.  The
torque-twist loop of a range A closes after the first cycle (Masing); ``loop_work``
gives pi times its area, which ``energy`` checks against the frictional work.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from .. import validation
from ..backends import METHODS
from ..criteria import GROSS_SLIP_TORQUE
from ..curves import monotonic_curves
from ..curves.interpolant import ONSET_DELTA
from ..diagnostics import ResolutionWarning
from ..solution import solve_cylinder
from ..solvers.weak_form import resolution_limit
from .memory import (
    CYCLIC_SLIP_RANGE,
    InterfaceState,
    _branch,
    _closure,
    _compose,
    _limit,
    _pop,
    _sign,
    _start,
    advance,
    history,
)
from .monotonic import point, register

__all__ = ["sample_path", "Loop", "hysteresis_loop", "loop_work", "tangent_compliance", "relaxation_profiles"]


# --------------------------------------------------------------------------- dense paths
def _stick_radius_grid(b_start: float, b_end: float, n_points: int, b_max: float) -> np.ndarray:
    """Interior stick radii from b_start (exclusive) down to b_end (exclusive), resolved ones only."""
    upper = min(b_start, b_max)
    if upper <= b_end:
        return np.empty(0)
    return np.linspace(upper, b_end, n_points + 1)[:-1][1 if upper == b_start else 0 :]


def _increments(b_a: float, b_b: float, n_points: int, method: str, n_terms) -> list[float]:
    """Monotonic torques tau at the interior stick radii of a slipping stretch (see ``sample_path``)."""
    if not METHODS[method].truncated:
        curves = monotonic_curves()
        radii = _stick_radius_grid(b_a, b_b, n_points, 1.0 - ONSET_DELTA)  # annuli the solver resolves well
        return [float(t) for t in np.atleast_1d(curves.torque(radii))] if radii.size else []
    out = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)  # only resolved radii are requested
        for b in _stick_radius_grid(b_a, b_b, n_points, resolution_limit(n_terms)[1]):
            out.append(register(solve_cylinder(stick_radius=float(b), method=method, n_terms=n_terms)))
    return out


def sample_path(state: InterfaceState, torque, n_points: int = 40) -> tuple[InterfaceState, ...]:
    """States along the monotonic path from ``state`` to ``torque`` (start excluded, end included).

    Stick stretches are represented by their end points (there omega and slip are
    constant and the traction is linear in T*); slipping stretches by ``n_points``
    states equally spaced in the stick radius (no inversion: T*(b) from ``curves`` for the
    default method, solved for b for the weak forms, up to their resolved limit).  Closed
    loops met on the way are erased exactly as in ``advance``; every state carries the
    energy dissipated up to it.
    """
    t = validation.torque("torque", torque)
    _require_cylinder(state, "sample_path")
    if t == state.torque:
        return ()
    method, n_terms, source = state.method, state.n_terms, state.source
    d = _sign(t - state.torque)
    stack = _start(state, d)
    current, energy = state.torque, state.dissipated_energy
    out: list[InterfaceState] = []
    while True:
        origin, g = _branch(stack)
        closes = bool(stack) and d * (t - _limit(stack)) >= 0
        end = _limit(stack) if closes else t
        tau_a, tau_b = abs(current - origin) / g, min(abs(end - origin) / g, GROSS_SLIP_TORQUE)
        (b_a, _, work_a), (b_b, _, work_b) = point(tau_a, method, n_terms), point(tau_b, method, n_terms)
        taus = [1.0] if tau_a < 1.0 < tau_b else []  # a stick stretch ends at the slip onset
        taus += _increments(b_a, b_b, n_points, method, n_terms)
        for tau in taus:
            w = energy + g * (point(tau, method, n_terms)[2] - work_a)
            out.append(_compose(stack, d, tau, origin + d * g * tau, w, source))
        energy += g * (work_b - work_a)
        if not closes:
            out.append(_compose(stack, d, tau_b, t, energy, source))
            return tuple(out)
        out.append(_closure(stack, d, end, energy, source))
        if end == t:
            return tuple(out)
        _pop(stack)
        current = end


def _require_cylinder(state: InterfaceState, name: str) -> None:
    """The dense sampling and compliance here use the cylinders' curves: refuse other models clearly."""
    if state.model != "cylinder":
        raise ValueError(f"{name} is available for model='cylinder' only, got a state of model={state.model!r} "
                         "(half-space: sample the torques with history(); compliance: half_space.closed_form."
                         "compliance)")


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


def hysteresis_loop(t_min, t_max, *, n_points: int = 40, method=None, n_terms=None) -> Loop:
    """Steady loop T_max -> T_min -> T_max after the history 0 -> T_max -> T_min -> T_max.

    By Masing closure the loop is reached in the first cycle.  ``n_points`` states per
    slipping stretch (see ``sample_path``).
    """
    t_min = validation.torque("t_min", t_min)
    t_max = validation.torque("t_max", t_max)
    if not t_min < t_max:
        raise ValueError(f"t_min must be below t_max, got t_min={t_min!r}, t_max={t_max!r}")
    start = history([t_max, t_min, t_max], method=method, n_terms=n_terms)[-1]
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


def loop_work(torque, rigid_rotation) -> float:
    """W = pi oint T* d omega by the trapezoidal rule along the path ((f p0)^2 a^3 / mu).

    For a closed path this is the enclosed area in the (omega, T*) plane times pi (see
    the module docstring for the factor).
    """
    torque = np.asarray(torque, dtype=float)
    omega = np.asarray(rigid_rotation, dtype=float)
    return float(math.pi * np.sum(0.5 * (torque[1:] + torque[:-1]) * np.diff(omega)))


def tangent_compliance(state: InterfaceState, *, step: float = 1e-4) -> float:
    """d omega / d T* (f p0 / mu per unit T*) along the current branch at ``state``.

    On a branch omega = omega_k + 2 d omega_m(tau), T* = T_k + 2 d tau, so the slope is
    omega_m'(tau) on every branch and on the virgin curve (zero while the branch
    sticks): omega'(b) / T*'(b), from the derivatives of the interpolants of ``curves``
    for the default method (the small-slip form (pi^3/4)(T* - 1)^2 below their range),
    by central differences of width ``step`` in b for the weak forms.  At a loop-closure
    point (see ``InterfaceState.front``) it is the slope of the outer branch that
    continues beyond it.
    """
    _require_cylinder(state, "tangent_compliance")
    tau = state.terms[-1][1]
    b = point(tau, state.method, state.n_terms)[0]
    if b >= 1.0:
        return 0.0
    if b <= 0.0:
        return math.inf
    if not METHODS[state.method].truncated:
        curves = monotonic_curves()
        if b > curves.b_high:
            return math.pi**3 / 4.0 * (tau - 1.0) ** 2
        rotation, torque = curves.by_radius["rigid_rotation"], curves.by_radius["torque"]
        return float(rotation.derivative(b) / torque.derivative(b))
    h = min(step, b / 2, (1 - b) / 2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        lo = solve_cylinder(stick_radius=b - h, method=state.method, n_terms=state.n_terms)
        hi = solve_cylinder(stick_radius=b + h, method=state.method, n_terms=state.n_terms)
    return float((hi.rigid_rotation - lo.rigid_rotation) / (hi.torque - lo.torque))


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
    onset = t_max - CYCLIC_SLIP_RANGE
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


