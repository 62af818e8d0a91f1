r"""Quadratures of the Abel-Fredholm interface formulas: traction (F6)/(F9), slip (F7), sigma_rt.

Units: r, t in a; tractions and stresses in f p0; displacements in f p0 a / mu.  Pure
functions of the stick radius b and of the series that ``solvers.abel_fredholm`` builds
(the equations are stated in that module's docstring).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial import chebyshev

from ..quadrature import gauss_legendre
from . import kernels

__all__ = ["log_gap", "chebyshev_coefficients", "stick_traction", "slip_integral", "face_shear",
           "face_shear_from_slip_integrand", "INNER_EXTRA", "SLIP_PANEL_NODES", "SIGMA_RT_NODES"]

#: Gauss nodes of the inner rule of (F9) beyond the number of Chebyshev terms of G_Y.
INNER_EXTRA = 32
#: Gauss-Legendre nodes per panel of the slip quadrature (F7).
SLIP_PANEL_NODES = 40
#: Gauss-Legendre nodes per half of the phi-integral of ``face_shear``.
SIGMA_RT_NODES = 48
_CHUNK_ENTRIES = 500_000  # points x inner nodes evaluated at once in (F9)


def log_gap(t):
    """ln(1 - t^2) for 0 <= t < 1, without cancellation near t = 1 (the variable of F8)."""
    t = np.asarray(t, dtype=float)
    near = t > 0.5
    return np.where(near, np.log((1.0 - t) * (1.0 + t) + ~near), np.log1p(-t * t))


def chebyshev_coefficients(values, n: int):
    """Chebyshev coefficients from values at the first-kind points cos(pi (j + 1/2) / n)."""
    angles = np.pi * (np.arange(n) + 0.5) / n
    c = (2.0 / n) * (np.cos(np.outer(np.arange(n), angles)) @ values)
    c[0] *= 0.5
    return c


def stick_traction(r, b: float, span: float, derivative_series):
    """q(r) of (F6) for 0 < b < 1 by (F9): 1 on the slip annulus r >= b.

    ``span`` = |ln(1 - b^2)|, ``derivative_series``: Chebyshev coefficients of dG/dY in Y (F8).
    """
    r = np.asarray(r, dtype=float)
    flat = r.ravel()
    out = np.ones_like(flat)
    inside = np.nonzero(flat < b)[0]
    if inside.size:
        x_nodes, x_weights = gauss_legendre(derivative_series.size + INNER_EXTRA)
        chunk = max(1, _CHUNK_ENTRIES // x_nodes.size)
        for start in range(0, inside.size, chunk):
            idx = inside[start : start + chunk]
            rho = flat[idx]
            gap = log_gap(rho)  # ln(1 - rho^2)
            half = 0.5 * np.sqrt(np.maximum(gap + span, 0.0))  # sqrt(V) / 2 of (F9)
            w = half[:, None] * (x_nodes[None, :] + 1.0)
            y = -2.0 * (gap[:, None] - w * w) / span - 1.0
            factor = 2.0 * w / np.sqrt(-np.expm1(-w * w))
            integral = half * ((chebyshev.chebval(y, derivative_series) * factor) @ x_weights)
            integral *= 2.0 / (span * np.exp(0.5 * gap))
            height = np.sqrt((b - rho) * (b + rho))
            edge = (2.0 / np.pi) * np.arctan2(rho * math.sqrt((1.0 - b) * (1.0 + b)), height)
            out[idx] = edge - (2.0 / np.pi) * rho * integral
    return out.reshape(r.shape)


def slip_integral(r, b: float, d_of_psi):
    """u(r, 0+) = (2/(pi r)) int_b^r t D(t) / sqrt(r^2 - t^2) dt of (F7), 0 for r <= b (0 < b < 1).

    In psi = arccos t: a cosh substitution on the first panel [psi_r, 2 psi_r] removes the
    inverse square root at t = r; the next panels double away from psi_r and halve their
    distance to psi = pi/2 (t = 0, where D has the t ln t of arcsech, just beyond the edge
    of a small stick disc) down to 1e-6 (below, t^2 ln t contributes < 1e-18).
    ``d_of_psi`` evaluates D(cos psi).
    """
    r = np.asarray(r, dtype=float)
    flat = r.ravel()
    out = np.zeros_like(flat)
    psi_b = math.acos(b)
    x_nodes, x_weights = gauss_legendre(SLIP_PANEL_NODES)
    all_psi, all_weight, owner = [], [], []
    for index in np.nonzero(flat > b)[0]:
        radius = float(flat[index])
        psi_r = 2.0 * math.asin(math.sqrt(max(0.0, 1.0 - radius) / 2.0))
        lo = 0.0
        if psi_r > 0.0:
            top = min(2.0 * psi_r, psi_b, 0.5 * (psi_r + 0.5 * np.pi))
            excess = (top - psi_r) / psi_r
            if excess <= 0.0:  # r = b to rounding: no slip yet
                continue
            w_end = math.log1p(excess + math.sqrt(excess * (2.0 + excess)))  # arccosh(top / psi_r)
            wv = 0.5 * w_end * (x_nodes + 1.0)
            half = np.sinh(0.5 * wv)
            psi = psi_r * np.cosh(wv)
            gap = np.sin(2.0 * psi_r * half * half)  # sin(psi - psi_r)
            jac = psi_r * 2.0 * half * np.cosh(0.5 * wv) / np.sqrt(gap * np.sin(psi + psi_r))
            all_psi.append(psi)
            all_weight.append(0.5 * w_end * x_weights * jac * np.sin(psi) * np.cos(psi))
            owner.append(np.full(psi.size, index))
            lo = top
        while lo < psi_b:
            distance = 0.5 * np.pi - lo
            graded = lo + 0.5 * distance if distance > 2e-6 else psi_b
            hi = min(2.0 * lo if lo > 0.0 else 0.25 * np.pi, psi_b, graded)
            psi = 0.5 * (hi - lo) * (x_nodes + 1.0) + lo
            if psi_r > 0.0:
                factor = np.sin(psi) * np.cos(psi) / np.sqrt(np.sin(psi - psi_r) * np.sin(psi + psi_r))
            else:  # r = 1: sqrt(1 - t^2) = sin(psi) cancels
                factor = np.cos(psi)
            all_psi.append(psi)
            all_weight.append(0.5 * (hi - lo) * x_weights * factor)
            owner.append(np.full(psi.size, index))
            lo = hi
    if all_psi:
        psi = np.concatenate(all_psi)
        weight = np.concatenate(all_weight) * d_of_psi(psi)
        idx = np.concatenate(owner)
        sums = np.bincount(idx, weights=weight, minlength=flat.size)
        sel = flat > b
        out[sel] = 2.0 * sums[sel] / (np.pi * flat[sel])
    return out.reshape(r.shape)


def face_shear(r, b: float, correction_series):
    """sigma_rt(r, 0) = u' - u/r of (F7) for b < 1/2, without differences (f p0):

        sigma_rt = (2/pi) int_(phi_b)^(pi/2) sin^2(phi) [k(x) - x m'(x)] dphi,   x = r sin(phi),

    phi_b = arcsin(b/r) (D(b) = 0 by F3 removes the boundary term), k of
    ``kernels.spinning_shear_kernel``, m(t) = (mixed(t) - E_b(t))/t from
    ``correction_series`` (Chebyshev in t on [0, 1]).  The k-part is the spinning one (K5)
    minus its integral over [0, phi_b] (x <= b < 1/2, where k is smooth).  0 on the stick
    disc and at r = 1.
    """
    r = np.asarray(r, dtype=float)
    flat = r.ravel()
    out = np.zeros_like(flat)
    slipping = (flat > b) & (flat < 1.0)
    x_r = flat[slipping]
    if x_r.size:
        nodes, weights = gauss_legendre(SIGMA_RT_NODES)
        phi_b = np.arcsin(b / x_r)
        lower = 0.5 * phi_b[:, None] * (nodes[None, :] + 1.0)  # [0, phi_b]
        upper = phi_b[:, None] + 0.5 * (0.5 * np.pi - phi_b)[:, None] * (nodes[None, :] + 1.0)
        x_low, x_up = x_r[:, None] * np.sin(lower), x_r[:, None] * np.sin(upper)
        m_prime = 2.0 * chebyshev.chebval(2.0 * x_up - 1.0, chebyshev.chebder(correction_series))
        stick_part = 0.5 * phi_b * ((np.sin(lower) ** 2 * kernels.spinning_shear_kernel(x_low)) @ weights)
        rest = 0.5 * (0.5 * np.pi - phi_b) * ((np.sin(upper) ** 2 * x_up * m_prime) @ weights)
        out[slipping] = kernels.spinning_shear(x_r) - (2.0 / np.pi) * (stick_part + rest)
    return out.reshape(r.shape)


def face_shear_from_slip_integrand(r, b: float, d_and_slope_of_psi):
    """sigma_rt(r, 0) = du/dr - u/r of (F7) for any 0 < b < 1, from D and dD/dpsi (psi = arccos t):

        sigma_rt(r, 0) = (2/(pi r^2)) int_b^r t^2 E(t) / sqrt(r^2 - t^2) dt,   E = dD/dt - D/t,

    (t = r sin(phi) in (F7); the boundary term at phi_b vanishes since D(b) = 0 by F3), i.e.
    ``slip_integral`` with D replaced by t E(t) = -cos(psi) D_psi / sin(psi) - D, divided by r.
    ``d_and_slope_of_psi`` returns (D, D_psi) at psi.  D_psi vanishes at psi = 0 (t = 1: no
    sqrt(1 - t) term, or sigma_rt would grow like ln(1/(1 - r)) at the free side), so E is
    finite there.  0 on the stick disc and at r = 1 (eq. 9).
    """
    r = np.asarray(r, dtype=float)

    def integrand(psi):
        d, slope = d_and_slope_of_psi(psi)
        return -np.cos(psi) * slope / np.sin(psi) - d

    out = np.zeros(r.shape)
    inside = (r > b) & (r < 1.0)
    if np.any(inside):
        out[inside] = slip_integral(r[inside], b, integrand) / r[inside]
    return out
