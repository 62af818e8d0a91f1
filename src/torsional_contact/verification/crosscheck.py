"""Precision cross-checks of the double-precision weak-form solver against the mpmath reference.

``rounding_error`` (same truncated system, so rounding only), ``condition_numbers`` (the
1-norm condition number against N) and ``truncation_error`` (N against a larger N).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy import linalg

from .. import validation
from ..diagnostics import AccuracyWarning, IllConditioningWarning, ResolutionWarning, UnphysicalResultWarning
from ..solvers.equilibration import _row_blocks, equilibrate_in_place
from ..solvers.weak_form import RCOND_WARN, WEAK_FORMS, closure_torque, complete_border, resolution_limit, solve_series
from ..solvers.weak_form import assemble as assemble_double
from ..special.zeros import bessel_j2_zeros
from .reference import ReferenceSolution

__all__ = ["rounding_error", "condition_numbers", "truncation_error", "truncation_errors", "weak_forms_at",
           "GROWTH_DIGITS"]

#: Digits a backward-stable dense solve may lose beyond log10 of its condition number.  LU with partial pivoting
#: bounds the forward error by kappa x 3n x growth x EPS (|dA| <= gamma_3n |L||U|; growth = || |L||U| || / ||A||,
#: a few for these equilibrated systems), and ``rcond`` is LAPACK's estimate of 1/kappa (dgecon: low by at most
#: ~3 here).  For the cross-check's n <= 580 the worst case is ~3.8 digits; rounding errors accumulate like
#: sqrt(3n) in practice (~1.6 digits): 3 digits.
GROWTH_DIGITS = 3
EPS = float(np.finfo(float).eps)


def _rel(a, b):
    return abs(float(a) - float(b)) / abs(float(b))


def rounding_error(reference: ReferenceSolution) -> dict:
    """Rounding error of ``solvers.weak_form.solve_series`` at the same (b, method, N).

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
        If scipy lost more digits than the condition number allows (+ ``GROWTH_DIGITS``).
    """
    b = float(reference.stick_radius)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnphysicalResultWarning)
        dp = solve_series(b, reference.method, reference.n_terms)
    ref_c = np.array([float(c) for c in reference.amplitudes])
    err_c = float(np.max(np.abs(dp.amplitudes - ref_c)) / np.max(np.abs(ref_c)))
    err_t = _rel(dp.torque, reference.torque)
    err_w = None if reference.rigid_rotation is None else _rel(dp.rigid_rotation, reference.rigid_rotation)
    worst = max(e for e in (err_t, err_w, err_c) if e is not None)
    eps = np.finfo(float).eps
    lost = math.log10(max(worst, eps) / eps)
    predicted = -math.log10(dp.rcond)
    if lost > predicted + GROWTH_DIGITS:
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


def _row_order(pivots) -> np.ndarray:
    """perm with (P A)[i] = A[perm[i]] for LAPACK's sequential row interchanges ``pivots`` (getrf's ipiv)."""
    perm = np.arange(pivots.size)
    for i, p in enumerate(pivots):
        perm[i], perm[p] = perm[p], perm[i]
    return perm


def _border(lu, order, column, row, corner):
    """(u, l, pivot) of the LU factors of [[A, column], [row, corner]] from those of A (P A = L U, getrf layout,
    ``order`` = ``_row_order`` of its interchanges).

    diag(P, 1) [[A, c], [r, d]] = [[L, 0], [l, 1]] [[U, u], [0, d - l.u]] with L u = P c and l U = r: two
    triangular solves, O(n^2).  The pivoting is A's (the border row is not a pivot candidate); a valid
    factorisation all the same, which is all the condition estimate needs.
    """
    u = linalg.solve_triangular(lu, column[order], lower=True, unit_diagonal=True, check_finite=False)
    l_row = linalg.solve_triangular(lu, row, trans="T", lower=False, check_finite=False)
    return u, l_row, corner - l_row @ u


def _factor_solves(lu, border=None, scale=None):
    """(solve, solve_t): x -> U^-1 L^-1 x and x -> L^-T U^-T x with LU factors in getrf layout, without their
    interchanges (the operator whose 1-norm dgecon estimates: ||U^-1 L^-1||_1 = ||A^-1||_1).

    ``border`` = (u, l, pivot) of ``_border``: the factors [[L, 0], [l, 1]] [[U, u], [0, pivot]] of the bordered
    matrix.  ``scale`` = (r_p, c), r_p = the row scaling in the factors' row order and c the column scaling: the
    factors of R A C are (R_p L R_p^-1)(R_p U C) with the same interchanges, so U^-1 L^-1 becomes
    C^-1 U^-1 L^-1 R_p^-1 (and its transpose R_p^-1 L^-T U^-T C^-1).
    """
    n = lu.shape[0]

    def lower(x, trans):
        return linalg.solve_triangular(lu, x, lower=True, unit_diagonal=True, trans=trans, check_finite=False)

    def upper(x, trans):
        return linalg.solve_triangular(lu, x, lower=False, trans=trans, check_finite=False)

    def apply(x, trans):
        """B x (trans 0) or B^T x (trans 1): the triangular factors in the order of that product, the scalings
        swapped and the border's row and column exchanged for the transpose."""
        first, second = (lower, upper) if trans == 0 else (upper, lower)
        if scale is not None:
            x = x / scale[trans]
        if border is None:
            y = second(first(x, trans), trans)
        else:
            u, l_row, pivot = border
            inner, outer = (l_row, u) if trans == 0 else (u, l_row)
            z = first(x[:n], trans)
            last = (x[n] - inner @ z) / pivot
            y = np.append(second(z - outer * last, trans), last)
        return y if scale is None else y / scale[1 - trans]

    return (lambda x: apply(x, 0)), (lambda x: apply(x, 1))


