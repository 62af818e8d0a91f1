r"""The loop model of a measured record and the samples' orthogonal distances from it.

Units: torque N m, twist rad, compliance rad / (N m).

The curve
---------
For the parameter vector p = [T_s, kappa, C, theta_0, U_1, ..., U_M] (slip-onset torque, contact
over rig twist kappa = k / (C T_s), compliance, twist of the virgin state, twist at each reversal)
the torque along the record is T = g(theta; p): the memory rules driven by the twist
(``fitting.masing``) on the inverted skeleton (``fitting.skeleton``), each sample on the segment
between reversals that its time order puts it on.  ``LoopModel.torque_at`` evaluates g, its slope
dg/dtheta and its derivatives with respect to p at any twists of the samples.

Errors in both variables
------------------------
Sample i is a noisy observation (T_i, theta_i) of a point (g(u_i; p), u_i) of the curve, with
independent Gaussian noise of standard deviations s_T and s_theta.  The likelihood, maximised
over the unknown true twists u_i (the functional model of orthogonal distance regression),
leaves one residual per sample, its distance from the curve in noise units:

    d_i^2 = min_u [(T_i - g(u))^2 / s_T^2 + (theta_i - u)^2 / s_theta^2].

``LoopModel.foot_points`` finds the minimising u_i* (the foot point) by Newton steps in u (with
the curvature g'' of the curve; Gauss-Newton's where the misfit is not convex) from the best of a
grid of twists spanning the interval |u - theta_i| <= s_theta |T_i - g(theta_i)| / s_T that
holds the global minimum (near a sharp bend a sample's misfit has two minima),
vectorised over the samples, each step tried at full length and at fractions (one evaluation for
all), each sample keeping the best that lowers its distance.
At the foot point the residual vector is normal to the curve, so that

    d_i = [T_i - g(u_i*) - g'(u_i*)(theta_i - u_i*)] / sqrt(s_T^2 + g'(u_i*)^2 s_theta^2)

(the effective-variance residual evaluated at the foot point instead of the measured twist,
which it equals to first order in the noise), and, by the envelope theorem (the derivative of
d_i with respect to u_i* vanishes there),

    dd_i / dp = -(dg / dp)(u_i*) / sqrt(s_T^2 + g'(u_i*)^2 s_theta^2).

The Gram matrix of these rows is the Schur complement of the full (p, u) Fisher information,
i.e. the covariance of p with the true twists eliminated.  Each sample keeps one degree of
freedom (two observations, one latent twist), so that sum d_i^2 / (N - P) estimates the noise
scale without the Neyman-Scott halving of the 2N residuals of the full problem.

Turning points
--------------
The memory rules start every branch at a turning point (U_j, T_j), T_j = g(U_j) on the branch that
arrives there.  The turning point is the true state of the reversal's own sample (the sample at the
vertex of the turning in time, ``samples.refined_reversals``, chosen without looking at that sample's
own noise; the drive turns within about a sampling step of it, where the twist differs from its
extreme by a second-order amount far below the noise), so
that sample keeps both its residuals, (T_rev - T_j) / s_T and (theta_rev - U_j) / s_theta, with U_j
in the place of its foot point.  Left free, the twists at the reversals would each give the branch
that follows an offset of its own wherever the loop slips at its tips: extra parameters that fit
noise (a loop in stick then showed slip in a fifth of the records).  The residual vector holds the
N - M distances of the other samples and the 2 M residuals of the reversals, N + M in all, for
P = 4 + M parameters: N - 4 degrees of freedom.

The foot points converge quadratically (two or three steps); a sample's iteration stops when
the next step would lower its d_i^2 by less than ``FOOT_GAIN`` (1e-8, so that the sum over the
record is exact to far below the 0.05 of a likelihood-ratio statistic that matters), or when
halving its step does not lower it (a foot point at a kink of the curve: a reversal, a loop
closure, a node of the skeleton's cubic pieces).
"""

