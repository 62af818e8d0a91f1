r"""High-precision reference solution of eq. (38) (``published``) and its completion.

Units: lengths in a (a = 1), tractions in f p0, displacements in f p0 a / mu,
omega in f p0 / mu, amplitudes c_n = lam_n A~_n (see ``formulations``).

Everything here is computed with mpmath at a chosen number of significant digits
(default 50) and runs unchanged at any precision: every function takes ``digits``
or works in the caller's ``mpmath.workdps`` context, and never leaves ``mp.dps``
changed.  The functions mirror the mathematical objects of the paper one by one:

* ``j2_zeros``                       lam_n, J2(lam_n) = 0 (eq. 19-20), Newton-refined
  from the double-precision zeros of ``zeros.bessel_j2_zeros``;
* ``dini_norm``                      h (eq. 35, a = 1), printed form;
* ``integral_t_j1_hyp1f2``           x^3/6 1F2(3/2; 2, 5/2; -x^2/4), the form printed in
  eq. (51) (mpmath.hyp1f2 picks its own extra precision / asymptotic expansion);
* ``integral_t_j1_struve``           the same integral as int_0^x J0 - x J0(x)
  = (pi x / 2) [J1(x) H0(x) - J0(x) H1(x)] (Struve functions), independent of 1F2;
* ``load_vector``                    B_m (eq. 51);
* ``lommel_offdiagonal``, ``lommel_diagonal``, ``lommel_matrix``
                                     the integrals of eq. (52), (53) (without the
                                     factor lam_n (lam_n - 1)), printed forms including
                                     the r = 1 terms;
* ``coupling_matrix``                C_mn (eq. 52, 53);
* ``assemble``                       the matrix of (iii)-(iv) of ``formulations``,
                                     with exactly the layout of ``formulations.assemble``;
* ``solve_reference``                T*, omega, c_n with the regularity condition (v).

The dense solve is the only O(N^3) step.  It uses python-flint's ``arb_mat.solve``
(ball arithmetic, so the result carries a rigorous bound for the rounding of the
solve) when python-flint is importable, otherwise mpmath's LU.  Measured on the
2-core development machine (N = 145, 50 digits, 70 working digits), per radius:
assembly about 1 s, dominated by the ~10^4 pure-Python mpf products of the Lommel
matrix (0.9 s; mpmath runs on its Python backend, no gmpy2), then 1450 Bessel
evaluations (0.3 s) and 290 1F2 evaluations (0.15 s); flint solve 0.2-0.3 s, mostly
the exact mpf -> arb conversion of the matrix; mpmath's LU instead takes about 6 s.
Six radii x two formulations: about 13 s alone, 21 s with other jobs on the cores.

``rounding_error`` and ``condition_numbers`` compare the double-precision solver
``formulations.solve_series`` with this reference.
"""

from __future__ import annotations

import contextlib
import json
import math
import platform
import time
import warnings
from dataclasses import dataclass, field

import mpmath
import numpy as np
from scipy import linalg

from . import validation
from .formulations import METHODS, solve_series
from .formulations import assemble as assemble_double
from .output import write_text
from .warnings import AccuracyWarning, IllConditioningWarning
from .zeros import bessel_j2_zeros

try:  # optional accelerator for the dense solve
    import flint
except ImportError:  # pragma: no cover - exercised only without python-flint
    flint = None

__all__ = [
    "DEFAULT_DIGITS",
    "GUARD_DIGITS",
    "ReferenceSolution",
    "j2_zeros",
    "j2_zeros_at",
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
    "solve_linear",
    "solve_reference",
    "reference_set",
    "write_json",
    "write_text",
    "write_reference_json",
    "truncation_error",
    "equilibrate",
    "package_versions",
    "rounding_error",
    "condition_numbers",
    "parse_stick_radius",
]

#: Default number of significant decimal digits of the reference.
DEFAULT_DIGITS = 50
#: Extra working digits: the system loses about log10(cond) ~ 4 digits at N = 145;
#: 20 guard digits leave a wide margin, which ``solve_reference`` verifies.
GUARD_DIGITS = 20


# --------------------------------------------------------------------------- utilities


