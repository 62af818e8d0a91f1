"""Interface fields of the twisted half-spaces: traction (H7), slip (H8), sigma_rt (H9).

Units: r in a; tractions and stresses in f p0; slip in f p0 a / mu; positive torque.  The
equations and their derivation are in ``half_space.closed_form``.
"""

from __future__ import annotations

import math

import numpy as np

from ..quadrature import gauss_legendre
from ..solvers import interface
from .closed_form import _rotation_from_angles, angles_from_radius

__all__ = ["interface_traction", "interface_slip", "interface_sigma_rt"]

#: Gauss nodes per panel and geometric panels of the (H9) quadrature.
_SHEAR_NODES = 16
_SHEAR_PANELS = 24


def interface_traction(r, b: float):
    """sigma_zt(r, 0) / (f p0): (H7) on the stick disc r < b, 1 on the annulus (positive torque)."""
    r = np.asarray(r, dtype=float)
    if b >= 1.0:
        return np.zeros_like(r)
    stick = r < b
    rs = np.where(stick, r, 0.0)
    height = np.sqrt(np.maximum((b - rs) * (b + rs), 0.0))
    inner = (2.0 / np.pi) * np.arctan2(rs * math.sqrt((1.0 - b) * (1.0 + b)), height)
    return np.where(stick, inner, 1.0)


def interface_slip(r, b: float):
    """s(r) = 2 u(r, 0+) (f p0 a / mu), eq. (H8): 0 on the stick disc, +inf for r > 0 at b = 0.

    The Abel integral with D(cos psi) = cos(psi) [artanh(sin psi_b) - artanh(sin psi)] by the
    quadrature of ``solvers.interface.slip_integral`` (cosh substitution at t = r, panels graded
    toward t = 0 for small stick discs); D is analytic in psi on [0, psi_b].
    """
    r = np.asarray(r, dtype=float)
    if b >= 1.0:
        return np.zeros_like(r)
    if b <= 0.0:
        return np.where(r > 0, math.inf, 0.0)
    psi_b, chi_b = angles_from_radius(b)
    level = 2.0 * float(_rotation_from_angles(psi_b, chi_b))  # artanh(sin psi_b) = arcsech b

    def d_of_psi(psi):
        return np.cos(psi) * (level - np.arcsinh(np.tan(psi)))

    return 2.0 * interface.slip_integral(r, float(b), d_of_psi)


def interface_sigma_rt(r, b: float):
    """sigma_rt(r, 0) / (f p0), eq. (H9): 0 on the stick disc, +inf at the contact edge r = 1.

    With theta = pi/2 - phi the integral of (H9) is (2/pi) int_0^theta_b cos^2(theta) /
    sqrt(sin^2(theta) + (1 - r^2) cos^2(theta)) dtheta, theta_b = arccos(b/r): a positive
    integrand peaked at theta = 0 over a width sqrt(1 - r^2).  Composite Gauss-Legendre
    (``_SHEAR_NODES`` per panel) on [0, w] and ``_SHEAR_PANELS`` panels geometric from
    w = min(sqrt(1 - r^2), theta_b) to theta_b: no cancellation, no special functions
    (the difference of complete and incomplete elliptic integrals lost 2e-12 next to r = b).
    """
    r = np.asarray(r, dtype=float)
    flat = r.ravel()
    out = np.zeros_like(flat)
    if b >= 1.0:
        return out.reshape(r.shape)
    out[flat >= 1.0] = math.inf
    slipping = (flat > b) & (flat < 1.0)
    x = flat[slipping]
    if x.size:
        gap = (1.0 - x) * (1.0 + x)
        theta_b = 2.0 * np.arcsin(np.sqrt((x - b) / (2.0 * x)))  # arccos(b/r) without cancellation
        width = np.minimum(np.sqrt(gap), theta_b)
        ratio = np.arange(_SHEAR_PANELS + 1) / _SHEAR_PANELS
        edges = np.concatenate([np.zeros((x.size, 1)), width[:, None] * (theta_b / width)[:, None] ** ratio], axis=1)
        nodes, weights = gauss_legendre(_SHEAR_NODES)
        half = 0.5 * np.diff(edges, axis=1)
        theta = 0.5 * (edges[:, :-1] + edges[:, 1:])[:, :, None] + half[:, :, None] * nodes
        c2, s2 = np.cos(theta) ** 2, np.sin(theta) ** 2
        values = c2 / np.sqrt(s2 + gap[:, None, None] * c2)
        out[slipping] = (2.0 / np.pi) * np.sum(half[:, :, None] * weights * values, axis=(1, 2))
    return out.reshape(r.shape)
