r"""The weak-form system of eqs. (33)-(38) and its completion in Arb ball arithmetic (python-flint).

The same printed formulas as ``weak_form_mp`` (eqs. 35, 51, 52, 53 and the completion), evaluated
with python-flint ``arb`` balls instead of mpmath numbers: the Bessel functions, 1F2 and the N^2
Lommel brackets run in C, and the matrix goes to ``arb_mat.solve`` without conversion.  The ball
radii bound the rounding of the assembly as well as of the solve.  ``weak_form_mp`` stays the
mpmath twin (the errata compare its printed forms with quadrature; ``reference.solve_reference``
with ``assembly="mpmath"`` runs the whole reference in mpmath, and the tests compare the two).
Lengths in a (a = 1); everything at flint's working precision (``arbitrary_precision.working_digits``).
"""

from __future__ import annotations

from .. import validation
from ..solvers.weak_form import WEAK_FORMS
from .arbitrary_precision import flint, to_full_accuracy

__all__ = ["integral_t_j1_hyp1f2", "assemble", "traction_weights"]


def _bessel(order: int, x):
    """J_order(x) for exact arb x (zero radius), to the full working precision (``to_full_accuracy``)."""
    return to_full_accuracy(lambda y: y.bessel_j(order), x)


def _products(lam, b) -> list:
    """lam_n b rounded to the working precision and taken as exact (the midpoints), as mpmath takes its
    rounded product: the functions of it can then reach full accuracy (a ball's radius times
    J' or G' ~ lam would cap them)."""
    return [(b * x).mid() for x in lam]


#: The functions of the zeros alone (``_at_zeros``) for the last few (working precision, zeros): the same for every
#: stick radius, of which a reference job solves several.
_ZERO_VALUES: dict = {}
_ZERO_VALUES_KEPT = 4


def _at_zeros(lam) -> tuple:
    """(J0, J1, J2 at lam_n, G(lam_n) = int_0^lam_n t J1(t) dt) as lists of arb: what the assembly needs of the zeros
    alone.  Kept for the last few sets of zeros and working precisions (keyed on the balls' exact midpoints and
    radii), so that each is evaluated once per job; the values are those of a fresh evaluation."""
    key = (flint.ctx.prec, tuple((x.mid().man_exp(), x.rad().man_exp()) for x in lam))
    values = _ZERO_VALUES.get(key)
    if values is None:
        values = tuple([_bessel(k, x) for x in lam] for k in (0, 1, 2)) + ([integral_t_j1_hyp1f2(x) for x in lam],)
        if len(_ZERO_VALUES) >= _ZERO_VALUES_KEPT:
            del _ZERO_VALUES[next(iter(_ZERO_VALUES))]
        _ZERO_VALUES[key] = values
    return values


def integral_t_j1_hyp1f2(x):
    """int_0^x t J1(t) dt = x^3/6 1F2(3/2; 2, 5/2; -x^2/4) (eq. 51, as printed), exact arb x >= 0."""
    if x.is_zero():
        return flint.arb(0)
    half3, half5 = flint.arb(3) / 2, flint.arb(5) / 2
    series = to_full_accuracy(lambda y: (-(y * y) / 4).hypgeom([half3], [2, half5]), x)
    return x**3 / 6 * series


def assemble(method: str, lam, b):
    """Matrix and right-hand sides of (iii)-(iv) (``weak_form_mp.assemble``'s layout) as Arb objects.

    ``lam``: exact arb zeros of J2; ``b``: exact arb stick radius.  Returns
    ``(arb_mat, arb_mat with the columns rhs_torque, rhs_constant)``.  Entry for entry the printed
    forms of ``weak_form_mp``: the Lommel brackets (52) with their r = 1 terms, the diagonal (53),
    h (35), the load integrals (51) with G in the 1F2 form, and the completion's row and column.
    """
    method = validation.choice("method", method, WEAK_FORMS)
    n = len(lam)
    blam = _products(lam, b)
    j0, j1, j2, g_one = _at_zeros(lam)
    b0, b1, b2 = ([_bessel(k, x) for x in blam] for k in (0, 1, 2))
    size = n if method == "published" else n + 1
    entries = [flint.arb(0)] * (size * size)
    squares = [x * x for x in lam]
    for i in range(n):
        lam_i, jm0, jm1, bm0, bm1 = lam[i], j0[i], j1[i], b0[i], b1[i]
        diagonal = (lam_i * jm0 * jm0 + lam_i * jm1 * jm1 - 2 * jm0 * jm1 + 2 * b * bm0 * bm1
                    - b * b * lam_i * (bm0 * bm0 + bm1 * bm1)) / (2 * lam_i)  # (53)
        dini = (jm0 * jm0 - 2 * jm0 * jm1 / lam_i + jm1 * jm1) / 2  # (35)
        entries[i * size + i] = diagonal * (lam_i - 1) + dini
        for k in range(i + 1, n):  # (52), symmetric before the column factor lam_k - 1
            lam_k = lam[k]
            bracket = (lam_k * j0[k] * jm1 - b * lam_k * b0[k] * bm1 - lam_i * jm0 * j1[k]
                       + b * lam_i * bm0 * b1[k])
            value = bracket / (squares[i] - squares[k])
            entries[i * size + k] = value * (lam_k - 1)
            entries[k * size + i] = value * (lam_i - 1)
    g_b = [integral_t_j1_hyp1f2(x) for x in blam]
    rhs_torque = [(j2[i] - b * b * b2[i]) / lam[i] for i in range(n)]
    rhs_constant = [-(g_one[i] - g_b[i]) / squares[i] for i in range(n)]
    if method == "complete":
        stick = [b * b * b2[i] / lam[i] for i in range(n)]
        for i in range(n):
            entries[i * size + n] = stick[i]
            entries[n * size + i] = (1 - lam[i]) * stick[i]
        entries[n * size + n] = b**4 / 4
        rhs_torque.append((1 - b**4) / 4)
        rhs_constant.append(-(1 - b**3) / 3)
    rhs = flint.arb_mat(size, 2, [v for pair in zip(rhs_torque, rhs_constant, strict=True) for v in pair])
    return flint.arb_mat(size, size, entries), rhs


def traction_weights(lam, b) -> list:
    """lam_n J1(lam_n b), the weights of the regularity condition (v), arb."""
    return [x * _bessel(1, y) for x, y in zip(lam, _products(lam, b), strict=True)]