from __future__ import annotations

import math

import numpy as np

from .masing import jacobian_along, pieces, torque_along, turning_torques, walk
from .parameters import COMPLIANCE, FIRST_TURNING, LOOP, PARAMETER_NAMES, SLIP_TORQUE, TURNING, turning_twists
from .skeleton import Skeleton, skeleton_of

__all__ = ["LoopModel", "FOOT_GAIN", "FOOT_ITERATIONS", "PARAMETERS"]

#: Names of the first four parameters; the twists at the reversals follow (``fitting.parameters``).
PARAMETERS = PARAMETER_NAMES
#: A foot point has converged when the next Gauss-Newton step would lower its squared distance by less than this.
FOOT_GAIN = 1e-6
#: Newton steps at most (two or three are taken at realistic noise).
FOOT_ITERATIONS = 12
#: The grid of starting twists, in units of the reach of each sample's global minimum (``LoopModel._project``); it
#: holds the measured twist (0).
FOOT_GRID = np.linspace(-1.0, 1.0, 9)
#: Samples whose starting grid is evaluated at once (bounds the memory of a long record's projection).
FOOT_BLOCK = 8192
#: Fractions of a foot-point step tried at once; a sample keeps the best that lowers its distance.
STEP_FRACTIONS = np.array([1.0, 0.5, 0.25, 1.0 / 16.0])
_FRACTIONS_COLUMN = STEP_FRACTIONS[:, None]


