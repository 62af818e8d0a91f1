"""Section 2: the uniform pressure (1) and the bilateral field (2)-(6).

Each ``check_*`` returns a list of errata records (``verdicts.entry``).  Dimensional
checks draw F, T, a, mu at random; the formula checks run at ``WORK_DPS`` digits.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
from scipy import optimize

from ...criteria import von_mises_index
from ...typeset import plain_sci
from .differential import lateral_traction
from .rules import double_rule, formula_rule
from .settings import TOL_DOUBLE, WORK_DPS
from .verdicts import entry, relative_difference, verdict_formula

__all__ = ["check_pressure", "check_bilateral", "bilateral_shear", "bilateral_displacement",
           "measure_pressure", "measure_no_rt_shear"]

#: Dimensional (F, T, a, mu) of the checks: unit values, a small steel rod, a large soft one.
_CASES = (("1", "1", "1", "1"), ("250", "35", "0.02", "8e10"), ("3.5", "0.4", "3", "2.5"))


def bilateral_shear(r, torque, a):
    """sigma_zt of eq. (2): 2 T r / (pi a^4)."""
    return 2 * torque * r / (mpmath.pi * a**4)


def bilateral_displacement(r, z, torque, mu, a):
    """u_theta of eq. (4): 2 T r z / (pi mu a^4)."""
    return 2 * torque * r * z / (mpmath.pi * mu * a**4)


def measure_pressure(pressure=None) -> float:
    """Relative discrepancy of the resultant of the pressure (1) against F (mpmath.quad).

    ``pressure(F, a)`` is p0 of eq. (1) (default F / (pi a^2)); a test feeds a wrong one.
    """
    pressure = pressure or (lambda force, a: force / (mpmath.pi * a**2))
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        for force, _, a, _ in _CASES:
            force, a = mpmath.mpf(force), mpmath.mpf(a)
            p0 = pressure(force, a)
            resultant = mpmath.quad(lambda r, p0=p0: 2 * mpmath.pi * r * p0, [0, a])
            worst = max(worst, relative_difference(resultant, force))
    return worst


def measure_no_rt_shear(displacement=None) -> float:
    """Largest |sigma_rt| of the field (4) on cylinders r = const, over the largest shear 2T/(pi a^3).

    sigma_rt is the tangential traction on r = const, computed from the Cartesian strain of
    the displacement (``differential.lateral_traction``), so it does not use the formula
    mu (du/dr - u/r) either.  ``displacement(r, z, T, mu, a)`` defaults to eq. (4).
    """
    displacement = displacement or bilateral_displacement
    worst = 0.0
    with mpmath.workdps(WORK_DPS):
        for _, torque, a, mu in _CASES:
            torque, a, mu = mpmath.mpf(torque), mpmath.mpf(a), mpmath.mpf(mu)
            scale = 2 * torque / (mpmath.pi * a**3)
            for rt, zt in (("0.3", "0.1"), ("0.8", "1.7"), ("1", "0.4")):
                r, z = mpmath.mpf(rt) * a, mpmath.mpf(zt) * a
                _, t_theta, _, _ = lateral_traction(
                    lambda s, t, torque=torque, mu=mu, a=a: displacement(s, t, torque, mu, a), mu, r, z)
                worst = max(worst, float(abs(t_theta) / scale))
    return worst


def _measure_shaft():
    """(2): resultant torque; (4): mu du/dz = (2) and Navier's equation, relative to the shear scale."""
    disc2 = disc4 = 0.0
    with mpmath.workdps(WORK_DPS):
        for _, torque, a, mu in _CASES:
            torque, a, mu = mpmath.mpf(torque), mpmath.mpf(a), mpmath.mpf(mu)
            resultant = mpmath.quad(lambda r, t=torque, a=a: 2 * mpmath.pi * r * r * bilateral_shear(r, t, a), [0, a])
            disc2 = max(disc2, relative_difference(resultant, torque))

            def disp(r, z, torque=torque, mu=mu, a=a):
                return bilateral_displacement(r, z, torque, mu, a)

            scale = 2 * torque / (mpmath.pi * a**3)
            for rt, zt in (("0.3", "0.1"), ("0.9", "2")):
                r, z = mpmath.mpf(rt) * a, mpmath.mpf(zt) * a
                hooke = mu * mpmath.diff(disp, (r, z), (0, 1))
                navier = (mpmath.diff(disp, (r, z), (2, 0)) + mpmath.diff(disp, (r, z), (1, 0)) / r
                          - disp(r, z) / r**2 + mpmath.diff(disp, (r, z), (0, 2)))
                disc4 = max(disc4, relative_difference(hooke, bilateral_shear(r, torque, a)),
                            float(abs(mu * navier * a) / scale))
    return disc2, disc4


def check_pressure():
    """(1): the uniform pressure p0 = F / (pi a^2) balances the axial force."""
    disc = measure_pressure()
    return [
        entry(
            "1",
            f"resultant 2 pi int_0^a r p0 dr of (1) vs F (mpmath.quad, {WORK_DPS} digits, 3 dimensional (F, a))"
            + formula_rule(),
            disc,
            verdict_formula(disc),
            "The uniform pressure balances F. It is exact for elastically similar cylinders of equal radius: "
            "uniform compression expands both by the same nu p0 r / E, so no interfacial shear arises "
            "(the 'single bar' of the paper).",
            r"The uniform pressure $p_0 = F/(\pi a^2)$ has resultant $F$ (40-digit quadrature). It is exact "
            r"because both cylinders expand radially by the same $\nu p_0 r/E$ under uniform compression.",
        )
    ]


