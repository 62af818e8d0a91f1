r"""Friction coefficient and shear modulus from a measured torque-twist loop, with honest intervals.

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
Parameters: T_s (hence f = 2 T_s / (F a)), kappa = k / (C T_s) (hence 1/G = pi a^3 kappa C / 4),
C, theta_0, and the twist U_j at every reversal of the loop (``fitting.loop_model``).  The record
must start from the virgin interface (first loading included) and the torque channel must read
zero at zero torque.  Written the way it is always defined, the torque is a function of the twist
along the branches (``fitting.masing``), saturating at the gross-slip torque 2 f F a / 3: a
twist-controlled rig's gross-slip plateau needs no special case.

Errors in both variables
------------------------
Both channels are noisy (levels s_T, s_theta: given, or estimated from the second differences by
``fitting.samples.noise_level`` and floored at the channel's resolution and at 1 % of the other channel's level
through the elastic slope, ``fitting.record_checks``, so that an exact or commanded channel cannot collapse the
likelihood; spikes are removed first and counted, and an inverted channel is an error); only their ratio shapes
the fit, the overall scale is estimated from the residuals).  Each sample's residual is its orthogonal distance
from the curve in noise units, its true twist eliminated by minimisation (``fitting.loop_model``: the foot point on the
curve; the functional errors-in-variables likelihood, i.e. orthogonal distance regression along every branch).  The
turning point of each branch is the true state of the reversal's own sample, which keeps its two residuals.  The
first implementation used the effective-variance residual (T_i - T(theta_i)) / sqrt(s_T^2 + T'^2 s_theta^2) at the
measured twist, the distance's first-order approximation, and left the twists at the reversals free: where the
contact's twist is a few noise levels wide (partial slip at 1e-5 rad of twist noise) the second-order error biased f
by 1.5 % (1.5 of its standard errors) and the free turning points let a loop in stick fit its noise with slip.  With
N samples and M reversals there are N + M residuals, 4 + M parameters and s^2 = sum r^2 / (N - 4) (one degree of
freedom per sample: two observations, one latent twist; no Neyman-Scott halving).

Fitting
-------
``scipy.optimize.least_squares`` (trust region reflective, bounds T_s, C > 0, ``KAPPA_MIN`` <=
kappa <= ``KAPPA_MAX``, each U_j within ``REVERSAL_REACH`` noise levels of its sample) on the
residuals with their analytic Jacobian (``fitting.profile.fit``), from the best point of a grid of
starting values (T_s from 0.75 to 1.05 times the largest torque, kappa from 0.02 to 1; C and
theta_0 from a straight-line fit to all samples and to the central ones, |T| < max|T| / 2, which
stay in stick on every branch of a symmetric loop), and also from its best slipping point when the
best is a straight loop (``starts._starts``).  A slipping loop that another contact model
fits clearly better gets no friction value (``fitting.model_check``).

Did it slip?
------------
A loop whose torques stay below the slip onset is straight (C and theta_0 only).  The
likelihood-ratio statistic of the straight loop against the full model (with the gross-slip
plateau 4/3 T_s not below the straight loop's largest torque: a plateau lower
down would clip the noisy tips of a straight loop) is compared with the critical value that
Davies' bound gives for the record at hand (``fitting.slip_test``: T_s is not identified under
stick and kappa >= 0 sits on its bound, so the statistic is not chi-square; the fixed 5.99 of
chi-square with 2 degrees of freedom, with free turning points, detected slip in about a fifth of
the records of a loop in stick).  Without slip the result gives no friction value, only the bound
f >= 2 max|T| / (F a) that full stick implies (``lower_bound``), and as ``interval`` the weaker
bound that holds whatever G (the torque never exceeded the gross-slip torque): f >= 1.5 (max|T| -
2 s_T) / (F a); G is not identified.

Intervals
---------
``stderr`` is the Wald standard error from s^2 (J^T J)^+.  ``interval`` is the profile-likelihood
interval (``fitting.profile``) on T_s (hence f), on y = kappa C (linear in 1/G, mapped to G)
and on C: the values whose likelihood-ratio statistic stays below F(1, N - 4) at the confidence
level.  Unlike the Wald interval it follows the curved, flat ridge along which T_s and kappa
trade off in partial slip (there the Wald standard error of f was a third of the scatter of the
estimates), and it ends where the data stop telling:

* when the profile of 1/G stays below the critical value down to kappa = ``KAPPA_MIN`` the
  modulus has no upper end; when it stays below it up to kappa = ``KAPPA_MAX`` its lower end is
  only that model bound (``assumed_end`` "lower"); either way G is not identified
  (``identified`` false, no value, ``interval`` what the data do say);
* when the profile of T_s stays below it up to the straight loop's largest torque (every larger
  T_s is the straight loop) the friction has only its lower bound.

kappa <= ``KAPPA_MAX`` holds when C includes at least the shaft over the gauge length; an end of
the friction interval set by it is named in ``assumed_end`` and ``message``.

A plateau that only clips the tips
----------------------------------
Where the twist noise buries the contact's twist (partial slip at 1e-4 rad), the best loop of the
likelihood may put its gross-slip plateau 4/3 T_s just at the largest torques: the samples at the
tips then trade their twist residuals for their distances to a flat line, about one residual
variance each (LR about 10 over every partial-slip loop for two cycles of 200 samples), and that
loop, stiff (G at 250-500 GPa for a true 80 GPa) and with T_s pinned to the tips, took a quarter of
the records, its narrow intervals excluding the truth.  A plateau whose samples (fitted slope below
``PLATEAU_SLOPE`` / C) span less than ``PLATEAU_RESOLVED`` noise levels of twist at every tip (a branch
and a sign of the torque: a reversal missed in the noise joins two tips in one branch)
is not seen in the data, and its gain is not counted as evidence: the intervals are taken against
the best loop whose plateau lies ``PLATEAU_CLEARANCE`` torque noise levels above its largest torque
(``_clipping_reference``; the value reported is that loop's), and the clipping loops, below it,
lie inside them.  A plateau a twist-controlled rig drives along (more than 20 noise levels per
branch in the coverage study's noisy gross-slip scenario) is evidence and stays.  ``noise_limited``
(with a ``NoiseLimitedFitWarning``) flags a result with a parameter not identified.
``bootstrap=N`` adds a parametric bootstrap (``fitting.bootstrap``): N records simulated from the
fitted curve and noise, refitted, and bias-corrected percentile intervals (``bootstrap_interval``),
a check of the profile intervals at the cost of N fits.

Limits
------
What remains is the functional estimator's own bias (of order the product of the two noise levels
times the loop's curvature): in partial slip at 1e-5 rad about 0.4 of the half-width of the f
interval on a short record; on long records it would outgrow the intervals, and is taken out where
the torque is fitted as a smooth function of time (``fitting.smoothing``; else ``many cycles``,
``record_checks``).  A loop that barely slips against the noise gives a bound on f, not a value; a
contact twist buried in the twist noise gives bounds on G.  A few hundred samples take 0.05-0.5 s.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace

import numpy as np
from scipy import special  # quantiles from special: scipy.stats costs 0.5 s more to import

from .. import models, units
from ..diagnostics import AccuracyWarning, NoiseLimitedFitWarning
from . import defects, model_check, parameters
from . import profile as profiles
from .known_modulus import shaft_compliance, with_known_modulus
from .loop_model import LoopModel
from .parameters import COMPLIANCE, CORE, KAPPA, LINE_COMPLIANCE, LINE_OFFSET, LOOP, OFFSET, SLIP_TORQUE, TURNING
from .per_cycle import cycles_with_progress, withheld_cycles
from .record_checks import checked_time, many_reversals_note, prepared_record
from .results import Estimate, LoopFit
from .samples import checked_loop
from .slip_test import GRID, critical_value, marginal_note, path_length
from .smoothing import smoothed_torque, widened_for_smoothing
from .starts import (  # noqa: F401 - the starting points' names, as the tests and the docstring use them
    PLATEAU_CLEARANCE,
    PLATEAU_RESOLVED,
    PLATEAU_SLOPE,
    START_KAPPAS,
    START_RATIOS,
    _central_line,
    _clipping_reference,
    _line_foot,
    _starts,
    _stick_equivalent,
    _stick_line,
    off_the_bound,
)

__all__ = ["Estimate", "LoopFit", "fit_loop", "KAPPA_MAX", "Fitted"]

#: The bounds on kappa and on the turning points' twists (``fitting.parameters``), also this module's names.
KAPPA_MAX, KAPPA_MIN, REVERSAL_REACH = parameters.KAPPA_MAX, parameters.KAPPA_MIN, parameters.REVERSAL_REACH
#: Restarts from a better minimum found by a profile.
RESTARTS = 3


def _wald(value, stderr, t):
    return (value - t * stderr, value + t * stderr)


def fit_loop(torque, twist, *, radius, normal_force, torque_noise=None, twist_noise=None,
             confidence: float = 0.95, bootstrap: int = 0, seed=None, time=None,
             check_defects: bool = True, model=None, per_cycle: bool = False, shear_modulus=None,
             gauge_length=None) -> LoopFit:
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
        Level of the intervals (default 0.95); the slip test's level is 1 - confidence.
    bootstrap : int
        Number of parametric-bootstrap refits (0: none; ``fitting.bootstrap``): adds
        ``bootstrap_interval`` to f, G and C.  Costs about ``bootstrap`` fits.
    seed :
        Seed of the bootstrap's random numbers (``numpy.random.default_rng``).
    time : array_like, optional
        The time of every sample (s, strictly increasing): a lag between the channels is then estimated in seconds
        (without it, in samples, assuming uniform sampling).
    model : str or ContactModel, optional
        The contact model (``models``; default "cylinder"): its slip onset, gross-slip torque, monotonic rotation
        and number of elastic bodies shape the loop (``fitting.skeleton``).
    shear_modulus : optional
        G (Pa, or a quantity): fixed, so that f and the compliance are fitted (``fitting.known_modulus``).  Without
        it the fitted G is an effective modulus of the contact (it absorbs the asperities' compliance).
    gauge_length : optional
        L (m), with ``shear_modulus`` and a model whose bodies are shafts: the shafts' L / (G J) is taken out of the
        compliance and ``rig_compliance`` reported.
    per_cycle : bool
        Also fit every whole cycle on its own (``fitting.per_cycle``): ``cycles`` in the result, with a progress
        bar on standard error for ten cycles or more (when it is a terminal).
    check_defects : bool
        Test the record for the defects rigs have (``fitting.defects``: offset, drift, lag), refit with those found,
        and check the contact model (``fitting.model_check``); False: the fit as it comes (for studies).

    Returns
    -------
    LoopFit

    Raises
    ------
    ValueError
        Naming the argument: arrays of different lengths, fewer than ``samples.MIN_SAMPLES``
        samples, a non-finite sample (by index), a constant channel, a bad radius, force,
        noise level, confidence or bootstrap count.
    """
    a = units.positive_si("radius", radius, "length")
    force = units.positive_si("normal_force", normal_force, "force")
    torque, twist = checked_loop(units.si_array("torque", torque, "torque"), units.si_array("twist", twist, "angle"))
    if not 0 < confidence < 1:
        raise ValueError(f"confidence must lie in (0, 1), got {confidence!r}")
    if isinstance(bootstrap, bool) or not isinstance(bootstrap, (int, np.integer)) or not (
            bootstrap == 0 or 20 <= bootstrap <= 100_000):
        raise ValueError(f"bootstrap must be 0 (none) or an integer from 20 to 100000, got {bootstrap!r}")
    estimated = torque_noise is None or twist_noise is None
    given_t = None if torque_noise is None else units.positive_si("torque_noise", torque_noise, "torque")
    given_theta = None if twist_noise is None else units.positive_si("twist_noise", twist_noise, "angle")
    record = prepared_record(torque, twist, given_t, given_theta)
    if time is None:
        clock = np.arange(np.size(torque), dtype=float)  # uniform sampling assumed: a lag in samples
    else:
        clock = checked_time(time, np.size(torque))
    clock = clock[record.kept]
    contact = models.get(model)
    modulus = None if shear_modulus is None else units.positive_si("shear_modulus", shear_modulus, "pressure")
    length = None if gauge_length is None else units.positive_si("gauge_length", gauge_length, "length")
    if length is not None:
        if modulus is None:
            raise ValueError("gauge_length needs shear_modulus (the shafts' L / (G J) is taken out of the compliance)")
        shaft_compliance(contact, a, modulus, length)  # a model whose bodies are not shafts: ValueError
    settings = (a, force, confidence, bootstrap, seed, estimated, contact)
    smooth = smoothed_torque(clock, record.torque, record.reversals, record.torque_noise)  # ``fitting.smoothing``
    whole = record if smooth is None else replace(record, torque=smooth.torque, torque_noise=smooth.noise)
    fitted = _fit_prepared(whole.torque, whole.twist, whole.reversals, whole.torque_noise, whole.twist_noise,
                           list(whole.warnings), whole.spikes, settings)
    if check_defects:
        fitted = defects.corrected_fit(fitted, clock, whole, settings, _fit_prepared, time is not None)
        fitted = model_check.checked_model(fitted, settings, record, smooth)  # the contact model the loop prefers
    fitted = widened_for_smoothing(fitted, smooth)
    result = fitted.result
    if modulus is not None:
        reach = REVERSAL_REACH * math.hypot(record.twist_noise, float(result.compliance.value or 0.0)
                                            * record.torque_noise)
        result = with_known_modulus(fitted, modulus, length, a, force, confidence, (KAPPA_MIN, KAPPA_MAX), reach)
    if per_cycle:
        cycles = cycles_with_progress(record, settings, _fit_prepared, clock if time is not None else None)
        result = replace(result, cycles=withheld_cycles(cycles, result.friction.withheld))
    note = many_reversals_note(record.reversals.size, result, smooth is not None)
    return result if note is None else replace(result, warnings=(*result.warnings, note))