class LoopModel:
    """The curve T = g(theta; p) of a record and the orthogonal distances of its samples (module docstring).

    Parameters
    ----------
    torque, twist : ndarray
        The samples (N m, rad) in time order.
    reversal_index : ndarray of int
        Indices of the reversals of the twist (``samples.turning_points``).
    torque_noise, twist_noise : float
        Noise levels s_T (N m) and s_theta (rad): only their ratio shapes the fit; the overall
        scale is estimated from the distances.
    contact : ContactModel or str, optional
        The contact model whose skeleton the branches follow (``models.get``; default the cylinders).
    """

    def __init__(self, torque, twist, reversal_index, torque_noise: float, twist_noise: float, contact=None):
        from .. import models

        self.contact = models.get(contact)
        self.torque = np.asarray(torque, dtype=float)
        self.twist = np.asarray(twist, dtype=float)
        self.reversals = np.asarray(reversal_index, dtype=int)
        self.segment = np.searchsorted(self.reversals, np.arange(self.twist.size), side="left")
        last = self.segment == self.reversals.size
        start = self.twist[self.reversals[-1]] if self.reversals.size else self.twist[0]
        heading = np.sign(self.twist[-1] - start) or 1.0
        self.end = float(self.twist[last].max() if heading > 0 else self.twist[last].min())
        self.torque_noise, self.twist_noise = float(torque_noise), float(twist_noise)
        self._curve = (None, None)
        self._foot = (None, None)
        self._free = np.ones(self.twist.size, dtype=bool)  # the samples that are not reversals
        self._free[self.reversals] = False
        self._free_index = self._free.nonzero()[0]
        self._columns = np.arange(self.twist.size)
        self._observed = np.array([self.torque, self.twist])
        self._jac_twist = None  # ``_twist_rows``
        self._residual = (None, None, None)  # ``distances``: (p, foot points, (residuals, their scales)) of the last p
        self._jacobian = (None, None, None)  # ``distances``: (p, foot points, Jacobian) of the last Jacobian

    @property
    def size(self) -> int:
        """Number of parameters P = 4 + M."""
        return FIRST_TURNING + self.reversals.size

    @property
    def residual_count(self) -> int:
        """Length N + M of the residual vector (``distances``): N - M distances and 2 M reversal residuals."""
        return self.twist.size + self.reversals.size

    def _curve_of(self, p, gradient: bool = False):
        """[walk, turning torques (with their gradient if ``gradient``), branch functions, twist of the virgin state,
        the walk's ``masing.pieces``] for p, cached for the last p."""
        p = np.asarray(p, dtype=float)
        key = p.tobytes()
        if self._curve[0] != key:
            slip_torque, kappa, compliance, offset = p[LOOP].tolist()
            skeleton = skeleton_of(kappa, self.contact)
            path = walk(np.concatenate((turning_twists(p), [self.end])) - offset)
            branches = _branches(skeleton, slip_torque, compliance)
            # the torques alone: the same numbers as with their gradient (the same evaluation of F), which waits until
            # a Jacobian is asked for
            turning = turning_torques(path, branches["value"])
            self._curve = (key, [path, turning, branches, offset, pieces(path, turning)])
        curve = self._curve[1]
        if gradient and curve[1].gradient is None:
            curve[1] = turning_torques(curve[0], curve[2]["jacobian"], True)
        return curve

    def torque_at(self, p, twist, jacobian: bool = False, index=None, curvature: bool = False, sparse: bool = False):
        """(g, dg/dtheta, turning-point torques[, dg/dp or d^2g/dtheta^2]) at the twists ``twist`` of the samples
        ``index``.

        ``index`` (default: every sample, in order) names the samples, hence their segments.  ``sparse``: dg/dp as
        a CSR matrix (``masing.jacobian_along``).
        """
        curve = self._curve_of(p)
        path, turning, branches, offset, lookup = curve
        segment = self.segment if index is None else self.segment[index]
        if jacobian and not curvature:
            # the turning points' gradient from the same evaluation of F as the samples' (``masing.jacobian_along``),
            # kept with the curve
            torque, slope, turning, jac = jacobian_along(path, np.asarray(twist, dtype=float) - offset, segment,
                                                         branches["jacobian"], turning, lookup, sparse)
            curve[1] = turning
            return torque, slope, turning.torque, jac
        branch = branches["curvature" if curvature else "jacobian" if jacobian else "value"]
        return torque_along(path, np.asarray(twist, dtype=float) - offset, segment, branch, jacobian, curvature,
                            turning, lookup)

    def foot_points(self, p) -> np.ndarray:
        """The true twist u_i* of every sample: the point of the curve nearest to it in noise units."""
        return self._project(p)[0]

    def _project(self, p):
        """(foot points, torque and slope there), cached for the last parameters."""
        key = np.asarray(p, dtype=float).tolist()  # the same floats (and the same equality) as float(v) for v in p
        if self._foot[0] == key:
            return self._foot[1]
        s_t2, s_w2 = self.torque_noise**2, self.twist_noise**2
        path, turning, branches, offset, lookup = self._curve_of(p)
        curve = _FootCurve(lookup, branches["skeleton"], p[SLIP_TORQUE], p[COMPLIANCE], offset)
        # each sample's first piece (ints), and rows of floats: torque, twist, then the heading of its segment and the
        # ends of its pieces (``_FootCurve``): gathered together for the samples still moving
        first = lookup.first[self.segment]
        observed = np.vstack([self._observed, lookup.heading[self.segment],
                              *(threshold[self.segment] for threshold in lookup.thresholds)])

        # Start from the best of a grid of twists around each sample.  The global minimum lies within
        # s_theta sqrt(misfit at the measured twist) of it (its misfit is no larger, and the twist term alone would
        # exceed that further out); near a sharp bend of the curve (the knee of a gross-slip loop with a small
        # contact twist) a sample's misfit has two minima, and Newton's steps from the measured twist find the wrong
        # one often enough to make the sum of squares jump as the parameters move.  The grid is (grid point,
        # sample); every sample's column shares its segment.
        columns = self._columns
        measured = curve(self.twist, first, observed[2:], torque_only=True)  # ``torque_at`` at the measured twists
        misfit = (self.torque - measured) ** 2 / s_t2
        reach = self.twist_noise * np.sqrt(misfit)
        # every sample's state: rows twist u, torque g, slope g' and curvature g'' at its foot point so far, and its
        # misfit there (``_descend``); the grid is evaluated for blocks of samples (``FOOT_BLOCK``: the same numbers,
        # sample by sample, with the memory of one block's grid)
        state = np.empty((5, columns.size))
        for start in range(0, columns.size, FOOT_BLOCK):
            block = slice(start, start + FOOT_BLOCK)
            twist, torque = self.twist[block], self.torque[block]
            grid = twist + FOOT_GRID[:, None] * reach[block]
            g_grid, s_grid, c_grid = curve(grid, first[block], observed[2:, block])
            values = (torque - g_grid) ** 2 / s_t2 + (twist - grid) ** 2 / s_w2
            # the grid point of each sample in the flattened (grid point, sample) arrays
            size = twist.size
            pick = values.argmin(axis=0) * size + np.arange(size)
            state[:, block] = np.array([grid, g_grid, s_grid, c_grid, values]).reshape(5, -1).take(pick, axis=1)
        state = self._descend(curve, state, columns, first, observed)
        if lookup.thresholds:
            state = self._across_corners(curve, state, lookup, offset, reach, first, observed)
        u, torque, slope = state[0], state[1], state[2]
        self._foot = (key, (u, torque, slope))
        return self._foot[1]

    def _descend(self, curve, start, samples, first, observed):
        """Newton's steps (``_project``) for the samples ``samples`` from their states ``start`` (rows twist, torque,
        slope and curvature, and their squared distances (noise units) if known, one column per sample) until none
        gains more than ``FOOT_GAIN``: their final states, with their squared distances.  ``first`` and ``observed``:
        every sample's first piece and rows of floats (``_project``)."""
        s_t2, s_w2 = self.torque_noise**2, self.twist_noise**2
        positions = np.arange(samples.size)
        # the samples still moving: their rows of floats, rows position in ``samples`` and first piece, and states
        # (the iteration's own copies)
        if samples is not self._columns:  # every sample (the projection's call) needs no copy of its rows
            observed = observed.take(samples, axis=1)
        index = np.array([positions, first[samples]])
        if start.shape[0] == 4:
            t_obs, w_obs, (w, g) = observed[0], observed[1], start[:2]
            start = np.concatenate([start, [(t_obs - g) ** 2 / s_t2 + (w_obs - w) ** 2 / s_w2]])
        state = start.copy()
        current = start
        with np.errstate(over="ignore", invalid="ignore"):
            for _ in range(FOOT_ITERATIONS):
                t_obs, w_obs, (w, g, s, c, misfit) = observed[0], observed[1], current
                torque_misfit, twist_misfit = t_obs - g, w_obs - w
                gauss_newton = s * s / s_t2 + 1.0 / s_w2  # half the misfit's second derivative, without curvature
                newton = gauss_newton - torque_misfit * c / s_t2  # with it: quadratic convergence where positive
                gradient = torque_misfit * s / s_t2 + twist_misfit / s_w2  # minus half the misfit's derivative
                step = gradient / np.where(newton > 0.1 * gauss_newton, newton, gauss_newton)
                gain = step * gradient  # predicted decrease of the misfit
                # no gain where it is NaN or +inf (FOOT_GAIN > 0)
                keep = ((gain > FOOT_GAIN) & (gain != np.inf)).nonzero()[0]
                if keep.size == 0:
                    break
                n = index.shape[1]
                if keep.size < n:
                    observed, index, current, step = (observed.take(keep, axis=1), index.take(keep, axis=1),
                                                      current.take(keep, axis=1), step.take(keep))
                    t_obs, w_obs, (w, misfit), n = observed[0], observed[1], current[::4], keep.size
                # the full step and its fractions in one evaluation (fraction, sample); each sample keeps its best if
                # it lowers the misfit
                # in blocks of ``FOOT_BLOCK`` samples (the same numbers, sample by sample: a long record's trials
                # over all samples at once set its peak memory)
                current = np.empty((5, n))
                for begin in range(0, n, FOOT_BLOCK):
                    block = slice(begin, begin + FOOT_BLOCK)
                    trial = w[block] + _FRACTIONS_COLUMN * step[block]
                    g_trial, s_trial, c_trial = curve(trial, index[1, block], observed[2:, block])
                    trial_misfit = (t_obs[block] - g_trial) ** 2 / s_t2 + (w_obs[block] - trial) ** 2 / s_w2
                    # each sample's best fraction in the flattened (fraction, sample) arrays
                    size = trial.shape[1]
                    pick = trial_misfit.argmin(axis=0) * size + positions[:size]
                    current[:, block] = np.array([trial, g_trial, s_trial, c_trial,
                                                  trial_misfit]).reshape(5, -1).take(pick, axis=1)
                lower = (current[4] <= misfit).nonzero()[0]
                # a sample whose step cannot lower its misfit sits at its foot point (a kink)
                if lower.size < n:
                    observed, index, current = (observed.take(lower, axis=1), index.take(lower, axis=1),
                                                current.take(lower, axis=1))
                state[:, index[0]] = current
                if lower.size == 0:
                    break
        return state

    def _across_corners(self, curve, state, lookup, offset, reach, first, observed):
        """The foot points, checked across the corners of the curve within each sample's reach.

        Where a branch joins an earlier one (a piece end of its segment) the curve has a corner, and a sample's
        misfit may have two minima a small fraction of the starting grid's spacing apart, one on each side of it
        (0.04 noise levels apart, 2e-3 apart in misfit, for a sample at a reversal): Newton's steps stay in the
        basin the grid chose.  For each corner within a sample's reach, the misfit just past it on the side away from
        the foot point so far is evaluated; where it falls going away from the corner (a minimum in that piece), the
        steps start again from there, and the lower of the two foot points is kept.  ``state``: as ``_descend``
        returns it (its squared distances in row 4); ``first`` and ``observed`` as ``_descend`` takes them.
        """
        heading = observed[2]
        best = state[4]  # the squared distances, updated with the states
        for threshold in observed[3:]:  # one piece end per segment (inf: none)
            with np.errstate(invalid="ignore"):
                corner = threshold * heading + offset  # the twist of the corner
                samples = (np.isfinite(corner) & (np.abs(corner - self.twist) <= reach)).nonzero()[0]  # those near
            if samples.size == 0:
                continue
            corner, direction = corner.take(samples), heading.take(samples)
            # the side of the corner away from the foot point so far (the steps found the minimum on its own side)
            side = np.where(direction * (state[0].take(samples) - corner) > 0.0, -direction, direction)
            twist = corner + side * 1e-6 * np.maximum(reach.take(samples), self.twist_noise)
            g, slope, second = curve(twist, first.take(samples), observed[2:].take(samples, axis=1))
            # half the misfit's derivative along the twist, going away from the corner on that side
            falling = side * ((g - self.torque[samples]) * slope / self.torque_noise**2
                              + (twist - self.twist[samples]) / self.twist_noise**2) < 0.0
            if not falling.any():
                continue
            moved = samples[falling]
            end = self._descend(curve, np.array([twist, g, slope, second])[:, falling], moved, first, observed)
            improved = end[4] < best[moved]
            state[:, moved[improved]] = end[:, improved]
        return state

    def distances(self, p, jacobian: bool = False, sparse: bool = False):
        """The residual vector (noise units) [and its Jacobian d/dp] (module docstring, "Turning points").

        The signed distances d_i of the samples other than the reversals, then for each reversal j its
        sample's torque and twist residuals against the turning point (U_j, T_j):
        (T_rev - T_j) / s_T and (theta_rev - U_j) / s_theta.  ``sparse``: the Jacobian as a CSR matrix, never
        formed dense (long records: ``profile.SPARSE_ENTRIES``).
        """
        foot = self._project(p)
        u = foot[0]
        key = np.asarray(p, dtype=float).tobytes()
        if self._residual[0] == key and self._residual[1] is foot:
            # the residuals of the last call (a Jacobian follows the values at the same parameters): the torque and
            # slope at the foot points that ``torque_at`` gives with the Jacobian are the same numbers as the foot
            # points' own (the same evaluation of F at the same twists and pieces)
            residual, scale = self._residual[2]
        else:
            torque, slope = foot[1], foot[2]
            with np.errstate(over="ignore"):
                scale = np.sqrt(self.torque_noise**2 + (slope * self.twist_noise) ** 2)
            d = (self.torque - torque - slope * (self.twist - u)) / scale
            turning = self._curve_of(p)[1]
            reversal_torque = (self.torque[self.reversals] - turning.torque) / self.torque_noise
            reversal_twist = (self.twist[self.reversals] - np.asarray(p[TURNING], dtype=float)) / self.twist_noise
            residual = np.concatenate([d.take(self._free_index), reversal_torque, reversal_twist])
            residual.flags.writeable = False  # handed out again with the Jacobian
            self._residual = (key, foot, (residual, scale))
        if not jacobian:
            return residual
        if self._jacobian[0] == (key, sparse) and self._jacobian[1] is foot:
            # the Jacobian of the last call with one (a profile's slope at the end of the fit that computed it)
            return residual, self._jacobian[2]
        out = self.torque_at(p, u, True, sparse=sparse)
        turning = self._curve_of(p, True)[1]
        free = self._free_index
        if sparse:
            from scipy import sparse as sp

            jac = sp.vstack([sp.diags(-1.0 / scale.take(free)) @ out[3][free],
                             sp.csr_matrix(-turning.gradient / self.torque_noise),
                             sp.csr_matrix(self._twist_rows(len(p)))], format="csr")
        else:
            jac = np.concatenate([-out[3].take(free, axis=0) / scale.take(free)[:, None],
                                  -turning.gradient / self.torque_noise, self._twist_rows(len(p))])
            jac.flags.writeable = False  # handed out again
        self._jacobian = ((key, sparse), foot, jac)
        return residual, jac

    def _twist_rows(self, size: int) -> np.ndarray:
        """The Jacobian's rows of the reversals' twist residuals for ``size`` parameters (kept for the model's size)."""
        if size == self.size and self._jac_twist is not None:
            return self._jac_twist
        m = self.reversals.size
        rows = np.zeros((m, size))
        rows[np.arange(m), FIRST_TURNING + np.arange(m)] = -1.0 / self.twist_noise
        rows.flags.writeable = False
        if size == self.size:
            self._jac_twist = rows
        return rows

    def sample_distances(self, p) -> np.ndarray:
        """The signed distance d_i of every sample from the curve, the reversals' included (their own foot points)."""
        u, torque, slope = self._project(p)
        with np.errstate(over="ignore"):
            scale = np.sqrt(self.torque_noise**2 + (slope * self.twist_noise) ** 2)
        return (self.torque - torque - slope * (self.twist - u)) / scale

    def first_order_distances(self, p) -> np.ndarray:
        """The effective-variance residuals at the measured twists (no foot points): a cheap first guess."""
        torque, slope = self.torque_at(p, self.twist)[:2]
        with np.errstate(over="ignore"):
            return (self.torque - torque) / np.sqrt(self.torque_noise**2 + (slope * self.twist_noise) ** 2)

    def linear_distances(self, compliance: float, offset: float) -> np.ndarray:
        """Distances from the straight loop theta = theta_0 + C T (stick), exact for a line (Deming)."""
        return (self.torque - (self.twist - offset) / compliance) / math.sqrt(
            self.torque_noise**2 + (self.twist_noise / compliance) ** 2)


