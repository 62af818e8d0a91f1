"""Dense solves of the weak forms: row and column equilibration and the 1-norm condition number.

One place for the scaling that ``weak_form`` solves with, the incremental oracle reuses and
the precision cross-checks measure.
"""

from __future__ import annotations

import numpy as np
from scipy import linalg

__all__ = ["equilibrate", "equilibrate_in_place", "equilibrated_solve", "reciprocal_condition", "scalings"]


def _max_abs(matrix, axis):
    """max |a| along ``axis`` without an |A| temporary (the same numbers: max |a| = max(max a, -min a))."""
    return np.maximum(np.max(matrix, axis=axis), -np.min(matrix, axis=axis))


#: Matrices of at least this many entries are summed without a temporary (8 MB).
_LARGE = 1 << 20
#: Entries per block of rows in the blocked passes over large matrices (256 kB: in cache between a block's
#: operations).
_BLOCK_ENTRIES = 1 << 15


def _row_blocks(shape):
    """Slices of consecutive rows of about ``_BLOCK_ENTRIES`` entries covering a matrix of ``shape``."""
    step = max(1, _BLOCK_ENTRIES // max(shape[1], 1))
    return [slice(start, min(start + step, shape[0])) for start in range(0, shape[0], step)]


def _by_columns(matrix) -> bool:
    """Whether a large matrix is scanned by blocks of columns (it is stored column after column)."""
    return matrix.flags.f_contiguous and not matrix.flags.c_contiguous


def scalings(matrix):
    """(row, col): the row then column scale factors to unit max-norm that ``equilibrate`` applies.

    Large matrices are scanned by blocks of rows (of columns in Fortran order), without the row-scaled
    temporary: the same numbers (maxima are exact).
    """
    if matrix.size < _LARGE:
        row = 1.0 / _max_abs(matrix, 1)
        col = 1.0 / _max_abs(matrix * row[:, None], 0)
        return row, col
    if _by_columns(matrix):
        row_max = np.full(matrix.shape[0], -np.inf)
        row_min = np.full(matrix.shape[0], np.inf)
        blocks = _row_blocks(matrix.T.shape)
        for cols in blocks:
            block = matrix[:, cols]
            np.maximum(row_max, np.max(block, axis=1), out=row_max)
            np.minimum(row_min, np.min(block, axis=1), out=row_min)
        row = 1.0 / np.maximum(row_max, -row_min)
        col = np.empty(matrix.shape[1])
        for cols in blocks:
            col[cols] = 1.0 / _max_abs(matrix[:, cols] * row[:, None], 0)
        return row, col
    row = np.empty(matrix.shape[0])
    col_max = np.full(matrix.shape[1], -np.inf)
    col_min = np.full(matrix.shape[1], np.inf)
    for rows in _row_blocks(matrix.shape):
        block = matrix[rows]
        row[rows] = 1.0 / _max_abs(block, 1)
        block = block * row[rows, None]
        np.maximum(col_max, np.max(block, axis=0), out=col_max)
        np.minimum(col_min, np.min(block, axis=0), out=col_min)
    return row, 1.0 / np.maximum(col_max, -col_min)


def _scaled(matrix):
    """(matrix * row) * col (the row and column scaling), in one array: the same bits as the two products."""
    row = 1.0 / _max_abs(matrix, 1)
    scaled = matrix * row[:, None]
    col = 1.0 / _max_abs(scaled, 0)
    scaled *= col[None, :]
    return scaled, row, col


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


def equilibrate_in_place(matrix):
    """Overwrite ``matrix`` with ``equilibrate(matrix)`` (the same numbers); returns (row, col, column_sums): the
    scalings and the column sums of the scaled entries' absolute values (their maximum is the 1-norm).

    A large matrix in Fortran order (the layout LAPACK factors in place) is scaled by blocks of columns, without
    a temporary of its size, and its columns are summed pairwise (numpy's sum along a contiguous axis): the
    sums of ``np.sum(np.abs(equilibrate(matrix)), axis=0)`` to (N + log2 N) EPS relative (each order of
    summation is within (N - 1) EPS of the exact sum of the N non-negative terms).  A nan or an inf among the
    scaled entries makes its column's sum non-finite (the finite ones are at most 1 in magnitude).
    """
    row, col = scalings(matrix)
    if matrix.size < _LARGE or not _by_columns(matrix):
        scaled = np.ascontiguousarray(matrix) * row[:, None] * col[None, :]
        matrix[...] = scaled
        return row, col, np.sum(np.abs(scaled), axis=0)
    sums = np.empty(matrix.shape[1])
    for cols in _row_blocks(matrix.T.shape):
        block = matrix[:, cols]
        block *= row[:, None]
        block *= col[None, cols]
        sums[cols] = np.sum(np.abs(block), axis=0)
    return row, col, sums


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
