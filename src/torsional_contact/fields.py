"""Stresses and displacements of the series solution anywhere in the upper cylinder.

Units: r, z in a; stresses in f p0; displacements in f p0 a / mu (docs/conventions.md).
With amplitudes c_n = lam_n A~_n (see ``solvers.weak_form``), eqs. (4), (22)-(24) read

    u_theta(r, z)  = T* r z + omega r + sum_n c_n exp(-lam_n z) J1(lam_n r)
    sigma_zt(r, z) = T* r - sum_n c_n lam_n exp(-lam_n z) J1(lam_n r)
    sigma_rt(r, z) = -sum_n c_n lam_n exp(-lam_n z) J2(lam_n r)

Away from the interface the terms decay like exp(-lam_n z), so each point sums only
the terms it needs: the first k for which the bound

    sum_{n > k} |c_n| w_n exp(-lam_n z) max|J|  <=  tol

holds (w_n = lam_n for stresses, 1 for the displacement; max|J1| = 0.5819,
max|J2| = 0.4865).  This bounds the difference from the full N-term sum, not the
truncation of the series at N (which is the formulation's error).  On z = 0 all N
terms are summed; there the series converges slowly near r = b (see the
formulation's convergence study).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy import special

from .diagnostics import TruncationWarning

__all__ = ["terms_needed", "series_sum", "dini_terms", "DEFAULT_TOLERANCE", "MAX_FIELD_TERMS"]

#: Default absolute tolerance of the per-point truncation (units f p0 or f p0 a / mu).
DEFAULT_TOLERANCE = 1e-12
#: Largest number of Dini terms summed for fields at z > 0 from an interface traction
#: (the amplitudes cost ~N^2: 2.6 s at 4096 terms).
MAX_FIELD_TERMS = 4096
_MIN_FIELD_TERMS = 64

_MAX_ABS = {1: 0.5818652242815, 2: 0.4864711766}
_BLOCK = 32
_CHUNK_ENTRIES = 2_000_000  # points x terms evaluated at once (16 MB)


def terms_needed(eigenvalues, weights, z, tol):
    """Number of leading terms each point needs, from the exponential tail bound.

    Parameters
    ----------
    eigenvalues, weights : ndarray (N,)
        lam_n and |c_n| w_n (the magnitude of each term's coefficient at z = 0).
    z : ndarray
        Axial coordinates >= 0 (any shape).
    tol : float
        Absolute tolerance on the omitted tail (already divided by max|J|).

    Returns
    -------
    ndarray of int, shape of z: k in [0, N].
    """
    z = np.asarray(z, dtype=float)
    unique_z, inverse = np.unique(z.ravel(), return_inverse=True)
    decay = np.exp(-np.outer(unique_z, eigenvalues)) * weights[None, :]
    # tail[k] = sum_{n >= k} (0-based): reverse cumulative sum
    tail = np.cumsum(decay[:, ::-1], axis=1)[:, ::-1]
    # first k with tail[k] <= tol (tail after dropping terms k..N-1); N if none
    ok = tail <= tol
    k = np.where(ok.any(axis=1), np.argmax(ok, axis=1), eigenvalues.size)
    return k[inverse].reshape(z.shape)


def series_sum(order, eigenvalues, coefficients, r, z, tol=DEFAULT_TOLERANCE):
    """sum_n coefficients_n exp(-lam_n z) J_order(lam_n r), truncated per point.

    Parameters
    ----------
    order : {1, 2}
        Bessel order.
    eigenvalues, coefficients : ndarray (N,)
    r, z : array_like, broadcastable; 0 <= r <= 1, z >= 0.
    tol : float
        Absolute tolerance on the omitted terms (z > 0); 0 sums every term.

    Returns
    -------
    ndarray with the broadcast shape of r and z.
    """
    r, z = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(z, dtype=float))
    shape = r.shape
    r, z = r.ravel(), z.ravel()
    bessel = special.j1 if order == 1 else (lambda x: special.jv(2, x))
    if tol > 0:
        k = terms_needed(eigenvalues, np.abs(coefficients), z, tol / _MAX_ABS[order])
    else:
        k = np.full(r.shape, eigenvalues.size)
    out = np.zeros(r.shape)
    # Group points by the number of terms (rounded up to a block) to stay vectorised.
    k_block = np.minimum(-(-k // _BLOCK) * _BLOCK, eigenvalues.size)
    for n_sum in np.unique(k_block):
        if n_sum == 0:
            continue
        lam = eigenvalues[:n_sum]
        group = np.nonzero(k_block == n_sum)[0]
        chunk = max(1, _CHUNK_ENTRIES // int(n_sum))
        for start in range(0, group.size, chunk):
            idx = group[start : start + chunk]
            terms = bessel(np.outer(r[idx], lam)) * np.exp(-np.outer(z[idx], lam))
            out[idx] = terms @ coefficients[:n_sum]
    return out.reshape(shape)


def dini_terms(z_min: float, tolerance: float) -> int:
    """Dini terms for fields at z >= z_min > 0 to ``tolerance`` (a power of two, 64 to ``MAX_FIELD_TERMS``).

    The tail beyond N terms decays like exp(-lambda_N z_min) with lambda_N ~ pi N, so
    N ~ ln(1/tolerance) / (pi z_min) terms are needed.  Beyond ``MAX_FIELD_TERMS`` the
    sum is truncated with a ``TruncationWarning``.
    """
    decades = math.log(1.0 / min(tolerance, 1.0)) if tolerance > 0 else math.inf
    needed = decades / (math.pi * z_min) + 1.0 if z_min > 0 else math.inf
    if needed > MAX_FIELD_TERMS:
        z_ok = decades / (math.pi * MAX_FIELD_TERMS)
        warnings.warn(
            f"fields at z < {z_ok:.2g} (asked down to z = {z_min:.2g}) are summed with "
            f"{MAX_FIELD_TERMS} Dini terms, short of tolerance={tolerance:g}: the omitted tail "
            f"is up to ~exp(-lambda_N z) = {math.exp(-math.pi * MAX_FIELD_TERMS * z_min):.1e} times the "
            "interface amplitude; the interface values (z = 0) are exact",
            TruncationWarning,
            stacklevel=4,
        )
        return MAX_FIELD_TERMS
    return max(_MIN_FIELD_TERMS, 1 << math.ceil(math.log2(needed)))