@contextlib.contextmanager
def _flint_dps(dps: int):
    """Temporarily set python-flint's working precision (restored on exit)."""
    saved = flint.ctx.prec
    flint.ctx.dps = dps
    try:
        yield
    finally:
        flint.ctx.prec = saved


def parse_stick_radius(value):
    """b/a as an mpf: a float is read as the decimal its shortest repr denotes.

    ``0.6`` therefore means exactly 6/10 (to the working precision), not the binary
    double nearest to it; the two differ by 2e-17 relative, far below double-precision
    rounding of the solve.  Strings are parsed as decimals.
    """
    if isinstance(value, str):
        text = value
    else:
        text = repr(validation.real_number("stick_radius", value, 0.0, 1.0))
    b = mpmath.mpf(text)
    if not (0 <= b <= 1):
        raise ValueError(f"stick_radius must lie in [0, 1], got {value!r}")
    return b


def _mp_to_arb(x):
    """Exact conversion mpf -> flint.arb (binary mantissa and exponent)."""
    sign, man, exp, _ = mpmath.mpf(x)._mpf_
    if man == 0:
        return flint.arb(0)
    value = flint.arb(flint.fmpz(-man if sign else man)) * flint.arb(2) ** exp
    return value


def _arb_to_mp(x):
    """flint.arb -> (mpf midpoint, mpf radius)."""
    mid, rad = x.mid(), x.rad()
    if mid.is_zero():
        mid_mp = mpmath.mpf(0)
    else:
        man, exp = mid.man_exp()
        mid_mp = mpmath.mpf((int(man), int(exp)))
    if rad.is_zero():
        rad_mp = mpmath.mpf(0)
    else:
        man, exp = rad.man_exp()
        rad_mp = mpmath.mpf((int(man), int(exp)))
    return mid_mp, rad_mp


# --------------------------------------------------------------------------- eq. (19)-(20)

_ZERO_CACHE: dict[tuple[int, int], tuple] = {}


def j2_zeros(n_terms: int, digits: int | None = None):
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
        _ZERO_CACHE[key] = _newton_j2(bessel_j2_zeros(n_terms), dps)
    return _ZERO_CACHE[key]


def j2_zeros_at(indices, digits: int | None = None):
    """The zeros lam_n (eq. 20) for the given 1-based ``indices`` only, to ``digits`` digits."""
    indices = [validation.positive_int("index", i) for i in indices]
    dps = mpmath.mp.dps if digits is None else validation.positive_int("digits", digits)
    start = bessel_j2_zeros(max(indices))
    return _newton_j2([start[i - 1] for i in indices], dps)


def _newton_j2(start, dps):
    """Newton on J2 from double-precision starting values, at dps + 10 working digits."""
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
    """Matrix and right-hand sides of (iii)-(iv) of ``formulations``, in mpmath.

    Same layout as ``formulations.assemble``: ``matrix @ x = T* rhs_torque +
    rhs_constant``, x = (c_1..c_N[, omega]).  With c_n = lam_n A~_n, the
    ``published`` system is eq. (38): A~_m lam_m h_m + sum_n A~_n C_mn = B_m.

    Returns
    -------
    (mpmath.matrix, list of mpf, list of mpf)
    """
    method = validation.choice("method", method, METHODS)
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


def solve_linear(matrix, rhs_columns, backend: str | None = None):
    """Solve ``matrix @ X = [rhs_columns]`` at the current mpmath precision.

    Parameters
    ----------
    matrix : mpmath.matrix
    rhs_columns : list of list of mpf
    backend : {"flint", "mpmath"}, optional
        ``flint``: python-flint ball arithmetic (rigorous rounding bound, fast);
        ``mpmath``: LU decomposition in pure Python.  Default: flint if importable.

    Returns
    -------
    columns : list of list of mpf
    bound : mpf or None
        Largest ball radius / |midpoint| of the solution (flint only): a rigorous
        bound on the relative rounding error of the solve.
    """
    if backend is None:
        backend = "flint" if flint is not None else "mpmath"
    backend = validation.choice("backend", backend, ("flint", "mpmath"))
    n = matrix.rows
    if backend == "mpmath":
        lu, perm = mpmath.mp.LU_decomp(matrix.copy())
        columns = []
        for rhs in rhs_columns:
            y = mpmath.mp.L_solve(lu, mpmath.matrix(list(rhs)), perm)
            x = mpmath.mp.U_solve(lu, y)
            columns.append([x[i] for i in range(n)])
        return columns, None
    if flint is None:  # pragma: no cover
        raise ValueError("backend='flint' needs python-flint (pip install python-flint==0.9.0)")
    with _flint_dps(mpmath.mp.dps):
        a = flint.arb_mat(n, n)
        for i in range(n):
            for k in range(n):
                a[i, k] = _mp_to_arb(matrix[i, k])
        rhs = flint.arb_mat(n, len(rhs_columns))
        for j, col in enumerate(rhs_columns):
            for i in range(n):
                rhs[i, j] = _mp_to_arb(col[i])
        x = a.solve(rhs)
        columns = []
        bound = mpmath.mpf(0)
        for j in range(len(rhs_columns)):
            col = []
            for i in range(n):
                mid, rad = _arb_to_mp(x[i, j])
                col.append(mid)
                if mid != 0:
                    bound = max(bound, rad / abs(mid))
            columns.append(col)
    return columns, bound