#: Iterations of LAPACK's 1-norm estimator (dlacn2's ITMAX).
_ESTIMATOR_ITERATIONS = 5


def _inverse_norm_estimate(solve, solve_t, n: int) -> float:
    """Hager-Higham estimate of ||B||_1 from products with B and B^T: LAPACK's dlacn2 step for step (Higham,
    ACM TOMS 14 (1988) 381, Algorithm 4.1, as dgecon drives it), so the same estimate to rounding: the norm of
    a computed B x (a lower bound, to rounding, usually the exact value; never more than a small factor below
    it on these systems, tests/test_reference.py)."""
    x = solve(np.full(n, 1.0 / n))
    if n == 1:
        return float(abs(x[0]))
    estimate = float(np.sum(np.abs(x)))
    sign = np.where(x >= 0.0, 1.0, -1.0)
    x = solve_t(sign)
    j = int(np.argmax(np.abs(x)))  # idamax: the first of equal maxima
    iteration = 2
    while True:
        unit = np.zeros(n)
        unit[j] = 1.0
        x = solve(unit)
        previous, estimate = estimate, float(np.sum(np.abs(x)))
        new_sign = np.where(x >= 0.0, 1.0, -1.0)
        if np.array_equal(new_sign, sign) or estimate <= previous:  # converged, or cycling
            break
        sign = new_sign
        x = solve_t(sign)
        last, j = j, int(np.argmax(np.abs(x)))
        if x[last] == abs(x[j]) or iteration >= _ESTIMATOR_ITERATIONS:
            break
        iteration += 1
    alternating = (1.0 + np.arange(n) / (n - 1)) * np.where(np.arange(n) % 2 == 0, 1.0, -1.0)
    extra = 2.0 * (float(np.sum(np.abs(solve(alternating)))) / (3 * n))
    return max(estimate, extra)


def _rcond_estimate(lu, anorm, border=None, scale=None) -> float:
    """dgecon's 1 / (||A||_1 ||A^-1||_1) for the matrix whose factors ``_factor_solves`` applies (0 for a zero
    pivot, as dgecon)."""
    pivots = np.append(np.diagonal(lu), [] if border is None else [border[2]])
    if anorm == 0.0 or not np.all(pivots != 0.0):
        return 0.0
    solve, solve_t = _factor_solves(lu, border, scale)
    with np.errstate(over="ignore", invalid="ignore"):
        norm = _inverse_norm_estimate(solve, solve_t, pivots.size)
    rcond = (1.0 / norm) / anorm if norm != 0.0 else 0.0
    if math.isnan(rcond):
        raise RuntimeError("the condition estimate is not a number")
    return rcond


