r"""Closed forms of the "hertz" and "flat-punch" models in complete elliptic integrals.

Units as ``half_space.jaeger``: b in a; T* = 2T/(f F a); Omega in f p-bar / mu.  K(m), E(m) are the
complete elliptic integrals of parameter m = k^2 = 1 - b^2 (scipy.special.ellipk / ellipe; K through
ellipkm1(b^2) so that small b keeps its accuracy).

Hertz, p = (3/2) sqrt(1 - r^2) (two elastically similar bodies).  With x^2 = b^2 + m sin^2(theta) in
(J1), R = (3/4) m int_0^(pi/2) cos^2 / sqrt(1 - m cos^2) = (3/4)(K - E):

    Omega(b) = (3/4) [K(m) - E(m)],            dT*/db = -(8/pi) b^2 E(m),                     (E1)

(dT*/db = (32/(3 pi)) b^3 dR/db, d(K - E)/dk = k E / k'^2); gross slip T*(0) = 3 pi / 8.
Small slip (T* -> 0, m -> 0): T* = 2m - (3/4) m^2 + ..., Omega = (3 pi / 32) T* (1 + 3 T*/8 + ...),
W_mono = (3 pi^2 / 256) T*^3 (1 + ...), W(A) = 4 W_mono(A/2) = (3 pi^2 / 512) A^3 (Mindlin's cubic law).

Flat punch, p = 1 / (2 sqrt(1 - r^2)) (a rigid punch on one elastic half-space).  R = (1/4) K:

    Omega(b) = K(m) / 4,   dT*/db = -(8/(3 pi)) b^2 (E(m) - b^2 K(m)) / m,                     (E2)

R(1) = pi/8, so the punch is bonded up to T* = (32/(3 pi)) pi/8 = 4/3 with Omega = 3 pi T*/32 and
slips fully at T*(0) = pi/2.  Beyond the onset, d = T* - 4/3: m = 3 d + (27/16) d^2 + ...,
Omega = pi/8 + (3 pi / 32) d + (27 pi / 128) d^2 + ..., W_mono = (9 pi^2 / 64) d^2 + ...

No closed form of T*(b) in complete elliptic integrals was found (int c^2 K(1 - c^2) dc is not a
combination of K, E with polynomial coefficients): T*(b) = T*(0) - int_0^b |dT*/dc| dc, and the
general quadrature (J2) of ``jaeger`` gives it.  Tests compare (E1), (E2) with the quadrature and
with mpmath.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

__all__ = ["hertz_rotation", "hertz_torque_slope", "punch_rotation", "punch_torque_slope", "HERTZ_GROSS_SLIP",
           "PUNCH_ONSET", "PUNCH_GROSS_SLIP", "HERTZ_CYCLE_COEFFICIENT", "PUNCH_CYCLE_COEFFICIENT"]

#: Gross-slip torque of "hertz": 4 int_0^1 (3/2) sqrt(1 - r^2) r^2 dr.
HERTZ_GROSS_SLIP = 3.0 * math.pi / 8.0
#: Slip onset and gross slip of "flat-punch".
PUNCH_ONSET = 4.0 / 3.0
PUNCH_GROSS_SLIP = math.pi / 2.0
#: W(A) ~ c A^3 for "hertz" as A -> 0.
HERTZ_CYCLE_COEFFICIENT = 3.0 * math.pi**2 / 512.0
#: W(A) ~ c (A/2 - 4/3)^2 for "flat-punch" just above A = 8/3.
PUNCH_CYCLE_COEFFICIENT = 9.0 * math.pi**2 / 16.0

_SERIES_M = 0.25
_SERIES_TERMS = 40


def _hypergeometric_terms(a: float) -> np.ndarray:
    """(a)_k (1/2)_k / (k!)^2, k = 0.._SERIES_TERMS: K = (pi/2) sum with a = 1/2, E with a = -1/2."""
    out = [1.0]
    for k in range(_SERIES_TERMS):
        out.append(out[-1] * (a + k) * (0.5 + k) / (k + 1) ** 2)
    return np.array(out)


_K_TERMS = _hypergeometric_terms(0.5)
_E_TERMS = _hypergeometric_terms(-0.5)


def _series(coefficients, m):
    total = np.zeros_like(m)
    for c in coefficients[::-1]:
        total = total * m + c
    return total


def _parameter(b):
    b = np.asarray(b, dtype=float)
    return b, (1.0 - b) * (1.0 + b)


def _scalar(value, like):
    return float(value) if np.ndim(like) == 0 else value


def hertz_rotation(b):
    """Omega(b) = (3/4)(K(m) - E(m)), eq. (E1), for 0 < b <= 1 (series in m below m = 1/4: no cancellation)."""
    b, m = _parameter(b)
    small = m < _SERIES_M
    series = 0.75 * 0.5 * math.pi * m * _series((_K_TERMS - _E_TERMS)[1:], m)
    with np.errstate(divide="ignore"):
        direct = 0.75 * (special.ellipkm1(b * b) - special.ellipe(m))
    return _scalar(np.where(small, series, direct), b)


def hertz_torque_slope(b):
    """dT*/db = -(8/pi) b^2 E(m), eq. (E1)."""
    b, m = _parameter(b)
    return _scalar(-(8.0 / math.pi) * b * b * special.ellipe(m), b)


def punch_rotation(b):
    """Omega(b) = K(m) / 4, eq. (E2), for 0 < b <= 1 (pi/8 at b = 1)."""
    b, m = _parameter(b)
    with np.errstate(divide="ignore"):
        return _scalar(0.25 * special.ellipkm1(b * b), b)


def punch_torque_slope(b):
    """dT*/db = -(8/(3 pi)) b^2 (E - b^2 K) / m, eq. (E2) (series below m = 1/4; -2/3 at b = 1)."""
    b, m = _parameter(b)
    small = m < _SERIES_M
    # E - (1 - m) K = (pi/2) sum_k (e_k - k_k + k_(k-1)) m^k; the k = 0 term vanishes
    combined = _E_TERMS - _K_TERMS + np.concatenate([[0.0], _K_TERMS[:-1]])
    series = 0.5 * math.pi * _series(combined[1:], m)
    with np.errstate(divide="ignore", invalid="ignore"):
        direct = (special.ellipe(m) - b * b * special.ellipkm1(b * b)) / m
    return _scalar(-(8.0 / (3.0 * math.pi)) * b * b * np.where(small, series, direct), b)
