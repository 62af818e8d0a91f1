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
chosen from that (``default_nodes``).  G = g + L is an even function of t, analytic
for |Re t| < 1 (its nearest singularity is the side image of E_1 at t = 1, 1 - b from
the stick edge); it is interpolated as a Chebyshev series in the logarithmic variable

    Y = 2 ln(1 - t^2) / ln(1 - b^2) - 1,        0 <= t <= b  <->  -1 <= Y <= 1,     (F8)

which keeps a strip of analyticity of width O(1) however thin the slip annulus is
(Chebyshev in t^2 would need ~10 / sqrt(1 - b) terms; in Y about 15 at b = 0.6 and
200 at 1 - b = 1e-6).  (F6) is then integrated in Y: with v = w^2 = ln((1 - rho^2) /
(1 - s^2)),

    int_rho^b G'(s) ds / sqrt(s^2 - rho^2)
        = 2 / (|ln(1 - b^2)| sqrt(1 - rho^2)) int_0^sqrt(V) G_Y(Y(w)) 2w / sqrt(1 - exp(-w^2)) dw,  (F9)

V = ln((1 - rho^2) / (1 - b^2)): a polynomial in w times an analytic factor, integrated
by Gauss-Legendre with ``len(series) + interface.INNER_EXTRA`` nodes (exact to rounding); G_Y is
sampled from the derivative of the Nystrom interpolant, not differentiated term by term.
D(t) is interpolated as a Chebyshev series in psi = arccos(t) on [0, arccos b]
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
from . import interface, kernels
from .interface import chebyshev_coefficients as _chebyshev_coefficients
from .interface import log_gap
from .nystrom import MAX_CHEBYSHEV, StickSystem, default_nodes, stick_system
from .nystrom import gauss_theta as _gauss_theta

__all__ = ["AbelFredholmSolution", "solve_abel_fredholm", "default_nodes", "log_gap", "MAX_NODES", "MIN_STICK_RADIUS",
           "MAX_CHEBYSHEV", "StickSystem", "stick_system"]

#: Cap on the Nystrom nodes; default_nodes exceeds it for b within ~8e-7 of 1 (warns).
MAX_NODES = 512
#: Smallest stick radius solved (below, b^2 underflows against 1; ``asymptotics`` takes over).
MIN_STICK_RADIUS = 1e-100
#: Chebyshev points (in psi) for the slip integrand D(t) on [b, 1].
SLIP_POINTS = 64
#: Chebyshev points (in t on [0, 1]) for the smooth part m(t) of D/t (sigma_rt, b < 1/2).
CORRECTION_POINTS = 48
#: Phase (rad) of sin(lam_N t) per 32-point Gauss panel in ``dini_amplitudes``.
DINI_PHASE = 20.0
#: Warn when the last Chebyshev coefficients of G exceed this (absolute, f p0 units).
RESOLUTION_TOLERANCE = 1e-10

_CHUNK_ENTRIES = 500_000  # (lam, s) entries evaluated at once in ``dini_amplitudes``


