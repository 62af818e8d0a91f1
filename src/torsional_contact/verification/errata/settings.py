r"""Settings of the errata checks: verdict words, thresholds, precisions and sample radii.

Each check returns a dict with

* ``equation``: the paper's equation number ("35", "A.40"), or a label for a statement
  in the text ("Sec.4-decay", "completeness", "Fig.5");
* ``check``: how it was checked;
* ``max_rel_discrepancy``: the largest measured relative discrepancy (None when the
  statement is not a number);
* ``verdict``: one of ``correct``, ``typo``, ``numerically-hazardous``, ``incorrect``,
  computed by the rules below from the measured numbers (never typed by hand);
* ``note``: what was found; ``details``: the numbers behind the verdict.

Verdict rules (thresholds are module constants)
-----------------------------------------------
* Formulas (closed forms, Appendix A, eqs. 10-17, 33-38): compared at
  ``WORK_DPS`` = 40 digits with independent Gauss-Legendre quadrature or mpmath
  numerical differentiation.  ``correct`` if the discrepancy is <= ``TOL_FORMULA``
  (1e-28); ``typo`` if it is not but a listed one-symbol correction is; otherwise
  ``incorrect``.  Identities checked in double precision use ``TOL_DOUBLE`` (1e-12).
* A formula that is exact but whose direct double-precision evaluation over the
  paper's range (lambda up to lambda_145 = 460) keeps fewer than
  ``HAZARD_DIGITS_KEPT`` (8) significant digits: ``numerically-hazardous``.
* Numbers quoted in the text: ``correct`` if within half a unit of the last printed
  digit of the computed value (the number the quoted digits denote), else
  ``incorrect``.  Which formulation produced the computed value is stated.
* Convergence statements: ``correct`` if the quantity changes by less than the
  stated threshold when N grows from 145 to ``N_CONVERGED``.

Units: a = 1, T* = 2T/(f F a), tractions in f p0, displacements in f p0 a / mu.
"""

from __future__ import annotations

__all__ = [
    "VERDICTS",
    "WORK_DPS",
    "TOL_FORMULA",
    "TOL_DOUBLE",
    "TOL_DIFF",
    "HAZARD_DIGITS_KEPT",
    "N_PAPER",
    "N_CONVERGED",
    "NEGLIGIBLE_CHANGE",
    "RADII",
    "N_DINI",
]

VERDICTS = ("correct", "typo", "numerically-hazardous", "incorrect")

#: Working precision of the formula checks (significant digits).
WORK_DPS = 40
#: A formula is exact if it agrees with the independent computation to this relative accuracy.
TOL_FORMULA = 1e-28
#: Same for identities evaluated in double precision.
TOL_DOUBLE = 1e-12
#: Fewer significant digits than this from a direct double evaluation: numerically hazardous.
HAZARD_DIGITS_KEPT = 8
#: Truncation used by the paper (section 4).
N_PAPER = 145
#: Larger truncation for the statements about N = 145 (the T* error decreases like 1/N;
#: ``workflow/scripts/errata_report.py`` also reports N = 4000).
N_CONVERGED = 1000
#: Relative change of the series coefficients that still counts as 'negligible'.
NEGLIGIBLE_CHANGE = 1e-2
#: Gauss-Legendre points per period of the fastest oscillation of a quadrature integrand.
GL_POINTS = 20
#: Stick radii of the solver-based checks (the six of the reference).
RADII = (0.1, 0.3, 0.5, 0.6, 0.7, 0.9)
#: Largest eigenvalue index in the checks of (34), (35) on [0, 1] (lam_320 ~ 1e3).
N_DINI = 320
#: Tolerance of checks that use (nested) numerical differentiation, relative to the term size.
TOL_DIFF = 1e-20
