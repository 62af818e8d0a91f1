"""Closed forms of the integrals of eq. (33)-(38) and Appendix B, in stable form.

Lengths are in units of the cylinder radius a (so the contact is 0 <= r <= 1), and
``lam`` is a dimensionless eigenvalue lambda_{2,n} (a zero of J2, eq. 20) unless a
function says it accepts any lambda.  With a = 1 the paper's formulas read:

* eq. (35): h(lam)   = int_0^1 J1(lam r)^2 r dr
                     = [J0^2 - 2 J0 J1 / lam + J1^2] / 2   (any lam)
                     = J1(lam)^2 / 2                       (when J2(lam) = 0).
* eq. (51): B_m      = int_b^1 (T* r - 1) J1(lam_m r) r dr
                     = T* * int_b^1 r^2 J1 dr - int_b^1 r J1 dr.
  The paper writes the second integral with 1F2(3/2; 2, 5/2; -x^2/4).  Summed as a
  power series in double precision that hypergeometric loses all digits once x is
  larger than about 30 (its terms grow like exp(x) while the sum is O(x^{3/2})), so
  ``integral_t_j1`` evaluates G(x) = int_0^x t J1(t) dt = x^3/6 1F2(...) by

      x < 2        the power series (alternating, no cancellation there);
      2 <= x <= 40 Neumann's series int_0^x J0 = 2 sum_k J_{2k+1}(x), minus x J0(x);
      x > 40       int_0^x J0(t) dt - x J0(x), int_0^x J0 from scipy's ``itj0y0``.

  The middle band exists because ``itj0y0`` is wrong by up to 5e-10 for
  11 < x < 35 (and ``struve`` by 5e-13 near x = 25), measured against mpmath.  The
  remaining error is at most ~2.5e-14 max(1, |G|) plus ~eps x^{3/2} absolute, the
  conditioning of G itself (G'(x) = x J1(x) and x is known to eps x): e.g. ~4e-13
  relative near x = 455 and ~1e-11 absolute at x = 1e4 (tests/test_integrals.py).
* eq. (52)-(53): C_mn = lam_n (lam_n - 1) I_mn with the Lommel integral
  I_mn = int_b^1 J1(lam_m r) J1(lam_n r) r dr.  For m != n the terms of (52)
  evaluated at r = 1 cancel exactly when J2(lam_m) = J2(lam_n) = 0 (because then
  J0(lam) = 2 J1(lam) / lam); we drop them instead of subtracting two rounded numbers.

Every closed form here is checked against Gauss-Legendre quadrature for lambda up to
1e4 in ``tests/test_integrals.py``.
"""

from __future__ import annotations

import functools

import numpy as np
from scipy import special

__all__ = [
    "dini_norm",
    "integral_t_j1",
    "stick_moment",
    "load_integral_linear",
    "load_integral_constant",
    "load_vector",
    "lommel_integral",
    "lommel_matrix",
    "coupling_matrix",
]

_SERIES_SWITCH = 2.0
_SERIES_TERMS = 30
_NEUMANN_SWITCH = 40.0
_NEUMANN_ORDERS = 2 * np.arange(int(_NEUMANN_SWITCH / 2) + 30) + 1  # J_{2k+1} negligible beyond


def dini_norm(lam):
    """h(lam) of eq. (35): int_0^1 J1(lam r)^2 r dr, valid for any lam > 0.

    Dimensionless (a = 1); the paper's h carries a factor a^2.
    """
    lam = np.asarray(lam, dtype=float)
    j0, j1 = special.j0(lam), special.j1(lam)
    return 0.5 * (j0 * j0 - 2.0 * j0 * j1 / lam + j1 * j1)


