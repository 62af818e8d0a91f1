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

Methods
-------
* ``fast`` (default): the Abel-Fredholm solution of ``fast`` (T*, omega to ~1e-14,
  interface traction and slip to ~1e-12, about 1 ms per stick radius).  Interface
  values (z = 0) are the method's own; fields at z > 0 are summed from Dini amplitudes
  computed from its traction, with as many terms as the smallest requested z > 0 and
  the tolerance need (at most ``MAX_FIELD_TERMS``; beyond that a TruncationWarning).
  sigma_rt(r, 0) is u'(r) - u/r of the interface displacement by second-order
  differences (~1e-9; ~1e-5 within 1e-4 of r = 1, where the corner of the cylinder
  makes u less smooth; exactly 0 at r = 1, eq. 9).
* ``complete`` / ``published``: the weak forms of ``formulations`` at ``n_terms``.

Inverse problem
---------------
``solve(torque=T)`` finds b with T*(b) = |T| by Brent's method; T*(b) decreases
monotonically from 4/3 (b = 0) to 1 (b = 1).  For the series methods the bracket is
[b_lo, 1], b_lo the smallest stick disc the N terms resolve; a torque above T*_N(b_lo)
raises a ResolutionWarning and is bracketed down to b = 1e-6.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from . import fields, validation
from .fast import MAX_NODES, FastSolution, default_nodes, solve_fast
from .formulations import GROSS_SLIP_TORQUE, SeriesSolution, resolution_limit, solve_series
from .formulations import METHODS as SERIES_METHODS
from .warnings import ResolutionWarning, TruncationWarning
from .zeros import bessel_j2_zeros

__all__ = ["Solution", "solve", "METHODS", "DEFAULT_METHOD", "DEFAULT_N_TERMS", "MAX_FIELD_TERMS", "torque_curve"]

