"""Verdict rules of the errata checks and the record each check returns (thresholds in ``settings``)."""

from __future__ import annotations

from .settings import KINDS, TOL_FORMULA, VERDICTS

__all__ = ["verdict_formula", "verdict_quoted", "entry", "relative_difference"]


def verdict_formula(discrepancy: float, tol: float = TOL_FORMULA, corrected_discrepancy: float | None = None) -> str:
    """``correct`` if discrepancy <= tol, ``typo`` if only a listed correction passes, else ``incorrect``."""
    if discrepancy <= tol:
        return "correct"
    if corrected_discrepancy is not None and corrected_discrepancy <= tol:
        return "typo"
    return "incorrect"


def verdict_quoted(computed: float, quoted: float, decimals: int) -> tuple[str, float]:
    """Quoted number with ``decimals`` printed decimals vs the computed value.

    Returns (verdict, relative discrepancy).  ``correct`` if |computed - quoted| is at
    most half a unit of the last printed decimal (plus 1e-12 for rounding of the test).
    """
    half_unit = 0.5 * 10.0 ** (-decimals)
    diff = abs(computed - quoted)
    return ("correct" if diff <= half_unit * (1 + 1e-12) else "incorrect"), diff / abs(computed)


def entry(equation, check, discrepancy, verdict, note, note_latex, *, kind="formula", depends_on_closure=False,
          **details):
    """One row of the errata table (see ``settings``).

    ``note`` is plain text (JSON, Markdown, CLI), ``note_latex`` one or two full LaTeX
    sentences for the manuscript.  ``kind`` and ``depends_on_closure`` go into ``details``.
    """
    if verdict not in VERDICTS:
        raise ValueError(f"verdict must be one of {VERDICTS}, got {verdict!r}")
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    return {
        "equation": equation,
        "check": check,
        "max_rel_discrepancy": None if discrepancy is None else float(discrepancy),
        "verdict": verdict,
        "note": note,
        "note_latex": note_latex,
        "details": {"kind": kind, "depends_on_closure": bool(depends_on_closure), **details},
    }


def relative_difference(a, b) -> float:
    """|a - b| / |b| as a float (mpf or float arguments)."""
    return float(abs(a - b) / abs(b))
