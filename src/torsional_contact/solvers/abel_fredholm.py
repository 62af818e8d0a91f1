r"""Fast, high-accuracy partial-slip solution: Abel reduction to a Fredholm equation.

Units (docs/conventions.md): r, t, s in a; tractions in f p0; displacements and slip in
f p0 a / mu; omega in f p0 / mu; T* = 2T/(f F a) (eq. 32).

Problem
-------
The upper cylinder carries u = T* r z + omega r + (Dini series, eq. 22); at z = 0 the
traction q(r) = du/dz satisfies q = 1 on the slip annulus b < r <= 1 (eq. 8) and
u(r, 0) = 0 on the stick disc 0 <= r < b (eq. 7).  With the Neumann-to-Dirichlet map
of ``solvers.kernels`` (K1-K3) and int_0^1 K(r, rho) rho^2 drho = BETA r, the stick condition
for the torque-free part q - T* r reads

    int_0^1 K(r, rho) q(rho) rho drho = Omega r,   0 <= r < b,   Omega = omega + BETA T*.   (F1)

Abel reduction
--------------
Let G(t) = int_t^1 q(rho) / sqrt(rho^2 - t^2) drho (eq. A1).  On t > b, G = arcsech(t)
(q = 1 there).  Write g(t) = int_t^b q / sqrt(rho^2 - t^2) drho = G(t) - L(t) for
t < b, L(t) = ln[(1 + sqrt(1 - t^2)) / (b + sqrt(b^2 - t^2))].  Applying S^{-1}
(``solvers.kernels``) to (F1) gives a Fredholm equation of the second kind on (0, b) with
the smooth kernel P of eq. (A2) (Copson; Sneddon's treatment of the Reissner-Sagoci
problem):

    g(t) + (2/(pi t)) int_0^b s g(s) P(t, s) ds = 2 Omega - L(t) - R(t) / t,
    R(t) = E_1(t) - E_b(t)           (the side correction due to q = 1 on (b, 1)).   (F2)

(The half-space kernel turns into the identity: S^{-1}[G_hs q] = t G(t).)  A
traction with a K (b - r)^(-1/2) singularity at r = b has g(b) = pi K / sqrt(2 b);
the regular solution (the stick-side traction rises continuously to 1)
is fixed by

    g(b) = 0,                                                                       (F3)

which determines Omega (g is linear in Omega: g = Omega g_1 + g_0).  Then, integrating
by parts against the Abel inverse q = -(2/pi) d/drho int_rho^1 s G(s) / sqrt(s^2 - rho^2) ds,

    T* = 4 int_0^1 q r^2 dr = (4/3)(1 - b^3) + (16/pi) int_0^b s^2 g(s) ds,         (F4)
    omega = Omega - BETA T*,                                                        (F5)
    q(rho) = (2/pi) arctan[rho sqrt(1 - b^2) / sqrt(b^2 - rho^2)]
             - (2 rho/pi) int_rho^b G'(s) / sqrt(s^2 - rho^2) ds,     rho < b,      (F6)
    u(r, 0) = (2/(pi r)) int_b^r t D(t) / sqrt(r^2 - t^2) dt,          r > b,       (F7)
    D(t) = 2 Omega t - t arcsech(t) - (2/pi) int_0^b s g(s) P(t, s) ds - R(t),

and s(r) = 2 u(r, 0) (docs/conventions.md).  D(b) = b g(b) = 0, so the slip starts like
(r - b)^(3/2).  The Dini amplitudes of the corrective field (eq. 22, c_n = lam_n A~_n)
follow from (q, J1(lam_n r)) = (2/pi) int_0^b s g(s) sin(lam_n s) ds +
int_b^1 r J1(lam_n r) dr:  c_n = -(q, J1(lam_n r)) / (lam_n h_n), h_n = J1(lam_n)^2/2.

Discretisation
--------------
Nystrom with Gauss-Legendre in theta, t = b cos(theta), 0 < theta < pi/2: every
integrand above is analytic in theta (the sqrt(b^2 - t^2) of L becomes b sin(theta)),
so the error decays geometrically; the rate is set by the image singularity of P at
t + s = 2, i.e. theta = i arccosh((2 - b)/b), and the default number of nodes is
chosen from that (``default_nodes``).  G = g + L is an even analytic function of t
and is interpolated as a Chebyshev series in x = 2 t^2/b^2 - 1 = cos(2 theta) for
(F6).  D(t) is interpolated as a Chebyshev series in psi = arccos(t) on [0, arccos b]
(analytic there, including t = 1 where the corner of the cylinder gives
sqrt(1 - t) terms), and (F7) is integrated over psi with a cosh substitution that
removes the inverse square root at t = r.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.polynomial import chebyshev

from ..criteria import GROSS_SLIP_TORQUE
from ..diagnostics import ResolutionWarning
from ..quadrature import gauss_legendre
from ..special import integrals
from ..special.zeros import bessel_j2_zeros
from . import kernels

__all__ = ["FastSolution", "solve_fast", "default_nodes", "MAX_NODES"]

#: Cap on the Nystrom nodes; default_nodes exceeds it for b within ~1.5e-6 of 1 (warns).
MAX_NODES = 400
#: Chebyshev points (in psi) for the slip integrand D(t) on [b, 1].
SLIP_POINTS = 64
#: Gauss-Legendre nodes per panel of the slip quadrature (F7).
_SLIP_PANEL_NODES = 40
#: Phase (rad) of sin(lam_N t) per 32-point Gauss panel in ``dini_amplitudes``.
DINI_PHASE = 20.0
#: Extra Chebyshev points (beyond n_nodes) for the series of G used by (F6).
CHEBYSHEV_EXTRA = 8
#: Warn when the last Chebyshev coefficients of G exceed this (absolute, f p0 units).
RESOLUTION_TOLERANCE = 1e-10

_TARGET_DIGITS = math.log(1e17)


def default_nodes(stick_radius: float) -> int:
    """Nystrom nodes for ~1e-14 accuracy, from the image singularity of P (see module).

    In theta in [0, pi/2] the singularity nearest to the interval is at
    theta_s = i arccosh((2 - b)/b); with the Bernstein-ellipse parameter rho of theta_s,
    Gauss-Legendre converges like rho^(-2n).
    """
    b = float(stick_radius)
    height = math.acosh((2.0 - b) / b) / (math.pi / 4.0)
    z = complex(-1.0, height)
    root = np.sqrt(z * z - 1.0)
    rho = max(abs(z + root), abs(z - root))
    n = math.ceil(1.15 * _TARGET_DIGITS / (2.0 * math.log(rho))) + 6
    return max(16, n)


def _chebyshev_points(b: float) -> int:
    """Chebyshev points in x = 2 t^2/b^2 - 1 for ~1e-16 decay of the series of G.

    G(t) is analytic up to t = 2 - b, i.e. x_s = 2 (2 - b)^2 / b^2 - 1 > 1.
    """
    x_s = 2.0 * ((2.0 - b) / b) ** 2 - 1.0
    rho = x_s + math.sqrt(x_s * x_s - 1.0)
    return math.ceil(_TARGET_DIGITS / math.log(rho)) + 4


def _gauss_theta(n: int):
    x, w = gauss_legendre(n)
    return np.pi / 4.0 * (x + 1.0), np.pi / 4.0 * w


def _chebyshev_coefficients(values, n: int):
    """Chebyshev coefficients from values at the first-kind points cos(pi (j + 1/2) / n)."""
    angles = np.pi * (np.arange(n) + 0.5) / n
    c = (2.0 / n) * (np.cos(np.outer(np.arange(n), angles)) @ values)
    c[0] *= 0.5
    return c


@dataclass(frozen=True)
class FastSolution:
    """Partial-slip solution for one stick radius 0 < b < 1 (positive torque).

    Attributes
    ----------
    stick_radius : float
        b/a.
    torque : float
        T*(b), eq. (F4).
    rigid_rotation : float
        omega in f p0 / mu, eq. (F5).
    n_nodes : int
        Nystrom nodes (resolution parameter).
    rotation_constant : float
        Omega = omega + BETA T* of (F1).
    nodes, weights, abel_density : ndarray
        Nystrom nodes t_j = b cos(theta_j), weights for int_0^b dt, values g(t_j) (F2).
    resolution_estimate : float
        Max of the last three Chebyshev coefficients of G = g + L in x = 2 t^2/b^2 - 1
        (an a-posteriori proxy for the resolution error of the traction).
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    n_nodes: int
    rotation_constant: float
    nodes: np.ndarray = field(repr=False)
    weights: np.ndarray = field(repr=False)
    abel_density: np.ndarray = field(repr=False)
    resolution_estimate: float = field(repr=False)
    _xi: np.ndarray = field(repr=False)
    _xi_weights: np.ndarray = field(repr=False)
    _g_chebyshev: np.ndarray = field(repr=False)

    # -- interface traction -------------------------------------------------------
    def interface_traction(self, r):
        """sigma_zt(r, 0) / (f p0) for 0 <= r <= 1, eq. (F6); 1 on the slip annulus."""
        r = np.asarray(r, dtype=float)
        b = self.stick_radius
        if b == 1.0:  # slip onset: the bilateral traction T* r with T* = 1
            return r.copy()
        flat = r.ravel()
        out = np.ones_like(flat)
        inside = flat < b
        rho = flat[inside]
        if rho.size:
            y_nodes, y_weights = gauss_legendre(self.n_nodes)
            height = np.sqrt((b - rho) * (b + rho))
            y = 0.5 * height[:, None] * (y_nodes[None, :] + 1.0)
            x = 2.0 * (rho[:, None] ** 2 + y * y) / (b * b) - 1.0
            derivative = chebyshev.chebval(x, chebyshev.chebder(self._g_chebyshev))
            integral = 0.5 * height * (derivative @ y_weights)
            edge = (2.0 / np.pi) * np.arctan2(rho * math.sqrt(1.0 - b * b), height)
            out[inside] = edge - 8.0 * rho * integral / (np.pi * b * b)
        return out.reshape(r.shape)

    # -- slip -----------------------------------------------------------------------
    @cached_property
    def _slip_chebyshev(self):
        """Chebyshev coefficients of D(cos psi) on psi in [0, arccos b] (F7)."""
        b = self.stick_radius
        psi_b = math.acos(b)
        j = np.arange(SLIP_POINTS)
        x = np.cos(np.pi * (j + 0.5) / SLIP_POINTS)
        t = np.cos(0.5 * psi_b * (x + 1.0))
        return _chebyshev_coefficients(self._d_function(t), SLIP_POINTS)

    def _d_function(self, t):
        """D(t) of (F7) for b <= t <= 1 (direct evaluation)."""
        b = self.stick_radius
        xi, w = self._xi, self._xi_weights
        p = kernels.abel_kernel(t, self.nodes, xi, w)
        mixed = (2.0 / np.pi) * p @ (self.weights * self.nodes * self.abel_density)
        near = kernels.load_transform(t, b, xi, w)
        return (
            2.0 * self.rotation_constant * t
            - t * kernels.arcsech(t)
            - mixed
            - kernels.spinning_transform(t)
            + near
        )

    def _d_interpolated(self, psi):
        psi_b = math.acos(self.stick_radius)
        return chebyshev.chebval(2.0 * psi / psi_b - 1.0, self._slip_chebyshev)

    def interface_displacement(self, r):
        """u_theta(r, 0+) in f p0 a / mu: 0 on the stick disc, eq. (F7) on the annulus."""
        r = np.asarray(r, dtype=float)
        b = self.stick_radius
        if b == 0.0:  # spinning: unbounded relative rotation
            return np.where(r > 0, math.inf, 0.0)
        flat = r.ravel()
        out = np.zeros_like(flat)
        psi_b = math.acos(b)
        x_nodes, x_weights = gauss_legendre(_SLIP_PANEL_NODES)
        all_psi, all_weight, owner = [], [], []
        for index in np.nonzero(flat > b)[0]:
            radius = float(flat[index])
            psi_r = 2.0 * math.asin(math.sqrt(max(0.0, 1.0 - radius) / 2.0))
            if psi_r == 0.0:
                psi = 0.5 * psi_b * (x_nodes + 1.0)
                all_psi.append(psi)
                all_weight.append(0.5 * psi_b * x_weights * np.cos(psi))
                owner.append(np.full(psi.size, index))
                continue
            # first panel [psi_r, min(2 psi_r, psi_b)]: psi = psi_r cosh(w)
            top = min(2.0 * psi_r, psi_b)
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
                hi = min(2.0 * lo, psi_b)
                psi = 0.5 * (hi - lo) * (x_nodes + 1.0) + lo
                factor = np.sin(psi) * np.cos(psi) / np.sqrt(np.sin(psi - psi_r) * np.sin(psi + psi_r))
                all_psi.append(psi)
                all_weight.append(0.5 * (hi - lo) * x_weights * factor)
                owner.append(np.full(psi.size, index))
                lo = hi
        if all_psi:
            psi = np.concatenate(all_psi)
            weight = np.concatenate(all_weight) * self._d_interpolated(psi)
            idx = np.concatenate(owner)
            sums = np.bincount(idx, weights=weight, minlength=flat.size)
            sel = flat > b
            out[sel] = 2.0 * sums[sel] / (np.pi * flat[sel])
        return out.reshape(r.shape)

    def interface_slip(self, r):
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu (docs/conventions.md); 0 for r <= b."""
        return 2.0 * self.interface_displacement(r)

    # -- Dini amplitudes ----------------------------------------------------------------
    def abel_transform(self, t):
        """g(t) = int_t^b q(rho) / sqrt(rho^2 - t^2) drho for 0 < t <= b (F2)."""
        t = np.asarray(t, dtype=float)
        b = self.stick_radius
        big_g = chebyshev.chebval(2.0 * (t / b) ** 2 - 1.0, self._g_chebyshev)
        root = np.sqrt(np.clip((b - t) * (b + t), 0.0, None))
        return big_g - np.log1p(np.sqrt((1.0 - t) * (1.0 + t))) + np.log(b + root)

    def dini_amplitudes(self, n_terms: int) -> np.ndarray:
        """c_n (n = 1..n_terms) of u = T* r z + omega r + sum c_n exp(-lam_n z) J1(lam_n r).

        c_n = -(q, J1(lam_n r)) / (lam_n h_n) with the stick part of the moment from the
        Abel form (2/pi) int_0^b s g(s) sin(lam_n s) ds (composite Gauss-Legendre in
        theta, t = b cos theta, panels spanning at most ``DINI_PHASE`` rad of the phase
        lam_N t) and the slip part in closed form (eq. 51).  Use with
        ``fields.series_sum`` away from the interface (z > 0).
        """
        lam = bessel_j2_zeros(int(n_terms))
        b = self.stick_radius
        if b == 1.0:
            return np.zeros(lam.size)
        if b == 0.0:  # traction 1 everywhere (c_m lam_m h_m = B_m with T* = 4/3)
            return -integrals.load_integral_constant(lam, 0.0) / (lam * integrals.dini_norm(lam))
        # composite 32-point Gauss in theta, at most DINI_PHASE rad of phase per panel
        panels = max(4, math.ceil(lam[-1] * b / DINI_PHASE))
        x, w = gauss_legendre(32)
        edges = np.linspace(0.0, 0.5 * np.pi, panels + 1)
        half = 0.5 * np.diff(edges)
        theta = (half[:, None] * (x[None, :] + 1.0) + edges[:-1, None]).ravel()
        w_theta = (half[:, None] * w[None, :]).ravel()
        s = b * np.cos(theta)
        weight = (2.0 / np.pi) * b * np.sin(theta) * w_theta * s * self.abel_transform(s)
        moments = np.sin(np.outer(lam, s)) @ weight + integrals.load_integral_constant(lam, b)
        return -moments / (lam * integrals.dini_norm(lam))


def _limit_solution(b: float) -> FastSolution:
    """b = 1 (slip onset: T* = 1, omega = 0) or b = 0 (spinning: T* = 4/3, omega = +inf)."""
    empty = np.zeros(0)
    onset = b == 1.0
    rotation = 0.0 if onset else math.inf
    return FastSolution(
        stick_radius=b,
        torque=1.0 if onset else GROSS_SLIP_TORQUE,
        rigid_rotation=rotation,
        n_nodes=0,
        rotation_constant=rotation,
        nodes=empty,
        weights=empty,
        abel_density=empty,
        resolution_estimate=0.0,
        _xi=empty,
        _xi_weights=empty,
        _g_chebyshev=np.zeros(1),
    )


def solve_fast(stick_radius: float, n_nodes: int | None = None) -> FastSolution:
    """Solve the partial-slip problem for a stick radius by the Abel-Fredholm method.

    Parameters
    ----------
    stick_radius : float
        b/a in [0, 1].  b = 1: slip onset (T* = 1, omega = 0); b = 0: spinning
        (T* = 4/3, omega = +inf; traction 1, slip infinite).
    n_nodes : int, optional
        Nystrom nodes (resolution parameter); default ``default_nodes(b)`` (about
        1e-14 in T*), 16 at least.

    Returns
    -------
    FastSolution

    Warns
    -----
    ResolutionWarning
        If the requested or needed nodes exceed ``MAX_NODES`` (b within ~1.5e-6 of 1),
        or the Chebyshev tail of G exceeds ``RESOLUTION_TOLERANCE``.
    """
    b = float(stick_radius)
    if not math.isfinite(b) or b < 0.0 or b > 1.0:
        raise ValueError(f"stick_radius must be a finite number in [0, 1], got {stick_radius!r}")
    if b in (0.0, 1.0):
        return _limit_solution(b)
    n = default_nodes(b) if n_nodes is None else int(n_nodes)
    if n < 2:
        raise ValueError(f"n_nodes must be an integer >= 2, got {n_nodes!r}")
    if n > MAX_NODES:
        warnings.warn(
            f"stick_radius={b:.17g} needs {n} Nystrom nodes; capped at {MAX_NODES}: "
            "T*, omega and the fields near r = b may lose digits",
            ResolutionWarning,
            stacklevel=2,
        )
        n = MAX_NODES
    xi, w_xi = kernels.xi_grid(1.0 - b)
    theta, w_theta = _gauss_theta(n)
    t = b * np.cos(theta)
    wt = b * np.sin(theta) * w_theta
    sin_theta = np.sin(theta)
    log_l = np.log1p(np.sqrt((1.0 - t) * (1.0 + t))) - np.log(b) - np.log1p(sin_theta)

    # Chebyshev points of the first kind in x = 2 t^2 / b^2 - 1 for the series of G
    n_cheb = min(max(n + CHEBYSHEV_EXTRA, _chebyshev_points(b)), 2 * MAX_NODES)
    x_cheb = np.cos(np.pi * (np.arange(n_cheb) + 0.5) / n_cheb)
    t_cheb = b * np.sqrt(0.5 * (1.0 + x_cheb))
    points = np.concatenate([t, [b], t_cheb])
    a_t = kernels.sinh_excess_scaled(xi, points)
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
    omega_big = -g_b0 / g_b1
    density = omega_big * g[:, 0] + g[:, 1]
    torque = GROSS_SLIP_TORQUE * (1.0 - b**3) + 16.0 / np.pi * np.sum(wt * t * t * density)
    rotation = omega_big - kernels.TORQUE_ROTATION * torque

    # G = g + L = 2 Omega - R(t)/t - (2/(pi t)) int_0^b s g P ds (Nystrom interpolant of
    # F2), sampled at the Chebyshev points and expanded in x = 2 t^2/b^2 - 1
    mixed = p[n + 1 :] @ (column * density)
    big_g = 2.0 * omega_big - (r_side[n + 1 :] + (2.0 / np.pi) * mixed) / t_cheb
    coefficients = _chebyshev_coefficients(big_g, n_cheb)
    tail = float(np.max(np.abs(coefficients[-3:])))
    if tail > RESOLUTION_TOLERANCE:
        warnings.warn(
            f"stick_radius={b:.17g}, n_nodes={n}: the Chebyshev tail of the Abel density is "
            f"{tail:.1e}; increase n_nodes",
            ResolutionWarning,
            stacklevel=2,
        )
    return FastSolution(
        stick_radius=b,
        torque=float(torque),
        rigid_rotation=float(rotation),
        n_nodes=n,
        rotation_constant=float(omega_big),
        nodes=t,
        weights=wt,
        abel_density=density,
        resolution_estimate=tail,
        _xi=xi,
        _xi_weights=w_xi,
        _g_chebyshev=coefficients,
    )
