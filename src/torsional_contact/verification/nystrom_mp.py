r"""Nystrom solution of the Abel-Fredholm equation in arbitrary precision (one solve).

Units (docs/conventions.md): r, t in a; tractions in f p0; slip in f p0 a / mu; omega in
f p0 / mu; T* = 2T/(f F a) (eq. 32).

The reduction of ``fast`` (equations (F1)-(F7) of its docstring), evaluated with
python-flint ``arb`` numbers at any precision: the Fredholm equation (F2) on the stick disc,

    g(t) + (2/(pi t)) int_0^b s g(s) P(t, s) ds = 2 Omega - L(t) - R(t)/t,   R = E_1 - E_b,

the regularity condition g(b) = 0 (F3), the torque identity (F4), omega = Omega - BETA T*
(F5), the traction (F6) and the slip (F7).  The xi-integrals P, E_c, BETA and the
closed-form tail of E_1 are those of ``kernels_mp`` (M1)-(M4), computed at the working
precision (no double-precision tables).

Discretisation
--------------
Nystrom with Gauss-Legendre in theta, t = b cos(theta) on (0, pi/2), as in ``fast``: the
error decays like rho^(-2n), rho the Bernstein parameter of the image singularity
theta = i arccosh((2 - b)/b) of P; ``nodes_for_digits`` scales ``fast.default_nodes``
from 17 to the requested digits (measured: conservative by 5-10 digits).  The Nystrom
interpolant bracket(t) = R(t) + (2/pi) int_0^b s g(s) P(t, s) ds is kept as two xi-profiles,
so that each new t costs one row of A(xi t).  G = g + L = 2 Omega - bracket(t)/t is
expanded in Chebyshev polynomials of x = 2 t^2/b^2 - 1 for (F6) (``chebyshev_points``:
G branches at t = 1 with L and E_1, x = 2/b^2 - 1).  (F7) is integrated over v,
psi = arccos(t) = psi_r + v^2 (which removes the inverse square root at t = r), on panels
graded geometrically toward v = 0 (scale sqrt(2 psi_r), the zero of sin(psi + psi_r)) and
toward t = b (scale set by the log singularity of D at t = 0, which matters for small b).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from functools import cached_property

import flint

from .arbitrary_precision import gauss_legendre, mp_to_arb, parse_decimal, working_digits
from .kernels_mp import (
    FIRST_PANEL,
    WIDTH_DECAYS,
    load_profiles,
    panel_nodes,
    spinning_tail,
    torque_rotation,
    xi_quadrature,
)
from .special_mp import bessel_ratio, sinh_excess_matrix

__all__ = ["AbelFredholmState", "nodes_for_digits", "chebyshev_points", "solve_state"]


def _bernstein_log(b: float, singular_t_over_b: float) -> float:
    """ln(rho) of the image point theta_s = i arccosh(singular_t_over_b) for theta in [0, pi/2]."""
    height = math.acosh(singular_t_over_b) / (math.pi / 4.0)
    z = complex(-1.0, height)
    root = (z * z - 1.0) ** 0.5
    return math.log(max(abs(z + root), abs(z - root)))


def nodes_for_digits(stick_radius, digits: int) -> int:
    """Nystrom nodes for an error 10^-digits in T* and omega at stick radius b.

    ``fast.default_nodes`` scaled to ``digits``: Gauss-Legendre in theta converges like
    rho^(-2n) with rho the Bernstein parameter of theta_s = i arccosh((2 - b)/b) (the
    image singularity of P); n = 1.15 digits ln 10 / (2 ln rho) + 6.
    """
    b = float(stick_radius)
    n = math.ceil(1.15 * digits * math.log(10.0) / (2.0 * _bernstein_log(b, (2.0 - b) / b))) + 6
    return max(16, n)


def chebyshev_points(stick_radius, digits: int) -> int:
    """Chebyshev points in x = 2 t^2/b^2 - 1 for a 10^-digits series of G = g + L.

    G branches at t = 1 (L and E_1 do), x_s = 2/b^2 - 1: coefficients decay like
    (x_s + sqrt(x_s^2 - 1))^-k.
    """
    b = float(stick_radius)
    x_s = 2.0 / (b * b) - 1.0
    rho = x_s + math.sqrt(x_s * x_s - 1.0)
    return math.ceil(digits * math.log(10.0) / math.log(rho)) + 8


def _position(r, b) -> int:
    """-1, 0, 1 for r below, at (within 2^(8 - prec)), or above the stick radius b (arb)."""
    tolerance = flint.arb(2) ** (8 - flint.ctx.prec)
    if r < b - tolerance:
        return -1
    if r > b + tolerance:
        return 1
    return 0


def _arcsech(t):
    """ln((1 + sqrt(1 - t^2)) / t) for 0 < t <= 1 (arb)."""
    return ((1 + (1 - t * t).sqrt()) / t).log()


def _column(values) -> flint.arb_mat:
    values = list(values)
    return flint.arb_mat(len(values), 1, values)


def _row(values) -> flint.arb_mat:
    values = list(values)
    return flint.arb_mat(1, len(values), values)


def _entries(matrix) -> list:
    return [matrix[i, 0] for i in range(matrix.nrows())]


@dataclass(frozen=True)
class AbelFredholmState:
    """One Nystrom solve at fixed nodes and working precision (all numbers ``arb``).

    Attributes
    ----------
    stick_radius : arb
        b (exact binary value of the decimal input at the working precision).
    n_nodes, work_digits : int
    torque, rigid_rotation, rotation_constant : arb
        T* (F4), omega (F5), Omega = omega + BETA T* (F1).
    nodes, weights, density : tuple of arb
        t_j = b cos(theta_j), weights for int_0^b dt, g(t_j) (F2).
    chebyshev : tuple of arb
        Coefficients of G = g + L in T_k(2 t^2/b^2 - 1) (for F6).
    seconds : float
        Wall-clock time of the solve.
    """

    stick_radius: object
    n_nodes: int
    work_digits: int
    torque: object
    rigid_rotation: object
    rotation_constant: object
    nodes: tuple = field(repr=False)
    weights: tuple = field(repr=False)
    density: tuple = field(repr=False)
    chebyshev: tuple = field(repr=False)
    seconds: float = 0.0
    _xi: tuple = field(repr=False, default=())
    _profile_a: tuple = field(repr=False, default=())
    _profile_y: tuple = field(repr=False, default=())
    _tail_start: float = field(repr=False, default=0.0)

    # -- the Nystrom interpolant --------------------------------------------------------
    def _bracket(self, t_points) -> list:
        """R(t) + (2/pi) int_0^b s g(s) P(t, s) ds for 0 < t <= 1 (arb list), see (F2), (F7)."""
        a_matrix = sinh_excess_matrix(t_points, self._xi)
        part_a = _entries(a_matrix * _column(self._profile_a))
        total_y = sum(self._profile_y, flint.arb(0))
        two_over_pi = 2 / flint.arb.pi()
        return [
            two_over_pi * (pa + t * total_y) + spinning_tail(t, self._tail_start)
            for t, pa in zip(t_points, part_a, strict=True)
        ]

    def _d_function(self, t_points) -> list:
        """D(t) = 2 Omega t - t arcsech(t) - [R(t) + (2/pi) int s g P ds] on [b, 1] (F7)."""
        bracket = self._bracket(t_points)
        omega2 = 2 * self.rotation_constant
        return [omega2 * t - t * _arcsech(t) - br for t, br in zip(t_points, bracket, strict=True)]

    # -- (F6) -----------------------------------------------------------------------------
    @cached_property
    def _chebyshev_derivative(self) -> tuple:
        c = list(self.chebyshev)
        n = len(c)
        d = [flint.arb(0)] * (n + 1)
        for k in range(n - 1, 0, -1):
            d[k - 1] = (d[k + 1] + 2 * k * c[k]).mid()
        d[0] = d[0] / 2
        return tuple(v.mid() for v in d[: n - 1])

    def traction_arb(self, radii) -> list:
        """sigma_zt(r, 0)/(f p0) at exact radii in [0, 1] (arb list), eq. (F6); 1 for r >= b."""
        with working_digits(self.work_digits):
            b = self.stick_radius
            derivative = self._chebyshev_derivative
            m = len(derivative) + 2
            y_nodes, y_weights = gauss_legendre(m)
            edge_factor = (1 - b * b).sqrt()
            out = []
            for r in radii:
                if _position(r, b) >= 0:
                    out.append(flint.arb(1))
                    continue
                height = ((b - r) * (b + r)).sqrt()
                total = flint.arb(0)
                for yj, wj in zip(y_nodes, y_weights, strict=True):
                    y = height * (yj + 1) / 2
                    x = (2 * (r * r + y * y) / (b * b) - 1).mid()
                    total += wj * _clenshaw(derivative, x)
                integral = height * total / 2
                edge = 2 * flint.arb.atan2(r * edge_factor, height) / flint.arb.pi()
                out.append(edge - 8 * r * integral / (flint.arb.pi() * b * b))
            return [+v for v in out]

    # -- (F7) ------------------------------------------------------------------------------
    def slip_arb(self, radii) -> list:
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu at exact radii in [0, 1], eq. (F7)."""
        with working_digits(self.work_digits):
            b = self.stick_radius
            psi_b = b.acos()
            half_pi = flint.arb.pi() / 2
            m = panel_nodes(self.work_digits)
            x_nodes, x_weights = gauss_legendre(m)
            t_all, w_all, owner = [], [], []
            for index, r in enumerate(radii):
                if _position(r, b) <= 0:
                    continue
                psi_r = r.acos() if r < 1 else flint.arb(0)
                length = (psi_b - psi_r).sqrt()
                # no near singularity at v = 0 when r = 1 (sin(psi + psi_r) = sin(psi) cancels)
                left = float((2 * psi_r).sqrt()) if r < 1 else float(length)
                right = float((half_pi - psi_r).sqrt() - length)
                for lo, hi in _graded_panels(float(length), left, right, length):
                    half, mid = (hi - lo) / 2, (hi + lo) / 2
                    for xj, wj in zip(x_nodes, x_weights, strict=True):
                        v = mid + half * xj
                        psi = psi_r + v * v
                        s_psi, c_psi = psi.sin(), psi.cos()
                        factor = 2 * v * c_psi * s_psi / ((v * v).sin() * (2 * psi_r + v * v).sin()).sqrt()
                        t_all.append(c_psi)
                        w_all.append(half * wj * factor)
                        owner.append(index)
            sums = [flint.arb(0)] * len(radii)
            if t_all:
                values = self._d_function(t_all)
                for k, w, dv in zip(owner, w_all, values, strict=True):
                    sums[k] += w * dv
            two_over_pi = 2 / flint.arb.pi()
            return [+(2 * two_over_pi * s / r) if _position(r, b) > 0 else flint.arb(0)
                    for s, r in zip(sums, radii, strict=True)]


