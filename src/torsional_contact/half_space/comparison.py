r"""The half-space model against the finite cylinders: energy per cycle and a friction fit.

Units: torque ranges A = Delta T* = 2 Delta T / (f F a); energies in (f p0)^2 a^3 / mu =
(f F)^2 / (pi^2 mu a).

A friction fit with the wrong model
-----------------------------------
An experimenter twists two cylinders (radius a, normal force F, shear modulus mu known) through
a torque range Delta T and measures the energy E dissipated per cycle (the area of the
torque-twist loop).  Fitting the half-space model means solving

    E = (f_fit F)^2 / (pi^2 mu a) W_hs(2 Delta T / (f_fit F a))

for f_fit (W_hs of ``closed_form.dissipation_per_cycle``).  If the specimens are the paper's
cylinders with friction f, then E = (f F)^2 / (pi^2 mu a) W_cyl(A), A = 2 Delta T / (f F a), so
the ratio kappa = f_fit / f depends on A alone:

    kappa^2 W_hs(A / kappa) = W_cyl(A).                                                  (C1)

kappa^2 W_hs(A / kappa) falls monotonically from +inf at kappa = 3A/8 (the half-space spins)
to 0 as kappa -> inf (W_hs ~ c x^4, so kappa^2 W_hs ~ c A^4 / kappa^2): its kappa-derivative is
kappa [2 W_hs(x) - x W_hs'(x)], x = A / kappa, negative since the logarithmic slope of W_hs is
at least 4 (4 as x -> 0 by (H13), growing to +inf at x = 8/3; checked on a grid in
tests/test_half_space.py).  So (C1) has exactly one root for W_cyl(A) > 0, i.e. A > 2, and
kappa > 1 there (W_hs > W_cyl at every range: the half-space always dissipates more); for
A <= 2 the cylinders dissipate nothing and no finite friction coefficient reproduces that
(kappa = +inf: the fit reports a contact that never slips).  The root is bracketed and found by Brent's method.
"""

from __future__ import annotations

import math

from scipy import optimize

from .. import validation
from ..criteria import GROSS_SLIP_TORQUE
from ..histories.energy import dissipation_per_cycle as cylinder_dissipation
from . import closed_form

__all__ = ["energy_per_cycle", "apparent_friction_ratio"]


def energy_per_cycle(torque_range, model: str) -> float:
    """W(A) of a closed loop of torque range 0 <= A <= 8/3 for ``model`` ("cylinder" or "half-space")."""
    a = validation.real_number("torque_range", torque_range, 0.0, 2 * GROSS_SLIP_TORQUE)
    if model == "half-space":
        return float(closed_form.dissipation_per_cycle(a))
    validation.choice("model", model, ("cylinder", "half-space"))
    return float(cylinder_dissipation(a))


def apparent_friction_ratio(torque_range, *, xtol: float = 1e-14) -> float:
    """kappa = f_fit / f of (C1): the half-space energy law fitted to the cylinders' energy per cycle.

    Parameters
    ----------
    torque_range : float
        The true normalised range A = 2 Delta T / (f F a) of the cylinder test, 0 <= A <= 8/3.

    Returns
    -------
    float
        +inf for A <= 2 (the cylinders do not dissipate), otherwise the root of (C1).
    """
    a = validation.real_number("torque_range", torque_range, 0.0, 2 * GROSS_SLIP_TORQUE)
    target = energy_per_cycle(a, "cylinder")
    if target <= 0.0:
        return math.inf
    if math.isinf(target):
        return 1.0 if a >= 2 * GROSS_SLIP_TORQUE else math.inf

    def mismatch(log_kappa):
        kappa = math.exp(log_kappa)
        return math.log(kappa * kappa * 4.0 * closed_form.state(0.5 * a / kappa)[2]) - math.log(target)

    lower = math.log(a / (2 * GROSS_SLIP_TORQUE)) + 1e-12  # just above the half-space's spinning
    upper = lower + 1.0
    while mismatch(upper) > 0:
        upper += 1.0
    return math.exp(optimize.brentq(mismatch, lower, upper, xtol=xtol))
