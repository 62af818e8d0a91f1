r"""The lag between a rig's channels: the twist's rate, the twist shifted in time, the straight loop with a lag.

Units: twist rad, torque N m, time s (or samples, when the record has no time column).

A lag tau of the twist channel behind the torque channel makes the record's twist theta(t_i - tau); the
correction is the twist at t_i + tau (``shifted_twist``), and to first order theta_i + tau theta'_i with the
twist's rate from a local cubic fit (``twist_rate``), whose noise would otherwise shrink a lag estimated by
regression on it.  ``lag_line`` is the straight loop (a contact in stick) with a lag, the alternative that
``defects.corrected_fit`` weighs slip against.
"""

from __future__ import annotations

import numpy as np
from scipy import optimize

__all__ = ["RATE_WINDOW", "twist_rate", "rate_window", "local_cubic", "shifted_twist", "lag_line"]

#: The window of the twist's derivative (``twist_rate``) as a share of the median branch.
RATE_WINDOW = 1.0 / 6.0


def twist_rate(twist: np.ndarray, clock: np.ndarray, reversals=None) -> np.ndarray:
    """theta'(t) (rad per unit of ``clock``): the derivative of a local cubic least-squares fit (Savitzky-Golay)
    over ``RATE_WINDOW`` of the median branch (the samples between turning points ``reversals``).

    The lag's size is a regression on this derivative: its noise attenuates the estimate by var(signal) /
    (var(signal) + var(noise)) (errors in the variable).  Differences of a five-sample running mean kept 0.2
    of the twist noise per sample interval, which at 500 samples per cycle and a twist noise of 2 % of the
    amplitude read a 2 ms lag as 1.6 ms; the window that grows with the branch keeps the noise's share of the
    derivative's variance near (noise/amplitude)^2 whatever the sampling rate, at a bias of order
    (omega h)^4 for a drive of angular frequency omega (half-window h, under 1e-2 at ``RATE_WINDOW``).
    """
    n = twist.size
    if n < 5:
        return np.gradient(twist, clock) if n > 1 else np.zeros(n)
    per_sample = local_cubic(twist, rate_window(n, reversals), derivative=True)
    return per_sample / np.gradient(clock)


def local_cubic(values: np.ndarray, window: int, derivative: bool = False) -> np.ndarray:
    """The value (or the derivative per sample) at every sample of the cubic fitted by least squares to the
    ``window`` (odd) samples around it; within half a window of either end, of the cubic fitted to the first or
    last window (Savitzky and Golay's filter, as ``scipy.signal.savgol_filter`` with mode "interp", without importing
    scipy.signal, which loads scipy.stats)."""
    half = window // 2
    offsets = np.arange(-half, half + 1, dtype=float)
    # the least-squares operator of the cubic in the offsets: row 0 gives the value at 0, row 1 the slope there
    operator = np.linalg.pinv(np.vander(offsets, 4, increasing=True))
    row = operator[1 if derivative else 0]
    out = np.empty(values.size)
    out[half:values.size - half] = np.convolve(values, row[::-1], mode="valid")
    for ends, block in ((slice(0, half), values[:window]), (slice(values.size - half, values.size), values[-window:])):
        coefficients = operator @ block
        at = offsets[:half] if ends.start == 0 else offsets[half + 1:]
        powers = np.vander(at, 4, increasing=True)
        if derivative:
            out[ends] = powers[:, :3] @ (coefficients[1:] * np.arange(1, 4))
        else:
            out[ends] = powers @ coefficients
    return out


def rate_window(n: int, reversals) -> int:
    """The odd window (samples) of ``twist_rate``: ``RATE_WINDOW`` of the median branch, at least 5, at most n."""
    ends = np.concatenate([[0], np.asarray([] if reversals is None else reversals, dtype=int), [n - 1]])
    branch = float(np.median(np.diff(ends))) if ends.size > 2 else float(n)
    return min(max(int(branch * RATE_WINDOW) | 1, 5), n if n % 2 else n - 1)


