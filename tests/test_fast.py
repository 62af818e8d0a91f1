"""The Abel-Fredholm solver (``solvers.abel_fredholm``) and its kernels (``solvers.kernels``).

Every check compares with something computed another way: mpmath quadrature, the Dini
series of ``solvers.weak_form`` (the paper's representation), the weak form extrapolated in
N, physical identities, or the solver at a different resolution.
"""

import math
import warnings

import mpmath
import numpy as np
import pytest
from arb_points import BESSEL_K_BITS, at_mpf
from numpy.polynomial import legendre
from scipy import special
from tolerances import (
    EPS,
    PROFILE_ACCURACY,
    ROTATION_ACCURACY,
    assert_beyond,
    assert_close,
    assert_within,
    onset_remainder,
    slip_rounding,
    spinning_table_bound,
    torque_accuracy,
)

from torsional_contact import fields
from torsional_contact.solvers import kernels
from torsional_contact.solvers.abel_fredholm import default_nodes, solve_abel_fredholm
from torsional_contact.solvers.weak_form import solve_series
from torsional_contact.special.zeros import bessel_j2_zeros

RADII = (0.02, 0.1, 0.3, 0.5, 0.6, 0.7, 0.9, 0.98)
#: Rounding of the interface traction (F6): the edge term and a Gauss sum of the Chebyshev series of dG/dY, each
#: of at most 512 + 64 terms of O(1) values: 576 EPS = 1.3e-13 absolute.
TRACTION_ROUNDING = 576 * EPS


def _gauss(a, b, n):
    x, w = legendre.leggauss(n)
    return 0.5 * (b - a) * (x + 1) + a, 0.5 * (b - a) * w


def _graded(a, b, toward, n=24, levels=30):
    """Composite Gauss nodes on [a, b] graded geometrically toward the end ``toward``."""
    nodes, weights = [], []
    length = b - a
    for k in range(levels):
        lo, hi = length * 2.0 ** -(k + 1), length * 2.0 ** -k
        if k == levels - 1:
            lo = 0.0
        x, w = _gauss(lo, hi, n)
        nodes.append(a + x if toward == "a" else b - x)
        weights.append(w)
    return np.concatenate(nodes), np.concatenate(weights)


# -- kernels --------------------------------------------------------------------------


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
def test_torque_rotation_constant_mpmath():
    mpmath.mp.dps = 25
    # the integrand in Arb (tests/arb_points.py): mpmath's Bessel K at 25 digits is ten times slower
    f = lambda x: at_mpf(lambda t: t.bessel_k(2) * (1 - t**2 / (8 * t.bessel_i(2))), x, bits=BESSEL_K_BITS)  # noqa: E731
    beta = mpmath.mpf(1) / 2 + mpmath.quad(f, [0, 1, 4, 16, 48, 80]) / mpmath.pi  # K2(80) ~ 1e-36
    # the double constant is BETA correctly rounded: half an ulp (one allowed)
    assert_within(abs(float(beta) - kernels.TORQUE_ROTATION), np.spacing(kernels.TORQUE_ROTATION), "one ulp",
                  exact=True)


def test_torque_load_is_a_rigid_rotation():
    # S^{-1}[int K rho^2] = t sqrt(1 - t^2) + int M rho^2 must equal 2 BETA t for all t
    t = np.array([1e-3, 0.1, 0.4, 0.7, 0.9, 0.97])
    xi, w = kernels.xi_grid(0.03)
    lhs = t * np.sqrt(1 - t * t) + kernels.torque_transform(t, xi, w)
    # rounding of the xi-sum (m nodes, terms of the size of the result) relative to 2 BETA t
    assert_close(lhs / (2 * t), kernels.TORQUE_ROTATION, "rounding of an m-term sum", rtol=xi.size * EPS)


@pytest.mark.parametrize("x", [0.3, 1.9, 7.0, 39.9, 40.1, 120.0, 3000.0])
def test_integral_x_i1_against_mpmath(x):
    mpmath.mp.dps = 30
    exact = mpmath.quad(lambda y: y * mpmath.besseli(1, y), [0, max(0, x - 50), x]) * mpmath.e ** (-x)
    value = kernels.integral_x_i1_scaled(np.array([x]))[0]
    # series or asymptotic sum of at most 90 positive terms (no cancellation): 90 EPS relative
    assert_within(abs(value / float(exact) - 1), 90 * EPS, "rounding of a 90-term positive sum")


