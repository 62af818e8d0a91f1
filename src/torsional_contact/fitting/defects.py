r"""The defects every rig has, tested for and fitted: a torque zero offset, a twist drift, a lag between channels.

Units: torque N m, twist rad, time s (or samples, when the record has no time column).

What each defect does to the record (measured = true + effect):

=================  =======================================  ====================================
defect             effect                                   correction of the record
=================  =======================================  ====================================
torque offset dT   T_i + dT                                 T_i - dT
twist drift r      theta_i + r (t_i - t_mid)                theta_i - r (t_i - t_mid)
lag tau            theta(t_i - tau) ~ theta_i - tau theta'  theta at t_i + tau (``shifted_twist``)
=================  =======================================  ====================================

(the twist's own zero is a parameter of every fit, theta_0; a mean torque is physics, not a defect).

Score tests
-----------
A defect moves the record by a known direction a_i (torque), b_i (twist) per unit of its size.
The fit's residual vector r (noise units, ``loop_model.LoopModel.distances``) then moves by
Z = dr/d(data) . (a, b): for a sample's orthogonal distance d_i (envelope theorem, the foot
point fixed) dd_i/dT_i = 1/w_i and dd_i/dtheta_i = -g'_i / w_i, w_i = sqrt(s_T^2 + g'^2 s_theta^2);
for a reversal's two residuals 1/s_T and 1/s_theta; for the straight loop's residual
(T - (theta - theta_0)/C)/w: 1/w and -1/(C w).  With Z_perp the part of Z outside the span
of the fit's Jacobian J, the score (Lagrange multiplier) statistic

    LM = (Z_perp . r)^2 / (s^2 |Z_perp|^2),     s^2 = S / dof,

is chi-square with one degree of freedom when the defect is absent (Rao's score test; only the
fit at hand is needed).  Defects enter one at a time, the largest LM first, while it exceeds
``LM_CRITICAL`` (the chi-square quantile at ``LM_LEVEL``, small because three are tested on every
record and a false alarm costs a refit), each tested against the fit's columns and those of the
defects already in.

The fit with the defects
------------------------
The defects found are estimated jointly with the fit by Gauss-Newton steps on their sizes
(each the least-squares step delta = (Z_perp^T Z_perp)^-1 Z_perp^T r with the fit's parameters
projected out, the record corrected and refitted from there; ``STEPS`` at most, stopping when
a step changes the residual sum by less than ``STEP_GAIN`` residual variances), and the record
corrected by them is fitted as any other, the slip test included: a stuck contact whose twist
lags the torque is a straight loop once the lag is taken out.  The intervals of that fit hold
the defects at their estimates; each is widened by the ratio of the Wald standard errors with
and without the defects' columns (sqrt of the diagonal of s^2 ([J Z]^T [J Z])^+ over that of
s^2 (J^T J)^+), the first-order cost of not knowing them.  Each defect found is one line of
``warnings``: its name, its estimate and its score statistic.

Lag against slip
----------------
A straight loop lagged in time is an ellipse, which a partial-slip loop imitates within the noise: the
slip fit absorbs the opening and the lag's score test against it can stay small.  When a slip fit is
claimed and the straight loop with a lag (``lag_line``) is within the slip test's critical value of it,
the lag enters all the same, its estimate started from the straight loop's.  Whenever a lag was fitted
and slip is still claimed, the two hypotheses are compared each with its own lag (and drift, when
found): slip fit with its lag against the straight loop with its lag.  Below the slip test's critical
value slip is not established: the record corrected by the straight loop's lag is fitted again, and no
friction value or modulus is given (the ``lag against slip`` warning).  The lag's direction is the
twist's rate from a local cubic fit (``twist_rate``), whose noise would otherwise shrink the lag's
estimate; the correction moves the twist's smooth part only (``shifted_twist``), so that every
sample keeps its own noise whatever the lag.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from scipy import sparse, special

from .lag import lag_line, rate_window, shifted_twist, twist_rate
from .parameters import COMPLIANCE, KAPPA, LINE_COMPLIANCE, SLIP_TORQUE
from .profile import covariance, is_large
from .results import Estimate

__all__ = ["KINDS", "LM_LEVEL", "LM_CRITICAL", "data_derivatives", "defect_directions", "score_statistics",
           "corrected_record", "corrected_fit", "widened", "widened_modulus"]

#: The defects, in the order of their columns: (name, unit of the size, unit without a time column).
KINDS = (("torque offset", "N m", "N m"), ("twist drift", "rad/s", "rad per sample"), ("lag", "s", "samples"))
#: Level of each score test, and its critical value (chi-square, one degree of freedom).
LM_LEVEL = 1e-4
LM_CRITICAL = float(special.chdtri(1, LM_LEVEL))
#: The virgin start is rejected when its LR on the later samples exceeds this (chi-square, 3 degrees of freedom,
#: at ``LM_LEVEL``: the first segment fixes the virgin twist, the first turning point's torque and its twist).
VIRGIN_CRITICAL = float(special.chdtri(3, LM_LEVEL))
#: ... or exceeds this (chi-square, one degree of freedom, at 5 %) while the friction fitted without the first
#: loading lies outside the interval fitted with it.
VIRGIN_HINT = float(special.chdtri(1, 0.05))
#: Gauss-Newton steps at most on the defects' sizes, and the gain (residual variances) below which they stop.
STEPS = 4
STEP_GAIN = 0.1
#: Columns of ``KINDS``.
OFFSET, DRIFT, LAG = 0, 1, 2


def data_derivatives(fitted) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(residual r, Jacobian J, dr/dT_i, dr/dtheta_i, sample index of each row) of a ``loop_fit.Fitted``."""
    model = fitted.model
    s_t, s_w = model.torque_noise, model.twist_noise
    if fitted.p is None:  # the straight loop
        compliance, offset = (float(v) for v in fitted.line.x)
        w = math.sqrt(s_t**2 + (s_w / compliance) ** 2)
        r = (model.torque - (model.twist - offset) / compliance) / w
        rows = np.arange(model.torque.size)
        return r, np.asarray(fitted.line.jac), np.full(r.size, 1.0 / w), np.full(r.size, -1.0 / (compliance * w)), rows
    r, jac = model.distances(fitted.p, jacobian=True, sparse=is_large(model.residual_count, model.size))
    slope = model._project(fitted.p)[2]
    w = np.sqrt(s_t**2 + (slope * s_w) ** 2)
    free = model._free_index
    m = model.reversals.size
    d_torque = np.concatenate([1.0 / w[free], np.full(m, 1.0 / s_t), np.zeros(m)])
    d_twist = np.concatenate([-slope[free] / w[free], np.zeros(m), np.full(m, 1.0 / s_w)])
    rows = np.concatenate([free, model.reversals, model.reversals])
    return np.asarray(r), jac if sparse.issparse(jac) else np.asarray(jac), d_torque, d_twist, rows


