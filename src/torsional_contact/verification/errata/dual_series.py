"""Section 3: the dual series equations (27)-(28) and their normalised form (29)-(32).

With random dimensional (T, f, F, a, mu, b) and five random amplitudes A_n, the residuals of
the printed equations are compared at ``WORK_DPS`` digits with those of the boundary
conditions (7), (8) built from (2), (4), (25) and (26):

    LHS(27)             = mu u(r, 0)                          0 < r < b
    LHS(28) - RHS(28)   = -a [sigma_zt(r, 0) - f F/(pi a^2)]  b < r < a
    LHS(29)             = (pi a / (f F)) LHS(27)              (= mu u / (f p0 a))
    LHS(30) - RHS(30)   = (pi a / (f F)) [LHS(28) - RHS(28)]  (= -[sigma / (f p0) - 1])

so each printed equation holds exactly where its condition does.  (31) and (32) are
definitions, checked for consistency.  ``PRINTED`` holds the printed sides; a test can
replace one with a corrupted version.
"""

from __future__ import annotations

import mpmath

from .bilateral import bilateral_displacement, bilateral_shear
from .conditions import random_cases
from .rules import formula_rule
from .settings import WORK_DPS
from .verdicts import entry, verdict_formula

__all__ = ["check_dual_series", "measure_dual", "PRINTED"]

_J = mpmath.besselj
_TERMS = 5


def _bessel_sum(coefficients, zeros, a, r, power):
    """sum_n coefficient_n zero_n^power J1(zero_n r / a)."""
    return mpmath.fsum(c * x**power * _J(1, x * r / a) for c, x in zip(coefficients, zeros, strict=True))


#: Printed sides.  Arguments: amplitudes A_n (or A~_n), zeros lambda_(2,n), r, and the case.
PRINTED = {
    "27": lambda amps, zeros, r, c: _bessel_sum(amps, zeros, c["a"], r, 1) / c["a"],
    "28-lhs": lambda amps, zeros, r, c: _bessel_sum(amps, zeros, c["a"], r, 2) / c["a"],
    "28-rhs": lambda r, c: 2 * c["T"] * r / (mpmath.pi * c["a"] ** 3) - c["f"] * c["F"] / (mpmath.pi * c["a"]),
    "29": lambda tilde, zeros, r, c: _bessel_sum(tilde, zeros, c["a"], r, 1),
    "30-lhs": lambda tilde, zeros, r, c: _bessel_sum(tilde, zeros, c["a"], r, 2),
    "30-rhs": lambda r, tstar, c: r / c["a"] * tstar - 1,
    "31": lambda amps, c: [A * mpmath.pi / (c["f"] * c["F"]) for A in amps],
    "32": lambda c: 2 * c["T"] / (c["f"] * c["F"] * c["a"]),
}


def measure_dual(printed=None) -> dict:
    """Relative discrepancies {"27": .., ..., "32": ..} (see the module docstring).

    The interface fields come from (4) (u^B), (25) (u^C), (2) (sigma^B), (26) (sigma^C):
    the latter two typed here independently of ``PRINTED``.  (31): A~_n lambda_n and
    A~_n lambda_n^2 are the amplitudes of u^C in f p0 a / mu and of -sigma^C in f p0.
    (32): T* r/a = sigma^B / (f p0), T* = 1 at T = f F a / 2 (eq. 5) and T* = 4/3 at the
    spinning torque 2 pi int_0^a f p0 r^2 dr (mpmath.quad).
    """
    printed = {**PRINTED, **(printed or {})}
    out = dict.fromkeys(("27", "28", "29", "30", "31", "32"), 0.0)
    with mpmath.workdps(WORK_DPS):
        zeros = [mpmath.besseljzero(2, n) for n in range(1, _TERMS + 1)]
        for k, (torque, f, force, a, mu, beta) in enumerate(random_cases(27)):
            case = {"T": torque, "f": f, "F": force, "a": a, "mu": mu}
            amps = [mpmath.mpf(x) / (k + 1) * f * force for x in ("0.31", "-0.12", "0.057", "-0.021", "0.008")]
            p0 = force / (mpmath.pi * a**2)
            tilde = printed["31"](amps, case)
            tstar = printed["32"](case)
            lams = [x / a for x in zeros]
            u_size = mpmath.fsum(abs(A) * lam for A, lam in zip(amps, lams, strict=True)) / mu
            s_size = mpmath.fsum(abs(A) * lam**2 for A, lam in zip(amps, lams, strict=True))
            for rho in (beta / 4, beta / 2, beta * 3 / 4, beta + (1 - beta) / 3, beta + (1 - beta) * 2 / 3, 1):
                r = rho * a
                u = bilateral_displacement(r, 0, torque, mu, a) + mpmath.fsum(  # (4) + (25)
                    A * lam * _J(1, lam * r) for A, lam in zip(amps, lams, strict=True)) / mu
                sigma_c = -mpmath.fsum(A * lam**2 * _J(1, lam * r) for A, lam in zip(amps, lams, strict=True))  # (26)
                sigma = bilateral_shear(r, torque, a) + sigma_c  # (2) + (26)
                slip_residual = sigma - f * force / (mpmath.pi * a**2)  # (8)
                res27 = printed["27"](amps, zeros, r, case)
                res28 = printed["28-lhs"](amps, zeros, r, case) - printed["28-rhs"](r, case)
                res29 = printed["29"](tilde, zeros, r, case)
                res30 = printed["30-lhs"](tilde, zeros, r, case) - printed["30-rhs"](r, tstar, case)
                scale28 = a * (bilateral_shear(r, torque, a) + s_size + f * p0)
                scale = mpmath.pi * a / (f * force)
                out["27"] = max(out["27"], float(abs(res27 - mu * u) / (mu * u_size)))
                out["28"] = max(out["28"], float(abs(res28 + a * slip_residual) / scale28))
                out["29"] = max(out["29"], float(abs(res29 - scale * res27) / (scale * mu * u_size)))
                out["30"] = max(out["30"], float(abs(res30 - scale * res28) / (scale * scale28)))
                # (31): A~ lam (in f p0 a / mu) and A~ lam^2 (in f p0) are the interface amplitudes of (25), (26)
                u_c = u - bilateral_displacement(r, 0, torque, mu, a)
                out["31"] = max(out["31"],
                                float(abs(_bessel_sum(tilde, zeros, a, r, 1) - u_c * mu / (f * p0 * a))
                                      * f * p0 * a / (mu * u_size)),
                                float(abs(_bessel_sum(tilde, zeros, a, r, 2) + sigma_c / (f * p0)) * f * p0 / s_size))
                out["32"] = max(out["32"], float(abs(tstar * rho - bilateral_shear(r, torque, a) / (f * p0))
                                                 / (tstar * rho)))
            onset = printed["32"]({**case, "T": f * force * a / 2})  # eq. (5): |T| = f F a / 2
            spinning = mpmath.quad(lambda s, f=f, p0=p0: 2 * mpmath.pi * f * p0 * s * s, [0, a])
            out["32"] = max(out["32"], float(abs(onset - 1)),
                            float(abs(printed["32"]({**case, "T": spinning}) - mpmath.mpf(4) / 3) * 3 / 4))
    return out


