"""Dense solves of the weak forms: row and column equilibration and the 1-norm condition number.

One place for the scaling that ``weak_form`` solves with, the incremental oracle reuses and
the precision cross-checks measure.
"""

from __future__ import annotations

import numpy as np
from scipy import linalg

__all__ = ["equilibrate", "equilibrated_solve", "reciprocal_condition", "scalings"]


def _max_abs(matrix, axis):
    """max |a| along ``axis`` without an |A| temporary (the same numbers: max |a| = max(max a, -min a))."""
    return np.maximum(np.max(matrix, axis=axis), -np.min(matrix, axis=axis))


def scalings(matrix):
    """(row, col): the row then column scale factors to unit max-norm that ``equilibrate`` applies."""
    row = 1.0 / _max_abs(matrix, 1)
    col = 1.0 / _max_abs(matrix * row[:, None], 0)
    return row, col


def _scaled(matrix):
    """(matrix * row) * col (the row and column scaling), in one array: the same bits as the two products."""
    row = 1.0 / _max_abs(matrix, 1)
    scaled = matrix * row[:, None]
    col = 1.0 / _max_abs(scaled, 0)
    scaled *= col[None, :]
    return scaled, row, col


#: Matrices of at least this many entries are summed without a temporary (8 MB).
_LARGE = 1 << 20


def _column_abs_sums(matrix):
    """sum_i |a_ij|: ``np.sum(np.abs(matrix), axis=0)``, for large (square, C-ordered) matrices added row after
    row, the order in which numpy reduces their outer axis (the same numbers), without the |A| temporary."""
    if matrix.size < _LARGE or matrix.shape[1] < 64:  # numpy may sum a narrow matrix's columns pairwise
        return np.sum(np.abs(matrix), axis=0)
    sums = np.abs(matrix[0])
    buffer = np.empty_like(sums)
    for row in matrix[1:]:
        sums += np.abs(row, out=buffer)
    return sums


def equilibrate(matrix):
    """Row then column scaling of ``matrix`` to unit max-norm (what ``equilibrated_solve`` factors)."""
    row, col = scalings(matrix)
    return matrix * row[:, None] * col[None, :]


def reciprocal_condition(matrix) -> float:
    """LAPACK's estimate (dgecon) of 1 / (||A||_1 ||A^-1||_1), within a small factor of the exact value."""
    lu, _ = linalg.lu_factor(matrix, check_finite=True)
    anorm = np.max(np.sum(np.abs(matrix), axis=0))
    rcond, _ = linalg.lapack.dgecon(lu, anorm, norm="1")
    return float(rcond)


def equilibrated_solve(matrix, rhs):
    """LU solve after row and column scaling to unit max-norm; returns (x, rcond of the scaled matrix).

    The scaled matrix is formed in one array; besides it, only the Fortran-ordered copy that LAPACK
    factors has the matrix's size (at N = 4640 each is 170 MB); the numbers are those of the plain
    expressions (``tests/test_equilibration.py``).  The finiteness check of ``lu_factor`` is made on the
    column sums (a nan or an inf in the scaled matrix makes its column's sum one; its entries are <= 1).
    """
    matrix = np.ascontiguousarray(matrix, dtype=float)
    scaled, row, col = _scaled(matrix)
    column_sums = _column_abs_sums(scaled)
    if not np.all(np.isfinite(column_sums)):
        raise ValueError("matrix must be finite (it contains an inf or a nan)")
    anorm = np.max(column_sums)
    lu, piv = linalg.lu_factor(scaled, overwrite_a=True, check_finite=False)
    del scaled
    rcond, _ = linalg.lapack.dgecon(lu, anorm, norm="1")
    x = linalg.lu_solve((lu, piv), rhs * row[:, None])
    return x * col[:, None], float(rcond)
