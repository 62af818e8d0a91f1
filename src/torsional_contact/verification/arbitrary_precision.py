"""Arbitrary-precision utilities of the verification wing: mpmath <-> python-flint, dense solves.

python-flint (Arb ball arithmetic) is optional: without it every function falls back to
mpmath, which is slower but gives the same digits; ``FLINT`` says which is in use.
Nothing here changes mpmath's or flint's working precision beyond a ``with`` block.
"""

from __future__ import annotations

import contextlib

import mpmath

from .. import validation

try:  # optional accelerator of Bessel functions and dense linear algebra
    import flint
except ImportError:  # pragma: no cover - exercised only without python-flint
    flint = None

__all__ = ["FLINT", "flint", "flint_dps", "mp_to_arb", "arb_to_mp", "solve_linear", "parse_stick_radius", "backend"]

#: True when python-flint is importable.
FLINT = flint is not None


def backend() -> str:
    """The default dense-solve backend: "flint" if python-flint is importable, else "mpmath"."""
    return "flint" if FLINT else "mpmath"



@contextlib.contextmanager
def flint_dps(dps: int):
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


def mp_to_arb(x):
    """Exact conversion mpf -> flint.arb (binary mantissa and exponent)."""
    sign, man, exp, _ = mpmath.mpf(x)._mpf_
    if man == 0:
        return flint.arb(0)
    value = flint.arb(flint.fmpz(int(-man if sign else man))) * flint.arb(2) ** int(exp)  # gmpy2 or int mantissa
    return value


def arb_to_mp(x):
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
                mid, rad = arb_to_mp(x[i, j])
                col.append(mid)
                if mid != 0:
                    bound = max(bound, rad / abs(mid))
            columns.append(col)
    return columns, bound