def check_dual_series():
    """(27)-(32)."""
    out = measure_dual()
    how = (f"3 random dimensional (T, f, F, a, mu, b/a), five random A_n, 6 radii on both sides of b, "
           f"{WORK_DPS} digits")
    rows = {
        "27": (f"LHS of (27) vs mu (u^B + u^C)(r, 0) from (4) and (25); {how}",
               "(27) is mu times (7) with (4) and (25) inserted (u^B(r, 0) = 0): exact.",
               r"Exact: (27) is $\mu$ times condition (7) once (4) and (25) are inserted, because "
               r"$u^B_\theta(r, 0) = 0$."),
        "28": (f"LHS - RHS of (28) vs -a times the residual of (8) with (2) and (26); {how}",
               "(28) is (8) multiplied by -a (with (2) and (26)): exact, and it holds where (8) does.",
               r"Exact: $\mathrm{LHS} - \mathrm{RHS}$ of (28) is $-a$ times the residual of (8) with (2) and (26) "
               r"inserted, so (28) holds exactly where (8) does."),
        "29": (f"LHS of (29) with (31) vs (pi a/(f F)) LHS(27) = mu u / (f p0 a); {how}",
               "(29) is (27) times pi a / (f F): the interface displacement in units f p0 a / mu. Exact.",
               r"Exact: (29) is (27) multiplied by $\pi a/(fF)$, i.e.\ the interface displacement in units of "
               r"$fp_0a/\mu$."),
        "30": (f"LHS - RHS of (30) with (31), (32) vs (pi a/(f F)) (LHS - RHS)(28); {how}",
               "(30) is (28) times pi a / (f F): the slip condition in units of f p0. Exact.",
               r"Exact: (30) is (28) multiplied by $\pi a/(fF)$, i.e.\ the slip condition (8) in units of $fp_0$."),
        "31": (f"A~_n lam_(2,n) and A~_n lam_(2,n)^2 vs the amplitudes of u^C(r, 0) / (f p0 a / mu) and "
               f"-sigma^C(r, 0) / (f p0) of (25), (26); {how}",
               "Definition (consistent with (25), (26), (29) and (30)): A~_n lam_n is the interface displacement "
               "amplitude in f p0 a / mu and A~_n lam_n^2 the traction amplitude in f p0.",
               r"Definition, consistent with (25), (26), (29) and (30): $\tilde A_n\lambda_{2,n}$ is the amplitude "
               r"of the interface displacement in units of $fp_0a/\mu$, $\tilde A_n\lambda_{2,n}^2$ that of the "
               r"traction in units of $fp_0$."),
        "32": (f"T* r/a vs sigma^B(r, 0) / (f p0) of (2); T* at T = f F a / 2 (eq. 5) vs 1; T* at the spinning "
               f"torque 2 pi int_0^a f p0 r^2 dr (mpmath.quad) vs 4/3; {how}",
               "Definition (consistent with (2), (5), (30) and section 4): T* r/a is the bilateral traction in f p0, "
               "slip starts at T* = 1 and spinning is T* = 4/3.",
               r"Definition, consistent with (2), (5), (30) and Section 4: $T^* r/a$ is the bilateral traction in "
               r"units of $fp_0$, slip starts at $T^* = 1$ and spinning occurs at $T^* = 4/3$."),
    }
    return [
        entry(key, check + formula_rule(), out[key], verdict_formula(out[key]), note, note_latex,
              kind="definition" if key in ("31", "32") else "formula")
        for key, (check, note, note_latex) in rows.items()
    ]
