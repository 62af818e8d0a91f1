"""Every closed form of eqs. (35), (51)-(53) against independent quadrature, lambda up to 1e4."""

import mpmath
import numpy as np
import pytest
from oscillatory_quadrature import integrate
from scipy import special
from tolerances import EPS, assert_close, assert_within

from torsional_contact.special import integrals
from torsional_contact.special.zeros import bessel_j2_zeros

LAM = bessel_j2_zeros(3200)  # lambda_3200 ~ 1.005e4
INDICES = [1, 2, 3, 10, 100, 1000, 3200]
RADII = [0.05, 0.3, 0.6, 0.95]


def j1(x):
    return special.j1(x)


@pytest.mark.parametrize("m", INDICES)
def test_dini_norm_eq35(m):
    lam = LAM[m - 1]
    expected = integrate(lambda r: j1(lam * r) ** 2 * r, 0.0, 1.0, 2 * lam)
    # the quadrature (tests/oscillatory_quadrature.py: ~1e-14 of the integrand's size) relative to h ~ 1/(pi lam),
    # and the closed form's rounding with J0, J1 at lam (conditioning lam EPS)
    assert_within(abs(integrals.dini_norm(lam) / expected - 1), 1e-14 * np.pi * lam + 16 * lam * EPS,
                  "quadrature relative to h + conditioning of J(lam)")
    # at a zero of J2 it reduces to J1(lam)^2 / 2: the same to the conditioning of J0, J1 at the rounded zero
    assert_within(abs(integrals.dini_norm(lam) / (0.5 * j1(lam) ** 2) - 1), 16 * lam * EPS, "conditioning lam EPS")


X_GRID = [1e-3, 0.1, 1.0, 1.99, 2.01, 5.0, 11.5, 14.0, 17.0, 19.0, 20.0, 22.0, 25.5, 30.0, 39.9, 40.1, 100.0, 1e3, 1e4]


@pytest.mark.parametrize("x", X_GRID)
def test_integral_t_j1_against_the_printed_hypergeometric_at_30_digits(x):
    with mpmath.workdps(30):
        exact = mpmath.mpf(x) ** 3 / 6 * mpmath.hyp1f2(1.5, 2, 2.5, -mpmath.mpf(x) ** 2 / 4)
    # Neumann's series (2 <= x <= 40) of up to ~50 terms: 50 ulp of the largest term (~ the result, |G| >= 1): 2.5e-14
    # relative; plus ten times the conditioning eps * x * |G'(x)| <= 0.8 eps x^1.5 (G' = x J1(x))
    tolerance = 2.5e-14 * max(1.0, abs(float(exact))) + 10 * 0.8 * EPS * x**1.5
    assert_within(abs(integrals.integral_t_j1(np.array([x]))[0] - float(exact)), tolerance,
                  "50 ulp of the series + conditioning eps x^1.5")


@pytest.mark.parametrize("x", [11.5, 14.0, 19.0, 20.0, 25.5])
def test_scipy_itj0y0_is_the_hazard_we_avoid(x):
    # documents why integral_t_j1 uses Neumann's series for 2 <= x <= 40
    with mpmath.workdps(30):
        exact = float(mpmath.mpf(x) ** 3 / 6 * mpmath.hyp1f2(1.5, 2, 2.5, -mpmath.mpf(x) ** 2 / 4))
    naive = special.itj0y0(x)[0] - x * special.j0(x)
    ours = integrals.integral_t_j1(np.array([x]))[0]
    assert_within(abs(ours - exact), 2.5e-14 * max(1, abs(exact)), "50 ulp of the series")
    assert 2.5e-14 * max(1, abs(exact)) < abs(naive - exact)  # the hazard: scipy's itj0y0 loses far more


@pytest.mark.parametrize("m", INDICES)
@pytest.mark.parametrize("b", RADII)
def test_load_vector_eq51(m, b):
    lam = LAM[m - 1]
    torque = 1.2
    expected = integrate(lambda r: (torque * r - 1.0) * j1(lam * r) * r, b, 1.0, lam)
    got = integrals.load_vector(np.array([lam]), b, torque)[0]
    scale = integrate(lambda r: np.abs(j1(lam * r)) * r, b, 1.0, lam)
    # relative to the integrand's size (the quadrature ~1e-14), plus the conditioning of J1(lam r) in lam
    assert_within(abs(got - expected), 1e-13 * scale + 1e-16 * lam**0.5, "quadrature + conditioning in lam")