@dataclass
class Fitted:
    """A fit with what the defect checks need: the result, the loop model, the parameters (None in stick) and the
    straight loop's (C, theta_0) with the line's Jacobian."""

    result: LoopFit
    model: LoopModel
    p: np.ndarray | None
    line: object


def _fit_prepared(torque, twist, reversal_index, s_t, s_theta, notes, spikes, settings, quick=False, start=None):
    """The fit of a prepared record (``fit_loop``): a ``Fitted`` (with ``quick``: the point estimate and the slip
    test's verdict only, no result; ``start``: parameters to start from instead of the best of the grid)."""
    a, force, confidence, bootstrap, seed, estimated, contact = settings
    model = LoopModel(torque, twist, reversal_index, s_t, s_theta, contact)
    gross = contact.gross_slip_torque
    record_spikes = spikes
    n = torque.size
    peak = float(np.max(np.abs(torque)))
    noise = {"torque": s_t, "twist": s_theta, "estimated": estimated}
    common = {"samples": n, "reversals": int(reversal_index.size), "radius": a, "normal_force": force, "noise": noise,
              "confidence": confidence}

    line = _stick_line(model)
    s_stick = float(np.sum(line.fun**2))
    lines = [tuple(line.x)]
    central = _central_line(model, peak)
    if central is not None:
        lines.append(central)
    starts = _starts(model, lines, twist[reversal_index], peak) if start is None else [np.array(start, dtype=float)]
    start = starts[0]
    lower = np.full(start.size, -np.inf)
    upper = np.full(start.size, np.inf)
    lower[CORE] = [1e-9 * peak, KAPPA_MIN, min(c for c, _ in lines) * 1e-6]
    upper[KAPPA] = KAPPA_MAX
    # the true turning points lie within a few noise levels (in twist: the twist's and the torque's through C) of the
    # extreme samples; unbounded, the reversal twists of a loop in stick wander off to fit noise with slip elsewhere
    reach = REVERSAL_REACH * math.hypot(s_theta, lines[0][LINE_COMPLIANCE] * s_t)
    lower[TURNING] = twist[reversal_index] - reach
    upper[TURNING] = twist[reversal_index] + reach
    dof = n - 4  # N - M distances and 2 M reversal residuals for 4 + M parameters (``loop_model``)
    p, s_full, result = min((profiles.fit(model, point, lower, upper) for point in starts), key=lambda fit: fit[1])
    # the straight loop is a loop of the full model (a slip torque above the largest torque): the fit from there
    # can end no worse than the straight loop, so that the slip test's statistic is >= 0 by construction
    p_line = _stick_equivalent(model, line.x, peak, lower, upper, KAPPA_MIN)
    p_alt, s_alt, result_alt = profiles.fit(model, p_line, lower, upper)
    if s_alt < s_full:
        p, s_full, result = p_alt, s_alt, result_alt
    p, s_full, result = off_the_bound(model, (p, s_full, result), lines, twist[reversal_index], peak, lower, upper,
                                      KAPPA_MAX)
    jacobian = result.jac
    scale2 = s_full / dof
    straight = (s_stick - s_full) / scale2  # LR of the straight loop: the profile of T_s above the largest torque
    compliance_0, offset_0 = line.x
    foot_0 = _line_foot(torque, twist, compliance_0, offset_0, s_t, s_theta)
    stick_peak = float(np.max(np.abs(foot_0 - offset_0))) / compliance_0
    # The slip test's alternative: slip that shows as the contact's twist, with the gross-slip plateau not below the
    # straight loop's largest torque (a plateau lower down clips the noisy tips of a loop in stick; fitting the
    # noise there is no evidence of slip, and it is not the smooth departure that Davies' bound counts).
    floor = stick_peak / gross  # the plateau at the straight loop's largest torque
    s_test = s_full
    if p[SLIP_TORQUE] < floor:
        lower_test = lower.copy()
        lower_test[SLIP_TORQUE] = floor
        start_test = p.copy()
        start_test[SLIP_TORQUE] = floor * (1 + 1e-6)
        s_test = profiles.fit(model, start_test, lower_test, upper)[1]
        if p_line[SLIP_TORQUE] >= floor:  # the straight loop is inside the alternative: start there too
            s_test = min(s_test, profiles.fit(model, p_line, lower_test, upper)[1])
    # the straight loop's sum of squares is the fit's from ``p_line`` up to the optimiser's tolerance: a statistic
    # below zero is that tolerance, or an optimisation that failed (said, never read as a verdict)
    if s_test > s_stick * (1 + 1e-6) + 1e-9 * scale2:
        notes.append(f"optimisation: the slip fit ended {(s_test - s_stick) / scale2:.3g} residual variances above the "
                     "straight loop it started from (a failed optimisation; the slip test is read as 0)")
    stick_test = max((s_stick - min(s_test, s_stick)) / scale2, 0.0)
    # Davies' bound with the score's path only near a critical value (the path over GRID points is <= 2 (GRID - 1))
    stick_critical = critical_value(2.0 * (GRID - 1), 1.0 - confidence)
    if stick_test < stick_critical:
        stick_critical = critical_value(path_length(model, compliance_0, offset_0, foot_0), 1.0 - confidence)

    if quick:
        return Fitted(None, model, None if stick_test < stick_critical else p, line)
    if stick_test < stick_critical:
        return Fitted(_stick_result(model, line, s_stick, stick_test, stick_critical, peak, force, a, confidence,
                                    common, notes, record_spikes), model, None, line)

    notes.extend(filter(None, [marginal_note(stick_test, 1.0 - confidence, model, compliance_0, offset_0, foot_0)]))
    critical = float(special.fdtri(1, dof, confidence))  # F(1, dof) quantile
    t_quantile = math.sqrt(critical)
    clipped = None
    for attempt in range(RESTARTS + 1):
        if clipped is None:  # checked again after a restart: a profile may have found the clipping loop
            clipped = _clipping_reference(model, p, s_full, lower, upper)
            if clipped is not None:  # the plateau's gain is no evidence: the reference is the best loop without it
                p, s_full, jacobian = clipped
                scale2 = s_full / dof
                straight = (s_stick - s_full) / scale2
        cov = profiles.covariance(jacobian, scale2)
        try:
            ends = _profile_intervals(model, p, s_full, scale2, cov, critical, t_quantile, lower, upper, stick_peak,
                                      straight, peak, better_minimum=attempt < RESTARTS and clipped is None)
            break
        except profiles.BetterMinimum as better:  # the first fit stopped in a local minimum: start again from there
            p, s_full, result = profiles.fit(model, better.p, lower, upper)
            jacobian = result.jac
            if s_full > better.s:  # the refit stopped short of the profile point: take the point itself
                p, s_full = better.p, better.s
                jacobian = model.distances(p, jacobian=True,
                                           sparse=profiles.is_large(model.residual_count, model.size))[1]
            scale2 = s_full / dof
            straight = (s_stick - s_full) / scale2
    return Fitted(_slip_result(model, p, s_full, scale2, cov, ends, stick_test, stick_critical, critical, force, a,
                               confidence, bootstrap, seed, lower, upper, common, notes, record_spikes,
                               clipped=clipped is not None), model, p, line)


