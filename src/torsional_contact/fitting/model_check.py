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
shorter record) under each model, the chosen one included, by one least-squares fit each from the fit's own
parameters (``residual_sums``): each model's sum is then the minimum nearest the chosen model's loop, an upper
bound of its best, so that the check errs towards keeping the chosen model.  Loops in stick (a straight loop
under every model) are not checked.  The record is the one the final fit used (corrected for the defects
found), with the raw torque where the fit smoothed it: the smoothed channel's errors are correlated, and on it
the gain scattered twice as widely as the chi-square bound allows.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from scipy import special

from .. import models
from . import profile
from .loop_model import LoopModel
from .parameters import (
    COMPLIANCE,
    CORE,
    FIRST_TURNING,
    KAPPA,
    KAPPA_MAX,
    KAPPA_MIN,
    REVERSAL_REACH,
    SLIP_TORQUE,
    TURNING,
)
from .results import Estimate

__all__ = ["MODEL_LEVEL", "MODEL_CRITICAL", "CHECK_TURNING", "residual_sums", "checked_model"]

#: Level of the model check, and its critical value in residual variances (chi-square, one degree of freedom, at
#: that level: the difference of two residual sums of equal parameter counts, strict because several models are
#: tried on every record).
MODEL_LEVEL = 1e-4
MODEL_CRITICAL = float(special.chdtri(1, MODEL_LEVEL))
#: Turning points of the stretch the check fits (two cycles from the virgin state).
CHECK_TURNING = 4
#: The key of ``residual_sums``'s output under which the models that could not be fitted are given, {name: reason}.
FAILED = "could not be fitted"


def _stretch(torque, twist, reversals):
    """(torque, twist, reversals) of the record's first ``CHECK_TURNING`` turning points (the whole record when it has
    no more; else the samples up to the next turning point, whose branch ends the stretch)."""
    if reversals.size <= CHECK_TURNING:
        return torque, twist, reversals
    end = int(reversals[CHECK_TURNING]) + 1
    return torque[:end], twist[:end], reversals[:CHECK_TURNING]


def _lean_fit(torque, twist, reversals, torque_noise, twist_noise, contact, start):
    """(residual sum, slip torque) of the loop of ``contact`` fitted from ``start`` alone, within the fit's bounds
    (``parameters``: kappa, the turning points' reach; T_s and C positive), by ``profile.fit``."""
    model = LoopModel(torque, twist, reversals, torque_noise, twist_noise, contact)
    lower, upper = np.full(start.size, -np.inf), np.full(start.size, np.inf)
    peak = float(np.max(np.abs(torque)))
    lower[CORE] = [1e-9 * peak, KAPPA_MIN, 1e-6 * start[COMPLIANCE]]
    upper[KAPPA] = KAPPA_MAX
    reach = REVERSAL_REACH * math.hypot(twist_noise, start[COMPLIANCE] * torque_noise)
    lower[TURNING], upper[TURNING] = twist[reversals] - reach, twist[reversals] + reach
    start = np.clip(start, lower, upper)
    p, s, _ = profile.fit(model, start, lower, upper)
    return float(s), float(p[SLIP_TORQUE])


def residual_sums(fitted, record=None, smooth=None) -> dict:
    """{model name: (residual sum, slip torque)} of every model of the table on the stretch of the record that
    ``fitted`` (a ``loop_fit.Fitted`` of a slipping loop) holds, each fitted from the fit's own parameters (its slip
    torque moved so that the gross-slip plateau stays where it was: the models share every parameter; a grid of
    starts per model doubled the cost of a short record's fit), and the degrees of freedom under the key None; a model
    other than the chosen one that raises on this loop (ValueError, ArithmeticError, RuntimeError) is left out and
    named under the key ``FAILED``, {name: reason}.
    ``record`` and ``smooth``: the prepared record and its ``smoothing.SmoothTorque`` when the fit smoothed the
    torque (the raw samples are then used)."""
    model = fitted.model
    torque, torque_noise = model.torque, model.torque_noise
    if smooth is not None:  # the fitted torque (its corrections included) with the spline's residual put back
        residual = np.asarray(record.torque, dtype=float) - smooth.torque
        torque, torque_noise = torque + residual[residual.size - torque.size:], smooth.raw_noise
    torque, twist, reversals = _stretch(torque, model.twist, model.reversals)
    out = {None: max(torque.size - 4, 1)}
    chosen = model.contact
    base = np.array(fitted.p, dtype=float)[:FIRST_TURNING + reversals.size]
    whole = reversals.size == model.reversals.size and smooth is None  # the stretch is the fitted record itself
    contacts = {name: models.get(name) for name in models.names()}
    contacts[chosen.name] = chosen  # a model passed as an object, not in the table, is compared all the same
    for name, contact in contacts.items():
        if contact is chosen and whole:  # the fit's own minimum, on the same samples
            r = model.distances(fitted.p)
            out[name] = (float(r @ r), float(fitted.p[SLIP_TORQUE]))
            continue
        start = base.copy()
        start[SLIP_TORQUE] *= chosen.gross_slip_torque / contact.gross_slip_torque
        if contact is chosen:
            out[name] = _lean_fit(torque, twist, reversals, torque_noise, model.twist_noise, contact, start)
            continue
        # another model of the table, perhaps one a user registered: when it cannot be evaluated on this loop, the
        # fit under the chosen model stands and the check says which model it could not compare (never a traceback
        # from a model the user did not ask for)
        try:
            out[name] = _lean_fit(torque, twist, reversals, torque_noise, model.twist_noise, contact, start)
        except (ValueError, ArithmeticError, RuntimeError) as error:
            out.setdefault(FAILED, {})[name] = f"{type(error).__name__}: {error}"
    return out


def checked_model(fitted, settings, record=None, smooth=None):
    """``fitted`` (a ``loop_fit.Fitted`` of a slipping loop) unchanged when no other model of the table fits its record
    better by more than ``MODEL_CRITICAL`` residual variances; else with no friction value, modulus or compliance
    (``Estimate.withheld`` "model") and a ``model`` warning (module docstring; ``record`` and ``smooth`` as
    ``residual_sums`` takes them).  A model of the table that could not be fitted to the loop is named in a ``model
    check`` warning and left out of the comparison."""
    if fitted.p is None:
        return fitted
    chosen = fitted.model.contact.name
    sums = residual_sums(fitted, record, smooth)
    dof = sums.pop(None)
    failed = sums.pop(FAILED, {})
    if failed:
        notes = tuple(f"model check: the {name!r} model could not be fitted to this loop ({reason}); the check "
                      f"compared {chosen!r} with the other models only" for name, reason in failed.items())
        fitted = replace(fitted, result=replace(fitted.result, warnings=(*fitted.result.warnings, *notes)))
    best = min(sums, key=lambda name: sums[name][0])
    scale2 = sums[best][0] / dof
    if best == chosen or not scale2 > 0:
        return fitted
    gain = (sums[chosen][0] - sums[best][0]) / scale2
    if not gain > MODEL_CRITICAL:
        return fitted
    a, force = settings[0], settings[1]
    there = f" (f {2.0 * sums[best][1] / (force * a):.3g} with it)"
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
