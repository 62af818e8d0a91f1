r"""Starting points and reference loops of the loop fit (``fitting.loop_fit``, whose docstring describes them).

Units: torque N m, twist rad, compliance rad / (N m).

``_stick_line`` (the straight loop through every sample), ``_central_line`` (through the samples that stay in stick on
every branch), ``_starts`` (the best points of a grid of starting values), ``_stick_equivalent`` (the straight loop as a
loop of the full model: the slip fit's second start, so that it ends no worse than the straight loop),
``_line_foot`` (the samples' foot points on a straight loop) and ``_clipping_reference`` (the reference fit when a
gross-slip plateau only clips the loop's tips).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize

from . import profile as profiles
from .loop_model import LoopModel
from .parameters import COMPLIANCE, KAPPA, LINE_COMPLIANCE, LINE_OFFSET, SLIP_TORQUE, vector

__all__ = ["START_RATIOS", "start_ratios", "START_KAPPAS", "PLATEAU_SLOPE", "PLATEAU_RESOLVED", "PLATEAU_CLEARANCE",
           "NEAR_BOUND", "off_the_bound"]

#: The starting grid: T_s / max|T| (0.75: the cylinders' gross-slip plateau at the largest torque) and kappa.  A
#: model whose gross-slip torque T*_gs lies above 4/3 slips up to larger T* (the flat punch to pi/2): its grid also
#: starts at 1 / T*_gs and half-way from there to 0.75 (``start_ratios``).
START_RATIOS = (0.75, 0.8, 0.87, 0.95, 1.05)
START_KAPPAS = (0.02, 0.2, 1.0)
#: A gross-slip plateau is resolved when its samples (fitted slope below ``PLATEAU_SLOPE`` / C) at one tip (a branch
#: and a sign of the torque) span this many noise levels hypot(s_theta, C s_T) of twist.  A plateau that clips the
#: noisy tips of a partial-slip loop spans at most 4 (the tips' twist noise); a twist-controlled gross-slip loop
#: (2.5e-3 rad, the noisy scenario of the coverage study: 1e-4 rad, 5 % of the torque range) more than 20 on each
#: full branch.
PLATEAU_RESOLVED = 8.0
#: The plateau of the reference fit lies at least this many torque noise levels above the largest fitted torque.
PLATEAU_CLEARANCE = 1.0
#: Samples whose slope dT/dtheta is at least this fraction of the elastic 1/C count in ``residual_rms``.
PLATEAU_SLOPE = 0.5


def _stick_line(model: LoopModel):
    """The straight loop through every sample: (C, theta_0, sum of squares, result)."""
    torque, twist, s_t, s_theta = model.torque, model.twist, model.torque_noise, model.twist_noise

    def fun(q):
        c, offset = q[LINE_COMPLIANCE], q[LINE_OFFSET]
        return (torque - (twist - offset) / c) / np.sqrt(s_t**2 + (s_theta / c) ** 2)

    slope, intercept = np.polyfit(torque, twist, 1)
    slope = slope if slope > 0 else float(np.ptp(twist) / np.ptp(torque))
    result = optimize.least_squares(fun, [slope, intercept], bounds=([slope * 1e-6, -np.inf], [np.inf, np.inf]),
                                    x_scale="jac")
    return result


def _central_line(model: LoopModel, peak: float):
    """C and theta_0 from the samples with |T| < max|T| / 2 (stick on every branch of a symmetric loop)."""
    central = np.abs(model.torque) < 0.5 * peak
    if np.count_nonzero(central) < 5 or np.ptp(model.torque[central]) == 0:
        return None
    slope, intercept = np.polyfit(model.torque[central], model.twist[central], 1)
    return (float(slope), float(intercept)) if slope > 0 else None


def _grid(model: LoopModel, lines, reversals, peak) -> list[tuple[float, np.ndarray]]:
    """The grid of starting values in (T_s, kappa, line), each with its first-order sum of squares, best first."""
    points = []
    for compliance, offset in lines:
        for ratio in start_ratios(model.contact.gross_slip_torque):
            for kappa in START_KAPPAS:
                p = vector(ratio * peak, kappa, compliance, offset, reversals)
                points.append((float(np.sum(model.first_order_distances(p) ** 2)), p))
    return sorted(points, key=lambda point: point[0])


def start_ratios(gross_slip_torque: float) -> tuple[float, ...]:
    """T_s / max|T| of the starting grid for a model whose gross-slip torque is ``gross_slip_torque`` (T*):
    ``START_RATIOS``, and below 0.75 the plateau's own ratio 1 / T*_gs and the point half-way to 0.75 (a loop of a
    flat punch at T* 1.5 has T_s / max|T| = 0.67, outside the cylinders' grid: its fit stopped in stick, the slip
    loop 30-40 residual variances below it unvisited)."""
    plateau = 1.0 / gross_slip_torque
    below = (plateau, 0.5 * (plateau + START_RATIOS[0])) if plateau < START_RATIOS[0] - 1e-12 else ()
    return (*below, *START_RATIOS)


def _starts(model: LoopModel, lines, reversals, peak) -> list[np.ndarray]:
    """Starting parameters: the best point of a grid in (T_s, kappa, line) by the first-order distances and, when
    that point's loop is straight (its slip onset above the largest torque), also the best point whose loop slips.

    The first-order distances favour the straight loop where the slip's twist is small against the twist noise: on
    torque-controlled records at T* 1.3 under 1e-4 rad (tens of microradians of slip) the fit from the straight
    start stayed on the straight loop, the slip test found nothing (19 of 64 records declared stuck), and the
    straight loop's C was 2-5 standard errors high with a tight interval; from the slipping start the fit of such a
    record (``tests/test_fit.py``) ends 19.7 residual variances below the straight loop (critical value 11.0)."""
    grid = _grid(model, lines, reversals, peak)
    onset = model.contact.slip_onset_torque
    starts = [grid[0][1]]
    if starts[0][SLIP_TORQUE] * onset >= peak:
        starts += [point for _, point in grid if point[SLIP_TORQUE] * onset < peak][:1]
    return starts


#: A fit whose kappa ends within this fraction of its upper bound is refitted from the other kappas of the grid.
NEAR_BOUND = 0.1


def off_the_bound(model: LoopModel, fitted, lines, reversals, peak, lower, upper, kappa_max: float):
    """The better of ``fitted`` = (p, S, result) and the fits from the best grid point of each other starting kappa,
    when ``fitted`` ends with kappa at its upper bound (else ``fitted``).

    The first-order distances that rank the grid misjudge a loop whose torque noise is far below its twist noise
    (a smoothed torque, ``fitting.smoothing``): on the rig generator's torque-controlled records of 10^4 samples its
    best point, at kappa = 1, led six records in thirty to a local minimum at the bound kappa = 2 (f 9 % high, G
    not identified), 77 residual variances above the minimum that the other starting kappas reach (f 0.2 % off)."""
    p, s_full, _ = fitted
    if p[KAPPA] < (1.0 - NEAR_BOUND) * kappa_max:
        return fitted
    best = fitted
    for kappa in START_KAPPAS:
        if kappa == p[KAPPA]:
            continue
        start = next(point for value, point in _grid(model, lines, reversals, peak) if point[KAPPA] == kappa)
        candidate = profiles.fit(model, start, lower, upper)
        if candidate[1] < best[1]:
            best = candidate
    return best


def _stick_equivalent(model: LoopModel, line, peak: float, lower, upper, kappa_min: float) -> np.ndarray:
    """The full model's parameters of the straight loop ``line`` (C, theta_0): the slip torque above the largest
    torque (every sample in stick), the reversals at their samples' foot points on the line, within the bounds."""
    compliance, offset = (float(v) for v in line)
    foot = _line_foot(model.torque, model.twist, compliance, offset, model.torque_noise, model.twist_noise)
    largest = max(peak, float(np.max(np.abs(foot - offset))) / compliance)
    onset, gross = model.contact.slip_onset_torque, model.contact.gross_slip_torque
    # a contact that slips at any torque is straight only without its twist (kappa at its bound)
    slip_torque, kappa = (1.05 * largest / onset, START_KAPPAS[1]) if onset > 0 else (1.05 * largest / gross,
                                                                                       kappa_min)
    p = vector(slip_torque, kappa, compliance, offset, foot[model.reversals])
    return np.clip(p, lower, upper)


