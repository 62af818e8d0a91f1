"""Precision cross-checks of the double-precision weak-form solver against the mpmath reference.

``rounding_error`` (same truncated system, so rounding only), ``condition_numbers`` (the
1-norm condition number against N) and ``truncation_error`` (N against a larger N).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..diagnostics import AccuracyWarning, UnphysicalResultWarning
from ..solvers.equilibration import equilibrate, reciprocal_condition
from ..solvers.weak_form import WEAK_FORMS, solve_series
from ..solvers.weak_form import assemble as assemble_double
from ..special.zeros import bessel_j2_zeros
from .reference import ReferenceSolution

__all__ = ["rounding_error", "condition_numbers", "truncation_error", "GROWTH_DIGITS"]

#: Digits a backward-stable dense solve may lose beyond log10 of its condition number.  LU with partial pivoting
#: bounds the forward error by kappa x 3n x growth x EPS (|dA| <= gamma_3n |L||U|; growth = || |L||U| || / ||A||,
#: a few for these equilibrated systems), and ``rcond`` is LAPACK's estimate of 1/kappa (dgecon: low by at most
#: ~3 here).  For the cross-check's n <= 580 the worst case is ~3.8 digits; rounding errors accumulate like
#: sqrt(3n) in practice (~1.6 digits): 3 digits.
GROWTH_DIGITS = 3


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


def condition_numbers(n_terms_list, stick_radius: float = 0.6, methods=WEAK_FORMS, progress: bool = False) -> list:
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
                "raw": 1.0 / reciprocal_condition(matrix),
                "equilibrated": 1.0 / reciprocal_condition(equilibrate(matrix)),
            }
        )
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
