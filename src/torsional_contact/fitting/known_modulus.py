r"""The loop fit with the shear modulus known: f and the compliance, and the rig's own compliance apart.

Units: modulus Pa, compliance rad / (N m), lengths m, torque N m.

With G known, the contact's twist per unit omega is known up to T_s: kappa C = y = k / T_s with
k = e f p-bar / G, i.e. y = 2 e / (pi a^3 G) (e = ``ContactModel.elastic_bodies``), and the fit
holds y there (``profile.Constraint("product", y)``): f (from T_s), C, the twist zero and the
turning points are fitted.  Their intervals are Wald intervals from the constrained fit's
Jacobian (value +- t s, Student's t with N - 3 degrees of freedom); with G fixed the ridge along
which T_s and kappa trade off is gone, and the likelihood is close to quadratic in T_s and C.

Without G the fitted modulus is what the loop's curvature says: an effective modulus of the
contact, which absorbs the asperities' and the rig's nonlinear compliance; and C is an effective
compliance that lumps the shaft's L/(G J) with the rig's.  With G and the gauge length L (the
shafts' length between the twist's two cross-sections; only for models whose bodies are shafts,
``ContactModel.shaft``) the shafts' compliance L / (G J), J = pi a^4 / 2, is taken out:
``rig_compliance`` = C - L / (G J), with C's standard error and interval shifted by it.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from scipy import special

from . import profile as profiles
from .parameters import COMPLIANCE, KAPPA, SLIP_TORQUE, TURNING
from .results import Estimate

__all__ = ["with_known_modulus", "shaft_compliance"]


def shaft_compliance(contact, radius: float, shear_modulus: float, gauge_length: float) -> float:
    """L / (G J), J = pi a^4 / 2 (rad / (N m)); ValueError for a model whose bodies are not shafts."""
    if not contact.shaft:
        raise ValueError(f"gauge_length does not apply to model {contact.name!r} ({contact.bodies} are not shafts: "
                         "the twist is the relative rotation of remote points)")
    return gauge_length / (shear_modulus * 0.5 * math.pi * radius**4)


def with_known_modulus(fitted, shear_modulus: float, gauge_length: float | None, radius: float, normal_force: float,
                       confidence: float, kappa_bounds: tuple[float, float], reach: float):
    """The ``LoopFit`` of ``fitted`` (``loop_fit.Fitted``) refitted with G = ``shear_modulus`` (module docstring).

    ``kappa_bounds``: the fit's (KAPPA_MIN, KAPPA_MAX); ``reach``: how far (rad) a turning point may move from its
    sample.
    """
    result, model = fitted.result, fitted.model
    contact = model.contact
    shaft = None if gauge_length is None else shaft_compliance(contact, radius, shear_modulus, gauge_length)
    modulus = Estimate(shear_modulus, None, (shear_modulus, shear_modulus))
    notes = list(result.warnings)
    compliance = result.compliance
    # a check that withheld the friction (a lag that explains the loop as well as slip, a contact model the loop
    # rejects: ``Estimate.withheld``) is not overridden by knowing G
    if fitted.p is not None and result.friction.withheld is None:
        y = 2.0 * contact.elastic_bodies / (math.pi * radius**3 * shear_modulus)
        p = np.array(fitted.p, dtype=float)
        kappa_min, kappa_max = kappa_bounds
        lower = np.full(p.size, -np.inf)
        upper = np.full(p.size, np.inf)
        lower[SLIP_TORQUE], lower[KAPPA], lower[COMPLIANCE] = 1e-9 * p[SLIP_TORQUE], kappa_min, 1e-9 * p[COMPLIANCE]
        upper[KAPPA] = kappa_max
        turning = model.twist[model.reversals]
        lower[TURNING], upper[TURNING] = turning - reach, turning + reach
        # C within what the bounds on kappa allow for this y
        p[COMPLIANCE] = min(max(p[COMPLIANCE], y / kappa_max * (1 + 1e-9)), y / kappa_min * (1 - 1e-9))
        p[KAPPA] = y / p[COMPLIANCE]
        constraint = profiles.Constraint("product", y)
        p, s, fit = profiles.fit(model, p, lower, upper, constraint, kappa_max)
        dof = model.torque.size - 3
        cov = profiles.covariance(fit.jac, s / dof)
        t = float(special.stdtrit(dof, 0.5 + confidence / 2))
        to_f = 2.0 / (radius * normal_force)
        # the covariance of the free parameters q (y held: no kappa), T_s and C at their places there
        i_ts, i_c = constraint.position(SLIP_TORQUE), constraint.position(COMPLIANCE)
        se_ts, se_c = math.sqrt(max(cov[i_ts, i_ts], 0.0)), math.sqrt(max(cov[i_c, i_c], 0.0))
        ts, c = p[SLIP_TORQUE], p[COMPLIANCE]
        friction = Estimate(to_f * ts, to_f * se_ts, (to_f * (ts - t * se_ts), to_f * (ts + t * se_ts)))
        compliance = Estimate(float(c), se_c, (c - t * se_c, c + t * se_c))
        if p[KAPPA] <= kappa_min * (1 + 1e-6) or p[KAPPA] >= kappa_max * (1 - 1e-6):
            notes.append(f"shear modulus: with G = {shear_modulus:.4g} Pa the fitted compliance sits at the model's "
                         f"bound on kappa = k / (C T_s) (in [{kappa_min:g}, {kappa_max:g}]): G does not fit this loop")
        result = replace(result, friction=friction, compliance=compliance, shear_modulus=modulus, correlation=None,
                         interval_method="wald (G fixed)", parameters=p, dof=int(dof),
                         message=result.message + f"; refitted with G fixed at {shear_modulus:.4g} Pa")
    else:
        result = replace(result, shear_modulus=modulus)
    rig = None
    if shaft is not None and compliance.value is not None:
        lo, hi = compliance.interval
        rig = Estimate(compliance.value - shaft, compliance.stderr,
                       (None if lo is None else lo - shaft, None if hi is None else hi - shaft))
        if rig.value < 0 and (hi is None or hi - shaft < 0):
            notes.append(f"rig compliance: the shafts' L / (G J) = {shaft:.4g} rad/(N m) exceeds the fitted compliance "
                         "(a gauge length or modulus too large, or sections closer than 2 a to the interface)")
    return replace(result, rig_compliance=rig, warnings=tuple(notes))
