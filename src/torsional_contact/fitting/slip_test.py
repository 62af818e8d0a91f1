r"""Did the loop slip?  The critical value of the likelihood-ratio test of stick, by Davies' bound.

Units: those of the loop model (torque N m, twist rad).

The test compares the straight loop theta = theta_0 + C T (stick) with the full model by

    LR = (S_stick - S_full) / s^2,     s^2 = S_full / (N - P),

S the least sums of squared orthogonal distances.  Its null distribution is not chi-square: under
stick the slip torque T_s is not identified (any T_s above the largest torque gives the same straight
loop, and so does kappa = 0 with any T_s above 3/4 of it), and kappa >= 0 sits on its bound.  Near
the null the full model adds kappa times the score column s(T_s) = dd/dkappa at kappa = 0, for some
T_s between 3/4 and 1 times the largest torque, so that LR is the supremum over T_s of max(0, Z)^2,
Z(T_s) = s_perp . d / (s |s_perp|), a unit-variance Gaussian process in T_s (s_perp: s with the stick
model's own directions, C and theta_0, projected out).  Davies (1987, Biometrika 74, 33-43) bounds
its upper tail by the expected number of upcrossings of the level:

    P(LR > c) <= Phi(-sqrt(c)) + V / (2 pi) exp(-c / 2),

with V the length of the path of the unit vector s_perp / |s_perp| as T_s runs over its range.
``critical_value`` computes V for the record at hand (``GRID`` values of T_s, geometric towards the
largest torque, where the path turns fastest) and solves for c at the test's level.  The bound is
tight at small levels (its error is of the order of the probability of two upcrossings); without the
T_s search (V = 0) it is the one-sided chi-square point 2.71.  The coverage study and
``tests/test_fit.py`` check the false-alarm rate by simulation.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize, special  # normal tails from special: scipy.stats costs 0.5 s more to import

from .loop_model import LoopModel
from .parameters import KAPPA, OFFSET, vector
from .profile import is_large

__all__ = ["unit_scores", "path_length", "critical_value", "marginal_note", "GRID", "STRICT_LEVEL"]

#: Values of T_s on which the path of the unit score is followed: the critical value changes by less than
#: 0.05 from 40 to 1000 points (a change of the test's level below 1e-3), and costs about 10 ms.
GRID = 40
#: The range of T_s / max|T| where kappa adds to the straight loop: from the plateau (3/4) to the largest torque.
LOWEST_RATIO = 0.75
#: Closest approach of the grid to the largest torque, relative (the score vanishes there as (T* - 1)^3).
CLOSEST = 1e-5
#: For a model that slips at any torque, the grid of T_s reaches this many times the plateau's (the contact's twist
#: is then within a few per cent of linear in the torque, a direction of the straight loop).
UNBONDED_REACH = 30.0


def unit_scores(model: LoopModel, compliance: float, offset: float, foot: np.ndarray) -> np.ndarray:
    """The unit score s_perp / |s_perp| at ``GRID`` values of T_s (rows), over the samples (columns).

    ``compliance``, ``offset``: the stick fit; ``foot``: its foot points (the true twists under stick).
    The score is the derivative of the torque at the foot points with respect to kappa at kappa = 0
    (in the distances it is divided by the same constant for every sample, which the normalisation
    removes), with the stick model's directions (C, theta_0) projected out.
    """
    peak = float(np.max(np.abs(foot - offset))) / compliance  # the largest torque of the straight loop
    turning = foot[model.reversals]
    onset, gross = model.contact.slip_onset_torque, model.contact.gross_slip_torque
    if onset > 0:  # T_s from the plateau (peak / gross) to the slip onset at the largest torque (peak / onset)
        gap = np.geomspace(CLOSEST, 1.0 - onset / gross, GRID)
        ratios = (1.0 - gap)[::-1] / onset
    else:  # slip at any torque: from the plateau up to where the contact's twist is nearly linear in the torque
        ratios = np.geomspace(1.0 / gross, UNBONDED_REACH / gross, GRID)
    directions = []
    basis = None
    large = is_large(model.residual_count, model.size)  # a long record: the Jacobian sparse, three columns dense
    wanted = slice(KAPPA, OFFSET + 1)  # the columns of kappa, C and theta_0 (``fitting.parameters``)
    for ratio in ratios:
        p = vector(ratio * peak, 0.0, compliance, offset, turning)
        jac = model.torque_at(p, foot, jacobian=True, sparse=large)[3]
        columns = jac[:, wanted].toarray() if large else jac[:, wanted]  # kappa, C, theta_0
        if basis is None:  # the stick model's own directions (C, theta_0): the same at every T_s
            basis = np.linalg.qr(columns[:, 1:3])[0]
        score = columns[:, 0] - basis @ (basis.T @ columns[:, 0])
        norm = float(np.linalg.norm(score))
        if norm > 0:
            directions.append(score / norm)
    return np.array(directions).reshape(len(directions), foot.size)


def path_length(model: LoopModel, compliance: float, offset: float, foot: np.ndarray) -> float:
    """V: the length of the path of the unit score over T_s (module docstring; arguments of ``unit_scores``)."""
    unit = unit_scores(model, compliance, offset, foot)
    if unit.shape[0] < 2:
        return 0.0
    return float(np.sum(np.linalg.norm(np.diff(unit, axis=0), axis=1)))


def critical_value(length: float, level: float = 0.05) -> float:
    """c with Phi(-sqrt(c)) + V / (2 pi) exp(-c / 2) = level (module docstring)."""
    if not 0 < level < 0.5:
        raise ValueError(f"level must lie in (0, 0.5), got {level!r}")

    def excess(c):
        return special.ndtr(-math.sqrt(c)) + length / (2 * math.pi) * math.exp(-c / 2) - level

    low = float(special.ndtri(level)) ** 2  # the upper normal quantile, squared
    if length <= 0:
        return low
    high = max(2 * math.log(length / (2 * math.pi * level)) + 1.0, low) + 10.0
    return float(optimize.brentq(excess, low, high, xtol=1e-10))


#: The level at which a detected slip is also tested (``marginal_note``): a contact that stuck throughout passes the
#: test at 5 % in one record in twenty, with a friction value that is wrong (its interval excludes the truth); above
#: the critical value at this level in one in a thousand.
STRICT_LEVEL = 1e-3


def marginal_note(statistic: float, level: float, model: LoopModel, compliance: float, offset: float,
                  foot: np.ndarray) -> str | None:
    """The warning for a slip detected at ``level`` but not at ``STRICT_LEVEL`` (None otherwise); the other arguments
    are those of ``path_length``, whose V is computed only when the statistic lies below the largest critical value
    at ``STRICT_LEVEL`` any path of ``GRID`` points can give."""
    if level <= STRICT_LEVEL or statistic >= critical_value(2.0 * (GRID - 1), STRICT_LEVEL):
        return None
    strict = critical_value(path_length(model, compliance, offset, foot), STRICT_LEVEL)
    if statistic >= strict:
        return None
    return (f"marginal slip: the slip test's statistic {statistic:.3g} passes its critical value at level {level:g} "
            f"but not the {strict:.3g} at level {STRICT_LEVEL:g}; a contact that stuck throughout gives this in "
            f"about {level:.0%} of records, and its friction value is then wrong")