def _bordered_norms(matrix, column, row, corner) -> dict:
    """The 1-norms and scalings of A (``matrix``, Fortran order) and of [[A, column], [row, corner]], raw and
    equilibrated, without forming the bordered matrix or any other of A's size: method -> (||M||_1, row scaling,
    column scaling, ||R M C||_1).

    The scalings are ``scalings``' of each matrix bit for bit (maxima are exact); the column sums of |M| and
    |R M C| are summed pairwise down A's contiguous columns, the border's entry last: the sums of the plain
    expressions to (N + log2 N) EPS relative (any order of summation of N + 1 non-negative terms is within
    N EPS of the exact sum).
    """
    n = matrix.shape[0]
    blocks = _row_blocks(matrix.T.shape)  # blocks of columns
    abs_row, abs_column = np.abs(row), np.abs(column)
    row_max = np.zeros(n)
    sums = np.empty(n)
    for cols in blocks:
        block = np.abs(matrix[:, cols])
        np.maximum(row_max, np.max(block, axis=1), out=row_max)
        sums[cols] = np.sum(block, axis=0)
    if not np.all(np.isfinite(sums)) and not np.all(np.isfinite(matrix)):
        raise ValueError("array must not contain infs or NaNs")
    row_p = 1.0 / row_max
    row_c = np.append(1.0 / np.maximum(row_max, abs_column), 1.0 / max(np.max(abs_row), abs(corner)))
    col_p, col_c = np.empty(n), np.empty(n + 1)
    last_c = abs_row * row_c[n]  # the border row, row-scaled
    for cols in blocks:
        block = matrix[:, cols]
        col_p[cols] = 1.0 / np.max(np.abs(block * row_p[:, None]), axis=0)
        col_c[cols] = 1.0 / np.maximum(np.max(np.abs(block * row_c[:n, None]), axis=0), last_c[cols])
    border_c = np.abs(column * row_c[:n])
    col_c[n] = 1.0 / max(np.max(border_c), abs(corner * row_c[n]))
    sums_p, sums_c = np.empty(n), np.empty(n + 1)
    for cols in blocks:
        block = matrix[:, cols]
        sums_p[cols] = np.sum(np.abs((block * row_p[:, None]) * col_p[None, cols]), axis=0)
        sums_c[cols] = np.sum(np.abs((block * row_c[:n, None]) * col_c[None, cols]), axis=0)
    sums_c[:n] += np.abs((row * row_c[n]) * col_c[:n])
    sums_c[n] = np.sum(np.abs((column * row_c[:n]) * col_c[n])) + abs((corner * row_c[n]) * col_c[n])
    raw_c = max(np.max(sums + abs_row), np.sum(abs_column) + abs(corner))
    return {"published": (np.max(sums), row_p, col_p, np.max(sums_p)),
            "complete": (raw_c, row_c, col_c, np.max(sums_c))}


