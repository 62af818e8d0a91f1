"""Zeros of the Bessel function J2: the eigenvalues of eq. (19)-(20).

The traction-free lateral surface, eq. (18), requires J2(lambda a) = 0, so the
eigenvalues of the corrective Dini series (21) are lambda_n = lambda_{2,n} / a, where
lambda_{2,n} is the n-th positive zero of J2 (eq. 20).  All lengths in this package
are in units of the cylinder radius a, so ``lambda_n = lambda_{2,n}`` (dimensionless).

The zeros are computed by McMahon's asymptotic expansion (DLMF 10.21.19) as a
starting value, refined by Newton's method on J2 with J2'(x) = J1(x) - 2 J2(x)/x.
For every n >= 1 the refined zeros agree with mpmath's ``besseljzero(2, n)`` to
within a few ulp (see ``tests/test_zeros.py``).
"""

from __future__ import annotations

import functools

import numpy as np
from scipy import special

__all__ = ["bessel_j2_zeros", "PAPER_J2_ZEROS"]

#: The five zeros printed after eq. (20) of the paper (4 decimals, as printed).
PAPER_J2_ZEROS = (5.1356, 8.4172, 11.6198, 14.7960, 17.9598)

_NEWTON_STEPS = 5


def _mcmahon(n: np.ndarray) -> np.ndarray:
    """McMahon's expansion of the n-th zero of J_nu for nu = 2 (DLMF 10.21.19)."""
    mu = 16.0  # 4 nu^2
    beta = (n + 0.5 * 2 - 0.25) * np.pi
    eight_beta = 8.0 * beta
    return (
        beta
        - (mu - 1) / eight_beta
        - 4 * (mu - 1) * (7 * mu - 31) / (3 * eight_beta**3)
        - 32 * (mu - 1) * (83 * mu**2 - 982 * mu + 3779) / (15 * eight_beta**5)
    )


@functools.lru_cache(maxsize=8)
def _zeros_cached(n_zeros: int) -> np.ndarray:
    index = np.arange(1, n_zeros + 1, dtype=float)
    x = _mcmahon(index)
    for _ in range(_NEWTON_STEPS):
        j2 = special.jv(2, x)
        dj2 = special.j1(x) - 2.0 * j2 / x
        x = x - j2 / dj2
    x.flags.writeable = False
    return x


def bessel_j2_zeros(n_zeros: int) -> np.ndarray:
    """First ``n_zeros`` positive zeros lambda_{2,n} of J2 (eq. 20), ascending.

    Parameters
    ----------
    n_zeros : int
        How many zeros, >= 1.

    Returns
    -------
    ndarray of shape (n_zeros,)
        Dimensionless zeros (read-only, cached).  lambda_{2,1} = 5.1356223...
    """
    if isinstance(n_zeros, bool) or not isinstance(n_zeros, (int, np.integer)):
        raise ValueError(f"n_zeros must be an integer >= 1, got {n_zeros!r}")
    if n_zeros < 1:
        raise ValueError(f"n_zeros must be an integer >= 1, got {n_zeros}")
    return _zeros_cached(int(n_zeros))