def defect_directions(twist: np.ndarray, clock: np.ndarray, reversals=None) -> np.ndarray:
    """(3, N): per unit size of each defect (``KINDS``), the move of the record, torque rows first then twist:
    returned as an array (kind, channel, sample).  The lag's direction is -theta'(t) (``twist_rate``)."""
    n = twist.size
    out = np.zeros((len(KINDS), 2, n))
    out[0, 0] = 1.0
    out[1, 1] = clock - 0.5 * (clock[0] + clock[-1])
    out[2, 1] = -twist_rate(twist, clock, reversals)
    return out


def _perp(q: np.ndarray, z: np.ndarray) -> np.ndarray:
    return z - q @ (q.T @ z)


def _basis(jac: np.ndarray) -> np.ndarray:
    u, s, _ = np.linalg.svd(jac, full_matrices=False)
    keep = s > s[0] * 1e-10 * math.sqrt(jac.shape[0]) if s.size else s > 0
    return u[:, keep]


class _Complement:
    """The projection onto the orthogonal complement of the column space of J (and of unit columns added to it).

    A dense J: its orthonormal basis by the SVD (``_basis``), extended by the added columns.  A sparse J (a long
    record, ``profile.SPARSE_ENTRIES``): z - J (J^T J)^+ J^T z with (J^T J)^+ from the column-scaled Gram matrix
    (``profile.covariance`` with unit scale), never a dense basis of N rows; added columns are taken out one after
    the other (they are orthogonal to J's columns and to each other)."""

    def __init__(self, jac):
        self.jac = jac
        self.extra = []
        if sparse.issparse(jac):
            self.inverse = covariance(jac, 1.0)
            self.basis = None
        else:
            self.basis = _basis(jac)

    def __call__(self, z: np.ndarray) -> np.ndarray:
        if self.basis is not None:
            return _perp(self.basis, z)
        out = z - self.jac @ (self.inverse @ (self.jac.T @ z))
        for column in self.extra:
            out = out - np.multiply.outer(column, column @ out) if out.ndim > 1 else out - column * (column @ out)
        return out

    def add(self, column: np.ndarray) -> None:
        unit = column / math.sqrt(float(column @ column))
        if self.basis is not None:
            self.basis = np.column_stack([self.basis, unit])
        else:
            self.extra.append(unit)


