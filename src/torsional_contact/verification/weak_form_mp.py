r"""The weak-form system of eqs. (33)-(38) and its completion in arbitrary precision (mpmath).

The mpmath twins of ``special.zeros``, ``special.integrals`` and ``solvers.weak_form``, one
function per mathematical object of the paper, in the printed forms (so the errata checks can
compare them with quadrature).  Every function works at the caller's ``mpmath.workdps``
(or takes ``digits``) and never leaves ``mp.dps`` changed.  Lengths in a (a = 1).
"""

from __future__ import annotations

import mpmath

from .. import validation
from ..solvers.weak_form import WEAK_FORMS
from ..special import zeros
from . import arbitrary_precision as ap

__all__ = [
    "bessel_j2_zeros",
    "bessel_j2_zeros_at",
    "dini_norm",
    "integral_t_j1_hyp1f2",
    "integral_t_j1_struve",
    "load_integral_linear",
    "load_integral_constant",
    "load_vector",
    "lommel_offdiagonal",
    "lommel_diagonal",
    "lommel_matrix",
    "coupling_matrix",
    "assemble",
]


# --------------------------------------------------------------------------- eq. (19)-(20)

_ZERO_CACHE: dict[tuple[int, int], tuple] = {}


def bessel_j2_zeros(n_terms: int, digits: int | None = None):
    """First ``n_terms`` positive zeros of J2 (eq. 20) to ``digits`` significant digits.

    Newton's method on J2 with J2'(x) = J1(x) - 2 J2(x)/x, started from the
    double-precision zeros of ``zeros.bessel_j2_zeros`` (each step doubles the
    number of correct digits; iterated until the step is below 10^-(digits + 5)
    relative).

    Parameters
    ----------
    n_terms : int
        Number of zeros, >= 1.
    digits : int, optional
        Significant digits; default: the current ``mpmath.mp.dps``.

    Returns
    -------
    tuple of mpf
        Dimensionless lam_n (a = 1), ascending.
    """
    n_terms = validation.positive_int("n_terms", n_terms)
    dps = mpmath.mp.dps if digits is None else validation.positive_int("digits", digits)
    key = (n_terms, dps)
    if key not in _ZERO_CACHE:
        _ZERO_CACHE[key] = _newton_j2(zeros.bessel_j2_zeros(n_terms), dps)
    return _ZERO_CACHE[key]


def bessel_j2_zeros_at(indices, digits: int | None = None):
    """The zeros lam_n (eq. 20) for the given 1-based ``indices`` only, to ``digits`` digits."""
    indices = [validation.positive_int("index", i) for i in indices]
    dps = mpmath.mp.dps if digits is None else validation.positive_int("digits", digits)
    start = zeros.bessel_j2_zeros(max(indices))
    return _newton_j2([start[i - 1] for i in indices], dps)


def _newton_j2(start, dps, arithmetic: str | None = None):
    """Newton on J2 from double-precision starting values, at dps + 10 working digits.

    ``arithmetic``: "arb" (python-flint's Bessel functions, ten times faster; the default when
    python-flint is importable) or "mpmath".  Both iterate from the same start to a step below
    10^-(dps + 5) relative and round to ``dps`` digits: they give the same mpf (tested).
    """
    arithmetic = arithmetic or ("arb" if ap.FLINT else "mpmath")
    if arithmetic == "arb":
        return _newton_j2_arb(start, dps)
    if arithmetic != "mpmath":
        raise ValueError(f"arithmetic must be 'arb' or 'mpmath', got {arithmetic!r}")
    with mpmath.workdps(dps + 10):
        tol = mpmath.mpf(10) ** (-(dps + 5))
        out = []
        for x0 in start:
            x = mpmath.mpf(float(x0))
            for _ in range(20):
                j2 = mpmath.besselj(2, x)
                step = j2 / (mpmath.besselj(1, x) - 2 * j2 / x)
                x -= step
                if abs(step) < tol * x:
                    break
            else:  # pragma: no cover - Newton from a 1-ulp start converges in 3 steps
                raise ArithmeticError(f"Newton did not converge for the zero near {x0}")
            out.append(x)
    with mpmath.workdps(dps):
        return tuple(+x for x in out)


