"""Every closed form of eqs. (35), (51)-(53) against independent quadrature, lambda up to 1e4."""

import mpmath
import numpy as np
import pytest
from quadrature import integrate
from scipy import special

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
    assert integrals.dini_norm(lam) == pytest.approx(expected, rel=1e-12)
    # at a zero of J2 it reduces to J1(lam)^2 / 2
    assert integrals.dini_norm(lam) == pytest.approx(0.5 * j1(lam) ** 2, rel=1e-12)


X_GRID = [1e-3, 0.1, 1.0, 1.99, 2.01, 5.0, 11.5, 14.0, 17.0, 19.0, 20.0, 22.0, 25.5, 30.0, 39.9, 40.1, 100.0, 1e3, 1e4]


@pytest.mark.parametrize("x", X_GRID)
def test_integral_t_j1_against_the_printed_hypergeometric_at_30_digits(x):
    with mpmath.workdps(30):
        exact = mpmath.mpf(x) ** 3 / 6 * mpmath.hyp1f2(1.5, 2, 2.5, -mpmath.mpf(x) ** 2 / 4)
    # a few ulp of the result, plus the conditioning eps * x * |G'(x)| ~ eps x^1.5
    tolerance = 2.5e-14 * max(1.0, abs(float(exact))) + 2.3e-16 * x**1.5
    assert abs(integrals.integral_t_j1(np.array([x]))[0] - float(exact)) <= tolerance


@pytest.mark.parametrize("x", [11.5, 14.0, 19.0, 20.0, 25.5])
def test_scipy_itj0y0_is_the_hazard_we_avoid(x):
    # documents why integral_t_j1 uses Neumann's series for 2 <= x <= 40
    with mpmath.workdps(30):
        exact = float(mpmath.mpf(x) ** 3 / 6 * mpmath.hyp1f2(1.5, 2, 2.5, -mpmath.mpf(x) ** 2 / 4))
    naive = special.itj0y0(x)[0] - x * special.j0(x)
    ours = integrals.integral_t_j1(np.array([x]))[0]
    assert abs(ours - exact) < 2.5e-14 * max(1, abs(exact)) < abs(naive - exact)


@pytest.mark.parametrize("m", INDICES)
@pytest.mark.parametrize("b", RADII)
def test_load_vector_eq51(m, b):
    lam = LAM[m - 1]
    torque = 1.2
    expected = integrate(lambda r: (torque * r - 1.0) * j1(lam * r) * r, b, 1.0, lam)
    got = integrals.load_vector(np.array([lam]), b, torque)[0]
    scale = integrate(lambda r: np.abs(j1(lam * r)) * r, b, 1.0, lam)
    # relative to the integrand's size, plus the conditioning of J1(lam r) in lam
    assert abs(got - expected) <= 1e-13 * scale + 1e-16 * lam**0.5


@pytest.mark.parametrize("m", INDICES)
@pytest.mark.parametrize("b", RADII)
def test_stick_moment_and_torque_free_eigenfunctions(m, b):
    lam = LAM[m - 1]
    stick = integrate(lambda r: r**2 * j1(lam * r), 0.0, b, lam)
    whole = integrate(lambda r: r**2 * j1(lam * r), 0.0, 1.0, lam)
    # b^2 J2(lam b) / lam is known to about eps * lam b |J2'| b^2 / lam (phase error of lam b)
    conditioning = 4e-16 * b**3.5 * lam**0.5
    assert integrals.stick_moment(lam, b) == pytest.approx(stick, abs=1e-13 / lam + conditioning)
    assert abs(whole) < 1e-13  # J2(lam) = 0: no eigenfunction carries torque


@pytest.mark.parametrize("b", RADII)
def test_lommel_matrix_eq52_eq53(b):
    idx = np.array(INDICES) - 1
    lam = LAM[idx]
    matrix = integrals.lommel_matrix(lam, b)
    for i, lam_m in enumerate(lam):
        for j, lam_n in enumerate(lam):
            expected = integrate(lambda r, m=lam_m, n=lam_n: j1(m * r) * j1(n * r) * r, b, 1.0, lam_m + lam_n)
            scale = 1.0 / np.sqrt(lam_m * lam_n)  # size of the integrand
            assert abs(matrix[i, j] - expected) <= 1e-12 * scale, (lam_m, lam_n, b)


def test_lommel_integral_general_lambda():
    for lam_m, lam_n, lo, hi in [(3.3, 7.1, 0.2, 0.9), (1e3 + 0.5, 2.5e3, 0.0, 1.0), (9e3, 1e4, 0.4, 0.6)]:
        expected = integrate(lambda r, m=lam_m, n=lam_n: j1(m * r) * j1(n * r) * r, lo, hi, lam_m + lam_n)
        got = integrals.lommel_integral(lam_m, lam_n, lo, hi)
        assert abs(got - expected) <= 1e-12 / np.sqrt(lam_m * lam_n) + 1e-14


def test_coupling_matrix_is_lommel_times_lambda_n_lambda_n_minus_one():
    lam = LAM[:6]
    c = integrals.coupling_matrix(lam, 0.5)
    i = integrals.lommel_matrix(lam, 0.5)
    np.testing.assert_allclose(c, i * lam * (lam - 1), rtol=1e-15)


def test_limits_b_zero_and_one():
    lam = LAM[:50]
    np.testing.assert_allclose(np.diag(integrals.lommel_matrix(lam, 0.0)), integrals.dini_norm(lam), rtol=1e-12)
    np.testing.assert_allclose(integrals.lommel_matrix(lam, 1.0), 0.0, atol=1e-15)
    np.testing.assert_allclose(integrals.load_vector(lam, 1.0, 1.3), 0.0, atol=1e-15)
