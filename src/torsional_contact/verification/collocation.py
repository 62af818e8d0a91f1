r"""Independent check of the Abel-Fredholm method: collocation of the first-kind stick equation.

Units (docs/conventions.md): r, rho in a; tractions in f p0; omega in f p0 / mu.

Method
------
No Abel transform: the stick condition is imposed on the displacement itself, with the
cylinder's Dini kernel in the closed form (K4) of ``solvers.kernels``,

    int_0^1 G(r, rho) q(rho) rho drho = omega r,   0 < r < b,
    G = G_hs + G_c - 4 BETA r rho,                                              (D1)

(G annihilates the torque load rho, so the T* r part of the traction drops out and
omega is the far-field rotation directly).  q = 1 on (b, 1).  On the stick disc the
traction is sought as

    q(rho) = (2/pi) arctan[rho sqrt(1 - b^2) / sqrt(b^2 - rho^2)]
             + rho sqrt(b^2 - rho^2) sum_k a_k T_k(2 rho^2/b^2 - 1),            (D2)

a regular traction (continuous, q(b) = 1, no (b - rho)^(-1/2) term): the first term is
the stick-side trace of the slip-zone load on a half-space, the second a Galin-type
basis (traction rho (b^2 - rho^2)^(-1/2) P(rho^2) gives a displacement r Q(r^2) on
a half-space disc).  The unknowns a_k and omega are found by least squares on
collocation points in (0, b); since a regular solution exists for exactly one T*,
the residual vanishes only at the physical solution, and T* = 4 int_0^1 q r^2 dr.

The kernel integrals are computed by brute force: composite Gauss-Legendre graded
geometrically toward the logarithmic singularity of G_hs at rho = r and the square-root
end point rho = b, with G_hs from complete elliptic integrals and G_c by its own
xi-quadrature (``kernels.cylinder_kernel``, I1-based, not the sinh-based kernels that
``solvers.abel_fredholm`` uses).  Slow (several seconds per radius) and meant for verification.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.polynomial import chebyshev, legendre

from ..solvers import kernels

__all__ = ["DirectSolution", "solve_direct"]

_PANEL = 20
_LEVELS = 28


@dataclass(frozen=True)
class DirectSolution:
    """Result of ``solve_direct``: T*, omega, the coefficients a_k of (D2), residual."""

    stick_radius: float
    torque: float
    rigid_rotation: float
    coefficients: np.ndarray
    residual: float

    def interface_traction(self, r):
        """sigma_zt(r, 0) from (D2) (1 on the slip annulus)."""
        r = np.asarray(r, dtype=float)
        out = np.ones_like(r)
        inside = r < self.stick_radius
        out[inside] = _traction(r[inside], self.stick_radius, self.coefficients)
        return out


@functools.cache
def _gauss_legendre(n):
    """Gauss-Legendre nodes and weights on [-1, 1] (computed once per n; read-only)."""
    x, w = legendre.leggauss(n)
    x.flags.writeable = False
    w.flags.writeable = False
    return x, w


def _gauss(a, b, n=_PANEL):
    x, w = _gauss_legendre(n)
    return 0.5 * (b - a) * (x + 1.0) + a, 0.5 * (b - a) * w


def _graded(a, b, toward_a, levels=_LEVELS):
    """Composite Gauss on [a, b], panels halving toward a (toward_a) or b."""
    nodes, weights = [], []
    length = b - a
    for k in range(levels):
        lo = 0.0 if k == levels - 1 else length * 2.0 ** -(k + 1)
        x, w = _gauss(lo, length * 2.0**-k)
        nodes.append(a + x if toward_a else b - x)
        weights.append(w)
    return np.concatenate(nodes), np.concatenate(weights)


def _edge_term(rho, b):
    return (2.0 / np.pi) * np.arctan2(rho * math.sqrt(1.0 - b * b), np.sqrt((b - rho) * (b + rho)))


def _basis(rho, b, m):
    shape = rho * np.sqrt((b - rho) * (b + rho))
    return shape[:, None] * chebyshev.chebvander(2.0 * (rho / b) ** 2 - 1.0, m - 1)


def _traction(rho, b, coefficients):
    return _edge_term(rho, b) + _basis(rho, b, coefficients.size) @ coefficients


def _kernel(r, rho):
    return (
        kernels.halfspace_kernel(r, rho)
        + kernels.cylinder_kernel(r, rho)
        - 4.0 * kernels.TORQUE_ROTATION * r * rho
    )


def _rules(r, b):
    """Quadrature on (0, b) and (b, 1) resolving the singularities of G(r, .) q rho."""
    mid = 0.5 * (r + b)
    left = _graded(0.0, r, toward_a=False)
    right = _graded(r, mid, toward_a=True)
    end = _graded(mid, b, toward_a=False)  # sqrt(b - rho) at b
    rho, w = (np.concatenate(parts) for parts in zip(left, right, end, strict=True))
    keep = rho != r  # a node rounded onto the log singularity (never for these gradings)
    stick = rho[keep], w[keep]
    slip = _graded(b, 1.0, toward_a=True)  # log(rho - r) when r is near b
    return stick, slip


def solve_direct(stick_radius: float, n_basis: int = 14, n_points: int | None = None) -> DirectSolution:
    """Least-squares collocation of (D1) with the regular traction (D2).

    Parameters
    ----------
    stick_radius : float
        b/a in (0, 1); intended for 0.05 <= b <= 0.95 (the quadrature is not adapted to
        smaller discs or narrower annuli).
    n_basis : int
        Number of Galin-type basis functions a_k.
    n_points : int, optional
        Collocation points (Chebyshev in r^2 on (0, b)); default 2 n_basis + 4.

    Returns
    -------
    DirectSolution
    """
    b = float(stick_radius)
    if not 0.0 < b < 1.0:
        raise ValueError(f"stick_radius must lie in (0, 1), got {stick_radius!r}")
    m = int(n_basis)
    count = 2 * m + 4 if n_points is None else int(n_points)
    x = np.cos(np.pi * (np.arange(count) + 0.5) / count)
    points = b * np.sqrt(0.5 * (1.0 + x))
    matrix = np.empty((count, m + 1))
    rhs = np.empty(count)
    for i, r in enumerate(points):
        (rho, w), (rho_s, w_s) = _rules(r, b)
        kernel = _kernel(r, rho) * rho * w
        matrix[i, :m] = kernel @ _basis(rho, b, m)
        matrix[i, m] = -r
        rhs[i] = -(kernel @ _edge_term(rho, b)) - (_kernel(r, rho_s) * rho_s) @ w_s
    scale = 1.0 / points  # the equation is O(r) at small r
    solution, *_ = np.linalg.lstsq(matrix * scale[:, None], rhs * scale, rcond=None)
    residual = float(np.max(np.abs(matrix @ solution - rhs) * scale))
    coefficients, omega = solution[:m], float(solution[m])
    theta, w_theta = _gauss(0.0, 0.5 * np.pi, 80)
    rho = b * np.cos(theta)
    moment = np.sum(b * np.sin(theta) * w_theta * rho**2 * _traction(rho, b, coefficients))
    torque = 4.0 * (moment + (1.0 - b**3) / 3.0)
    return DirectSolution(b, float(torque), omega, coefficients, residual)