def shifted_twist(twist: np.ndarray, clock: np.ndarray, reversals, lag: float) -> np.ndarray:
    """The twist at t_i + ``lag``: its smooth part (the local cubic fit of ``twist_rate``) moved by the lag, each
    sample's noise kept, and beyond either end of the record the cubic fitted to the end's window.  Interpolating
    the raw samples instead would average neighbours' noise (by up to half its variance at half-sample shifts),
    which lowers the residual sum at some lags and not at others and so biases both the lag and the slip test
    against the straight loop; holding the end value would leave the last lag / dt samples uncorrected (a 30 ms
    lag at 200 Hz left 140 residual variances in the last six samples)."""
    return _Shift(twist, clock, reversals)(lag)


class _Shift:
    """``shifted_twist`` for many lags of one record: its smooth part and end cubics formed once."""

    def __init__(self, twist, clock, reversals):
        self.twist, self.clock = np.asarray(twist, dtype=float), np.asarray(clock, dtype=float)
        n = self.twist.size
        self.window = rate_window(n, reversals) if n >= 5 else n
        self.smooth = local_cubic(self.twist, self.window) if n >= 5 else self.twist
        polynomial = np.polynomial.polynomial
        self.ends = []
        for block in (slice(0, self.window), slice(n - self.window, n)):
            centre = float(np.mean(self.clock[block]))
            degree = min(3, self.window - 1)
            self.ends.append((centre, polynomial.polyfit(self.clock[block] - centre, self.twist[block], degree)))

    def __call__(self, lag: float) -> np.ndarray:
        target = self.clock + lag
        moved = np.interp(target, self.clock, self.smooth)
        for outside, (centre, coefficients) in zip((target < self.clock[0], target > self.clock[-1]), self.ends,
                                                   strict=True):
            if outside.any():
                moved[outside] = np.polynomial.polynomial.polyval(target[outside] - centre, coefficients)
        return self.twist + moved - self.smooth


def lag_line(model, clock: np.ndarray, drift: bool = False, inner=None, exact: bool = True):
    """The straight loop with a lag: (S, lag, S of the straight loop without it), the residuals
    (T_i - (theta(t_i + tau) - theta_0) / C) / w with the twist shifted as the record's correction shifts it
    (``shifted_twist``), so that the straight loop and the slip fit with a lag see the same data; with ``drift``
    both fits also take out a twist drift r (t_i - t_mid).  The lag is found to first order (theta_i + tau
    theta'_i, a linear least-squares start), then refined on the exact shift (bounded scalar minimisation over a
    bracket of twice that lag or four samples; without ``exact`` the first-order fit is returned, its sum on the
    first-order shift).  ``inner``: a mask of the samples the sums run over (default all).
    ``model`` needs ``torque``, ``twist``, ``torque_noise``, ``twist_noise`` and ``reversals``."""
    torque, twist = model.torque, model.twist
    s_t, s_w = model.torque_noise, model.twist_noise
    rate = twist_rate(twist, clock, model.reversals)
    centred = clock - 0.5 * (clock[0] + clock[-1])
    slope, intercept = np.polyfit(torque, twist, 1)
    if not slope > 0:
        return None
    columns = 3 if drift else 2

    def line_sum(shifted, extra=None):
        """The straight loop's residual sum on ``shifted`` (and its extra column's size, the first-order lag)."""
        count = columns + (extra is not None)

        def residual(q):
            compliance, offset = q[0], q[1]
            w = np.sqrt(s_t**2 + (s_w / compliance) ** 2)
            moved = shifted - offset - (q[2] * centred if drift else 0.0)
            if extra is not None:
                moved = moved + q[-1] * extra
            out = (torque - moved / compliance) / w
            return out if inner is None else out[inner]

        start = np.zeros(count)
        start[:2] = slope, intercept
        bounds = (np.concatenate([[slope * 1e-6], np.full(count - 1, -np.inf)]), np.full(count, np.inf))
        out = optimize.least_squares(residual, start, bounds=bounds, x_scale="jac")
        return float(np.sum(out.fun**2)), float(out.x[-1])

    s_line = line_sum(twist)[0]
    s_first, first_order = line_sum(twist, rate)
    if not exact:
        return s_first, first_order, s_line
    shift = _Shift(twist, clock, model.reversals)
    step = float(np.median(np.diff(clock))) if clock.size > 1 else 1.0
    reach = max(abs(first_order), 4.0 * step)
    best = optimize.minimize_scalar(lambda tau: line_sum(shift(tau))[0], method="bounded",
                                    bounds=(first_order - reach, first_order + reach),
                                    options={"xatol": 1e-3 * step})
    return float(best.fun), float(best.x), s_line
