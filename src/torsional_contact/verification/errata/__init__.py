"""Machine-readable errata of the paper: every checked statement, with a computed verdict.

Each check returns a record with ``equation`` (the paper's equation number, e.g. "35",
"A.40", "33-38", or a label for a statement in the text: "Sec.4-decay", "completeness",
"Fig.5"), ``check`` (how it was checked, with the threshold of its verdict),
``max_rel_discrepancy`` (None when the statement is not a number), ``verdict``
(``correct``, ``typo``, ``numerically-hazardous`` or ``incorrect``, computed from the
measured numbers by the rules of ``settings``), ``note`` (plain text), ``note_latex`` (the
note as LaTeX sentences for the manuscript) and ``details`` (the numbers; ``kind`` and
``depends_on_closure``).

Solutions are compared with the Abel-Fredholm solution (``truth``).  The 'published'
results are the printed equations plus this project's closure (T* fixed by traction
continuity at r = b), which the paper does not state; see ``settings`` for this caveat.

The checks are split by the paper's sections: ``bilateral`` (eqs. 1-6), ``conditions``
(7-9), ``solution_e`` (10-19), ``quoted`` (20, the decay of section 4, Fig. 5),
``series_terms`` (21-26), ``dual_series`` (27-32), ``weak_form`` (33-38), ``closures`` (the
printed scheme under three closures), ``appendix_b``
(34, 35, 51-53), ``appendix_a`` (39-50) and ``statements`` (the text of sections 3-4);
``checks`` assembles the table, ``coverage`` maps it onto the equations 1-53, ``rules``
states the verdict rules and ``report`` writes the table as Markdown.
"""

from .checks import errata_table, errata_timing, summary
from .coverage import coverage, paper_equations
from .report import markdown_report, write_markdown_report
from .rules import closure_caveat, verdict_rules
from .settings import (
    CONSISTENCY_FACTOR,
    HAZARD_DIGITS_KEPT,
    N_CONVERGED,
    N_PAPER,
    NEGLIGIBLE_CHANGE,
    PAPER_EQUATIONS,
    QUOTED_TORQUE_HALF_UNIT,
    TOL_DOUBLE,
    TOL_FORMULA,
    UNCHECKED,
    VERDICTS,
    WORK_DPS,
)
from .verdicts import verdict_formula, verdict_quoted

__all__ = [
    "errata_table",
    "errata_timing",
    "summary",
    "coverage",
    "paper_equations",
    "markdown_report",
    "write_markdown_report",
    "verdict_rules",
    "closure_caveat",
    "verdict_formula",
    "verdict_quoted",
    "VERDICTS",
    "WORK_DPS",
    "TOL_FORMULA",
    "TOL_DOUBLE",
    "HAZARD_DIGITS_KEPT",
    "N_PAPER",
    "N_CONVERGED",
    "NEGLIGIBLE_CHANGE",
    "QUOTED_TORQUE_HALF_UNIT",
    "CONSISTENCY_FACTOR",
    "PAPER_EQUATIONS",
    "UNCHECKED",
]