def _graded_panels(length: float, left_scale: float, right_scale: float, exact_length):
    """Panels [lo, hi] (arb) of [0, length], halving toward 0 down to ``left_scale`` and
    toward ``length`` down to ``right_scale`` (geometric meshes for near end singularities)."""
    edges = {0.0}
    e = length / 2.0
    while e > left_scale and e > length * 1e-30:
        edges.add(e)
        e /= 2.0
    d = right_scale
    while d < length / 2.0:
        edges.add(length - d)
        d *= 2.0
    edges = sorted(edges)
    edges = [flint.arb(e) for e in edges] + [exact_length]
    return list(zip(edges[:-1], edges[1:], strict=True))


def _clenshaw(coefficients, x):
    """sum_k c_k T_k(x) in midpoint arithmetic (exact arb coefficients and x).

    Each step is rounded to an exact midpoint: in ball arithmetic the recurrence inflates
    the radii like (1 + sqrt 2)^k and Arb then drops midpoint precision (measured: 1e-30
    instead of 1e-42 at 40 digits with 50 terms, O(1) errors with 290 terms at b = 0.98).
    The rounding error of Clenshaw's recurrence itself is O(k^2) ulps; the error estimate
    of ``solve_reference_abel_fredholm`` covers it.
    """
    b1 = flint.arb(0)
    b2 = flint.arb(0)
    two_x = (2 * x).mid()
    for c in reversed(coefficients[1:]):
        b1, b2 = (two_x * b1 - b2 + c).mid(), b1
    return x * b1 - b2 + coefficients[0]


