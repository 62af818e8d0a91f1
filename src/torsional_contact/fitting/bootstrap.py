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
"""

from __future__ import annotations

import numpy as np
from scipy import special  # the normal quantiles (scipy.stats: the same functions, 0.5 s more to import)

from .loop_model import LoopModel
from .profile import fit

__all__ = ["bootstrap_intervals", "bias_corrected_percentiles"]


def bias_corrected_percentiles(replicates, estimate: float, confidence: float):
    """The bias-corrected percentile interval of ``replicates`` about ``estimate`` (module docstring).

    Returns (lower, upper); None at an end that a replicate pinned to a bound cannot place.
    """
    r = np.sort(np.asarray(replicates, dtype=float))
    below = (np.count_nonzero(r < estimate) + 0.5 * np.count_nonzero(r == estimate)) / r.size
    below = min(max(below, 0.5 / r.size), 1.0 - 0.5 / r.size)
    z0 = float(special.ndtri(below))
    z = float(special.ndtri(0.5 + confidence / 2))
    probabilities = special.ndtr([2 * z0 - z, 2 * z0 + z])
    return tuple(float(np.quantile(r, q)) for q in probabilities)


def bootstrap_intervals(model: LoopModel, p, scale2: float, count: int, confidence: float, seed, lower, upper,
                        kappa_max: float) -> dict:
    """{"slip_torque", "product", "compliance"}: (lower, upper) bias-corrected percentile intervals."""
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
        world = LoopModel(torque, twist, model.reversals, model.torque_noise, model.twist_noise)
        q = fit(world, p, lower, upper, kappa_max=kappa_max)[0]
        replicates[b] = (q[0], q[1] * q[2], q[2])
    estimates = (p[0], p[1] * p[2], p[2])
    out = {}
    for j, name in enumerate(("slip_torque", "product", "compliance")):
        lo, hi = bias_corrected_percentiles(replicates[:, j], estimates[j], confidence)
        if name == "product" and lo <= 0.0:
            lo = None  # 1/G at its bound 0: no upper end of G
        out[name] = (lo, hi)
    return out