def _profile_intervals(model, p, s_min, scale2, cov, critical, t_quantile, lower, upper, stick_peak, straight,
                       peak, better_minimum: bool = True):
    """Both ends of the profile intervals of T_s, y = kappa C and C (``fitting.profile``)."""
    y = p[KAPPA] * p[COMPLIANCE]
    y_gradient = np.array([0.0, p[COMPLIANCE], p[KAPPA]])
    y_se = math.sqrt(max(float(y_gradient @ cov[CORE, CORE] @ y_gradient), 0.0))
    se = {"slip_torque": math.sqrt(max(cov[SLIP_TORQUE, SLIP_TORQUE], 0.0)),
          "compliance": math.sqrt(max(cov[COMPLIANCE, COMPLIANCE], 0.0)), "product": y_se}
    value = {"slip_torque": p[SLIP_TORQUE], "compliance": p[COMPLIANCE], "product": y}
    # T_s above the straight loop's largest torque: the straight loop (LR ``straight``); a plateau at a third of the
    # largest torque is far outside any interval; y at kappa = KAPPA_MIN: G infinite for any purpose
    onset = model.contact.slip_onset_torque
    upper_limit = (stick_peak / onset, straight) if onset > 0 else (None, None)  # every larger T_s: the straight loop
    limits = {("slip_torque", 1): upper_limit, ("slip_torque", -1): (0.25 * peak, None),
              ("product", -1): (KAPPA_MIN * p[COMPLIANCE], None), ("product", 1): (None, None),
              # C -> 0 (a contact whose own twist is linear in the torque takes it all): no lower end
              ("compliance", -1): (1e-6 * p[COMPLIANCE], None), ("compliance", 1): (None, None)}

    def search(kind, side, start_from=None):
        limit, limit_lr = limits[(kind, side)]
        if limit is not None and side * (limit - value[kind]) <= 0:
            return profiles.ProfileEnd(None, None, 0)
        first = t_quantile * se[kind] if se[kind] > 0 else 0.1 * abs(value[kind])
        return profiles.profile_end(model, p, s_min, scale2, kind, side, first, critical, lower, upper, KAPPA_MAX,
                                    limit, limit_lr, better_minimum, cov, start_from)

    ends = {(kind, side): search(kind, side) for kind in ("slip_torque", "product", "compliance") for side in (-1, 1)}
    return profiles.across_valleys(ends, model, p, s_min, scale2, critical, lower, upper, KAPPA_MAX, search,
                                   better_minimum)


