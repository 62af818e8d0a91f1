"""Dense solves of the weak forms: row and column equilibration and the 1-norm condition number.

One place for the scaling that ``weak_form`` solves with, the incremental oracle reuses and
the precision cross-checks measure.
"""

from __future__ import annotations

import numpy as np
from scipy import linalg

__all__ = ["equilibrate", "equilibrated_solve", "reciprocal_condition", "scalings"]


def scalings(matrix):
    """(row, col): the row then column scale factors to unit max-norm that ``equilibrate`` applies."""
    row = 1.0 / np.max(np.abs(matrix), axis=1)
    col = 1.0 / np.max(np.abs(matrix * row[:, None]), axis=0)
    return row, col


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
    """LU solve after row and column scaling to unit max-norm; returns (x, rcond of the scaled matrix)."""
    row, col = scalings(matrix)
    scaled = matrix * row[:, None] * col[None, :]
    lu, piv = linalg.lu_factor(scaled, check_finite=True)
    anorm = np.max(np.sum(np.abs(scaled), axis=0))
    rcond, _ = linalg.lapack.dgecon(lu, anorm, norm="1")
    x = linalg.lu_solve((lu, piv), rhs * row[:, None])
    return x * col[:, None], float(rcond)
