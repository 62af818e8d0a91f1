"""The Nystrom system of the Abel-Fredholm method: nodes, the kernel P and the two solves of (F2).

Units and equations (F1)-(F8) as in ``solvers.abel_fredholm``, which closes this system by the
regularity condition g(b) = 0 (F3); ``solvers.limit_problem`` closes it by omega = 0 instead.
Nodes: Gauss-Legendre in theta, t = b cos(theta), their number from the image singularity of P
(``default_nodes``); Chebyshev points in the variable Y of (F8) for the series of G.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..criteria import GROSS_SLIP_TORQUE
from ..quadrature import gauss_legendre
from . import kernels
from .interface import log_gap

__all__ = ["StickSystem", "stick_system", "default_nodes", "chebyshev_points", "gauss_theta", "MAX_CHEBYSHEV"]

#: Most Chebyshev terms of the series of G in the variable Y of (F8).
MAX_CHEBYSHEV = 512
#: Half-width (in ln(1 - t^2)) of the strip in which G is analytic, a safe lower bound.
_STRIP_HALF_WIDTH = 1.3
_TARGET_DIGITS = math.log(1e17)


def default_nodes(stick_radius: float) -> int:
    """Nystrom nodes for ~1e-14 accuracy, from the image singularity of P (see module).

    In theta in [0, pi/2] the singularity nearest to the interval is at
    theta_s = i arccosh((2 - b)/b); with the Bernstein-ellipse parameter rho of theta_s,
    Gauss-Legendre converges like rho^(-2n).
    """
    b = float(stick_radius)
    # arccosh((2 - b)/b) = 2 arcsinh(sqrt((1 - b)/b)): no overflow for tiny b
    height = 2.0 * math.asinh(math.sqrt(1.0 - b) / math.sqrt(b)) / (math.pi / 4.0)
    z = complex(-1.0, height)
    root = np.sqrt(z * z - 1.0)
    rho = max(abs(z + root), abs(z - root))
    n = math.ceil(1.15 * _TARGET_DIGITS / (2.0 * math.log(rho))) + 6
    return max(16, n)


def chebyshev_points(b: float) -> int:
    """Chebyshev points in Y of (F8) for ~1e-16 decay of the series of G.

    G is analytic in a strip |Im ln(1 - t^2)| < ~1.3 (from Re t < 1); over the interval
    of length |ln(1 - b^2)| mapped to [-1, 1] that is a Bernstein ellipse of parameter
    rho = eta + sqrt(1 + eta^2), eta = 2.6 / |ln(1 - b^2)|.
    """
    eta = 2.0 * _STRIP_HALF_WIDTH / float(-log_gap(b))
    rho = eta + math.sqrt(1.0 + eta * eta)
    return min(MAX_CHEBYSHEV, max(12, math.ceil(_TARGET_DIGITS / math.log(rho)) + 8))


def gauss_theta(n: int):
    x, w = gauss_legendre(n)
    return np.pi / 4.0 * (x + 1.0), np.pi / 4.0 * w


@dataclass(frozen=True)
class StickSystem:
    """The Nystrom solution of (F2) for the two right-hand sides of Omega and of the rest.

    ``density_rotation`` and ``density_constant`` are g_1 and g_0 at the nodes (g = Omega g_1 + g_0),
    ``edge_rotation`` and ``edge_constant`` their values at t = b (so g(b) = Omega g_1(b) + g_0(b)),
    ``kernel`` P of (A2) between every point (nodes, b, Chebyshev points of (F8)) and the nodes, ``side``
    R(t) there, ``column`` the nodes' weights times t.  Units as in the module docstring.
    """

    stick_radius: float
    nodes: np.ndarray
    weights: np.ndarray
    kernel: np.ndarray
    side: np.ndarray
    column: np.ndarray
    density_rotation: np.ndarray
    density_constant: np.ndarray
    edge_rotation: float
    edge_constant: float
    xi: np.ndarray
    xi_weights: np.ndarray
    span: float
    n_cheb: int
    t_cheb: np.ndarray

    def torque(self, omega_big: float) -> float:
        """T* of (F4) for the rotation constant Omega (any Omega: (F3) is not imposed)."""
        density = omega_big * self.density_rotation + self.density_constant
        moment = np.sum(self.weights * self.nodes**2 * density)
        deficit = GROSS_SLIP_TORQUE * self.stick_radius**3 - 16.0 / np.pi * moment
        return float(GROSS_SLIP_TORQUE - deficit)


def stick_system(b: float, n: int) -> StickSystem:
    """Assemble and solve the Nystrom system of (F2) at stick radius ``b`` (0 < b < 1) with ``n`` nodes."""
    xi, w_xi = kernels.xi_grid(1.0 - b)
    theta, w_theta = gauss_theta(n)
    t = b * np.cos(theta)
    wt = b * np.sin(theta) * w_theta
    sin_theta = np.sin(theta)
    log_l = np.log1p(np.sqrt((1.0 - t) * (1.0 + t))) - np.log(b) - np.log1p(sin_theta)

    # Chebyshev points of the first kind in Y of (F8) for the series of G
    span = float(-log_gap(b))  # |ln(1 - b^2)|
    n_cheb = chebyshev_points(b)
    y_cheb = np.cos(np.pi * (np.arange(n_cheb) + 0.5) / n_cheb)
    t_cheb = np.sqrt(-np.expm1(-0.5 * (y_cheb + 1.0) * span))
    points = np.concatenate([t, [b], t_cheb])
    # 1 - t without the rounding of t (it sets the kernel near t + s = 2 when b ~ 1)
    gaps = np.concatenate([(1.0 - b) + 2.0 * b * np.sin(0.5 * theta) ** 2, [1.0 - b],
                           np.exp(-0.5 * (y_cheb + 1.0) * span) / (1.0 + t_cheb)])
    a_t = kernels.sinh_excess_scaled(xi, points, gaps)
    y_t = kernels.linear_scaled(xi, points)
    ratio = w_xi * kernels.bessel_ratio_scaled(xi)
    a_s, y_s = a_t[:n], y_t[:n]
    p = (2.0 / np.pi) * ((a_t * ratio) @ (a_s + y_s).T + (y_t * ratio) @ a_s.T)
    full_1, excess_1 = kernels.load_profiles(1.0, xi)
    full_b, excess_b = kernels.load_profiles(b, xi)
    r_side = (2.0 / np.pi) * (a_t @ (ratio * (full_1 - full_b)) + y_t @ (ratio * (excess_1 - excess_b)))

    column = wt * t
    matrix = np.eye(n) + (2.0 / np.pi) * (p[:n] / t[:, None]) * column[None, :]
    rhs = np.column_stack([np.full(n, 2.0), -log_l - r_side[:n] / t])
    g = np.linalg.solve(matrix, rhs)
    edge = (2.0 / np.pi) * (p[n] * column) / b
    g_b1 = 2.0 - edge @ g[:, 0]
    g_b0 = -float(kernels.arcsech(b)) - r_side[n] / b - edge @ g[:, 1]
    return StickSystem(stick_radius=b, nodes=t, weights=wt, kernel=p, side=r_side, column=column,
                       density_rotation=g[:, 0],
                       density_constant=g[:, 1], edge_rotation=float(g_b1), edge_constant=float(g_b0), xi=xi,
                       xi_weights=w_xi, span=span, n_cheb=n_cheb, t_cheb=t_cheb)