def integral_t_j1(x):
    """int_0^x t J1(t) dt = x^3/6 1F2(3/2; 2, 5/2; -x^2/4), stable for all x >= 0.

    The antiderivative behind the 1F2 of eq. (51); see the module docstring for the
    three ranges (power series, Neumann series, int_0^x J0 - x J0(x)).
    """
    x = np.asarray(x, dtype=float)
    out = np.empty_like(x)
    small = np.abs(x) < _SERIES_SWITCH
    xs = x[small]
    # sum_k (-1)^k x^(2k+3) / (2^(2k+1) (2k+3) k! (k+1)!)
    term = xs**3 / 2.0  # k = 0 without the 1/(2k+3) factor
    total = term / 3.0
    for k in range(1, _SERIES_TERMS):
        term = -term * xs * xs / (4.0 * k * (k + 1))
        total = total + term / (2 * k + 3)
    out[small] = total
    middle = ~small & (np.abs(x) <= _NEUMANN_SWITCH)
    xm = x[middle]
    odd = special.jv(_NEUMANN_ORDERS[None, ::-1], xm[:, None])  # smallest terms first
    out[middle] = 2.0 * np.sum(odd, axis=1) - xm * special.j0(xm)
    large = np.abs(x) > _NEUMANN_SWITCH
    xl = x[large]
    out[large] = special.itj0y0(xl)[0] - xl * special.j0(xl)
    return out


def stick_moment(lam, b):
    """S(lam) = int_0^b r^2 J1(lam r) dr = b^2 J2(lam b) / lam.

    The overlap of an eigenfunction with the rigid rotation r over the stick disc;
    it is minus ``load_integral_linear`` when J2(lam) = 0 (the eigenfunctions carry
    no torque: int_0^1 r^2 J1(lam r) dr = J2(lam) / lam = 0).
    """
    lam = np.asarray(lam, dtype=float)
    return b * b * special.jv(2, lam * b) / lam


def load_integral_linear(lam, b):
    """int_b^1 r^2 J1(lam r) dr for J2(lam) = 0: -b^2 J2(lam b) / lam (T* part of eq. 51)."""
    return -stick_moment(lam, b)


#: Largest set of eigenvalues whose G(lam) ``load_integral_constant`` keeps (``_integral_t_j1_kept``).
_KEPT_SIZE = 1 << 14


@functools.lru_cache(maxsize=16)
def _integral_t_j1_kept(eigenvalues: bytes) -> np.ndarray:
    """``integral_t_j1`` of the float64 array with these bytes (read-only), for the last few arrays asked for."""
    values = integral_t_j1(np.frombuffer(eigenvalues, dtype=float))
    values.flags.writeable = False
    return values


def load_integral_constant(lam, b):
    """int_b^1 r J1(lam r) dr = [G(lam) - G(lam b)] / lam^2, G(x) = int_0^x t J1(t) dt.

    The 1F2 part of eq. (51), in the stable form of ``integral_t_j1``.  Any lam > 0.  G(lam) does not depend
    on b: for a 1-d lam of up to ``_KEPT_SIZE`` entries it is kept for the last few lam (keyed on their bytes;
    the same numbers), so that a sweep over stick radii evaluates it once (its Neumann series costs about 1 ms
    for 145 eigenvalues, more than the rest of an N = 145 solve).
    """
    lam = np.asarray(lam, dtype=float)
    if lam.ndim == 1 and lam.size <= _KEPT_SIZE:
        at_lam = _integral_t_j1_kept(np.ascontiguousarray(lam).tobytes())
    else:
        at_lam = integral_t_j1(lam)
    return (at_lam - integral_t_j1(lam * b)) / (lam * lam)


def load_vector(lam, b, torque):
    """B_m of eq. (51): int_b^1 (T* r - 1) J1(lam_m r) r dr for J2(lam_m) = 0.

    Parameters
    ----------
    lam : array_like
        Zeros of J2 (dimensionless).
    b : float
        Stick radius b/a in [0, 1].
    torque : float
        T* = 2T/(f F a), eq. (32).
    """
    return torque * load_integral_linear(lam, b) - load_integral_constant(lam, b)


def lommel_integral(lam_m, lam_n, lower, upper):
    """int_lower^upper J1(lam_m r) J1(lam_n r) r dr for any lam_m != lam_n (Lommel).

    Uses x [lam_n J1(lam_m x) J0(lam_n x) - lam_m J0(lam_m x) J1(lam_n x)] /
    (lam_m^2 - lam_n^2) at both limits; the general form behind eq. (52).
    """
    lam_m = np.asarray(lam_m, dtype=float)
    lam_n = np.asarray(lam_n, dtype=float)

    def primitive(x):
        return x * (
            lam_n * special.j1(lam_m * x) * special.j0(lam_n * x)
            - lam_m * special.j0(lam_m * x) * special.j1(lam_n * x)
        )

    return (primitive(upper) - primitive(lower)) / (lam_m**2 - lam_n**2)


