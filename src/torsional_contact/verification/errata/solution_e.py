"""Section 3: Solution E (10), the separated potential (11)-(14), its terms (15)-(17), the side (18)-(19).

Every formula is compared at ``WORK_DPS`` digits with (10) applied to the potential by
numerical differentiation (``differential``), Laplacians in Cartesian coordinates.  The
``measure_*`` functions take the printed formula as an argument so that a test can feed a
corrupted one; the ``check_*`` functions return errata records (``verdicts.entry``).
"""

from __future__ import annotations

import mpmath

from .differential import laplacian_cartesian, solution_e
from .rules import formula_rule
from .settings import WORK_DPS
from .verdicts import entry, verdict_formula

__all__ = ["check_potential", "check_separation", "check_side_condition", "measure_terms",
           "measure_separation", "measure_bounded", "measure_harmonic", "measure_side", "measure_eigen_condition",
           "PRINTED_TERMS"]

_J = mpmath.besselj
#: Potential amplitude A, modulus mu and the points (r, z) of the checks of (10), (14)-(18).
_AMPLITUDE, _MU = "0.7", "1.9"
_LAMBDAS = ("5.1356223018406825563", "11.7", "40.1")
_POINTS = (("0.2", "0"), ("0.55", "0.1"), ("0.9", "0.03"), ("1", "0.2"))
#: Stick-free radii a of the side-condition checks (dimensional; any a > 0).
_RADII = ("0.37", "2.9")


def _potential(amp, lam):
    """psi of eq. (14)."""
    return lambda r, z: amp * mpmath.exp(-lam * z) * _J(0, lam * r)


#: Eqs. (15)-(17) as printed: (2 mu u, sigma_rt, sigma_zt) of psi = A exp(-lam z) J0(lam r).
PRINTED_TERMS = {
    "15": lambda amp, lam, r, z: 2 * amp * lam * mpmath.exp(-lam * z) * _J(1, lam * r),
    "16": lambda amp, lam, r, z: -amp * lam**2 * mpmath.exp(-lam * z) * _J(2, lam * r),
    "17": lambda amp, lam, r, z: -amp * lam**2 * mpmath.exp(-lam * z) * _J(1, lam * r),
}


def measure_terms(printed=None) -> dict:
    """(10) consistent with Hooke and Navier; (15)-(17) vs (10) applied to (14).  Relative to the term size.

    Returns {"10": d, "15": d, "16": d, "17": d}; ``printed`` overrides entries of ``PRINTED_TERMS``.
    """
    printed = {**PRINTED_TERMS, **(printed or {})}
    out = dict.fromkeys(("10", "15", "16", "17"), 0.0)
    with mpmath.workdps(WORK_DPS):
        amp, mu = mpmath.mpf(_AMPLITUDE), mpmath.mpf(_MU)
        for lt in _LAMBDAS:
            lam = mpmath.mpf(lt)
            psi = _potential(amp, lam)

            def u(r, z, psi=psi):  # (10): 2 mu u = -2 dpsi/dr
                return -mpmath.diff(psi, (r, z), (1, 0)) / mu

            for rt, zt in _POINTS:
                r, z = mpmath.mpf(rt), mpmath.mpf(zt)
                size = abs(amp) * lam**2 * mpmath.exp(-lam * z)  # term size, not the value
                uu, srt, szt = solution_e(psi, mu, r, z)
                for key, got in (("15", 2 * mu * uu), ("16", srt), ("17", szt)):
                    out[key] = max(out[key], float(abs(got - printed[key](amp, lam, r, z)) / size))
                # (10) consistent with Hooke (sigma_zt = mu du/dz, sigma_rt = mu (du/dr - u/r))
                # and with Navier's equation for u_theta: lap u - u/r^2 = 0
                hooke_z = mu * mpmath.diff(u, (r, z), (0, 1))
                hooke_r = mu * (mpmath.diff(u, (r, z), (1, 0)) - uu / r)
                navier = (mpmath.diff(u, (r, z), (2, 0)) + mpmath.diff(u, (r, z), (1, 0)) / r - uu / r**2
                          + mpmath.diff(u, (r, z), (0, 2)))
                out["10"] = max(out["10"], float(abs(hooke_z - szt) / size), float(abs(hooke_r - srt) / size),
                                float(abs(mu * navier) / size))
    return out


