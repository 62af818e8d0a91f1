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

When the Dini series represents an exact solution (the Abel-Fredholm method), the terms
beyond N are estimated by ``tail_estimate`` from the decay of the computed amplitudes,
|c_n| ~ C n^(-p) (fitted to the envelope of the last quarter), so that a truncated sum
can say how much it misses.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

__all__ = [
    "terms_needed",
    "series_sum",
    "dini_terms",
    "required_terms",
    "tail_estimate",
    "DEFAULT_TOLERANCE",
    "MAX_FIELD_TERMS",
    "MAX_ABS_BESSEL",
]

#: Default absolute tolerance of the per-point truncation (units f p0 or f p0 a / mu).
DEFAULT_TOLERANCE = 1e-12
#: Largest number of Dini terms summed for fields at z > 0 from an interface traction
#: (the amplitudes cost ~N^2: 2.6 s at 4096 terms).
MAX_FIELD_TERMS = 4096
_MIN_FIELD_TERMS = 64

_MAX_ABS = {1: 0.5818652242815, 2: 0.4864711766}
#: max |J1| and max |J2| on the real line.
MAX_ABS_BESSEL = dict(_MAX_ABS)
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
    bessel_rows = _shared_rows(r, eigenvalues[: int(k_block.max(initial=0))], bessel)
    decay_rows = _shared_rows(z, eigenvalues[: int(k_block.max(initial=0))], lambda x: np.exp(-x))
    for n_sum in np.unique(k_block):
        if n_sum == 0:
            continue
        group = np.nonzero(k_block == n_sum)[0]
        chunk = max(1, _CHUNK_ENTRIES // int(n_sum))
        for start in range(0, group.size, chunk):
            idx = group[start : start + chunk]
            terms = bessel_rows(idx, n_sum) * decay_rows(idx, n_sum)
            out[idx] = terms @ coefficients[:n_sum]
    return out.reshape(shape)


def _shared_rows(coordinate, eigenvalues, function):
    """rows(idx, n) = function(outer(coordinate[idx], eigenvalues[:n])), each distinct coordinate evaluated once.

    Points on a grid share their r (or z) values: the table of the distinct values is computed once
    when it fits in ``_CHUNK_ENTRIES`` (the same numbers as evaluating per point), else per call.
    """
    distinct, inverse = np.unique(coordinate, return_inverse=True)
    if distinct.size == coordinate.size or distinct.size * eigenvalues.size > _CHUNK_ENTRIES:
        return lambda idx, n: function(np.outer(coordinate[idx], eigenvalues[:n]))
    table = function(np.outer(distinct, eigenvalues))
    return lambda idx, n: table[inverse[idx], :n]


def required_terms(z_min: float, tolerance: float) -> float:
    """Dini terms that fields at z >= z_min > 0 need for ``tolerance``: ln(1/tol) / (pi z_min) + 1.

    The tail beyond N terms decays like exp(-lambda_N z_min) with lambda_N ~ pi N.
    """
    decades = math.log(1.0 / min(tolerance, 1.0)) if tolerance > 0 else math.inf
    return decades / (math.pi * z_min) + 1.0 if z_min > 0 else math.inf


def dini_terms(z_min: float, tolerance: float) -> int:
    """Dini terms for fields at z >= z_min > 0 to ``tolerance`` (a power of two, 64 to ``MAX_FIELD_TERMS``).

    Capped at ``MAX_FIELD_TERMS``; the caller estimates what the cap loses with
    ``tail_estimate`` (``Solution`` warns once per call).
    """
    needed = required_terms(z_min, tolerance)
    if needed > MAX_FIELD_TERMS:
        return MAX_FIELD_TERMS
    return max(_MIN_FIELD_TERMS, 1 << math.ceil(math.log2(needed)))


def tail_estimate(eigenvalues, amplitudes, weight_power: int, z_min: float, radius: float | None = None) -> float:
    """Estimate of the omitted terms sum_{n > N} c_n lam_n^p exp(-lam_n z_min) J(lam_n r) (f p0 or f p0 a / mu).

    |c_n| ~ C n^(-alpha) is fitted (least squares in log-log) to the maxima of blocks of 8
    of the last quarter of the computed amplitudes (their envelope: c_n oscillates with
    lam_n b), lam_n ~ lam_N + pi (n - N), and the sum is replaced by its integral from
    N + 1/2.  |J(lam r)| is bounded by max|J1| = 0.582 (a bound, ~100 times the real error
    away from the axis), or, given ``radius`` (the stick edge b, where the terms add up in
    phase: c_n ~ cos(lam_n b + ...) against J(lam_n r) ~ cos(lam_n r - 3 pi/4) leaves half
    the product coherent at r = b), by half its envelope sqrt(2 / (pi lam radius)): then
    the estimate is ~1.4 times the largest real error over r (measured at z = 1e-3, 1e-4,
    1e-6 in tests/test_extremes.py).  0 for z_min <= 0 (interface values are not summed).
    """
    lam = np.asarray(eigenvalues, dtype=float)
    c = np.abs(np.asarray(amplitudes, dtype=float))
    n_terms = lam.size
    if z_min <= 0 or n_terms == 0 or not np.any(c):
        return 0.0
    start = max(0, n_terms - max(32, n_terms // 4))
    blocks = (n_terms - start) // 8
    if blocks >= 2:
        envelope = c[start : start + 8 * blocks].reshape(blocks, 8).max(axis=1)
        index = start + 8 * np.arange(blocks) + 4.5
        keep = envelope > 0
        slope, offset = np.polyfit(np.log(index[keep]), np.log(envelope[keep]), 1)
        alpha, scale = max(-slope, 0.0), math.exp(offset)
    else:
        alpha, scale = 0.0, float(c[-1])
    lam_n = float(lam[-1])

    def term(n):
        eigen = lam_n + math.pi * (n - n_terms)
        if radius is None:
            bessel = _MAX_ABS[1]
        else:
            bessel = 0.5 * min(_MAX_ABS[1], math.sqrt(2.0 / (math.pi * max(eigen * radius, 1e-300))))
        return scale * n ** (-alpha) * eigen**weight_power * math.exp(-eigen * z_min) * bessel

    from scipy import integrate  # here: importing it costs 0.3 CPU-s, and only this tail estimate needs it

    value, _ = integrate.quad(term, n_terms + 0.5, math.inf, limit=200)
    return float(value)