# --------------------------------------------------------------------------- solution


@dataclass(frozen=True)
class ReferenceSolution:
    """High-precision solution for one stick radius (units of ``formulations``).

    Attributes
    ----------
    method : str
    stick_radius : mpf
        b/a.
    torque : mpf
        T*(b) from the regularity condition (v).
    rigid_rotation : mpf or None
        omega (f p0 / mu); None for ``published``.
    eigenvalues, amplitudes : tuple of mpf
        lam_n and c_n = lam_n A~_n (f p0 a / mu).
    digits : int
        Significant digits requested (the working precision is digits + GUARD_DIGITS).
    solve_bound : mpf or None
        Rigorous relative bound on the rounding of the dense solve (flint backend).
    seconds : dict
        Wall-clock time of zeros, assembly and solve.
    """

    method: str
    stick_radius: object
    torque: object
    rigid_rotation: object
    eigenvalues: tuple
    amplitudes: tuple
    digits: int
    backend: str
    solve_bound: object = None
    seconds: dict = field(default_factory=dict)

    @property
    def n_terms(self) -> int:
        return len(self.eigenvalues)

    def as_dict(self, digits: int | None = None) -> dict:
        """JSON-ready dict with decimal strings of ``digits`` significant digits."""
        d = self.digits if digits is None else digits

        def s(x):
            return None if x is None else mpmath.nstr(x, d, strip_zeros=False)

        return {
            "stick_radius": s(self.stick_radius),
            "torque": s(self.torque),
            "rigid_rotation": s(self.rigid_rotation),
            "amplitudes": [s(c) for c in self.amplitudes],
            "eigenvalues": [s(x) for x in self.eigenvalues],
            "method": self.method,
            "n_terms": self.n_terms,
            "digits": d,
            "backend": self.backend,
            "solve_bound": None if self.solve_bound is None else float(self.solve_bound),
            "seconds": self.seconds,
        }