def solve_state(stick_radius, n_nodes: int, work_digits: int, *, first_panel: float = FIRST_PANEL,
                width_decays: float = WIDTH_DECAYS) -> AbelFredholmState:
    """Solve (F2)-(F5) with ``n_nodes`` Nystrom nodes at ``work_digits`` working digits.

    Parameters
    ----------
    stick_radius : mpf, str or Decimal
        b in (0, 1), exact (see ``arbitrary_precision.parse_decimal``).
    n_nodes : int
        Gauss-Legendre nodes in theta, >= 4.
    work_digits : int
        Working decimal digits of every operation.
    first_panel, width_decays : float
        Layout of the xi-quadrature (``kernels_mp.xi_quadrature``).
    """
    if isinstance(n_nodes, bool) or not isinstance(n_nodes, int) or n_nodes < 4:
        raise ValueError(f"n_nodes must be an integer >= 4, got {n_nodes!r}")
    start = time.perf_counter()
    with working_digits(work_digits):
        b = mp_to_arb(parse_decimal("stick_radius", stick_radius, 0, 1, closed=False))
        n = n_nodes
        pi = flint.arb.pi()
        two_over_pi = 2 / pi
        theta_x, theta_w = gauss_legendre(n)
        theta = [pi / 4 * (x + 1) for x in theta_x]
        t = [b * th.cos() for th in theta]
        wt = [b * th.sin() * pi / 4 * w for th, w in zip(theta, theta_w, strict=True)]
        quadrature = xi_quadrature(float(1 - b), work_digits, first_panel, width_decays)
        xi = quadrature.nodes
        scale = [w * r for w, r in zip(quadrature.weights, bessel_ratio(xi), strict=True)]
        below = quadrature.n_below
        full_1, excess_1 = load_profiles(flint.arb(1), xi[:below])
        full_b, excess_b = load_profiles(b, xi)
        zero = flint.arb(0)
        side_full = [(full_1[k] if k < below else zero) - full_b[k] for k in range(len(xi))]
        side_excess = [(excess_1[k] if k < below else zero) - excess_b[k] for k in range(len(xi))]

        # A(xi_k t_i) at the nodes and at t = b; weighted transpose for the products
        points = t + [b]
        a_points = sinh_excess_matrix(points, xi)
        weighted = flint.arb_mat(len(xi), n, [scale[k] * a_points[j, k] for k in range(len(xi)) for j in range(n)])
        moment_row = _row(xi) * weighted  # sum_k scale_k xi_k A(xi_k t_j)
        moment_nodes = [moment_row[0, j] for j in range(n)]
        moment_points = _entries(a_points * _column(s * x for s, x in zip(scale, xi, strict=True)))
        product = a_points * weighted
        side_a = _entries(a_points * _column(s * f for s, f in zip(scale, side_full, strict=True)))
        side_y = sum((s * x * e for s, x, e in zip(scale, xi, side_excess, strict=True)), zero)
        tail_start = quadrature.asymptotic_start
        r_side = [two_over_pi * (sa + p * side_y) + spinning_tail(p, tail_start)
                  for p, sa in zip(points, side_a, strict=True)]
        # P(t_i, t_j) for i < n and the edge row i = n (t = b)
        kernel = [[two_over_pi * (product[i, j] + moment_points[i] * t[j] + points[i] * moment_nodes[j])
                   for j in range(n)] for i in range(n + 1)]
        column = [w * tj for w, tj in zip(wt, t, strict=True)]
        matrix = flint.arb_mat(n, n, [(1 if i == j else 0) + two_over_pi * kernel[i][j] / t[i] * column[j]
                                      for i in range(n) for j in range(n)])
        log_l = [((1 + (1 - tj * tj).sqrt()) / (b + b * th.sin())).log() for tj, th in zip(t, theta, strict=True)]
        rhs = flint.arb_mat(n, 2, [v for i in range(n) for v in (flint.arb(2), -log_l[i] - r_side[i] / t[i])])
        solution = matrix.solve(rhs)
        g1 = [solution[i, 0] for i in range(n)]
        g0 = [solution[i, 1] for i in range(n)]
        edge = [two_over_pi * kernel[n][j] * column[j] / b for j in range(n)]
        g_b1 = 2 - sum((e * g for e, g in zip(edge, g1, strict=True)), zero)
        g_b0 = -_arcsech(b) - r_side[n] / b - sum((e * g for e, g in zip(edge, g0, strict=True)), zero)
        omega_big = -g_b0 / g_b1
        density = [omega_big * a + c for a, c in zip(g1, g0, strict=True)]
        torque = 4 * (1 - b**3) / 3 + 16 / pi * sum((w * tj * tj * g for w, tj, g in zip(wt, t, density, strict=True)),
                                                     zero)
        rotation = omega_big - torque_rotation(work_digits) * torque

        # xi-profiles of the interpolant: bracket(t) = (2/pi) sum_k [A(xi_k t) a_k + t y_k] + tail
        weights_g = [c * g for c, g in zip(column, density, strict=True)]
        sum_a = _entries(flint.arb_mat(len(xi), n, [a_points[j, k] for k in range(len(xi)) for j in range(n)])
                         * _column(weights_g))
        sum_c = sum((c * tj for c, tj in zip(weights_g, t, strict=True)), zero)
        profile_a = tuple(s * (two_over_pi * (sa + x * sum_c) + f)
                          for s, x, sa, f in zip(scale, xi, sum_a, side_full, strict=True))
        profile_y = tuple(s * x * (two_over_pi * sa + e)
                          for s, x, sa, e in zip(scale, xi, sum_a, side_excess, strict=True))
        state = AbelFredholmState(
            stick_radius=b, n_nodes=n, work_digits=work_digits, torque=torque, rigid_rotation=rotation,
            rotation_constant=omega_big, nodes=tuple(t), weights=tuple(wt), density=tuple(density),
            chebyshev=(), _xi=xi, _profile_a=profile_a, _profile_y=profile_y, _tail_start=tail_start,
        )
        # Chebyshev series of G = 2 Omega - bracket(t)/t in x = 2 t^2/b^2 - 1 (for F6)
        n_cheb = chebyshev_points(float(b), work_digits)
        angles = [pi * (j + flint.arb(1) / 2) / n_cheb for j in range(n_cheb)]
        x_cheb = [a.cos() for a in angles]
        t_cheb = [b * ((1 + x) / 2).sqrt() for x in x_cheb]
        big_g = [2 * omega_big - br / tc for br, tc in zip(state._bracket(t_cheb), t_cheb, strict=True)]
        cosines = flint.arb_mat(n_cheb, n_cheb, [(k * a).cos() for k in range(n_cheb) for a in angles])
        coefficients = _entries(cosines * _column(big_g))
        coefficients = [2 * c / n_cheb for c in coefficients]
        coefficients[0] = coefficients[0] / 2
    seconds = time.perf_counter() - start
    return AbelFredholmState(
        stick_radius=b, n_nodes=n, work_digits=work_digits, torque=torque, rigid_rotation=rotation,
        rotation_constant=omega_big, nodes=tuple(t), weights=tuple(wt), density=tuple(density),
        chebyshev=tuple(coefficients), seconds=seconds, _xi=xi, _profile_a=profile_a, _profile_y=profile_y,
        _tail_start=tail_start,
    )
