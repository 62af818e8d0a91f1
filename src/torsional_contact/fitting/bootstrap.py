r"""Parametric bootstrap of the loop fit: bias-corrected percentile intervals of T_s, y = kappa C and C.

Units: those of the loop model (torque N m, twist rad, compliance rad / (N m)).

The fitted curve and the fitted noise (s_T and s_theta times the fit's noise scale) define a
world in which the truth is known: the true state of sample i is the foot point (u_i*,
g(u_i*)) of the fit.  ``bootstrap_intervals`` draws ``count`` records in it (white Gaussian
noise on both channels, the record's reversal indices kept), refits each from the fitted
parameters (``fitting.profile.fit``), and returns for each quantity psi the bias-corrected
percentile interval (Efron, 1982): with z_0 = Phi^-1(fraction of the refits below psi_hat) and
z the normal quantile of the level,

    [Q(Phi(2 z_0 - z)), Q(Phi(2 z_0 + z))],        Q: the quantiles of the refits.

It corrects the median bias of the estimator and follows a skewed sampling distribution; it
inherits the fitted parameters as the truth, so that where the fit itself is far off (a loop
that barely identifies G) it is no better than the profile interval.  Its Monte Carlo error at
``count`` refits is about sqrt(q (1 - q) / count) / density at each end: use a few hundred
refits.  Cost: ``count`` fits (about 10-30 ms each for a few hundred samples).

Resolution.  B refits resolve a level q only within [1/(B + 1), B/(B + 1)] (the (B + 1) q-th
order statistic must exist).  A level beyond it puts the end at the smallest or largest refit,
short of the bias-corrected end: the interval comes out too narrow, and the more so the larger
|z_0| (at B = 40 and z_0 = -1.4, a sixth of the width; an estimator biased by one standard error,
as C of a twist-controlled gross-slip loop with a small contact twist, has |z_0| ~ 1).  Such an
end is reported as unresolved, with the number of refits that would resolve it
(``BootstrapInterval``); ``fit_loop`` says so in its message and warns.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special  # the normal quantiles (scipy.stats: the same functions, 0.5 s more to import)

from .loop_model import LoopModel
from .parameters import COMPLIANCE, KAPPA, SLIP_TORQUE
from .profile import fit
from .results import Estimate

__all__ = ["bootstrap_intervals", "bias_corrected_percentiles", "bias_correction", "percentile_levels",
           "unresolved_ends", "BootstrapInterval", "with_bootstrap", "unresolved_note"]


@dataclass(frozen=True)
class BootstrapInterval:
    """One quantity's bootstrap: ``interval`` (lower, upper), the bias correction ``bias`` = z_0, the ends
    (``"lower"``, ``"upper"``) whose level the refits do not resolve (module docstring, "Resolution"), and
    ``refits_needed``, the fewest refits that would resolve both (None: both are resolved)."""

    interval: tuple
    bias: float
    unresolved: tuple = ()
    refits_needed: int | None = None


def bias_correction(replicates, estimate: float) -> float:
    """z_0 = Phi^-1(fraction of ``replicates`` below ``estimate``, ties counted half), the fraction kept within
    [1/(2B), 1 - 1/(2B)] for B replicates (so that z_0 is finite)."""
    r = np.asarray(replicates, dtype=float)
    below = (np.count_nonzero(r < estimate) + 0.5 * np.count_nonzero(r == estimate)) / r.size
    below = min(max(below, 0.5 / r.size), 1.0 - 0.5 / r.size)
    return float(special.ndtri(below))


def percentile_levels(bias: float, confidence: float) -> tuple:
    """The levels (Phi(2 z_0 - z), Phi(2 z_0 + z)) of the bias-corrected ends, z the normal quantile of the level."""
    z = float(special.ndtri(0.5 + confidence / 2))
    lower, upper = special.ndtr([2 * bias - z, 2 * bias + z])
    return float(lower), float(upper)


def unresolved_ends(levels, count: int) -> tuple:
    """(ends, refits): the ends ("lower", "upper") whose level lies outside [1/(B + 1), B/(B + 1)] for B = ``count``
    refits, and the fewest refits that resolve both levels (None when both are resolved)."""
    lower, upper = levels
    ends = tuple(name for name, tail in (("lower", lower), ("upper", 1.0 - upper)) if (count + 1) * tail < 1.0)
    if not ends:
        return (), None
    tail = min(lower, 1.0 - upper)
    return ends, math.ceil(1.0 / tail) - 1 if tail > 0 else None


def bias_corrected_percentiles(replicates, estimate: float, confidence: float):
    """The bias-corrected percentile interval of ``replicates`` about ``estimate`` (module docstring).

    Returns (lower, upper); None at an end that a replicate pinned to a bound cannot place.
    """
    r = np.sort(np.asarray(replicates, dtype=float))
    probabilities = percentile_levels(bias_correction(r, estimate), confidence)
    return tuple(float(np.quantile(r, q)) for q in probabilities)


def bootstrap_intervals(model: LoopModel, p, scale2: float, count: int, confidence: float, seed, lower, upper,
                        kappa_max: float) -> dict:
    """{"slip_torque", "product", "compliance"}: their ``BootstrapInterval`` (bias-corrected percentile intervals,
    z_0 and the ends the ``count`` refits do not resolve)."""
    rng = np.random.default_rng(seed)
    p = np.asarray(p, dtype=float)
    true_twist = model.foot_points(p).copy()
    true_torque = model.torque_at(p, true_twist)[0]
    s_t = model.torque_noise * np.sqrt(scale2)
    s_w = model.twist_noise * np.sqrt(scale2)
    replicates = np.empty((count, 3))
    for b in range(count):
        torque = true_torque + s_t * rng.standard_normal(true_torque.size)
        twist = true_twist + s_w * rng.standard_normal(true_twist.size)
        world = LoopModel(torque, twist, model.reversals, model.torque_noise, model.twist_noise, model.contact)
        q = fit(world, p, lower, upper, kappa_max=kappa_max)[0]
        replicates[b] = (q[SLIP_TORQUE], q[KAPPA] * q[COMPLIANCE], q[COMPLIANCE])
    estimates = (p[SLIP_TORQUE], p[KAPPA] * p[COMPLIANCE], p[COMPLIANCE])
    out = {}
    for j, name in enumerate(("slip_torque", "product", "compliance")):
        bias = bias_correction(replicates[:, j], estimates[j])
        levels = percentile_levels(bias, confidence)
        lo, hi = (float(np.quantile(replicates[:, j], q)) for q in levels)
        if name == "product" and lo <= 0.0:
            lo = None  # 1/G at its bound 0: no upper end of G
        ends, refits = unresolved_ends(levels, count)
        out[name] = BootstrapInterval((lo, hi), bias, ends, refits)
    return out


def with_bootstrap(estimate: Estimate, interval, factor: float, bias: float) -> Estimate:
    """``estimate`` with its bootstrap interval (the quantity's, times ``factor``) and bias correction z_0."""
    lo, hi = interval
    scaled = (None if lo is None else factor * lo, None if hi is None else factor * hi)
    return Estimate(estimate.value, estimate.stderr, estimate.interval, estimate.identified, estimate.lower_bound,
                    scaled, estimate.assumed_end, bias)


def unresolved_note(boot: dict, count: int) -> str:
    """What the message says of bootstrap ends at levels ``count`` refits do not resolve ("" if none)."""
    flipped = {"lower": "upper", "upper": "lower"}
    ends, needed, total = [], [], 0
    for key, symbol in (("slip_torque", "f"), ("product", "G"), ("compliance", "C")):
        item = boot[key]
        names = sorted(flipped[e] if key == "product" else e for e in item.unresolved)
        if not names:
            continue
        bias = -item.bias if key == "product" else item.bias  # G's own z_0 (``Estimate.bootstrap_bias``)
        ends.append(f"the {' and '.join(names)} end{'s' if len(names) > 1 else ''} of {symbol} (z_0 = {bias:.2f})")
        total += len(names)
        if item.refits_needed is not None:
            needed.append(item.refits_needed)
    if not ends:
        return ""
    several = total > 1
    more = f"; about {max(needed)} refits resolve {'them' if several else 'it'}" if needed else ""
    return (f"bootstrap: the bias-corrected level{'s' if several else ''} of {' and '.join(ends)} "
            f"lie{'' if several else 's'} beyond what {count} refits resolve (1/{count + 1} from either side): "
            f"{'such an end is' if several else 'that end is'} the extreme refit, and the bootstrap interval too "
            f"narrow{more}")
