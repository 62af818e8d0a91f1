"""The formulas of the manuscript's appendix, each checked numerically against an independent route.

* beta = 0.60531512622...: from the Dini series of the Neumann-to-Dirichlet kernel G, through
  the identity G = G_hs + G_c - 4 beta r rho integrated against r rho (G_hs by its Abel form,
  G_c by its xi-integral in mpmath), against ``kernels.TORQUE_ROTATION``;
* the half-space part of the Abel reduction, int G_hs q rho drho = S[t Gq(t)], for two loads;
* the regularity argument in both directions: for a smooth G on [0, b], the Abel inverse gives
  a stick-side traction K_b (b - rho)^(-1/2) + O(1) with K_b = sqrt(2b) g(b) / pi, and, when
  g(b) = 0, a traction that rises continuously to the friction limit 1 (round trip checked by
  the forward transform);
* Omega = omega + beta T*: the Dini representation u = omega r + sum c_n J1(lam_n r) of the
  converged traction vanishes on the stick disc with omega = Omega - beta T*;
* the torque identity T* = (16/pi) int s^2 Gq(s) ds for the load 1.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy import integrate, special

from torsional_contact.solvers import kernels
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.special import integrals
from torsional_contact.special.zeros import bessel_j2_zeros


def _cylinder_part_of_the_double_moment():
    """int int G_c(r, rho) r rho dr drho = (2/pi) int_0^inf [(F/xi^2)^2 - xi^2/36] K2/I2 dxi, 30 digits.

    F(x) = int_0^x y I1(y) dy = x^3/6 1F2(3/2; 2, 5/2; x^2/4).  The integrand decays only like
    xi^-3 (the image point r + rho = 2 is reached at r = rho = 1), so the range goes to infinity;
    Gauss-Legendre on the finite panels keeps its nodes away from xi = 0, where the subtraction
    cancels to O(xi^4) against K2/I2 ~ 16/xi^4.
    """
    def integrand(x):
        f = x / 6 * mpmath.hyp1f2(1.5, 2, 2.5, x**2 / 4)
        return (f**2 - x**2 / 36) * mpmath.besselk(2, x) / mpmath.besseli(2, x)

    finite = mpmath.quad(integrand, [0, 1, 4, 16, 40, 80], method="gauss-legendre")
    return 2 / mpmath.pi * (finite + mpmath.quad(integrand, [80, mpmath.inf]))


def test_beta_from_the_dini_series():
    """beta = (9/4) [int int K r rho - sum_n (int J1(lam_n r) r dr)^2 / (lam_n h_n)]."""
    with mpmath.workdps(30):
        # half-space part: int_0^1 S[t arcsech t](r) r dr = (2/pi) int_0^1 t^2 arcsech(t)^2 dt
        halfspace = 2 / mpmath.pi * mpmath.quad(lambda t: t**2 * mpmath.asech(t) ** 2, [0, 0.5, 1])
        double_moment = float(halfspace + _cylinder_part_of_the_double_moment())
    lam = bessel_j2_zeros(10_000)
    terms = (integrals.integral_t_j1(lam) / lam**2) ** 2 / (lam * special.j1(lam) ** 2 / 2)
    dini = float(np.sum(terms[::-1]))  # smallest first
    # the terms decay like n^-4: the tail beyond N is about N terms_N / 3
    tail = terms[-1] * lam.size / 3
    beta = 9 / 4 * (double_moment - dini)
    # tolerance: 10 x the truncation bound of the series (9/4 tail), above the ~1e-16 rounding of the sum
    assert abs(beta - kernels.TORQUE_ROTATION) < max(10 * 9 / 4 * tail, 1e-15)
    assert abs(beta - 0.60531512622) < 1e-11  # the value the manuscript prints


@pytest.mark.parametrize("load", ["uniform", "quadratic"])
@pytest.mark.parametrize("r", [0.25, 0.7])
def test_halfspace_part_is_the_abel_operator(load, r):
    """int_0^1 G_hs(r, rho) q(rho) rho drho = S[t Gq(t)](r), Gq the Abel transform of q."""
    with mpmath.workdps(20):
        if load == "uniform":  # q = 1: Gq = arcsech t
            q, abel = (lambda x: 1.0), (lambda t: mpmath.asech(t))
        else:  # q = rho^2: Gq = int_t^1 rho^2 / sqrt(rho^2 - t^2) = (sqrt(1 - t^2) + t^2 arcsech t) / 2
            q, abel = (lambda x: x * x), (lambda t: (mpmath.sqrt(1 - t**2) + t**2 * mpmath.asech(t)) / 2)
        operator = 2 / (mpmath.pi * r) * mpmath.quad(
            lambda th: (r * mpmath.sin(th)) ** 2 * abel(r * mpmath.sin(th)), [0, mpmath.pi / 2])
    # G_hs has a logarithmic singularity at rho = r: graded Gauss-Legendre on both sides of it
    x, w = np.polynomial.legendre.leggauss(40)
    total = 0.0
    for lo, hi in ((0.0, r), (r, 1.0)):
        for k in range(40):  # geometric panels toward rho = r
            a, c = (lo, hi) if lo == r else (hi, lo)  # a: the end at rho = r
            near, far = (hi - lo) * 2.0 ** -(k + 1), (hi - lo) * 2.0 ** -k
            if k == 39:
                near = 0.0
            s0, s1 = a + math.copysign(near, c - a), a + math.copysign(far, c - a)
            rho = 0.5 * (s1 - s0) * x + 0.5 * (s1 + s0)
            total += abs(0.5 * (s1 - s0)) * np.sum(w * kernels.halfspace_kernel(r, rho) * rho
                                                   * np.vectorize(q)(rho))
    # tolerance: the graded rule converges to ~1e-15 (the log singularity is resolved to 2^-40)
    assert abs(total - float(operator)) < 1e-12


def _traction_from_abel(g_at_b, b, e):
    """Stick-side traction at rho = b - e of the Abel transform G on [0, b] (arcsech on (b, 1)):

        q(rho) = (2 rho / pi) [G(b)/sqrt(b^2 - rho^2) - int_rho^b G'(s) ds / sqrt(s^2 - rho^2)
                               - int_b^1 s arcsech(s) (s^2 - rho^2)^(-3/2) ds],

    for G(s) = arcsech(b) + g_at_b + 0.2 (s^2 - b^2) (smooth, g(b) = G(b) - arcsech(b) = g_at_b).
    The distance e = b - rho is the argument, so that rho -> b loses no digits.  Double precision:
    the two terms of order e^(-1/2) cancel to O(1), leaving about 1e-11 absolute at e = 1e-10.
    """
    rho = b - e
    g_b = math.acosh(1 / b) + g_at_b
    inner = 0.4 * math.sqrt(e * (2 * b - e))  # int_rho^b 0.4 s / sqrt(s^2 - rho^2) ds in closed form
    # the annulus integrand peaks within e of s = b: geometric panels b + e 10^k
    edges = [b] + [b + e * 10.0**k for k in range(0, 40) if b + e * 10.0**k < (1 + b) / 2] + [(1 + b) / 2, 1.0]
    outer = sum(integrate.quad(lambda s: s * math.acosh(1 / s) * ((s - b + e) * (s + rho)) ** -1.5, lo, hi,
                               epsabs=0, epsrel=1e-11, limit=200)[0] for lo, hi in zip(edges, edges[1:], strict=False))
    return 2 * rho / math.pi * (g_b / math.sqrt(e * (2 * b - e)) - inner - outer)


@pytest.mark.parametrize("g_at_b", [0.0, 0.05])
def test_regularity_in_both_directions(g_at_b):
    """g(b) = pi K_b / sqrt(2 b): a bounded traction, rising to 1, exactly when g(b) = 0."""
    b, t = 0.6, 0.3
    # the inverse formula is right: its forward Abel transform returns G at an inner point.
    # p = b - (b - t) cos^2(theta) removes both inverse square roots (at p = t and p = b);
    # the integrand is then smooth in theta and Gauss-Legendre converges geometrically.
    x, w = np.polynomial.legendre.leggauss(48)
    theta, w = np.pi / 4 * (x + 1), np.pi / 4 * w
    e = (b - t) * np.cos(theta) ** 2
    stick = sum(wk * _traction_from_abel(g_at_b, b, ek) * 2 * math.sqrt(ek) / math.sqrt(b - ek + t)
                for wk, ek in zip(w, e, strict=True))
    forward = stick + math.acosh(1 / t) - math.acosh(b / t)  # + int_b^1 dp / sqrt(p^2 - t^2)
    expected = math.acosh(1 / b) + g_at_b + 0.2 * (t * t - b * b)
    # tolerance: the quadratures are good to ~1e-12; 1e-9 leaves room for the cancellation near p = b
    assert forward == pytest.approx(expected, abs=1e-9)
    # the edge behaviour
    eps = [1e-4, 1e-6, 1e-8]  # below 1e-8 the O(e^(-1/2)) cancellation eats the digits
    k_b = math.sqrt(2 * b) * g_at_b / math.pi
    if g_at_b:
        misses = [abs(_traction_from_abel(g_at_b, b, e) * math.sqrt(e) - k_b) for e in eps]
        # q sqrt(b - rho) = K_b + O(1) sqrt(b - rho) (the bounded part of q is of order the friction
        # limit): the miss shrinks 10-fold per 100-fold step and is below 3 sqrt(b - rho)
        assert misses[1] < misses[0] / 5 and misses[2] < misses[1] / 5
        assert misses[-1] < 3 * math.sqrt(eps[-1])
    else:
        gaps = [abs(1 - _traction_from_abel(0.0, b, e)) for e in eps]
        # q -> 1 like 1 - C sqrt(b - rho): the distance to 1 shrinks 10-fold per 100-fold step
        assert gaps[-1] < 1e-3 and gaps[1] < gaps[0] / 5 and gaps[2] < gaps[1] / 5


def test_rigid_rotation_is_omega_plus_beta_torque():
    """u = omega r + sum c_n J1(lam_n r) vanishes on the stick disc with omega = Omega - beta T*."""
    b = 0.6
    state = solve_abel_fredholm(b)
    assert state.rigid_rotation == pytest.approx(state.rotation_constant - kernels.TORQUE_ROTATION * state.torque,
                                                 abs=1e-15)
    lam = bessel_j2_zeros(4000)
    amplitudes = state.dini_amplitudes(lam.size)
    r = np.linspace(0.05, 0.55, 11)
    u = state.rigid_rotation * r + special.j1(np.outer(r, lam)) @ amplitudes
    # the series converges like N^-3/2 at a fixed point of the stick disc (amplitudes ~ n^-5/2):
    # with N = 4000 the truncation is below 1e-6; the wrong rigid rotation Omega would leave beta T* r ~ 0.3
    assert np.max(np.abs(u)) < 1e-6
    assert np.max(np.abs(u + kernels.TORQUE_ROTATION * state.torque * r)) > 0.1


def test_torque_identity_for_the_uniform_load():
    """T* = (16/pi) int_0^1 s^2 Gq(s) ds equals 4 int_0^1 q r^2 dr = 4/3 for q = 1 (Gq = arcsech)."""
    with mpmath.workdps(30):
        value = 16 / mpmath.pi * mpmath.quad(lambda s: s * s * mpmath.asech(s), [0, 1])
        assert abs(value - mpmath.mpf(4) / 3) < mpmath.mpf(10) ** -25
