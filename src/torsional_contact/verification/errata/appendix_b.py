"""Appendix B (eqs. 51-53) and the Dini norm and orthogonality (eqs. 34, 35) against quadrature.

Each ``check_*`` returns a list of errata records (``verdicts.entry``); units as in
``settings``.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np

from ...special import integrals
from ...special.zeros import bessel_j2_zeros
from ...typeset import fixed, sci
from .. import weak_form_mp as mp_forms
from ..quadrature_mp import GL_POINTS, Nodes
from .rules import formula_rule, threshold
from .settings import HAZARD_DIGITS_KEPT, N_DINI, N_PAPER, WORK_DPS
from .verdicts import entry, relative_difference, verdict_formula

__all__ = ["check_appendix_b", "check_dini_norm", "check_series_hazard"]


#: (m, n) index pairs per stick radius for (52), (53), (51); large indices give lambda ~ 1e3 - 1e4.
_GRID = {
    "0.1": ((1, 2), (1, 1), (7, 30), (30, 30), (144, 145), (145, 145)),
    "0.5": ((1, 3), (2, 2), (600, 601), (600, 600)),
    "0.9": ((1, 2), (5, 5), (3000, 3001), (3000, 3000)),
}


def _grid_lambdas(digits):
    """{index: lam_index} for the indices of ``_GRID`` (Newton-refined one by one)."""
    indices = sorted({i for pairs in _GRID.values() for p in pairs for i in p})
    return dict(zip(indices, mp_forms.bessel_j2_zeros_at(indices, digits), strict=True))


def check_appendix_b():
    """Eqs. (51), (52), (53) (and the 1F2 vs Struve forms) against GL quadrature."""
    out = {"51": [], "51-struve": [], "52": [], "53": []}
    with mpmath.workdps(WORK_DPS):
        lam = _grid_lambdas(WORK_DPS)
        for b_text, pairs in _GRID.items():
            b = mpmath.mpf(b_text)
            fmax = 2 * max(lam[i] for p in pairs for i in p)
            nodes = Nodes(b, 1, fmax)
            for m, n in pairs:
                quad = nodes.integral_of_j1([lam[m], lam[n]], (0, 1))  # int_b^1 J1 J1 r dr
                factor = lam[n] * (lam[n] - 1)
                if m == n:
                    closed = mp_forms.lommel_diagonal(lam[m], b)
                    out["53"].append((relative_difference(factor * closed, factor * quad), m, n, b_text, float(lam[n])))
                else:
                    closed = mp_forms.lommel_offdiagonal(lam[m], lam[n], b)
                    out["52"].append((relative_difference(factor * closed, factor * quad), m, n, b_text, float(lam[n])))
            for m in sorted({i for p in pairs for i in p}):
                for torque in (mpmath.mpf(0), mpmath.mpf("1.23"), mpmath.mpf(4) / 3):
                    quad = nodes.integral_of_j1([lam[m]], (0, -1, torque))  # int_b^1 (T* r - 1) J1 r dr
                    closed = mp_forms.load_vector(lam[m], b, torque, form="hyp1f2")
                    struve = mp_forms.load_vector(lam[m], b, torque, form="struve")
                    out["51"].append((relative_difference(closed, quad), m, b_text, float(lam[m])))
                    out["51-struve"].append((relative_difference(struve, quad), m, b_text, float(lam[m])))
    entries = []
    lam_top = max(e[-1] for e in out["52"])
    disc = max(e[0] for e in out["51"])
    lam_51 = max(e[-1] for e in out["51"])
    struve = max(e[0] for e in out["51-struve"])
    entries.append(
        entry(
            "51",
            f"B_m as printed (1F2 via mpmath.hyp1f2, {WORK_DPS} digits) vs {GL_POINTS}-point composite "
            f"Gauss-Legendre quadrature of int_b^1 (T* r - 1) J1(lam_m r) r dr, {len(out['51'])} cases, "
            f"b in {{0.1, 0.5, 0.9}}, T* in {{0, 1.23, 4/3}}, lam up to {lam_51:.0f}" + formula_rule(),
            disc,
            verdict_formula(disc),
            "Exact (a = 1 and general a: every term scales with a^2).  The second form "
            f"int_0^x J0 - x J0(x) (Struve functions) agrees to {struve:.1e}.",
            rf"Exact: $B_m$ as printed agrees with {WORK_DPS}-digit quadrature for $\lambda$ up to "
            rf"${sci(lam_51)}$, $0.1 \le b \le 0.9$ and $0 \le T^* \le 4/3$; every term scales with $a^2$.",
            struve_discrepancy=struve,
        )
    )
    disc = max(e[0] for e in out["52"])
    entries.append(
        entry(
            "52",
            f"C_mn (m != n) as printed, incl. the r = a terms, vs GL quadrature of lam_n (lam_n - 1) "
            f"int_b^1 J1 J1 r dr at {WORK_DPS} digits, {len(out['52'])} pairs, lam up to {lam_top:.0f}"
            + formula_rule(),
            disc,
            verdict_formula(disc),
            "Exact.  At zeros of J2 the r = a terms cancel exactly (J0(lam) = 2 J1(lam)/lam).",
            rf"Exact: $C_{{mn}}$ ($m \ne n$) agrees with {WORK_DPS}-digit quadrature for $\lambda$ up to "
            rf"${sci(lam_top)}$; at zeros of $J_2$ its $r = a$ terms cancel, since "
            r"$J_0(\lambda) = 2J_1(\lambda)/\lambda$.",
            cases=[list(e) for e in out["52"]],
        )
    )
    disc = max(e[0] for e in out["53"])
    lam_53 = max(e[-1] for e in out["53"])
    entries.append(
        entry(
            "53",
            f"C_nn as printed vs GL quadrature at {WORK_DPS} digits, {len(out['53'])} cases, "
            f"lam up to {lam_53:.0f}" + formula_rule(),
            disc,
            verdict_formula(disc),
            "Exact.",
            rf"Exact: $C_{{nn}}$ agrees with {WORK_DPS}-digit quadrature for $\lambda$ up to ${sci(lam_53)}$ and "
            r"$0.1 \le b \le 0.9$.",
            cases=[list(e) for e in out["53"]],
        )
    )
    return entries


def check_dini_norm():
    """Eq. (34) orthogonality and eq. (35) h on [0, 1]."""
    with mpmath.workdps(WORK_DPS):
        lam = mp_forms.bessel_j2_zeros(N_DINI, WORK_DPS)
        extra = mpmath.mpf("7.3")  # (35) holds for any lambda, not only zeros of J2
        chosen = [lam[0], lam[1], lam[144], lam[-1], extra]
        nodes = Nodes(0, 1, 2 * lam[-1])
        disc35 = 0.0
        for x in chosen:
            quad = nodes.integral_of_j1([x, x], (0, 1))
            disc35 = max(disc35, relative_difference(mp_forms.dini_norm(x), quad))
        disc34 = 0.0
        for m, n in ((1, 2), (144, 145), (N_DINI - 1, N_DINI), (1, N_DINI)):
            quad = nodes.integral_of_j1([lam[m - 1], lam[n - 1]], (0, 1))
            norm = mpmath.sqrt(mp_forms.dini_norm(lam[m - 1]) * mp_forms.dini_norm(lam[n - 1]))
            disc34 = max(disc34, float(abs(quad) / norm))
    return [
        entry(
            "34",
            f"int_0^1 J1(lam_m r) J1(lam_n r) r dr / sqrt(h_m h_n) for m != n by GL quadrature "
            f"({WORK_DPS} digits), pairs (1,2), (144,145), ({N_DINI - 1},{N_DINI}), (1,{N_DINI})" + formula_rule(),
            disc34,
            verdict_formula(disc34),
            "Orthogonality holds (Dini series with H + nu = 0).",
            rf"Orthogonality holds: the normalised overlap of distinct eigenfunctions is below "
            rf"${sci(max(disc34, 1e-40))}$ up to $\lambda_{{2,{N_DINI}}} \approx {float(lam[-1]):.0f}$ "
            r"(a Dini series with $H + \nu = 0$).",
        ),
        entry(
            "35",
            f"h as printed vs GL quadrature of int_0^1 J1(lam r)^2 r dr at lam_1, lam_2, lam_145, "
            f"lam_{N_DINI} = {float(lam[-1]):.0f} and lam = 7.3 (not a zero)" + formula_rule(),
            disc35,
            verdict_formula(disc35),
            "Exact for any lambda (with a^2 for general a).  At zeros of J2 it reduces to J1(lam)^2/2.",
            r"Exact for any $\lambda$, not only at the zeros of $J_2$ (with the factor $a^2$ for general $a$); at "
            r"the zeros it reduces to $a^2J_1(\lambda)^2/2$.",
        ),
    ]


def _hyp1f2_series_double(x: float, max_terms: int = 400) -> float:
    """x^3/6 1F2(3/2; 2, 5/2; -x^2/4) summed term by term in double precision (the naive way)."""
    z = -x * x / 4.0
    term, total = 1.0, 1.0
    for k in range(max_terms):
        term *= (1.5 + k) / ((2.0 + k) * (2.5 + k) * (k + 1.0)) * z
        total += term
        if abs(term) < 1e-17 * abs(total) and k > 2:
            break
    return x**3 / 6.0 * total


def check_series_hazard():
    lam = bessel_j2_zeros(N_PAPER)
    kept = []
    with mpmath.workdps(30):
        for x in lam:
            exact = mp_forms.integral_t_j1_struve(mpmath.mpf(float(x)))
            naive = _hyp1f2_series_double(float(x))
            err = abs(naive - float(exact)) / abs(float(exact)) if math.isfinite(naive) else math.inf
            kept.append(-math.log10(max(err, 1e-17)))
    kept = np.array(kept)
    first_bad = int(np.argmax(kept < HAZARD_DIGITS_KEPT)) if np.any(kept < HAZARD_DIGITS_KEPT) else None
    first_zero = int(np.argmax(kept <= 0)) if np.any(kept <= 0) else None
    stable = integrals.integral_t_j1(lam)
    with mpmath.workdps(30):
        stable_err = max(
            abs(float(s) - float(mp_forms.integral_t_j1_struve(mpmath.mpf(float(x))))) / abs(float(s))
            for s, x in zip(stable, lam, strict=True)
        )
    hazardous = min(kept) < HAZARD_DIGITS_KEPT
    verdict = "numerically-hazardous" if hazardous else "correct"
    worst = 10.0 ** (-min(kept))
    if first_bad is not None and first_zero is not None:
        note = (
            "The 1F2 of eq. (51) summed as a power series in double precision keeps "
            f"{kept[0]:.1f} digits at lam_1; fewer than {HAZARD_DIGITS_KEPT} from lam_{first_bad + 1} = "
            f"{lam[first_bad]:.1f} and none from lam_{first_zero + 1} = {lam[first_zero]:.1f} on "
            "(terms grow like exp(lam)/lam while the sum is O(lam^1.5)).  Exact in exact arithmetic "
            "(MATLAB's symbolic hypergeom would be safe).  The library's double-precision form "
            f"(integrals.integral_t_j1): max rel error {stable_err:.1e} over lam_1..lam_145."
        )
        note_latex = (
            rf"Summed term by term in double precision, the ${{}}_1F_2$ of (51) keeps fewer than "
            rf"{HAZARD_DIGITS_KEPT} digits from $\lambda_{{2,{first_bad + 1}}} = {fixed(lam[first_bad], 1)}$ and "
            rf"none from $\lambda_{{2,{first_zero + 1}}} = {fixed(lam[first_zero], 1)}$ on: its terms grow like "
            r"$e^{\lambda}/\lambda$ while the sum is of order $\lambda^{3/2}$, so the series loses all digits. "
            rf"A stable form of the same integral is accurate to ${sci(stable_err)}$ up to "
            rf"$\lambda_{{2,{N_PAPER}}}$."
        )
    else:
        note = f"Power series keeps at least {min(kept):.1f} digits over lam_1..lam_145."
        note_latex = (rf"Summed term by term in double precision, the ${{}}_1F_2$ of (51) keeps at least "
                      rf"{fixed(min(kept), 1)} digits up to $\lambda_{{2,{N_PAPER}}}$.")
    return [
        entry(
            "51-series",
            "x^3/6 1F2(3/2; 2, 5/2; -x^2/4) summed term by term in double precision at x = lam_1..lam_145 "
            f"vs mpmath (Struve form, 30 digits); hazardous if fewer than {threshold('HAZARD_DIGITS_KEPT')} digits "
            "kept",
            worst,
            verdict,
            note,
            note_latex,
            digits_kept=[round(float(k), 2) for k in kept],
            stable_form_max_rel_error=stable_err,
            summary_latex=(rf"Summed term by term in double precision, the ${{}}_1F_2$ of (51) keeps fewer than "
                           rf"{HAZARD_DIGITS_KEPT} digits from $\lambda_{{2,{first_bad + 1}}}$ on."
                           if first_bad is not None else note_latex),
        )
    ]
