"""Piecewise Chebyshev interpolants: evaluation (vectorised and scalar), derivative, root finding.

Each panel [edges[k], edges[k+1]] carries a Chebyshev series in the affine variable
x = (2 v - edges[k] - edges[k+1]) / (edges[k+1] - edges[k]) in [-1, 1].  The variable v
and its units are the caller's (``curves.interpolant``).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.polynomial import chebyshev

__all__ = ["Piecewise"]


class Piecewise:
    """A piecewise Chebyshev series on increasing ``edges`` (one coefficient list per panel).

    Points outside [edges[0], edges[-1]] evaluate to nan: the caller handles the ends.
    """

    def __init__(self, edges, coefficients):
        self.edges = np.asarray(edges, dtype=float)
        self.coefficients = [np.asarray(c, dtype=float) for c in coefficients]
        if self.edges.ndim != 1 or self.edges.size != len(self.coefficients) + 1 or np.any(np.diff(self.edges) <= 0):
            raise ValueError("edges must increase and number one more than the coefficient lists")
        self._lists = [c.tolist() for c in self.coefficients]
        self._edge_list = self.edges.tolist()

    def panel(self, v) -> np.ndarray:
        """Panel index of each point (-1 outside the edges)."""
        v = np.asarray(v, dtype=float)
        k = np.searchsorted(self.edges, v, side="right") - 1
        k = np.where(v == self.edges[-1], self.edges.size - 2, k)
        return np.where((v >= self.edges[0]) & (v <= self.edges[-1]), k, -1)

    def local(self, k: int, v):
        lo, hi = self.edges[k], self.edges[k + 1]
        return (2.0 * np.asarray(v, dtype=float) - lo - hi) / (hi - lo)

    def __call__(self, v) -> np.ndarray:
        v = np.asarray(v, dtype=float)
        flat = v.ravel()
        out = np.full(flat.shape, np.nan)
        index = self.panel(flat)
        order = np.argsort(index, kind="stable")
        bounds = np.searchsorted(index[order], np.arange(-1, len(self.coefficients) + 1))
        for k in range(len(self.coefficients)):
            chosen = order[bounds[k + 1] : bounds[k + 2]]
            if chosen.size:
                out[chosen] = chebyshev.chebval(self.local(k, flat[chosen]), self.coefficients[k])
        return out.reshape(v.shape)

    def scalar(self, v: float) -> float:
        """The same value for one float, without numpy overhead (nan outside the edges)."""
        edges = self._edge_list
        if not edges[0] <= v <= edges[-1]:
            return math.nan
        lo_index, hi_index = 0, len(edges) - 1
        while hi_index - lo_index > 1:  # bisection for the panel
            mid = (lo_index + hi_index) // 2
            if v >= edges[mid]:
                lo_index = mid
            else:
                hi_index = mid
        lo, hi = edges[lo_index], edges[lo_index + 1]
        x = (2.0 * v - lo - hi) / (hi - lo)
        coefficients = self._lists[lo_index]
        b1 = b2 = 0.0  # Clenshaw
        for c in reversed(coefficients[1:]):
            b1, b2 = 2.0 * x * b1 - b2 + c, b1
        return x * b1 - b2 + coefficients[0]

    @functools.cached_property
    def derivative(self) -> Piecewise:
        """d/dv of the interpolant (same panels; computed once)."""
        widths = np.diff(self.edges)
        return Piecewise(
            self.edges,
            [chebyshev.chebder(c) * 2.0 / w if c.size > 1 else np.zeros(1) for c, w in zip(self.coefficients, widths,
                                                                                             strict=True)],
        )

    def solve(self, target, *, iterations: int = 60) -> np.ndarray:
        """v with f(v) = target for a monotonic interpolant (safeguarded Newton per panel).

        Returns nan where the target is outside the range of f over the edges.
        """
        target = np.asarray(target, dtype=float)
        flat = target.ravel()
        out = np.full(flat.shape, np.nan)
        ends = np.array([chebyshev.chebval([-1.0, 1.0], c) for c in self.coefficients])  # (panels, 2)
        slope = self.derivative
        for k, c in enumerate(self.coefficients):
            f_lo, f_hi = ends[k]
            low, high = min(f_lo, f_hi), max(f_lo, f_hi)
            slack = 1e-13 * max(abs(low), abs(high))  # rounding of targets at the panel ends
            mask = (flat >= low - slack) & (flat <= high + slack) & np.isnan(out)
            if not mask.any():
                continue
            y = flat[mask]
            sign = 1.0 if f_hi >= f_lo else -1.0
            a, b = np.full(y.shape, -1.0), np.full(y.shape, 1.0)
            x = np.clip(-1.0 + 2.0 * (y - f_lo) / (f_hi - f_lo) if f_hi != f_lo else np.zeros(y.shape), -1.0, 1.0)
            dc = slope.coefficients[k] * 0.5 * (self.edges[k + 1] - self.edges[k])
            for _ in range(iterations):
                residual = chebyshev.chebval(x, c) - y
                below = sign * residual < 0
                a = np.where(below, x, a)
                b = np.where(below, b, x)
                derivative = chebyshev.chebval(x, dc)
                with np.errstate(divide="ignore", invalid="ignore"):
                    step = x - residual / derivative
                bad = ~((step > a) & (step < b))
                step = np.where(bad, 0.5 * (a + b), step)
                done = np.abs(step - x) <= 4e-16 * np.maximum(1.0, np.abs(x))
                x = step
                if done.all():
                    break
            out[np.nonzero(mask)[0]] = 0.5 * (self.edges[k + 1] - self.edges[k]) * x + 0.5 * (
                self.edges[k + 1] + self.edges[k])
        return out.reshape(target.shape)
