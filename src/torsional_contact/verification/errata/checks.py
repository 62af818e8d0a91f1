"""The errata table: every check in paper order, with eq. (51)'s combined verdict; cached per process."""

from __future__ import annotations

import functools
import time

from .appendix_a import check_appendix_a
from .appendix_b import check_appendix_b, check_dini_norm, check_series_hazard
from .bilateral import check_bilateral, check_pressure
from .closures import check_closures
from .conditions import check_conditions
from .coverage import sort_key
from .dual_series import check_dual_series
from .quoted import check_decay, check_fig5, check_zeros
from .series_terms import check_series_terms
from .solution_e import check_potential, check_separation, check_side_condition
from .statements import check_completeness, check_limits, check_torque_evaluation, check_truncation
from .weak_form_passage import check_weak_form_passage, check_weighting

__all__ = ["errata_table", "errata_timing", "summary"]

_CHECKS = (
    check_pressure,
    check_bilateral,
    check_conditions,
    check_potential,
    check_separation,
    check_side_condition,
    check_zeros,
    check_series_terms,
    check_dual_series,
    check_weak_form_passage,
    check_weighting,
    check_dini_norm,
    check_appendix_b,
    check_series_hazard,
    check_appendix_a,
    check_decay,
    check_limits,
    check_truncation,
    check_torque_evaluation,
    check_closures,
    check_completeness,
    check_fig5,
)


@functools.lru_cache(maxsize=1)
def _table(progress: bool):
    rows, timing = [], {}
    checks = _CHECKS
    if progress:
        from tqdm import tqdm

        checks = tqdm(checks, desc="errata checks")
    for check in checks:
        t0 = time.perf_counter()
        rows.extend(check())
        timing[check.__name__.lstrip("_")] = time.perf_counter() - t0
    rows = sorted(_as_printed_verdicts(rows), key=lambda row: sort_key(row["equation"]))  # stable
    return tuple(rows), timing


def _as_printed_verdicts(rows):
    """Eq. (51)'s own verdict: exact, but hazardous as written if its series check says so.

    The paper prints B_m with a 1F2; the formula is right (row "51") but summing it in
    double precision is not (row "51-series"), which is what ``numerically-hazardous``
    means (docs/conventions.md).  The two measurements stay separate rows; the verdict of "51"
    combines them.
    """
    by_equation = {row["equation"]: row for row in rows}
    formula, series = by_equation.get("51"), by_equation.get("51-series")
    if formula and series and formula["verdict"] == "correct" and series["verdict"] == "numerically-hazardous":
        formula["verdict"] = "numerically-hazardous"
        formula["note"] += (" As printed (a 1F2 power series) it is unusable in double precision beyond "
                            "lam ~ 20 (see row 51-series); the library sums a stable form instead.")
        formula["note_latex"] += (r" Summed as the printed ${}_1F_2$ power series in double precision it is "
                                  r"unusable beyond $\lambda \approx 20$ (next row).")
        formula["details"] = {**formula["details"], "summary_latex": (
            r"Exact, but as printed (a ${}_1F_2$ power series) unusable in double precision beyond "
            r"$\lambda \approx 20$; a stable form of the same integral is exact to rounding.")}
    return rows


def errata_table(progress: bool = False) -> list:
    """All checks, in paper order (equations 1-53, then the statements of the text).  Cached per process.

    Returns
    -------
    list of dict (see ``settings``); each dict is a fresh copy.
    """
    rows, _ = _table(bool(progress))
    return [dict(r) for r in rows]


def errata_timing(progress: bool = False) -> dict:
    """Seconds spent per check by ``errata_table`` (computes the table if not cached)."""
    return dict(_table(bool(progress))[1])


def summary(table) -> dict:
    """equation -> verdict."""
    return {row["equation"]: row["verdict"] for row in table}
