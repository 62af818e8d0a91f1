"""Section 3: the eigenfunction series (21) and its fields (22)-(26), with a and mu explicit.

A five-term potential psi of (21) with random amplitudes A_n and lambda_n = lambda_(2,n)/a
is differentiated numerically (eq. 10, ``differential``) at ``WORK_DPS`` digits and
compared with the printed series, at random radii a and points (r, z).  ``PRINTED`` holds
the printed formulas; a test can replace one with a corrupted version.
"""

from __future__ import annotations

import mpmath
import numpy as np

from .differential import laplacian_cartesian, solution_e
from .rules import formula_rule
from .settings import WORK_DPS
from .verdicts import entry, verdict_formula

__all__ = ["check_series_terms", "measure_series", "PRINTED", "series_case"]

_J = mpmath.besselj
_TERMS = 5


def _sum(amps, lams, power, order, r, z):
    """sum_n A_n lam_n^power exp(-lam_n z) J_order(lam_n r)."""
    return mpmath.fsum(A * lam**power * mpmath.exp(-lam * z) * _J(order, lam * r) for A, lam in zip(amps, lams,
                                                                                                    strict=True))


#: The printed series as functions of (amps, lams, mu, r, z); lams are lambda_(2,n)/a.
PRINTED = {
    "21": lambda amps, lams, mu, r, z: _sum(amps, lams, 0, 0, r, z),  # psi
    "22": lambda amps, lams, mu, r, z: _sum(amps, lams, 1, 1, r, z) / mu,  # u_theta
    "23": lambda amps, lams, mu, r, z: -_sum(amps, lams, 2, 2, r, z),  # sigma_rt
    "24": lambda amps, lams, mu, r, z: -_sum(amps, lams, 2, 1, r, z),  # sigma_zt
    "25": lambda amps, lams, mu, r, z: _sum(amps, lams, 1, 1, r, 0) / mu,  # u_theta(r, 0)
    "26": lambda amps, lams, mu, r, z: -_sum(amps, lams, 2, 1, r, 0),  # sigma_zt(r, 0)
}


def series_case(seed: int):
    """(a, mu, amplitudes, lambda_n = lambda_(2,n)/a) at the working precision, drawn at random (seeded)."""
    rng = np.random.default_rng(seed)
    a = mpmath.mpf(f"{rng.uniform(0.2, 3.0):.10g}")
    mu = mpmath.mpf(f"{10 ** rng.uniform(-1, 2):.10g}")
    amps = [mpmath.mpf(f"{x:.10g}") for x in rng.uniform(-1, 1, _TERMS)]
    lams = [mpmath.besseljzero(2, n) / a for n in range(1, _TERMS + 1)]
    return a, mu, amps, lams


