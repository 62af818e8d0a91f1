r"""What a rig's record does before any model sees it: noise floors, spikes, an inverted channel.

Units: torque N m, twist rad (SI floats; ``units`` converts at the boundary).

Noise floors
------------
An estimated noise level (``samples.noise_level``) cannot fall below what the channel can
resolve: a channel quantised in steps q (an ADC, a file's last digit) carries at least the
rounding noise q^2 / 12 in variance, and a commanded (exact) channel must not make the
orthogonal distances degenerate (the residual scale sqrt(s_T^2 + g'^2 s_theta^2) of a sample on a
gross-slip plateau, g' = 0, is s_T alone; with s_T at 1e-12 of the torque the likelihood
collapses onto those samples).  ``noise_floor`` is the largest of

* the quantisation floor q / sqrt(12), q the smallest step between the channel's distinct values
  when the channel takes fewer distinct values than samples (a quantised channel repeats values);
* ``RATIO_FLOOR`` times the other channel's level carried through the elastic slope (torque:
  s_theta / C; twist: C s_T), which changes the likelihood by RATIO_FLOOR^2 (1e-4) where both
  channels are noisy and keeps it regular where one is exact;
* 1e-12 of the channel's range (a record without any noise).

A level given by the user (``--torque-noise``, ``--twist-noise``) is taken as it is (it is the
user's statement of the channel's resolution and noise).

Spikes
------
``find_spikes`` marks a sample that departs from the median of its four nearest neighbours
(a running median of width 5, which a single spike cannot move) by more than
``SPIKE_LEVEL`` robust noise levels of that departure plus twice the local curvature h^2 |x''|
of the smoothed signal (a reversal or a knee of the smooth signal moves its own sample off the
median by about that much).  A spike in either channel removes the sample from both.
Noise of a few levels is never a spike (the chance of a 12 sigma Gaussian departure is 4e-33).

Sign
----
A loop that dissipates energy is traversed so that the work int T dtheta over a closed cycle is
positive (the upper branch is the one loading in the positive sense).  ``loop_work`` is that
work over the whole cycles of the record (from its first turning point to the last one of the
same kind, the small gap closed by a straight segment) with its standard deviation from the
noise; ``check_sign`` raises a ValueError when the twist falls as the torque rises (a negative
compliance) or the work is negative by more than ``SIGN_LEVEL`` standard deviations: a channel's
sign is inverted (or the channels' order), which no fit can repair.

Many cycles
-----------
Two biases of the fit do not fall with the record's length while its intervals shrink like one over
the square root of it.  The first came from the reversals (the noisy extreme of the twist as the
turning point's sample; ``samples.refined_reversals`` takes the vertex of the turning instead).  The
second is the errors-in-variables functional model's own, of the order of the product of the two
channels' noise levels times the loop's curvature: it is taken out where the torque can be fitted as a
smooth function of time (``fitting.smoothing``: records of a few hundred samples per branch or more).
Where it cannot (fewer samples per branch, or a torque that is not smooth on the spline's scale) a
record with more than ``MANY_REVERSALS`` reversals whose fit gives a friction value carries the note of
``many_reversals_note``.  Measured (synthetic rig, torque-controlled partial slip at T* 1.3, 100
samples per cycle, noise 0.5 % of the torque range and 1e-5 rad, 20 cycles, eight seeds): f was
1.2 standard errors high on average before the reversals were refined and 0.5 after (0.45 with the
true reversal samples); on the independent rig generator at 10^5 samples (50 cycles at 2000 samples per
cycle) f and G were 5-6 and 5-8 standard errors off with the reversals refined and the torque as sampled,
within 1.1 with the torque smoothed (docs/fitting.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

from .. import units
from .samples import MIN_SAMPLES, noise_level, refined_reversals, reversal_threshold, turning_points

__all__ = ["PreparedRecord", "prepared_record", "checked_time", "RATIO_FLOOR", "SPIKE_LEVEL", "SIGN_LEVEL",
           "quantisation_step", "noise_floor", "find_spikes", "loop_work", "check_sign", "MANY_REVERSALS",
           "many_reversals_note"]

#: The smallest ratio of one channel's noise level to the other's carried through the elastic slope.
RATIO_FLOOR = 0.01
#: A spike departs from its running median by more than this many robust noise levels (plus the curvature term).
SPIKE_LEVEL = 12.0
#: A loop whose work is negative by more than this many standard deviations has an inverted channel.
SIGN_LEVEL = 5.0


def quantisation_step(values: np.ndarray) -> float:
    """The channel's quantisation step q: the smallest positive difference between its distinct values when every
    difference is a whole multiple of it (to 1e-6 of q: a quantised channel), else 0."""
    distinct = np.unique(np.asarray(values, dtype=float))
    if distinct.size < 2:
        return 0.0
    gaps = np.diff(distinct)
    q = float(np.min(gaps))
    if q <= 0 or np.max(np.abs(gaps / q - np.round(gaps / q))) > 1e-6:
        return 0.0
    return q


def noise_floor(values: np.ndarray, other_level: float, slope: float) -> float:
    """The floor of a channel's estimated noise level (module docstring): ``other_level`` is the other channel's
    level and ``slope`` converts it into this channel's units (1 / C for the torque, C for the twist)."""
    values = np.asarray(values, dtype=float)
    return max(quantisation_step(values) / math.sqrt(12.0), RATIO_FLOOR * abs(slope) * other_level,
               1e-12 * float(np.ptp(values)))