def _stick_result(model, line, s_stick, stick_test, stick_critical, peak, force, a, confidence, common, notes,
                  spikes):
    n = model.torque.size
    compliance, offset = line.x
    cov = profiles.covariance(line.jac, s_stick / (n - 2))
    se = np.sqrt(np.diag(cov))
    t = float(special.stdtrit(n - 2, 0.5 + confidence / 2))  # Student t quantile
    onset, gross = model.contact.slip_onset_torque, model.contact.gross_slip_torque
    # in stick |T*| <= the slip onset; whatever G, |T*| <= the gross-slip torque
    bound = 2.0 * peak / (force * a * onset) if onset > 0 else None
    proven = 2.0 / gross * max(peak - 2.0 * model.torque_noise, 0.0) / (force * a)
    torque, twist = model.torque, model.twist
    return LoopFit(
        friction=Estimate(None, None, (proven, None), identified=False, lower_bound=bound),
        shear_modulus=Estimate(None, None, (None, None), identified=False),
        compliance=Estimate(float(compliance), float(se[LINE_COMPLIANCE]), _wald(compliance, se[LINE_COMPLIANCE], t)),
        twist_offset=Estimate(float(offset), float(se[LINE_OFFSET]), _wald(offset, se[LINE_OFFSET], t)),
        correlation=None,
        residual_rms=float(np.sqrt(np.mean((twist - offset - compliance * torque) ** 2))),
        torque_residual_rms=float(np.sqrt(np.mean((torque - (twist - offset) / compliance) ** 2))),
        noise_scale=math.sqrt(s_stick / (n - 2)), regime="stick", slip_detected=False, noise_limited=False,
        stick_test=stick_test, stick_critical=stick_critical, interval_method="wald", dof=n - 2,
        fitted_torque=(twist - offset) / compliance, warnings=tuple(notes), spikes=spikes,
        message=(f"no slip detected (the full model lowers the residual sum by {stick_test:.2f} residual "
                 f"variances, below the critical value {stick_critical:.2f} of the slip test): the loop is "
                 f"straight, without hysteresis; "
                 + (f"if the interface stuck throughout, |T*| <= {onset:.4g} gives f >= 2 max|T| / ({onset:.4g} F "
                    f"a) = {bound:.4g} (lower_bound); a slip too small to detect is not excluded, and "
                    if bound is not None else "the contact slips at any torque, so its twist is too small to see: ")
                 + f"what the record proves whatever G is |T*| <= {model.contact.gross_slip_text}: f >= "
                 f"(2 / {gross:.4g}) (max|T| - 2 s_T) / (F a) = {proven:.4g} (interval); G is not identified; C is "
                 "the straight loop's slope, which a slip too small to detect makes steeper than the rig's"),
        **common)


