r"""Derivatives for the formula checks, by mpmath numerical differentiation at the working precision.

Independent of the paper's algebra: Solution E (eq. 10) is applied to a potential by
differentiating it numerically, Laplacians are taken in Cartesian coordinates, and the
traction on r = a is computed from the Cartesian strain of the displacement field.
Coordinates are dimensional (a explicit); functions take and return mpf.
"""

from __future__ import annotations

import mpmath

__all__ = ["solution_e", "laplacian_cartesian", "lateral_traction"]


def solution_e(psi, mu, r, z):
    """(u_theta, sigma_rt, sigma_zt) of eq. (10) for psi(r, z), by mpmath.diff.

    2 mu u = -2 dpsi/dr, sigma_rt = (1/r) dpsi/dr - d2psi/dr2, sigma_zt = -d2psi/dr dz.
    """
    psi_r = mpmath.diff(psi, (r, z), (1, 0))
    psi_rr = mpmath.diff(psi, (r, z), (2, 0))
    psi_rz = mpmath.diff(psi, (r, z), (1, 1))
    return -psi_r / mu, psi_r / r - psi_rr, -psi_rz


def laplacian_cartesian(psi, r, z, angle="0.7"):
    """Laplacian of the axisymmetric psi(r, z) at (r, angle, z), from x, y, z derivatives.

    Independent of the cylindrical form d2/dr2 + (1/r) d/dr + d2/dz2 used by the paper.
    """
    phi = mpmath.mpf(angle)
    x0, y0 = r * mpmath.cos(phi), r * mpmath.sin(phi)

    def f(x, y, zz):
        return psi(mpmath.sqrt(x * x + y * y), zz)

    return sum(mpmath.diff(f, (x0, y0, z), order) for order in ((2, 0, 0), (0, 2, 0), (0, 0, 2)))


def lateral_traction(u_theta, mu, radius, z, angle="0.4"):
    """Traction (t_r, t_theta, t_z) on the surface r = radius of the torsion field u_theta(r, z).

    The displacement (-u sin phi, u cos phi, 0) is differentiated in Cartesian coordinates and
    sigma = 2 mu eps + lambda tr(eps) I; the trace is returned too: it is zero for a torsion
    field, so the Lame constant lambda does not enter.  Returns (t_r, t_theta, t_z, tr eps).
    """
    phi = mpmath.mpf(angle)
    point = (radius * mpmath.cos(phi), radius * mpmath.sin(phi), z)

    def component(i):
        def f(x, y, zz):
            rr = mpmath.sqrt(x * x + y * y)
            u = u_theta(rr, zz)
            return (-u * y / rr, u * x / rr, mpmath.mpf(0))[i]

        return f

    grad = [[mpmath.diff(component(i), point, tuple(int(k == j) for k in range(3))) for j in range(3)]
            for i in range(3)]  # grad[i][j] = d u_i / d x_j
    eps = [[(grad[i][j] + grad[j][i]) / 2 for j in range(3)] for i in range(3)]
    normal = (mpmath.cos(phi), mpmath.sin(phi), mpmath.mpf(0))
    tangent = (-mpmath.sin(phi), mpmath.cos(phi), mpmath.mpf(0))
    traction = [2 * mu * sum(eps[i][j] * normal[j] for j in range(3)) for i in range(3)]
    t_r = sum(traction[i] * normal[i] for i in range(3))
    t_theta = sum(traction[i] * tangent[i] for i in range(3))
    return t_r, t_theta, traction[2], eps[0][0] + eps[1][1] + eps[2][2]
