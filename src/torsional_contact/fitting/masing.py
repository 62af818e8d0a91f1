r"""The memory rules driven by the twist: the torque a rig measures along any twist history.

The memory rules of ``histories.memory`` (Cattaneo-Mindlin, Masing) are stated for a torque
history: a branch from a turning point (T_k, theta_k) is theta - theta_k = d g Theta(|T - T_k|
/ g), with Theta the monotonic (skeleton) twist of ``fitting.skeleton``, g = 2 on a branch and
g = 1 on the virgin curve, and loops close where a branch reaches the previous turning point
(or, from the first one, its mirror image).  Along every branch the twist is a strictly
increasing function of the torque, so the same rules hold with the roles exchanged:

    T - T_k = d g F(|theta - theta_k| / g),    F = Theta^(-1),

and a branch reaches a turning point's torque exactly when it reaches its twist.  The stack of
remembered turning points, the loop closures and the pieces of each branch therefore depend
on the twists alone; the torque follows by one evaluation of F per sample.  F saturates at the
gross-slip torque 2 f F a / 3 as the twist grows: a twist-controlled rig's gross-slip plateau
is the far end of the same branches, with no special case (the spinning state erases the
memory because its torque exceeds every remembered one; so does the long branch here).

``walk`` does the bookkeeping on the turning-point twists (the one Masing engine, ``histories.masing``);
``torque_along`` evaluates the
torque and its slope dT/dtheta at every sample (``pieces`` tabulates, once per walk, what it looks
up for each sample: its piece's origin, factor and direction).  ``tests/test_fit.py`` checks both against the
torque-driven ``histories.analyse_signal`` of the same history.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..histories import masing

__all__ = ["Walk", "walk", "Turning", "turning_torques", "Pieces", "pieces", "torque_along", "curvature_along",
           "jacobian_along"]


@dataclass(frozen=True)
class Walk:
    """Pieces of branches along the segments between turning points (``walk``).

    Twists u are measured from the virgin state (u = 0, T = 0).  Piece p lies on the branch
    from turning point ``origin[p]`` (-1: the virgin curve through 0) with factor ``g[p]`` and
    direction ``direction[p]``; it ends at twist ``end[p]``.  Segment j runs from turning point
    j - 1 (the virgin state for j = 0) to ``targets[j]``, over pieces ``first[j]`` to
    ``first[j] + count[j] - 1``; turning point j (j < number of segments - 1) has its torque on
    piece ``first[j] + count[j] - 1``.
    """

    targets: np.ndarray
    origin: np.ndarray
    g: np.ndarray
    direction: np.ndarray
    end: np.ndarray
    first: np.ndarray
    count: np.ndarray


def walk(targets) -> Walk:
    """The memory rules on the turning-point twists ``targets`` (from the virgin state u = 0).

    ``targets[j]`` is where segment j ends: the turning points, then the last twist reached.  The stack is
    the one Masing engine's (``histories.masing.walk``); a segment of zero length reverses the previous one
    (a turning twist that an optimiser has put on top of the previous one).
    """
    u = [float(v) for v in targets]
    directions, current, heading = [], 0.0, 0
    for target in u:
        heading = 1 if target > current else -1 if target < current else (-heading or 1)
        directions.append(heading)
        current = target
    p = masing.walk(u, directions)
    return Walk(np.array(u), p.origin, p.g, p.direction.take(p.step).astype(float), p.end, p.first, p.count)


@dataclass(frozen=True)
class Turning:
    """Torques at the turning points of a ``Walk`` (``turning_torques``) and, if asked for, their derivatives."""

    torque: np.ndarray
    gradient: np.ndarray | None


def turning_torques(path: Walk, branch, jacobian: bool = False) -> Turning:
    """T_j = T(origin) + d g F(d (U_j - u_origin) / g) at the M turning points, in order [and dT_j/dparams].

    ``branch`` as for ``torque_along`` (with ``jacobian``: returning the derivatives of F too).  The
    gradient's columns: the skeleton's q parameters, the twist of the virgin state, the M turning
    twists.
    """
    o, gain, v = _turning_arguments(path)
    return _turning_from(o, gain, branch(v), jacobian)


def _turning_arguments(path: Walk):
    """(origins, d g, the arguments d (U_j - u_origin) / g of F) of the turning points (``turning_torques``): lists
    of Python floats and ints but for the arguments (the same IEEE operations as on arrays of a few elements, without
    their per-call overhead)."""
    targets, origin = path.targets.tolist(), path.origin.tolist()
    g, direction = path.g.tolist(), path.direction.tolist()
    first, count = path.first.tolist(), path.count.tolist()
    o, gain, arguments = [], [], []
    for j in range(len(targets) - 1):
        last = first[j] + count[j] - 1
        o.append(origin[last])
        u_origin = targets[origin[last]] if origin[last] >= 0 else 0.0
        gain.append(g[last] * direction[last])
        arguments.append(direction[last] * (targets[j] - u_origin) / g[last])
    return o, gain, np.array(arguments, dtype=float)


def _turning_from(o, gain, at_turning, jacobian: bool) -> Turning:
    """``turning_torques`` from ``_turning_arguments``' origins and gains and the branch's values at the arguments."""
    n_turning = len(o)
    increments = [gain_j * value for gain_j, value in zip(gain, at_turning[0].tolist(), strict=True)]
    turning_list = []  # Python floats: the same IEEE additions as on the array, without its per-element overhead
    for j, origin_j in enumerate(o):
        turning_list.append((turning_list[origin_j] if origin_j >= 0 else 0.0) + increments[j])
    turning = np.array(turning_list, dtype=float)
    if not jacobian:
        return Turning(turning, None)
    # d T_j = d T(origin) + d g dF/dparams + F'(v_j) (dU_j - dU_origin), with U_origin = theta_0 on the virgin curve;
    # on Python floats, row by row (the same IEEE operations as on the rows of an array)
    q = at_turning[2].shape[1]
    columns = q + 1 + n_turning
    slopes, derivatives = at_turning[1].tolist(), at_turning[2].tolist()
    rows = []
    for j, origin_j in enumerate(o):
        row = list(rows[origin_j]) if origin_j >= 0 else [0.0] * columns
        gain_j, derivative = gain[j], derivatives[j]
        for k in range(q):
            row[k] += gain_j * derivative[k]
        row[q + 1 + j] += slopes[j]
        row[q + 1 + origin_j if origin_j >= 0 else q] -= slopes[j]
        rows.append(row)
    grad_turning = np.array(rows, dtype=float).reshape(n_turning, columns)
    return Turning(turning, grad_turning)


@dataclass(frozen=True)
class Pieces:
    """What ``torque_along`` looks up for a sample, tabulated once for a ``Walk`` and its ``Turning`` torques.

    ``table`` rows, one column per piece: the twist of its origin (0 on the virgin curve), the torque there (0), its
    direction over its factor d / g and d g (d = +-1 and g = 1 or 2, so that multiplying by d / g is the same
    operation as multiplying by d and dividing by g, rounding included).  Per segment: ``first`` piece,
    ``heading`` (its direction), and for m = 0, 1, ... ``thresholds[m]``, heading times the end of its piece m
    where the segment has a piece m + 1 after it, else +inf: a sample past it (in the segment's direction) lies on
    a later piece.
    """

    table: np.ndarray
    first: np.ndarray
    heading: np.ndarray
    thresholds: tuple


def pieces(path: Walk, turning: Turning) -> Pieces:
    """The lookup tables of ``path`` for ``torque_along`` (``Pieces``), formed on Python floats (the same IEEE
    operations as on arrays of a few elements)."""
    targets, origin = path.targets.tolist(), path.origin.tolist()
    direction, g, end = path.direction.tolist(), path.g.tolist(), path.end.tolist()
    torque = turning.torque.tolist() if len(targets) > 1 else None
    table = np.array([[targets[o] if o >= 0 else 0.0 for o in origin],
                      [torque[o] if o >= 0 else 0.0 for o in origin] if torque is not None else [0.0] * len(origin),
                      [d / f for d, f in zip(direction, g, strict=True)],
                      [d * f for d, f in zip(direction, g, strict=True)]], dtype=float)
    first, count = path.first.tolist(), path.count.tolist()
    heading = [direction[f] for f in first]
    thresholds = tuple(np.array([h * end[min(f + m, len(end) - 1)] if c > m + 1 else np.inf
                                 for h, f, c in zip(heading, first, count, strict=True)], dtype=float)
                       for m in range(max(count) - 1))
    return Pieces(table, path.first, np.array(heading, dtype=float), thresholds)


def _piece_of(lookup: Pieces, u, segment):
    """The piece of every sample: the first of its segment, plus the piece ends it has passed (piece ends increase
    along the segment)."""
    piece = lookup.first[segment]
    if lookup.thresholds:
        ahead = lookup.heading[segment] * u
        for threshold in lookup.thresholds:
            piece = piece + (ahead > threshold[segment])
    return piece


def torque_along(path: Walk, u: np.ndarray, segment: np.ndarray, branch, jacobian: bool = False,
                 curvature: bool = False, turning: Turning | None = None, lookup: Pieces | None = None):
    """Torque and slope dT/du at twists ``u`` (from the virgin state) of samples on segments ``segment``.

    ``branch(v)`` returns (F(v), F'(v)) of the skeleton, odd in v, and with ``jacobian`` also the
    derivatives of F with respect to its own parameters (an (n, q) array), with ``curvature`` F''(v)
    instead (then the fourth value returned is d^2T/du^2 = d F''(v) / g at every sample).  A sample
    beyond either end of its segment is evaluated on the nearest piece, continued (the branch's own
    smooth continuation: a noisy sample next to a turning point).  ``turning``: the walk's
    ``turning_torques`` if already known (with their gradient when ``jacobian``); ``lookup``: its ``pieces``
    (made from ``turning``) if already known.  ``u`` and ``segment`` may have any (common) shape without
    ``jacobian``; with it they are 1-d.

    Returns (torque, slope, turning-point torques), and with ``jacobian`` the derivatives of the
    torque at every sample (n, q + 1 + M) with respect to the skeleton's parameters, the twist of
    the virgin state (which moves the virgin curve: u = theta - theta_0) and the M turning-point
    twists (``path.targets[:M]``; the last target only bounds the last segment).
    """
    if jacobian and not curvature:
        torque, slope, turning, jac = jacobian_along(path, u, segment, branch, turning, lookup)
        return torque, slope, turning.torque, jac
    if turning is None:
        turning = turning_torques(path, branch)
        lookup = None
    if lookup is None:
        lookup = pieces(path, turning)
    if curvature:
        torque, slope, second = curvature_along(lookup, u, segment, branch)
        return torque, slope, turning.torque, second
    piece = _piece_of(lookup, u, segment)
    origin_twist, origin_torque, shrink, gain = lookup.table.take(piece, axis=1)
    values = branch((u - origin_twist) * shrink)  # d (u - u_origin) / g
    return origin_torque + gain * values[0], values[1], turning.torque


def curvature_along(lookup: Pieces, u, segment, branch):
    """(torque, slope, d^2T/du^2) at twists ``u`` of samples on segments ``segment`` (any common shape):
    ``torque_along`` with ``curvature``, ``branch`` returning (F, F', F''), for the walk's ``pieces`` ``lookup``."""
    piece = _piece_of(lookup, u, segment)
    origin_twist, origin_torque, shrink, gain = lookup.table.take(piece, axis=1)
    values = branch((u - origin_twist) * shrink)  # d (u - u_origin) / g
    return origin_torque + gain * values[0], values[1], values[2] * shrink


def jacobian_along(path: Walk, u: np.ndarray, segment: np.ndarray, branch, turning: Turning | None = None,
                   lookup: Pieces | None = None, sparse: bool = False):
    """``torque_along`` with ``jacobian``, returning the ``Turning`` (with its gradient) in the place of its torques.

    Where ``turning`` and ``lookup`` are known but not the turning points' gradient, F and its derivatives at the
    turning points come from the same evaluation of ``branch`` as the samples' (F acts elementwise: the same numbers
    as from two), and their torques are recomputed from it (the same numbers as ``turning``'s).

    ``sparse``: the Jacobian as a ``scipy.sparse`` CSR matrix, built without its dense form (each sample's row is
    its piece's origin gradient, few turning points in a steady loop, plus the skeleton's columns and one twist
    column): the same numbers, for records whose dense Jacobian is large.
    """
    n_turning = path.targets.size - 1
    joint = turning is not None and turning.gradient is None and lookup is not None
    if turning is None or (turning.gradient is None and not joint):
        turning = turning_torques(path, branch, True)
        lookup = None
    if lookup is None:
        lookup = pieces(path, turning)
    piece = _piece_of(lookup, u, segment)
    origin_twist, origin_torque, shrink, gain = lookup.table.take(piece, axis=1)
    arguments = (u - origin_twist) * shrink  # d (u - u_origin) / g
    if joint:
        o, turning_gain, at_turning = _turning_arguments(path)
        values = branch(np.concatenate((at_turning, arguments)))
        turning = _turning_from(o, turning_gain, [value[:n_turning] for value in values], True)
        values = [value[n_turning:] for value in values]
    else:
        values = branch(arguments)
    torque = origin_torque + gain * values[0]
    # per piece (then gathered for the samples): the gradient of its origin's torque (0 on the virgin curve) and the
    # column of its origin's twist (theta_0's on the virgin curve)
    known = path.origin >= 0
    q = values[2].shape[1]
    columns = q + 1 + n_turning
    twist_column = np.where(known, q + 1 + path.origin, q).take(piece)
    if sparse:
        from scipy import sparse as sp

        rows = np.arange(u.size)
        local = sp.csr_matrix((np.concatenate([(gain[:, None] * values[2]).ravel(), -values[1]]),
                               (np.concatenate([np.repeat(rows, q), rows]),
                                np.concatenate([np.tile(np.arange(q), u.size), twist_column]))),
                              shape=(u.size, columns))
        if not n_turning:
            return torque, values[1], turning, local
        origins = sp.csr_matrix(turning.gradient[np.maximum(path.origin, 0)] * known[:, None])
        return torque, values[1], turning, origins[piece] + local
    if n_turning:
        jac = (turning.gradient[np.maximum(path.origin, 0)] * known[:, None]).take(piece, axis=0)
    else:
        jac = np.zeros((u.size, columns))
    jac[:, :q] += gain[:, None] * values[2]
    jac[np.arange(u.size), twist_column] -= values[1]
    return torque, values[1], turning, jac