def _slip_result(model, p, s_full, scale2, cov, ends, stick_test, stick_critical, critical, force, a,
                 confidence, bootstrap, seed, lower, upper, common, record_notes, spikes, clipped: bool = False):
    slip_torque, kappa, compliance, offset = (float(v) for v in p[LOOP])
    se = np.sqrt(np.maximum(np.diag(cov)[LOOP], 0.0))
    to_f = 2.0 / (force * a)
    # kappa = k / (C T_s), k = e f p-bar / G (e elastic bodies), T_s = f F a / 2: 1/G = c_g kappa C
    c_g = math.pi * a**3 / (2.0 * model.contact.elastic_bodies)
    y = kappa * compliance
    y_gradient = np.array([0.0, compliance, kappa])
    y_se = math.sqrt(max(float(y_gradient @ cov[CORE, CORE] @ y_gradient), 0.0))
    ends_at_cap = {key for key, e in ends.items() if e.at_cap and e.value is not None}
    ts_lo, ts_hi = ends[("slip_torque", -1)].value, ends[("slip_torque", 1)].value
    y_lo, y_hi = ends[("product", -1)].value, ends[("product", 1)].value
    y_lo = y_lo if y_lo is not None and y_lo > KAPPA_MIN * compliance else None  # 1/G -> 0 inside: no upper G
    c_lo, c_hi = ends[("compliance", -1)].value, ends[("compliance", 1)].value
    notes = []
    if clipped:
        notes.append("a gross-slip plateau at the loop's tips, not resolved in the twist, fits the noise better; its "
                     "gain is not counted as evidence and the intervals include it")

    f_identified = ts_hi is not None and ts_lo is not None
    f_assumed = next((name for name, side in (("upper", 1), ("lower", -1)) if ("slip_torque", side) in ends_at_cap),
                     None)
    if f_assumed:
        notes.append(f"the {f_assumed} end of the friction interval is set by the model's bound kappa <= {KAPPA_MAX:g}")
    f_se = to_f * se[SLIP_TORQUE]
    if f_identified:
        friction = Estimate(to_f * slip_torque, f_se, (to_f * ts_lo, to_f * ts_hi), assumed_end=f_assumed)
    else:
        bound = to_f * ts_lo if ts_lo is not None else None
        friction = Estimate(None, None, (bound, None), identified=False, lower_bound=bound, assumed_end=f_assumed)
    g_from = (lambda v: 1.0 / (c_g * v) if v is not None and v > 0 else None)  # noqa: E731
    g_capped = ("product", 1) in ends_at_cap  # the lower end of G is the bound kappa <= kappa_max itself
    g_interval = (g_from(y_hi), g_from(y_lo))
    g_identified = f_identified and y_lo is not None and y_hi is not None and not g_capped
    if g_identified:
        modulus = Estimate(1.0 / (c_g * y), y_se / (c_g * y**2), g_interval)
        cov_fy = float(np.array([to_f, 0.0, 0.0]) @ cov[CORE, CORE] @ y_gradient)
        correlation = -cov_fy / (f_se * y_se) if f_se > 0 and y_se > 0 else None
    else:
        modulus = Estimate(None, None, g_interval, identified=False,
                           lower_bound=None if g_capped else g_interval[0], assumed_end="lower" if g_capped else None)
        correlation = None
    if c_lo is not None and c_hi is not None:
        compliance_estimate = Estimate(compliance, float(se[COMPLIANCE]), (c_lo, c_hi))
    else:
        compliance_estimate = Estimate(None, None, (c_lo, c_hi), identified=False, lower_bound=c_lo)

    torque, twist = model.torque, model.twist
    fitted, slope, turning = model.torque_at(p, twist)[:3]
    plateau_free = slope >= PLATEAU_SLOPE / compliance
    twist_residual = (torque - fitted)[plateau_free] / slope[plateau_free]
    reached = float(np.max(np.abs(np.append(turning, fitted[-1])))) / slip_torque
    onset, gross = model.contact.slip_onset_torque, model.contact.gross_slip_torque
    regime = "gross-slip" if reached >= gross * (1 - 1e-6) else "partial-slip" if reached > onset else "stick"
    message = f"slip detected ({regime}, max |T*| = {reached:.4f}; slip test {stick_test:.1f} > {stick_critical:.2f})"
    noise_limited = not (f_identified and g_identified and compliance_estimate.identified)
    if not f_identified:
        message += ("; the loop is as compatible with a straight loop as the noise allows: f is not identified"
                    + (f", only its lower bound {friction.lower_bound:.4g}" if friction.lower_bound is not None else "")
                    + ", nor is G")
    elif not g_identified:
        reasons = []
        if y_lo is None:
            reasons.append("the profile of 1/G reaches 0 (no upper end of G)")
        if g_capped:
            reasons.append(f"its lower end is only the model's bound kappa <= {KAPPA_MAX:g}, i.e. G >= "
                           f"{g_interval[0]:.4g} Pa")
        elif y_hi is not None and g_interval[0] is not None:
            reasons.append(f"the data give G >= {g_interval[0]:.4g} Pa")
        if g_interval[1] is not None:
            reasons.append(f"the data give G <= {g_interval[1]:.4g} Pa")
        message += "; the contact's twist is not resolved from the noise: G is not identified (" + "; ".join(
            reasons) + ")"
    for note in notes:
        message += "; " + note
    if noise_limited:
        warnings.warn(message, NoiseLimitedFitWarning, stacklevel=3)
    n_boot = 0
    if bootstrap:
        from .bootstrap import bootstrap_intervals, unresolved_note, with_bootstrap

        boot = bootstrap_intervals(model, p, scale2, bootstrap, confidence, seed, lower, upper, KAPPA_MAX)
        n_boot = int(bootstrap)
        friction = with_bootstrap(friction, boot["slip_torque"].interval, to_f, boot["slip_torque"].bias)
        lo, hi = boot["product"].interval
        # G = 1 / (c_g y) falls as y rises: y's lower end is G's upper end, and the fraction below flips
        modulus = with_bootstrap(modulus, (g_from(hi), g_from(lo)), 1.0, -boot["product"].bias)
        compliance_estimate = with_bootstrap(compliance_estimate, boot["compliance"].interval, 1.0,
                                              boot["compliance"].bias)
        unresolved = unresolved_note(boot, n_boot)
        if unresolved:
            message += "; " + unresolved
            warnings.warn(unresolved, AccuracyWarning, stacklevel=3)
    return LoopFit(
        friction=friction, shear_modulus=modulus, compliance=compliance_estimate,
        twist_offset=Estimate(offset, float(se[OFFSET]), _wald(offset, se[OFFSET], math.sqrt(critical))),
        correlation=correlation,
        residual_rms=float(np.sqrt(np.mean(twist_residual**2))) if twist_residual.size else math.nan,
        torque_residual_rms=float(np.sqrt(np.mean((torque - fitted) ** 2))),
        noise_scale=math.sqrt(scale2), regime=regime, slip_detected=True, stick_test=stick_test,
        stick_critical=stick_critical, noise_limited=noise_limited, interval_method="profile likelihood",
        dof=int(model.torque.size - 4), fitted_torque=fitted, message=message, bootstrap=n_boot,
        warnings=tuple(record_notes), spikes=spikes,
        parameters=np.array(p, dtype=float), **common)