def _newton_j2_arb(start, dps):
    """``_newton_j2`` in Arb: each iterate is the midpoint of its ball (Newton corrects its own rounding)."""
    with ap.flint_dps(dps + 10):
        tol = ap.flint.arb(10) ** (-(dps + 5))
        out = []
        for x0 in start:
            x = ap.flint.arb(float(x0))
            for _ in range(20):
                j2 = x.bessel_j(2)
                step = (j2 / (x.bessel_j(1) - 2 * j2 / x)).mid()
                x = (x - step).mid()
                if abs(step) < tol * x:
                    break
            else:  # pragma: no cover - Newton from a 1-ulp start converges in 3 steps
                raise ArithmeticError(f"Newton did not converge for the zero near {x0}")
            out.append(x)
    with mpmath.workdps(dps + 10):
        out = [ap.arb_to_mp(x) for x in out]
    with mpmath.workdps(dps):
        return tuple(+x for x in out)


# --------------------------------------------------------------------------- eq. (35), (51)


def dini_norm(lam):
    """h of eq. (35) with a = 1: [J0(lam)^2 - 2 J0(lam) J1(lam)/lam + J1(lam)^2] / 2.

    As printed (valid for any lam > 0); equals int_0^1 J1(lam r)^2 r dr.  Dimensionless.
    """
    j0, j1 = mpmath.besselj(0, lam), mpmath.besselj(1, lam)
    return (j0 * j0 - 2 * j0 * j1 / lam + j1 * j1) / 2


def integral_t_j1_hyp1f2(x):
    """int_0^x t J1(t) dt in the form printed in eq. (51): x^3/6 1F2(3/2; 2, 5/2; -x^2/4)."""
    x = mpmath.mpf(x)
    if x == 0:
        return mpmath.mpf(0)
    return x**3 / 6 * mpmath.hyp1f2(mpmath.mpf(3) / 2, 2, mpmath.mpf(5) / 2, -(x**2) / 4)


def integral_t_j1_struve(x):
    """int_0^x t J1(t) dt = int_0^x J0 - x J0(x) = (pi x/2) [J1(x) H0(x) - J0(x) H1(x)].

    Uses the Struve functions H0, H1 (DLMF 10.22.2 with 10.22.1); independent of
    the 1F2 form of eq. (51).
    """
    x = mpmath.mpf(x)
    if x == 0:
        return mpmath.mpf(0)
    return (
        mpmath.pi * x / 2 * (mpmath.besselj(1, x) * mpmath.struveh(0, x) - mpmath.besselj(0, x) * mpmath.struveh(1, x))
    )


_G_FORMS = {"hyp1f2": integral_t_j1_hyp1f2, "struve": integral_t_j1_struve}


def load_integral_linear(lam, b):
    """int_b^1 r^2 J1(lam r) dr = [J2(lam) - b^2 J2(lam b)] / lam (T* part of eq. 51), any lam."""
    return (mpmath.besselj(2, lam) - b * b * mpmath.besselj(2, lam * b)) / lam


def load_integral_constant(lam, b, form: str = "hyp1f2"):
    """int_b^1 r J1(lam r) dr = [G(lam) - G(lam b)] / lam^2, G(x) = int_0^x t J1 dt.

    ``form`` selects G: ``"hyp1f2"`` (as printed in eq. 51) or ``"struve"``.
    """
    g = _G_FORMS[form]
    return (g(lam) - g(lam * b)) / (lam * lam)


def load_vector(lam, b, torque, form: str = "hyp1f2"):
    """B_m of eq. (51) (a = 1) for one eigenvalue: T* int_b^1 r^2 J1 dr - int_b^1 r J1 dr."""
    return torque * load_integral_linear(lam, b) - load_integral_constant(lam, b, form)


# --------------------------------------------------------------------------- eq. (52), (53)


def lommel_offdiagonal(lam_m, lam_n, b):
    """int_b^1 J1(lam_m r) J1(lam_n r) r dr, lam_m != lam_n: the bracket of eq. (52) / (lam_m^2 - lam_n^2).

    As printed, with the r = 1 terms (they cancel at zeros of J2; at high precision
    the cancellation costs nothing).  Any lam_m != lam_n.
    """
    jm0, jm1 = mpmath.besselj(0, lam_m), mpmath.besselj(1, lam_m)
    jn0, jn1 = mpmath.besselj(0, lam_n), mpmath.besselj(1, lam_n)
    bm0, bm1 = mpmath.besselj(0, b * lam_m), mpmath.besselj(1, b * lam_m)
    bn0, bn1 = mpmath.besselj(0, b * lam_n), mpmath.besselj(1, b * lam_n)
    return _lommel_bracket(lam_m, lam_n, b, jm0, jm1, jn0, jn1, bm0, bm1, bn0, bn1)