#: Entries per block of rows in ``lommel_matrix`` (256 kB: a block's operations run in cache, and no
#: temporary has the matrix's size).
_BLOCK_ENTRIES = 1 << 15


def lommel_matrix(lam, b, out=None):
    """I_mn = int_b^1 J1(lam_m r) J1(lam_n r) r dr for zeros lam of J2 (eq. 52, 53).

    Off the diagonal only the r = b terms of (52) are kept (the r = 1 terms cancel
    exactly at zeros of J2).  The diagonal is eq. (53) without its prefactor:
    h(lam) - (b^2/2) [J0(lam b)^2 + J1(lam b)^2 - 2 J0(lam b) J1(lam b) / (lam b)].

    ``out``: an (N, N) float array (a view is fine) to write the matrix to, e.g. the leading block of
    a bordered system; one whose columns are contiguous (Fortran order) is written column block by column
    block.  The entries do not depend on the layout.

    Returns
    -------
    ndarray of shape (len(lam), len(lam)), symmetric (``out`` if given).
    """
    lam = np.asarray(lam, dtype=float)
    n = lam.size
    if out is None:
        out = np.empty((n, n))
    elif out.shape != (n, n) or out.dtype != float:
        raise ValueError(f"out must be a float array of shape {(n, n)}, got {out.dtype} {out.shape}")
    x = lam * b
    j0b, j1b = special.j0(x), special.j1(x)
    lam_j0b, lam_sq = lam * j0b, lam**2
    # -b [lam_n J1(lam_m b) J0(lam_n b) - lam_m J0(lam_m b) J1(lam_n b)] / (lam_m^2 - lam_n^2), block of rows by
    # block of rows (the same operations, in the same order, as the plain expression); in Fortran order the
    # blocks are of rows of the transpose: index k runs over n, the other over m
    by_columns = out.ndim == 2 and n > 1 and abs(out.strides[0]) < abs(out.strides[1])
    target = out.T if by_columns else out
    step = max(1, _BLOCK_ENTRIES // max(n, 1))
    work = np.empty((min(step, n), n))
    for start in range(0, n, step):
        k = slice(start, min(start + step, n))
        block, w = target[k], work[: k.stop - start]
        if by_columns:  # block[n, m] = I_mn
            np.multiply(lam[k, None], j1b[None, :], out=block)
            block *= j0b[k, None]
            np.multiply(lam_j0b[None, :], j1b[k, None], out=w)
        else:  # block[m, n] = I_mn
            np.multiply(lam[None, :], j1b[k, None], out=block)
            block *= j0b[None, :]
            np.multiply(lam_j0b[k, None], j1b[None, :], out=w)
        block -= w
        block *= -b
        if by_columns:
            np.subtract(lam_sq[None, :], lam_sq[k, None], out=w)
        else:
            np.subtract(lam_sq[k, None], lam_sq[None, :], out=w)
        local = np.arange(k.stop - start)
        w[local, start + local] = 1.0
        block /= w
    with np.errstate(divide="ignore", invalid="ignore"):
        cross = np.where(x > 0, 2.0 * j0b * j1b / np.where(x > 0, x, 1.0), 1.0)
    diagonal = 0.5 * special.j1(lam) ** 2 - 0.5 * b * b * (j0b**2 + j1b**2 - cross)
    np.fill_diagonal(out, diagonal)
    return out


def coupling_matrix(lam, b):
    """C_mn of eq. (52)-(53): lam_n (lam_n - 1) I_mn, I from ``lommel_matrix``.

    The factor (lam_n - 1) combines the stick-zone displacement condition (29) with
    the slip-zone traction condition (30), which is why it is only meaningful with
    lengths in units of a (see the errata note on eq. 37).
    """
    lam = np.asarray(lam, dtype=float)
    return lommel_matrix(lam, b) * (lam * (lam - 1.0))[None, :]
