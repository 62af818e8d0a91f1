"""Section 3: the boundary conditions (7)-(9) in the paper's normalisation, dimensional values at random.

(7) and (8) are checked as the statements they make once the bilateral field (2), (4) is
inserted and the project's normalisation applied (T* = 2T/(f F a), tractions in f p0,
displacements in f p0 a / mu); (9) from the traction vector on r = a computed from the
Cartesian strain of the total displacement.  ``measure_*`` take the printed ingredients as
arguments so that a test can feed corrupted ones.
"""

from __future__ import annotations

import mpmath
import numpy as np

from .bilateral import bilateral_displacement, bilateral_shear
from .differential import lateral_traction
from .rules import formula_rule
from .settings import WORK_DPS
from .verdicts import entry, verdict_formula

__all__ = ["check_conditions", "random_cases", "measure_stick", "measure_slip", "measure_side_traction"]

_J = mpmath.besselj


def random_cases(seed: int, count: int = 3):
    """Dimensional (T, f, F, a, mu, beta) drawn at random, as decimal mpf (reproducible, seeded)."""
    rng = np.random.default_rng(seed)
    cases = []
    for _ in range(count):
        a, f = rng.uniform(0.05, 3.0), rng.uniform(0.1, 0.9)
        mu, force = 10 ** rng.uniform(-1, 11), 10 ** rng.uniform(-1, 4)
        tstar = rng.uniform(1.0, 4.0 / 3.0)  # partial slip
        torque = tstar * f * force * a / 2
        values = (torque, f, force, a, mu, rng.uniform(0.1, 0.9))
        cases.append(tuple(mpmath.mpf(f"{v:.12g}") for v in values))
    return cases


def measure_stick(displacement=None) -> float:
    """(7): u^B(r, 0) = 0, so (7) is u^C(r, 0) = 0; and u^B / (f p0 a / mu) = T* (r/a)(z/a).

    ``displacement(r, z, T, mu, a)`` defaults to eq. (4).  Relative to T* (r/a)(z/a) at z = a/2.
    """
    displacement = displacement or bilateral_displacement
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        for torque, f, force, a, mu, beta in random_cases(7):
            p0 = force / (mpmath.pi * a**2)
            tstar = 2 * torque / (f * force * a)
            unit = f * p0 * a / mu
            for rho in (beta / 3, beta * 2 / 3, beta):
                interface = displacement(rho * a, 0, torque, mu, a) / unit
                inside = displacement(rho * a, a / 2, torque, mu, a) / unit
                scale = tstar * rho / 2
                worst = max(worst, float(abs(interface) / scale), float(abs(inside - tstar * rho / 2) / scale))
    return worst


def measure_slip(limit=None) -> float:
    """(8): the printed limit f F / (pi a^2) is f p0 of (1), and sigma^B(r, 0) / (f p0) = T* r / a.

    ``limit(f, F, a)`` is the right side of (8).  For the sigma^C(r, 0) that satisfies (8)
    with sigma^B of (2), checks that (8) divided by f p0 reads T* r/a + sigma^C / (f p0) = 1
    (T* of eq. 32); absolute, in units of f p0.
    """
    limit = limit or (lambda f, force, a: f * force / (mpmath.pi * a**2))
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        for torque, f, force, a, _, beta in random_cases(8):
            p0 = force / (mpmath.pi * a**2)  # eq. (1)
            tstar = 2 * torque / (f * force * a)
            for rho in (beta + (1 - beta) / 3, 1):
                corrective = limit(f, force, a) - bilateral_shear(rho * a, torque, a)  # sigma^C that satisfies (8)
                normalised = tstar * rho + corrective / (f * p0)
                worst = max(worst, float(abs(normalised - 1)))
    return worst