def test_halfspace_kernel_against_abel_form():
    """G_hs = (2/(pi r rho)) int_0^min t^2 / sqrt((r^2 - t^2)(rho^2 - t^2)) dt (Sneddon)."""
    mpmath.mp.dps = 25
    for r, rho in [(0.3, 0.7), (0.5, 0.2), (0.6, 0.601), (0.9, 0.05)]:
        low, high = min(r, rho), max(r, rho)
        # t = low sin(phi) removes the inverse square root at t = low
        def integrand(p, lo=low, hi=high):
            return (lo * mpmath.sin(p)) ** 2 / mpmath.sqrt(hi**2 - (lo * mpmath.sin(p)) ** 2)

        exact = 2 * mpmath.quad(integrand, [0, mpmath.pi / 2]) / (mpmath.pi * r * rho)
        # complete elliptic integrals (scipy, a few ulp) of m = 4 r rho / (r + rho)^2 (1 - m formed exactly), in
        # (1 - m/2) K - E: terms up to K ~ ln(4 / sqrt(1 - m)) times the result, cancelling like m^2 for small m
        m = 4 * r * rho / (r + rho) ** 2
        big_k = math.log(4 / math.sqrt(1 - m))
        assert_within(abs(kernels.halfspace_kernel(r, rho) / float(exact) - 1), 64 * EPS * (1 + big_k) / m**2,
                      "elliptic integrals: 64 EPS (1 + K) / m^2")


@pytest.mark.parametrize("r", [0.2, 0.5, 0.8])
def test_kernel_reproduces_dini_eigenfunctions(r):
    """int_0^1 (G_hs + G_c)(r, rho) J1(lam rho) rho drho = J1(lam r) / lam (torque-free)."""
    lam = bessel_j2_zeros(3)
    left, wl = _graded(0.0, r, "b")
    right, wr = _graded(r, 1.0, "a")
    rho = np.concatenate([left, right])
    w = np.concatenate([wl, wr])
    kernel = kernels.halfspace_kernel(r, rho) + kernels.cylinder_kernel(r, rho)
    moments = (special.j1(np.outer(lam, rho)) * rho * kernel) @ w
    # the graded rule leaves the innermost panel (width 2^-30) of a log-singular kernel: ~2^-30 ln(2^30) / 30
    assert_close(moments, special.j1(lam * r) / lam, "innermost panel of the graded rule: 2^-30 x 21 / 30",
                 atol=2.0**-30 * 21 / 30)


def test_i1_excess_against_mpmath():
    """exp(-xi) (I1(x) - x/2) of ``kernels._i1_excess_scaled`` on both branches (series below 1/2, Cephes i1e above)
    against 30-digit mpmath, with x broadcast against xi as ``cylinder_kernel`` does."""
    xi = np.array([0.3, 1.0, 7.0, 40.0, 300.0])
    fraction = np.array([[0.0], [0.01], [0.4], [0.9], [0.999]])
    x = fraction * xi
    got = kernels._i1_excess_scaled(x, xi)
    with mpmath.workdps(30):
        expected = np.array([[float(mpmath.exp(-mpmath.mpf(c)) * (mpmath.besseli(1, mpmath.mpf(a)) - mpmath.mpf(a) / 2))
                              for a, c in zip(row, xi, strict=True)] for row in x])
        size = np.array([[float(mpmath.exp(-mpmath.mpf(c)) * (mpmath.besseli(1, mpmath.mpf(a)) + mpmath.mpf(a) / 2))
                          for a, c in zip(row, xi, strict=True)] for row in x])
    # relative to the size of the terms I1 + x/2 (the subtraction cancels): i1e's peak relative error 2e-15 is a
    # measured sample (Cephes' own test), not a bound: ten times it; exp of the rounded difference x - xi:
    # |x - xi| EPS / 2; the product and the subtraction: 4 EPS.  (The series below 1/2: its rounding, a few EPS.)
    assert_close(got, expected, "10 x i1e's sampled peak 2e-15 + |x - xi| EPS / 2 + 4 EPS, relative to I1 + x/2",
                 atol=(2e-14 + (np.abs(x - xi) / 2 + 4) * EPS) * size)


def test_cylinder_kernel_scalar_point_as_broadcast():
    """A scalar r against a vector rho (one row of Bessel factors, broadcast) gives the numbers of r given per rho."""
    rho = np.linspace(0.0, 0.95, 40)
    row = kernels.cylinder_kernel(0.4, rho)
    full = kernels.cylinder_kernel(np.full(rho.shape, 0.4), rho)
    np.testing.assert_array_equal(row, full)  # the same elementwise operations: equal to the last bit


