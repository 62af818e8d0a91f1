r"""The verdict rules, the thresholds and the reconstruction caveat as text, generated from ``settings``.

``threshold(name)`` is what a check's ``check`` text cites ("TOL_FORMULA = 1e-28");
``verdict_rules`` and ``closure_caveat`` are the paragraphs the report and the
manuscript print (plain or LaTeX).
"""

from __future__ import annotations

from ...typeset import plain_sci, sci
from . import settings

__all__ = ["threshold", "formula_rule", "double_rule", "verdict_rules", "closure_caveat", "CLOSURE_TAG",
           "CLOSURE_TAG_LATEX", "TRUTH"]

#: What every solver-based row compares with.
TRUTH = "the truth (the Abel-Fredholm solution torsional_contact.solve(stick_radius=b))"

#: Appended to both notes of rows whose verdict or numbers use the closure (v).
CLOSURE_TAG = (" These numbers are for the reconstructed printed scheme: the printed equations closed by this "
               "project's choice (T* fixed by traction continuity at r = b), which the paper does not state; row "
               "Sec.3-closure says which findings survive other closures.")
CLOSURE_TAG_LATEX = (r" These numbers are for the reconstructed printed scheme (the printed equations closed by "
                     r"continuity of the traction at $r = b$, which the paper does not state; the closures row says "
                     r"which findings survive other closures).")


def threshold(name: str) -> str:
    """'TOL_FORMULA = 1e-28' for the ``check`` text of a row (the constant of ``settings``)."""
    value = getattr(settings, name)
    if isinstance(value, float) and value < 1e-3:
        return f"{name} = {value:.0e}".replace("e-0", "e-")
    return f"{name} = {value:g}" if isinstance(value, float) else f"{name} = {value}"


def formula_rule() -> str:
    """'; correct if <= TOL_FORMULA = 1e-28' (the rule of every 40-digit formula check)."""
    return f"; correct if <= {threshold('TOL_FORMULA')} relative"


def double_rule() -> str:
    """'; correct if <= TOL_DOUBLE = 1e-12' (checks in double precision)."""
    return f"; correct if <= {threshold('TOL_DOUBLE')} relative"


def verdict_rules(latex: bool = False) -> str:
    """The verdict rules with the thresholds of ``settings``, as one paragraph (plain or LaTeX)."""
    s = settings
    if latex:
        return (
            r"\emph{Correct}: a formula agrees with an independent computation at "
            rf"{s.WORK_DPS} significant digits to a relative ${sci(s.TOL_FORMULA, 0)}$ (a statement checked in double "
            rf"precision: ${sci(s.TOL_DOUBLE, 0)}$); a quoted number differs from the computed value by at most "
            r"half a unit of its last printed digit; a definition is consistent with the equations it serves. "
            r"\emph{Typo}: wrong as printed, but a one-symbol correction is correct. "
            r"\emph{Numerically hazardous}: exact, but evaluated directly in double precision over the paper's range "
            rf"($\lambda \le \lambda_{{2,{s.N_PAPER}}} \approx 460$) it keeps fewer than {s.HAZARD_DIGITS_KEPT} "
            r"significant digits, or (for the truncation $N = 145$) the series coefficients differ from the exact "
            rf"ones, or change when $N$ grows, by more than ${sci(s.NEGLIGIBLE_CHANGE, 0)}$ relative while $T^*$ "
            r"stays within the quoted precision. \emph{Incorrect}: none of these. Solutions are compared with the "
            r"Abel--Fredholm solution (its torque verified to better than $10^{-13}$ against a 30-digit evaluation); "
            r"a torque counts as right within half a unit of the last digit of the quoted $T^* = 1.23$, i.e.\ "
            rf"${sci(s.QUOTED_TORQUE_HALF_UNIT)}$ relative. A row labelled by an equation judges the formula as "
            r"printed; a row labelled by a section judges a statement of the text or the scheme the equations "
            r"form, so a formula can be correct while the scheme built on it is not."
        )
    return (
        f"Correct: a formula agrees with an independent computation at {s.WORK_DPS} digits to "
        f"{plain_sci(s.TOL_FORMULA, 0)} relative (TOL_FORMULA; double-precision statements: "
        f"{plain_sci(s.TOL_DOUBLE, 0)}, TOL_DOUBLE); a quoted number differs from the computed value by at most "
        "half a unit of its last printed digit; a definition is consistent with the equations it serves. Typo: "
        "wrong as printed, but a one-symbol correction is correct. Numerically hazardous: exact, but a direct "
        f"double evaluation over lam <= lam_{s.N_PAPER} keeps fewer than {s.HAZARD_DIGITS_KEPT} digits "
        "(HAZARD_DIGITS_KEPT), or (truncation N = 145) the coefficients differ from the exact ones, or change when "
        f"N grows, by more than {s.NEGLIGIBLE_CHANGE:g} (NEGLIGIBLE_CHANGE) while T* stays within the quoted "
        "precision. Incorrect: none of these. Solutions are compared with the Abel-Fredholm solution (its torque "
        "verified to better than 1e-13 against a 30-digit evaluation); a torque is right within "
        f"{s.QUOTED_TORQUE_HALF_UNIT:.1e} relative (QUOTED_TORQUE_HALF_UNIT, half a unit of the last digit of the "
        "quoted 1.23). A row labelled by an equation judges the formula as printed; a row labelled by a section "
        "judges a statement of the text or the scheme the equations form, so a formula can be correct while the "
        "scheme built on it is not."
    )


def closure_caveat(latex: bool = False) -> str:
    """The reconstruction caveat (see ``settings``) as one paragraph."""
    if latex:
        return (
            r"The paper fixes $b$, solves (38) and `evaluates the torque actually present', but that torque equals "
            r"any imposed $T^*$, so the printed equations do not determine $T^*(b)$. The `published' results "
            r"checked here are the printed equations together with this project's closure ($T^*$ fixed by "
            r"continuity of the truncated traction at $r = b$), which the paper never states. The paper's own "
            r"results ($b/a = 0.6$ at $T^* = 1.23$, a torque curve ending at $4/3$) agree with the corrected "
            r"solution, not with this reconstruction (the reconstructed printed scheme); rows that depend on the "
            r"closure are marked $\dagger$, and the closures row repeats the measurements under two other closures."
        )
    return (
        "The paper fixes b, solves (38) and 'evaluates the torque actually present', but that torque equals any "
        "imposed T*, so the printed equations do not determine T*(b). The 'published' results checked here are the "
        "printed equations plus this project's closure (T* fixed by continuity of the truncated traction at r = b), "
        "which the paper never states. The paper's own results (b/a = 0.6 at T* = 1.23, a torque curve ending at "
        "4/3) agree with the corrected solution, not with this reconstruction (the reconstructed printed scheme); rows "
        "that depend on the closure say so, and row Sec.3-closure repeats the measurements under two other closures."
    )