def _running_median(x: np.ndarray, half: int = 2) -> np.ndarray:
    padded = np.concatenate([np.full(half, x[0]), x, np.full(half, x[-1])])
    window = sliding_window_view(padded, 2 * half + 1)
    # the median of the neighbours only (the sample itself left out): a spike cannot pull its own reference
    neighbours = np.delete(window, half, axis=1)
    return np.median(neighbours, axis=1)


def find_spikes(x: np.ndarray, level: float = SPIKE_LEVEL, floor: float = 0.0) -> np.ndarray:
    """Boolean mask of the spikes of one channel (module docstring); ``floor``: the least noise level assumed."""
    x = np.asarray(x, dtype=float)
    if x.size < 7:
        return np.zeros(x.size, dtype=bool)
    reference = _running_median(x)
    departure = x - reference
    mad = float(np.median(np.abs(departure - np.median(departure))))
    sigma = max(1.4826 * mad, floor, 1e-12 * float(np.ptp(x)))
    # the smooth signal's own departure from the median of its neighbours: about h^2 |x''| (a reversal, a knee)
    curvature = np.abs(np.diff(reference, 2))
    curvature = np.concatenate([[curvature[0]], curvature, [curvature[-1]]])
    local = np.maximum.reduce([np.roll(curvature, k) for k in (-2, -1, 0, 1, 2)])
    return np.abs(departure) > level * sigma + 2.0 * local