@dataclass(frozen=True)
class AbelFredholmSolution:
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
        Max of the last three Chebyshev coefficients of G = g + L in Y of (F8) (an
        a-posteriori proxy for the resolution error of the traction).
    torque_deficit : float
        4/3 - T* from (F4) without cancellation: (4/3) b^3 - (16/pi) int_0^b s^2 g ds
        (relative accuracy ~1e-15 even where 4/3 - T* is far below the rounding of T*).
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
    torque_deficit: float = field(repr=False)
    _log_span: float = field(repr=False)
    _xi: np.ndarray = field(repr=False)
    _xi_weights: np.ndarray = field(repr=False)
    _g_chebyshev: np.ndarray = field(repr=False)

    @classmethod
    def without_nodes(cls, *, stick_radius, torque, rigid_rotation, rotation_constant, torque_deficit,
                      log_span=0.0, xi=None, xi_weights=None):
        """A state given in closed form (no Nystrom nodes): the limits b = 0, 1 and the expansions."""
        empty = np.zeros(0)
        return cls(
            stick_radius=stick_radius, torque=torque, rigid_rotation=rigid_rotation, n_nodes=0,
            rotation_constant=rotation_constant, nodes=empty, weights=empty, abel_density=empty,
            resolution_estimate=0.0, torque_deficit=torque_deficit, _log_span=log_span,
            _xi=empty if xi is None else xi, _xi_weights=empty if xi_weights is None else xi_weights,
            _g_chebyshev=np.zeros(1),
        )

    # -- interface traction -------------------------------------------------------
    @cached_property
    def _gy_chebyshev(self):
        """Chebyshev coefficients of dG/dY = G'(t) (span/4)(1 - t^2)/t in Y of (F8) (for F9).

        Sampled from the derivative of the Nystrom interpolant of G at the Chebyshev points
        of G and expanded on their own: differentiating the series of G would amplify its
        rounding ~n^2 times at the stick edge Y = 1, where (F9) needs it most.
        """
        b, span, n_cheb = self.stick_radius, self._log_span, self._g_chebyshev.size
        y_cheb = np.cos(np.pi * (np.arange(n_cheb) + 0.5) / n_cheb)
        gap_factor = np.exp(-0.5 * (y_cheb + 1.0) * span)  # 1 - t^2
        t_cheb = np.sqrt(-np.expm1(-0.5 * (y_cheb + 1.0) * span))
        theta, _ = _gauss_theta(self.n_nodes)
        xi = self._xi
        ratio = self._xi_weights * kernels.bessel_ratio_scaled(xi)
        nodes = self.nodes
        a_s = kernels.sinh_excess_scaled(xi, nodes, (1.0 - b) + 2.0 * b * np.sin(0.5 * theta) ** 2)
        y_s = kernels.linear_scaled(xi, nodes)
        full_1, _ = kernels.load_profiles(1.0, xi)
        full_b, _ = kernels.load_profiles(b, xi)
        slope = kernels.sinh_excess_slope(xi, t_cheb, gap_factor / (1.0 + t_cheb))  # -(d/dt) of a_t / t
        column = self.weights * self.nodes * self.abel_density
        g_prime = (2.0 / np.pi) * (
            slope @ (ratio * (full_1 - full_b)) + (2.0 / np.pi) * ((slope * ratio) @ (a_s + y_s).T) @ column
        )
        return _chebyshev_coefficients(g_prime * (0.25 * span) * gap_factor / t_cheb, n_cheb)

    def interface_traction(self, r):
        """sigma_zt(r, 0) / (f p0) for 0 <= r <= 1, eq. (F6); 1 on the slip annulus."""
        r = np.asarray(r, dtype=float)
        b = self.stick_radius
        if b == 1.0:  # slip onset: the bilateral traction T* r with T* = 1
            return r.copy()
        if b == 0.0 or not np.any(r < b):  # spinning: traction 1 everywhere
            return np.ones_like(r)
        return interface.stick_traction(r, b, self._log_span, self._gy_chebyshev)

    # -- slip -----------------------------------------------------------------------
    @cached_property
    def _slip_chebyshev(self):
        """Chebyshev coefficients in psi in [0, arccos b] (t = cos psi) of the slip integrand (F7).

        b >= 1/2: D(t) itself.  b < 1/2: D(t)/t + arcsech(t) = 2 Omega - (mixed + R)/t,
        analytic in psi on the whole of [0, pi/2], whereas D has the t ln t of arcsech at
        t = 0, just beyond the stick edge of a small stick disc.  (For b near 1 D is
        small and is interpolated directly, keeping its relative accuracy.)
        """
        b = self.stick_radius
        psi_b = math.acos(b)
        j = np.arange(SLIP_POINTS)
        x = np.cos(np.pi * (j + 0.5) / SLIP_POINTS)
        t = np.cos(0.5 * psi_b * (x + 1.0))
        values = self._d_regular(t) if b < 0.5 else self._d_function(t)
        return _chebyshev_coefficients(values, SLIP_POINTS)

    def _d_regular(self, t):
        """D(t)/t + arcsech(t) = 2 Omega - (mixed(t) + E_1(t) - E_b(t)) / t, 0 < t <= 1 (F7)."""
        b = self.stick_radius
        xi, w = self._xi, self._xi_weights
        p = kernels.abel_kernel(t, self.nodes, xi, w)
        mixed = (2.0 / np.pi) * p @ (self.weights * self.nodes * self.abel_density)
        near = kernels.load_transform(t, b, xi, w)
        return 2.0 * self.rotation_constant - (mixed + kernels.spinning_transform(t) - near) / t

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
        """D(cos psi) from the series of ``_slip_chebyshev`` (arcsech added back exactly for b < 1/2)."""
        b = self.stick_radius
        psi_b = math.acos(b)
        series = chebyshev.chebval(2.0 * psi / psi_b - 1.0, self._slip_chebyshev)
        if b >= 0.5:
            return series
        t = np.cos(psi)
        return t * (series - kernels.arcsech(t))

    def interface_displacement(self, r):
        """u_theta(r, 0+) in f p0 a / mu: 0 on the stick disc, eq. (F7) on the annulus."""
        r = np.asarray(r, dtype=float)
        b = self.stick_radius
        if b == 0.0:  # spinning: unbounded relative rotation
            return np.where(r > 0, math.inf, 0.0)
        return interface.slip_integral(r, b, self._d_interpolated)

    def interface_slip(self, r):
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu (docs/conventions.md); 0 for r <= b."""
        return 2.0 * self.interface_displacement(r)

    # -- sigma_rt on the interface (b < 1/2) ---------------------------------------------
    @cached_property
    def _correction_chebyshev(self):
        """Chebyshev coefficients in t on [0, 1] of m(t) = (mixed(t) - E_b(t)) / t (F7).

        m is analytic on [0, 1] (its singularities are at t = 2 - b > 3/2 for b < 1/2):
        D/t = 2 Omega - arcsech t - E_1(t)/t - m(t), the spinning part being exact (K5).
        """
        j = np.arange(CORRECTION_POINTS)
        t = 0.5 * (np.cos(np.pi * (j + 0.5) / CORRECTION_POINTS) + 1.0)
        xi, w = self._xi, self._xi_weights
        p = kernels.abel_kernel(t, self.nodes, xi, w)
        mixed = (2.0 / np.pi) * p @ (self.weights * self.nodes * self.abel_density)
        values = (mixed - kernels.load_transform(t, self.stick_radius, xi, w)) / t
        return _chebyshev_coefficients(values, CORRECTION_POINTS)

    def interface_sigma_rt(self, r):
        """sigma_rt(r, 0) = u' - u/r in f p0 from (F7), without differences.

        b < 1/2: with x = r sin(phi), phi_b = arcsin(b/r) (D(b) = 0 by F3 removes the
        boundary term) and k of ``kernels.spinning_shear_kernel``,

            sigma_rt = (2/pi) int_(phi_b)^(pi/2) sin^2(phi) [k(x) - x m'(x)] dphi,

        the k-part being the spinning (K5) minus its integral over [0, phi_b] (x <= b < 1/2,
        where k is smooth).  b >= 1/2 (where x reaches the corner t -> 1 and k cancels):
        (2/(pi r^2)) int_b^r t^2 (D' - D/t) / sqrt(r^2 - t^2) dt with D and dD/dpsi from the
        Chebyshev series of D in psi = arccos t (``interface.face_shear_from_slip_integrand``).
        Measured against the 30-digit reference (tests/test_sigma_rt.py): 2e-14 to 2.5e-12 for
        1 - r >= 1e-4 (1 - b); closer to the corner the error grows like ln(1/(1 - r)) times the
        slope error (5e-10) of the spinning table E_1 at t = 1 (``kernels.spinning_transform``;
        the same for both formulas): 3e-11 at 1 - r = 1e-6 (1 - b), 6e-10 at 1e-8 (1 - b), at most
        (5e-10/pi) ln(1/(1 - r)) < 1e-8 absolute, where sigma_rt itself falls to 0 like
        (1 - r) ln(1/(1 - r)).  0 on the stick disc and at r = 1.
        """
        b = self.stick_radius
        if b < 0.5:
            return interface.face_shear(r, b, self._correction_chebyshev)
        return interface.face_shear_from_slip_integrand(r, b, self._d_and_slope)

    def _d_and_slope(self, psi):
        """D(cos psi) and dD/dpsi from the series of ``_slip_chebyshev`` (b >= 1/2: D itself)."""
        psi_b = math.acos(self.stick_radius)
        y = 2.0 * psi / psi_b - 1.0
        coefficients = self._slip_chebyshev
        return (chebyshev.chebval(y, coefficients),
                chebyshev.chebval(y, chebyshev.chebder(coefficients)) * (2.0 / psi_b))

    # -- Dini amplitudes ----------------------------------------------------------------
    def abel_transform(self, t):
        """g(t) = int_t^b q(rho) / sqrt(rho^2 - t^2) drho for 0 < t <= b (F2)."""
        t = np.asarray(t, dtype=float)
        b = self.stick_radius
        big_g = chebyshev.chebval(-2.0 * log_gap(t) / self._log_span - 1.0, self._g_chebyshev)
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
        moments = integrals.load_integral_constant(lam, b)
        block = max(1, _CHUNK_ENTRIES // s.size)  # rows of the (lam, s) matrix at once
        for start in range(0, lam.size, block):
            moments[start : start + block] += np.sin(np.outer(lam[start : start + block], s)) @ weight
        return -moments / (lam * integrals.dini_norm(lam))


def _limit_solution(b: float) -> AbelFredholmSolution:
    """b = 1 (slip onset: T* = 1, omega = 0) or b = 0 (spinning: T* = 4/3, omega = +inf)."""
    onset = b == 1.0
    rotation = 0.0 if onset else math.inf
    return AbelFredholmSolution.without_nodes(
        stick_radius=b,
        torque=1.0 if onset else GROSS_SLIP_TORQUE,
        rigid_rotation=rotation,
        rotation_constant=rotation,
        torque_deficit=GROSS_SLIP_TORQUE - 1.0 if onset else 0.0,
        log_span=math.inf if onset else 0.0,
    )


def solve_abel_fredholm(stick_radius: float, n_nodes: int | None = None) -> AbelFredholmSolution:
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
    AbelFredholmSolution

    Warns
    -----
    ResolutionWarning
        If the needed nodes exceed ``MAX_NODES`` (b within ~8e-7 of 1),
        or the Chebyshev tail of G exceeds ``RESOLUTION_TOLERANCE``.
    """
    b = float(stick_radius)
    if not math.isfinite(b) or b < 0.0 or b > 1.0:
        raise ValueError(f"stick_radius must be a finite number in [0, 1], got {stick_radius!r}")
    if b in (0.0, 1.0):
        return _limit_solution(b)
    if b < MIN_STICK_RADIUS:
        raise ValueError(
            f"stick_radius must be 0 or in [{MIN_STICK_RADIUS:g}, 1] for the Abel-Fredholm solver, got {b!r} "
            "(smaller stick discs: torsional_contact.asymptotics)"
        )
    n = default_nodes(b) if n_nodes is None else int(n_nodes)
    if n < 2 or (n_nodes is not None and n > MAX_NODES):
        raise ValueError(f"n_nodes must be an integer in [2, {MAX_NODES}], got {n_nodes!r}")
    if n > MAX_NODES:
        warnings.warn(
            f"stick_radius={b:.17g} needs {n} Nystrom nodes; capped at {MAX_NODES}: "
            "T*, omega and the fields near r = b may lose digits",
            ResolutionWarning,
            stacklevel=2,
        )
        n = MAX_NODES
    system = stick_system(b, n)
    t, wt, p, r_side, column = system.nodes, system.weights, system.kernel, system.side, system.column
    xi, w_xi, span, n_cheb, t_cheb = system.xi, system.xi_weights, system.span, system.n_cheb, system.t_cheb
    omega_big = -system.edge_constant / system.edge_rotation
    density = omega_big * system.density_rotation + system.density_constant
    deficit = GROSS_SLIP_TORQUE * b**3 - 16.0 / np.pi * np.sum(wt * t * t * density)
    torque = GROSS_SLIP_TORQUE - deficit
    rotation = omega_big - kernels.TORQUE_ROTATION * torque

    # G = g + L = 2 Omega - R(t)/t - (2/(pi t)) int_0^b s g P ds (Nystrom interpolant of
    # F2), sampled at the Chebyshev points and expanded in Y of (F8)
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
    return AbelFredholmSolution(
        stick_radius=b,
        torque=float(torque),
        rigid_rotation=float(rotation),
        n_nodes=n,
        rotation_constant=float(omega_big),
        nodes=t,
        weights=wt,
        abel_density=density,
        resolution_estimate=tail,
        torque_deficit=float(deficit),
        _log_span=span,
        _xi=xi,
        _xi_weights=w_xi,
        _g_chebyshev=coefficients,
    )