def score_statistics(fitted, clock: np.ndarray):
    """(selected kinds in order of entry, their LM statistics, the columns Z (rows, kinds), r, J, dof, s^2)."""
    r, jac, d_torque, d_twist, rows = data_derivatives(fitted)
    model = fitted.model
    directions = defect_directions(model.twist, clock, model.reversals)
    z = np.stack([d_torque * directions[k, 0, rows] + d_twist * directions[k, 1, rows] for k in range(len(KINDS))],
                 axis=1)
    dof = max(r.size - jac.shape[1], 1)
    scale2 = float(r @ r) / dof
    complement = _Complement(jac)
    chosen, statistics = [], []
    while len(chosen) < len(KINDS):
        best, best_lm = None, 0.0
        for k in range(len(KINDS)):
            if k in chosen:
                continue
            zk = complement(z[:, k])
            norm2 = float(zk @ zk)
            if norm2 <= 1e-24 * max(float(z[:, k] @ z[:, k]), 1e-300):
                continue
            lm = float(zk @ r) ** 2 / (scale2 * norm2)
            if lm > best_lm:
                best, best_lm = k, lm
        if best is None or best_lm < LM_CRITICAL:
            break
        chosen.append(best)
        statistics.append(best_lm)
        complement.add(complement(z[:, best]))
    return chosen, statistics, z, r, jac, dof, scale2


def corrected_record(torque, twist, clock, kinds, sizes, reversals):
    """The record with the defects ``kinds`` of sizes ``sizes`` taken out (module docstring's table; the lag by
    ``shifted_twist`` with the record's turning points ``reversals``)."""
    torque, twist = np.array(torque, dtype=float), np.array(twist, dtype=float)
    for k, size in zip(kinds, sizes, strict=True):
        if k == 0:
            torque = torque - size
        elif k == 1:
            twist = twist - size * (clock - 0.5 * (clock[0] + clock[-1]))
        else:
            twist = shifted_twist(twist, clock, reversals, size)
    return torque, twist


def _step(fitted, clock, kinds):
    """The Gauss-Newton step on the sizes of ``kinds`` with the fit's parameters projected out, and its gain."""
    r, jac, d_torque, d_twist, rows = data_derivatives(fitted)
    directions = defect_directions(fitted.model.twist, clock, fitted.model.reversals)
    z = np.stack([d_torque * directions[k, 0, rows] + d_twist * directions[k, 1, rows] for k in kinds], axis=1)
    zp = _Complement(jac)(z)
    step, *_ = np.linalg.lstsq(zp, r, rcond=None)
    dof = max(r.size - jac.shape[1] - len(kinds), 1)
    gain = float(r @ (zp @ step)) / (float(r @ r) / dof)
    return step, gain, r, jac, z


def _lag_opens_the_loop(fitted, clock):
    """(LR of the lag on the straight loop, the lag) when a lag explains the loop's opening within the slip test's
    critical value of the slip fit, and by more than ``LM_CRITICAL`` over the straight loop; else None.

    A straight loop lagged in time is an ellipse, which a partial-slip loop imitates within the noise: the slip
    fit then absorbs the opening and the lag's score test against it stays small.  The lag is then estimated with
    the slip fit all the same (``corrected_fit``), from this lag on, and the two are compared there."""
    line = lag_line(fitted.model, clock, exact=False)  # a gate: to first order (the comparison is exact)
    if line is None:
        return None
    s_lag, tau, s_line = line
    r, jac = data_derivatives(fitted)[:2]
    scale2 = float(r @ r) / max(r.size - jac.shape[1], 1)
    gain = (s_line - s_lag) / scale2
    if gain > LM_CRITICAL and (s_lag - float(r @ r)) / scale2 < fitted.result.stick_critical:
        return gain, tau
    return None


