r"""Arbitrary-precision utilities of the verification wing: precision contexts, exact conversions
between mpmath and python-flint, decimal input, Gauss-Legendre nodes and dense solves.

Every function works at the precision currently set in ``mpmath.mp`` and ``flint.ctx``;
``working_digits`` sets both together and restores them afterwards, so that callers never leave
either library's precision changed.  python-flint's ``arb`` numbers are balls (midpoint,
radius): the radius is a rigorous bound on the rounding error accumulated so far (not on
truncation or discretisation errors, which the callers estimate themselves).

python-flint is optional: the weak-form reference falls back to mpmath (slower, the same
digits; ``FLINT`` says which is in use); the Abel-Fredholm reference, written in Arb
arithmetic, needs it and says so (``require_flint``).
"""

from __future__ import annotations

import contextlib
import decimal
import functools
import math

import mpmath

from .. import validation
from ..extras import install_hint

try:  # optional: Arb ball arithmetic (Bessel functions, dense linear algebra)
    import flint
except ImportError:  # pragma: no cover - exercised only without python-flint
    flint = None

__all__ = [
    "FLINT",
    "flint",
    "require_flint",
    "backend",
    "flint_dps",
    "GUARD_BITS",
    "precision_bits",
    "working_digits",
    "mp_to_arb",
    "arb_to_mp",
    "arb_radius",
    "decimal_string",
    "parse_decimal",
    "gauss_legendre",
    "arb_vector",
    "to_full_accuracy",
    "matrix_column",
    "solve_linear",
]

#: True when python-flint is importable.
FLINT = flint is not None


def require_flint(what: str) -> None:
    """Raise ImportError naming ``what`` if python-flint is not installed."""
    if not FLINT:
        raise ImportError(f"{what} needs python-flint, not installed: {install_hint('reference')}")


def backend() -> str:
    """The default dense-solve backend: "flint" if python-flint is importable, else "mpmath"."""
    return "flint" if FLINT else "mpmath"


@contextlib.contextmanager
def flint_dps(dps: int):
    """Temporarily set python-flint's working precision to ``dps`` digits (restored on exit)."""
    require_flint("flint_dps")
    saved = flint.ctx.prec
    flint.ctx.dps = dps
    try:
        yield
    finally:
        flint.ctx.prec = saved


#: Bits added to ceil(digits * log2(10)) when a number of decimal digits is converted
#: to a binary precision (so that ``digits`` decimal digits survive the last rounding).
GUARD_BITS = 10


def precision_bits(digits: int) -> int:
    """Binary precision (bits) that carries ``digits`` significant decimal digits."""
    return math.ceil(digits * math.log2(10)) + GUARD_BITS


@contextlib.contextmanager
def working_digits(digits: int):
    """Set mpmath's and python-flint's working precision to ``digits`` decimal digits.

    Both are restored on exit (also on error).  Yields the precision in bits.
    """
    bits = precision_bits(digits)
    saved_mp = mpmath.mp.prec
    saved_flint = flint.ctx.prec if FLINT else None
    mpmath.mp.prec = bits
    if FLINT:
        flint.ctx.prec = bits
    try:
        yield bits
    finally:
        mpmath.mp.prec = saved_mp
        if FLINT:
            flint.ctx.prec = saved_flint


def mp_to_arb(x):
    """Exact conversion of an mpf (or int) to a flint ``arb`` with zero radius."""
    sign, man, exp, _ = mpmath.mpf(x)._mpf_
    if man == 0:
        return flint.arb(0)
    return flint.arb((-int(man) if sign else int(man), int(exp)))


def _arf_to_mp(value):
    """An exact flint ``arb`` with zero radius (a midpoint or a radius) as an mpf."""
    if value.is_zero():
        return mpmath.mpf(0)
    man, exp = value.man_exp()
    return mpmath.mpf((int(man), int(exp)))


def arb_to_mp(x):
    """Midpoint of a flint ``arb`` as an mpf (exact; rounded only to mpmath's precision)."""
    return _arf_to_mp(x.mid())


def arb_radius(x):
    """Radius of a flint ``arb`` ball as an mpf (a rigorous bound on its rounding error)."""
    return _arf_to_mp(x.rad())


def decimal_string(x, digits: int) -> str:
    """``digits`` significant decimal digits of an mpf or arb (midpoint), trailing zeros kept."""
    if FLINT and isinstance(x, flint.arb):
        x = arb_to_mp(x)
    with mpmath.workdps(digits + 5):
        return mpmath.nstr(mpmath.mpf(x), digits, strip_zeros=False, min_fixed=-3, max_fixed=3)


