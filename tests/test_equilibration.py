"""The equilibrated dense solve of the weak forms (``solvers.equilibration``) and the Lommel matrix it solves.

The solve forms the scaled matrix in one array and sums the columns' absolute values by blocks (no
temporaries of the matrix's size); these tests hold it to the plain expressions, which it must
reproduce bit for bit (T*, omega and the coefficients of ``solve`` do not depend on the memory it
saves), and to an independent solve in 50 digits.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy import linalg

from torsional_contact.solvers import equilibration
from torsional_contact.solvers.weak_form import assemble, complete_border
from torsional_contact.special import integrals
from torsional_contact.special.zeros import bessel_j2_zeros


def plain_equilibrated_solve(matrix, rhs):
    """The textbook form: row max-norm scaling, then columns, LU of the scaled copy, dgecon."""
    row = 1.0 / np.max(np.abs(matrix), axis=1)
    col = 1.0 / np.max(np.abs(matrix * row[:, None]), axis=0)
    scaled = matrix * row[:, None] * col[None, :]
    lu, piv = linalg.lu_factor(scaled, check_finite=True)
    anorm = np.max(np.sum(np.abs(scaled), axis=0))
    rcond, _ = linalg.lapack.dgecon(lu, anorm, norm="1")
    return linalg.lu_solve((lu, piv), rhs * row[:, None]) * col[:, None], float(rcond)


def plain_lommel(lam, b):
    x = lam * b
    j0b, j1b = integrals.special.j0(x), integrals.special.j1(x)
    diff = lam[:, None] ** 2 - lam[None, :] ** 2
    np.fill_diagonal(diff, 1.0)
    return -b * (lam[None, :] * j1b[:, None] * j0b[None, :] - lam[:, None] * j0b[:, None] * j1b[None, :]) / diff


@pytest.mark.parametrize("shape", [(1, 1), (2, 1), (300, 1), (3, 7), (17, 8), (255, 256), (300, 257), (40, 1000),
                                   (1161, 1161), (1025, 1025)])
def test_column_abs_sums_are_numpys(shape, monkeypatch):
    monkeypatch.setattr(equilibration, "_LARGE", 0)  # the row-by-row sum at every size it takes
    rng = np.random.default_rng(shape[1])
    matrix = rng.standard_normal(shape) * np.exp(rng.uniform(-30, 30, shape[0]))[:, None]
    assert np.array_equal(equilibration._column_abs_sums(matrix), np.sum(np.abs(matrix), axis=0))


@pytest.mark.parametrize("n_terms", [145, 580])
@pytest.mark.parametrize("method", ["published", "complete"])
@pytest.mark.parametrize("b", [0.1, 0.6, 0.9])
def test_weak_form_solve_is_the_plain_one(method, b, n_terms):
    matrix, rhs_torque, rhs_constant = assemble(method, bessel_j2_zeros(n_terms), b)
    rhs = np.column_stack([rhs_torque, rhs_constant])
    x, rcond = equilibration.equilibrated_solve(matrix.copy(), rhs)
    x_plain, rcond_plain = plain_equilibrated_solve(matrix, rhs)
    assert np.array_equal(x, x_plain)
    # dgecon is not reproducible to the last bit from call to call (OpenBLAS's kernels depend on the
    # alignment of the factors: 2 ulp seen); 1e-13 relative is 500 ulp
    assert rcond == pytest.approx(rcond_plain, rel=1e-13)


@pytest.mark.parametrize("b", [0.0, 0.1, 0.6, 0.98, 1.0])
def test_lommel_matrix_is_the_plain_expression(b):
    lam = bessel_j2_zeros(300)
    matrix = integrals.lommel_matrix(lam, b)
    off = ~np.eye(lam.size, dtype=bool)
    assert np.array_equal(matrix[off], plain_lommel(lam, b)[off])


@pytest.mark.parametrize("b", [0.0, 0.6, 1.0])
def test_lommel_matrix_is_the_same_in_any_layout(b):
    """Written into a Fortran-ordered array or into the leading block of a bordered one (either order), by
    blocks of rows or of columns: the same entries bit for bit, and the border untouched."""
    lam = bessel_j2_zeros(300)
    n = lam.size
    matrix = integrals.lommel_matrix(lam, b)
    assert np.array_equal(integrals.lommel_matrix(lam, b, out=np.empty((n, n), order="F")), matrix)
    for order in ("C", "F"):
        bordered = np.full((n + 1, n + 1), 7.0, order=order)
        integrals.lommel_matrix(lam, b, out=bordered[:n, :n])
        assert np.array_equal(bordered[:n, :n], matrix)
        assert np.all(bordered[n, :] == 7.0) and np.all(bordered[:, n] == 7.0)
    with pytest.raises(ValueError, match="out must be a float array of shape"):
        integrals.lommel_matrix(lam, b, out=np.empty((n, n + 1)))


@pytest.mark.parametrize("method", ["published", "complete"])
@pytest.mark.parametrize("b", [0.1, 0.9])
def test_assemble_in_fortran_order_is_the_same_system(method, b):
    lam = bessel_j2_zeros(200)
    matrix, rhs_torque, rhs_constant = assemble(method, lam, b)
    matrix_f, rhs_torque_f, rhs_constant_f = assemble(method, lam, b, order="F")
    assert matrix_f.flags.f_contiguous
    assert np.array_equal(matrix_f, matrix) and np.array_equal(rhs_torque_f, rhs_torque)
    assert np.array_equal(rhs_constant_f, rhs_constant)
    if method == "complete":
        n = lam.size
        column, row, corner, torque_last, constant_last = complete_border(lam, b)
        published, _, _ = assemble("published", lam, b)
        assert np.array_equal(matrix[:n, :n], published)
        assert np.array_equal(matrix[:n, n], column) and np.array_equal(matrix[n, :n], row)
        assert matrix[n, n] == corner and rhs_torque[n] == torque_last and rhs_constant[n] == constant_last


def _badly_scaled(shape, order="C"):
    rng = np.random.default_rng(shape[0] * 7 + shape[1])
    matrix = rng.standard_normal(shape) * np.exp(rng.uniform(-30, 30, shape[0]))[:, None]
    return np.asarray(matrix * np.exp(rng.uniform(-30, 30, shape[1]))[None, :], order=order)


@pytest.mark.parametrize("shape", [(1, 1), (300, 257), (257, 300), (40, 1000), (1161, 1161)])
@pytest.mark.parametrize("order", ["C", "F"])
def test_blocked_scalings_are_the_plain_ones(shape, order, monkeypatch):
    """Blocks of rows (of columns in Fortran order) at every size, several blocks and a short last one: the
    plain expressions bit for bit (maxima are exact)."""
    monkeypatch.setattr(equilibration, "_LARGE", 0)
    monkeypatch.setattr(equilibration, "_BLOCK_ENTRIES", 3000)
    matrix = _badly_scaled(shape, order)
    row = 1.0 / np.max(np.abs(matrix), axis=1)
    col = 1.0 / np.max(np.abs(matrix * row[:, None]), axis=0)
    row_b, col_b = equilibration.scalings(matrix)
    assert np.array_equal(row_b, row) and np.array_equal(col_b, col)


@pytest.mark.parametrize("shape", [(1, 1), (300, 257), (40, 1000), (1161, 1161)])
@pytest.mark.parametrize("large", [True, False])
def test_equilibrate_in_place_against_equilibrate_and_exact_sums(shape, large, monkeypatch):
    """The scaled entries are ``equilibrate``'s bit for bit; the column sums of their absolute values are within
    (m - 1) EPS of the exact sums (math.fsum) of the m non-negative terms, the bound of any order of summation."""
    if large:
        monkeypatch.setattr(equilibration, "_LARGE", 0)
        monkeypatch.setattr(equilibration, "_BLOCK_ENTRIES", 3000)
    matrix = _badly_scaled(shape, "F")
    plain = equilibration.equilibrate(matrix)
    row, col, sums = equilibration.equilibrate_in_place(matrix)
    assert np.array_equal(matrix, plain) and matrix.flags.f_contiguous
    assert np.array_equal(row, 1.0 / np.max(np.abs(_badly_scaled(shape)), axis=1))
    exact = np.array([math.fsum(np.abs(plain[:, j])) for j in range(shape[1])])
    eps = np.finfo(float).eps
    assert np.all(np.abs(sums - exact) <= (shape[0] - 1) * eps * exact)


def test_badly_scaled_system_against_50_digits():
    """Rows and columns scaled over 10^+-40: the equilibrated solve recovers x to cond(scaled) eps."""
    rng = np.random.default_rng(2024)
    n = 12
    core = rng.standard_normal((n, n)) + n * np.eye(n)
    left, right = 10.0 ** rng.uniform(-40, 40, n), 10.0 ** rng.uniform(-40, 40, n)
    matrix = left[:, None] * core * right[None, :]
    rhs = rng.standard_normal((n, 1))
    x, rcond = equilibration.equilibrated_solve(matrix, rhs)
    with mpmath.workdps(50):  # the float matrix's exact solution: rows and columns unscaled exactly, then LU
        inner = mpmath.matrix(n, n)
        for i in range(n):
            for j in range(n):
                inner[i, j] = mpmath.mpf(matrix[i, j]) / mpmath.mpf(left[i]) / mpmath.mpf(right[j])
        unscaled_rhs = [mpmath.mpf(v) / mpmath.mpf(w) for v, w in zip(rhs[:, 0], left, strict=True)]
        y = mpmath.lu_solve(inner, mpmath.matrix(unscaled_rhs))
        exact = np.array([float(y[j] / mpmath.mpf(right[j])) for j in range(n)])
    # backward-stable LU of the equilibrated matrix: the error of right * x, relative to its max-norm, is below
    # about n eps / rcond (norm-wise perturbation bound); 100 n eps / rcond is >= 10x the worst of seeds 1-3, 2024
    error = np.max(np.abs(right * (x[:, 0] - exact))) / np.max(np.abs(right * exact))
    assert error < 100 * n * np.finfo(float).eps / rcond


def test_non_finite_matrix_is_refused():
    matrix = np.eye(4)
    matrix[1, 2] = np.nan
    with pytest.raises(ValueError, match="matrix must be finite"):
        equilibration.equilibrated_solve(matrix, np.ones((4, 1)))
    matrix[1, 2] = -np.inf
    with pytest.raises(ValueError, match="matrix must be finite"):
        equilibration.equilibrated_solve(matrix, np.ones((4, 1)))
