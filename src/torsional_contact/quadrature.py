"""Gauss-Legendre rules shared by the solvers, the histories and the checks (double precision).

Lengths in the cylinder radius a.  The arbitrary-precision rules of the verification
wing are in ``verification/quadrature_mp.py``.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence

import numpy as np
from numpy.polynomial import legendre

__all__ = ["gauss_legendre", "gauss_legendre_panels", "PANEL_NODES"]

#: Nodes per panel of ``gauss_legendre_panels``.
PANEL_NODES = 32


def _legendre_and_derivative(n: int, x):
    """P_n(x) and P_n'(x) by the three-term recurrence (in the precision of ``x``)."""
    previous, current = np.ones_like(x), x.copy()
    for k in range(2, n + 1):
        previous, current = current, ((2 * k - 1) * x * current - (k - 1) * previous) / k
    return current, n * (x * current - previous) / (x * x - 1)


@functools.lru_cache(maxsize=64)
def gauss_legendre(n: int):
    """Read-only Gauss-Legendre nodes and weights on [-1, 1] (cached per ``n``).

    numpy's ``leggauss`` nodes, polished by Newton's method on the recurrence for P_n in
    extended precision (``np.longdouble``), and the weights 2 / ((1 - x^2) P_n'(x)^2)
    from the same recurrence: relative error ~1e-16 in the weights, where ``leggauss``
    (and scipy's ``roots_legendre``) are off by ~1e-11 at n = 150 and ~1e-9 at n = 450.
    """
    n = int(n)
    x, _ = legendre.leggauss(n)
    x = x.astype(np.longdouble)
    for _ in range(2):
        p, dp = _legendre_and_derivative(n, x)
        x = x - p / dp
    _, dp = _legendre_and_derivative(n, x)
    w = 2 / ((1 - x * x) * dp * dp)
    x, w = x.astype(float), w.astype(float)
    x = 0.5 * (x - x[::-1])  # exactly symmetric
    w = 0.5 * (w + w[::-1])
    x.flags.writeable = False
    w.flags.writeable = False
    return x, w


def gauss_legendre_panels(lower: float, upper: float, max_width: float, breakpoints: Sequence[float] = ()):
    """Nodes and weights of a composite Gauss-Legendre rule on [lower, upper].

    The interval is first split at the ``breakpoints`` inside it, then every piece
    into equal panels no wider than ``max_width``, each with ``PANEL_NODES`` nodes.

    Returns
    -------
    (nodes, weights) : tuple of ndarray
        Empty arrays when upper <= lower.
    """
    if upper <= lower:
        return np.empty(0), np.empty(0)
    cuts = sorted({lower, upper, *(float(x) for x in breakpoints if lower < x < upper)})
    x_ref, w_ref = gauss_legendre(PANEL_NODES)
    nodes, weights = [], []
    for a, b in zip(cuts[:-1], cuts[1:], strict=True):
        n_panels = max(1, math.ceil((b - a) / max_width))
        edges = np.linspace(a, b, n_panels + 1)
        half = 0.5 * np.diff(edges)
        mid = 0.5 * (edges[:-1] + edges[1:])
        nodes.append((mid[:, None] + half[:, None] * x_ref[None, :]).ravel())
        weights.append((half[:, None] * w_ref[None, :]).ravel())
    return np.concatenate(nodes), np.concatenate(weights)
