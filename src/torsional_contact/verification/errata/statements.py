"""Statements of sections 3-4: completeness of (21), 'the torque actually present', N = 145, the limits.

Each ``check_*`` returns a list of errata records (``verdicts.entry``); units as in
``settings``.
"""

from __future__ import annotations

import mpmath
import numpy as np
from scipy import linalg, special

from ...criteria import GROSS_SLIP_TORQUE
from ...solvers.weak_form import assemble as assemble_double
from ...special.zeros import bessel_j2_zeros
from .series import quiet_solve, series_displacement, series_traction
from .settings import N_CONVERGED, N_PAPER, NEGLIGIBLE_CHANGE, RADII, TOL_DOUBLE
from .verdicts import entry, relative_difference

__all__ = ["check_completeness", "check_torque_evaluation", "check_truncation", "check_limits"]

def check_completeness():
    """The published series lacks the rigid rotation r: its consequences, measured."""
    b = 0.6
    pub = quiet_solve(b, "published", N_PAPER)
    nodes, weights = np.polynomial.legendre.leggauss(800)
    rr, ww = 0.5 * (nodes + 1), 0.5 * weights
    moment = float(np.sum(ww * rr**2 * series_displacement(pub, rr)))
    # u = alpha r on the stick disc
    r_stick = np.linspace(0.1, 0.5, 9) * b / 0.6
    alpha_samples = series_displacement(pub, r_stick) / r_stick
    alpha = float(np.median(alpha_samples))
    alpha_spread = float(np.ptp(alpha_samples) / abs(alpha))
    # traction 1 - alpha r on the slip annulus (away from r = b)
    r_slip = np.linspace(0.7, 0.95, 11)
    traction = series_traction(pub, r_slip)
    trac_disc = float(np.max(np.abs(traction - (1 - alpha * r_slip))))
    # slip just outside b
    r_edge = np.linspace(b + 0.005, b + 0.05, 10)
    min_slip = float(np.min(2 * series_displacement(pub, r_edge)))
    small_b = {bb: quiet_solve(bb, "published", N_PAPER).torque for bb in (0.01, 0.1, 0.3)}
    differences = {}
    for n in (N_PAPER, N_CONVERGED):
        differences[n] = max(
            abs(quiet_solve(bb, "published", n).torque - quiet_solve(bb, "complete", n).torque)
            / quiet_solve(bb, "complete", n).torque
            for bb in RADII
        )
    complete_change = max(
        abs(quiet_solve(bb, "complete", N_PAPER).torque - quiet_solve(bb, "complete", N_CONVERGED).torque)
        / quiet_solve(bb, "complete", N_CONVERGED).torque
        for bb in RADII
    )
    above_spinning = max(small_b.values()) > GROSS_SLIP_TORQUE
    not_converging = differences[N_CONVERGED] > 10 * complete_change
    verdict = "incorrect" if above_spinning or not_converging else "correct"
    return [
        entry(
            "completeness",
            f"published eq. (38) (N = {N_PAPER}, b = 0.6): int_0^1 u r^2 dr, u/r on the stick disc, traction on "
            f"the slip annulus, slip near r = b; published T*(b) for small b; max_b |T*_pub - T*_complete| / "
            f"T*_complete over b in {RADII} at N = {N_PAPER} and {N_CONVERGED}; incorrect if T*_pub > 4/3 "
            f"anywhere or the difference at N = {N_CONVERGED} exceeds 10 x the complete solution's own change "
            f"from N = {N_PAPER}",
            differences[N_CONVERGED],
            verdict,
            "The eigenfunctions J1(lam_n r) of (21) are all orthogonal to r with weight r "
            "(int_0^1 r^2 J1(lam_n r) dr = J2(lam_n)/lam_n = 0), so they are not complete on (0, 1): "
            f"the published series forces int_0^1 u r^2 dr = 0 (measured {moment:.1e}).  The weak form then "
            f"leaves a residual along r: on the stick disc u = alpha r with alpha = {alpha:.4f} (a backward "
            f"rigid slip; u/r constant to {alpha_spread:.0e}), the slip-annulus traction is 1 - alpha r "
            f"(max deviation {trac_disc:.1e} for 0.7 <= r <= 0.95), i.e. above the friction limit, and the "
            f"slip just outside r = b is negative (min {min_slip:.4f}), against the friction law.  Published "
            f"T*(b) = {small_b[0.3]:.3f}, {small_b[0.1]:.3f}, {small_b[0.01]:.3f} at b = 0.3, 0.1, 0.01: above "
            f"the spinning torque 4/3.  Published vs complete T*: max rel difference {differences[N_PAPER]:.3f} "
            f"at N = {N_PAPER}, {differences[N_CONVERGED]:.3f} at N = {N_CONVERGED} (does not converge away; "
            f"the complete T* itself changes by {complete_change:.1e}).  Fix: add the rigid rotation omega r "
            "(the lambda = 0 Dini mode) to (21) and r to the test functions (formulations, method 'complete').",
            stick_moment=moment,
            alpha=alpha,
            traction_deviation=trac_disc,
            min_slip_near_b=min_slip,
            published_small_b={str(k): v for k, v in small_b.items()},
            published_vs_complete={str(k): v for k, v in differences.items()},
        )
    ]


