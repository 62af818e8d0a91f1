r"""The limit problem of the printed series: no rigid rotation, a traction singular at r = b.

Units (docs/conventions.md): r, t in a; tractions in f p0; omega in f p0 / mu; T* = 2T/(f F a).

The printed representation (21) of the interface displacement has no rigid-rotation member, so
every printed solution has omega = 0 (its moment int_0^1 u r^2 dr vanishes).  As the number of
terms grows, the printed scheme closed by the stick condition at the front (C2) or by the torque of
the traction present (C3) drives the rigid slip alpha of the stick disc to zero: it tends to the
problem

    u(r, 0) = 0 on 0 <= r < b,   q = 1 on b < r <= 1,   omega = 0,

which fixes T* without the regularity condition (F3), so that its stick-side traction has an
inverse-square-root singularity at r = b.  In the Abel-Fredholm formulation
(``solvers.abel_fredholm``, equations (F1)-(F5)) omega = 0 means Omega = BETA T*; the density is
g = Omega g_1 + g_0 (F2) and (F4) is linear in T*:

    T* [1 - (16/pi) BETA S_1] = (4/3)(1 - b^3) + (16/pi) S_0,   S_k = int_0^b s^2 g_k(s) ds.   (L1)

The traction behaves like C_b (b - rho)^(-1/2) as rho -> b^-, with C_b = sqrt(2 b) g(b) / pi
(paper, Appendix A), g(b) = Omega g_1(b) + g_0(b).                                             (L2)

Same Nystrom discretisation as the regular solution (geometric convergence in the nodes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import kernels
from .abel_fredholm import MAX_NODES, default_nodes, stick_system

__all__ = ["LimitSolution", "solve_without_rotation"]


@dataclass(frozen=True)
class LimitSolution:
    """Solution of the limit problem at one stick radius (units of the module docstring)."""

    stick_radius: float
    torque: float  #: T* of (L1)
    rotation_constant: float  #: Omega = BETA T*
    edge_coefficient: float  #: C_b of (L2): the traction ~ C_b (b - rho)^(-1/2) at the stick front


def solve_without_rotation(stick_radius: float, n_nodes: int | None = None) -> LimitSolution:
    """Solve the limit problem (omega = 0, no regularity at r = b) for ``stick_radius`` in (0, 1).

    ``n_nodes``: Nystrom nodes, in [2, MAX_NODES]; default that of the regular solution.
    """
    b = float(stick_radius)
    if not math.isfinite(b) or not 0.0 < b < 1.0:
        raise ValueError(f"stick_radius must be a finite number in (0, 1), got {stick_radius!r}")
    if n_nodes is not None and not 2 <= int(n_nodes) <= MAX_NODES:
        raise ValueError(f"n_nodes must be an integer in [2, {MAX_NODES}], got {n_nodes!r}")
    n = min(default_nodes(b), MAX_NODES) if n_nodes is None else int(n_nodes)
    system = stick_system(b, n)
    moment = system.weights * system.nodes**2
    s_rotation = float(np.sum(moment * system.density_rotation))
    s_constant = float(np.sum(moment * system.density_constant))
    beta = kernels.TORQUE_ROTATION
    torque = ((4.0 / 3.0) * (1.0 - b**3) + 16.0 / np.pi * s_constant) / (1.0 - 16.0 / np.pi * beta * s_rotation)
    omega_big = beta * torque
    g_edge = omega_big * system.edge_rotation + system.edge_constant
    return LimitSolution(stick_radius=b, torque=float(torque), rotation_constant=float(omega_big),
                         edge_coefficient=float(math.sqrt(2.0 * b) * g_edge / math.pi))