def parse_decimal(name: str, value, low, high, *, closed: bool = True):
    """A real number given as an exact decimal, as an mpf at the current mpmath precision.

    Parameters
    ----------
    name : str
        Argument name used in the error message.
    value : str, mpf, int, Decimal or float
        Strings and Decimals are read as exact decimals (correctly rounded to the working
        precision); an mpf or int is taken exactly; a float is read as the decimal its
        shortest repr denotes (``0.6`` means 6/10, not the nearest binary double).
    low, high : int or str
        Valid range, inclusive if ``closed`` else open.

    Raises
    ------
    ValueError
        Naming ``name`` and the valid range, if ``value`` is not a finite decimal number
        in the range.
    """
    bounds = f"[{low}, {high}]" if closed else f"({low}, {high})"
    if isinstance(value, bool):
        raise ValueError(f"{name} must be a decimal number in {bounds}, got {value!r}")
    if isinstance(value, mpmath.mpf):
        exact = value
        check = decimal.Decimal(mpmath.nstr(value, 60)) if mpmath.isfinite(value) else None
    else:
        text = repr(value) if isinstance(value, float) else str(value).strip()
        try:
            check = decimal.Decimal(text)
        except (decimal.InvalidOperation, ValueError):
            raise ValueError(f"{name} must be a decimal number in {bounds}, got {value!r}") from None
        if not check.is_finite():
            raise ValueError(f"{name} must be a finite decimal number in {bounds}, got {value!r}")
        exact = None
    if check is None:
        raise ValueError(f"{name} must be a finite decimal number in {bounds}, got {value!r}")
    lo, hi = decimal.Decimal(str(low)), decimal.Decimal(str(high))
    inside = lo <= check <= hi if closed else lo < check < hi
    if not inside:
        raise ValueError(f"{name} must lie in {bounds}, got {value!r}")
    return exact if exact is not None else mpmath.mpf(str(check))


@functools.lru_cache(maxsize=64)
def _gauss_legendre_cached(m: int, prec: int):
    saved = flint.ctx.prec
    flint.ctx.prec = prec + 20
    try:
        pairs = [flint.arb.legendre_p_root(m, k, weight=True) for k in range(m)]
    finally:
        flint.ctx.prec = saved
    return tuple(+x for x, _ in reversed(pairs)), tuple(+w for _, w in reversed(pairs))


def gauss_legendre(m: int):
    """Gauss-Legendre nodes (ascending) and weights on [-1, 1] at flint's working precision.

    Computed by python-flint (``arb.legendre_p_root``) with 20 extra bits; cached.

    Returns
    -------
    nodes, weights : tuple of arb
    """
    return _gauss_legendre_cached(int(m), flint.ctx.prec)


def to_full_accuracy(function, *args):
    """``function(*args)`` (arb-valued) with its full relative accuracy at flint's precision.

    Some python-flint special functions return wide balls in a transition region (e.g.
    ``arb.bessel_k`` near x = 20 loses about half the bits); this re-evaluates with
    doubling extra precision until the ball's relative accuracy reaches the working
    precision, then rounds.  ``args`` must be exact or accurate at the higher precision.
    """
    prec = flint.ctx.prec
    extra = 16
    try:
        while True:
            flint.ctx.prec = prec + extra
            value = function(*args)
            if value.rel_accuracy_bits() >= prec or extra > 8 * prec:
                break
            extra *= 2
    finally:
        flint.ctx.prec = prec
    return +value


def arb_vector(values):
    """A column vector (``arb_mat`` n x 1) from a sequence of arb."""
    values = list(values)
    return flint.arb_mat(len(values), 1, values)


def matrix_column(matrix, j: int = 0) -> list:
    """Column ``j`` of an ``arb_mat`` as a list of arb."""
    return [matrix[i, j] for i in range(matrix.nrows())]


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
    backend_name = validation.choice("backend", backend or globals()["backend"](), ("flint", "mpmath"))
    n = matrix.rows
    if backend_name == "mpmath":
        lu, perm = mpmath.mp.LU_decomp(matrix.copy())
        columns = []
        for rhs in rhs_columns:
            y = mpmath.mp.L_solve(lu, mpmath.matrix(list(rhs)), perm)
            x = mpmath.mp.U_solve(lu, y)
            columns.append([x[i] for i in range(n)])
        return columns, None
    if flint is None:  # pragma: no cover
        raise ValueError("backend='flint' needs python-flint (pip install python-flint==0.9.0)")
    with flint_dps(mpmath.mp.dps):
        a = flint.arb_mat(n, n)
        for i in range(n):
            for k in range(n):
                a[i, k] = mp_to_arb(matrix[i, k])
        rhs = flint.arb_mat(n, len(rhs_columns))
        for j, col in enumerate(rhs_columns):
            for i in range(n):
                rhs[i, j] = mp_to_arb(col[i])
        x = a.solve(rhs)
        columns = []
        bound = mpmath.mpf(0)
        for j in range(len(rhs_columns)):
            col = []
            for i in range(n):
                mid, rad = arb_to_mp(x[i, j]), arb_radius(x[i, j])
                col.append(mid)
                if mid != 0:
                    bound = max(bound, rad / abs(mid))
            columns.append(col)
    return columns, bound