def _lommel_bracket(lam_m, lam_n, b, jm0, jm1, jn0, jn1, bm0, bm1, bn0, bn1):
    bracket = lam_n * jn0 * jm1 - b * lam_n * bn0 * bm1 - lam_m * jm0 * jn1 + b * lam_m * bm0 * bn1
    return bracket / (lam_m * lam_m - lam_n * lam_n)


def lommel_diagonal(lam, b):
    """int_b^1 J1(lam r)^2 r dr: the bracket of eq. (53) divided by 2 lam (a = 1), any lam."""
    j0, j1 = mpmath.besselj(0, lam), mpmath.besselj(1, lam)
    b0, b1 = mpmath.besselj(0, b * lam), mpmath.besselj(1, b * lam)
    return _diag_bracket(lam, b, j0, j1, b0, b1)


def _diag_bracket(lam, b, j0, j1, b0, b1):
    bracket = lam * j0 * j0 + lam * j1 * j1 - 2 * j0 * j1 + 2 * b * b0 * b1 - b * b * lam * (b0 * b0 + b1 * b1)
    return bracket / (2 * lam)


def lommel_matrix(lam, b, progress: bool = False):
    """I_mn = int_b^1 J1(lam_m r) J1(lam_n r) r dr (eq. 52, 53 without lam_n (lam_n - 1)).

    Each Bessel value is computed once (O(N) calls); the N^2 entries are then
    arithmetic on cached values.  Returns an ``mpmath.matrix``.
    """
    n = len(lam)
    j0 = [mpmath.besselj(0, x) for x in lam]
    j1 = [mpmath.besselj(1, x) for x in lam]
    b0 = [mpmath.besselj(0, b * x) for x in lam]
    b1 = [mpmath.besselj(1, b * x) for x in lam]
    out = mpmath.matrix(n, n)
    rows = range(n)
    if progress:
        from tqdm import tqdm

        rows = tqdm(rows, desc="Lommel matrix", leave=False)
    for i in rows:
        out[i, i] = _diag_bracket(lam[i], b, j0[i], j1[i], b0[i], b1[i])
        for k in range(i + 1, n):
            v = _lommel_bracket(lam[i], lam[k], b, j0[i], j1[i], j0[k], j1[k], b0[i], b1[i], b0[k], b1[k])
            out[i, k] = v
            out[k, i] = v
    return out


def coupling_matrix(lam, b):
    """C_mn = lam_n (lam_n - 1) I_mn of eq. (52), (53) (a = 1)."""
    matrix = lommel_matrix(lam, b)
    n = len(lam)
    for k in range(n):
        factor = lam[k] * (lam[k] - 1)
        for i in range(n):
            matrix[i, k] *= factor
    return matrix


# --------------------------------------------------------------------------- assembly


def assemble(method: str, lam, b, form: str = "hyp1f2", progress: bool = False):
    """Matrix and right-hand sides of (iii)-(iv) of ``solvers.weak_form``, in mpmath.

    Same layout as ``solvers.weak_form.assemble``: ``matrix @ x = T* rhs_torque +
    rhs_constant``, x = (c_1..c_N[, omega]).  With c_n = lam_n A~_n, the
    ``published`` system is eq. (38): A~_m lam_m h_m + sum_n A~_n C_mn = B_m.

    Returns
    -------
    (mpmath.matrix, list of mpf, list of mpf)
    """
    method = validation.choice("method", method, WEAK_FORMS)
    n = len(lam)
    lommel = lommel_matrix(lam, b, progress=progress)
    size = n if method == "published" else n + 1
    matrix = mpmath.matrix(size, size)
    for k in range(n):
        factor = lam[k] - 1
        for i in range(n):
            matrix[i, k] = lommel[i, k] * factor
    for i in range(n):
        matrix[i, i] += dini_norm(lam[i])
    rhs_torque = [load_integral_linear(x, b) for x in lam]
    rhs_constant = [-load_integral_constant(x, b, form) for x in lam]
    if method == "complete":
        stick = [b * b * mpmath.besselj(2, b * x) / x for x in lam]
        for i in range(n):
            matrix[i, n] = stick[i]
            matrix[n, i] = (1 - lam[i]) * stick[i]
        matrix[n, n] = b**4 / 4
        rhs_torque.append((1 - b**4) / 4)
        rhs_constant.append(-(1 - b**3) / 3)
    return matrix, rhs_torque, rhs_constant
