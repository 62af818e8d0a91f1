r"""A measured loop as the fit sees it: checked samples, noise levels, turning points of the twist.

Units: torque in N m, twist in rad (SI floats; ``units`` converts at the boundary).

* ``checked_loop``: two equal-length 1-d arrays of finite numbers, at least ``MIN_SAMPLES``
  samples, both channels varying.  A bad sample is named by its index.
* ``noise_level``: the standard deviation of white measurement noise on one channel,
  estimated from its second differences, x[i+1] - 2 x[i] + x[i-1] (variance 6 sigma^2 for
  white noise; a signal smooth on the sampling scale contributes its curvature, h^2 x'', far
  below the noise at the sampling rates of a loop), robustly: 1.4826 times their median
  absolute deviation over sqrt(6), so that the few samples at kinks (reversals, the slip onset
  in time) do not count.  Correlated (filtered) noise is underestimated: give the levels
  explicitly then; the fit's residual scale corrects the overall level either way.
* ``turning_points``: the reversals of the twist, the driving channel of the model
  (``fitting.masing``): a reversal counts once the twist has retreated from its running
  extreme by more than ``threshold`` (8 noise levels, at least 1e-3 of the twist range), so
  that noise near a turning point makes no reversals of its own.  A genuine reversal smaller
  than that is missed: the samples on it are then fitted as part of the branch around it.

  The hysteresis gate of the histories (``histories.gate``) is a filter of the same family (a
  reversal counts once the signal retreats by a threshold from its running extreme) and they are
  kept apart on purpose: the gate filters a torque history that starts at the virgin torque 0
  and decides whether the first extreme is a turning point by the half loop it closes (2 |T_1|
  against the gate, the memory rules' own criterion), and it returns the gated signal; the fit's
  filter works on a twist with an arbitrary zero (the twist of the virgin state is a fitted
  parameter, so no sample is known to be the origin), its threshold is set by the channel's noise,
  and it returns the indices of the extreme samples, which keep their own residuals in the fit.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["MIN_SAMPLES", "checked_loop", "noise_level", "turning_points", "reversal_threshold"]

#: Fewest samples a loop may have: four parameters and the turning points need several samples each.
MIN_SAMPLES = 20
#: The reversal threshold in noise levels of the twist, and as a fraction of the twist range.
THRESHOLD_NOISE, THRESHOLD_RANGE = 8.0, 1e-3


def _channel(name: str, values) -> np.ndarray:
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a 1-d sequence of real numbers, got {type(values).__name__}") from None
    if array.ndim != 1:
        raise ValueError(f"{name} must be a 1-d sequence of real numbers, got shape {array.shape}")
    bad = ~np.isfinite(array)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}[{i}] must be a finite number, got {float(array[i])!r}")
    return array


def checked_loop(torque, twist) -> tuple[np.ndarray, np.ndarray]:
    """(torque, twist) as float arrays, or ValueError naming the argument (and the bad sample)."""
    torque, twist = _channel("torque", torque), _channel("twist", twist)
    if torque.size != twist.size:
        raise ValueError(f"torque and twist must have the same number of samples, got {torque.size} and {twist.size}")
    if torque.size < MIN_SAMPLES:
        raise ValueError(f"a loop needs at least {MIN_SAMPLES} samples (torque and twist in time order), got "
                         f"{torque.size}")
    for name, array in (("torque", torque), ("twist", twist)):
        if np.ptp(array) == 0:
            raise ValueError(f"{name} must vary along the loop, got a constant {array[0]!r}")
    return torque, twist


def noise_level(values: np.ndarray) -> float:
    """Robust standard deviation of white noise on ``values`` from their second differences (module docstring)."""
    second = np.diff(np.asarray(values, dtype=float), 2)
    mad = float(np.median(np.abs(second - np.median(second))))
    return 1.4826 * mad / math.sqrt(6.0)


def reversal_threshold(twist: np.ndarray, twist_noise: float) -> float:
    """Retreat of the twist (rad) that makes a reversal (module docstring)."""
    return max(THRESHOLD_NOISE * twist_noise, THRESHOLD_RANGE * float(np.ptp(twist)))


def turning_points(twist: np.ndarray, threshold: float) -> np.ndarray:
    """Indices of the reversals of ``twist`` (each at the sample of the extreme), first and last samples excluded."""
    x = np.asarray(twist, dtype=float)
    start = x[0]
    moved = np.flatnonzero(np.abs(x - start) > threshold)
    if moved.size == 0:
        return np.zeros(0, dtype=int)
    heading = 1.0 if x[moved[0]] > start else -1.0
    extreme = int(moved[0])
    found = []
    values = x.tolist()
    best = values[extreme]
    for i in range(extreme + 1, len(values)):
        v = values[i]
        if heading * (v - best) > 0:
            best, extreme = v, i
        elif heading * (best - v) > threshold:
            found.append(extreme)
            heading = -heading
            best, extreme = v, i
    return np.array(found, dtype=int)