def condition_numbers(n_terms_list, stick_radius: float = 0.6, methods=WEAK_FORMS, progress: bool = False) -> list:
    """1-norm condition numbers of the double-precision system vs N (raw and equilibrated).

    kappa_1 = ||A||_1 ||A^-1||_1 with ||A^-1||_1 estimated as LAPACK's dgecon estimates it (Hager-Higham, within
    a small factor of the exact value, usually exact) from LU factors.  One O(N^3) factorisation per N serves
    the four matrices: the published A is factorised, the complete system is A bordered by one row and column
    (``_border``) and the equilibrated ones have the same factors scaled by the row and column scalings
    (``_factor_solves``); the estimator's products with the inverse and its transpose are triangular solves
    with A's factors and O(N) corrections, so each estimate is of the same operator inverse as from its own
    factorisation, to rounding (relative kappa EPS < 1e-10 here, far below the estimator's own factor).  A is
    assembled in LAPACK's layout and factored in place after ``_bordered_norms`` has taken the four 1-norms
    and scalings from it and the border (no other array of its size).

    Returns
    -------
    list of dict(n_terms, method, raw, equilibrated)
    """
    unknown = set(methods) - set(WEAK_FORMS)
    if unknown:
        raise ValueError(f"methods must be among {WEAK_FORMS}, got {sorted(unknown)}")
    out = []
    sizes = [int(n) for n in n_terms_list]
    if progress:
        from tqdm import tqdm

        sizes = tqdm(sizes, desc="condition numbers")
    for n in sizes:
        lam = bessel_j2_zeros(n)
        # the published matrix in the layout LAPACK factors (in place, after its norms are taken); the complete
        # system borders it
        published, _, _ = assemble_double("published", lam, stick_radius, order="F")
        column, row, corner, _, _ = complete_border(lam, stick_radius)
        norms = _bordered_norms(published, column, row, corner)
        lu, pivots = linalg.lu_factor(published, overwrite_a=True, check_finite=False)
        del published
        order = _row_order(pivots)
        systems = {"published": (order, None)}
        if "complete" in methods:
            systems["complete"] = (np.append(order, n), _border(lu, order, column, row, corner))
        for m in methods:
            order_m, border_m = systems[m]
            anorm, row_scale, col_scale, anorm_equilibrated = norms[m]
            raw = _rcond_estimate(lu, anorm, border_m)
            equilibrated = _rcond_estimate(lu, anorm_equilibrated, border_m, (row_scale[order_m], col_scale))
            out.append({"n_terms": n, "method": m, "stick_radius": stick_radius, "raw": 1.0 / raw,
                        "equilibrated": 1.0 / equilibrated})
    return out