#: Every method ``solve`` accepts; the first is the default.
METHODS = ("fast",) + SERIES_METHODS
DEFAULT_METHOD = "fast"
#: The paper's truncation (section 4), the default of the series methods.
DEFAULT_N_TERMS = 145
#: Largest number of Dini terms the fast method sums for fields at z > 0 (the
#: amplitudes cost ~N^2: 2.6 s at 4096 terms).
MAX_FIELD_TERMS = 4096
_MIN_FIELD_TERMS = 64
#: Step of the central differences for sigma_rt(r, 0) of the fast method.
_DIFF_STEP = 1e-5
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
    n_terms : int or None
        Series methods: the N of the weak form.  ``fast``: the number of Dini terms for
        fields at z > 0 if given, else None (chosen per call from z and ``tolerance``).
    series : SeriesSolution or None
        The weak-form coefficients for positive torque (series methods).
    fast : FastSolution or None
        The Abel-Fredholm solution for positive torque (``fast``).
    tolerance : float
        Absolute accuracy asked of the off-interface fields (units f p0, f p0 a / mu).
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    regime: str
    method: str
    n_terms: int | None
    series: SeriesSolution | None = field(default=None, repr=False)
    fast: FastSolution | None = field(default=None, repr=False)
    tolerance: float = field(default=fields.DEFAULT_TOLERANCE, repr=False)
    _dini_cache: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def sign(self) -> float:
        return -1.0 if self.torque < 0 else 1.0

    @property
    def _bilateral(self) -> bool:
        """Stick, or a slip annulus below resolution (fields: the bilateral ones, traction capped at 1)."""
        return self.regime == "stick" or (self.regime == "partial-slip" and self.fast is None and self.series is None)

    # -- the Dini representation used off the interface --------------------------------
    def field_terms(self, z_min: float) -> int:
        """Dini terms the fast method sums for fields at z >= z_min > 0 (see module docstring)."""
        if self.n_terms is not None:
            return self.n_terms
        decades = math.log(1.0 / min(self.tolerance, 1.0)) if self.tolerance > 0 else math.inf
        needed = decades / (math.pi * z_min) + 1.0
        if needed > MAX_FIELD_TERMS:
            z_ok = decades / (math.pi * MAX_FIELD_TERMS)
            warnings.warn(
                f"fields at z < {z_ok:.2g} (asked down to z = {z_min:.2g}) are summed with "
                f"{MAX_FIELD_TERMS} Dini terms, short of tolerance={self.tolerance:g}: the omitted tail "
                f"is up to ~exp(-lambda_N z) = {math.exp(-math.pi * MAX_FIELD_TERMS * z_min):.1e} times the "
                "interface amplitude; the interface values (z = 0) are exact",
                TruncationWarning,
                stacklevel=3,
            )
            return MAX_FIELD_TERMS
        return max(_MIN_FIELD_TERMS, 1 << math.ceil(math.log2(needed)))  # powers of 2: cache hits

    def dini_series(self, n_terms: int) -> SeriesSolution:
        """The fast solution's Dini amplitudes c_n, n <= n_terms, as a SeriesSolution (cached)."""
        if self.series is not None:
            return self.series
        if n_terms not in self._dini_cache:
            fs = self.fast
            self._dini_cache[n_terms] = SeriesSolution(
                "fast", fs.stick_radius, fs.torque, fs.rigid_rotation, bessel_j2_zeros(n_terms),
                fs.dini_amplitudes(n_terms), 1.0)
        return self._dini_cache[n_terms]

    def _sum(self, order, weights_power, r, z):
        """sign * sum c_n lam_n^p exp(-lam_n z) J_order(lam_n r) over the points with z > 0 or all."""
        positive = z[z > 0]
        n = self.field_terms(float(positive.min())) if (self.fast is not None and positive.size) else None
        series = self.dini_series(n) if self.fast is not None else self.series
        lam = series.eigenvalues
        return self.sign * fields.series_sum(order, lam, series.amplitudes * lam**weights_power, r, z,
                                             self.tolerance)

    # -- interface ----------------------------------------------------------------------
    def traction(self, r):
        """Interface shear traction sigma_zt(r, 0) / (f p0), eq. (8), (26)."""
        r = validation.coordinates(r)
        if self._bilateral:
            return np.clip(self.torque * r, -1.0, 1.0).astype(float)
        if self.fast is not None:
            return self.sign * self.fast.interface_traction(r)
        return self.sign * self.series.torque * r - self._sum(1, 1, r, np.zeros_like(r))

    def slip(self, r):
        """Slip s(r) = 2 u_theta(r, 0+) in f p0 a / mu (0 on the stick disc up to the method's error)."""
        r = validation.coordinates(r)
        if self._bilateral:
            return np.zeros_like(r)
        return 2.0 * self._interface_displacement(r)

    def _interface_displacement(self, r):
        if self.regime == "gross-slip":
            return np.where(r > 0, self.sign * math.inf, 0.0)
        if self.fast is not None:
            return self.sign * self.fast.interface_displacement(r)
        rigid = 0.0 if self.method == "published" else self.series.rigid_rotation
        return self.sign * rigid * r + self._sum(1, 0, r, np.zeros_like(r))

    def _interface_sigma_rt(self, r):
        """sigma_rt(r, 0) = du/dr - u/r from the fast interface displacement (0 on the stick disc)."""
        out = np.zeros_like(r)
        b = self.stick_radius
        slipping = r > b
        x = r[slipping]
        if x.size:
            h = min(_DIFF_STEP, 0.25 * (1.0 - b))
            u = self.fast.interface_displacement
            ux = u(x)
            # central differences inside, second-order one-sided ones within h of r = b or r = 1
            derivative = np.empty_like(x)
            central = (x - h >= b) & (x + h <= 1.0)
            forward = (x - h < b) & ~central
            backward = ~central & ~forward
            xc, xf, xb = x[central], x[forward], x[backward]
            derivative[central] = (u(xc + h) - u(xc - h)) / (2 * h)
            derivative[forward] = (-3 * ux[forward] + 4 * u(xf + h) - u(xf + 2 * h)) / (2 * h)
            derivative[backward] = (3 * ux[backward] - 4 * u(xb - h) + u(xb - 2 * h)) / (2 * h)
            out[slipping] = self.sign * (derivative - ux / x)
        out[r == 1.0] = 0.0  # the lateral surface is traction free, eq. (9), exactly
        return out

    # -- fields anywhere -------------------------------------------------------------------
    def stress(self, r, z):
        """(sigma_zt, sigma_rt) / (f p0) at (r, z), z >= 0; eqs. (2), (3), (23), (24)."""
        r, z = validation.coordinates(r, z)
        r, z = np.broadcast_arrays(r, z)
        if self._bilateral:
            return (self.torque * r).astype(float), np.zeros(r.shape)
        torque = self.sign * (self.fast.torque if self.fast is not None else self.series.torque)
        sigma_zt = np.empty(r.shape)
        sigma_rt = np.empty(r.shape)
        on_face = (z == 0) if self.fast is not None else np.zeros(r.shape, dtype=bool)
        inside = ~on_face
        if inside.any():
            ri, zi = r[inside], z[inside]
            sigma_zt[inside] = torque * ri - self._sum(1, 1, ri, zi)
            sigma_rt[inside] = -self._sum(2, 1, ri, zi)
        if on_face.any():
            sigma_zt[on_face] = self.traction(r[on_face])
            sigma_rt[on_face] = self._interface_sigma_rt(r[on_face])
        return sigma_zt, sigma_rt

    def displacement(self, r, z):
        """u_theta(r, z) of the upper cylinder in f p0 a / mu, z >= 0; eqs. (4), (22)."""
        r, z = validation.coordinates(r, z)
        r, z = np.broadcast_arrays(r, z)
        if self._bilateral:
            return (self.torque * r * z + self.rigid_rotation * r).astype(float)
        if self.regime == "gross-slip":
            return np.where(r > 0, self.sign * math.inf, 0.0)
        source = self.fast if self.fast is not None else self.series
        rigid = 0.0 if self.method == "published" else source.rigid_rotation
        out = np.empty(r.shape)
        on_face = (z == 0) if self.fast is not None else np.zeros(r.shape, dtype=bool)
        inside = ~on_face
        if inside.any():
            ri, zi = r[inside], z[inside]
            out[inside] = self.sign * (source.torque * ri * zi + rigid * ri) + self._sum(1, 0, ri, zi)
        if on_face.any():
            out[on_face] = self._interface_displacement(r[on_face])
        return out

    def as_dict(self) -> dict:
        """JSON-ready summary (non-finite rigid rotation becomes None)."""
        omega = self.rigid_rotation
        out = {
            "stick_radius": self.stick_radius,
            "torque": self.torque,
            "rigid_rotation": omega if math.isfinite(omega) else None,
            "regime": self.regime,
            "method": self.method,
            "n_terms": self.n_terms,
        }
        if self.fast is not None:
            out["n_nodes"] = self.fast.n_nodes
        return out


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