def check_potential():
    """(10) against Hooke's law and Navier, and (15)-(17) from psi = A exp(-lam z) J0(lam r) (14)."""
    out = measure_terms()
    notes = {
        "10": ("Solution E is consistent: its stresses follow from u by Hooke's law and u satisfies Navier's "
               "equation for axisymmetric torsion.",
               r"Solution E is consistent: its stresses follow from $u_\theta$ by Hooke's law, and $u_\theta$ "
               r"satisfies Navier's equation $\nabla^2 u_\theta - u_\theta/r^2 = 0$."),
        "15": ("Exact: (10) applied to (14).",
               r"Exact: it is (10) applied to the potential (14), differentiated numerically at 40 digits."),
        "16": ("Exact (uses (50) and (45)).",
               r"Exact: (10) applied to (14) gives $-A\lambda^2 e^{-\lambda z} J_2(\lambda r)$ via (50) and (45)."),
        "17": ("Exact: (10) applied to (14).",
               r"Exact: it is (10) applied to the potential (14), differentiated numerically at 40 digits."),
    }
    checks = {
        "10": (f"sigma_zt = mu du/dz, sigma_rt = mu (du/dr - u/r) and lap u - u/r^2 = 0 for u, sigma of (10) with "
               f"psi of (14), mpmath.diff at {WORK_DPS} digits, relative to A lam^2 exp(-lam z)"),
    }
    default = (f"eq. ({{key}}) vs (10) applied to psi of (14) by mpmath.diff at {WORK_DPS} digits, "
               "lam in {{lam_1, 11.7, 40.1}}, 4 points (r, z); error relative to A lam^2 exp(-lam z)")
    return [
        entry(key, checks.get(key, default.format(key=key)) + formula_rule(), val, verdict_formula(val),
              notes[key][0], notes[key][1])
        for key, val in out.items()
    ]


# -- (11)-(14): separation of variables -----------------------------------------------------------

def _k():
    """The wavenumber 1.3 of a test function, exact at the working precision."""
    return mpmath.mpf(13) / 10


#: Test functions g(r) with their exact first and second derivatives (not solutions of (12)).
_TEST_FUNCTIONS = (
    (lambda r: mpmath.cos(_k() * r) + r**3, lambda r: -_k() * mpmath.sin(_k() * r) + 3 * r**2,
     lambda r: -_k() ** 2 * mpmath.cos(_k() * r) + 6 * r),
    (lambda r: mpmath.exp(-r * r), lambda r: -2 * r * mpmath.exp(-r * r),
     lambda r: (4 * r * r - 2) * mpmath.exp(-r * r)),
)


def _printed_ode(g, dg, d2g, lam, r):
    """Left side of eq. (12)."""
    return d2g(r) + dg(r) / r + lam**2 * g(r)


def measure_separation(form=None, ode=None) -> tuple[float, float]:
    """(11): e^{lam z} lap psi is independent of z; (12): it equals the printed ODE.  Relative.

    ``form(lam, g)`` returns psi(r, z) (default (11): exp(-lam z) g(r)); ``ode(g, dg, d2g,
    lam, r)`` the left side of (12).  The Laplacian is Cartesian; g is an arbitrary test
    function with exact derivatives.  Returns (d11, d12).
    """
    form = form or (lambda lam, g: (lambda r, z: mpmath.exp(-lam * z) * g(r)))
    ode = ode or _printed_ode
    d11 = d12 = 0.0
    with mpmath.workdps(WORK_DPS):
        for lt in _LAMBDAS[:2]:
            lam = mpmath.mpf(lt)
            for g, dg, d2g in _TEST_FUNCTIONS:
                psi = form(lam, g)
                for rt in ("0.3", "0.8"):
                    r = mpmath.mpf(rt)
                    reduced = [laplacian_cartesian(psi, r, mpmath.mpf(zt)) * mpmath.exp(lam * mpmath.mpf(zt))
                               for zt in ("0", "0.15")]
                    size = abs(d2g(r)) + abs(dg(r) / r) + lam**2 * abs(g(r))
                    d11 = max(d11, float(abs(reduced[0] - reduced[1]) / size))
                    d12 = max(d12, float(abs(reduced[0] - ode(g, dg, d2g, lam, r)) / size))
    return d11, d12


