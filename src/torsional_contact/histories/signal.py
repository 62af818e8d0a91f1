r"""Long sampled torque signals: turning points, memory-rule states, closed loops, energy per sample.

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.

``analyse_signal`` applies exactly the rules of ``histories.memory`` (same numbers as
``history`` of the same torques) on arrays, so that a record of 10^6 samples with
2 x 10^5 reversals is analysed in well under a second:

1. the signal is reduced to its turning points (first sample, reversals, last sample;
   repeated samples merged, the index of a turning point is the first sample that
   reaches it);
2. one pass over the turning points (``stack_walk.walk``, plain Python on floats: the only loop)
   runs the stack of rule 4 on the torques alone and records the closed loops (which
   remembered points each erased) and, for every state, the newest remembered turning
   point after it; a remembered point also records the point remembered under it, so
   that the stack of every state is a chain through these pointers (O(1) per state,
   whatever the depth of the stack);
3. from these the stretches ("pieces") of branches crossed on the way are assembled
   with array operations: origin state, factor g = 1 on the virgin curve or 2 on a
   branch, direction, increments tau_a, tau_b;
4. b(tau), omega_m(tau) and W_mono(tau) are evaluated once for all of them (vectorised);
   omega = omega(origin) + d g omega_m(tau) (one short recurrence) and the energy
   (rule 5: g [W_mono(tau_b) - W_mono(tau_a)] per piece, summed along the path).

Closed loops and rainflow counting
----------------------------------
A closed loop is an inner loop T_(k-1) -> T_k -> T_(k-1) erased by the stack (k >= 2:
both ends real turning points); it dissipates W(|T_k - T_(k-1)|) = 4 W_mono(range / 2).
A branch from the first remembered point T_1 that reaches its mirror image -T_1 joins
the mirrored virgin curve (rule 4): half a loop of range 2 |T_1| (count 1/2), which
dissipates 2 W_mono(|T_1|) = W(2 |T_1|) / 2.  A torque cycling between -T and T is a
sequence of such halves, and two of them close the loop T -> -T -> T exactly, so the
number of loops is counted as rainflow counting counts cycles: full loops count 1,
halves 1/2 (``SignalHistory.closed_loops``; the ``rainflow`` package's ``count_cycles``
sums its half cycles in the same way).  The first loading from the virgin state and
the branches still open at the end (rainflow's "residue") are not loops.

This is rainflow counting (ASTM E1049-85, three-point rule, ties counted: a loop closes
when the torque *reaches* the earlier turning point) in which the first loading plays
the part of the skeleton curve.  Exactly: if the first turning point T_1 has the
largest |T*| of the signal, the loops here are ASTM's cycles of the sequence -T_1, T_1,
T_2, ... (full cycles are full loops, half cycles half loops), apart from ASTM's
final residue of len(memory[-1]) + 1 half cycles: the ASTM stack is then always
(-T_1, T_1, ..., T_k, current) for the memory stack (T_1, ..., T_k), ASTM's half cycle
of a three-point stack is the branch from T_1 reaching -T_1, its full cycle the branch
from T_k reaching T_(k-1).  ``tests/test_history_signal.py`` checks this against the
package, with ties.  When the amplitude grows later, the memory rules close the branch
from T_1 at -T_1 where ASTM closes it at its first sample; the loops then differ from
ASTM's only by loops that involve the oldest remembered point.

Hysteresis gate: ``histories.gate`` (``gate`` in ``analyse_signal``, ``--gate``).

``sample_values`` gives omega and the cumulative dissipated energy at every sample: each
sample lies on one piece, whose origin, factor and energy offset are known.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from .. import models, validation
from ..contact_models.base import ContactModel
from ..records import BinRecord, CycleRecord, SignalStateRecord
from . import stack_walk
from .gate import gated_signal
from .samples import turning_point_indices, validated_signal

__all__ = [
    "validated_signal",
    "turning_point_indices",
    "gated_signal",
    "RememberedPoints",
    "SignalHistory",
    "analyse_signal",
    "MIN_BIN_WIDTH",
]

#: Smallest bin width of ``SignalHistory.rainflow_bins`` (finer bins would hold one loop each).
MIN_BIN_WIDTH = 1e-6


class RememberedPoints(Sequence):
    """The remembered turning points of every state, oldest first, as tuples of state numbers.

    Stored as pointers (``top[k]``: the newest point remembered at state k, ``below[j]``:
    the point remembered under j), so that a long signal costs O(1) per state.
    """

    def __init__(self, top: np.ndarray, below: np.ndarray):
        self._top = top
        self._below = below

    def __len__(self) -> int:
        return int(self._top.size)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return [self[i] for i in range(*k.indices(len(self)))]
        j = int(self._top[k])
        chain = []
        while j >= 0:
            chain.append(j)
            j = int(self._below[j])
        return tuple(reversed(chain))


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
        +1 / -1 (0 only for a first sample at T* = 0).
    front : ndarray
        Slip front remembered if the torque reverses at the state (``InterfaceState.front``).
    memory_top, memory_below, memory_depth : ndarray of int
        The stack of remembered turning points as pointers: ``memory_top[k]`` is the newest
        turning point (state number) remembered at state k, ``memory_below[j]`` the one
        remembered under j (-1: none), ``memory_depth[k]`` their number.  ``memory[k]``
        follows the chain.
    cycle_range, cycle_mean, cycle_state, cycle_count : ndarray
        The closed loops (count 1) and half loops (count 1/2: a branch from the first
        remembered point T_1 reaching -T_1, range 2 |T_1|, mean 0): range and mean torque,
        the state at which each closed, and the count.
    cycle_energy : ndarray
        count * W(range): the energy each dissipated.
    gate : float
        The hysteresis gate applied before the memory rules (0: none; ``gated_signal``).
    dropped_turning_points : int
        Turning points of the signal removed by the gate.
    method, n_terms :
        The monotonic solutions used.
    contact : ContactModel
        The contact model (``models``); ``model`` is its name.
    """

    samples: int
    index: np.ndarray
    torque: np.ndarray
    stick_radius: np.ndarray
    rigid_rotation: np.ndarray
    dissipated_energy: np.ndarray
    direction: np.ndarray
    front: np.ndarray
    memory_top: np.ndarray
    memory_below: np.ndarray
    memory_depth: np.ndarray
    cycle_range: np.ndarray
    cycle_mean: np.ndarray
    cycle_state: np.ndarray
    cycle_count: np.ndarray
    cycle_energy: np.ndarray
    method: str
    n_terms: int | None
    gate: float
    dropped_turning_points: int
    _pieces: dict = field(repr=False)
    _signal: np.ndarray = field(repr=False)
    contact: ContactModel = field(default_factory=models.get, repr=False)

    @property
    def model(self) -> str:
        """The name of the contact model."""
        return self.contact.name

    @property
    def memory(self) -> RememberedPoints:
        """Per state, the remembered turning points as state numbers, oldest first."""
        return RememberedPoints(self.memory_top, self.memory_below)

    @property
    def signal(self) -> np.ndarray:
        """The samples the memory rules ran on (the gated signal if ``gate`` > 0)."""
        return self._signal

    @property
    def regime(self) -> list[str]:
        """Per state: "stick", "partial-slip" or "gross-slip" (of the current branch)."""
        return ["stick" if b >= 1.0 else "gross-slip" if b <= 0.0 else "partial-slip" for b in self.stick_radius]

    @property
    def total_dissipated_energy(self) -> float:
        return float(self.dissipated_energy[-1])

    @property
    def closed_loops(self) -> float:
        """Number of closed loops as rainflow counting counts cycles: full loops 1, half loops 1/2."""
        return float(np.sum(self.cycle_count))

    @property
    def half_loops(self) -> int:
        """Number of half loops (each counted 1/2 in ``closed_loops``)."""
        return int(np.count_nonzero(self.cycle_count == 0.5))

    @property
    def loop_energy(self) -> float:
        """Energy dissipated in the counted loops (the rest: first loading and the open branches)."""
        return float(np.sum(self.cycle_energy))

    def slip_fronts(self, k: int) -> list[float]:
        """Slip fronts (< 1) remembered at state k, oldest first."""
        return [float(self.front[j]) for j in self.memory[k] if self.front[j] < 1.0]

    def state_records(self) -> list[SignalStateRecord]:
        """One result record per state (``records``); for short signals."""
        regime = self.regime
        memory = self.memory
        out = []
        for k in range(self.index.size):
            remembered = memory[k]
            out.append(SignalStateRecord(
                float(self.torque[k]), float(self.stick_radius[k]),
                [float(self.front[j]) for j in remembered if self.front[j] < 1.0],
                [float(self.torque[j]) for j in remembered], float(self.rigid_rotation[k]), regime[k],
                float(self.dissipated_energy[k]), int(self.direction[k]), int(self.index[k])))
        return out

    def states(self) -> list[dict]:
        """One JSON-ready record per state (non-finite numbers -> None); for short signals."""
        return [r.as_dict() for r in self.state_records()]

    def state_columns(self) -> dict[str, np.ndarray]:
        """The states as named columns (one row per turning point) for a table file.

        ``state`` (row number, to which ``memory_top`` and ``memory_below`` point), ``index``,
        ``torque``, ``direction``, ``stick_radius``, ``slip_front`` (``front``),
        ``rigid_rotation``, ``dissipated_energy``, ``memory_depth``, ``memory_top``,
        ``memory_below``.  The regime follows from the stick radius (1: stick, 0: gross slip).
        """
        return {
            "state": np.arange(self.index.size),
            "index": self.index,
            "torque": self.torque,
            "direction": self.direction,
            "stick_radius": self.stick_radius,
            "slip_front": self.front,
            "rigid_rotation": self.rigid_rotation,
            "dissipated_energy": self.dissipated_energy,
            "memory_depth": self.memory_depth,
            "memory_top": self.memory_top,
            "memory_below": self.memory_below,
        }

    def cycle_records(self) -> list[CycleRecord]:
        """Loops grouped by exact (range, mean) (``records.CycleRecord``)."""
        groups: dict[tuple[float, float], list] = {}
        for a, m, c, w in zip(self.cycle_range.tolist(), self.cycle_mean.tolist(), self.cycle_count.tolist(),
                              self.cycle_energy.tolist(), strict=True):
            entry = groups.setdefault((a, m), [0.0, 0.0])
            entry[0] += c
            entry[1] += w
        return [CycleRecord(a, m, n, w) for (a, m), (n, w) in groups.items()]

    def cycles(self) -> list[dict]:
        """Loops grouped by exact (range, mean): ``range``, ``mean``, ``count`` (halves 1/2), ``dissipated_energy``."""
        return [r.as_dict() for r in self.cycle_records()]

    def rainflow_bins(self, bin_width: float) -> list[dict]:
        """The loops as a rainflow matrix: bins of range and mean torque, the non-empty ones.

        Bins are [i w, (i + 1) w) in range and [j w, (j + 1) w) in mean (w = ``bin_width``),
        each with ``range`` and ``mean`` (the bin centres), ``range_bin`` and ``mean_bin``
        (the edges), ``count`` (full loops 1, halves 1/2) and ``dissipated_energy`` (the sum
        of the loops' own energies, not W at the centre); sorted by range, then mean.
        """
        return [r.as_dict() for r in self.bin_records(bin_width)]

    def bin_records(self, bin_width: float) -> list[BinRecord]:
        """``rainflow_bins`` as result records (``records.BinRecord``)."""
        w = validation.real_number("bin_width", bin_width, MIN_BIN_WIDTH, 2.0 * self.contact.gross_slip_torque)
        if self.cycle_range.size == 0:
            return []
        i, j = _bin(self.cycle_range, w), _bin(self.cycle_mean, w)
        low, span = int(j.min()), int(j.max() - j.min()) + 1  # one integer key per bin, ordered by (i, j)
        keys, which = np.unique(i * span + (j - low), return_inverse=True)
        counts = np.bincount(which, weights=self.cycle_count, minlength=keys.size)
        energy = np.bincount(which, weights=self.cycle_energy, minlength=keys.size)
        return [BinRecord((a + 0.5) * w, (m + 0.5) * w, c, e, [a * w, (a + 1) * w], [m * w, (m + 1) * w])
                for a, m, c, e in zip((keys // span).tolist(), (keys % span + low).tolist(), counts.tolist(),
                                      energy.tolist(), strict=True)]

    def sample_values(self) -> tuple[np.ndarray, np.ndarray]:
        """(omega, cumulative dissipated energy) at every sample of ``signal``."""
        p = self._pieces
        which, state = stack_walk.piece_of_sample(self._signal, self.index, p)
        origin_omega = np.where(p["origin"] >= 0, self.rigid_rotation[np.maximum(p["origin"], 0)], 0.0)
        g, d = p["g"][which], p["d"][which]
        tau = np.minimum(np.abs(self._signal - p["origin_torque"][which]) / g, self.contact.gross_slip_torque)
        _, omega_m, work = self.contact.monotonic(self.method, self.n_terms).points(tau)
        with np.errstate(invalid="ignore"):  # inf - inf after spinning (omega: replaced below; energy stays inf)
            omega = origin_omega[which] + d * g * omega_m
        # a sample at a turning point where a loop closed exactly is that earlier state (or the mirrored
        # virgin one): its omega, not the cancellation of two equal increments (nan after spinning)
        closure = p["exact"][state] & (self._signal == self.torque[state])
        omega[closure] = self.rigid_rotation[state[closure]]
        with np.errstate(invalid="ignore"):
            energy = p["energy_before"][which] + g * (work - p["work_start"][which])
        energy = np.where(np.isnan(energy) & np.isinf(p["energy_before"][which]), np.inf, energy)
        return omega, energy


def _finite(value):
    value = float(value)
    return value if math.isfinite(value) else None


def _bin(values: np.ndarray, width: float) -> np.ndarray:
    """Bin numbers i with i w <= value < (i + 1) w, the edges as computed in floating point."""
    i = np.floor(values / width)
    i -= values < i * width
    i += values >= (i + 1) * width
    return i.astype(np.int64)


def analyse_signal(signal, *, method=None, n_terms=None, model=None, name: str = "signal", gate=0.0,
                   gate_name: str = "gate") -> SignalHistory:
    """States at the turning points of ``signal``, closed loops and energies (module docstring).

    Parameters
    ----------
    signal : array_like
        T* samples within the model's gross-slip torque ([-4/3, 4/3] for the cylinders), the history
        starting from the virgin interface.
    method, n_terms, model :
        As for ``history`` (default: the cylinders, the Abel-Fredholm method through ``curves``).
    name : str
        Name of the signal in error messages.
    gate : float
        Hysteresis gate in [0, 8/3]: reversals smaller than this torque range are removed
        first (``gated_signal``; 0, the default: none).
    gate_name : str
        Name of the gate in error messages.

    Returns
    -------
    SignalHistory
        With the same states as ``history(signal)`` at the turning points (of the gated
        signal if ``gate`` > 0).

    Raises
    ------
    ValueError
        Naming ``name[i]`` for a bad sample; for an empty signal, a bad method or gate.
    """
    contact = models.get(model)
    curves = contact.monotonic(method, n_terms)
    method, n_terms, points = curves.method, curves.n_terms, curves.points
    values = validated_signal(name, signal, contact)
    gate = validation.real_number(gate_name, gate, 0.0, 2.0 * contact.gross_slip_torque)
    dropped = 0
    if gate > 0.0:
        before = turning_point_indices(values).size
        values = gated_signal(values, gate, model=contact)
        dropped = before - turning_point_indices(values).size
    index = turning_point_indices(values)
    torque = values[index]
    n = index.size
    direction = np.sign(np.diff(torque, prepend=0.0)).astype(np.int64)
    walk = pieces = stack_walk.walk(torque, direction, contact.gross_slip_torque)
    last = pieces["last"]

    _, _, work_a = points(pieces["tau_a"])
    b_b, omega_b, work_b = points(pieces["tau_b"])
    g = pieces["g"]
    with np.errstate(invalid="ignore"):
        piece_work = g * (work_b - work_a)
    piece_work = np.where(np.isnan(piece_work), np.inf, piece_work)
    energy = np.cumsum(np.bincount(pieces["state"], weights=piece_work, minlength=n))

    # the state: on the last piece of its step, or (exact closure) the earlier state / mirrored virgin curve
    closing = pieces["limit"][last]  # -2: not a closure; -1: the mirrored virgin curve; j >= 0: state j
    stick_b = b_b[last]
    front = stick_b.copy()
    delta = direction * g[last] * omega_b[last]
    source = pieces["origin"][last].copy()
    mirrored = np.flatnonzero(closing == -1)
    if mirrored.size:  # on the virgin curve at -T_1: tau = |T|, g = 1, origin the virgin state
        b_m, omega_m, _ = points(np.abs(torque[mirrored]))
        front[mirrored] = b_m
        delta[mirrored] = direction[mirrored] * 1.0 * omega_m
        source[mirrored] = -1
    earlier = np.flatnonzero(closing >= 0)
    source[earlier] = closing[earlier]
    delta[earlier] = 0.0
    rotation = stack_walk.accumulate(source.tolist(), delta.tolist())
    for k in earlier.tolist():  # increasing: an earlier exact closure is resolved first
        front[k] = front[closing[k]]

    ranges, means, counts, states = stack_walk.cycles(torque, walk)
    piece_energy_before = np.concatenate([[0.0], np.cumsum(piece_work)[:-1]])
    sample_pieces = {
        "origin": pieces["origin"],
        "origin_torque": pieces["origin_torque"],
        "g": g,
        "d": direction[pieces["state"]].astype(float),
        "energy_before": piece_energy_before,
        "work_start": work_a,
        "state": pieces["state"],
        "end": pieces["end"],
        "first": pieces["first"],
        "count": pieces["count"],
        "exact": closing != -2,
    }
    return SignalHistory(
        samples=int(values.size),
        index=index,
        torque=torque,
        stick_radius=stick_b,
        rigid_rotation=rotation,
        dissipated_energy=energy,
        direction=direction,
        front=front,
        memory_top=walk["top"],
        memory_below=walk["below"],
        memory_depth=walk["depth"],
        cycle_range=ranges,
        cycle_mean=means,
        cycle_state=states,
        cycle_count=counts,
        cycle_energy=counts * contact.energy_per_cycle(ranges, method=method, n_terms=n_terms) if ranges.size
        else np.zeros(0),
        method=method,
        n_terms=n_terms,
        gate=gate,
        dropped_turning_points=int(dropped),
        _pieces=sample_pieces,
        _signal=values,
        contact=contact,
    )