def loop_work(torque: np.ndarray, twist: np.ndarray, reversals: np.ndarray, torque_noise: float,
              twist_noise: float) -> tuple[float, float] | None:
    """(int T dtheta over the record's whole cycles, its standard deviation from the noise), or None without a
    whole cycle (fewer than three turning points)."""
    if reversals.size < 3:
        return None
    last = reversals[2 * ((reversals.size - 1) // 2)]  # the last turning point of the first one's kind
    t, w = torque[reversals[0]:last + 1], twist[reversals[0]:last + 1]
    # the shoelace sum of the closed polygon: sum T_i (w_{i+1} - w_{i-1}) / 2, cyclically
    work = 0.5 * float(np.sum(t * (np.roll(w, -1) - np.roll(w, 1))))
    # summation by parts: the work is linear in each channel, its noise sum x_i (y_{i+1} - y_{i-1}) / 2
    twist_part = 0.5 * (np.roll(t, 1) - np.roll(t, -1))
    torque_part = 0.5 * (np.roll(w, -1) - np.roll(w, 1))
    sd = math.sqrt(twist_noise**2 * float(np.sum(twist_part**2)) + torque_noise**2 * float(np.sum(torque_part**2)))
    return work, sd


def check_sign(torque: np.ndarray, twist: np.ndarray, reversals: np.ndarray, torque_noise: float,
               twist_noise: float) -> None:
    """ValueError when a channel's sign is inverted (module docstring, "Sign")."""
    slope = np.polyfit(torque, twist, 1)[0]
    if slope <= 0:
        raise ValueError("twist falls as the torque rises (a negative compliance): the sign of the twist (or of the "
                         "torque) channel is inverted; flip one channel")
    work = loop_work(torque, twist, reversals, torque_noise, twist_noise)
    if work is not None and work[0] < -SIGN_LEVEL * work[1]:
        raise ValueError(f"the loop's work int T dtheta is negative ({work[0]:.3g} N m rad, {-work[0] / work[1]:.1f} "
                         "standard deviations below zero): a dissipating loop has positive area; the twist channel's "
                         "sign (or the channels' order) is inverted, or the twist leads the torque")


@dataclass(frozen=True)
class PreparedRecord:
    """A record as the fit takes it: the samples kept (``kept``: their indices in the record), the noise levels
    (N m, rad), the turning points of the twist, the number of ``spikes`` removed and the ``warnings`` (one line
    each)."""

    torque: np.ndarray
    twist: np.ndarray
    torque_noise: float
    twist_noise: float
    reversals: np.ndarray
    kept: np.ndarray
    spikes: int
    warnings: tuple


def prepared_record(torque, twist, torque_noise: float | None = None, twist_noise: float | None = None,
                    check: bool = True) -> PreparedRecord:
    """Spikes removed, noise levels (given, or estimated and floored), turning points, the sign checked.

    ``torque_noise``, ``twist_noise``: the user's levels (N m, rad) or None (estimated, ``noise_floor``).
    Raises ValueError for an inverted channel (``check_sign``, with ``check``) or fewer than ``MIN_SAMPLES``
    samples left.
    """
    torque, twist = np.asarray(torque, dtype=float), np.asarray(twist, dtype=float)
    notes = []
    spikes = find_spikes(torque, floor=torque_noise or 0.0) | find_spikes(twist, floor=twist_noise or 0.0)
    kept = np.flatnonzero(~spikes)
    if spikes.any():
        if kept.size < MIN_SAMPLES:
            raise ValueError(f"a loop needs at least {MIN_SAMPLES} samples, got {kept.size} after removing "
                             f"{int(spikes.sum())} spikes")
        torque, twist = torque[kept], twist[kept]
        first = ", ".join(str(int(i)) for i in np.flatnonzero(spikes)[:5])
        notes.append(f"spikes: {int(spikes.sum())} sample(s) removed (departing from their neighbours by more than "
                     f"{SPIKE_LEVEL:g} noise levels; sample {first}{', ...' if spikes.sum() > 5 else ''})")
    s_t = noise_level(torque) if torque_noise is None else float(torque_noise)
    s_theta = noise_level(twist) if twist_noise is None else float(twist_noise)
    tiny_t, tiny_theta = 1e-12 * float(np.ptp(torque)), 1e-12 * float(np.ptp(twist))
    s_t, s_theta = max(s_t, tiny_t), max(s_theta, tiny_theta)
    reversals = _reversals(torque, twist, s_t, s_theta)
    if check:
        check_sign(torque, twist, reversals, s_t, s_theta)
    slope = float(np.polyfit(torque, twist, 1)[0])
    if slope > 0:
        raw_t, raw_theta = s_t, s_theta
        if torque_noise is None:
            s_t = max(raw_t, noise_floor(torque, raw_theta, 1.0 / slope))
        if twist_noise is None:
            s_theta = max(raw_theta, noise_floor(twist, raw_t, slope))
        for name, raw, level in (("torque", raw_t, s_t), ("twist", raw_theta, s_theta)):
            if level > 2.0 * raw:
                notes.append(f"noise floor: the {name} channel's estimated noise ({raw:.3g}) is below its resolution "
                             f"or far below the other channel's; {level:.3g} is used (state it with "
                             f"--{name}-noise)")
        if (s_t, s_theta) != (raw_t, raw_theta):
            reversals = _reversals(torque, twist, s_t, s_theta)
    return PreparedRecord(torque, twist, s_t, s_theta, reversals, kept, int(spikes.sum()), tuple(notes))


def _reversals(torque, twist, s_t: float, s_theta: float) -> np.ndarray:
    """The reversals of the twist (``samples.turning_points``), each at the vertex of its turning
    (``samples.refined_reversals``)."""
    threshold = reversal_threshold(twist, s_theta)
    return refined_reversals(torque, twist, turning_points(twist, threshold), threshold, s_t, s_theta)


def checked_time(time, n: int) -> np.ndarray:
    """The time column (s) as floats: as many as the samples, finite and strictly increasing; else ValueError."""
    clock = units.si_array("time", time, "time")
    clock = np.asarray(clock, dtype=float)
    if clock.ndim != 1 or clock.size != n:
        raise ValueError(f"time must hold one value per sample ({n}), got shape {clock.shape}")
    if not np.all(np.isfinite(clock)) or not np.all(np.diff(clock) > 0):
        raise ValueError("time must be finite and strictly increasing")
    return clock


#: Reversals (two per cycle) up to which the loop fit's intervals were found to hold (module docstring).
MANY_REVERSALS = 20


def many_reversals_note(reversals: int, result, smoothed: bool) -> str | None:
    """The note for a fit of ``reversals`` reversals that gives a friction value without a smoothed torque (module
    docstring), or None."""
    if (smoothed or reversals <= MANY_REVERSALS or result.friction.value is None
            or not result.friction.identified):
        return None
    return (f"many cycles: {reversals} reversals, and the torque was not fitted as a smooth function of time (too "
            "few samples per branch, or not smooth); over more than "
            f"{MANY_REVERSALS // 2} cycles the bias that the noise on both channels gives the fitted loop may exceed "
            "the intervals of f and G: fit a few cycles, or each cycle (per_cycle), and compare")
