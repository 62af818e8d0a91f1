r"""Friction coefficient and shear modulus from a measured torque-twist loop.

Units: torque N m, twist rad, radius m, normal force N, modulus Pa (SI floats or quantities,
converted by ``units``).

The model
---------
Between two cross-sections a rig measures (``specimen``; the shaft's uniform twist and the
rig's compliance are one linear term, since neither can be told apart from a loop)

    theta(t) = theta_0 + C T(t) + k omega(T*(t); history),   k = 2 f p0 / G,  T* = T / T_s,

with T_s = f F a / 2 the slip-onset torque, p0 = F / (pi a^2), omega the contact's rigid
rotation along the history by the memory rules, C the compliance (rad / (N m)) and theta_0 the
arbitrary zero of the twist (a parameter: the virgin state sits at an unknown twist).
Parameters: T_s (hence f = 2 T_s / (F a)), k (hence G = 4 T_s / (pi a^3 k)), C, theta_0, and the
twist at every reversal of the loop.  The record must start from the virgin interface (first
loading included) and the torque channel must read zero at zero torque.

The residual
------------
Both channels are noisy.  The model is written the way it is always defined: the torque as a
function of the twist along the branches (``fitting.masing``), which saturates at the
gross-slip torque 2 f F a / 3 instead of running off to an infinite rotation.  The residual of
sample i is the effective-variance residual (Orear's method, the first-order form of
orthogonal distance regression):

    r_i = (T_i - T_model(theta_i)) / sqrt(s_T^2 + (dT/dtheta)_i^2 s_theta^2),

a torque residual where the loop is flat (a gross-slip plateau, dT/dtheta = 0: there the
twist says nothing and the plateau torque fixes f directly) and, in effect, a twist residual
where it is steep (stick: (T_i - T_model) / (dT/dtheta) is the twist residual).  No sample is
dropped and none is classified by hand.  s_T and s_theta are the channels' noise levels
(given, or estimated by ``fitting.samples.noise_level``); the overall scale is then estimated
from the residuals (the covariance is multiplied by the reduced chi-square).

The reversals
-------------
The twist at each reversal is a parameter: the memory rules start every branch at its
reversal, and the extreme sample is a noisy and biased (by about 1.5 noise levels) stand-in
for the true turning point.  Their uncertainty enters the intervals of f, G and C through the
joint covariance.

Fitting and intervals
---------------------
``scipy.optimize.least_squares`` (trust region reflective, bounds T_s, k, C > 0) from
starting values on a grid (T_s from 0.75 to 1.3 times the largest torque, kappa = k / (C T_s)
from 1e-3 to 30), C and theta_0 from the stick fit; the Jacobian by finite differences.
lmfit would add named parameters and the same covariance, nothing the problem needs.  The
covariance is s^2 (J^T J)^-1 (pseudo-inverse: a reversal in stick has no influence) and the
95 % intervals are Wald intervals with Student's t on N - P degrees of freedom: on T_s (f), on
C, and on 1/G (linear in k, the quantity the loop measures) mapped to G, whose upper end is
infinite when the interval on 1/G reaches 0.

Limits
------
The effective-variance residual is exact to first order in the noise.  Its second-order term
is a bias of about (1/2) (s / w) s per sample, where s is the twist noise (the torque noise
counted through C) and w the scale on which the loop bends: the contact's twist amplitude
k omega(max T*), or k omega(4/3 - 1e-3) = 0.9 k for a gross-slip loop (its knee).  Over the N_b
samples where the loop bends (slope between 2 % and 98 % of the elastic one) that is about
(1/2)(s / w) sqrt(N_b) standard errors.  When it
exceeds ``NOISE_LIMIT`` (one standard error) the estimates are biased and the intervals too
narrow (the coverage study shows by how much): the result is flagged ``noise_limited`` and a
``NoiseLimitedFitWarning`` is raised.  Gross-slip loops, whose contact twist is large, are not
affected; partial-slip loops need a twist resolution well below the contact's twist.

Identifiability
---------------
A loop whose every torque stays below the slip onset has no hysteresis: the twist is linear
in the torque and only C, theta_0 are defined.  The fit compares the full model with the
linear one (stick): when the decrease of the residual sum, in units of the residual variance,
is below the 95 % point of chi-square with 2 degrees of freedom (5.99), the loop shows no slip
and the result gives no friction value, only the bound f >= 2 max|T| / (F a) that full stick
implies (``lower_bound``), and no modulus.  A slip too small to detect is not excluded by the
record, so the ``interval`` of f is the weaker bound that holds whatever G: the torque never
exceeded the gross-slip torque, f >= 1.5 (max|T| - 2 s_T) / (F a).  With slip, G is reported
only when its interval excludes infinity (the contact's twist k is resolved from zero);
otherwise only its lower bound.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize, stats

from .. import units
from ..criteria import GROSS_SLIP_TORQUE
from ..curves import monotonic_curves
from ..diagnostics import NoiseLimitedFitWarning
from .masing import torque_along, walk
from .samples import checked_loop, noise_level, reversal_threshold, turning_points
from .skeleton import Skeleton

__all__ = ["Estimate", "LoopFit", "fit_loop", "STICK_TEST_QUANTILE"]

#: 95 % point of chi-square with 2 degrees of freedom: the slip test (full model against stick).
STICK_TEST_QUANTILE = float(stats.chi2.ppf(0.95, 2))
#: Largest kappa = k / (C T_s): C holds at least the shaft over the gauge length L, L / (G J), so kappa <= 2 a / L,
#: and the twist formula needs sections about 2 a or more from the interface (L >= 4 a, kappa <= 0.5); 2 leaves room.
KAPPA_MAX = 2.0
#: Evaluations per least-squares pass: enough for any loop with slip (about 10-20 are used); a loop in stick,
#: where T_s and kappa are free to wander, stops here (the stick test then errs towards "no slip").
MAX_EVALUATIONS = 60
#: The starting grid: T_s / max|T| (0.75: a gross-slip plateau) and kappa.
START_RATIOS = (0.75, 0.8, 0.87, 0.95, 1.05)
START_KAPPAS = (0.02, 0.2, 1.0)
#: The bend of a gross-slip loop: its knee ends where omega_m = 0.9 (T* = 4/3 - 1e-3), beyond it lies the plateau.
KNEE_TORQUE = GROSS_SLIP_TORQUE - 1e-3
#: Largest expected second-order bias (in standard errors) of an estimate that is not flagged as noise limited.
NOISE_LIMIT = 1.0
#: Samples whose slope dT/dtheta is at least this fraction of the elastic 1/C count in ``residual_rms``.
PLATEAU_SLOPE = 0.5


@dataclass(frozen=True)
class Estimate:
    """A fitted quantity: ``value``, ``stderr``, ``interval`` (lower, upper; None: unbounded or undefined)."""

    value: float | None
    stderr: float | None
    interval: tuple[float | None, float | None]
    identified: bool = True
    lower_bound: float | None = None

    def as_dict(self) -> dict:
        out = {"value": _json(self.value), "stderr": _json(self.stderr),
               "interval": [_json(self.interval[0]), _json(self.interval[1])], "identified": self.identified}
        if self.lower_bound is not None:
            out["lower_bound"] = _json(self.lower_bound)
        return out


def _json(x):
    return None if x is None or not math.isfinite(x) else float(x)


@dataclass(frozen=True)
class LoopFit:
    """Result of ``fit_loop`` (module docstring).  ``friction`` is None-valued when the loop never slipped.

    Attributes
    ----------
    friction, shear_modulus (Pa), compliance (rad / (N m)), twist_offset (rad) : Estimate
    correlation : float or None
        Correlation of the friction and modulus estimates (None unless both are identified).
    residual_rms : float
        RMS twist residual (rad) off the gross-slip plateaus, (T_i - T_model) / (dT/dtheta).
    torque_residual_rms : float
        RMS torque residual (N m) over every sample.
    noise : dict
        The noise levels used (``torque`` N m, ``twist`` rad) and whether they were ``estimated``.
    noise_scale : float
        sqrt(reduced chi-square): 1 when the residuals match the noise levels.
    regime : str
        "stick", "partial-slip" or "gross-slip": the largest |T*| the fitted loop reaches.
    slip_detected : bool
    stick_test : float
    noise_limited : bool
        The twist noise is too large against the contact's twist for the intervals to be trusted
        (module docstring, "Limits"); a ``NoiseLimitedFitWarning`` was raised.
        Decrease of the residual sum from stick to the full model, in residual variances.
    message : str
    samples, reversals, dof : int
    fitted_torque : ndarray
        The model's torque at every sample (N m).
    """

    friction: Estimate
    shear_modulus: Estimate
    compliance: Estimate
    twist_offset: Estimate
    correlation: float | None
    residual_rms: float
    torque_residual_rms: float
    noise: dict
    noise_scale: float
    regime: str
    slip_detected: bool
    stick_test: float
    noise_limited: bool
    message: str
    samples: int
    reversals: int
    dof: int
    radius: float
    normal_force: float
    fitted_torque: np.ndarray = field(repr=False)

    def as_dict(self) -> dict:
        """JSON-ready (non-finite numbers -> None); ``fitted_torque`` is left out."""
        return {
            "friction": self.friction.as_dict(),
            "shear_modulus": self.shear_modulus.as_dict(),
            "compliance": self.compliance.as_dict(),
            "twist_offset": self.twist_offset.as_dict(),
            "correlation": _json(self.correlation),
            "residual_rms": _json(self.residual_rms),
            "torque_residual_rms": _json(self.torque_residual_rms),
            "noise": {k: (_json(v) if isinstance(v, float) else v) for k, v in self.noise.items()},
            "noise_scale": _json(self.noise_scale),
            "regime": self.regime,
            "slip_detected": self.slip_detected,
            "stick_test": _json(self.stick_test),
            "noise_limited": self.noise_limited,
            "message": self.message,
            "samples": self.samples,
            "reversals": self.reversals,
            "dof": self.dof,
            "radius": self.radius,
            "normal_force": self.normal_force,
            "units": {"shear_modulus": "Pa", "compliance": "rad/(N m)", "twist_offset": "rad", "residual_rms": "rad",
                      "torque_residual_rms": "N m", "radius": "m", "normal_force": "N",
                      "noise": {"torque": "N m", "twist": "rad"}},
        }


class _Model:
    """The torque at every sample for a parameter vector [T_s, kappa, C, theta_0, U_1..U_M] (module docstring)."""

    def __init__(self, torque, twist, reversal_index, torque_noise, twist_noise):
        self.torque, self.twist = torque, twist
        self.reversals = reversal_index
        self.segment = np.searchsorted(reversal_index, np.arange(twist.size), side="left")
        last = self.segment == reversal_index.size
        heading = np.sign(twist[-1] - (twist[reversal_index[-1]] if reversal_index.size else twist[0])) or 1.0
        self.end = float(twist[last].max() if heading > 0 else twist[last].min())
        self.torque_noise, self.twist_noise = torque_noise, twist_noise
        self._cache = (None, None)

    def evaluate(self, p, jacobian: bool = False):
        """(torque, slope dT/dtheta, turning-point torques[, jacobian]) at every sample."""
        key = (tuple(p), jacobian)
        if self._cache[0] == key:
            return self._cache[1]
        slip_torque, kappa, compliance, offset = p[:4]
        skeleton = Skeleton(kappa)
        scale = compliance * slip_torque

        def branch(v):
            x = v / scale
            if not jacobian:
                t, slope = skeleton(x)
                return slip_torque * t, slope / compliance
            t, slope, omega = skeleton(x, rotation=True)
            with np.errstate(invalid="ignore"):
                d_kappa = np.where(slope > 0, -slip_torque * omega * slope, 0.0)
            grad = np.column_stack([t - slope * x, d_kappa, -slip_torque * slope * x / compliance])
            return slip_torque * t, slope / compliance, grad

        targets = np.append(p[4:], self.end) - offset
        out = torque_along(walk(targets), self.twist - offset, self.segment, branch, jacobian)
        self._cache = (key, out)
        return out

    def weights(self, p):
        """1 / sqrt(s_T^2 + (dT/dtheta)^2 s_theta^2): the effective-variance weights at ``p``."""
        slope = self.evaluate(p)[1]
        with np.errstate(over="ignore"):  # a trial C -> 0 makes the slope overflow: weight 0
            return 1.0 / np.sqrt(self.torque_noise**2 + (slope * self.twist_noise) ** 2)

    def linear_weights(self, compliance):
        return np.full(self.torque.size, 1.0 / math.sqrt(self.torque_noise**2 + (self.twist_noise / compliance) ** 2))


def _least_squares(model: _Model, start, lower, upper, passes: int = 3, stop=None):
    """Effective-variance least squares: weights fixed per pass, updated from the solution (IRLS).

    ``stop(result)``: end after a pass for which it is true (a loop plainly in stick).
    """
    p = np.asarray(start, dtype=float)
    result = None
    for _ in range(passes):
        w = model.weights(p)

        def fun(q, w=w):
            return w * (model.torque - model.evaluate(q, jacobian=True)[0])

        def jac(q, w=w):
            return -w[:, None] * model.evaluate(q, jacobian=True)[3]

        result = optimize.least_squares(fun, np.clip(p, lower, upper), jac=jac, bounds=(lower, upper),
                                        x_scale="jac", method="trf", max_nfev=MAX_EVALUATIONS)
        with np.errstate(over="ignore", divide="ignore"):
            change = np.max(np.abs(result.x - p) / np.maximum(np.sqrt(np.diag(_covariance(result.jac, 1.0))), 1e-300))
        p = result.x
        # settled: the parameters moved by less than 0.05 standard errors, or the caller's verdict is plain
        if change < 0.05 or (stop is not None and stop(result)):
            break
    return result


def _linear_least_squares(model: _Model):
    """Stick: theta = theta_0 + C T, the same effective-variance residuals (Deming regression)."""
    torque, twist, s_t, s_theta = model.torque, model.twist, model.torque_noise, model.twist_noise

    def fun(q):
        return (torque - (twist - q[1]) / q[0]) / np.sqrt(s_t**2 + (s_theta / q[0]) ** 2)

    slope, intercept = np.polyfit(torque, twist, 1)
    slope = slope if slope > 0 else float(np.ptp(twist) / np.ptp(torque))
    return optimize.least_squares(fun, [slope, intercept], bounds=([slope * 1e-6, -np.inf], [np.inf, np.inf]),
                                  x_scale="jac")


def _covariance(jacobian: np.ndarray, scale2: float) -> np.ndarray:
    u, s, vt = np.linalg.svd(jacobian, full_matrices=False)
    keep = s > s[0] * 1e-10 * math.sqrt(jacobian.shape[0])
    inverse = (vt[keep].T / s[keep] ** 2) @ vt[keep]
    return scale2 * inverse


def _wald(value, stderr, t):
    return (value - t * stderr, value + t * stderr)


def fit_loop(torque, twist, *, radius, normal_force, torque_noise=None, twist_noise=None,
             confidence: float = 0.95) -> LoopFit:
    """Fit f, G and the compliance to a measured torque-twist loop (module docstring).

    Parameters
    ----------
    torque, twist : array_like
        Samples in time order, from the virgin interface: torque in N m, twist in rad
        (numbers in SI, or pint quantity arrays).
    radius, normal_force :
        Cylinder radius a (m) and normal force F (N): floats in SI, quantities or strings ("5 mm").
    torque_noise, twist_noise : optional
        Standard deviations of the measurement noise (N m, rad); estimated from the data by default.
    confidence : float
        Level of the intervals (default 0.95).

    Returns
    -------
    LoopFit

    Raises
    ------
    ValueError
        Naming the argument: arrays of different lengths, fewer than ``samples.MIN_SAMPLES``
        samples, a non-finite sample (by index), a constant channel, a bad radius, force,
        noise level or confidence.
    """
    a = units.positive_si("radius", radius, "length")
    force = units.positive_si("normal_force", normal_force, "force")
    torque, twist = checked_loop(units.si_array("torque", torque, "torque"), units.si_array("twist", twist, "angle"))
    if not 0 < confidence < 1:
        raise ValueError(f"confidence must lie in (0, 1), got {confidence!r}")
    estimated = torque_noise is None or twist_noise is None
    torque_range, twist_range = float(np.ptp(torque)), float(np.ptp(twist))
    s_t = noise_level(torque) if torque_noise is None else units.positive_si("torque_noise", torque_noise, "torque")
    s_theta = noise_level(twist) if twist_noise is None else units.positive_si("twist_noise", twist_noise, "angle")
    s_t, s_theta = max(s_t, 1e-12 * torque_range), max(s_theta, 1e-12 * twist_range)  # noise-free records
    reversal_index = turning_points(twist, reversal_threshold(twist, s_theta))
    model = _Model(torque, twist, reversal_index, s_t, s_theta)
    n = torque.size
    peak = float(np.max(np.abs(torque)))
    t_of = lambda dof: float(stats.t.ppf(0.5 + confidence / 2, dof))  # noqa: E731
    noise = {"torque": s_t, "twist": s_theta, "estimated": estimated}
    common = {"samples": n, "reversals": int(reversal_index.size), "radius": a, "normal_force": force, "noise": noise}

    linear = _linear_least_squares(model)
    chi2_linear = float(np.sum(linear.fun**2))
    start = _start(model, linear.x, twist[reversal_index], peak)
    lower = np.full(start.size, -np.inf)
    upper = np.full(start.size, np.inf)
    lower[:3] = [1e-9 * peak, 0.0, linear.x[0] * 1e-6]
    upper[1] = KAPPA_MAX
    dof = n - start.size

    def plainly_stick(result):  # far below the slip test's threshold: more passes cannot change the verdict
        chi2_full = float(np.sum(result.fun**2))
        return (chi2_linear - chi2_full) / (chi2_full / dof) < 0.25 * STICK_TEST_QUANTILE

    full = _least_squares(model, start, lower, upper, stop=plainly_stick)
    chi2 = float(np.sum(full.fun**2))
    scale2 = chi2 / dof
    stick_test = (chi2_linear - chi2) / scale2

    if stick_test < STICK_TEST_QUANTILE:
        compliance, offset = linear.x
        cov = _covariance(linear.jac, chi2_linear / (n - 2))
        se = np.sqrt(np.diag(cov))
        bound = 2.0 * peak / (force * a)
        proven = 1.5 * max(peak - 2.0 * s_t, 0.0) / (force * a)  # |T*| <= 4/3 whatever G: the torque was carried
        return LoopFit(
            friction=Estimate(None, None, (proven, None), identified=False, lower_bound=bound),
            shear_modulus=Estimate(None, None, (None, None), identified=False),
            compliance=Estimate(float(compliance), float(se[0]), _wald(compliance, se[0], t_of(n - 2))),
            twist_offset=Estimate(float(offset), float(se[1]), _wald(offset, se[1], t_of(n - 2))),
            correlation=None,
            residual_rms=float(np.sqrt(np.mean((twist - offset - compliance * torque) ** 2))),
            torque_residual_rms=float(np.sqrt(np.mean((torque - (twist - offset) / compliance) ** 2))),
            noise_scale=math.sqrt(chi2_linear / (n - 2)), regime="stick", slip_detected=False, noise_limited=False,
            stick_test=stick_test, dof=n - 2, fitted_torque=(twist - offset) / compliance,
            message=(f"no slip detected (the full model lowers the residual sum by {stick_test:.2f} residual "
                     f"variances, below {STICK_TEST_QUANTILE:.2f}): the loop is linear, without hysteresis; if the "
                     f"interface stuck throughout, |T*| <= 1 gives f >= 2 max|T| / (F a) = {bound:.4g} "
                     f"(lower_bound); a slip too small to detect is not excluded, and what the record proves "
                     f"whatever G is |T*| <= 4/3: f >= 1.5 (max|T| - 2 s_T) / (F a) = {proven:.4g} (interval); "
                     "G is not identified"),
            **common)

    cov = _covariance(full.jac, scale2)
    slip_torque, kappa, compliance, offset = full.x[:4]
    se = np.sqrt(np.diag(cov)[:4])
    t_quantile = t_of(dof)
    friction = 2.0 * slip_torque / (force * a)
    f_se = 2.0 * se[0] / (force * a)
    # 1/G = pi a^3 kappa C / 4 (k = kappa C T_s = 2 f p0 / G)
    c_g = math.pi * a**3 / 4.0
    y = c_g * kappa * compliance
    gradient = np.array([0.0, c_g * compliance, c_g * kappa])
    y_se = math.sqrt(max(float(gradient @ cov[:3, :3] @ gradient), 0.0))
    y_lo, y_hi = _wald(y, y_se, t_quantile)
    g_identified = bool(y_lo > 0)
    g_lower = 1.0 / y_hi if y_hi > 0 else None
    if g_identified:
        modulus = Estimate(1.0 / y, y_se / y**2, (1.0 / y_hi, 1.0 / y_lo))
        cov_fy = float(np.array([2.0 / (force * a), 0.0, 0.0]) @ cov[:3, :3] @ gradient)
        correlation = -cov_fy / (f_se * y_se) if f_se > 0 and y_se > 0 else None
    else:
        modulus = Estimate(None, None, (g_lower, None), identified=False, lower_bound=g_lower)
        correlation = None
    fitted, slope, turning = model.evaluate(full.x)[:3]
    plateau_free = slope >= PLATEAU_SLOPE / compliance
    twist_residual = (torque - fitted)[plateau_free] / slope[plateau_free]
    reached = float(np.max(np.abs(np.append(turning, fitted[-1])))) / slip_torque
    regime = "gross-slip" if reached >= GROSS_SLIP_TORQUE * (1 - 1e-6) else "partial-slip" if reached > 1 else "stick"
    message = f"slip detected ({regime}, max |T*| = {reached:.4f})"
    # the second-order bias of the effective-variance residual, in standard errors (module docstring, "Limits")
    knee = min(reached, KNEE_TORQUE)
    contact = kappa * compliance * slip_torque * float(monotonic_curves().rotation(knee))
    noise_twist = math.sqrt(scale2) * math.hypot(s_theta, compliance * s_t)
    bending = int(np.sum((slope > 0.02 / compliance) & (slope < 0.98 / compliance)))  # the partly slipping samples
    bias = 0.5 * noise_twist / contact * math.sqrt(bending) if contact > 0 else math.inf
    noise_limited = bool(bias > NOISE_LIMIT)
    if noise_limited:
        message += (f"; the twist noise ({noise_twist:.3g} rad) is large against the contact's twist "
                    f"({contact:.3g} rad): the estimates are biased by about {bias:.1f} standard errors and the "
                    "intervals are too narrow")
        warnings.warn(message, NoiseLimitedFitWarning, stacklevel=2)
    if not g_identified:
        message += ("; the contact's twist is not resolved from the noise: G is not identified, only its lower "
                    f"bound {g_lower:.4g} Pa" if g_lower else "; G is not identified")
    return LoopFit(
        friction=Estimate(friction, f_se, _wald(friction, f_se, t_quantile)),
        shear_modulus=modulus,
        compliance=Estimate(float(compliance), float(se[2]), _wald(compliance, se[2], t_quantile)),
        twist_offset=Estimate(float(offset), float(se[3]), _wald(offset, se[3], t_quantile)),
        correlation=correlation,
        residual_rms=float(np.sqrt(np.mean(twist_residual**2))) if twist_residual.size else math.nan,
        torque_residual_rms=float(np.sqrt(np.mean((torque - fitted) ** 2))),
        noise_scale=math.sqrt(scale2), regime=regime, slip_detected=True, stick_test=stick_test, dof=dof,
        noise_limited=noise_limited,
        fitted_torque=fitted, message=message, **common)


def _start(model: _Model, linear, reversals, peak) -> np.ndarray:
    """Starting parameters: the best point of a grid in (T_s, kappa), C and theta_0 from the stick fit."""
    compliance, offset = linear
    best, best_p = math.inf, None
    for ratio in START_RATIOS:
        for kappa in START_KAPPAS:
            p = np.concatenate([[ratio * peak, kappa, compliance, offset], reversals])
            value = float(np.sum((model.weights(p) * (model.torque - model.evaluate(p)[0])) ** 2))
            if value < best:
                best, best_p = value, p
    return best_p