@pytest.mark.parametrize("order", [1, 2])
def test_series_sum_grid_tables_against_direct_sum(order):
    """On a tensor grid the Bessel and decay factors come from tables of the distinct r and z; against the sum
    written out point by point (every term, tol=0)."""
    lam = bessel_j2_zeros(300)
    coefficients = 1.0 / lam**2
    r, z = np.meshgrid(np.linspace(0.0, 1.0, 11), np.array([1e-3, 0.01, 0.2, 1.0]))
    grid = fields.series_sum(order, lam, coefficients, r, z, tol=0.0).ravel()
    terms = special.jv(order, np.outer(r.ravel(), lam)) * np.exp(-np.outer(z.ravel(), lam)) * coefficients
    # the same terms summed in another order (BLAS kernels differ with the number of rows): N EPS sum |terms|
    assert_close(grid, terms.sum(axis=1), "summation order: N EPS sum |terms|",
                 atol=lam.size * EPS * np.abs(terms).sum(axis=1))


def test_kernel_against_dini_series():
    """(K4): sum_n J1 J1 / (lam h) = G_hs + G_c - 4 BETA r rho at sample points."""
    lam = bessel_j2_zeros(100_000)
    h = special.j1(lam) ** 2 / 2
    for r, rho in [(0.2, 0.5), (0.6, 0.2), (0.7, 0.9), (0.3, 0.8)]:
        partial = np.cumsum(special.j1(lam * r) * special.j1(lam * rho) / (lam * h))
        dini = partial[lam.size // 2 :].mean()  # averages out the O(1/N) oscillation
        closed = kernels.halfspace_kernel(r, rho) + kernels.cylinder_kernel(r, rho)
        # terms ~ cos(lam r) cos(lam rho) / lam^2: the averaged tail is O(1/(N |r - rho|)^2); 10 / (N |r - rho|)^2
        # plus the rounding of a 1e5-term sum (N EPS x its first term, ~1)
        assert_within(abs(dini - (closed - 4 * kernels.TORQUE_ROTATION * r * rho)),
                      10 / (lam.size * abs(r - rho)) ** 2 + lam.size * EPS, "O(1/N^2) averaged tail + rounding")


def test_spinning_transform_table_against_direct_quadrature():
    t = np.array([0.05, 0.3, 0.7, 0.95, 0.999, 0.99999])
    xi, w = kernels.xi_grid(1e-5)
    direct = kernels.load_transform(t, 1.0, xi, w)
    assert_close(kernels.spinning_transform(t), direct, "the table's bound + the direct m-term sum's rounding",
                 atol=spinning_table_bound(t) + xi.size * EPS * np.abs(direct))


# -- convergence ---------------------------------------------------------------------


@pytest.mark.parametrize("b", RADII)
def test_resolution_convergence(b):
    """The default resolution (``default_nodes``: about 1e-14 in T*) against twice as many nodes: both within the
    solver's accuracy bounds (tests/tolerances.py)."""
    n = default_nodes(b)
    coarse, fine = solve_abel_fredholm(b), solve_abel_fredholm(b, 2 * n)
    assert_within(abs(coarse.torque - fine.torque), 2 * torque_accuracy(b), "T* bound, both resolutions")
    assert_within(abs(coarse.rigid_rotation - fine.rigid_rotation), 2 * ROTATION_ACCURACY, "omega bound, both")
    r = np.linspace(0, 1, 301)
    assert_close(coarse.interface_traction(r), fine.interface_traction(r), "profile bound, both resolutions",
                 atol=2 * PROFILE_ACCURACY)
    assert_close(coarse.interface_slip(r), fine.interface_slip(r), "profile bound, both resolutions",
                 atol=2 * PROFILE_ACCURACY)
    # the default is not wastefully far from what the error needs
    half = solve_abel_fredholm(b, max(4, n // 2))
    assert abs(half.torque - fine.torque) > 0 or n == 16


def test_geometric_convergence_in_nodes():
    """Gauss-Legendre in theta converges like rho^(-2n), rho the Bernstein parameter of the image singularity of P
    (``default_nodes``): four more nodes divide the error by rho^8."""
    b = 0.9
    reference = solve_abel_fredholm(b, 80)
    errors = [abs(solve_abel_fredholm(b, n).torque - reference.torque) for n in (6, 10, 14, 18)]
    height = 2.0 * math.asinh(math.sqrt(1.0 - b) / math.sqrt(b)) / (math.pi / 4.0)
    z = complex(-1.0, height)
    rho = max(abs(z + np.sqrt(z * z - 1.0)), abs(z - np.sqrt(z * z - 1.0)))
    assert_beyond(errors[0], 1e-6, "the coarsest solve is visibly unconverged")
    for e0, e1 in zip(errors, errors[1:], strict=False):
        assert_within(e1 / e0, 10 * rho**-8, "geometric rate rho^-8 per four nodes (ten times)")


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
def test_agrees_with_extrapolated_weak_form():
    """T_N = T + (a + c ln N)/N fitted to the complete weak form at N = 1000..4000."""
    b = 0.6
    fast = solve_abel_fredholm(b)
    n_values = np.array([1000, 1414, 2000, 2828, 4000])
    runs = [solve_series(b, "complete", int(n)) for n in n_values]
    torque = np.array([s.torque for s in runs])
    omega = np.array([s.rigid_rotation for s in runs])
    design = np.column_stack([np.ones(n_values.size), 1 / n_values, np.log(n_values) / n_values])
    t_fit = np.linalg.lstsq(design, torque, rcond=None)[0][0]
    o_fit = np.linalg.lstsq(design, omega, rcond=None)[0][0]
    # the fit leaves the O(ln(N)^2 / N^2) terms: (ln 1000 / 1000)^2 = 5e-5 times their coefficient (< 0.1)
    remainder = 0.1 * (np.log(n_values[0]) / n_values[0]) ** 2
    assert_within(abs(t_fit - fast.torque), remainder, "O((ln N / N)^2) remainder of the fit")
    assert_within(abs(o_fit - fast.rigid_rotation), remainder, "O((ln N / N)^2) remainder of the fit")
    # and the raw weak-form error decays like ln(N)/N toward the fast value (its coefficient settles near 0.055)
    scaled = (torque - fast.torque) * n_values / np.log(n_values)
    assert np.all(scaled > 0.04) and np.all(scaled < 0.07)


@pytest.mark.parametrize("b", [0.3, 0.6, 0.9])
def test_dini_representation_of_the_solution(b):
    """omega r + sum c_n J1(lam_n r) (the paper's eq. 25 with the rigid mode) reproduces
    the Abel interface displacement: zero on the stick disc, slip/2 on the annulus."""
    fast = solve_abel_fredholm(b)
    n_terms = 4000
    lam = bessel_j2_zeros(n_terms)
    amplitudes = fast.dini_amplitudes(n_terms)
    r = np.linspace(0.0, 1.0, 41)
    r = r[(np.abs(r - b) > 0.02) & (r < 0.98)]  # the series converges slowly at r = b, 1
    dini = fast.rigid_rotation * r + fields.series_sum(1, lam, amplitudes, r, 0.0, 0.0)
    # the series at z = 0 converges algebraically: the change from 1000 to 4000 terms bounds the 4000-term error
    coarse = fast.rigid_rotation * r + fields.series_sum(1, lam[:1000], amplitudes[:1000], r, 0.0, 0.0)
    assert_close(dini, fast.interface_displacement(r), "truncation: |S_4000 - S_1000| + profile accuracy",
                 atol=np.abs(dini - coarse) + PROFILE_ACCURACY)
    # the leading amplitudes do not depend on how many are asked for (quadrature converged): the moments are
    # sums over 32 Gauss nodes per panel, up to ~1300 panels, of terms ~ |c| lam h: rounding 4e4 EPS |c|
    small = fast.dini_amplitudes(50)
    assert_close(small, amplitudes[:50], "rounding of the moment sums", atol=4e4 * EPS * np.max(np.abs(small)))
    # the complete weak form at N = 2000: its amplitudes' truncation error, which falls like ln N / N (as T*'s,
    # test_agrees_with_extrapolated_weak_form): below the change from N = 60, which is 16 times it
    weak = solve_series(b, "complete", 2000).amplitudes[:5]
    coarse = solve_series(b, "complete", 60).amplitudes[:5]
    assert_close(weak, amplitudes[:5], "weak-form truncation at N = 2000: the change from N = 60",
                 atol=np.abs(weak - coarse))


# -- physics -------------------------------------------------------------------------


@pytest.mark.parametrize("b", RADII)
def test_interface_conditions_and_identities(b):
    fast = solve_abel_fredholm(b)
    x, w = legendre.leggauss(200)
    theta, w_theta = np.pi / 4 * (x + 1), np.pi / 4 * w
    rho, w_rho = b * np.cos(theta), b * np.sin(theta) * w_theta
    traction = fast.interface_traction(rho)
    assert_within(max(0.0, float(np.max(np.abs(traction))) - 1), TRACTION_ROUNDING, "stick bound: rounding of (F6)")
    # torque balance T* = 4 int q r^2 dr (the stick part by 200-point Gauss in theta, exact for the analytic
    # integrand): the rounding of (F6) integrated, and of (F4)
    assert_within(abs(4 * (w_rho @ (rho**2 * traction) + (1 - b**3) / 3) - fast.torque),
                  4 * TRACTION_ROUNDING * b**3 / 3 + 1e3 * EPS, "rounding of (F6) integrated + (F4)")
    # slip annulus: traction 1, slip >= 0, growing like (r - b)^(3/2)
    r_slip = b + (1 - b) * np.linspace(1e-9, 1, 50)
    assert np.all(fast.interface_traction(r_slip) == 1.0)
    slip = fast.interface_slip(r_slip)
    assert np.all(slip >= 0) and np.all(np.diff(slip) > 0)
    eps = (1 - b) * np.array([1e-6, 1e-5])
    ratio = fast.interface_slip(b + eps) / eps**1.5
    # next term O((r - b)/L), L the shorter of the stick radius b and the annulus 1 - b: ten times that at
    # r - b = 1e-5 (1 - b), plus the slip's rounding relative to the slip
    rounding = 2 * slip_rounding(fast, b + eps[0]) / (ratio[0] * eps[0] ** 1.5)
    assert_within(abs(ratio[0] / ratio[1] - 1), 10 * eps[1] / min(b, 1 - b) + rounding,
                  "next term of the (r - b)^(3/2) start + rounding")
    # stick disc: no slip; traction rises continuously to 1 (no inverse sqrt at r = b)
    assert np.all(fast.interface_slip(np.linspace(0, b, 20)) == 0)
    gap = 1 - fast.interface_traction(b * (1 - np.array([1e-12, 1e-8])))
    assert np.all(gap > 0) and np.all(gap < 1e-3)  # 1 - q = C sqrt(b - r) <= C 1e-4, C < 10
    # (F3): g(b) = G(b) - arcsech(b) from the Chebyshev series of G (n_cheb terms, G ~ arcsech(b) ~ ln(2/b)):
    # 4 n_cheb EPS x 4 max(1, arcsech b)
    scale = 4 * max(1.0, math.acosh(1 / b))
    assert_within(abs(fast.abel_transform(np.array([b]))[0]), 4 * fast._g_chebyshev.size * EPS * scale,
                  "rounding of the series of G at the stick edge")
    # omega = 4 int u r^2 dr = 2 int s r^2 dr (every Dini term is orthogonal to r)
    # r = b + (1 - b) sin^2(phi) makes (r - b)^(3/2) and sqrt(1 - r) analytic in phi
    phi, w_phi = np.pi / 4 * (x + 1), np.pi / 4 * w
    radius = b + (1 - b) * np.sin(phi) ** 2
    jacobian = (1 - b) * np.sin(2 * phi)
    integral = 2 * np.sum(w_phi * jacobian * fast.interface_slip(radius) * radius**2)
    # the slip's rounding integrated (2 int r^2 dr < 1) and omega's
    assert_within(abs(integral - fast.rigid_rotation), float(slip_rounding(fast)) + ROTATION_ACCURACY,
                  "rounding of the slip integrated + omega's bound")


def test_torque_curve_is_monotone_with_the_right_limits():
    radii = np.linspace(0.02, 0.98, 49)
    torque = np.array([solve_abel_fredholm(b).torque for b in radii])
    assert np.all(np.diff(torque) < 0)
    assert 1 < torque[-1] < torque[0] < 4 / 3


def test_small_stick_discs():
    radii = np.geomspace(1e-3, 0.02, 6)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        runs = [solve_abel_fredholm(b) for b in radii]
    torque = np.array([s.torque for s in runs])
    omega = np.array([s.rigid_rotation for s in runs])
    assert np.all(np.isfinite(torque)) and np.all(np.isfinite(omega))
    # T* -> 4/3 like b^3 (the stick disc carries O(b^3) less torque than traction 1)
    deficit = 4 / 3 - torque
    # (S7): relative O(b^2) corrections, coefficient < 1 (-0.48): 10 b^2, plus T*'s rounding relative to b^3
    assert_close(deficit / radii**3, deficit[0] / radii[0] ** 3, "10 b^2 (S7 remainder) + T* accuracy / b^3",
                 rtol=10 * radii**2 + 2 * torque_accuracy(0.0) / radii**3)
    # omega ~ ln(1/b)/2 + const as b -> 0, with an O(b^2) correction (coefficient 0.2 < 1): 10 b^2
    offset = omega - 0.5 * np.log(1 / radii)
    assert_within(np.ptp(offset), 10 * radii[-1] ** 2 + 2 * ROTATION_ACCURACY, "10 b^2 + omega's bound")
    spinning = solve_abel_fredholm(0.0)
    assert spinning.torque == 4 / 3 and spinning.rigid_rotation == math.inf
    assert np.all(spinning.interface_traction([0.0, 0.5, 1.0]) == 1.0)
    assert spinning.interface_slip(0.5) == math.inf
    # both the closed form B_m / (lam_m h_m) (eq. 51 at b = 0): a few ulp of amplitudes below 0.1
    assert_close(spinning.dini_amplitudes(20), solve_series(0.0, "complete", 20).amplitudes, "8 ulp of 0.1",
                 atol=8 * EPS * 0.1)


def test_large_stick_discs():
    radii = 1 - np.geomspace(0.02, 1e-3, 5)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        runs = [solve_abel_fredholm(b) for b in radii]
    torque = np.array([s.torque for s in runs])
    assert np.all(np.isfinite(torque)) and np.all(np.diff(torque) < 0)
    # T* - 1 = (2/pi) delta + delta^2/8 + remainder (S1) near slip onset
    delta = 1 - radii
    slope = (torque - 1) / delta
    bound = np.array([onset_remainder(d) + torque_accuracy(1 - d) for d in delta]) / delta
    assert_close(slope, 2 / np.pi + delta / 8, "(S1) remainder + solver accuracy, over delta", atol=bound)
    assert np.all([s.rigid_rotation > 0 for s in runs])
    onset = solve_abel_fredholm(1.0)
    assert onset.torque == 1.0 and onset.rigid_rotation == 0.0
    r = np.linspace(0, 1, 11)
    assert np.all(onset.interface_traction(r) == r) and np.all(onset.interface_slip(r) == 0)
    assert np.all(onset.dini_amplitudes(10) == 0)


def test_capped_resolution_warns():
    from torsional_contact.diagnostics import ResolutionWarning

    with pytest.warns(ResolutionWarning):
        solve_abel_fredholm(1 - 1e-9)


def test_bad_input():
    for bad in (-0.1, 1.1, math.nan, math.inf):
        with pytest.raises(ValueError, match="stick_radius"):
            solve_abel_fredholm(bad)


#: Accuracy of the direct collocation (``verification.collocation``) against the exact solution.  An exception to
#: deriving tolerances from bounds, explained: the collocation's kernels come from brute-force quadrature, which
#: limits it to ~1e-11 whatever the basis (6 and 8 functions give the same errors at b = 0.3), and it reports no
#: error estimate.  These are the statements the second method makes, each at least ten times the largest error
#: at b = 0.3 (8 functions) and 0.6 (10): T* 2.5e-12, omega 5.2e-12, traction 2.6e-11.
COLLOCATION = {"torque": 1e-10, "rigid_rotation": 1e-10, "traction": 5e-10}


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
@pytest.mark.parametrize(("b", "n_basis"), [(0.3, 8), (0.6, 10)])
def test_agrees_with_direct_collocation(b, n_basis):
    """A second method: first-kind collocation of u = 0 on the stick disc (``verification.collocation``)."""
    from torsional_contact.verification.collocation import solve_direct

    fast, direct = solve_abel_fredholm(b), solve_direct(b, n_basis)
    assert direct.residual < 1e-12  # the collocation's own convergence criterion
    r = np.linspace(0, 1, 101)
    reason = "stated accuracy of the collocation (COLLOCATION)"
    assert_within(abs(direct.torque - fast.torque), COLLOCATION["torque"], reason)
    assert_within(abs(direct.rigid_rotation - fast.rigid_rotation), COLLOCATION["rigid_rotation"], reason)
    assert_close(direct.interface_traction(r), fast.interface_traction(r), reason, atol=COLLOCATION["traction"])
