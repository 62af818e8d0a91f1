"""The formulas of the manuscript's appendix, each checked numerically against an independent route.

* beta = 0.60531512622...: from the Dini series of the Neumann-to-Dirichlet kernel G, through
  the identity G = G_hs + G_c - 4 beta r rho integrated against r rho (G_hs by its Abel form,
  G_c by its xi-integral in Arb and mpmath), against ``kernels.TORQUE_ROTATION``;
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

import flint
import mpmath
import numpy as np
import pytest
from arb_points import BESSEL_K_BITS, at_mpf
from scipy import integrate, special
from tolerances import EPS, assert_beyond, assert_close, assert_within

from torsional_contact.solvers import kernels
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.special import integrals
from torsional_contact.special.zeros import bessel_j2_zeros


def _cylinder_integrand_arb(t):
    """(F/xi^2)^2 - xi^2/36) K2/I2 of an Arb ball (tests/arb_points.py evaluates it at mpmath's points)."""
    f = t / 6 * (t**2 / 4).hypgeom([flint.arb(3) / 2], [2, flint.arb(5) / 2])
    return (f**2 - t**2 / 36) * t.bessel_k(2) / t.bessel_i(2)


def _cylinder_part_of_the_double_moment():
    """int int G_c(r, rho) r rho dr drho = (2/pi) int_0^inf [(F/xi^2)^2 - xi^2/36] K2/I2 dxi, 30 digits.

    F(x) = int_0^x y I1(y) dy = x^3/6 1F2(3/2; 2, 5/2; x^2/4).  The integrand decays only like
    xi^-3 (the image point r + rho = 2 is reached at r = rho = 1), so the range goes to infinity;
    Gauss-Legendre on the finite panels keeps its nodes away from xi = 0, where the subtraction
    cancels to O(xi^4) against K2/I2 ~ 16/xi^4.  The finite panels take their integrand from Arb (ten times
    faster than mpmath's Bessel K there, and the same digits), the tail beyond 80 from mpmath.
    """
    def integrand(x):
        f = x / 6 * mpmath.hyp1f2(1.5, 2, 2.5, x**2 / 4)
        return (f**2 - x**2 / 36) * mpmath.besselk(2, x) / mpmath.besseli(2, x)

    # Arb's 1F2 has no large-argument expansion (no finite ball beyond a few hundred): Arb on the finite panels only
    finite = mpmath.quad(lambda x: at_mpf(_cylinder_integrand_arb, x, bits=BESSEL_K_BITS), [0, 1, 4, 16, 40, 80],
                         method="gauss-legendre")
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
    # the terms decay like n^-4: the tail beyond N is N terms_N / 3 (the integral of C n^-4) up to terms_N / 2
    # (Euler-Maclaurin) and O(tail / N); it is added, so that the comparison is not at the size of the tail
    # (2.4e-14, where a tenfold margin over the truncation would have left no room)
    tail = terms[-1] * lam.size / 3
    beta = 9 / 4 * (double_moment - dini - tail)
    # the rest: the tail's error (<= terms_N, with the O(tail / N) term), the recursive-summation bound of the N
    # positive terms (N EPS dini), the 30-digit double moment rounded to double (half an ulp), and the difference
    # and product (2 EPS beta)
    bound = 9 / 4 * (terms[-1] + lam.size * EPS * dini + EPS * double_moment) + 2 * EPS * beta
    assert_close(beta, kernels.TORQUE_ROTATION, "tail correction + rounding of the sums", atol=bound)
    # the value the manuscript prints: correct to its 11 decimals, half a unit of the last one
    assert_within(abs(kernels.TORQUE_ROTATION - 0.60531512622), 5e-12, "11 printed decimals", exact=True)


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
    # the graded rule: the innermost panel of each side (width 2^-40 of the side, next to the log singularity)
    # holds at most width (|ln width| + 1) max(G_hs rho q) of the integral, and Gauss's error there is a fraction
    # of that; the other panels are analytic (geometric convergence); plus the rounding of 3200 positive terms
    # (3200 EPS of the total) and of the 20-digit reference (half an ulp)
    width = 2.0**-40
    singular = 2 * width * (abs(math.log(width)) + 1) * 4 / math.pi
    assert_close(total, float(operator), "innermost panels + rounding of the graded rule",
                 atol=singular + 3200 * EPS * abs(total) + EPS)


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
    # the traction's error: quad's epsrel 1e-11 on the outer integral (positive panels, sqrt(e) outer <= 2 b
    # arcsech(b) / (2 b)^(3/2), its value next to the edge) and the rounding of the O(e^(-1/2)) terms (8 EPS
    # g_b / sqrt(2 b)), times sqrt(e) (2 rho / pi <= 2 b / pi); the forward rule weighs it with int 2 dtheta /
    # sqrt(b - e + t) <= pi / sqrt(t) (48 Gauss nodes on a smooth integrand: truncation far below)
    g_b = math.acosh(1 / b) + g_at_b
    edge = 2 * b / math.pi * (1e-11 * 2 * b * math.acosh(1 / b) / (2 * b) ** 1.5 + 8 * EPS * g_b / math.sqrt(2 * b))
    assert_close(forward, expected, "quad's epsrel and rounding of the traction, through the forward rule",
                 atol=math.pi / math.sqrt(t) * edge)
    # the edge behaviour
    eps = [1e-4, 1e-6, 1e-8]  # below 1e-8 the O(e^(-1/2)) cancellation eats the digits
    k_b = math.sqrt(2 * b) * g_at_b / math.pi
    if g_at_b:
        misses = [abs(_traction_from_abel(g_at_b, b, e) * math.sqrt(e) - k_b) for e in eps]
        # q sqrt(b - rho) = K_b + O(1) sqrt(b - rho): the miss shrinks 10-fold per 100-fold step (an order of
        # the edge behaviour, not a tolerance)
        assert misses[1] < misses[0] / 5 and misses[2] < misses[1] / 5
        # and exactly so: the inverse is linear in G, and the part g_at_b of G is a constant on [0, b], whose
        # inverse is g_at_b (2 rho / pi) / sqrt(e (2 b - e)) (-> K_b e^(-1/2)); the rest is the traction of g = 0.
        # Both tractions share their inner and outer integrals (the same code on the same e), so they cancel in
        # the difference but for the rounding of the terms (8 EPS of the terms' sizes: the edge term, and |q|)
        for e in eps:
            rho = b - e
            q_g, q_0 = _traction_from_abel(g_at_b, b, e), _traction_from_abel(0.0, b, e)
            singular = 2 * rho / math.pi / math.sqrt(e * (2 * b - e))
            terms = singular * (2 * math.acosh(1 / b) + g_at_b) + abs(q_g) + abs(q_0)
            assert_close(q_g - q_0, g_at_b * singular, "linearity: rounding of the terms", atol=8 * EPS * terms)
    else:
        gaps = [abs(1 - _traction_from_abel(0.0, b, e)) for e in eps]
        # q -> 1 like 1 - C sqrt(b - rho): the distance to 1 shrinks 10-fold per 100-fold step (an order)
        assert gaps[1] < gaps[0] / 5 and gaps[2] < gaps[1] / 5
        # continuously to 1: at the smallest e within ten times the square-root law from e = 1e-6 (an allowance
        # of ten on the coefficient C, which the digits lost to cancellation at e = 1e-8 leave uncertain)
        assert_within(gaps[-1], 10 * gaps[1] * math.sqrt(eps[2] / eps[1]), "ten times the sqrt law")


def test_rigid_rotation_is_omega_plus_beta_torque():
    """u = omega r + sum c_n J1(lam_n r) vanishes on the stick disc with omega = Omega - beta T*."""
    b = 0.6
    state = solve_abel_fredholm(b)
    # the same product and difference: two roundings of |Omega|
    assert_close(state.rigid_rotation, state.rotation_constant - kernels.TORQUE_ROTATION * state.torque,
                 "a product and a difference", atol=2 * EPS * abs(state.rotation_constant))
    lam = bessel_j2_zeros(4000)
    amplitudes = state.dini_amplitudes(lam.size)
    r = np.linspace(0.05, 0.55, 11)
    u = state.rigid_rotation * r + special.j1(np.outer(r, lam)) @ amplitudes
    # the series converges like N^-3/2 at a fixed point of the stick disc: amplitudes |c_n| <= A n^-5/2 (A the
    # largest |c_n| n^(5/2) of the last 200) and |J1(lam r)| <= sqrt(2 / (pi lam r)), lam_n ~ n pi, bound the
    # tail by A sqrt(2 / (pi^2 r)) sum_(n > N) n^-3 = A sqrt(2 / (pi^2 r)) / (2 N^2) (absolutely: the signs of
    # J1 only make it smaller); plus the rounding of the N-term sum (N EPS of sum |c_n|)
    n = np.arange(1, lam.size + 1)
    scale = np.max(np.abs(amplitudes[-200:]) * n[-200:] ** 2.5)
    tail = scale * np.sqrt(2 / (np.pi**2 * r.min())) / (2 * lam.size**2)
    error = tail + lam.size * EPS * np.sum(np.abs(amplitudes))
    assert_within(np.max(np.abs(u)), error, "Dini tail bound")
    # the wrong rigid rotation Omega would leave beta T* r ~ 0.3: far beyond ten times that error bound
    assert_beyond(np.max(np.abs(u + kernels.TORQUE_ROTATION * state.torque * r)), 10 * error,
                  "Omega misses by beta T* r, beyond ten times the series' error")


def test_torque_identity_for_the_uniform_load():
    """T* = (16/pi) int_0^1 s^2 Gq(s) ds equals 4 int_0^1 q r^2 dr = 4/3 for q = 1 (Gq = arcsech)."""
    with mpmath.workdps(30):
        value = 16 / mpmath.pi * mpmath.quad(lambda s: s * s * mpmath.asech(s), [0, 1])
        # a 30-digit tanh-sinh quadrature of an integrand with a log endpoint singularity: 1e-25, five digits
        # above the working precision
        assert_close(value, mpmath.mpf(4) / 3, "30-digit quadrature", atol=mpmath.mpf(10) ** -25)