def measure_side_traction(claimed=None) -> float:
    """(9): the traction on r = a of u = u^B + u^C is (0, sigma^C_rt(a, z), 0), and vanishes for lam = lam_2n / a.

    The traction vector comes from the Cartesian strain (``differential.lateral_traction``)
    of u^B of (4) plus a term of (15).  For lam a = 7.7 (not a zero of J2) the tangential
    component must equal ``claimed(amp, lam, a, z)`` (default sigma^C_rt of (16) at r = a,
    the paper's statement that sigma_rt = sigma^C_rt there) and the normal and axial ones
    vanish; for lam a = lam_(2,2) all three vanish.  Relative to the shear scale
    2T/(pi a^3) + A lam^2.
    """
    claimed = claimed or (lambda amp, lam, a, z: -amp * lam**2 * mpmath.exp(-lam * z) * _J(2, lam * a))
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        for torque, _, _, a, mu, _ in random_cases(9, count=2):
            amp = 2 * torque / (mpmath.pi * a**3) / 10  # a corrective term of a tenth of the bilateral shear
            for lam_a, is_zero in ((mpmath.mpf("7.7"), False), (mpmath.besseljzero(2, 2), True)):
                lam = lam_a / a

                def u(r, z, lam=lam, amp=amp, a=a, mu=mu, torque=torque):
                    corrective = amp * lam * mpmath.exp(-lam * z) * _J(1, lam * r) / mu  # (15)
                    return bilateral_displacement(r, z, torque, mu, a) + corrective

                scale = 2 * torque / (mpmath.pi * a**3) + amp * lam**2
                for zt in ("0", "0.2"):
                    z = mpmath.mpf(zt) * a
                    t_r, t_theta, t_z, trace = lateral_traction(u, mu, a, z)
                    expected = 0 if is_zero else claimed(amp, lam, a, z)
                    worst = max(worst, *(float(abs(x) / scale) for x in (t_r, t_theta - expected, t_z, mu * trace)))
    return worst


def check_conditions():
    """(7), (8), (9)."""
    d7, d8, d9 = measure_stick(), measure_slip(), measure_side_traction()
    random = "3 random dimensional (T, f, F, a, mu, b/a) with 1 < T* < 4/3"
    return [
        entry(
            "7",
            f"u^B(r, 0) of (4) over f p0 a / mu (must vanish) and u^B(r, a/2) / (f p0 a / mu) vs T* (r/a)(1/2), "
            f"0 < r < b, {random}, {WORK_DPS} digits" + formula_rule(),
            d7,
            verdict_formula(d7),
            "In units f p0 a / mu the bilateral displacement is T* r z, which vanishes on z = 0, so (7) is "
            "u^C(r, 0) = 0 on the stick disc: the condition that leads to (27).",
            r"In units of $fp_0a/\mu$ the bilateral displacement is $T^* r z$, zero on $z = 0$, so (7) says "
            r"$u^C_\theta(r, 0) = 0$ on the stick disc, the condition that leads to (27).",
        ),
        entry(
            "8",
            f"(8) divided by f p0 = f F / (pi a^2) (eq. 1) with sigma^B of (2): T* r/a + sigma^C / (f p0) = 1 on "
            f"b < r < a, {random}, {WORK_DPS} digits" + formula_rule(),
            d8,
            verdict_formula(d8),
            "The limit f F / (pi a^2) is f p0 of (1), the Coulomb limit f |sigma_zz|, and sigma^B(r, 0) / (f p0) = "
            "T* r / a, so (8) reads T* r/a + sigma^C / (f p0) = 1 on the slip annulus (positive torque).",
            r"The limit $fF/(\pi a^2)$ is $fp_0$, the Coulomb limit $f|\sigma_{zz}|$ of (1), and "
            r"$\sigma^B_{z\theta}(r,0)/(fp_0) = T^* r/a$, so (8) reads $T^* r/a + \sigma^C_{z\theta}/(fp_0) = 1$ "
            r"on the slip annulus.",
        ),
        entry(
            "9",
            "traction vector on r = a of u^B (4) + one term of (15), from the Cartesian strain (mpmath.diff, "
            f"{WORK_DPS} digits): normal and axial parts zero, tangential part = sigma^C_rt(a, z) of (16) for "
            "lam a = 7.7 and zero for lam a = lam_(2,2); 2 random dimensional cases, z/a in {0, 0.2}, relative "
            "to 2T/(pi a^3) + A lam^2" + formula_rule(),
            d9,
            verdict_formula(d9),
            "On r = a a torsion field has only the traction sigma_rt, and sigma^B_rt = 0 by (3), so (9) "
            "(sigma^C_rt(a, z) = 0 for all z) is the complete traction-free condition of the side.",
            r"On $r = a$ a torsion field has only the traction $\sigma_{r\theta}$, and $\sigma^B_{r\theta} = 0$ by "
            r"(3), so (9) is the complete traction-free condition of the cylinder's side.",
        ),
    ]
