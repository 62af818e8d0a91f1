"""Machine-readable errata of the paper: every checked statement, with a computed verdict.

Each check returns a record with ``equation`` (the paper's equation number, e.g. "35",
"A.40", or a label for a statement in the text: "Sec.4-decay", "completeness", "Fig.5"),
``check`` (how it was checked), ``max_rel_discrepancy`` (None when the statement is not a
number), ``verdict`` (``correct``, ``typo``, ``numerically-hazardous`` or ``incorrect``,
computed from the measured numbers by the rules of ``settings``), ``note`` and ``details``.

The checks are split by the paper's sections: ``bilateral`` (eqs. 2-6, 10-17),
``weak_form`` (33-38), ``appendix_a`` (39-50), ``appendix_b`` (34, 35, 51-53),
``statements`` and ``quoted`` (the text of sections 3-4 and Fig. 5); ``checks`` assembles
the table and ``report`` writes it as Markdown.
"""

from .checks import errata_table, errata_timing, summary
from .report import markdown_report, write_markdown_report
from .settings import (
    HAZARD_DIGITS_KEPT,
    N_CONVERGED,
    N_PAPER,
    NEGLIGIBLE_CHANGE,
    TOL_DIFF,
    TOL_DOUBLE,
    TOL_FORMULA,
    VERDICTS,
)
from .verdicts import verdict_formula, verdict_quoted

__all__ = [
    "errata_table",
    "errata_timing",
    "summary",
    "markdown_report",
    "write_markdown_report",
    "verdict_formula",
    "verdict_quoted",
    "VERDICTS",
    "TOL_FORMULA",
    "TOL_DOUBLE",
    "TOL_DIFF",
    "HAZARD_DIGITS_KEPT",
    "N_PAPER",
    "N_CONVERGED",
    "NEGLIGIBLE_CHANGE",
]