def _branches(skeleton: Skeleton, slip_torque: float, compliance: float) -> dict:
    """F(v) = T_s T*(v / (C T_s)) and its derivatives, for ``masing.torque_along``: "value" (F, F'), "curvature"
    (F, F', F'') and "jacobian" (F, F', dF/d(T_s, kappa, C))."""
    scale = compliance * slip_torque

    def value(v):
        t, slope = skeleton(v / scale)
        return slip_torque * t, slope / compliance

    def curvature(v):
        t, slope, second = skeleton(v / scale, curvature=True)
        return slip_torque * t, slope / compliance, second / (compliance * scale)

    def jacobian(v):
        x = v / scale
        t, slope, omega = skeleton(x, rotation=True)
        with np.errstate(invalid="ignore"):
            d_kappa = np.where(slope > 0, -slip_torque * omega * slope, 0.0)
        grad = np.array([t - slope * x, d_kappa, -slip_torque * slope * x / compliance]).T  # the columns (CORE)
        return slip_torque * t, slope / compliance, grad

    return {"value": value, "curvature": curvature, "jacobian": jacobian, "skeleton": skeleton}


class _FootCurve:
    """g, dg/dtheta and d^2g/dtheta^2 at twists of the samples, for their foot points (``LoopModel._project``).

    The numbers of ``masing.curvature_along`` on the "curvature" branch of ``_branches``, in one pass: a point at
    twist theta on piece k (origin twist u_k and torque T_k, direction d and factor g) has
    x = (theta - theta_0 - u_k) / (C T_s g / d) on the skeleton, torque T_k + d g T_s T*(x) (N m), slope T*'(x) / C
    (N m / rad) and curvature T*''(x) / (C^2 T_s g / d) (N m / rad^2).  The factors d / g and d g are +-1 or +-2 to
    the power +-1, so that folding them into one divisor or factor per piece is exact: the same roundings as scaling,
    then dividing, in turn.

    Parameters
    ----------
    lookup : masing.Pieces
        The walk's pieces.
    skeleton : Skeleton
        T*(x) for the parameters' kappa.
    slip_torque, compliance, offset : float
        T_s (N m), C (rad / (N m)) and theta_0 (rad).
    """

    def __init__(self, lookup, skeleton: Skeleton, slip_torque: float, compliance: float, offset: float):
        slip_torque, compliance = float(slip_torque), float(compliance)
        scale = compliance * slip_torque
        origin_twist, origin_torque, shrink, gain = lookup.table
        # rows, one column per piece: origin twist, origin torque, the divisor of x, the factor of T*, the divisor of
        # T*'' (each with its piece's d / g or d g)
        self.table = np.array([origin_twist, origin_torque, scale / shrink, gain * slip_torque,
                               compliance * scale / shrink])
        self.skeleton, self.compliance, self.offset = skeleton, compliance, offset

    def __call__(self, twist, first, lookup_rows, torque_only: bool = False):
        """(g, g', g'') at ``twist`` (rad, any shape ending in the samples' axis), or g alone with ``torque_only``.

        ``first``: each sample's first piece; ``lookup_rows``: rows of floats per sample, the heading of its segment,
        then the end of each of its pieces in that heading (``masing.Pieces.thresholds``): a point past one lies on a
        later piece.
        """
        u = twist - self.offset
        piece = first
        if lookup_rows.shape[0] > 1:
            ahead = lookup_rows[0] * u
            for threshold in lookup_rows[1:]:
                piece = piece + (ahead > threshold)
        origin_twist, origin_torque, divisor, factor, curvature_divisor = self.table.take(piece, axis=1)
        x = (u - origin_twist) / divisor
        sign = np.sign(x)
        if torque_only:
            return origin_torque + factor * (sign * self.skeleton.magnitudes(np.abs(x))[0])
        t, slope, second = self.skeleton.magnitudes(np.abs(x), True)[:3]
        return origin_torque + factor * (sign * t), slope / self.compliance, sign * second / curvature_divisor