def truncation_error(stick_radius: float, method: str, n_terms: int, n_terms_converged: int) -> dict:
    """Change of T* (and omega) between N and a much larger N (double precision).

    This is the truncation error of the N-term system, separate from rounding
    (which ``rounding_error`` measures at fixed N).
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnphysicalResultWarning)
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


def weak_forms_at(stick_radius: float, n_terms: int) -> dict:
    """(T*, omega) of both weak forms at N = ``n_terms`` from one factorisation: method -> (torque, omega), and
    ``rounding_bound`` = EPS / rcond of the equilibrated A (the relative rounding both routes are subject to).

    The published system is solved exactly as ``solve_series`` solves it (row and column equilibration,
    LU with partial pivoting, closure (v)); the complete system [[A, s], [t, d]] borders it by the
    rigid-rotation unknown and is solved with the same factors by block elimination,
    omega = (f_n - t.A^-1 f) / (d - t.A^-1 s), c = A^-1 f - omega A^-1 s, a backward-stable route while the
    Schur complement d - t.A^-1 s is not small against |d| + |t||A^-1 s| (checked: ``AccuracyWarning``).  The two
    routes to the complete solution agree to kappa EPS (kappa = 1 / rcond of the equilibrated A).

    Raises ValueError naming the argument for stick_radius outside (0, 1], n_terms not an integer >= 1, or a
    stick radius whose system or T* leaves the double range (about 1e-200 and below at N = 60); warns
    (``ResolutionWarning``) where N does not resolve the stick disc or the slip annulus.
    """
    b = validation.real_number("stick_radius", stick_radius, 0.0, 1.0)
    if b == 0.0:
        raise ValueError("stick_radius must lie in (0, 1]: at 0 the closure of the weak forms divides by zero "
                         "(solve() takes the spinning limit there)")
    lam = bessel_j2_zeros(validation.positive_int("n_terms", n_terms))
    b_min, b_max = resolution_limit(lam.size)
    if not b_min <= b <= b_max and b != 1.0:
        warnings.warn(f"stick_radius={b:.6g} is not resolved by n_terms={lam.size} (resolved: [{b_min:.4g}, "
                      f"{b_max:.4g}]): T* and omega of both weak forms may be off in their leading digits",
                      ResolutionWarning, stacklevel=2)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):  # the result is checked below
        out = _weak_forms(b, lam)
    if not all(np.isfinite(out[method][0]) for method in WEAK_FORMS) or not np.isfinite(out["complete"][1]):
        raise ValueError(f"stick_radius={b:.6g} is too small for the weak forms at n_terms={lam.size}: their system "
                         f"or T* leaves the double range")
    return out


def _weak_forms(b: float, lam: np.ndarray) -> dict:
    """The numbers of ``weak_forms_at`` (checked there)."""
    n = lam.size
    # the published matrix in the layout LAPACK factors, equilibrated and factored in place; the complete system
    # borders it
    scaled, rhs_torque, rhs_constant = assemble_double("published", lam, b, order="F")
    column, t, d, torque_last, constant_last = complete_border(lam, b)
    row, col, column_sums = equilibrate_in_place(scaled)
    if not np.all(np.isfinite(column_sums)):  # the scaling overflows: nothing below is a number
        return {method: (math.inf, math.nan) for method in WEAK_FORMS} | {"rounding_bound": math.nan}
    lu, pivots = linalg.lu_factor(scaled, overwrite_a=True, check_finite=False)
    del scaled
    rcond = _rcond_estimate(lu, np.max(column_sums))  # dgecon's estimate, by triangular solves
    if rcond < RCOND_WARN:
        warnings.warn(f"the weak forms for stick_radius={b:.6g}, n_terms={n} are ill-conditioned "
                      f"(reciprocal condition number {rcond:.2e})", IllConditioningWarning, stacklevel=3)
    rhs = np.column_stack([rhs_torque, rhs_constant])
    x = linalg.lu_solve((lu, pivots), rhs * row[:, None]) * col[:, None]  # as equilibrated_solve
    border = linalg.lu_solve((lu, pivots), column * row) * col
    out = {"published": (closure_torque("traction", "published", lam, b, x[:, 0], x[:, 1]), math.nan),
           "rounding_bound": EPS / rcond}
    schur = d - t @ border
    if abs(schur) < 1e3 * EPS * (abs(d) + np.abs(t) @ np.abs(border)):
        warnings.warn(f"block elimination of the complete system at stick_radius={b:.6g}, n_terms={n}: the Schur "
                      f"complement {schur:.3g} is at rounding level", AccuracyWarning, stacklevel=3)
    omega = (np.array([torque_last, constant_last]) - t @ x) / schur
    coefficients = x - border[:, None] * omega[None, :]
    solution = np.vstack([coefficients, omega[None, :]])
    torque = closure_torque("traction", "complete", lam, b, solution[:, 0], solution[:, 1])
    out["complete"] = (torque, float(solution[n, 1] + torque * solution[n, 0]))
    return out


def truncation_errors(stick_radius: float, n_terms: int, n_terms_converged: int, methods=WEAK_FORMS,
                      converged: dict | None = None) -> list:
    """``truncation_error`` for each of ``methods`` at one b, the converged systems solved with one factorisation
    (``weak_forms_at``): the published T* is computed as ``solve_series`` computes it, the complete one by
    block elimination (agreeing with ``solve_series`` to kappa EPS, ~1e-11 relative at N = 4000).  ``converged``:
    ``weak_forms_at(stick_radius, n_terms_converged)`` if the caller has it already."""
    if converged is None:
        converged = weak_forms_at(stick_radius, n_terms_converged)
    out = []
    for method in methods:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UnphysicalResultWarning)
            a = solve_series(stick_radius, method, n_terms)
        torque, omega = converged[method]
        out.append({
            "stick_radius": stick_radius,
            "method": method,
            "n_terms": n_terms,
            "n_terms_converged": n_terms_converged,
            "torque": a.torque,
            "torque_converged": torque,
            "torque_rel_change": abs(a.torque - torque) / torque,
            "rigid_rotation": a.rigid_rotation if method == "complete" else None,
            "rigid_rotation_converged": omega if method == "complete" else None,
            "converged_rounding_bound": converged["rounding_bound"],
        })
    return out