def check_torque_evaluation():
    """'evaluate the imposed torque actually present': 4 int sigma r^2 dr equals T* for any T*."""
    b = 0.6
    lam = bessel_j2_zeros(N_PAPER)
    matrix, rhs_t, rhs_c = assemble_double("complete", lam, b)
    x = linalg.solve(matrix, np.column_stack([rhs_t, rhs_c]))
    nodes, weights = np.polynomial.legendre.leggauss(1200)
    rr, ww = 0.5 * (nodes + 1), 0.5 * weights
    worst = 0.0
    present = {}
    for t in (1.0, 1.1, 1.2340, 1.3):
        c = (x[:, 1] + t * x[:, 0])[: lam.size]
        traction = t * rr - special.j1(np.outer(rr, lam)) @ (c * lam)
        got = 4.0 * float(np.sum(ww * traction * rr**2))
        present[t] = got
        worst = max(worst, abs(got - t) / t)
    vacuous = worst <= TOL_DOUBLE
    return [
        entry(
            "Sec.3-torque",
            "'solve for the corrective stress distribution and finally evaluate the imposed torque actually "
            "present': torque 4 int_0^1 sigma_zt r^2 dr (800-point Gauss-Legendre) of the solution of (iii) for "
            "b = 0.6 and four imposed T*; the step can fix T*(b) only if this differs from the imposed T*",
            worst,
            "incorrect" if vacuous else "correct",
            "The torque present equals the imposed T* to rounding for every imposed T* (each eigenfunction "
            "carries zero torque: 4 int_0^1 r^2 lam J1(lam r) dr = 4 J2(lam) = 0), so the described procedure "
            "does not determine T*(b).  An extra condition is needed: the regularity of the stick-side "
            "traction at r = b (formulations, condition (v)).",
            torque_present={str(k): v for k, v in present.items()},
        )
    ]


def check_truncation():
    """'when N is set to 145 the change in the calculated coefficients is negligible for all b/a'."""
    torque_change, coeff_change = {}, {}
    for b in RADII:
        a = quiet_solve(b, "complete", N_PAPER)
        c = quiet_solve(b, "complete", N_CONVERGED)
        torque_change[b] = abs(a.torque - c.torque) / c.torque
        ref = c.amplitudes[:N_PAPER]
        coeff_change[b] = float(np.max(np.abs(a.amplitudes - ref)) / np.max(np.abs(ref)))
    t_max, c_max = max(torque_change.values()), max(coeff_change.values())
    quoted_precision = 0.005 / 1.23  # T* is quoted with 3 significant digits (1.23)
    if t_max > quoted_precision:
        verdict = "incorrect"
    elif c_max > NEGLIGIBLE_CHANGE:
        verdict = "numerically-hazardous"
    else:
        verdict = "correct"
    return [
        entry(
            "Sec.4-N145",
            f"complete formulation, b in {RADII}: relative change of T* and of the coefficients c_1..c_145 "
            f"(max-norm) from N = {N_PAPER} to N = {N_CONVERGED}; incorrect if T* changes by more than the "
            f"quoted precision ({quoted_precision:.1e}), numerically-hazardous if the coefficients change by "
            f"more than {NEGLIGIBLE_CHANGE:g}",
            c_max,
            verdict,
            f"T* changes by up to {t_max:.1e} (largest at b = {max(torque_change, key=torque_change.get)}) and "
            f"the coefficients by up to {c_max:.2f} (b = {max(coeff_change, key=coeff_change.get)}): the series "
            "converges slowly (T* error about 1/N) because the exact traction has a square-root corner at r = b; "
            "N = 145 fixes T* to about 3 digits, not the coefficients.",
            torque_change={str(k): v for k, v in torque_change.items()},
            coefficient_change={str(k): v for k, v in coeff_change.items()},
        )
    ]


def check_limits():
    """Slip onset T* = 1 and spinning T* = 4/3 (section 4)."""
    with mpmath.workdps(30):
        spinning = mpmath.quad(lambda r: 4 * r * r, [0, 1])  # torque balance, traction 1
        disc_spin = relative_difference(spinning, mpmath.mpf(4) / 3)
    near_onset = quiet_solve(0.98, "complete", N_CONVERGED)
    near_spin = quiet_solve(0.05, "complete", N_CONVERGED)
    pub_spin = quiet_solve(0.05, "published", N_CONVERGED)
    ok = disc_spin <= 1e-25 and 1.0 < near_onset.torque < 1.0 + 0.05 and 4 / 3 - 1e-3 < near_spin.torque < 4 / 3
    return [
        entry(
            "Sec.4-limits",
            f"T* = 4/3 from torque balance with traction 1 (mpmath.quad); complete T*(b) at b = 0.98 and 0.05 "
            f"(N = {N_CONVERGED}) must lie in (1, 1.05) and (4/3 - 1e-3, 4/3)",
            disc_spin,
            "correct" if ok else "incorrect",
            f"Slip onset T* = 1 (eq. 5) and spinning T* = 4/3 hold.  Complete: T*(0.98) = {near_onset.torque:.5f}, "
            f"T*(0.05) = {near_spin.torque:.6f}; the published formulation gives T*(0.05) = "
            f"{pub_spin.torque:.3f} > 4/3.",
        )
    ]
