"""The public ``solve`` function: regimes, the inverse problem T* -> b, and fields.

Units and sign conventions follow CONTRACT.md: r, z in a; T* = 2T/(f F a); tractions
and stresses in f p0; displacements and slip in f p0 a / mu; omega in f p0 / mu.

Regimes
-------
* ``stick``: |T*| <= 1.  b = 1, the bilateral field (eqs. 2-4) is exact, omega = 0.
* ``partial-slip``: 1 < |T*| < 4/3.  Stick disc 0 <= r < b, slip annulus b < r <= 1.
* ``gross-slip``: |T*| = 4/3.  b = 0, traction f p0 everywhere (spinning); the
  stresses are finite but the relative rotation is unbounded (omega ~ ln(1/b)/2 as
  b -> 0), so ``rigid_rotation``, ``slip`` and ``displacement`` are infinite there.

Negative torque mirrors positive torque: T*, omega, tractions, stresses, slip and
displacements change sign, b does not.

Inverse problem
---------------
``solve(torque=T)`` finds b with T*_N(b) = |T| by Brent's method on [b_lo, 1], where
T*_N(b) (the series solution of ``formulations`` at N terms) decreases monotonically
from T*_N(b_lo) to T*_N(1) = 1.  b_lo is the smallest stick disc the N terms
resolve; a torque above T*_N(b_lo) has a stick disc too small to resolve and raises
a ResolutionWarning, returning b = b_lo's neighbourhood found by bisection on a
finer bracket (down to 1e-6).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from . import fields, validation
from .formulations import GROSS_SLIP_TORQUE, METHODS, SeriesSolution, resolution_limit, solve_series
from .warnings import ResolutionWarning

__all__ = ["Solution", "solve", "DEFAULT_METHOD", "DEFAULT_N_TERMS", "torque_curve"]

DEFAULT_METHOD = "complete"
#: The paper's truncation (section 4).
DEFAULT_N_TERMS = 145
#: Relative tolerance on |T*| - 4/3 and |T*| - 1 that still counts as the limit.
_LIMIT_TOL = 4 * np.finfo(float).eps
#: Accuracy of b in the inverse problem.
_B_XTOL = 1e-14


@dataclass(frozen=True)
class Solution:
    """State of the interface and the fields for one torque (see module docstring).

    Attributes
    ----------
    stick_radius : float
        b/a in [0, 1].
    torque : float
        T* = 2T/(f F a), signed.
    rigid_rotation : float
        omega in f p0 / mu, signed; 0 in stick, +-inf at gross slip, nan for the
        ``published`` formulation (it has no such unknown).
    regime : str
        "stick", "partial-slip" or "gross-slip".
    method : str
    n_terms : int
    series : SeriesSolution or None
        The coefficients for positive torque (None in the stick regime).
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    regime: str
    method: str
    n_terms: int
    series: SeriesSolution | None = field(default=None, repr=False)
    tolerance: float = field(default=fields.DEFAULT_TOLERANCE, repr=False)

    @property
    def sign(self) -> float:
        return -1.0 if self.torque < 0 else 1.0

    def _sum(self, order, weights, r, z):
        s = self.series
        return fields.series_sum(order, s.eigenvalues, s.amplitudes * weights, r, z, self.tolerance)

    def traction(self, r):
        """Interface shear traction sigma_zt(r, 0) / (f p0), eq. (8), (26)."""
        r = validation.coordinates(r)
        if self.regime == "stick":
            return (self.torque * r).astype(float)
        lam = self.series.eigenvalues
        return self.sign * (self.series.torque * r - self._sum(1, lam, r, 0.0))

    def slip(self, r):
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu (0 on the stick disc up to the series error)."""
        r = validation.coordinates(r)
        if self.regime == "stick":
            return np.zeros_like(r)
        return 2.0 * self._interface_displacement(r)

    def _interface_displacement(self, r):
        if self.regime == "gross-slip":
            return np.where(r > 0, self.sign * math.inf, 0.0)
        s = self.series
        rigid = 0.0 if self.method == "published" else s.rigid_rotation
        return self.sign * (rigid * r + self._sum(1, 1.0, r, 0.0))

    def stress(self, r, z):
        """(sigma_zt, sigma_rt) / (f p0) at (r, z), z >= 0; eqs. (2), (3), (23), (24)."""
        r, z = validation.coordinates(r, z)
        r, z = np.broadcast_arrays(r, z)
        if self.regime == "stick":
            return (self.torque * r).astype(float), np.zeros(r.shape)
        lam = self.series.eigenvalues
        sigma_zt = self.sign * self.series.torque * r - self.sign * self._sum(1, lam, r, z)
        sigma_rt = -self.sign * self._sum(2, lam, r, z)
        return sigma_zt, sigma_rt

    def displacement(self, r, z):
        """u_theta(r, z) of the upper cylinder in f p0 a / mu, z >= 0; eqs. (4), (22)."""
        r, z = validation.coordinates(r, z)
        r, z = np.broadcast_arrays(r, z)
        if self.regime == "stick":
            return (self.torque * r * z).astype(float)
        if self.regime == "gross-slip":
            return np.where(r > 0, self.sign * math.inf, 0.0)
        s = self.series
        rigid = 0.0 if self.method == "published" else s.rigid_rotation
        uniform = self.sign * s.torque * r * z
        return uniform + self.sign * (rigid * r + self._sum(1, 1.0, r, z))

    def as_dict(self) -> dict:
        """JSON-ready summary (non-finite rigid rotation becomes None)."""
        omega = self.rigid_rotation
        return {
            "stick_radius": self.stick_radius,
            "torque": self.torque,
            "rigid_rotation": omega if math.isfinite(omega) else None,
            "regime": self.regime,
            "method": self.method,
            "n_terms": self.n_terms,
        }


def _from_series(series: SeriesSolution, sign: float, n_terms: int, regime: str) -> Solution:
    return Solution(
        stick_radius=series.stick_radius,
        torque=sign * series.torque,
        rigid_rotation=sign * series.rigid_rotation,
        regime=regime,
        method=series.method,
        n_terms=n_terms,
        series=series,
    )


def _stick(torque: float, method: str, n_terms: int) -> Solution:
    omega = math.nan if method == "published" else 0.0
    return Solution(1.0, torque, omega, "stick", method, n_terms, None)


def _invert(target: float, method: str, n_terms: int) -> SeriesSolution:
    """Stick radius b with T*_N(b) = target for 1 < target < 4/3."""
    b_lo, _ = resolution_limit(n_terms)

    def residual(b):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResolutionWarning)
            warnings.simplefilter("ignore", RuntimeWarning)
            return solve_series(b, method, n_terms).torque - target

    lower = b_lo
    if residual(lower) < 0:
        # Resolve downward: the torque needs a stick disc smaller than N terms resolve.
        lower = 1e-6
        if residual(lower) < 0:
            raise ValueError(
                f"torque={target:.17g} is within {GROSS_SLIP_TORQUE - target:.2e} of spinning "
                f"(4/3): its stick disc is below b = 1e-6, beyond what n_terms={n_terms} resolves"
            )
        warnings.warn(
            f"torque={target:.12g} needs a stick disc smaller than n_terms={n_terms} resolves "
            f"(b < {b_lo:.3g}); the stick radius and fields are inaccurate",
            ResolutionWarning,
            stacklevel=3,
        )
    b = optimize.brentq(residual, lower, 1.0, xtol=_B_XTOL, rtol=4 * np.finfo(float).eps)
    if lower == b_lo:  # otherwise the warning above has been given
        return solve_series(b, method, n_terms)  # warns if the slip annulus is unresolved
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        return solve_series(b, method, n_terms)


def solve(stick_radius=None, torque=None, *, method=None, n_terms=None) -> Solution:
    """Solve the partial-slip torsion problem for a stick radius or a torque.

    Parameters
    ----------
    stick_radius : float, optional
        b/a in [0, 1] (1: the whole face sticks, T* = 1; 0: spinning, T* = 4/3).
        Gives a positive torque.
    torque : float, optional
        T* = 2T/(f F a) in [-4/3, 4/3].  Exactly one of ``stick_radius`` and
        ``torque`` must be given.
    method : {"complete", "published"}, optional
        ``published``: eq. (38) exactly as printed; ``complete``: the same weak form
        with the missing rigid-rotation mode.  Default: the most accurate method
        available (currently ``complete``).
    n_terms : int, optional
        Number of eigenfunctions, >= 1 (default 145, the paper's).

    Returns
    -------
    Solution

    Raises
    ------
    ValueError
        Naming the argument and its valid range, for non-finite or out-of-range
        numbers, |torque| > 4/3 (the cylinders spin: no static solution), both or
        neither of stick_radius/torque, n_terms < 1, or an unknown method.
    """
    method = validation.choice("method", DEFAULT_METHOD if method is None else method, METHODS)
    n_terms = validation.positive_int("n_terms", DEFAULT_N_TERMS if n_terms is None else n_terms)
    if (stick_radius is None) == (torque is None):
        raise ValueError("give exactly one of stick_radius (in [0, 1]) and torque (in [-4/3, 4/3])")
    if stick_radius is not None:
        b = validation.real_number("stick_radius", stick_radius, 0.0, 1.0)
        if b == 1.0:
            return _stick(1.0, method, n_terms)
        series = solve_series(b, method, n_terms)
        regime = "gross-slip" if b == 0.0 else "partial-slip"
        return _from_series(series, 1.0, n_terms, regime)

    t = validation.real_number("torque", torque)
    magnitude = abs(t)
    if magnitude > GROSS_SLIP_TORQUE * (1 + _LIMIT_TOL):
        raise ValueError(
            f"torque must lie in [-4/3, 4/3], got {t!r}: above 4/3 the cylinders spin "
            "(gross slip), there is no static solution"
        )
    sign = -1.0 if t < 0 else 1.0
    if magnitude <= 1.0:
        return _stick(t, method, n_terms)
    if magnitude >= GROSS_SLIP_TORQUE * (1 - _LIMIT_TOL):
        return _from_series(solve_series(0.0, method, n_terms), sign, n_terms, "gross-slip")
    solution = _from_series(_invert(magnitude, method, n_terms), sign, n_terms, "partial-slip")
    # Report the torque asked for; the fields use the series' own T*_N(b), which
    # differs from it by the root-finding tolerance (about 1e-12).
    return dataclasses.replace(solution, torque=t)


def torque_curve(stick_radii, *, method=None, n_terms=None) -> np.ndarray:
    """T*(b) for an array of stick radii (Fig. 3), one series solve per radius."""
    radii = np.asarray(stick_radii, dtype=float)
    torques = [solve(stick_radius=float(b), method=method, n_terms=n_terms).torque for b in radii.ravel()]
    return np.array(torques).reshape(radii.shape)
