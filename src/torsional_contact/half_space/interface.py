"""Interface fields of the twisted half-spaces: traction (H7), slip (H8), sigma_rt (H9).

Units: r in a; tractions and stresses in f p0; slip in f p0 a / mu; positive torque.  The
equations and their derivation are in ``half_space.closed_form``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from ..quadrature import gauss_legendre
from ..solvers import interface
from .closed_form import _rotation_from_angles, angles_from_radius

__all__ = ["interface_traction", "interface_slip", "interface_sigma_rt"]

#: Gauss nodes of (H9) for r^2 < 1/2 (smooth integrand, no cancellation).
_SHEAR_NODES = 40


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

    r^2 < 1/2: Gauss-Legendre on the positive integrand (smooth there); r^2 >= 1/2: the
    incomplete elliptic integrals F, E (no cancellation there), K(m) from 1 - m = (1 - r)(1 + r).
    """
    r = np.asarray(r, dtype=float)
    flat = r.ravel()
    out = np.zeros_like(flat)
    if b >= 1.0:
        return out.reshape(r.shape)
    slipping = flat > b
    edge = slipping & (flat >= 1.0)
    out[edge] = math.inf
    inner = slipping & ~edge & (flat * flat < 0.5)
    outer = slipping & ~edge & ~inner
    if inner.any():
        x, w = gauss_legendre(_SHEAR_NODES)
        ri = flat[inner]
        phi_b = np.arcsin(np.minimum(b / ri, 1.0))
        half = 0.5 * (0.5 * np.pi - phi_b)
        phi = phi_b[:, None] + half[:, None] * (x[None, :] + 1.0)
        s2 = np.sin(phi) ** 2
        out[inner] = (2.0 / np.pi) * half * ((s2 / np.sqrt(1.0 - ri[:, None] ** 2 * s2)) @ w)
    if outer.any():
        ro = flat[outer]
        m = ro * ro
        m1 = (1.0 - ro) * (1.0 + ro)
        phi_b = np.arcsin(np.minimum(b / ro, 1.0))
        complete = special.ellipkm1(m1) - special.ellipe(m)
        partial = special.ellipkinc(phi_b, m) - special.ellipeinc(phi_b, m)
        out[outer] = (2.0 / np.pi) * (complete - partial) / m
    return out.reshape(r.shape)
