r"""Which contact model a loop prefers: the chosen model's fit against every other model of the table.

Units: torque N m, twist rad, friction 1.

A loop's shape depends on the contact (its slip onset, its gross-slip torque, the rotation of its stick zone
along a branch), and one loop does not say which contact made it: a record of a sphere on a flat (Hertz) read
with the cylinders' model gave f 14 % low, its intervals excluding the truth in every record of the fit study,
with only a lag warning (the misfit read as a lag of about 13 ms).  Every model of the table (``models``) fits
the same parameters (T_s, kappa, C, theta_0 and the turning points' twists; ``fitting.parameters``) in the one
normalisation T* = 2 T / (f F a), so the residual sums of their fits to the same samples compare directly: a
comparison of non-nested models with equal numbers of parameters, in which the smaller sum is the better model.
Under the chosen model, another curve at a distance d (noise units) from the truth lowers the sum by
-d^2 - 2 d.e (e the noise), which exceeds c with probability Phi(-(c + d^2) / (2 d)), at most Phi(-sqrt(c))
whatever d: 5e-5 per model at c = ``MODEL_CRITICAL``.  When another model's sum lies below the chosen model's
by more than ``MODEL_CRITICAL`` residual variances (the variance of the better fit), the data reject the chosen
model: the
result then gives no friction value, modulus or compliance (each depends on the contact model: the sphere's
records read as cylinders gave C 45-50 % high as well), and its warning names the model the loop prefers and
the friction fitted with it.

Measured on the rig generator (two cycles of 200 samples, noise 0.5 % of the torque range and 1e-5 rad,
residual sums over about 400 degrees of freedom): a Hertz record (T* 1.1) gave 850 with the cylinders'
model, 390 with Hertz's and 400 with uniform pressure; a cylinders' record (T* 1.3) gave 355-405 with its
own model, 358-407 with the flat punch's (the two are not told apart there) and 30-40 more with Hertz's or
uniform pressure.

The check fits the record's first ``CHECK_TURNING`` turning points (two cycles from the virgin state; all of a
shorter record) under each model, the chosen one included, with the fit's quick path (point estimate and slip
verdict): a few quick fits of a few thousand samples at most.  Loops in stick (a straight loop under every
model) are not checked, nor a record whose stretch the chosen model reads as stick (its straight loop's sum is
then no minimum of the full model, and the gain would partly be the slip test's).  The record is the one the
final fit used (corrected for the defects found), with the raw torque where the fit smoothed it: the smoothed
channel's errors are correlated, and on it the gain scattered twice as widely as the chi-square bound allows.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from scipy import special

from .. import models
from .parameters import SLIP_TORQUE
from .results import Estimate

__all__ = ["MODEL_LEVEL", "MODEL_CRITICAL", "CHECK_TURNING", "residual_sums", "checked_model"]

#: Level of the model check, and its critical value in residual variances (chi-square, one degree of freedom, at
#: that level: the difference of two residual sums of equal parameter counts, strict because several models are
#: tried on every record).
MODEL_LEVEL = 1e-4
MODEL_CRITICAL = float(special.chdtri(1, MODEL_LEVEL))
#: Turning points of the stretch the check fits (two cycles from the virgin state).
CHECK_TURNING = 4


def _stretch(torque, twist, reversals):
    """(torque, twist, reversals) of the record's first ``CHECK_TURNING`` turning points (the whole record when it has
    no more; else the samples up to the next turning point, whose branch ends the stretch)."""
    if reversals.size <= CHECK_TURNING:
        return torque, twist, reversals
    end = int(reversals[CHECK_TURNING]) + 1
    return torque[:end], twist[:end], reversals[:CHECK_TURNING]


def _residual_sum(fitted) -> float:
    """The residual sum of a quick fit: its slip fit's where slip was found, else the straight loop's."""
    if fitted.p is None:
        return float(np.sum(np.asarray(fitted.line.fun) ** 2))
    r = fitted.model.distances(fitted.p)
    return float(r @ r)


def residual_sums(fitted, settings, fit_prepared, record=None, smooth=None) -> dict:
    """{model name: (residual sum, slip torque or None)} of every model of the table on the stretch of the record
    that ``fitted`` (a ``loop_fit.Fitted``) holds, fitted by ``fit_prepared`` with ``settings`` (``loop_fit``) but
    the contact model; and the degrees of freedom under the key None.  ``record`` and ``smooth``: the prepared
    record and its ``smoothing.SmoothTorque`` when the fit smoothed the torque (the raw samples are then used)."""
    model = fitted.model
    torque, torque_noise = model.torque, model.torque_noise
    if smooth is not None:  # the fitted torque (its corrections included) with the spline's residual put back
        residual = np.asarray(record.torque, dtype=float) - smooth.torque
        torque, torque_noise = torque + residual[residual.size - torque.size:], smooth.raw_noise
    torque, twist, reversals = _stretch(torque, model.twist, model.reversals)
    out = {None: max(torque.size - 4, 1)}
    for name in models.names():
        other = settings[:-1] + (models.get(name),)
        quick = fit_prepared(torque, twist, reversals, torque_noise, model.twist_noise, [], 0, other, quick=True)
        out[name] = (_residual_sum(quick), None if quick.p is None else float(quick.p[SLIP_TORQUE]))
    return out


def checked_model(fitted, settings, fit_prepared, record=None, smooth=None):
    """``fitted`` (a ``loop_fit.Fitted`` of a slipping loop) unchanged when no other model of the table fits its record
    better by more than ``MODEL_CRITICAL`` residual variances; else with no friction value, modulus or compliance
    (``Estimate.withheld`` "model") and a ``model`` warning (module docstring; ``record`` and ``smooth`` as
    ``residual_sums`` takes them)."""
    if fitted.p is None:
        return fitted
    chosen = settings[-1].name
    sums = residual_sums(fitted, settings, fit_prepared, record, smooth)
    dof = sums.pop(None)
    if sums[chosen][1] is None:  # the chosen model reads the stretch as stick: no minimum of its own to compare
        return fitted
    best = min(sums, key=lambda name: sums[name][0])
    scale2 = sums[best][0] / dof
    if best == chosen or not scale2 > 0:
        return fitted
    gain = (sums[chosen][0] - sums[best][0]) / scale2
    if not gain > MODEL_CRITICAL:
        return fitted
    a, force = settings[0], settings[1]
    slip_torque = sums[best][1]
    there = "" if slip_torque is None else f" (f {2.0 * slip_torque / (force * a):.3g} with it)"
    note = (f"model: the loop fits the {best!r} model better than {chosen!r} by {gain:.1f} residual variances "
            f"(above {MODEL_CRITICAL:.1f}, on its first {min(model_turning(fitted), CHECK_TURNING)} turning points)"
            f"{there}; f, G and the compliance depend on the contact model, so none is given: fit with "
            f"model={best!r} if that is the contact of the test")
    withheld = Estimate.withheld_by("model")
    result = replace(fitted.result, friction=withheld, shear_modulus=withheld, compliance=withheld, correlation=None,
                     warnings=(*fitted.result.warnings, note))
    return replace(fitted, result=result)


def model_turning(fitted) -> int:
    """The number of turning points of the record ``fitted`` holds."""
    return int(fitted.model.reversals.size)
