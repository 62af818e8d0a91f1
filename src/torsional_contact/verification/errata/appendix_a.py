"""Appendix A: the Bessel identities (39)-(50) at 40 digits by numerical differentiation.

Each ``check_*`` returns a list of errata records (``verdicts.entry``); units as in
``settings``.
"""

from __future__ import annotations

import mpmath

from .rules import formula_rule
from .settings import TOL_FORMULA, WORK_DPS
from .verdicts import entry, verdict_formula

#: The identities of Appendix A as typeset (for the LaTeX notes).
_TYPESET = {
    "A.39": r"J_0'(x) = -J_1(x)",
    "A.40": r"2J_1'(x) = J_0(x) - J_2(x)",
    "A.41": r"J_0''(x) = \tfrac12\,[J_2(x) - J_0(x)]",
    "A.42": r"\tfrac{d}{dr}J_0(\lambda r) = -\lambda J_1(\lambda r)",
    "A.43": r"\tfrac{d^2}{dr^2}J_0(\lambda r) = \tfrac12\lambda^2[J_2(\lambda r) - J_0(\lambda r)]",
    "A.44": r"xJ_0(x) + xJ_2(x) = 2J_1(x)",
    "A.45": r"J_2(x) = 2J_1(x)/x - J_0(x)",
    "A.46": r"J_0''(x) = J_1(x)/x - J_0(x)",
    "A.47": r"J_0''(x) + J_0'(x)/x = -J_0(x)",
    "A.48": r"(\tfrac{d^2}{dr^2} + \tfrac1r\tfrac{d}{dr})J_0(\lambda r) = -\lambda^2 J_0(\lambda r)",
    "A.49": r"(\tfrac{d^2}{dr^2} + \tfrac1r\tfrac{d}{dr} + \lambda^2)J_0(\lambda r) = 0",
    "A.50": r"\tfrac1r\tfrac{d}{dr}J_0(\lambda r) - \tfrac{d^2}{dr^2}J_0(\lambda r) = "
            r"-2\lambda J_1(\lambda r)/r + \lambda^2 J_0(\lambda r)",
}

__all__ = ["check_appendix_a"]


def _appendix_a_identities():
    """(equation, lhs(x, lam, r), rhs(x, lam, r)) of Appendix A, by mpmath differentiation."""
    j = mpmath.besselj

    def d(f, x, n=1):
        return mpmath.diff(f, x, n)

    def j0r(lam):
        return lambda r: j(0, lam * r)

    return [
        ("A.39", lambda x, lam, r: d(lambda t: j(0, t), x), lambda x, lam, r: -j(1, x)),
        ("A.40", lambda x, lam, r: 2 * d(lambda t: j(1, t), x), lambda x, lam, r: j(0, x) - j(2, x)),
        ("A.41", lambda x, lam, r: d(lambda t: j(0, t), x, 2), lambda x, lam, r: (j(2, x) - j(0, x)) / 2),
        ("A.42", lambda x, lam, r: d(j0r(lam), r), lambda x, lam, r: -lam * j(1, lam * r)),
        (
            "A.43",
            lambda x, lam, r: d(j0r(lam), r, 2),
            lambda x, lam, r: lam**2 * (j(2, lam * r) - j(0, lam * r)) / 2,
        ),
        ("A.44", lambda x, lam, r: x * j(0, x) + x * j(2, x), lambda x, lam, r: 2 * j(1, x)),
        ("A.45", lambda x, lam, r: j(2, x), lambda x, lam, r: 2 * j(1, x) / x - j(0, x)),
        ("A.46", lambda x, lam, r: d(lambda t: j(0, t), x, 2), lambda x, lam, r: j(1, x) / x - j(0, x)),
        (
            "A.47",
            lambda x, lam, r: d(lambda t: j(0, t), x, 2) + d(lambda t: j(0, t), x) / x,
            lambda x, lam, r: -j(0, x),
        ),
        (
            "A.48",
            lambda x, lam, r: d(j0r(lam), r, 2) + d(j0r(lam), r) / r,
            lambda x, lam, r: -(lam**2) * j(0, lam * r),
        ),
        (
            "A.49",
            lambda x, lam, r: d(j0r(lam), r, 2) + d(j0r(lam), r) / r + lam**2 * j(0, lam * r),
            lambda x, lam, r: mpmath.mpf(0),
        ),
        (
            "A.50",
            lambda x, lam, r: d(j0r(lam), r) / r - d(j0r(lam), r, 2),
            lambda x, lam, r: -2 * lam * j(1, lam * r) / r + lam**2 * j(0, lam * r),
        ),
    ]


def check_appendix_a():
    """(39)-(50): both sides at 40 digits over a grid of x, lambda, r."""
    xs = ("0.3", "1", "2.5", "7.25", "20.5", "61")
    lams = ("0.7", "5.1356223018406825563", "30.2")
    rs = ("0.05", "0.37", "0.8", "1")
    entries = []
    with mpmath.workdps(WORK_DPS):
        for eq, lhs, rhs in _appendix_a_identities():
            worst = 0.0
            for xt in xs:
                for lt in lams:
                    for rt in rs:
                        x, lam, r = mpmath.mpf(xt), mpmath.mpf(lt), mpmath.mpf(rt)
                        left, right = lhs(x, lam, r), rhs(x, lam, r)
                        # scale: the size of the terms (lam^2 for second r-derivatives)
                        scale = max(abs(left), abs(right), (1 + lam) ** 2 * mpmath.mpf(10) ** -3)
                        worst = max(worst, float(abs(left - right) / scale))
            entries.append(
                entry(
                    eq,
                    f"both sides at {WORK_DPS} digits, derivatives by mpmath.diff, x in {{{', '.join(xs)}}}, "
                    f"lam in {{0.7, 5.1356, 30.2}}, r in {{{', '.join(rs)}}}, relative to the size of the terms"
                    + formula_rule(),
                    worst,
                    verdict_formula(worst),
                    "Identity holds." if worst <= TOL_FORMULA else "Identity fails.",
                    (rf"Exact: ${_TYPESET[eq]}$ holds to {WORK_DPS} digits at every sample point."
                     if worst <= TOL_FORMULA else rf"The identity ${_TYPESET[eq]}$ fails at some sample point."),
                )
            )
    return entries