def measure_bounded(solution=None) -> tuple[float, bool]:
    """(13): g solves (12), is bounded at r = 0, and the other solution Y0 is not.

    ``solution(lam, r)`` defaults to J0(lam r).  Returns (discrepancy, bounded): the
    largest relative residual of (12) for g and for Y0(lam r) (mpmath.diff) and of the
    Wronskian J0 Y0' - J0' Y0 = 2/(pi r) (independence); ``bounded`` is True if |g| stays
    below 1 down to r = 1e-30 while |Y0| exceeds 40 there.
    """
    solution = solution or (lambda lam, r: _J(0, lam * r))
    worst, bounded = 0.0, True
    with mpmath.workdps(WORK_DPS):
        for lt in _LAMBDAS:
            lam = mpmath.mpf(lt)

            def first(r, lam=lam):
                return _J(0, lam * r)

            def second(r, lam=lam):
                return mpmath.bessely(0, lam * r)

            for rt in ("0.05", "0.4", "1"):
                r = mpmath.mpf(rt)
                for f in (lambda s, lam=lam: solution(lam, s), second):
                    d1, d2 = mpmath.diff(f, r), mpmath.diff(f, r, 2)
                    size = abs(d2) + abs(d1 / r) + lam**2 * abs(f(r))
                    worst = max(worst, float(abs(d2 + d1 / r + lam**2 * f(r)) / size))
                wronskian = first(r) * mpmath.diff(second, r) - mpmath.diff(first, r) * second(r)
                exact = 2 / (mpmath.pi * r)
                worst = max(worst, float(abs(wronskian - exact) / exact))
            tiny = mpmath.mpf(10) ** -30
            bounded = bounded and abs(solution(lam, tiny)) <= 1 and abs(second(tiny)) > 40
    return worst, bounded


def measure_harmonic(potential=None) -> float:
    """(14): Cartesian Laplacian of psi, relative to A lam^2 exp(-lam z).  ``potential(amp, lam)`` -> psi(r, z)."""
    potential = potential or _potential
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        amp = mpmath.mpf(_AMPLITUDE)
        for lt in _LAMBDAS:
            lam = mpmath.mpf(lt)
            psi = potential(amp, lam)
            for rt, zt in _POINTS:
                r, z = mpmath.mpf(rt), mpmath.mpf(zt)
                worst = max(worst, float(abs(laplacian_cartesian(psi, r, z)) / (amp * lam**2 * mpmath.exp(-lam * z))))
    return worst


def check_separation():
    """(11), (12), (13), (14)."""
    d11, d12 = measure_separation()
    d13, bounded = measure_bounded()
    d14 = measure_harmonic()
    lap = f"Cartesian Laplacian (mpmath.diff, {WORK_DPS} digits)"
    return [
        entry(
            "11",
            f"psi = exp(-lam z) g(r) for two test functions g (not solutions), lam in {{5.1356, 11.7}}: "
            f"exp(lam z) lap psi at z = 0 and 0.15 must agree ({lap}), relative to |g''| + |g'/r| + lam^2 |g|"
            + formula_rule(),
            d11,
            verdict_formula(d11),
            "The form (11) separates Laplace's equation: exp(lam z) lap psi does not depend on z, for any g.",
            r"The form (11) separates Laplace's equation: $e^{\lambda z}\nabla^2\psi$ does not depend on $z$ for "
            r"any $g(r)$, as a Cartesian Laplacian of two test functions confirms.",
        ),
        entry(
            "12",
            f"exp(lam z) lap psi ({lap}) vs the printed left side g'' + g'/r + lam^2 g of (12), same test functions"
            + formula_rule(),
            d12,
            verdict_formula(d12),
            "The ordinary differential equation is exactly what Laplace's equation becomes (sign of lam^2 included).",
            r"Exact: Laplace's equation for (11) is $g'' + g'/r + \lambda^2 g = 0$, with the sign of $\lambda^2$ "
            r"as printed.",
        ),
        entry(
            "13",
            f"residual of (12) for J0(lam r) and Y0(lam r) (mpmath.diff, {WORK_DPS} digits), Wronskian "
            "J0 Y0' - J0' Y0 vs 2/(pi r), and |J0| <= 1 while |Y0(lam r)| > 40 at r = 1e-30" + formula_rule()
            + " and bounded",
            d13,
            verdict_formula(d13) if bounded else "incorrect",
            "J0 and Y0 are two independent solutions of (12); only J0 is bounded at r = 0, so g = A J0(lam r).",
            r"$J_0(\lambda r)$ and $Y_0(\lambda r)$ solve (12) and are independent (Wronskian $2/(\pi r)$); only "
            r"$J_0$ is bounded at $r = 0$, so $g = A J_0(\lambda r)$.",
        ),
        entry(
            "14",
            f"{lap} of psi = A exp(-lam z) J0(lam r), lam in {{lam_1, 11.7, 40.1}}, 4 points, relative to "
            "A lam^2 exp(-lam z)" + formula_rule(),
            d14,
            verdict_formula(d14),
            "The potential is harmonic (Cartesian Laplacian zero).",
            r"The potential $\psi = A e^{-\lambda z}J_0(\lambda r)$ is harmonic: its Cartesian Laplacian vanishes.",
        ),
    ]


