"""The memory-rule stack walk of a long signal on arrays (``histories.signal``, steps 2 and 3 and the samples).

Units: T* = 2T/(f F a).  Internal to ``analyse_signal``: the loops closed and the remembered
points of every state (one plain-Python loop over the turning points), the stretches of
branches ("pieces") they cross, assembled with numpy, and the piece of every sample.
"""

from __future__ import annotations

import numpy as np

__all__ = ["walk", "assemble_pieces", "accumulate", "cycles", "piece_of_sample"]


def walk(torque: np.ndarray, direction: np.ndarray) -> dict:
    """Rule 4 on the torques alone: the loops closed and the remembered points of every state.

    Returns arrays: per loop closed, ``closed_state`` (the state whose step closed it),
    ``closed_origin`` (the branch's origin T_k, a state number) and ``closed_limit``
    (T_(k-1), or -1 for the mirrored virgin curve at -T_1); per state ``top``, ``depth``
    and ``below`` (``SignalHistory.memory_top`` etc.).
    """
    t = torque.tolist()
    d = direction.tolist()
    n = len(t)
    push = [False] + ((direction[:-1] != 0) & (direction[1:] != direction[:-1])).tolist()
    stack: list[int] = []  # state numbers of the remembered turning points
    limits: list[float] = []  # the torque at which the branch from each of them closes
    top, depth, below = [-1] * n, [0] * n, [-1] * n
    closed_state, closed_origin, closed_limit = [], [], []
    for k in range(n):
        tk, dk = t[k], d[k]
        if push[k]:  # a reversal at state k - 1: it is remembered
            if stack:
                below[k - 1] = stack[-1]
                limits.append(t[stack[-1]])
            else:
                limits.append(-t[k - 1])
            stack.append(k - 1)
        while limits and dk * (tk - limits[-1]) >= 0:  # reaching the limit closes the loop (ties included)
            limit = limits.pop()
            closed_state.append(k)
            closed_origin.append(stack.pop())
            if stack:
                closed_limit.append(stack.pop())
                limits.pop()
            else:
                closed_limit.append(-1)
            if limit == tk:  # exactly at the earlier state: the step ends there
                break
        if stack:
            top[k] = stack[-1]
            depth[k] = len(stack)
    return {
        "closed_state": np.array(closed_state, dtype=np.int64),
        "closed_origin": np.array(closed_origin, dtype=np.int64),
        "closed_limit": np.array(closed_limit, dtype=np.int64),
        "top": np.array(top, dtype=np.int64),
        "depth": np.array(depth, dtype=np.int64),
        "below": np.array(below, dtype=np.int64),
    }


def assemble_pieces(torque: np.ndarray, direction: np.ndarray, walk: dict, gross_slip_torque: float) -> dict:
    """The stretches of branches crossed by every step, in order (``histories.signal``, step 3).

    A step k crosses one piece per loop it closes (origin T_k of the loop, ending at its
    limit) and, unless it ends exactly at a limit, a last piece from the newest remembered
    point (or the virgin curve) to T_k.  ``limit`` is -2 for those last pieces.  The increments tau
    are capped at the model's ``gross_slip_torque``.
    """
    n = torque.size
    c_state, c_origin, c_limit = walk["closed_state"], walk["closed_origin"], walk["closed_limit"]
    c_end = np.where(c_limit >= 0, torque[np.maximum(c_limit, 0)], -torque[c_origin])
    exact = np.zeros(n, dtype=bool)
    exact[c_state[c_end == torque[c_state]]] = True
    closures = np.bincount(c_state, minlength=n)
    count = closures + ~exact
    first = np.cumsum(count) - count
    total = int(count.sum())
    state = np.repeat(np.arange(n), count)
    origin = np.empty(total, dtype=np.int64)
    limit = np.empty(total, dtype=np.int64)
    end = np.empty(total)
    position = first[c_state] + (np.arange(c_state.size) - (np.cumsum(closures) - closures)[c_state])
    origin[position], limit[position], end[position] = c_origin, c_limit, c_end
    final = np.flatnonzero(~exact)
    position = first[final] + closures[final]
    origin[position], limit[position], end[position] = walk["top"][final], -2, torque[final]
    start = np.concatenate([[0.0], end[:-1]])
    on_branch = origin >= 0
    origin_torque = np.where(on_branch, torque[np.maximum(origin, 0)], 0.0)
    g = np.where(on_branch, 2.0, 1.0)
    return {
        "state": state,
        "origin": origin,
        "origin_torque": origin_torque,
        "limit": limit,
        "end": end,
        "g": g,
        "tau_a": np.abs(start - origin_torque) / g,
        "tau_b": np.minimum(np.abs(end - origin_torque) / g, gross_slip_torque),
        "first": first,
        "count": count,
        "last": first + count - 1,
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
