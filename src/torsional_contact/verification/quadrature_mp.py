"""Arbitrary-precision composite Gauss-Legendre rules for the closed-form checks (mpmath).

The rules run at the caller's ``mpmath.workdps``; ``Nodes`` caches J1(lam r) at the nodes
(python-flint's Arb Bessel functions when importable, otherwise mpmath's).
"""

from __future__ import annotations

import functools
import math

import mpmath

from . import arbitrary_precision as ap

__all__ = ["GL_POINTS", "gauss_legendre", "Nodes"]

#: Gauss-Legendre points per period of the fastest oscillation of a quadrature integrand.
GL_POINTS = 20



@functools.lru_cache(maxsize=4)
def _gl_rule(points: int, dps: int):
    with mpmath.workdps(dps):
        x, w = mpmath.mp.gauss_quadrature(points, "legendre")
        return tuple(x), tuple(w)


def gauss_legendre(lower, upper, max_frequency, points: int = GL_POINTS):
    """Composite Gauss-Legendre nodes and weights on [lower, upper] at the current precision.

    The interval is cut into pieces of at most one period 2 pi / max_frequency of the
    fastest oscillation (at least 4 pieces); each piece gets a ``points``-point rule,
    whose error for exp(i w x) over one period is below 1e-38 for 20 points.

    Returns
    -------
    (list of mpf, list of mpf)
    """
    lower, upper = mpmath.mpf(lower), mpmath.mpf(upper)
    pieces = max(4, int(math.ceil(float(upper - lower) * float(max_frequency) / (2 * math.pi))))
    x, w = _gl_rule(points, mpmath.mp.dps)
    h = (upper - lower) / pieces
    nodes, weights = [], []
    for k in range(pieces):
        mid = lower + (k + mpmath.mpf(1) / 2) * h
        for xi, wi in zip(x, w, strict=True):
            nodes.append(mid + xi * h / 2)
            weights.append(wi * h / 2)
    return nodes, weights


class Nodes:
    """GL nodes on [lower, upper] with cached J1(lam r) values at every node."""

    def __init__(self, lower, upper, max_frequency):
        self.nodes, self.weights = gauss_legendre(lower, upper, max_frequency)
        self._j1 = {}
        self._j1_balls = {}
        self._arb_nodes = None
        self._arb_weight_list = None

    def j1(self, lam):
        """J1(lam r) at the nodes (mpf): python-flint (Arb) if importable, else mpmath."""
        key = mpmath.nstr(lam, 30)
        if key not in self._j1:
            if not ap.FLINT:  # pragma: no cover - without python-flint
                self._j1[key] = [mpmath.besselj(1, lam * r) for r in self.nodes]
            else:
                self._j1[key] = [ap.arb_to_mp(v) for v in self._j1_arb(lam)]
        return self._j1[key]

    def _j1_arb(self, lam):
        """J1(lam r) at the nodes as Arb balls at mpmath's precision + 5 digits (cached)."""
        key = (mpmath.nstr(lam, 30), mpmath.mp.dps)
        if key not in self._j1_balls:
            with ap.flint_dps(mpmath.mp.dps + 5):
                lam_arb = ap.mp_to_arb(lam)
                if self._arb_nodes is None:
                    self._arb_nodes = [ap.mp_to_arb(r) for r in self.nodes]
                self._j1_balls[key] = [(lam_arb * r).bessel_j(1) for r in self._arb_nodes]
        return self._j1_balls[key]

    def _arb_weights(self):
        if self._arb_weight_list is None:
            self._arb_weight_list = [ap.mp_to_arb(w) for w in self.weights]
        return self._arb_weight_list

    def integral(self, values):
        return mpmath.fsum(w * v for w, v in zip(self.weights, values, strict=True))

    def integral_of_j1(self, lams, polynomial):
        """The rule applied to p(r) prod_k J1(lam_k r), p(r) = sum_j polynomial[j] r^j (mpf).

        In Arb when python-flint is importable: the sum of the weighted products is formed in
        balls at mpmath's precision + 5 digits (no mpf product per node) and rounded once; else
        as ``integral`` over mpf values.
        """
        coefficients = [mpmath.mpf(c) for c in polynomial]
        if not ap.FLINT:  # pragma: no cover - without python-flint
            factors = [self.j1(lam) for lam in lams]
            values = []
            for i, r in enumerate(self.nodes):
                value = _horner(coefficients, r)
                for factor in factors:
                    value *= factor[i]
                values.append(value)
            return self.integral(values)
        with ap.flint_dps(mpmath.mp.dps + 5):
            factors = [self._j1_arb(lam) for lam in lams]
            weights = self._arb_weights()
            c = [ap.mp_to_arb(x) for x in coefficients]
            total = ap.flint.arb(0)
            for i, r in enumerate(self._arb_nodes):
                value = _horner(c, r) * weights[i]
                for factor in factors:
                    value *= factor[i]
                total += value
        return ap.arb_to_mp(total)


def _horner(coefficients, r):
    """sum_j coefficients[j] r^j by Horner's rule (mpf or arb alike)."""
    value = coefficients[-1]
    for coefficient in reversed(coefficients[:-1]):
        value = value * r + coefficient
    return value