def _from_fast(fs: FastSolution, sign: float, n_terms: int | None, regime: str) -> Solution:
    return Solution(
        stick_radius=fs.stick_radius,
        torque=sign * fs.torque,
        rigid_rotation=sign * fs.rigid_rotation,
        regime=regime,
        method="fast",
        n_terms=n_terms,
        fast=fs,
    )


def _stick(torque: float, method: str, n_terms: int | None) -> Solution:
    omega = math.nan if method == "published" else 0.0
    return Solution(1.0, torque, omega, "stick", method, n_terms)


@functools.lru_cache(maxsize=1)
def _fast_largest_radius() -> float:
    """Largest stick radius the fast method resolves with at most MAX_NODES nodes (~1 - 1.5e-6)."""
    lo, hi = 0.99, 1.0 - 1e-12
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if default_nodes(mid) <= MAX_NODES else (lo, mid)
    return lo


def _onset_asymptote(target: float, sign: float, n_terms) -> Solution:
    """1 < T* < T*(b_max): a slip annulus narrower than the fast method resolves (< ~1.5e-6).

    From the small-slip asymptotics (``history`` docstring; checked in tests/test_fast.py):
    1 - b = (pi/2)(T* - 1) and omega = (pi^3/12)(T* - 1)^3, both to relative O(T* - 1)
    (< 1e-6 here).  The fields are the bilateral ones with the traction capped at the
    friction limit: off by at most T* - 1 in traction and (T* - 1)^2 in slip.
    """
    excess = target - 1.0
    warnings.warn(
        f"torque={sign * target:.17g} is within {excess:.1e} of slip onset: its slip annulus "
        f"({0.5 * math.pi * excess:.1e} wide) is narrower than the fast method resolves; the stick radius and "
        "rigid rotation come from the small-slip asymptotes and the fields are the bilateral ones capped at the "
        f"friction limit (errors below {excess:.0e} in traction)",
        ResolutionWarning,
        stacklevel=3,
    )
    return Solution(1.0 - 0.5 * math.pi * excess, sign * target, sign * math.pi**3 / 12.0 * excess**3,
                    "partial-slip", "fast", n_terms)