class _Channels:
    """What ``lag_line`` reads of a record: its channels, noise levels and turning points."""

    def __init__(self, torque, twist, record):
        self.torque, self.twist, self.reversals = torque, twist, record.reversals
        self.torque_noise, self.twist_noise = record.torque_noise, record.twist_noise


def _slip_beyond_the_lag(final, record, clock, kinds, sizes):
    """(LR, lag of the straight loop) of the slip fit ``final`` (the lag and the other defects fitted with it)
    against the straight loop with its own lag (and drift, when found): slip is established when the LR exceeds
    the slip test's critical value, both hypotheses having the lag free."""
    others = [(k, size) for k, size in zip(kinds, sizes, strict=True) if k != LAG]
    torque, twist = corrected_record(record.torque, record.twist, clock, [k for k, _ in others],
                                     [size for _, size in others], record.reversals)
    # both sums leave out the ends, where a shift by the lag reaches past the record (its end cubic) or takes the
    # record's first samples, held before the lagging channel moved, into the smooth part's window: twice the slip
    # fit's lag and half a window at each end (a stuck record lagging 30 ms at 200 Hz read the straight loop's lag
    # as 29 ms and its sum 38 residual variances above the slip fit's, with the ends in)
    n = torque.size
    step = float(np.median(np.diff(clock))) if n > 1 else 1.0
    margin = int(math.ceil(2.0 * abs(float(sizes[kinds.index(LAG)])) / step)) + rate_window(n, record.reversals) // 2
    inner = np.zeros(n, dtype=bool)
    inner[margin:n - margin] = True
    if inner.sum() < n // 2:
        inner[:] = True
    line = lag_line(_Channels(torque, twist, record), clock, drift=DRIFT in kinds, inner=inner)
    if line is None:
        return math.inf, 0.0
    r, jac, _, _, rows = data_derivatives(final)
    scale2 = float(r @ r) / max(r.size - jac.shape[1], 1)
    s_final = float(np.sum(r[inner[rows]] ** 2))
    return max(line[0] - s_final, 0.0) / scale2, line[1]


def _virgin_statistic(virgin, steady, start: int) -> float:
    """LR of the virgin start on the samples from the first turning point on: the virgin fit's sum of squares there
    against the steady fit's (the same samples, the same parameters but the first segment), in the steady fit's
    residual variances."""
    r_v, _, _, _, rows = data_derivatives(virgin)
    common = float(np.sum(r_v[rows >= start] ** 2))
    r_s, jac_s = data_derivatives(steady)[:2]
    s_steady = float(r_s @ r_s)
    scale2 = s_steady / max(r_s.size - jac_s.shape[1], 1)
    return max(common - s_steady, 0.0) / scale2


def widened(estimate: Estimate, ratio: float) -> Estimate:
    if estimate.value is None or not ratio > 1.0:
        return estimate
    lo, hi = estimate.interval
    v = estimate.value
    lo = None if lo is None else v - ratio * (v - lo)
    hi = None if hi is None else v + ratio * (hi - v)
    return replace(estimate, stderr=None if estimate.stderr is None else estimate.stderr * ratio, interval=(lo, hi))


