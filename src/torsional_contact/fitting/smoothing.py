r"""The torque channel as a smooth function of time, and what that does to the intervals.

Units: torque N m, time s (or samples, when the record has no time column).

Why
---
The orthogonal-distance fit (``fitting.loop_model``) gives every sample a latent true twist; with noise on both
channels the functional estimator keeps a bias of the order of the product of the two noise levels times the
curvature of the loop, which does not fall with the record's length while the intervals do.  Measured on the
independent rig generator (``verification.rig_records``: torque-controlled partial slip, T* = 1.3, 50 cycles at
0.5 Hz and 1 kHz, 10^5 samples, noise 0.5 % of the torque range and 1e-5 rad): f 6 standard errors high and G 7
low with noise on both channels, within 1 with noise on either alone.  The true torque of a rig is a smooth
function of time, sampled far faster than it turns: fitted by a regression spline in time with a few coefficients
per branch, its noise falls by sqrt(coefficients / samples) (0.12 at 2000 samples per cycle), and so does the
bias (the same record: f and G within 1 standard error).

The spline
----------
A cubic regression spline in time (least squares on the B-spline basis) with a knot of multiplicity three at
every reversal (a kink is allowed there: a triangular command turns sharply) and ``KNOTS_PER_BRANCH`` - 1 interior
knots equally spaced in time on each branch between reversals (a sinusoid's branch is then resolved to 2e-6 of
its amplitude).  It is used only where

* the record has more than ``SMOOTH_REVERSALS`` turning points (ten cycles): the bias grows with the number of
  cycles and is within the intervals below that, while the widening below is first order and falls short on short
  records (two cycles of 500 samples, 60 records of the rig generator at T* 1.3: friction intervals covered 0.6 in
  57 without smoothing, 53 with it, their z scattering 1.56 times their standard errors; 20 cycles, 10^4
  samples, smoothed: 55 of 60),
* there are at least ``SAMPLES_PER_COEFFICIENT`` samples per coefficient (shorter records gain little, and their
  intervals are wider than the bias), and
* the channel is smooth on that scale: a spline with twice the knots does not take out more than noise (the
  nested F test of the two residual sums, p-value above ``SMOOTH_LEVEL``; no noise level is needed, whose own
  estimate is uncertain by a few per cent), and the residuals' lag-one autocorrelation lies within
  ``SMOOTH_FIT`` / sqrt(N) of white noise's, -sum P_(i,i+1) / dof (the projection anticorrelates the residuals;
  a misfit that the spline leaves correlates them positively).

A torque that is not smooth on the spline's scale (the plateau's knee of a twist-controlled gross-slip loop at a
low sampling rate, steps) keeps its samples.  The fit is then told the smoothed channel's noise level,
s_T sqrt(q / N) for q coefficients.

The intervals
-------------
The smoothed torque's errors are not independent from sample to sample: they are the projection P of the raw
noise on the spline's basis S, with covariance s_T^2 P, P = S (S^T S)^-1 S^T.  The fit's covariance (its
Jacobian J, the derivatives D of its residuals with respect to each sample's torque, ``defects.data_derivatives``)
is corrected by the sandwich term

    (J^T J)^-1 J^T D (s_T^2 P - s^2 I) D J (J^T J)^-1,   s = the level the fit was told,

and the intervals of f, G and C are widened about their estimates by the square root of the ratio of the
corrected to the fit's own variance where it exceeds one (never narrowed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy import sparse, special
from scipy.interpolate import BSpline
from scipy.sparse import linalg as sparse_linalg

from .defects import data_derivatives, widened, widened_modulus
from .parameters import COMPLIANCE, KAPPA, LINE_COMPLIANCE, SLIP_TORQUE
from .profile import covariance
from .record_checks import MANY_REVERSALS

__all__ = ["SmoothTorque", "smoothed_torque", "widened_for_smoothing", "KNOTS_PER_BRANCH",
           "SAMPLES_PER_COEFFICIENT", "SMOOTH_FIT", "SMOOTH_REVERSALS"]

#: Knot intervals per branch between reversals.
KNOTS_PER_BRANCH = 16
#: Fewest samples per spline coefficient for the torque to be smoothed.
SAMPLES_PER_COEFFICIENT = 8
#: Turning points a record needs beyond this for its torque to be smoothed: the number above which an unsmoothed
#: fit's bias may exceed its intervals (``record_checks.MANY_REVERSALS``).
SMOOTH_REVERSALS = MANY_REVERSALS
#: Standard deviations within which the residuals' lag-one autocorrelation must lie ...
SMOOTH_FIT = 3.0
#: ... and the smallest p-value of the F test of twice the knots (about 3 standard deviations, one-sided).
SMOOTH_LEVEL = 1e-3
#: The spline's degree (cubic) and the multiplicity of its knot at a reversal (continuity C^0 there).
DEGREE, REVERSAL_MULTIPLICITY = 3, 3


@dataclass(frozen=True)
class SmoothTorque:
    """A smoothed torque channel: the ``torque`` (N m) at the samples, the raw channel's noise level ``raw_noise``
    and the smoothed one's ``noise`` (N m), and the spline's ``basis`` (sparse, samples x coefficients)."""

    torque: np.ndarray
    raw_noise: float
    noise: float
    basis: sparse.csr_matrix

    @property
    def coefficients(self) -> int:
        return self.basis.shape[1]


def _knots(clock: np.ndarray, reversals: np.ndarray, per_branch: int = KNOTS_PER_BRANCH) -> np.ndarray:
    """The spline's knots (module docstring): the ends of the record with multiplicity DEGREE + 1, each reversal's
    time with multiplicity REVERSAL_MULTIPLICITY and ``per_branch`` - 1 equally spaced knots on every branch."""
    ends = np.concatenate([[clock[0]], clock[reversals], [clock[-1]]])
    inner = [np.linspace(a, b, per_branch + 1)[1:-1] for a, b in zip(ends[:-1], ends[1:], strict=True)]
    turning = np.repeat(clock[reversals], REVERSAL_MULTIPLICITY)
    return np.concatenate([np.full(DEGREE + 1, clock[0]), np.sort(np.concatenate([*inner, turning])),
                           np.full(DEGREE + 1, clock[-1])])


def _least_squares(clock, torque, knots) -> tuple[np.ndarray, np.ndarray, sparse.csr_matrix, object]:
    """(the spline's values, the residuals, the basis S, the factorised S^T S) of the least-squares spline on
    ``knots``: the normal equations of the banded B-spline basis (well conditioned; scipy's ``make_lsq_spline``
    reaches the same coefficients by a QR reduction ten times slower at 10^5 samples)."""
    basis = BSpline.design_matrix(clock, knots, DEGREE).tocsr()
    gram = sparse_linalg.splu((basis.T @ basis).tocsc())
    smooth = basis @ gram.solve(basis.T @ torque)
    return smooth, torque - smooth, basis, gram


def smoothed_torque(clock, torque, reversals, noise: float) -> SmoothTorque | None:
    """The torque as a regression spline in time, or None where it is not used (module docstring).

    ``clock``: sample times (strictly increasing); ``reversals``: indices of the turning points
    (``samples.refined_reversals``); ``noise``: the raw channel's noise level (N m)."""
    clock, torque = np.asarray(clock, dtype=float), np.asarray(torque, dtype=float)
    reversals = np.asarray(reversals, dtype=int)
    if not noise > 0 or clock.size < 2 or reversals.size <= SMOOTH_REVERSALS:
        return None
    knots = _knots(clock, reversals)
    count = knots.size - DEGREE - 1
    if clock.size < SAMPLES_PER_COEFFICIENT * count:
        return None
    smooth, residual, basis, gram = _least_squares(clock, torque, knots)
    fine = _knots(clock, reversals, 2 * KNOTS_PER_BRANCH)
    fine_residual = _least_squares(clock, torque, fine)[1]
    # nested F test: does a spline with twice the knots take out more than noise?  (no noise level needed)
    extra, fine_dof = fine.size - knots.size, clock.size - (fine.size - DEGREE - 1)
    rss, fine_rss = float(residual @ residual), float(fine_residual @ fine_residual)
    f_statistic = ((rss - fine_rss) / extra) / (fine_rss / fine_dof)
    if special.fdtrc(extra, fine_dof, f_statistic) < SMOOTH_LEVEL:
        return None
    # white noise's residuals (I - P) e are anticorrelated by the projection: E sum r_i r_(i+1) = -s^2 sum P_(i,i+1)
    neighbours = (basis[:-1].T @ basis[1:]).toarray()
    expected = -float(np.trace(gram.solve(neighbours))) / (clock.size - count)
    lag_one = float(residual[1:] @ residual[:-1]) / rss
    if abs(lag_one - expected) > SMOOTH_FIT / math.sqrt(clock.size):
        return None
    return SmoothTorque(smooth, float(noise), float(noise) * math.sqrt(count / clock.size), basis)


def _sandwich_extra(fitted, smooth: SmoothTorque, columns: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the fit's covariance, the sandwich term) on the parameters ``columns`` (module docstring)."""
    r, jac, d_torque, _, rows = data_derivatives(fitted)
    scale2 = float(r @ r) / max(r.size - jac.shape[1], 1)
    cov = covariance(jac, scale2)
    inverse = cov[:, columns] / scale2  # (J^T J)^-1 on the columns wanted
    n = fitted.model.torque.size
    per_row = d_torque[:, None] * np.asarray(jac @ inverse)
    per_sample = np.zeros((n, columns.size))
    np.add.at(per_sample, rows, per_row)  # D J (J^T J)^-1, one row per sample
    # the fit may hold the record's later samples only (from its first turning point on)
    basis = smooth.basis[smooth.basis.shape[0] - n:]
    gram = (smooth.basis.T @ smooth.basis).tocsc()
    projected = basis.T @ per_sample
    solved = sparse_linalg.splu(gram).solve(np.asarray(projected))
    extra = smooth.raw_noise**2 * (projected.T @ solved) - fitted.model.torque_noise**2 * (per_sample.T @ per_sample)
    return cov[np.ix_(columns, columns)], extra


def widened_for_smoothing(fitted, smooth: SmoothTorque | None):
    """``fitted`` with the intervals of f, G and C widened for the smoothed torque's correlated errors (module
    docstring) and its ``noise`` holding the raw torque channel's level (``torque``), the smoothed one's
    (``torque_smoothed``) and the spline's ``spline_coefficients``; unchanged without smoothing."""
    if smooth is None:
        return fitted
    # the noise the user's channel has, and the smoothed channel's that the fit was told
    result = replace(fitted.result, noise={**fitted.result.noise, "torque": smooth.raw_noise,
                                           "torque_smoothed": smooth.noise, "spline_coefficients": smooth.coefficients})
    if fitted.p is None:  # the straight loop: C is the line's first parameter
        cov, extra = _sandwich_extra(fitted, smooth, np.array([LINE_COMPLIANCE]))
        ratio = math.sqrt(max((cov[0, 0] + extra[0, 0]) / cov[0, 0], 1.0)) if cov[0, 0] > 0 else 1.0
        return replace(fitted, result=replace(result, compliance=widened(result.compliance, ratio)))
    p = fitted.p
    cov, extra = _sandwich_extra(fitted, smooth, np.array([SLIP_TORQUE, KAPPA, COMPLIANCE]))

    def ratio(gradient):
        own = float(gradient @ cov @ gradient)
        return math.sqrt(max((own + float(gradient @ extra @ gradient)) / own, 1.0)) if own > 0 else 1.0

    slip_torque, product, compliance = (ratio(np.array(g, dtype=float)) for g in
                                        ([1, 0, 0], [0, p[COMPLIANCE], p[KAPPA]], [0, 0, 1]))
    return replace(fitted, result=replace(result, friction=widened(result.friction, slip_torque),
                                          shear_modulus=widened_modulus(result.shear_modulus, product),
                                          compliance=widened(result.compliance, compliance)))