# -- (18)-(19): the side r = a ------------------------------------------------------------------------

def _side_stress(amp, lam, a, z):
    """sigma_rt(a, z) of (10) applied to (14), by mpmath.diff."""
    return solution_e(_potential(amp, lam), mpmath.mpf(1), a, z)[1]


def measure_side(printed=None) -> float:
    """(18): sigma_rt(a, z) from (10) vs the printed -A lam^2 exp(-lam z) J2(lam a), lam not a zero of J2.

    ``printed(amp, lam, a, z)``; relative to A lam^2 exp(-lam z).
    """
    printed = printed or (lambda amp, lam, a, z: -amp * lam**2 * mpmath.exp(-lam * z) * _J(2, lam * a))
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        amp = mpmath.mpf(_AMPLITUDE)
        for at in _RADII:
            a = mpmath.mpf(at)
            for lt in ("2.3", "7.7", "19.1"):
                lam = mpmath.mpf(lt) / a
                for zt in ("0", "0.1", "0.5"):
                    z = mpmath.mpf(zt) * a
                    size = amp * lam**2 * mpmath.exp(-lam * z)
                    worst = max(worst, float(abs(_side_stress(amp, lam, a, z) - printed(amp, lam, a, z)) / size))
    return worst


def measure_eigen_condition(eigenvalues=None) -> float:
    """(19): at lam a = the n-th zero of J2 (n = 1..5), sigma_rt(a, z) of (10) vanishes for every z.

    ``eigenvalues(n)`` gives lam a (default the zeros of J2); relative to A lam^2 exp(-lam z).
    """
    eigenvalues = eigenvalues or (lambda n: mpmath.besseljzero(2, n))
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        amp = mpmath.mpf(_AMPLITUDE)
        for at in _RADII:
            a = mpmath.mpf(at)
            for n in range(1, 6):
                lam = eigenvalues(n) / a
                for zt in ("0", "0.1", "0.5"):
                    z = mpmath.mpf(zt) * a
                    size = amp * lam**2 * mpmath.exp(-lam * z)
                    worst = max(worst, float(abs(_side_stress(amp, lam, a, z)) / size))
    return worst


def check_side_condition():
    """(18) and (19)."""
    d18, d19 = measure_side(), measure_eigen_condition()
    return [
        entry(
            "18",
            f"sigma_rt(a, z) of (10) applied to (14) (mpmath.diff, {WORK_DPS} digits) vs the printed "
            "-A lam^2 exp(-lam z) J2(lam a), a in {0.37, 2.9}, lam a in {2.3, 7.7, 19.1}, z/a in {0, 0.1, 0.5}, "
            "relative to A lam^2 exp(-lam z)" + formula_rule(),
            d18,
            verdict_formula(d18),
            "Exact: on the side r = a the corrective shear is proportional to J2(lam a) at every z.",
            r"Exact: on the side $r = a$ the corrective shear is $-A\lambda^2e^{-\lambda z}J_2(\lambda a)$, "
            r"proportional to $J_2(\lambda a)$ at every height.",
        ),
        entry(
            "19",
            f"sigma_rt(a, z) of (10) at lam = lam_(2,n)/a, n = 1..5, a in {{0.37, 2.9}}, z/a in {{0, 0.1, 0.5}} "
            f"(mpmath.diff, {WORK_DPS} digits), relative to A lam^2 exp(-lam z)" + formula_rule(),
            d19,
            verdict_formula(d19),
            "Exact: (18) vanishes for all z if and only if J2(lam a) = 0 (A, lam nonzero).",
            r"Exact: (18) vanishes at every height if and only if $J_2(\lambda a) = 0$; at the zeros the side "
            r"shear computed from (10) is zero to 40 digits.",
        ),
    ]
