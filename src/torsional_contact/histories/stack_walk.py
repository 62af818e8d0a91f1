"""The memory-rule stack walk of a long signal on arrays (``histories.signal``, steps 2 and 3 and the samples).

Units: T* = 2T/(f F a).  Internal to ``analyse_signal``: the loops closed and the remembered
points of every state and the stretches of branches ("pieces") they cross, from the one Masing
engine (``histories.masing``), and the piece of every sample.
"""

from __future__ import annotations

import numpy as np

from . import masing

__all__ = ["walk", "accumulate", "cycles", "piece_of_sample"]


def walk(torque: np.ndarray, direction: np.ndarray, gross_slip_torque: float) -> dict:
    """Rule 4 on the turning-point torques (``histories.masing.walk``, the one Masing engine), as the arrays of
    ``histories.signal``.

    Per piece (the stretches of branches crossed by every step, in order; a step k crosses one piece per
    loop it closes, origin T_k of the loop, ending at its limit, and, unless it ends exactly at a limit, a
    last piece from the newest remembered point or the virgin curve to T_k): ``state`` (k), ``origin`` (a
    state number, -1: the virgin curve), ``origin_torque``, ``limit`` (-2 for those last pieces, -1 for the
    mirrored virgin curve at -T_1, else the state reached), ``end``, ``g``, the increments ``tau_a``,
    ``tau_b`` (capped at the model's ``gross_slip_torque``); per step ``first``, ``count``, ``last``; per
    loop closed ``closed_state`` (the state whose step closed it), ``closed_origin`` and ``closed_limit``
    (-1: the mirrored virgin curve); per state ``top``, ``depth`` and ``below`` (``SignalHistory.memory_top``
    etc.).
    """
    p = masing.walk(torque, direction)
    limit = np.where(p.closure == masing.OPEN, -2, np.where(p.closure == masing.MIRROR, -1, p.closure))
    closed = np.flatnonzero(limit != -2)
    on_branch = p.origin >= 0
    origin_torque = np.where(on_branch, torque[np.maximum(p.origin, 0)], 0.0)
    start = np.concatenate([[0.0], p.end[:-1]])
    return {
        "state": p.step,
        "origin": p.origin,
        "origin_torque": origin_torque,
        "limit": limit,
        "end": p.end,
        "g": p.g,
        "tau_a": np.abs(start - origin_torque) / p.g,
        "tau_b": np.minimum(np.abs(p.end - origin_torque) / p.g, gross_slip_torque),
        "first": p.first,
        "count": p.count,
        "last": p.first + p.count - 1,
        "closed_state": p.step[closed],
        "closed_origin": p.origin[closed],
        "closed_limit": limit[closed],
        "top": p.top,
        "depth": p.depth,
        "below": p.below,
    }


def accumulate(source: list[int], delta: list[float]) -> np.ndarray:
    """x_k = x_source[k] + delta_k (source[k] < k, -1: 0), in order: omega along the chain of origins."""
    x = [0.0] * (len(delta) + 1)  # x[-1] stays 0: the virgin state
    for k, (s, dk) in enumerate(zip(source, delta, strict=True)):
        x[k] = x[s] + dk
    return np.array(x[:-1])


def cycles(torque: np.ndarray, walk: dict):
    """Range, mean, count and closing state of every loop closed (``histories.signal``, closed loops)."""
    s1, s2 = walk["closed_origin"], walk["closed_limit"]
    full = s2 >= 0
    t1, t2 = torque[s1], torque[np.maximum(s2, 0)]
    ranges = np.where(full, np.abs(t1 - t2), 2.0 * np.abs(t1))
    means = np.where(full, 0.5 * (t1 + t2), 0.0)
    counts = np.where(full, 1.0, 0.5)
    return ranges, means, counts, walk["closed_state"]


def piece_of_sample(values: np.ndarray, index: np.ndarray, pieces: dict) -> tuple[np.ndarray, np.ndarray]:
    """The piece and the step (state) of each sample: the samples of a step, split at its loop closures.

    The samples of step k (after turning point k - 1, up to k) are monotonic; those beyond
    the end of a closing piece (in the direction of the step) lie on the next piece.  The
    closures of a step are passed in order, so each round compares the samples still
    moving with the next closure: exact comparisons, no search.
    """
    first, count = pieces["first"], pieces["count"]
    steps = np.diff(index, prepend=-1)
    steps[-1] += values.size - 1 - index[-1]  # a final run of equal samples stays at the last turning point
    state = np.repeat(np.arange(index.size), steps)
    out = first[state]
    direction = pieces["d"][first]  # the direction of each step (the same on all its pieces)
    oriented = direction[state] * values
    active = np.flatnonzero(count[state] > 1)
    passed = 0
    while active.size:
        k = state[active]
        piece = first[k] + passed
        beyond = oriented[active] > direction[k] * pieces["end"][piece]
        active = active[beyond]
        out[active] += 1
        passed += 1
        active = active[count[state[active]] > passed + 1]
    return out, state