@pytest.mark.parametrize("m", INDICES)
@pytest.mark.parametrize("b", RADII)
def test_stick_moment_and_torque_free_eigenfunctions(m, b):
    lam = LAM[m - 1]
    stick = integrate(lambda r: r**2 * j1(lam * r), 0.0, b, lam)
    whole = integrate(lambda r: r**2 * j1(lam * r), 0.0, 1.0, lam)
    # b^2 J2(lam b) / lam is known to about eps * lam b |J2'| b^2 / lam (phase error of lam b)
    conditioning = 4e-16 * b**3.5 * lam**0.5
    # quadrature (~1e-14 of the integrand, over a length b, integrand ~ b^2 / sqrt(lam)) + the conditioning
    assert_close(integrals.stick_moment(lam, b), stick, "quadrature + phase conditioning of J2(lam b)",
                 atol=1e-13 / lam + conditioning)
    # J2(lam) = 0: no eigenfunction carries torque; the quadrature's accuracy (~1e-14 x its integrand's size)
    assert_within(abs(whole), 1e-13, "quadrature of a sign-changing integrand of size < 1")


@pytest.mark.parametrize("b", RADII)
def test_lommel_matrix_eq52_eq53(b):
    idx = np.array(INDICES) - 1
    lam = LAM[idx]
    matrix = integrals.lommel_matrix(lam, b)
    for i, lam_m in enumerate(lam):
        for j, lam_n in enumerate(lam):
            expected = integrate(lambda r, m=lam_m, n=lam_n: j1(m * r) * j1(n * r) * r, b, 1.0, lam_m + lam_n)
            scale = 1.0 / np.sqrt(lam_m * lam_n)  # size of the integrand
            # quadrature (~1e-14 x the integrand) and the closed form's rounding with J at lam (lam EPS x scale)
            assert_within(abs(matrix[i, j] - expected), 1e-12 * scale, "quadrature + conditioning, of the size")


def test_lommel_integral_general_lambda():
    for lam_m, lam_n, lo, hi in [(3.3, 7.1, 0.2, 0.9), (1e3 + 0.5, 2.5e3, 0.0, 1.0), (9e3, 1e4, 0.4, 0.6)]:
        expected = integrate(lambda r, m=lam_m, n=lam_n: j1(m * r) * j1(n * r) * r, lo, hi, lam_m + lam_n)
        got = integrals.lommel_integral(lam_m, lam_n, lo, hi)
        assert_within(abs(got - expected), 1e-12 / np.sqrt(lam_m * lam_n) + 1e-14,
                      "quadrature + conditioning, of the integrand's size")


def test_coupling_matrix_is_lommel_times_lambda_n_lambda_n_minus_one():
    lam = LAM[:6]
    c = integrals.coupling_matrix(lam, 0.5)
    i = integrals.lommel_matrix(lam, 0.5)
    # the same product formed in another order: three roundings of half an ulp each, 1.5 EPS; 16 EPS
    assert_close(c, i * lam * (lam - 1), "three roundings", rtol=16 * EPS)


def test_limits_b_zero_and_one():
    lam = LAM[:50]
    # closed forms at b = 0 against (35): rounding with the conditioning of J at lam (lam EPS)
    assert_close(np.diag(integrals.lommel_matrix(lam, 0.0)), integrals.dini_norm(lam), "conditioning lam EPS",
                 rtol=16 * lam * EPS)
    # at b = 1 the integrals vanish; their closed forms cancel to the rounding of terms ~ J(lam)^2 / lam <= 1
    assert_close(integrals.lommel_matrix(lam, 1.0), 0.0, "cancellation of O(1) terms: 8 ulp", atol=8 * EPS)
    assert_close(integrals.load_vector(lam, 1.0, 1.3), 0.0, "cancellation of O(1) terms: 8 ulp", atol=8 * EPS)


def test_load_integral_constant_keeps_g_at_the_eigenvalues_without_mixing_them_up():
    """G(lam) of ``load_integral_constant`` is kept per eigenvalue array: the numbers of a fresh
    (G(lam) - G(lam b)) / lam^2 at every b, for the array it was computed for and not for another of the same size
    (one eigenvalue moved by 0.1 %: its G changes), nor for a 2-d or a non-contiguous array (not kept)."""
    lam = bessel_j2_zeros(145)
    nudged = lam.copy()
    nudged[77] *= 1.001
    assert integrals.integral_t_j1(nudged[77:78])[0] != integrals.integral_t_j1(lam[77:78])[0]
    for values in (lam, nudged, lam[::2], np.stack([lam, nudged])):
        for b in (0.05, 0.6, 0.98):
            fresh = (integrals.integral_t_j1(values) - integrals.integral_t_j1(values * b)) / (values * values)
            assert np.array_equal(integrals.load_integral_constant(values, b), fresh)
    # the kept values cannot be changed by a caller
    kept = integrals._integral_t_j1_kept(lam.tobytes())
    with pytest.raises(ValueError):
        kept[0] = 0.0
