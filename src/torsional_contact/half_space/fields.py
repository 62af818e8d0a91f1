r"""Displacement and stresses inside the twisted half-spaces: quadrature of Reissner-Sagoci fields.

Units: r, z in a; stresses in f p0; displacements in f p0 a / mu (mu = f p0 = a = 1 below).

Eq. (H10) of ``half_space.closed_form`` writes the upper body's field as a superposition
over disc radii c = cos(psi), 0 <= psi <= psi_b = arccos b, of rigid-disc rotations:

    u(r, z)        = (r/pi)  int_0^psi_b G(xi)                               dpsi / cos(psi),
    sigma_zt(r, z) = (2r/pi) int_0^psi_b eta / (c (1 + xi^2)(xi^2 + eta^2))       dpsi / cos(psi),
    sigma_rt(r, z) = (2r/pi) int_0^psi_b rho xi / (c (1 + xi^2)^2 (xi^2 + eta^2)) dpsi / cos(psi),

G(xi) = arctan(xi) + xi/(1 + xi^2), (xi, eta) the oblate spheroidal coordinates of
(rho, zeta) = (r/c, z/c): xi^2 and -eta^2 are the roots of X^2 - (rho^2 + zeta^2 - 1) X -
zeta^2 = 0, each taken from the root without cancellation.  Every integrand is positive.

Quadrature: for z > 0 the integrands are analytic in psi except near the disc whose edge
passes close to the point (c ~ r, at distance ~ z) and, for small stick discs, near the
pole of 1/cos(psi) at c = 0 (distance b).  The rule is composite Gauss-Legendre
(``PANEL_NODES`` per panel) on panels whose edges are c = r +- z 4^k (geometric toward the
edge, clipped to [b, 1]) and c = b 4^k (toward a small stick disc), mapped to psi and
split to at most ``MAX_PANEL`` rad: each panel sees its nearest singularity at least about
its own width away, so the rule converges geometrically (measured: 1e-14 against mpmath,
tests/test_half_space.py).  On z = 0 the interface closed forms (H7)-(H9) are used instead.
At b = 0 (spinning) the displacement is infinite (the far field turns without bound); the
stresses stay finite (the integrands vanish like c^2 as c -> 0; panels down to c = 1e-12).
"""

from __future__ import annotations

import math

import numpy as np

from ..quadrature import gauss_legendre

__all__ = ["displacement", "stress", "spheroidal", "PANEL_NODES", "MAX_PANEL"]

#: Gauss-Legendre nodes per panel.
PANEL_NODES = 20
#: Widest panel in psi (rad).
MAX_PANEL = 0.2
#: Smallest c of the grading toward c = 0 at spinning (below it the stress integrands are < 1e-24).
SPIN_CUTOFF = 1e-12


def spheroidal(rho, zeta):
    """Oblate spheroidal (xi, eta) of the point (rho, zeta) for the unit disc, xi >= 0, eta >= 0."""
    rho, zeta = np.asarray(rho, dtype=float), np.asarray(zeta, dtype=float)
    p = (rho - 1.0) * (rho + 1.0) + zeta * zeta
    root = np.hypot(p, 2.0 * zeta)
    positive = p >= 0
    big = np.where(positive, p + root, root - p)  # 2 xi^2 (p >= 0) or 2 eta^2 (p < 0), no cancellation
    small = np.divide(2.0 * zeta * zeta, big, out=np.zeros_like(big), where=big > 0)  # the other one, x 1
    xi2 = np.where(positive, 0.5 * big, small)
    eta2 = np.where(positive, small, 0.5 * big)
    return np.sqrt(xi2), np.sqrt(eta2)


def _rule(r: float, z: float, b: float):
    """Nodes psi and weights (for int dpsi) on [0, psi_b] for the point (r, z), z > 0."""
    lower = max(b, SPIN_CUTOFF) if b <= 0.0 else b
    cuts = {lower, 1.0}
    centre = min(max(r, lower), 1.0)
    step = z
    while step < 1.0:
        for c in (centre - step, centre + step):
            if lower < c < 1.0:
                cuts.add(c)
        step *= 4.0
    c = 4.0 * lower
    while c < 1.0:
        cuts.add(c)
        c *= 4.0
    psi = np.sort(np.arccos(np.clip(np.array(sorted(cuts)), 0.0, 1.0)))
    edges = [psi[0]]
    for hi in psi[1:]:
        lo = edges[-1]
        n = max(1, math.ceil((hi - lo) / MAX_PANEL))
        edges.extend(lo + (hi - lo) * np.arange(1, n + 1) / n)
    edges = np.array(edges)
    x, w = gauss_legendre(PANEL_NODES)
    half = 0.5 * np.diff(edges)
    mid = 0.5 * (edges[:-1] + edges[1:])
    return (mid[:, None] + half[:, None] * x[None, :]).ravel(), (half[:, None] * w[None, :]).ravel()


def _integrate(r, z, b: float, integrand):
    """int_0^psi_b integrand(r, z, c) dpsi / cos(psi) at every point (r, z > 0), flattened."""
    out = np.empty(r.size)
    for k in range(r.size):
        psi, w = _rule(float(r[k]), float(z[k]), b)
        c = np.cos(psi)
        out[k] = np.sum(w * integrand(float(r[k]), float(z[k]), c) / c)
    return out


def _displacement_integrand(r, z, c):
    xi, _ = spheroidal(r / c, z / c)
    return np.arctan(xi) + xi / (1.0 + xi * xi)


def _zt_integrand(r, z, c):
    xi, eta = spheroidal(r / c, z / c)
    return eta / (c * (1.0 + xi * xi) * (xi * xi + eta * eta))


def _rt_integrand(r, z, c):
    xi, eta = spheroidal(r / c, z / c)
    return (r / c) * xi / (c * (1.0 + xi * xi) ** 2 * (xi * xi + eta * eta))


def displacement(r, z, b: float):
    """u_theta(r, z) of the upper half-space for z > 0 (flat arrays), eq. (H10); +inf at b = 0, r > 0."""
    r, z = np.asarray(r, dtype=float), np.asarray(z, dtype=float)
    if b >= 1.0:
        return np.zeros(r.size)
    if b <= 0.0:
        return np.where(r > 0, math.inf, 0.0)
    return (r / np.pi) * _integrate(r, z, b, _displacement_integrand)


def stress(r, z, b: float):
    """(sigma_zt, sigma_rt)(r, z) of the upper half-space for z > 0 (flat arrays), from (H10)."""
    r, z = np.asarray(r, dtype=float), np.asarray(z, dtype=float)
    if b >= 1.0:
        return np.zeros(r.size), np.zeros(r.size)
    scale = 2.0 * r / np.pi
    return scale * _integrate(r, z, b, _zt_integrand), scale * _integrate(r, z, b, _rt_integrand)