def _line_foot(torque, twist, compliance, offset, s_t, s_theta):
    """Foot points (true twists) of the samples on the straight loop theta = theta_0 + C T."""
    # minimise (T - (u - theta_0) / C)^2 / s_T^2 + (theta - u)^2 / s_theta^2 over u
    a = 1.0 / (compliance**2 * s_t**2)
    b = 1.0 / s_theta**2
    return (a * (compliance * torque + offset) + b * twist) / (a + b)


def _clipping_reference(model: LoopModel, p, s_full: float, lower, upper):
    """The reference fit when the fitted loop's gross-slip plateau only clips its tips, else None.

    Where the twist noise hides the contact's twist, a plateau 4/3 T_s at the largest torque lets the samples at
    the tips trade their twist residuals for the smaller distance to a flat line: a gain of about one residual
    variance per sample within a torque noise level of the plateau (LR about 10 for the 1.3 T_s loop at 1e-4 rad),
    which the likelihood takes for evidence of a plateau, hence of a T_s and a stiff contact (G at 250-500 GPa with
    intervals that excluded the true 80 GPa in a quarter of the records).  A plateau whose samples span less than
    ``PLATEAU_RESOLVED`` noise levels of twist at every tip is not seen in the data; its gain is not evidence.
    The reference is then the best loop whose plateau lies ``PLATEAU_CLEARANCE`` torque noise levels above the
    largest fitted torque: (p, S, Jacobian).  The intervals are taken against it (the clipped loops, below it,
    count as LR = 0, inside every interval).
    """
    slip_torque, compliance = float(p[SLIP_TORQUE]), float(p[COMPLIANCE])
    s_t, s_theta = model.torque_noise, model.twist_noise
    foot = model.foot_points(p)
    fitted, slope, turning = model.torque_at(p, foot)[:3]
    tips = float(np.max(np.abs(np.append(turning, fitted))))
    gross = model.contact.gross_slip_torque
    if gross * slip_torque - tips > s_t:
        return None  # the plateau is not reached
    on_plateau = slope < PLATEAU_SLOPE / compliance
    level = math.hypot(s_theta, compliance * s_t)
    # one tip: a branch and a sign of the torque (a reversal missed in the noise joins two tips in one branch)
    tip = 2 * model.segment + (fitted > 0)
    spans = [np.ptp(foot[on_plateau & (tip == j)]) for j in np.unique(tip[on_plateau])]
    if spans and max(spans) >= PLATEAU_RESOLVED * level:
        return None  # a plateau the data show
    lower_reference = np.array(lower, dtype=float)
    lower_reference[SLIP_TORQUE] = (tips + PLATEAU_CLEARANCE * s_t) / gross
    start = np.array(p, dtype=float)
    start[SLIP_TORQUE] = lower_reference[SLIP_TORQUE] * (1 + 1e-6)
    p_ref, s_ref, result = profiles.fit(model, start, lower_reference, upper)
    if s_ref <= s_full:
        return None
    return p_ref, s_ref, result.jac
