"""Sections 2-3: the bilateral field (2)-(6) and Solution E with its series terms (10)-(17).

Each ``check_*`` returns a list of errata records (``verdicts.entry``); units as in
``settings``.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
from scipy import optimize

from ...criteria import von_mises_index
from .settings import TOL_DIFF, TOL_DOUBLE, WORK_DPS
from .verdicts import entry, relative_difference, verdict_formula

__all__ = ["check_bilateral", "check_potential"]


def check_potential():
    """(10) against Hooke's law and Navier, and (15)-(17) from psi = A exp(-lam z) J0(lam r) (14)."""
    out = {"10": 0.0, "15": 0.0, "16": 0.0, "17": 0.0}
    with mpmath.workdps(WORK_DPS):
        amp, mu = mpmath.mpf("0.7"), mpmath.mpf("1.9")
        for lt in ("5.1356223018406825563", "11.7", "40.1"):
            lam = mpmath.mpf(lt)

            def psi(r, z, lam=lam):
                return amp * mpmath.exp(-lam * z) * mpmath.besselj(0, lam * r)

            def u(r, z, lam=lam, psi=psi):  # (10): 2 mu u = -2 dpsi/dr
                return -mpmath.diff(lambda s: psi(s, z), r) / mu

            for rt, zt in (("0.2", "0"), ("0.55", "0.1"), ("0.9", "0.03"), ("1", "0.2")):
                r, z = mpmath.mpf(rt), mpmath.mpf(zt)
                e = mpmath.exp(-lam * z)
                srt = mpmath.diff(lambda s, z=z: psi(s, z), r) / r - mpmath.diff(lambda s, z=z: psi(s, z), r, 2)
                szt = -mpmath.diff(psi, (r, z), (1, 1))
                uu = u(r, z)
                # (15)-(17) as printed
                for key, got, printed in (
                    ("15", 2 * mu * uu, 2 * amp * lam * e * mpmath.besselj(1, lam * r)),
                    ("16", srt, -amp * lam**2 * e * mpmath.besselj(2, lam * r)),
                    ("17", szt, -amp * lam**2 * e * mpmath.besselj(1, lam * r)),
                ):
                    size = 2 * amp * lam * e if key == "15" else amp * lam**2 * e  # term size, not the value
                    out[key] = max(out[key], float(abs(got - printed) / size))
                # (10) consistent with Hooke (sigma_zt = mu du/dz, sigma_rt = mu (du/dr - u/r))
                # and with Navier's equation for u_theta: lap u - u/r^2 = 0
                hooke_z = mu * mpmath.diff(lambda t, r=r: u(r, t), z)
                hooke_r = mu * (mpmath.diff(lambda s, z=z: u(s, z), r) - uu / r)
                navier = (
                    mpmath.diff(lambda s, z=z: u(s, z), r, 2)
                    + mpmath.diff(lambda s, z=z: u(s, z), r) / r
                    - uu / r**2
                    + mpmath.diff(lambda t, r=r: u(r, t), z, 2)
                )
                scale = lam**2 * abs(amp) * e / mu
                out["10"] = max(
                    out["10"],
                    float(abs(hooke_z - szt) / (mu * scale)),
                    float(abs(hooke_r - srt) / (mu * scale)),
                    float(abs(navier) / scale),
                )
    notes = {
        "10": "Solution E is consistent: its stresses follow from u by Hooke's law and u satisfies "
        "Navier's equation for axisymmetric torsion.",
        "15": "Exact.",
        "16": "Exact (uses (50) and (45)).",
        "17": "Exact.",
    }
    checks = {
        "10": "sigma_zt = mu du/dz, sigma_rt = mu (du/dr - u/r) and lap u - u/r^2 = 0 for u, sigma of (10) "
        "with psi of (14), mpmath.diff at 40 digits",
    }
    return [
        entry(
            key,
            checks.get(
                key,
                f"eq. ({key}) vs (10) applied to psi of (14) by mpmath.diff at {WORK_DPS} digits, "
                "lam in {lam_1, 11.7, 40.1}, 4 points (r, z); error relative to A lam^2 exp(-lam z)",
            ),
            val,
            verdict_formula(val, tol=TOL_DIFF),
            notes[key],
        )
        for key, val in out.items()
    ]


def check_bilateral():
    """(2) and (4) from torsion of a solid shaft; (5) slip onset; (6) von Mises."""
    rng = np.random.default_rng(12345)
    disc2 = disc4 = 0.0
    with mpmath.workdps(30):
        for a, torque, mu in ((1.0, 1.0, 1.0), (0.02, 35.0, 8e10), (3.0, 0.4, 2.5)):
            a, torque, mu = mpmath.mpf(a), mpmath.mpf(torque), mpmath.mpf(mu)

            def sigma(r, a=a, torque=torque):  # (2)
                return 2 * torque * r / (mpmath.pi * a**4)

            resultant = mpmath.quad(lambda r, sigma=sigma: 2 * mpmath.pi * r * r * sigma(r), [0, a])
            disc2 = max(disc2, relative_difference(resultant, torque))

            def disp(r, z, a=a, torque=torque, mu=mu):  # (4)
                return 2 * torque * r * z / (mpmath.pi * mu * a**4)

            for r, z in ((0.3, 0.1), (0.9, 2.0)):
                r, z = mpmath.mpf(r) * a, mpmath.mpf(z) * a
                disc4 = max(disc4, relative_difference(mu * mpmath.diff(lambda t, r=r: disp(r, t), z), sigma(r)))
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
            "resultant 2 pi int_0^a r^2 sigma_zt dr of (2) = T (mpmath.quad, 30 digits, 3 (a, T))",
            disc2,
            verdict_formula(disc2, tol=1e-25),
            "Elementary torsion of a solid shaft.",
        ),
        entry(
            "4",
            "mu du/dz of (4) = sigma_zt of (2) (mpmath.diff)",
            disc4,
            verdict_formula(disc4, tol=1e-25),
            "Consistent with (2).",
        ),
        entry(
            "5",
            "largest |T| with max_r |sigma_zt of (2)| <= f p0, by root finding (double), vs f F a / 2",
            disc5,
            verdict_formula(disc5, tol=TOL_DOUBLE),
            "Slip starts at r = a when |T|/(F a) = f/2, i.e. T* = 1 (eq. 32).",
        ),
        entry(
            "6",
            "second invariant J2 of the stress tensor (sigma_zz = -p0, sigma_zt = 2T/(pi a^3) at r = a) "
            "from its eigenvalues, J2/k^2 vs left side of (6), 20 random (T, F, a, k), double",
            disc6,
            verdict_formula(disc6, tol=TOL_DOUBLE),
            "Von Mises J2 = k^2 at the outer radius of the bilateral field; slip only lowers the interface "
            "shear, so (6) also bounds the split shaft.",
        ),
    ]
