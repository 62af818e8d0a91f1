"""Slip onset (eq. 5), spinning, and the von Mises onset of plastic flow (eq. 6).

Dimensional inputs are in any consistent units (N, m, Pa); results are dimensionless.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

__all__ = [
    "SLIP_ONSET_TORQUE",
    "GROSS_SLIP_TORQUE",
    "spinning_deficit",
    "von_mises_index",
    "von_mises_torque_limit",
]

#: T* at which slip starts at r = a (eq. 5 in the normalisation of eq. 32).
SLIP_ONSET_TORQUE = 1.0
#: T* at which the whole face slips (traction f p0 everywhere: T = 2 pi a^3 f p0 / 3).
GROSS_SLIP_TORQUE = 4.0 / 3.0


#: 4/3 - float(4/3), the rounding of GROSS_SLIP_TORQUE (exact: Fraction(4, 3) - Fraction(4/3)).
_GROSS_SLIP_ROUNDING = float(Fraction(4, 3) - Fraction(GROSS_SLIP_TORQUE))


def spinning_deficit(torque):
    """4/3 - T* for floats T* near 4/3, to the rounding of the result (vectorised).

    (4/3 - float(4/3)) + (float(4/3) - T*): the second difference is exact for
    2/3 <= T* <= 8/3 (Sterbenz), so the deficit keeps its relative accuracy even when it is
    a few ulp of 4/3, where 4/3 - T* in floating point would lose every digit.
    """
    torque = np.asarray(torque, dtype=float)
    out = _GROSS_SLIP_ROUNDING + (GROSS_SLIP_TORQUE - torque)
    return out if out.ndim else float(out)


def von_mises_index(torque, normal_force, radius, shear_yield):
    """Left side of eq. (6): (2T/(pi a^3 k))^2 + (F/(pi a^2 k))^2 / 3.

    Plastic flow starts where this reaches 1.  Eq. (6) is the von Mises condition
    sigma_zt^2 + sigma_zz^2 / 3 = k^2 at r = a, where the bilateral shear stress (2) is
    largest (2T/(pi a^3)) and sigma_zz = -F/(pi a^2) (eq. 1).  Slip only lowers the
    interface shear (traction <= f p0), so eq. (6) bounds the split shaft too.
    """
    tau = 2.0 * np.asarray(torque, dtype=float) / (np.pi * radius**3 * shear_yield)
    sigma = np.asarray(normal_force, dtype=float) / (np.pi * radius**2 * shear_yield)
    return tau**2 + sigma**2 / 3.0


def von_mises_torque_limit(normal_force, radius, shear_yield):
    """Torque |T| at which eq. (6) is met for a given F; nan when F alone yields."""
    sigma = np.asarray(normal_force, dtype=float) / (np.pi * radius**2 * shear_yield)
    remaining = 1.0 - sigma**2 / 3.0
    with np.errstate(invalid="ignore"):
        return np.where(remaining >= 0, 0.5 * np.pi * radius**3 * shear_yield * np.sqrt(remaining), np.nan)
