r"""Frictional work of a monotonic loading from the Abel-Fredholm solution.

Units: r, t in a; energies in (f p0)^2 a^3 / mu; T* = 2T/(f F a).

During a monotonic loading every slipping point carries the friction limit, traction 1
(eq. 8), and its slip grows monotonically, so the work done against friction up to the
state of stick radius b is

    W_mono = 2 pi int_0^1 q ds r dr = 2 pi int_b^1 s(r) r dr = 4 pi int_b^1 u(r, 0) r dr.   (W1)

With the slip formula (F7) of ``solvers.abel_fredholm``,
u(r, 0) = (2/(pi r)) int_b^r t D(t) / sqrt(r^2 - t^2) dt, the order of integration can be
exchanged (int_t^1 dr / sqrt(r^2 - t^2) = arcsech t):

    W_mono = 8 int_b^1 t D(t) arcsech(t) dt.                                              (W2)

D is smooth on [b, 1] in psi = arccos t (the corner r = 1 gives sqrt(1 - t) terms,
analytic in psi), and so is arcsech(cos psi) = artanh(sin psi); near t -> 0 (small stick
discs) both carry t ln t terms, which panels graded geometrically toward t = b resolve.
(W2) needs D at about 50-150 points and no slip profile; ``tests/test_curves.py`` checks it
against the direct quadrature of the slip (W1) and against the torque-twist route of
``curves.interpolant`` (loop area).
"""

from __future__ import annotations

import math

import numpy as np

from ..quadrature import gauss_legendre
from ..solvers import kernels
from ..solvers.abel_fredholm import AbelFredholmSolution

__all__ = ["abel_fredholm_loading_work"]

#: Gauss-Legendre nodes on psi in [0, min(pi/3, arccos b)] and per graded panel in t.
_PSI_NODES = 64
_T_NODES = 24
#: Ratio of the geometric panels toward a small stick disc.
_GRADING = 4.0


def _rule(b: float):
    """Nodes t in [b, 1] and weights for int dt (psi-Gauss near t = 1, graded panels near t = b)."""
    x, w = gauss_legendre(_PSI_NODES)
    top = min(math.pi / 3.0, math.acos(b))
    psi = 0.5 * top * (x + 1.0)
    nodes, weights = [np.cos(psi)], [0.5 * top * w * np.sin(psi)]
    if b < 0.5:
        edges = [b]
        while edges[-1] * _GRADING < 0.5:
            edges.append(edges[-1] * _GRADING)
        edges.append(0.5)
        xt, wt = gauss_legendre(_T_NODES)
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            nodes.append(0.5 * (hi - lo) * (xt + 1.0) + lo)
            weights.append(0.5 * (hi - lo) * wt)
    return np.concatenate(nodes), np.concatenate(weights)


def abel_fredholm_loading_work(solution: AbelFredholmSolution) -> float:
    """W_mono of (W2) for one Abel-Fredholm solution ((f p0)^2 a^3 / mu).

    0 at slip onset (b = 1); +inf at spinning (b = 0: unbounded slip).
    """
    b = solution.stick_radius
    if b >= 1.0:
        return 0.0
    if b <= 0.0:
        return math.inf
    t, w = _rule(b)
    d = solution._d_function(t)  # noqa: SLF001 - D(t) of (F7), evaluated directly (no interpolant)
    return float(8.0 * np.sum(w * t * d * kernels.arcsech(t)))
