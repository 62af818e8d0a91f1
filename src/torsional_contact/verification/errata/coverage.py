"""Which of the paper's numbered equations (1-53) have a row in the errata table.

A row's ``equation`` label names the equations it checks: "35" -> (35), "A.40" -> (40)
(Appendix A keeps the paper's numbering), "33-38" -> (33)..(38), "51-series" -> (51); statements of
the text and of the scheme ("Sec.3-weighting", "Sec.4-decay", "completeness", "Fig.5", ...) name none.
"""

from __future__ import annotations

import re

from .settings import PAPER_EQUATIONS, UNCHECKED

__all__ = ["paper_equations", "coverage", "sort_key"]

_LABEL = re.compile(r"(?:A\.)?(\d+)(?:-(\d+))?(?:-([a-z]+))?")


def paper_equations(label: str) -> tuple[int, ...]:
    """The paper's equation numbers a row label covers (empty for statements of the text)."""
    match = _LABEL.fullmatch(label)
    if match is None:
        return ()
    first = int(match.group(1))
    last = int(match.group(2)) if match.group(2) else first
    return tuple(range(first, last + 1))


def sort_key(label: str) -> tuple:
    """Paper order: equations by number (a suffixed row after its equation), then the statements."""
    numbers = paper_equations(label)
    if not numbers:
        return (1, 0, 0)
    return (0, numbers[0], 0 if _LABEL.fullmatch(label).group(3) is None else 1)


def coverage(table) -> dict:
    """Coverage of the paper's equations 1-53 by the rows of ``table``.

    Returns
    -------
    dict with ``equations`` (all numbers), ``checked`` (numbers with at least one row),
    ``unchecked`` (number -> reason, from ``settings.UNCHECKED``) and ``missing`` (numbers
    with neither a row nor a stated reason; empty when the table is complete).
    """
    checked = sorted({n for row in table for n in paper_equations(row["equation"])} & set(PAPER_EQUATIONS))
    unchecked = {n: UNCHECKED[n] for n in PAPER_EQUATIONS if n in UNCHECKED and n not in checked}
    missing = [n for n in PAPER_EQUATIONS if n not in checked and n not in unchecked]
    return {"equations": list(PAPER_EQUATIONS), "checked": checked, "unchecked": unchecked, "missing": missing}
