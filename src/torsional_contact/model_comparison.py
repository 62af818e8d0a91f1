r"""Contact models against each other: energy per cycle, and the friction a fit under the wrong model returns.

Units: torque ranges A = Delta T* = 2 Delta T / (f F a); energies in (f p-bar)^2 a^3 / mu =
(f F)^2 / (pi^2 mu a).

A friction fit with the wrong model
-----------------------------------
An experimenter twists a contact (radius a, normal force F, shear modulus mu known) through a
torque range Delta T and measures the energy E dissipated per cycle (the area of the torque-twist
loop).  Fitting an assumed model (energy law W_as of ``ContactModel.energy_per_cycle``) means
solving

    E = (f_fit F)^2 / (pi^2 mu a) W_as(2 Delta T / (f_fit F a))

for f_fit.  If the contact is in truth the model W_tr with friction f, then E = (f F)^2 / (pi^2
mu a) W_tr(A), A = 2 Delta T / (f F a), so the ratio kappa = f_fit / f depends on A alone:

    kappa^2 W_as(A / kappa) = W_tr(A).                                                   (C1)

kappa^2 W_as(A / kappa) is +inf where the assumed contact spins (kappa at or below A / (2 T*_gs,as))
and falls to 0 as kappa grows, monotonically when the logarithmic slope of W_as exceeds 2 (its
kappa-derivative is kappa [2 W_as(x) - x W_as'(x)], x = A / kappa): 4 for the uniform half-space
(W ~ x^4, (H13) of ``half_space.closed_form``), 3 for the cylinders just above their threshold
((pi^4/3)(x/2 - 1)^3 grows from zero) and the Hertzian contact (Mindlin's cube law), all rising to
+inf at spinning (checked on a grid in the tests).  So (C1) has exactly one root when W_tr(A) > 0;
where the true contact dissipates nothing (the cylinders for A <= 2) no finite friction reproduces
that (kappa = +inf: the fit reports a contact that never slips).  The root is bracketed and found
by Brent's method on log kappa.  For the half-space fitted to the cylinders, kappa > 1 at every
range (the half-space always dissipates more).

This is the friction read from partial-slip dissipation; read from a gross-slip plateau both
models give the true f (the plateau torque f F a T*_gs / 2 of each model is known), which is why
the comparison matters only below gross slip.
"""

from __future__ import annotations

import math

from scipy import optimize

from . import models, validation

__all__ = ["energy_per_cycle", "apparent_friction_ratio"]


def energy_per_cycle(torque_range, model=None) -> float:
    """W(A) of a closed loop of torque range A for ``model`` (``ContactModel.energy_per_cycle``)."""
    return float(models.get(model).energy_per_cycle(torque_range))


def apparent_friction_ratio(torque_range, *, true_model=None, assumed_model="half-space", xtol: float = 1e-14) -> float:
    """kappa = f_fit / f of (C1): the ``assumed_model`` energy law fitted to ``true_model``'s energy per cycle.

    Parameters
    ----------
    torque_range : float
        The true normalised range A = 2 Delta T / (f F a), 0 <= A <= twice the true model's gross-slip torque.
    true_model, assumed_model : str or ContactModel
        The contact tested (default the cylinders) and the one fitted (default the uniform half-space).

    Returns
    -------
    float
        +inf where the true contact does not dissipate, 1.0 where both spin at the same torque and A
        reaches it, otherwise the root of (C1).
    """
    truth, assumed = models.get(true_model), models.get(assumed_model)
    a = validation.real_number("torque_range", torque_range, 0.0, 2 * truth.gross_slip_torque)
    target = truth.energy_per_cycle(a)
    if target <= 0.0:
        return math.inf
    spin = a / (2.0 * assumed.gross_slip_torque)  # the assumed contact spins for kappa <= spin
    if math.isinf(target):
        return spin if spin > 0 else math.inf

    def mismatch(log_kappa):
        kappa = math.exp(log_kappa)
        x = min(a / kappa, 2.0 * assumed.gross_slip_torque)
        value = kappa * kappa * assumed.energy_per_cycle(x)
        return (math.log(value) if value > 0 else -745.0) - math.log(target)

    lower = math.log(spin) + 1e-12  # just above the assumed contact's spinning
    upper = lower + 1.0
    while mismatch(upper) > 0:
        upper += 1.0
    return math.exp(optimize.brentq(mismatch, lower, upper, xtol=xtol))