def corrected_fit(fitted, clock, record, settings, fit_prepared, timed: bool):
    """The fit of ``record`` with the defects the score tests find (module docstring): a ``loop_fit.Fitted``."""
    kinds, statistics = score_statistics(fitted, clock)[:2]
    found = dict(zip(kinds, statistics, strict=True))
    lag_start = None
    if fitted.p is not None and LAG not in found:  # slip claimed: is the loop's opening a lag instead?
        opening = _lag_opens_the_loop(fitted, clock)
        if opening is not None:
            found[LAG], lag_start = opening
            kinds, statistics = [*kinds, LAG], [*statistics, found[LAG]]
    current = fitted
    start = int(record.reversals[0]) if record.reversals.size >= 2 else None
    steady_record = None
    if start is not None:
        # the steady branches depend on torque differences only; the mean torque of the loop is taken out, so that
        # the first turning point's torque (tied to the virgin curve, which a steady loop about its mean reaches at
        # its tips) stays within the gross-slip torque whatever the zero of the torque channel
        later = record.torque[start:]
        mean = 0.5 * (float(np.max(later)) + float(np.min(later)))
        steady_record = replace(record, torque=later - mean, twist=record.twist[start:],
                                reversals=record.reversals - start, kept=record.kept[start:])
    virgin_lr = None
    if steady_record is not None and fitted.p is not None and 0 not in found:
        # a long record's steady fit starts from the fit with the first loading (the same loop but for it; the grid's
        # start cost 2.5 of 12 CPU-s on 10^5 samples): its likelihood is near quadratic there (``profile.is_large``)
        near = fitted.p if is_large(fitted.model.residual_count, fitted.model.size) else None
        steady_fit = fit_prepared(steady_record.torque, steady_record.twist, steady_record.reversals,
                                  record.torque_noise, record.twist_noise, [], 0, settings, quick=True, start=near)
        virgin_lr = _virgin_statistic(fitted, steady_fit, start)
        lo, hi = fitted.result.friction.interval
        to_f = 2.0 / (settings[0] * settings[1])
        outside = steady_fit.p is not None and fitted.result.friction.value is not None and not (
            lo <= to_f * steady_fit.p[SLIP_TORQUE] <= hi)
        if virgin_lr <= VIRGIN_CRITICAL and not (outside and virgin_lr > VIRGIN_HINT):
            virgin_lr = None
    if not kinds and virgin_lr is None:
        return fitted
    steady = steady_record is not None and (0 in found or virgin_lr is not None)
    if steady:  # fitted from the first turning point on: no torque offset moves the steady branches
        record = steady_record
        clock = clock[start:]
        kinds = [k for k in kinds if k != 0]
        current = fit_prepared(record.torque, record.twist, record.reversals, record.torque_noise,
                               record.twist_noise, list(record.warnings), record.spikes, settings, quick=True)
        statistics = [found[k] for k in kinds]
    sizes = np.zeros(len(kinds))
    if lag_start is not None:  # the joint fit starts from the straight loop's lag
        sizes[kinds.index(LAG)] = lag_start
        torque, twist = corrected_record(record.torque, record.twist, clock, kinds, sizes, record.reversals)
        current = fit_prepared(torque, twist, record.reversals, record.torque_noise, record.twist_noise,
                               list(record.warnings), record.spikes, settings, quick=True)
    for _ in range(STEPS if kinds else 0):
        step, gain = _step(current, clock, kinds)[:2]
        sizes = sizes + step
        torque, twist = corrected_record(record.torque, record.twist, clock, kinds, sizes, record.reversals)
        current = fit_prepared(torque, twist, record.reversals, record.torque_noise, record.twist_noise,
                               list(record.warnings), record.spikes, settings, quick=True)
        if abs(gain) < STEP_GAIN:
            break
    torque, twist = corrected_record(record.torque, record.twist, clock, kinds, sizes, record.reversals)
    final = fit_prepared(torque, twist, record.reversals, record.torque_noise, record.twist_noise,
                         list(record.warnings), record.spikes, settings)
    lag_note = None
    if LAG in kinds and final.p is not None:  # slip against the straight loop, each with its own lag
        lr, line_lag = _slip_beyond_the_lag(final, record, clock, kinds, sizes)
        critical = final.result.stick_critical
        if lr < critical:
            sizes[kinds.index(LAG)] = line_lag
            torque, twist = corrected_record(record.torque, record.twist, clock, kinds, sizes, record.reversals)
            final = fit_prepared(torque, twist, record.reversals, record.torque_noise, record.twist_noise,
                                 list(record.warnings), record.spikes, settings)
            lag_note = (f"lag against slip: with the lag fitted to each, the slip fit improves on the straight loop "
                        f"by {lr:.1f} residual variances, below the slip test's {critical:.1f}: the loop's "
                        "opening is the lag; slip is not established and no friction value or modulus is given")
            if final.p is not None:
                withheld = Estimate.withheld_by("lag")
                final = replace(final, result=replace(final.result, friction=withheld, shear_modulus=withheld,
                                                      compliance=withheld, correlation=None, noise_limited=True))
    result = final.result
    notes = list(result.warnings)
    if steady:
        test = (f"score test {found[0]:.1f} > {LM_CRITICAL:.1f}" if 0 in found else
                f"the first loading disagrees with the later branches: LR {virgin_lr:.1f}, and the friction fitted "
                "from the first turning point on lies outside the interval with the first loading")
        notes.append(f"torque offset or non-virgin start ({test}): the "
                     f"record is fitted from its first turning point on (sample {start}), on the steady Masing "
                     "branches, which neither a torque zero offset nor the history before the record moves")
    if not kinds:
        return replace(final, result=replace(result, warnings=tuple(notes)))
    for k, size, lm in zip(kinds, sizes, statistics, strict=True):
        name, unit, unit_untimed = KINDS[k]
        test = ("on the straight loop, whose opening it explains as well as slip does" if k == LAG and
                lag_start is not None else "score test")
        notes.append(f"{name}: {size:.3g} {unit if timed else unit_untimed} estimated ({test} {lm:.1f} > "
                     f"{LM_CRITICAL:.1f}); the record is corrected for it and the intervals widened for its "
                     "uncertainty")
    if lag_note is not None:
        notes.append(lag_note)
    # the intervals' widening: Wald standard errors with and without the defects' columns
    r, jac, d_torque, d_twist, rows = data_derivatives(final)
    directions = defect_directions(final.model.twist, clock, final.model.reversals)
    z = np.stack([d_torque * directions[k, 0, rows] + d_twist * directions[k, 1, rows] for k in kinds], axis=1)
    dof = max(r.size - jac.shape[1] - len(kinds), 1)
    scale2 = float(r @ r) / dof
    with np.errstate(invalid="ignore", divide="ignore"):
        with_defects = sparse.hstack([jac, sparse.csr_matrix(z)], format="csr") if sparse.issparse(jac) else \
            np.column_stack([jac, z])
        core = np.diag(covariance(jac, scale2))
        joint = np.diag(covariance(with_defects, scale2))[:jac.shape[1]]
        ratios = np.sqrt(np.where(core > 0, joint / core, 1.0))
    if final.p is None:  # a straight loop: C is the line's first parameter
        result = replace(result, compliance=widened(result.compliance, float(ratios[LINE_COMPLIANCE])))
    else:
        p = final.p
        y_gradient = np.zeros(jac.shape[1])
        y_gradient[KAPPA], y_gradient[COMPLIANCE] = p[COMPLIANCE], p[KAPPA]
        cov_core = covariance(jac, scale2)
        cov_joint = covariance(with_defects, scale2)[:jac.shape[1], :jac.shape[1]]
        y_core, y_joint = float(y_gradient @ cov_core @ y_gradient), float(y_gradient @ cov_joint @ y_gradient)
        y_ratio = math.sqrt(y_joint / y_core) if y_core > 0 else 1.0
        result = replace(result, friction=widened(result.friction, float(ratios[SLIP_TORQUE])),
                         shear_modulus=widened_modulus(result.shear_modulus, y_ratio),
                         compliance=widened(result.compliance, float(ratios[COMPLIANCE])))
    return replace(final, result=replace(result, warnings=tuple(notes)))


def widened_modulus(estimate: Estimate, ratio: float) -> Estimate:
    """G's interval widened by ``ratio`` in 1/G (linear in the fitted y = kappa C)."""
    if estimate.value is None or not ratio > 1.0:
        return estimate
    inverse = Estimate(1.0 / estimate.value, None,
                       tuple(None if e is None else 1.0 / e for e in estimate.interval[::-1]))
    wide = widened(inverse, ratio)
    lo, hi = wide.interval
    interval = (None if hi is None or hi <= 0 else 1.0 / hi, None if lo is None or lo <= 0 else 1.0 / lo)
    return replace(estimate, stderr=None if estimate.stderr is None else estimate.stderr * ratio, interval=interval)
