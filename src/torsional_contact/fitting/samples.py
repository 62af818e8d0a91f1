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
* ``refined_reversals``: the sample that stands for each reversal, chosen by the vertex of the
  drive's turning in time rather than by the extreme of the noisy twist (below).

Which sample is the reversal
----------------------------
The fit takes the reversal's own sample as the turning point's true state (``fitting.loop_model``),
so the sample must be chosen without looking at its own noise.  The extreme of the measured twist is
not: near a turning point the twist is flat over many samples (``W`` within the noise: about 10 at
100 samples per cycle, 50 at 1000), and the largest of them carries a noise that is biased outward
by about the expected maximum of W normal deviates (1.5 noise levels at W = 10).  The turning point
is then placed outside the loop on every branch: a bias that does not fall with the record's length
while the intervals do (synthetic rig, torque-controlled partial slip, twist noise 1e-5 rad and an
exact torque, 20 cycles of 100 samples, eight seeds: f 1.7 standard errors high on average, up to
5.3; with the true reversal samples -0.7 +- 0.4; with ``refined_reversals`` -0.4 +- 0.3).
``refined_reversals`` takes the cap of each turning (the samples about the extreme whose twist lies
within the reversal threshold of it, between the neighbouring reversals) and, for every sample of the
cap as a candidate vertex v, fits each channel by a two-sided parabola x = c + a (k - v)^2 before v
and c + b (k - v)^2 after it (the twist of a torque-controlled loop turns with different curvatures on
the two sides: the arriving branch slips, the departing one starts elastic; the torque of a
twist-controlled gross-slip loop is flat before and falls after), with quartic terms of each side where
the parabola's chi-square exceeds its degrees of freedom by more than ``TURNING_FIT`` standard
deviations (the wide cap of a nearly exact channel, whose sinusoid's quartic term is many noise levels).
The vertex is the candidate of least chi-square summed over the two channels, each in its own noise
level (the joint maximum likelihood of the turning's time on the sample grid): a rate-independent
contact turns both channels at the same instant.  Checked (``tests/test_fit_smoothing.py``): the
chosen samples' own noise averages to zero within its standard error at 100 and 1000 samples per
cycle, where the extreme's is outward by about 1.5 noise levels; on the rig generator at 2000 samples
per cycle and an exact torque every reversal is found at the drive's turning sample (a one-sided
parabola, symmetric about the vertex, was up to 36 samples off there, and f 3.8 standard errors high).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["MIN_SAMPLES", "checked_loop", "noise_level", "turning_points", "reversal_threshold", "refined_reversals"]

#: Fewest samples a loop may have: four parameters and the turning points need several samples each.
MIN_SAMPLES = 20
#: The reversal threshold in noise levels of the twist, and as a fraction of the twist range.
THRESHOLD_NOISE, THRESHOLD_RANGE = 8.0, 1e-3
#: Candidate vertices whose two-sided parabolas are fitted at once (``_turning_misfit``).
TURNING_BLOCK = 128
#: The parabola fits a cap where its chi-square lies within this many standard deviations of its dof.
TURNING_FIT = 4.0
#: Fewest samples in a turning's cap for a vertex (a parabola has three coefficients).
VERTEX_SAMPLES = 5


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


def _turning_misfit(values: np.ndarray, noise: float, quartic: bool = False) -> np.ndarray:
    """Chi-square of the best two-sided parabola x = c + a (k - v)^2 (k < v), c + b (k - v)^2 (k >= v) through
    ``values`` (at k = 0, 1, ...) for every candidate vertex v = 0 .. len - 1, in units of ``noise`` (module
    docstring), with a quartic term (k - v)^4 of its own on each side when ``quartic``: three (five) linear
    coefficients per candidate, solved at once by their normal equations."""
    k = np.arange(values.size, dtype=float) / max(values.size - 1, 1)  # scaled to [0, 1]: a well-posed design
    misfit = np.empty(values.size)
    for first in range(0, values.size, TURNING_BLOCK):  # blocks of candidates bound the memory of a wide cap
        offset = k[None, :] - k[first:first + TURNING_BLOCK, None]  # rows: candidate vertices; columns: samples
        square = offset**2
        left, right = np.where(offset < 0, square, 0.0), np.where(offset >= 0, square, 0.0)
        columns = [np.ones_like(square), left, right] + ([left**2, right**2] if quartic else [])
        design = np.stack(columns, axis=-1)  # (candidate, sample, coefficient)
        normal = np.einsum("csi,csj->cij", design, design)
        rhs = np.einsum("csi,s->ci", design, values)
        # a candidate at the cap's end has one side empty: the pseudo-inverse leaves that coefficient at zero
        coef = np.einsum("cij,cj->ci", np.linalg.pinv(normal), rhs)
        fitted = np.einsum("csi,ci->cs", design, coef)
        misfit[first:first + TURNING_BLOCK] = np.sum((values[None, :] - fitted) ** 2, axis=1)
    return misfit / noise**2


def _channel_misfit(values: np.ndarray, noise: float) -> np.ndarray:
    """``_turning_misfit`` of one channel: the two-sided parabola, or with quartic terms where the best parabola's
    chi-square exceeds its degrees of freedom by more than ``TURNING_FIT`` standard deviations (a wide cap of a
    nearly exact channel: a sinusoid's quartic term is then many noise levels)."""
    misfit = _turning_misfit(values, noise)
    dof = values.size - 3
    if dof > 2 and float(misfit.min()) - dof > TURNING_FIT * math.sqrt(2.0 * dof):
        misfit = _turning_misfit(values, noise, quartic=True)
    return misfit


def refined_reversals(torque: np.ndarray, twist: np.ndarray, reversals: np.ndarray, threshold: float,
                      torque_noise: float, twist_noise: float) -> np.ndarray:
    """The sample of each reversal at the vertex of the turning in time, not at the noisy extreme (module docstring).

    ``reversals`` from ``turning_points(twist, threshold)``; the noise levels (N m, rad) weight the channels.
    Returns indices in the same order, each inside the cap of its turning and between its neighbours."""
    torque, twist = np.asarray(torque, dtype=float), np.asarray(twist, dtype=float)
    index = np.asarray(reversals, dtype=int)
    out = index.copy()
    for j, r in enumerate(index.tolist()):
        low_limit = out[j - 1] + 1 if j else 1
        high_limit = index[j + 1] - 1 if j + 1 < index.size else twist.size - 2
        near = np.abs(twist[low_limit:high_limit + 1] - twist[r]) < threshold
        # the contiguous run of ``near`` samples that holds r: the cap of this turning
        far_before = np.flatnonzero(~near[:r - low_limit])
        far_after = np.flatnonzero(~near[r - low_limit:])
        low = low_limit + (int(far_before[-1]) + 1 if far_before.size else 0)
        high = r + (int(far_after[0]) - 1 if far_after.size else high_limit - r)
        if high - low + 1 < VERTEX_SAMPLES:
            continue
        misfit = sum(_channel_misfit(channel[low:high + 1], noise)
                     for channel, noise in ((twist, twist_noise), (torque, torque_noise)))
        out[j] = low + int(np.argmin(misfit))
    return out