def check_bilateral():
    """(2), (3), (4) from torsion of a solid shaft; (5) slip onset; (6) von Mises."""
    disc2, disc4 = _measure_shaft()
    disc3 = measure_no_rt_shear()
    rng = np.random.default_rng(12345)
    # (5): largest |T| with |sigma_zt| <= f p0 on 0 < r < a, found numerically, in units of f F a / 2
    disc5 = 0.0
    for f, force, a in ((0.3, 100.0, 0.01), (0.8, 2.0, 1.5)):
        p0 = force / (math.pi * a * a)

        def excess(torque, f=f, a=a, p0=p0):
            radii = np.linspace(0.0, a, 2001)
            return np.max(np.abs(2 * torque * radii / (math.pi * a**4))) - f * p0

        limit = optimize.brentq(excess, 0.0, 10 * f * force * a, xtol=1e-300, rtol=1e-15)
        disc5 = max(disc5, abs(limit / (f * force * a) - 0.5) / 0.5)
    # (6): von Mises from principal stresses of sigma_zz = -p0, sigma_zt = 2T/(pi a^3) at r = a
    disc6 = 0.0
    for _ in range(20):
        torque, force, a, k = rng.uniform(0.1, 5.0, size=4)
        tau, szz = 2 * torque / (math.pi * a**3), -force / (math.pi * a * a)
        stress = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, tau], [0.0, tau, szz]])  # (r, theta, z)
        p = np.linalg.eigvalsh(stress)
        j2 = ((p[0] - p[1]) ** 2 + (p[1] - p[2]) ** 2 + (p[2] - p[0]) ** 2) / 6.0
        disc6 = max(disc6, abs(j2 / k**2 - von_mises_index(torque, force, a, k)) / (j2 / k**2))
    return [
        entry(
            "2",
            f"resultant 2 pi int_0^a r^2 sigma_zt dr of (2) = T (mpmath.quad, {WORK_DPS} digits, 3 dimensional "
            "(a, T))" + formula_rule(),
            disc2,
            verdict_formula(disc2),
            "Elementary torsion of a solid shaft: the shear (2) carries the torque T.",
            r"The shear (2) carries the torque: $2\pi\int_0^a r^2\sigma_{z\theta}\,dr = T$ (40-digit quadrature), "
            r"as in elementary torsion of a solid shaft.",
        ),
        entry(
            "3",
            "tangential traction on cylinders r = const of the displacement (4), from its Cartesian strain "
            f"(mpmath.diff, {WORK_DPS} digits), over 2T/(pi a^3); 3 dimensional (T, mu, a), 3 points" + formula_rule(),
            disc3,
            verdict_formula(disc3),
            "The uniform twist (4) has sigma_rt = mu (du/dr - u/r) = 0 everywhere, computed here from the "
            "Cartesian strain, so the side r = a is traction-free.",
            r"The uniform twist (4) has $\sigma_{r\theta} = \mu(\partial u_\theta/\partial r - u_\theta/r) = 0$, "
            r"computed here from its Cartesian strain; the side $r = a$ is therefore traction-free.",
        ),
        entry(
            "4",
            "mu du/dz of (4) = sigma_zt of (2), and Navier's equation lap u - u/r^2 = 0 for u of (4) "
            f"(mpmath.diff, {WORK_DPS} digits, relative to 2T/(pi a^3))" + formula_rule(),
            disc4,
            verdict_formula(disc4),
            "Consistent with (2), and an elastic solution (Navier's equation holds).",
            r"Hooke's law $\sigma_{z\theta} = \mu\,\partial u_\theta/\partial z$ gives (2), and (4) satisfies "
            r"Navier's equation $\nabla^2 u_\theta - u_\theta/r^2 = 0$.",
        ),
        entry(
            "5",
            "largest |T| with max_r |sigma_zt of (2)| <= f p0, by root finding (double), vs f F a / 2"
            + double_rule(),
            disc5,
            verdict_formula(disc5, tol=TOL_DOUBLE),
            "Slip starts at r = a when |T|/(F a) = f/2, i.e. T* = 1 (eq. 32).",
            r"Slip starts at $r = a$ when $|T|/(Fa) = f/2$, that is at $T^* = 1$ by (32); root finding in "
            r"double precision reproduces the bound to rounding.",
        ),
        entry(
            "6",
            "second invariant J2 of the stress tensor (sigma_zz = -p0, sigma_zt = 2T/(pi a^3) at r = a) "
            "from its eigenvalues, J2/tau_Y^2 vs left side of (6) (the original's k is tau_Y), 20 random "
            "(T, F, a, tau_Y), double" + double_rule(),
            disc6,
            verdict_formula(disc6, tol=TOL_DOUBLE),
            "Von Mises J2 = tau_Y^2 at the outer radius of the bilateral field; slip only lowers the interface "
            f"shear, so (6) also bounds the split shaft (agreement {plain_sci(disc6)}).",
            r"The von Mises condition $J_2 = \tau_Y^2$ at $r = a$ of the bilateral field is (6); slip only lowers the "
            r"interface shear, so (6) also bounds the split shaft.",
        ),
    ]
