r"""The one Masing engine: the stack of remembered turning points (memory rule 4 of ``histories.memory``).

The memory rules need, for a history of turning points x_1, x_2, ... reached from the virgin state
x = 0, only the order of these numbers: which earlier turning points are remembered, which loops
close and erase them, and the stretches of branches ("pieces") every step crosses.  The coordinate
x may be the torque (``histories.memory``, ``histories.signal``) or, along the branches where the
twist is a strictly increasing function of the torque, the twist (``fitting.masing``); the rules
are the same:

* a step that reverses the direction of the previous one remembers the point where it starts;
* a branch starts at the newest remembered point with factor g = 2 (the virgin curve: origin 0,
  g = 1); it closes its loop when it *reaches* (ties included) the limit x_(k-1), the point
  remembered before its origin x_k, or, from the first remembered point, its mirror image -x_1;
* a closed loop is erased (both points popped; from the first one, only it) and the step goes
  on along the branch that led to the limit; a step that ends exactly at a limit ends there.

``MasingStack`` runs these rules one step at a time on labelled points (``step``: a turning-point object
for ``histories.memory.advance``, a state or turning-point number for the array walks); ``walk`` runs
them over a whole sequence and returns the pieces as arrays (``Pieces``), with, per step, the
newest remembered point after it and the chain of points below each remembered one (the stack of
every state in O(1) each).  Nothing else in the package runs a Masing stack.

Units: those of the coordinate (T* or a twist); the engine does no arithmetic on it beyond
comparisons and the mirror image -x_1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["VIRGIN", "MIRROR", "OPEN", "MasingStack", "Pieces", "walk"]

#: Origin label of the virgin curve (through the coordinate 0).
VIRGIN = -1
#: Closure label of a branch from the first remembered point that reaches its mirror image -x_1.
MIRROR = -2
#: ``Pieces.closure`` of a piece that ends at its step's target without closing a loop.
OPEN = -3


class MasingStack:
    """Remembered turning points, oldest first: ``points`` (coordinates) and ``labels`` (anything).

    ``heading`` is the direction of the last step (0: none yet), ``current`` the coordinate reached.
    """

    __slots__ = ("points", "labels", "heading", "current")

    def __init__(self, points=(), labels=(), heading: int = 0, current: float = 0.0):
        self.points, self.labels = list(points), list(labels)
        self.heading, self.current = heading, current

    def limit(self) -> float:
        """Where the branch from the newest remembered point closes its loop."""
        points = self.points
        return points[-2] if len(points) >= 2 else -points[-1]

    def step(self, target: float, label=None, direction: int = 0) -> list[tuple]:
        """Go from ``current`` to ``target``: the pieces crossed, in order, and the stack updated.

        ``label``: remembered with ``current`` if the step reverses (a callable is called for it then,
        and only then).  ``direction``: +1 or -1 when ``target`` equals ``current`` (otherwise ignored);
        with equal coordinates and no direction the step is one empty piece on the current branch and
        changes nothing.  Each piece is (origin label, g, end, closure): origin ``VIRGIN`` on the virgin
        curve; closure None when the piece ends at ``target`` without reaching a limit, else the label
        of the earlier point reached (``MIRROR``: the mirror image of the first point), whose loop is
        erased with it.  (The stack a piece lies on is the one below its origin, plus the origin.)
        """
        current = self.current
        d = 1 if target > current else -1 if target < current else direction
        points, labels = self.points, self.labels
        if d == 0:
            return [(labels[-1], 2.0, target, None) if points else (VIRGIN, 1.0, target, None)]
        if d != self.heading and self.heading:
            points.append(current)
            labels.append(label() if callable(label) else label)
        self.heading = d
        self.current = target
        pieces = []
        depth = len(points)
        while depth:
            if depth >= 2:
                limit = points[-2]
                if d * (target - limit) < 0:
                    break
                pieces.append((labels[-1], 2.0, limit, labels[-2]))
                del points[-2:], labels[-2:]
                depth -= 2
            else:
                limit = -points[-1]
                if d * (target - limit) < 0:
                    break
                pieces.append((labels[-1], 2.0, limit, MIRROR))
                points.pop(), labels.pop()
                depth = 0
            if limit == target:  # exactly at the earlier point: the step ends there
                return pieces
        pieces.append((labels[-1], 2.0, target, None) if depth else (VIRGIN, 1.0, target, None))
        return pieces


@dataclass(frozen=True)
class Pieces:
    """The pieces of a ``walk``, in order, and the stacks of its states (arrays).

    Per piece: ``step`` (the step k it belongs to, the step from point k - 1 to point k), ``origin``
    (the point number of the branch's origin, ``VIRGIN``), ``g`` (1 or 2), ``end`` (coordinate),
    ``closure`` (-3: it ends at the step's target without closing a loop; ``MIRROR``; or the number of
    the earlier point reached).  Per step: ``first`` piece and ``count``, ``direction`` (+1 / -1),
    ``top`` (the newest point remembered after it, ``VIRGIN`` if none), ``depth`` (how many) and
    ``below`` (for a remembered point, the point remembered under it, ``VIRGIN`` if none).
    """

    step: np.ndarray
    origin: np.ndarray
    g: np.ndarray
    end: np.ndarray
    closure: np.ndarray
    first: np.ndarray
    count: np.ndarray
    direction: np.ndarray
    top: np.ndarray
    depth: np.ndarray
    below: np.ndarray


def walk(targets, directions=None) -> Pieces:
    """The memory rules on the points ``targets`` reached one after the other from the virgin state (coordinate 0).

    Point k is where step k ends; it is labelled k.  ``directions`` (optional, +1 / -1 per step, or 0) gives the
    direction of a step whose target equals the previous point; without it such a step is one empty piece on the
    current branch and changes nothing (``MasingStack.step``).
    """
    values = [float(v) for v in targets]
    given = [int(v) for v in directions] if directions is not None else [0] * len(values)
    n = len(values)
    stack = MasingStack()
    labels = stack.labels
    origin, g, end, closure = [], [], [], []  # columns, not tuples: a long list of tuples keeps the collector busy
    first, count, heading = [0] * n, [0] * n, [0] * n
    top, depth, below = [VIRGIN] * n, [0] * n, [VIRGIN] * n
    step = stack.step
    current, last = 0.0, 0  # the point reached and the direction of the last step that had one
    for k in range(n):
        target = values[k]
        d = 1 if target > current else -1 if target < current else given[k]
        if d != last and last and d:  # point k - 1 will be remembered above the newest one
            below[k - 1] = labels[-1] if labels else VIRGIN
        start = len(origin)
        first[k] = start
        for o, factor, e, c in step(target, k - 1, d):
            origin.append(o)
            g.append(factor)
            end.append(e)
            closure.append(OPEN if c is None else c)
        count[k] = len(origin) - start
        heading[k] = d
        if labels:
            top[k] = labels[-1]
            depth[k] = len(labels)
        current = target
        if d:
            last = d
    step_of = np.repeat(np.arange(n, dtype=np.int64), count)
    as_int = np.int64
    return Pieces(step_of, np.array(origin, dtype=as_int), np.array(g, dtype=float),
                  np.array(end, dtype=float), np.array(closure, dtype=as_int), np.array(first, dtype=as_int),
                  np.array(count, dtype=as_int), np.array(heading, dtype=as_int), np.array(top, dtype=as_int),
                  np.array(depth, dtype=as_int), np.array(below, dtype=as_int))
