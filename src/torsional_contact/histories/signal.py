r"""Long sampled torque signals: turning points, memory-rule states, closed loops, energy per sample.

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.

``analyse_signal`` applies exactly the rules of ``histories.memory`` (same numbers as
``history`` of the same torques) but keeps the stack as plain lists and returns arrays,
so that a record of 10^6 samples with 10^4 reversals is analysed in a fraction of a
second:

1. the signal is reduced to its turning points (first sample, reversals, last sample;
   repeated samples merged, the index of a turning point is the first sample that
   reaches it);
2. one pass over the turning points runs the stack of rule 4 on the torques alone and
   records, for every state, the branch it lies on (origin state, factor g = 1 on the
   virgin curve or 2 on a branch, direction, increment tau), the remembered turning
   points, the closed loops and the stretches ("pieces") of branches crossed on the way;
3. b(tau), omega_m(tau) and W_mono(tau) are evaluated once for all of them (vectorised);
4. omega = omega(origin) + d g omega_m(tau) and the energy (rule 5: g [W_mono(tau_b) -
   W_mono(tau_a)] per piece, summed along the path) follow by short recurrences.

A closed loop is an inner loop T_(k-1) -> T_k -> T_(k-1) erased by the stack (k >= 2: both
ends real turning points); it dissipates W(|T_k - T_(k-1)|) = 4 W_mono(range / 2).  A
branch from the first remembered point T_1 that reaches its mirror image -T_1 joins the
mirrored virgin curve (rule 4): half a loop of range 2 |T_1| (count 1/2), which
dissipates 2 W_mono(|T_1|) = W(2 |T_1|) / 2 (a torque cycling between -T and T is a
sequence of such halves).  This is rainflow counting in which the first loading plays
the part of the skeleton curve; ``tests/test_history_signal.py`` compares it with the
``rainflow`` package (ASTM E1049-85): every full cycle of the package is a closed loop
here; the package counts the loops that involve the oldest remembered point as two
halves.

``sample_values`` gives omega and the cumulative dissipated energy at every sample: each
sample lies on one piece, whose origin, factor and energy offset are known.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import validation
from ..criteria import GROSS_SLIP_TORQUE
from ..models import DEFAULT_MODEL, monotonic_model

__all__ = ["validated_signal", "turning_point_indices", "SignalHistory", "analyse_signal"]


def validated_signal(name: str, signal) -> np.ndarray:
    """``signal`` as a 1-d float array of finite torques in [-4/3, 4/3] (rounding beyond 4/3 clipped).

    Raises
    ------
    ValueError
        Naming ``name[i]`` of the first bad sample (not a real number, not finite, or
        |T*| > 4/3), or for an empty signal.
    """
    if isinstance(signal, (str, bytes)):
        raise ValueError(f"{name} must be a sequence of torques in [-4/3, 4/3], got {signal!r}")
    try:
        values = np.asarray(signal)
    except (TypeError, ValueError):  # ragged input: the element-wise check names the culprit
        values = np.asarray(validation.torque_sequence(name, signal), dtype=float)
    if values.dtype.kind not in "fiu":
        values = np.asarray(validation.torque_sequence(name, signal), dtype=float)
    values = values.astype(float, copy=False).ravel()
    if values.size == 0:
        raise ValueError(f"{name} must contain at least one torque in [-4/3, 4/3]")
    limit = GROSS_SLIP_TORQUE * (1.0 + validation.TORQUE_TOLERANCE)
    bad = ~(np.abs(values) <= limit)  # nan compares False
    if bad.any():
        i = int(np.argmax(bad))
        validation.torque(f"{name}[{i}]", values[i].item())  # raises the canonical message
    return np.clip(values, -GROSS_SLIP_TORQUE, GROSS_SLIP_TORQUE)


def turning_point_indices(values: np.ndarray) -> np.ndarray:
    """Sample indices of the turning points: the first sample, every reversal, the last value reached.

    Runs of equal samples count once, at their first sample.
    """
    values = np.asarray(values, dtype=float)
    starts = np.concatenate([[0], np.flatnonzero(np.diff(values) != 0) + 1])
    if starts.size <= 2:
        return starts
    step = np.sign(np.diff(values[starts]))
    reversals = np.flatnonzero(step[1:] != step[:-1]) + 1
    return starts[np.concatenate([[0], reversals, [starts.size - 1]])]


@dataclass(frozen=True)
class SignalHistory:
    """Memory-rule states at the turning points of a sampled signal (arrays; ``analyse_signal``).

    Attributes
    ----------
    samples : int
        Number of samples of the signal.
    index, torque, stick_radius, rigid_rotation, dissipated_energy, direction : ndarray
        Per turning point (state): its first sample, T*, b of the current branch (units a),
        omega (f p0 / mu), work against friction since the virgin state ((f p0)^2 a^3 / mu),
        +1 / -1 (0 never: the first state is reached from the virgin one).
    front : ndarray
        Slip front remembered if the torque reverses at the state (``InterfaceState.front``).
    memory : tuple of tuple of int
        Per state, the remembered turning points as state numbers, oldest first.
    cycle_range, cycle_mean, cycle_state, cycle_count : ndarray
        The closed loops (count 1) and half loops (count 1/2: a branch from the first
        remembered point T_1 reaching -T_1, range 2 |T_1|, mean 0): range and mean torque,
        the state at which each closed, and the count.
    cycle_energy : ndarray
        count * W(range): the energy each dissipated.
    method, n_terms :
        The monotonic solutions used.
    model : str
        The contact model (``models``).
    """

    samples: int
    index: np.ndarray
    torque: np.ndarray
    stick_radius: np.ndarray
    rigid_rotation: np.ndarray
    dissipated_energy: np.ndarray
    direction: np.ndarray
    front: np.ndarray
    memory: tuple
    cycle_range: np.ndarray
    cycle_mean: np.ndarray
    cycle_state: np.ndarray
    cycle_count: np.ndarray
    cycle_energy: np.ndarray
    method: str
    n_terms: int | None
    _pieces: dict = field(repr=False)
    _signal: np.ndarray = field(repr=False)
    model: str = DEFAULT_MODEL

    @property
    def regime(self) -> list[str]:
        """Per state: "stick", "partial-slip" or "gross-slip" (of the current branch)."""
        return ["stick" if b >= 1.0 else "gross-slip" if b <= 0.0 else "partial-slip" for b in self.stick_radius]

    @property
    def total_dissipated_energy(self) -> float:
        return float(self.dissipated_energy[-1])

    def slip_fronts(self, k: int) -> list[float]:
        """Slip fronts (< 1) remembered at state k, oldest first."""
        return [float(self.front[j]) for j in self.memory[k] if self.front[j] < 1.0]

    def states(self) -> list[dict]:
        """One JSON-ready record per state (non-finite numbers -> None)."""
        regime = self.regime
        return [
            {
                "index": int(self.index[k]),
                "torque": float(self.torque[k]),
                "stick_radius": float(self.stick_radius[k]),
                "slip_fronts": self.slip_fronts(k),
                "turning_points": [float(self.torque[j]) for j in self.memory[k]],
                "rigid_rotation": _finite(self.rigid_rotation[k]),
                "regime": regime[k],
                "dissipated_energy": _finite(self.dissipated_energy[k]),
                "direction": int(self.direction[k]),
            }
            for k in range(self.index.size)
        ]

    def cycles(self) -> list[dict]:
        """Loops grouped by (range, mean): ``range``, ``mean``, ``count`` (halves count 1/2), ``dissipated_energy``."""
        groups: dict[tuple[float, float], list] = {}
        for a, m, c, w in zip(self.cycle_range.tolist(), self.cycle_mean.tolist(), self.cycle_count.tolist(),
                              self.cycle_energy.tolist(), strict=True):
            entry = groups.setdefault((a, m), [0.0, 0.0])
            entry[0] += c
            entry[1] += w
        return [{"range": a, "mean": m, "count": n, "dissipated_energy": _finite(w)}
                for (a, m), (n, w) in groups.items()]

    def sample_values(self) -> tuple[np.ndarray, np.ndarray]:
        """(omega, cumulative dissipated energy) at every sample of the signal."""
        p = self._pieces
        which = p["of_sample"]
        origin_omega = np.where(p["origin"] >= 0, self.rigid_rotation[np.maximum(p["origin"], 0)], 0.0)
        g, d = p["g"][which], p["d"][which]
        tau = np.minimum(np.abs(self._signal - p["origin_torque"][which]) / g, GROSS_SLIP_TORQUE)
        _, omega_m, work = monotonic_model(self.model, self.method, self.n_terms).points(tau)
        omega = origin_omega[which] + d * g * omega_m
        with np.errstate(invalid="ignore"):  # inf - inf after spinning: the energy stays inf
            energy = p["energy_before"][which] + g * (work - p["work_start"][which])
        energy = np.where(np.isnan(energy) & np.isinf(p["energy_before"][which]), np.inf, energy)
        return omega, energy


def _finite(value):
    value = float(value)
    return value if math.isfinite(value) else None


def analyse_signal(signal, *, method=None, n_terms=None, model=None, name: str = "signal") -> SignalHistory:
    """States at the turning points of ``signal``, closed loops and energies (module docstring).

    Parameters
    ----------
    signal : array_like
        T* samples in [-4/3, 4/3], the history starting from the virgin interface.
    method, n_terms, model :
        As for ``history`` (default: the cylinders, the Abel-Fredholm method through ``curves``).
    name : str
        Name of the signal in error messages.

    Returns
    -------
    SignalHistory
        With the same states as ``history(signal)`` at the turning points.

    Raises
    ------
    ValueError
        Naming ``name[i]`` for a bad sample; for an empty signal or a bad method.
    """
    source = monotonic_model(model, method, n_terms)
    method, n_terms, points = source.method, source.n_terms, source.points
    values = validated_signal(name, signal)
    index = turning_point_indices(values)
    walk = _walk(values[index].tolist())
    taus = np.array(walk["tau"] + walk["stick_tau"] + walk["tau_a"] + walk["tau_b"])
    b, omega_m, work = points(taus)
    n, m = len(walk["tau"]), len(walk["tau_a"])
    stick_b = b[n : 2 * n]
    omega_m_state, b_state = omega_m[:n], b[:n]
    work_a, work_b = work[2 * n : 2 * n + m], work[2 * n + m :]

    rotation, front = np.empty(n), np.empty(n)
    for k in range(n):
        e = walk["same_as"][k]
        if e >= 0:  # exact closure: the earlier state itself
            rotation[k], front[k] = rotation[e], front[e]
            continue
        o = walk["origin"][k]
        rotation[k] = (rotation[o] if o >= 0 else 0.0) + walk["d"][k] * walk["g"][k] * omega_m_state[k]
        front[k] = b_state[k]
    g_piece = np.array(walk["piece_g"])
    with np.errstate(invalid="ignore"):
        piece_work = g_piece * (work_b - work_a)
    piece_work = np.where(np.isnan(piece_work), np.inf, piece_work)
    energy = np.cumsum(np.bincount(np.array(walk["piece_state"], dtype=int), weights=piece_work, minlength=n))
    energy_before = np.concatenate([[0.0], np.cumsum(piece_work)[:-1]])

    pieces = {
        "origin": np.array(walk["piece_origin"], dtype=int),
        "origin_torque": np.array(walk["piece_origin_torque"]),
        "g": g_piece,
        "d": np.array(walk["piece_d"], dtype=float),
        "energy_before": energy_before,
        "work_start": work_a,
        "of_sample": _piece_of_sample(values, index, walk),
    }
    ranges = np.array(walk["cycle_range"], dtype=float)
    counts = np.array(walk["cycle_count"], dtype=float)
    return SignalHistory(
        samples=int(values.size),
        index=index,
        torque=values[index],
        stick_radius=stick_b,
        rigid_rotation=rotation,
        dissipated_energy=energy,
        direction=np.array(walk["d"], dtype=int),
        front=front,
        memory=tuple(walk["memory"]),
        cycle_range=ranges,
        cycle_mean=np.array(walk["cycle_mean"], dtype=float),
        cycle_state=np.array(walk["cycle_state"], dtype=int),
        cycle_count=counts,
        cycle_energy=counts * 4.0 * points(0.5 * ranges)[2] if ranges.size else np.zeros(0),
        method=method,
        n_terms=n_terms,
        _pieces=pieces,
        _signal=values,
        model=source.model,
    )


def _walk(torques: list[float]) -> dict:
    """Rule 4 on the torques alone: branch, memory, loops and pieces of every state (module docstring)."""
    out = {key: [] for key in ("tau", "stick_tau", "origin", "g", "d", "same_as", "memory", "tau_a", "tau_b",
                               "piece_g", "piece_state", "piece_origin", "piece_origin_torque", "piece_d",
                               "piece_end", "cycle_range", "cycle_mean", "cycle_state", "cycle_count")}
    stack: list[int] = []  # state numbers of the remembered turning points
    current, direction = 0.0, 0
    for k, t in enumerate(torques):
        d = 1 if t > current else -1 if t < current else 0  # 0: the first sample is the virgin torque 0
        if direction != 0 and d != direction:
            stack.append(k - 1)
        same_as = -1
        while True:
            origin = stack[-1] if stack else -1
            origin_torque, g = (torques[origin], 2.0) if stack else (0.0, 1.0)
            limit = (torques[stack[-2]] if len(stack) >= 2 else -torques[stack[-1]]) if stack else None
            closes = limit is not None and d * (t - limit) >= 0
            end = limit if closes else t
            out["tau_a"].append(abs(current - origin_torque) / g)
            out["tau_b"].append(min(abs(end - origin_torque) / g, GROSS_SLIP_TORQUE))
            for key, value in (("piece_g", g), ("piece_state", k), ("piece_origin", origin),
                               ("piece_origin_torque", origin_torque), ("piece_d", d), ("piece_end", end)):
                out[key].append(value)
            if not closes:
                out["tau"].append(min(abs(t - origin_torque) / g, GROSS_SLIP_TORQUE))
                out["stick_tau"].append(out["tau"][-1])
                out["origin"].append(origin)
                out["g"].append(g)
                break
            closing_tau = abs(end - origin_torque) / 2.0
            if len(stack) >= 2:
                out["cycle_range"].append(abs(torques[stack[-1]] - torques[stack[-2]]))
                out["cycle_mean"].append(0.5 * (torques[stack[-1]] + torques[stack[-2]]))
                out["cycle_state"].append(k)
                out["cycle_count"].append(1.0)
                earlier = stack[-2]
                del stack[-2:]
            else:  # the branch from T_1 reaches -T_1: half a loop of range 2 |T_1| (rule 4)
                out["cycle_range"].append(2.0 * abs(torques[stack[-1]]))
                out["cycle_mean"].append(0.0)
                out["cycle_state"].append(k)
                out["cycle_count"].append(0.5)
                earlier = -1
                stack.pop()
            if end == t:  # exact closure: the earlier state (or the mirrored virgin curve)
                out["stick_tau"].append(closing_tau)
                if earlier >= 0:
                    same_as = earlier
                    out["tau"].append(0.0)
                    out["origin"].append(-1)
                    out["g"].append(1.0)
                else:
                    out["tau"].append(abs(t))
                    out["origin"].append(-1)
                    out["g"].append(1.0)
                break
            current = end
        out["d"].append(d)
        out["same_as"].append(same_as)
        out["memory"].append(tuple(stack))
        current, direction = t, d
    return out


def _piece_of_sample(values: np.ndarray, index: np.ndarray, walk: dict) -> np.ndarray:
    """The piece each sample lies on (samples of a step between two turning points, split at loop closures)."""
    piece_state = np.array(walk["piece_state"], dtype=int)
    first_piece = np.searchsorted(piece_state, np.arange(index.size))
    count = np.diff(np.append(first_piece, piece_state.size))
    step_start = np.concatenate([[0], index[:-1] + 1])
    step_end = index + 1
    out = np.repeat(first_piece, step_end - step_start)
    ends, ds = walk["piece_end"], walk["piece_d"]
    for k in np.flatnonzero(count > 1):
        lo, hi = int(step_start[k]), int(step_end[k])
        oriented = ds[first_piece[k]] * values[lo:hi]
        for j in range(first_piece[k], first_piece[k] + count[k] - 1):  # samples past each closure
            out[lo + np.searchsorted(oriented, ds[j] * ends[j], side="right") :hi] = j + 1
    return out