@functools.lru_cache(maxsize=1)
def _fast_torque_table():
    """T*(b) of the fast method on 33 radii: brackets for the inverse problem (once per process)."""
    radii = np.append(np.linspace(0.0, 1.0, 33)[:-1], _fast_largest_radius())
    with warnings.catch_warnings():  # brackets only: T* near the cap is still good to ~1e-12
        warnings.simplefilter("ignore", ResolutionWarning)
        torques = np.array([solve_fast(b).torque for b in radii])
    return radii, torques


def _invert_fast(target: float) -> FastSolution | None:
    """Stick radius b with T*(b) = target, 1 < target < 4/3 (fast method; ~10 solves)."""
    radii, torques = _fast_torque_table()
    if target <= torques[-1]:
        return None  # below the resolution of the fast method: see _onset_asymptote
    upper = int(np.argmax(torques <= target))  # first radius whose torque is below the target
    lower = max(upper - 1, 0)
    with warnings.catch_warnings():  # the probes; the answer below warns for itself
        warnings.simplefilter("ignore", ResolutionWarning)
        b = optimize.brentq(lambda b: solve_fast(b).torque - target, radii[lower], radii[upper],
                            xtol=_B_XTOL, rtol=4 * np.finfo(float).eps)
    return solve_fast(b)


def _invert_series(target: float, method: str, n_terms: int) -> SeriesSolution:
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
    method : {"fast", "complete", "published"}, optional
        ``fast`` (default): the Abel-Fredholm method of ``fast`` (the most accurate);
        ``published``: eq. (38) exactly as printed; ``complete``: the same weak form
        with the missing rigid-rotation mode.
    n_terms : int, optional
        Series methods: number of eigenfunctions, >= 1 (default 145, the paper's).
        ``fast``: number of Dini terms for fields at z > 0 (default: chosen per call).

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
    if n_terms is not None or method != "fast":
        n_terms = validation.positive_int("n_terms", DEFAULT_N_TERMS if n_terms is None else n_terms)
    if (stick_radius is None) == (torque is None):
        raise ValueError("give exactly one of stick_radius (in [0, 1]) and torque (in [-4/3, 4/3])")
    if stick_radius is not None:
        b = validation.real_number("stick_radius", stick_radius, 0.0, 1.0)
        if b == 1.0:
            return _stick(1.0, method, n_terms)
        regime = "gross-slip" if b == 0.0 else "partial-slip"
        if method == "fast":
            return _from_fast(solve_fast(b), 1.0, n_terms, regime)
        return _from_series(solve_series(b, method, n_terms), 1.0, n_terms, regime)

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
        if method == "fast":
            return _from_fast(solve_fast(0.0), sign, n_terms, "gross-slip")
        return _from_series(solve_series(0.0, method, n_terms), sign, n_terms, "gross-slip")
    if method == "fast":
        fs = _invert_fast(magnitude)
        if fs is None:
            return _onset_asymptote(magnitude, sign, n_terms)
        solution = _from_fast(fs, sign, n_terms, "partial-slip")
    else:
        solution = _from_series(_invert_series(magnitude, method, n_terms), sign, n_terms, "partial-slip")
    # Report the torque asked for; the fields use the solution's own T*(b), which
    # differs from it by the root-finding tolerance (about 1e-12 or less).
    return dataclasses.replace(solution, torque=t)


def torque_curve(stick_radii, *, method=None, n_terms=None) -> np.ndarray:
    """T*(b) for an array of stick radii (Fig. 3), one solve per radius."""
    radii = np.asarray(stick_radii, dtype=float)
    torques = [solve(stick_radius=float(b), method=method, n_terms=n_terms).torque for b in radii.ravel()]
    return np.array(torques).reshape(radii.shape)