def solve_reference(
    stick_radius,
    method: str = "complete",
    n_terms: int = 145,
    digits: int = DEFAULT_DIGITS,
    *,
    backend: str | None = None,
    form: str = "hyp1f2",
    progress: bool = False,
) -> ReferenceSolution:
    """High-precision analogue of ``formulations.solve_series`` (0 < b < 1).

    Assembles (iii)-(iv) at ``digits + GUARD_DIGITS`` working digits, solves for the
    two right-hand sides (torque part, constant part) and fixes T* with the
    regularity condition (v): T* b - sum_n c_n lam_n J1(lam_n b) = 1.

    Parameters
    ----------
    stick_radius : float or str
        b/a in (0, 1); a float is read as its decimal repr (see ``parse_stick_radius``).
    method : {"published", "complete"}
    n_terms : int
    digits : int
        Significant digits wanted in T*, omega, c_n (rounding only; the truncation at
        N terms is the formulation's and is not reduced by precision).
    backend, form
        See ``solve_linear`` and ``load_integral_constant``.
    progress : bool
        Show a tqdm progress bar over the rows of the Lommel matrix.

    Warns
    -----
    IllConditioningWarning
        If the rigorous bound of the flint solve leaves fewer than ``digits`` digits.
    """
    method = validation.choice("method", method, METHODS)
    n_terms = validation.positive_int("n_terms", n_terms)
    digits = validation.positive_int("digits", digits)
    b_in = stick_radius
    work = digits + GUARD_DIGITS
    seconds = {}
    with mpmath.workdps(work):
        b = parse_stick_radius(b_in)
        if b == 0 or b == 1:
            raise ValueError(f"stick_radius must lie in (0, 1) for the reference solve, got {b_in!r}")
        t0 = time.perf_counter()
        lam = j2_zeros(n_terms, work)
        seconds["zeros"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        matrix, rhs_torque, rhs_constant = assemble(method, lam, b, form=form, progress=progress)
        seconds["assembly"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        (x_torque, x_constant), bound = solve_linear(matrix, [rhs_torque, rhs_constant], backend)
        seconds["solve"] = time.perf_counter() - t0
        weight = [x * mpmath.besselj(1, x * b) for x in lam]
        wk = mpmath.fsum(w * c for w, c in zip(weight, x_constant, strict=False))
        wl = mpmath.fsum(w * c for w, c in zip(weight, x_torque, strict=False))
        torque = (1 + wk) / (b - wl)
        coeffs = [k + torque * t for k, t in zip(x_constant, x_torque, strict=False)]
    if bound is not None and bound > 0 and -mpmath.log10(bound) < digits:
        warnings.warn(
            f"the reference solve for stick_radius={b_in!r}, n_terms={n_terms} keeps only "
            f"{float(-mpmath.log10(bound)):.1f} of {digits} requested digits; raise digits",
            IllConditioningWarning,
            stacklevel=2,
        )
    with mpmath.workdps(digits):
        return ReferenceSolution(
            method=method,
            stick_radius=+b,
            torque=+torque,
            rigid_rotation=+coeffs[n_terms] if method == "complete" else None,
            eigenvalues=tuple(+x for x in lam),
            amplitudes=tuple(+c for c in coeffs[:n_terms]),
            digits=digits,
            backend=backend or ("flint" if flint is not None else "mpmath"),
            solve_bound=bound,
            seconds=seconds,
        )


def reference_set(stick_radii, methods=METHODS, n_terms=145, digits=DEFAULT_DIGITS, progress=True, **kwargs):
    """``solve_reference`` for every (method, b); returns (list of solutions, total seconds)."""
    jobs = [(m, b) for m in methods for b in stick_radii]
    if progress:
        from tqdm import tqdm

        jobs = tqdm(jobs, desc=f"reference N={n_terms}, {digits} digits")
    t0 = time.perf_counter()
    out = [solve_reference(b, m, n_terms, digits, **kwargs) for m, b in jobs]
    return out, time.perf_counter() - t0


def package_versions() -> dict:
    """Versions of the packages the reference depends on (JSON metadata)."""
    import scipy

    from . import __version__

    return {
        "python": platform.python_version(),
        "torsional_contact": __version__,
        "mpmath": mpmath.__version__,
        "mpmath_backend": mpmath.libmp.BACKEND,
        "python-flint": getattr(flint, "__version__", None),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
    }


def write_json(path, payload) -> None:
    """Write ``payload`` as JSON (no NaN/inf) atomically."""
    write_text(path, json.dumps(payload, indent=1, allow_nan=False) + "\n")


def write_reference_json(path, solutions, seconds_total: float | None = None) -> None:
    """Write reference solutions with full-precision decimal strings and metadata."""
    payload = {
        "description": "High-precision reference of the torsional contact series (a = 1); "
        "T* = 2T/(f F a), omega in f p0/mu, amplitudes c_n = lam_n A~_n in f p0 a/mu.",
        "versions": package_versions(),
        "seconds_total": seconds_total,
        "solutions": [s.as_dict() for s in solutions],
    }
    write_json(path, payload)


# --------------------------------------------------------------------------- cross-checks


def _rel(a, b):
    return abs(float(a) - float(b)) / abs(float(b))


def rounding_error(reference: ReferenceSolution) -> dict:
    """Rounding error of ``formulations.solve_series`` at the same (b, method, N).

    Compares the double-precision result with the high-precision reference of the
    *same* truncated system, so only rounding (not truncation) is measured.

    Returns
    -------
    dict with ``torque``, ``rigid_rotation`` (None for published), ``amplitudes``
    (normwise relative error ||c - c_ref||_inf / ||c_ref||_inf), ``digits_lost``
    (16 - significant digits kept by the worst of the three), ``rcond`` (scipy's
    reciprocal condition number estimate of the equilibrated system) and
    ``predicted_digits_lost`` = log10(1/rcond).

    Warns
    -----
    AccuracyWarning
        If scipy lost more digits than the condition number allows (+2).
    """
    b = float(reference.stick_radius)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        dp = solve_series(b, reference.method, reference.n_terms)
    ref_c = np.array([float(c) for c in reference.amplitudes])
    err_c = float(np.max(np.abs(dp.amplitudes - ref_c)) / np.max(np.abs(ref_c)))
    err_t = _rel(dp.torque, reference.torque)
    err_w = None if reference.rigid_rotation is None else _rel(dp.rigid_rotation, reference.rigid_rotation)
    worst = max(e for e in (err_t, err_w, err_c) if e is not None)
    eps = np.finfo(float).eps
    lost = math.log10(max(worst, eps) / eps)
    predicted = -math.log10(dp.rcond)
    if lost > predicted + 2:
        warnings.warn(
            f"scipy lost {lost:.1f} digits at b={b}, N={reference.n_terms} ({reference.method}); "
            f"the condition number predicts {predicted:.1f}",
            AccuracyWarning,
            stacklevel=2,
        )
    return {
        "stick_radius": b,
        "method": reference.method,
        "n_terms": reference.n_terms,
        "torque": err_t,
        "rigid_rotation": err_w,
        "amplitudes": err_c,
        "digits_lost": lost,
        "rcond": dp.rcond,
        "predicted_digits_lost": predicted,
    }


def _rcond_1(matrix) -> float:
    lu, _ = linalg.lu_factor(matrix, check_finite=True)
    anorm = np.max(np.sum(np.abs(matrix), axis=0))
    rcond, _ = linalg.lapack.dgecon(lu, anorm, norm="1")
    return float(rcond)


def equilibrate(matrix):
    """Row then column scaling to unit max-norm, as in ``formulations.equilibrated_solve``."""
    scaled = matrix / np.max(np.abs(matrix), axis=1)[:, None]
    return scaled / np.max(np.abs(scaled), axis=0)[None, :]


def condition_numbers(n_terms_list, stick_radius: float = 0.6, methods=METHODS, progress: bool = False) -> list:
    """1-norm condition numbers of the double-precision system vs N (raw and equilibrated).

    kappa_1 = ||A||_1 ||A^-1||_1 estimated by LAPACK dgecon from the LU factors
    (within a small factor of the exact value).  O(N^3) per entry: N = 5000 takes
    several seconds per matrix on one core.

    Returns
    -------
    list of dict(n_terms, method, raw, equilibrated)
    """
    out = []
    jobs = [(n, m) for n in n_terms_list for m in methods]
    if progress:
        from tqdm import tqdm

        jobs = tqdm(jobs, desc="condition numbers")
    for n, m in jobs:
        lam = bessel_j2_zeros(int(n))
        matrix, _, _ = assemble_double(m, lam, stick_radius)
        out.append(
            {
                "n_terms": int(n),
                "method": m,
                "stick_radius": stick_radius,
                "raw": 1.0 / _rcond_1(matrix),
                "equilibrated": 1.0 / _rcond_1(equilibrate(matrix)),
            }
        )
    return out


def truncation_error(stick_radius: float, method: str, n_terms: int, n_terms_converged: int) -> dict:
    """Change of T* (and omega) between N and a much larger N (double precision).

    This is the truncation error of the N-term system, separate from rounding
    (which ``rounding_error`` measures at fixed N).
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        a = solve_series(stick_radius, method, n_terms)
        b = solve_series(stick_radius, method, n_terms_converged)
    return {
        "stick_radius": stick_radius,
        "method": method,
        "n_terms": n_terms,
        "n_terms_converged": n_terms_converged,
        "torque": a.torque,
        "torque_converged": b.torque,
        "torque_rel_change": abs(a.torque - b.torque) / b.torque,
        "rigid_rotation": a.rigid_rotation if method == "complete" else None,
        "rigid_rotation_converged": b.rigid_rotation if method == "complete" else None,
    }