def measure_series(printed=None, zeros=None) -> dict:
    """Relative discrepancies {"21": .., ..., "26": ..} of the printed series against (10) applied to (21).

    (21): the Cartesian Laplacian of psi and sigma_rt(a, z) of (10) (condition 9) vanish;
    (22)-(24): the printed fields vs (10) at interior points; (25), (26): at z = 0.  Relative to
    the term sizes sum |A_n| lam_n^p exp(-lam_n z) (p = 2 for stresses and the Laplacian,
    p = 1 over mu for the displacement).  ``printed`` overrides entries of ``PRINTED``;
    ``zeros(n, a)`` overrides lambda_n (default lambda_(2,n)/a).
    """
    printed = {**PRINTED, **(printed or {})}
    out = dict.fromkeys(PRINTED, 0.0)
    with mpmath.workdps(WORK_DPS):
        for seed in (21, 22):
            a, mu, amps, lams = series_case(seed)
            if zeros is not None:
                lams = [zeros(n, a) for n in range(1, _TERMS + 1)]

            def psi(r, z, amps=amps, lams=lams, mu=mu):
                return printed["21"](amps, lams, mu, r, z)

            for rt, zt in (("0.13", "0.02"), ("0.5", "0.1"), ("0.87", "0.05"), ("1", "0.2")):
                r, z = mpmath.mpf(rt) * a, mpmath.mpf(zt) * a
                stress_size = mpmath.fsum(abs(A) * lam**2 * mpmath.exp(-lam * z) for A, lam in zip(amps, lams,
                                                                                                     strict=True))
                u, srt, szt = solution_e(psi, mu, r, z)
                side = solution_e(psi, mu, a, z)[1]
                out["21"] = max(out["21"], float(abs(laplacian_cartesian(psi, r, z)) / stress_size),
                                float(abs(side) / stress_size))
                disp_size = mpmath.fsum(abs(A) * lam * mpmath.exp(-lam * z) for A, lam in zip(amps, lams,
                                                                                                strict=True)) / mu
                for key, got, size in (("22", u, disp_size), ("23", srt, stress_size), ("24", szt, stress_size)):
                    out[key] = max(out[key], float(abs(got - printed[key](amps, lams, mu, r, z)) / size))
                u0, _, szt0 = solution_e(psi, mu, r, mpmath.mpf(0))
                disp0 = mpmath.fsum(abs(A) * lam for A, lam in zip(amps, lams, strict=True)) / mu
                stress0 = mpmath.fsum(abs(A) * lam**2 for A, lam in zip(amps, lams, strict=True))
                out["25"] = max(out["25"], float(abs(u0 - printed["25"](amps, lams, mu, r, z)) / disp0))
                out["26"] = max(out["26"], float(abs(szt0 - printed["26"](amps, lams, mu, r, z)) / stress0))
    return out


_NOTES = {
    "21": ("Each term is (14) with lam_n = lam_(2,n)/a: the series is harmonic and satisfies (9) term by term.  "
           "(The series is not complete: it lacks the rigid rotation; see the statement row 'completeness'.)",
           r"Each term is (14) with $\lambda_n = \lambda_{2,n}/a$: the series is harmonic and satisfies the side "
           r"condition (9) term by term. That it is not complete (it lacks the rigid rotation) is judged in the "
           r"Sec.~3 row on completeness."),
    "22": ("Exact: (10) applied to (21) term by term (1/mu and the a-scaling included).",
           r"Exact: it is (10) applied to (21) term by term, including the factor $1/\mu$ and the scaling with $a$."),
    "23": ("Exact: (16) summed over lam_n.", r"Exact: it is (16) summed over $\lambda_n = \lambda_{2,n}/a$."),
    "24": ("Exact: (17) summed over lam_n.", r"Exact: it is (17) summed over $\lambda_n = \lambda_{2,n}/a$."),
    "25": ("Exact: (22) at z = 0.", r"Exact: it is (22) on the interface $z = 0$."),
    "26": ("Exact: (24) at z = 0.", r"Exact: it is (24) on the interface $z = 0$."),
}


def check_series_terms():
    """(21)-(26)."""
    out = measure_series()
    how = (f"five-term psi of (21), random amplitudes, lambda_n = lambda_(2,n)/a, 2 random (a, mu), 4 points "
           f"(r, z), (10) by mpmath.diff at {WORK_DPS} digits")
    checks = {
        "21": f"{how}: Cartesian Laplacian of psi and sigma_rt(a, z) (condition 9), relative to "
              "sum |A_n| lam_n^2 exp(-lam_n z)",
        "22": f"{how} vs the printed u_theta, relative to sum |A_n| lam_n exp(-lam_n z) / mu",
        "23": f"{how} vs the printed sigma_rt, relative to sum |A_n| lam_n^2 exp(-lam_n z)",
        "24": f"{how} vs the printed sigma_zt, relative to sum |A_n| lam_n^2 exp(-lam_n z)",
        "25": f"{how} at z = 0 vs the printed u_theta(r, 0), relative to sum |A_n| lam_n / mu",
        "26": f"{how} at z = 0 vs the printed sigma_zt(r, 0), relative to sum |A_n| lam_n^2",
    }
    return [entry(key, checks[key] + formula_rule(), out[key], verdict_formula(out[key]), *_NOTES[key])
            for key in PRINTED]
