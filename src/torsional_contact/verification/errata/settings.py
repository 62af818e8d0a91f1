r"""Settings of the errata checks: verdict words, thresholds, precisions, the truth and its caveat.

Each check returns a dict with

* ``equation``: the paper's equation number ("35", "A.40", "33-38"), or a label for a
  statement in the text ("Sec.4-decay", "completeness", "Fig.5");
* ``check``: how it was checked, naming the threshold of its verdict;
* ``max_rel_discrepancy``: the largest measured relative discrepancy (None when the
  statement is not a number);
* ``verdict``: one of ``correct``, ``typo``, ``numerically-hazardous``, ``incorrect``,
  computed by the rules below from the measured numbers (never typed by hand);
* ``note``: what was found (plain text); ``note_latex``: the same in one or two full
  sentences of LaTeX for the manuscript (mathematics in $...$);
* ``details``: the numbers behind the verdict (``kind``: "formula", "definition",
  "quoted" or "statement"; ``depends_on_closure``: see the caveat below).

Verdict rules (thresholds are module constants; ``rules.verdict_rules`` states them)
-----------------------------------------------------------------------------------
* Formulas (eqs. 1-4, 7-19, 21-53): compared at ``WORK_DPS`` = 40 digits with an
  independent computation (Gauss-Legendre quadrature, mpmath numerical differentiation,
  the defining relations).  ``correct`` if the relative discrepancy is <= ``TOL_FORMULA``
  (1e-28); ``typo`` if it is not but a listed one-symbol correction is; otherwise
  ``incorrect``.  Statements checked in double precision (eqs. 5, 6, shakedown) use
  ``TOL_DOUBLE`` (1e-12).
* Definitions (eqs. 31, 32) cannot be wrong; they are ``correct`` if consistent (to
  ``TOL_FORMULA``) with the equations they serve, else ``incorrect``.
* A formula that is exact but whose direct double-precision evaluation over the
  paper's range (lambda up to lambda_145 = 460) keeps fewer than
  ``HAZARD_DIGITS_KEPT`` (8) significant digits: ``numerically-hazardous``.
* Numbers quoted in the text: ``correct`` if within half a unit of the last printed
  digit of the computed value, else ``incorrect``.
* Statements about the solution (T*(b), tractions, the truncation N = 145) are compared
  with the truth: the Abel-Fredholm solution ``torsional_contact.solve(stick_radius=b)``
  (verified elsewhere to ~1e-13 against a 30-digit reference).  T* is quoted with three
  digits (1.23), so a T* is 'right' if within ``QUOTED_TORQUE_HALF_UNIT`` relative.
  ``N_CONVERGED`` is used only where the statement itself is about changing N.

Reconstruction caveat
---------------------
The paper fixes b, solves (38) and 'evaluates the torque actually present'; that torque
equals any imposed T* (row Sec.3-torque), so the printed equations do not determine
T*(b).  What the checks call the 'published' results (the reconstructed printed scheme) are
the printed equations PLUS this project's closure: T* fixed by continuity of the truncated
traction at r = b (condition (v) of ``solvers.weak_form``), which the paper never states.
Row Sec.3-closure (``closures``) repeats the measurements under the two other closures of
``solvers.weak_form`` and says which findings survive them.  The paper's own reported
results (b/a = 0.6 at T* = 1.23, a torque curve ending at 4/3) agree with the corrected
(complete, Abel-Fredholm) solution, not with this reconstruction, so the original
computation may have closed the system differently.  Rows whose verdict or numbers
depend on the closure set ``details["depends_on_closure"]`` and say so in both notes.

Units: a = 1, T* = 2T/(f F a), tractions in f p0, displacements in f p0 a / mu, unless
a check keeps a explicit (then it says so).
"""

from __future__ import annotations

__all__ = [
    "VERDICTS",
    "KINDS",
    "WORK_DPS",
    "TOL_FORMULA",
    "TOL_DOUBLE",
    "HAZARD_DIGITS_KEPT",
    "N_PAPER",
    "N_CONVERGED",
    "NEGLIGIBLE_CHANGE",
    "QUOTED_TORQUE_HALF_UNIT",
    "CONSISTENCY_FACTOR",
    "RADII",
    "N_DINI",
    "PAPER_EQUATIONS",
    "UNCHECKED",
]

VERDICTS = ("correct", "typo", "numerically-hazardous", "incorrect")
#: What a row checks: a formula, a definition, a number quoted in the text, a statement.
KINDS = ("formula", "definition", "quoted", "statement")

#: Working precision of the formula checks (significant digits).
WORK_DPS = 40
#: A formula is exact if it agrees with the independent computation to this relative accuracy.  The checks work
#: at WORK_DPS = 40 digits and their independent computations (quadrature, numerical differentiation, sums that
#: cancel) lose at most ~12 of them; a wrong formula (a wrong symbol, factor or sign) is off by O(1), a typo-size
#: slip by far more than 1e-6: 1e-28 sits orders of magnitude from both (the correct rows measure 1e-36 or less).
TOL_FORMULA = 1e-28
#: Same for statements evaluated in double precision: their rounding is a condition number below 1e3 times EPS,
#: at most ~2e-13, while a false statement is off by O(1) (or, for the 'torque actually present' of Sec. 3, is
#: exactly true to this rounding); 1e-12.
TOL_DOUBLE = 1e-12
#: Fewer significant digits than this from a direct double evaluation: numerically hazardous.
HAZARD_DIGITS_KEPT = 8
#: Truncation used by the paper (section 4).
N_PAPER = 145
#: Larger truncation, only for statements about what changes when N grows.
N_CONVERGED = 1000
#: Relative change (max-norm) of the series coefficients that still counts as 'negligible'.
NEGLIGIBLE_CHANGE = 1e-2
#: Half a unit of the last digit of the quoted T* = 1.23, relative: the precision the paper claims.
QUOTED_TORQUE_HALF_UNIT = 0.005 / 1.23
#: A formulation is inconsistent if its error stays this many times above the complete one's.
CONSISTENCY_FACTOR = 10
#: Stick radii of the solver-based checks (the six of the reference).
RADII = (0.1, 0.3, 0.5, 0.6, 0.7, 0.9)
#: Largest eigenvalue index in the checks of (34), (35) on [0, 1] (lam_320 ~ 1e3).
N_DINI = 320
#: The paper's numbered equations (1-38 in the text, 39-50 in Appendix A, 51-53 in Appendix B).
PAPER_EQUATIONS = tuple(range(1, 54))
#: Equations without a row, each with the reason (every one of 1-53 is checked today).
UNCHECKED: dict = {}
