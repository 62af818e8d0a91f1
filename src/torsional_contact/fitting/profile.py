r"""Least squares on the orthogonal distances, with a parameter held fixed, and profile-likelihood intervals.

Units: those of the loop model (``fitting.loop_model``): torque N m, twist rad.

Constrained fits
----------------
A ``Constraint`` holds one function psi(p) of the parameters at a value: the slip torque T_s
(friction f = 2 T_s / (F a)), the compliance C, or the contact twist per unit omega over T_s,
y = kappa C = k / T_s (shear modulus: 1/G = pi a^3 y / 4).  It maps the P - 1 free parameters
q to p and gives dp/dq, so that ``fit`` minimises S = sum d_i^2 over q with the Jacobian
J_p dp/dq (scipy's trust-region reflective least squares, bounds included).

Profile-likelihood intervals
----------------------------
With S_min the least sum of squares over all P parameters and s^2 = S_min / (N - P), the
likelihood-ratio statistic of psi = psi_0 is

    LR(psi_0) = (min_{psi(p) = psi_0} S - S_min) / s^2,

and the interval is {psi_0 : LR(psi_0) <= F(1, N - P; level)}, the profile-likelihood interval of
nonlinear regression (Bates and Watts, 1988, sec. 6.1).  It follows the likelihood where the Wald
interval psi_hat +- t se assumes it quadratic: along the curved ridge of (T_s, kappa) of a
partial-slip loop, against the bound y >= 0 (G -> infinity) and the flat profile of a loop that
barely slips (every T_s above the largest torque is the same straight loop).  Each end is found
by secant steps on the signed root r(psi) = +-sqrt(LR), nearly linear in psi, from the Wald end,
each constrained fit started from the nearest profile point already computed; it stops when r is
within ``ROOT_TOLERANCE`` of sqrt(F) (LR within 3 % of F: the interval's level within 0.3 %);
inside a bracket by Newton's step from the bracket's end nearest the target, or bisection when that
does not halve the step (``BRACKETED_STEPS`` more fits once bracketed: where kappa reaches its bound
the profile has a kink and rises like a wall).  A bracket narrower than ``ROOT_TOLERANCE`` of its
outer end also ends the search, at that outer end (the interval errs wide): where r is linear in
psi that is the accuracy the tolerance on r gives, and where the profile jumps (a constrained fit
past the jump lands in another valley, r leaps from below sqrt(F) to many times it) no point comes
within the tolerance, and bisection would only narrow the jump until the fits run out.
An end beyond a parameter's limit (y = 0, or T_s above the largest torque, where the profile is
flat) is unbounded.  A profile point below S_min means that the first fit stopped in a local
minimum: ``BetterMinimum`` carries the point, and the caller starts again from there.

Each search follows one valley of S, and S can have two along kappa: the ridge of a partial-slip loop
with kappa at its bound and one at a small kappa (a smaller T_s), apart by a saddle.  A compliance end
found in the first may lie inside the interval the second gives (for about one record in twelve of
T* 1.3 under 1e-5 rad of twist noise, sqrt(LR) at the end 0.03-0.5 below sqrt(F) from the other
valley: an interval too narrow).  ``across_valleys`` fits each end of C again from the points of least
and largest kappa, and where one is inside the interval the search goes on outward from it.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize, sparse

from .loop_model import LoopModel
from .parameters import COMPLIANCE, KAPPA, SLIP_TORQUE

__all__ = ["Constraint", "fit", "covariance", "is_large", "ProfileEnd", "profile_end", "across_valleys",
           "BetterMinimum", "ROOT_TOLERANCE"]

#: Relative tolerance on sqrt(LR) at an interval's end.
ROOT_TOLERANCE = 0.015
#: Constrained fits per end at most (well-behaved profiles take one to three); an end not pinned down by then is the
#: outer end of its bracket (the interval errs wide), or unbounded when there is no bracket.
MAX_PROFILE_STEPS = 8
#: Further constrained fits allowed once an end is bracketed: where the profile turns into the wall of the bound on
#: kappa (the slip torque's upper end) it has a kink, and eight steps could stop with the bracket's outer end far up
#: the wall (LR 105 against F = 3.9), an end the data reject.
BRACKETED_STEPS = 4
#: Function evaluations per least-squares fit at most (a fit from a good start takes 3-10).
MAX_EVALUATIONS = 60
#: The same for a constrained fit: one near the end of an interval starts close to its minimum and takes 2-6; one far
#: outside stops early, overstating its LR statistic, which leaves it outside.
MAX_CONSTRAINED_EVALUATIONS = 20
#: Relative tolerances of the least-squares fits (scipy's ftol, xtol, gtol): S to 1e-6 of itself, about 4e-4 for a
#: few hundred samples, far below the 0.02 F that decides an interval's end.
TOLERANCE = 1e-6
#: Jacobians with at least this many entries (residuals x parameters) are handed to the least-squares solver as
#: sparse matrices, its trust-region steps solved by LSMR instead of an SVD per iteration: a long record (10^5
#: samples, a hundred reversals, each reversal's twist acting on its own branch only) has a Jacobian about 2 % full,
#: whose dense SVD was two thirds of the fit's time.  Below it (records of a few thousand samples) the dense, exact
#: steps are kept.
SPARSE_ENTRIES = 2_000_000
#: Relative tolerances of LSMR's steps (its atol and btol): far below ``TOLERANCE``, so that the fit converges to
#: the same minimum as with exact steps.
LSMR_TOLERANCE = 1e-10
#: The first step (a fraction of psi's scale) where the Wald half-width exceeds a fifth of it (``profile_end``).
FIRST_STEP_CAP = 0.05
#: A profile point this far (in LR units) below the minimum is a better minimum, not rounding.
BETTER_MINIMUM_SLACK = 0.05
#: Profile points whose kappa differ by more than this factor are taken for different valleys of S (``across_valleys``).
VALLEY_RATIO = 2.0


class BetterMinimum(Exception):
    """A constrained fit found a smaller sum of squares ``s`` than the unconstrained one: restart from ``p``."""

    def __init__(self, p, s):
        super().__init__("a constrained fit found a smaller sum of squares")
        self.p, self.s = p, s


@dataclass(frozen=True)
class Constraint:
    """psi(p) = value for psi one of "slip_torque" (T_s, N m), "compliance" (C, rad / (N m)) or "product" (y = kappa C,
    rad / (N m)); the free parameters q are p without the one held (``_FIXED``: kappa for the product)."""

    kind: str
    value: float

    def free(self, size: int) -> np.ndarray:
        """Indices of the free parameters q in p (read-only)."""
        return _free_indices(self.kind, size)

    def position(self, index: int) -> int:
        """The place in q of the free parameter p[index]."""
        return index - (index > _FIXED[self.kind])

    def expand(self, q: np.ndarray, size: int) -> np.ndarray:
        p = np.empty(size)
        p[self.free(size)] = q
        if self.kind == "slip_torque":
            p[SLIP_TORQUE] = self.value
        elif self.kind == "compliance":
            p[COMPLIANCE] = self.value
        else:
            p[KAPPA] = self.value / p[COMPLIANCE]
        return p

    def tangent(self, q: np.ndarray, size: int) -> np.ndarray:
        """dp/dq, (P, P - 1)."""
        free = self.free(size)
        t = np.zeros((size, free.size))
        t[free, np.arange(free.size)] = 1.0
        if self.kind == "product":  # kappa = y / C: d kappa / d C = -y / C^2
            c = self.position(COMPLIANCE)
            t[KAPPA, c] = -self.value / q[c] ** 2
        return t

    def bounds(self, lower: np.ndarray, upper: np.ndarray, kappa_max: float):
        free = self.free(lower.size)
        lo, hi = lower[free].copy(), upper[free].copy()
        if self.kind == "product":  # kappa's lower bound <= y / C <= kappa_max: y / kappa_max <= C <= y / lower bound
            c = self.position(COMPLIANCE)
            lo[c] = max(lo[c], self.value / min(kappa_max, upper[KAPPA]))
            if lower[KAPPA] > 0:
                hi[c] = min(hi[c], self.value / lower[KAPPA])
        return lo, hi

    def of(self, p) -> float:
        return float(p[SLIP_TORQUE] if self.kind == "slip_torque" else p[COMPLIANCE] if self.kind == "compliance"
                     else p[KAPPA] * p[COMPLIANCE])


#: The parameter each kind of ``Constraint`` holds (y = kappa C: kappa, from y and the free C).
_FIXED = {"slip_torque": SLIP_TORQUE, "compliance": COMPLIANCE, "product": KAPPA}


@functools.lru_cache(maxsize=64)
def _free_indices(kind: str, size: int) -> np.ndarray:
    free = np.delete(np.arange(size), _FIXED[kind])
    free.flags.writeable = False
    return free


def fit(model: LoopModel, start, lower, upper, constraint: Constraint | None = None, kappa_max: float = np.inf):
    """Least squares on the orthogonal distances (all parameters, or all but the constrained one).

    Returns (p, S, result) with p the full parameter vector and S = sum d_i^2.
    """
    size = model.size
    is_sparse = is_large(model.residual_count, size)
    if constraint is None:
        def fun(q):
            return model.distances(q)

        def jac(q):
            return model.distances(q, jacobian=True, sparse=is_sparse)[1]

        lo, hi, q0 = lower, upper, np.asarray(start, dtype=float)
    else:
        def fun(q):
            return model.distances(constraint.expand(q, size))

        def jac(q):
            jacobian = model.distances(constraint.expand(q, size), jacobian=True, sparse=is_sparse)[1]
            if is_sparse:
                return (jacobian @ sparse.csr_matrix(constraint.tangent(q, size))).tocsr()
            return jacobian @ constraint.tangent(q, size)

        lo, hi = constraint.bounds(lower, upper, kappa_max)
        q0 = np.asarray(start, dtype=float)[constraint.free(size)]
    q0 = np.clip(q0, lo, hi)
    with np.errstate(invalid="ignore"):  # start exactly on a bound: least_squares nudges it inside
        q0 = np.where(np.isfinite(hi) & (q0 >= hi), hi - 1e-12 * np.maximum(np.abs(hi), 1e-300), q0)
    solver = ({"tr_solver": "lsmr", "tr_options": {"atol": LSMR_TOLERANCE, "btol": LSMR_TOLERANCE}} if is_sparse
              else {"tr_solver": "exact"})
    result = optimize.least_squares(fun, q0, jac=jac, bounds=(lo, hi), x_scale="jac", method="trf",
                                    max_nfev=MAX_EVALUATIONS if constraint is None else MAX_CONSTRAINED_EVALUATIONS,
                                    ftol=TOLERANCE, xtol=TOLERANCE, gtol=TOLERANCE, **solver)
    p = result.x if constraint is None else constraint.expand(result.x, size)
    return p, float(np.sum(result.fun**2)), result


def is_large(rows: int, columns: int) -> bool:
    """Whether a Jacobian of that shape takes the sparse path (``SPARSE_ENTRIES``)."""
    return rows * columns >= SPARSE_ENTRIES


def covariance(jacobian: np.ndarray, scale2: float) -> np.ndarray:
    """s^2 (J^T J)^+ by the SVD (a parameter without influence, e.g. a reversal in stick, gets no variance).

    A large Jacobian (``SPARSE_ENTRIES``) goes through its Gram matrix instead, J^T J formed sparse with the columns
    scaled to unit norm (D), and its eigen-decomposition: the singular values of J D are the roots of the eigenvalues,
    kept by the same relative threshold; accurate to about cond(J D)^2 eps, against cond(J D) eps by the SVD, which
    for the loop model's scaled columns (condition numbers of 10^2 to 10^4) is still far below the statistical
    error.  A long record's dense SVD cost as much as a fit."""
    rows, columns = jacobian.shape
    if not sparse.issparse(jacobian) and not is_large(rows, columns):
        u, s, vt = np.linalg.svd(jacobian, full_matrices=False)
        keep = s > s[0] * 1e-10 * math.sqrt(rows)
        return scale2 * ((vt[keep].T / s[keep] ** 2) @ vt[keep])
    matrix = sparse.csr_matrix(jacobian)
    norms = np.sqrt(np.asarray(matrix.multiply(matrix).sum(axis=0)).ravel())
    acting = np.flatnonzero(norms > 0.0)  # a column without influence gets no variance (and is left out of eigh)
    matrix, scale = matrix[:, acting], norms[acting]
    gram = (matrix.T @ matrix).toarray() / np.outer(scale, scale)
    eigenvalues, vectors = np.linalg.eigh(gram)
    keep = eigenvalues > eigenvalues[-1] * 1e-20 * rows
    out = np.zeros((columns, columns))
    out[np.ix_(acting, acting)] = ((vectors[:, keep] / eigenvalues[keep]) @ vectors[:, keep].T) / np.outer(scale, scale)
    return scale2 * out


@dataclass(frozen=True)
class ProfileEnd:
    """One end of a profile interval: ``value`` (None: unbounded), the parameters there, ``steps`` taken."""

    value: float | None
    p: np.ndarray | None
    steps: int
    at_cap: bool = False


def _slope(model: LoopModel, p, kind: str) -> float:
    """dS/dpsi along the profile: the partial derivative at the constrained minimum (envelope theorem)."""
    d, jac = model.distances(p, jacobian=True, sparse=is_large(model.residual_count, model.size))
    gradient = jac.T @ d  # dS/dp / 2, for a dense or a sparse Jacobian
    if kind == "slip_torque":
        return 2.0 * float(gradient[SLIP_TORQUE])
    if kind == "compliance":
        return 2.0 * float(gradient[COMPLIANCE])
    return 2.0 * float(gradient[KAPPA]) / p[COMPLIANCE]  # y = kappa C at fixed C: d kappa / d y = 1 / C


def _bracketed_newton(points, lo: float, hi: float, target: float) -> float:
    """Newton's step on r from that end of the bracket (lo, hi) nearest the target whose step stays inside (nan: none).

    Past a kink of the profile (where kappa reaches its bound, r grows steeply and nearly linearly) Newton's step
    from the shallow side overshoots; the one from the end on the wall lands close to the root.
    """
    candidates = sorted((abs(pt[1] - target), pt[0] + (target - pt[1]) / pt[2]) for pt in points
                        if pt[0] in (lo, hi) and pt[2] > 0)
    inside = [step for _, step in candidates if lo < step < hi]
    return inside[0] if inside else math.nan


def _start_at(start, kind: str, psi: float, kappa_max: float) -> np.ndarray:
    """A constrained fit's start: ``start`` with psi held at its value (for the product, C at least psi / kappa_max)."""
    start = np.array(start, dtype=float)
    if kind == "slip_torque":
        start[SLIP_TORQUE] = psi
    elif kind == "compliance":
        start[COMPLIANCE] = psi
    else:
        start[COMPLIANCE] = max(start[COMPLIANCE], psi / kappa_max * (1 + 1e-9))
    return start


def profile_end(model: LoopModel, p_hat, s_min: float, scale2: float, kind: str, side: int, first_step: float,
                critical: float, lower, upper, kappa_max: float, limit: float | None = None,
                limit_lr: float | None = None, better_minimum: bool = True, covariance=None,
                start_from: tuple | None = None) -> ProfileEnd:
    """The end of the profile interval of psi (``Constraint`` kind) on ``side`` (+1 above psi_hat, -1 below).

    ``first_step`` > 0: the first trial distance from psi_hat (the Wald half-width).  ``limit``: the
    furthest psi on this side; ``limit_lr``: the LR statistic there if known without a fit (the
    flat profile of a slip torque above the largest torque).  An end not found within
    ``MAX_PROFILE_STEPS`` fits is the outer end of its bracket, or unbounded (None) without one.
    Each constrained fit starts from the nearest profile point with r <= 3 target; an end found by a
    fit started outside the interval is fitted again from the minimum, and the lower of the two is
    the profile there (a fit outside may sit in another valley).  An end at ``limit`` is ``limit``
    itself.  Raises ``BetterMinimum`` (with ``better_minimum``; without, a point below the minimum counts
    as LR = 0).  ``covariance``: the fit's (P x P); on a record large enough for the sparse path (``is_large``),
    where the likelihood is near quadratic, each constrained fit then starts from its point's prediction along the
    profile's tangent at the estimate, p + cov g (psi - psi_hat) / (g^T cov g) with g = dpsi/dp (the profile of a
    quadratic likelihood, exactly), always from the minimum (so no end needs the check from the minimum), and the
    first trial distance is the Wald half-width down to 1e-6 of psi's scale (1e-3 otherwise): a 10^5-sample
    torque-controlled record's ends took 16 constrained fits instead of 27, the same to 1e-6.  Not on smaller
    records: on the flat, curved ridges of a short partial-slip loop the prediction led a constrained fit into
    another valley (a regression record of ``tests/test_fit.py``).  ``start_from``: (psi, parameters) of a
    point inside the interval in another valley (``across_valleys``): the search starts with a fit there from those
    parameters and goes on outward from it, each later fit started from the nearest point as above.
    """
    psi_hat = Constraint(kind, 0.0).of(p_hat)
    target = math.sqrt(critical)
    span = abs(limit - psi_hat) if limit is not None else math.inf
    if span <= 0 or (limit is not None and limit_lr is not None and limit_lr < critical):
        return ProfileEnd(None, None, 0)
    # beyond the last fitted point short of a known limit: at most 0.999 of the way (the profile is flat there)
    reach = span if limit_lr is None else 0.999 * span
    points = []  # (distance from psi_hat, r, dr/d distance, parameters)
    steps = 0
    tangent = None
    if covariance is not None and is_large(model.residual_count, model.size):
        gradient = np.zeros(len(p_hat))
        gradient[{"slip_torque": [SLIP_TORQUE], "compliance": [COMPLIANCE], "product": [KAPPA, COMPLIANCE]}[kind]] = (
            [p_hat[COMPLIANCE], p_hat[KAPPA]] if kind == "product" else [1.0])
        variance = float(gradient @ covariance @ gradient)
        tangent = covariance @ gradient / variance if variance > 0 else None
    if start_from is not None:  # another valley than the estimate's: the tangent at the estimate says nothing there
        tangent = None

    def psi_at(delta):
        """psi at that distance; the limit itself (not psi_hat + side span, which rounds to either side of it) there,
        so that a caller can tell an end the data set from one at the limit."""
        return limit if limit is not None and delta >= span else psi_hat + side * delta

    def evaluate(delta, from_minimum=False, given=None):
        """(r, parameters, whether the fit started outside the interval) of the constrained fit at delta (from the
        parameters ``given``, or as below)."""
        nonlocal steps
        psi = psi_at(delta)
        # from the nearest point of the profile that is not far outside the interval (a fit far out may have
        # wandered into another valley), or from the minimum
        sane = [(0.0, 0.0, 0.0, np.asarray(p_hat, dtype=float))] + [pt for pt in points if pt[1] <= 3.0 * target]
        # with the tangent (a large record), always from the minimum: its prediction needs no nearer point, and no
        # start from outside the interval then needs checking from the minimum
        nearest = sane[0] if from_minimum or tangent is not None else min(sane, key=lambda pt: abs(pt[0] - delta))
        if given is not None:
            nearest = (delta, 0.0, 0.0, given)
        start = np.array(nearest[3], dtype=float)
        if tangent is not None:
            start = start + tangent * (psi - Constraint(kind, 0.0).of(start))
        p, s, _ = fit(model, _start_at(start, kind, psi, kappa_max), lower, upper, Constraint(kind, psi), kappa_max)
        steps += 1
        lr = (s - s_min) / scale2
        if lr < -BETTER_MINIMUM_SLACK and better_minimum:
            raise BetterMinimum(p, s)
        r = math.sqrt(max(lr, 0.0))
        slope = side * _slope(model, p, kind) / scale2 / (2.0 * r) if r > 0 else 0.0  # dr/d delta
        points.append((delta, r, slope, p))
        return r, p, nearest[1] > target

    # y = kappa C beyond kappa_max C needs a larger C, which the data fix far more tightly than y: the profile rises
    # like a wall there.  When the search reaches the bound it tries just inside: if the end lies beyond, the model's
    # bound sets it.
    y_cap = kappa_max * p_hat[COMPLIANCE] * (1 - 1e-6) if kind == "product" and side > 0 else math.inf
    if y_cap <= psi_hat:
        return ProfileEnd(psi_hat, np.asarray(p_hat, dtype=float), 0, True)
    reach = min(reach, y_cap - psi_hat)
    # the Wald half-width, within 1e-3 and 0.2 of psi's scale (a degenerate covariance, a poorly determined psi: the
    # steps grow from there); the scale of y = kappa C is its range, kappa_max C (its estimate may sit at 0)
    scale = kappa_max * p_hat[COMPLIANCE] if kind == "product" and math.isfinite(kappa_max) else abs(psi_hat)
    delta = first_step if math.isfinite(first_step) else 0.1 * scale
    if delta > 0.2 * scale and y_cap == math.inf:
        # a Wald half-width beyond a fifth of psi's scale says nothing about the profile (the likelihood is far from
        # quadratic: in partial slip under twist noise the T_s ends lie 2-10 % from the estimate while the Wald
        # half-width is 40-90 %, and a first fit at a fifth lands at LR 1e3-3e3 times F, costing two capped fits
        # on the way back); start at a quarter of that, from which one growth step (at most 4 times) reaches it
        delta = FIRST_STEP_CAP * scale
    # (on a large record, whose likelihood is near quadratic, the Wald half-width is trusted down to 1e-6 of the scale:
    # a 10^5-sample record's compliance is known to 1.5e-4, and a first fit at 1e-3 landed at LR 190, costing two)
    delta = min(max(delta, (1e-6 if tangent is not None else 1e-3) * scale), 0.2 * scale, reach)
    given = None
    if start_from is not None:
        delta, given = min(side * (start_from[0] - psi_hat), reach), start_from[1]
    lo, hi = 0.0, math.inf  # the bracket: r < target at lo, r >= target at hi
    step, last_step = math.inf, math.inf
    while steps < MAX_PROFILE_STEPS or (hi < math.inf and steps < MAX_PROFILE_STEPS + BRACKETED_STEPS):
        r, p, from_outside = evaluate(delta, given=given)
        given = None
        if abs(r - target) <= ROOT_TOLERANCE * target and from_outside:
            # an end reached from a fit outside the interval may sit in that fit's valley, above the profile: the fit
            # from the minimum decides (the lower is the profile)
            r_minimum, p_minimum, _ = evaluate(delta, from_minimum=True)
            if r_minimum < r:
                r, p = r_minimum, p_minimum
            else:
                points.pop()
        at_cap = kind != "compliance" and p[KAPPA] >= kappa_max * (1 - 1e-6)
        if abs(r - target) <= ROOT_TOLERANCE * target:
            return ProfileEnd(psi_at(delta), p, steps, at_cap)
        slope = points[-1][2]
        if r < target:
            lo = delta
            if delta >= reach:  # the limit (or the bound on kappa) itself lies inside the interval
                return ProfileEnd(None, None, steps) if y_cap == math.inf else ProfileEnd(y_cap, p, steps, True)
        else:
            hi = delta
        # as close as the tolerance on r gives where r is linear in psi - psi_hat (a jump: no closer), and as close
        # as it gives on psi itself: near psi = 0 (y's lower end, G far above its estimate) r is steep in psi, and a
        # bracket narrow against its distance from psi_hat may still leave r 2 % from its target
        if hi < math.inf and hi - lo <= ROOT_TOLERANCE * min(hi, abs(psi_at(lo)), abs(psi_at(hi))):
            break
        newton = delta + (target - r) / slope if slope > 0 else math.nan
        if hi < math.inf:  # bracketed: Newton's step when it stays inside and shrinks fast enough, else bisection
            newton = _bracketed_newton(points, lo, hi, target)
            if lo < newton < hi and abs(newton - delta) < 0.5 * last_step:
                last_step, step = step, abs(newton - delta)
                delta = newton
            else:
                last_step, step = step, 0.5 * (hi - lo)
                delta = lo + step
        else:  # Newton from the last point, growing by 1.25 to 4 times
            grow = newton if math.isfinite(newton) else math.inf
            delta = min(min(max(grow, 1.25 * delta), 4.0 * delta), reach)
    if hi < math.inf:  # the outer end of the bracket: the interval errs wide
        outer = min((pt for pt in points if pt[0] == hi), key=lambda pt: pt[1])
        return ProfileEnd(psi_at(hi), outer[3], steps, kind != "compliance"
                          and outer[3][KAPPA] >= kappa_max * (1 - 1e-6))
    return ProfileEnd(None, None, steps)


def across_valleys(ends: dict, model: LoopModel, p_hat, s_min: float, scale2: float, critical: float, lower, upper,
                   kappa_max: float, search, better_minimum: bool = True) -> dict:
    """The ends {(kind, side): ProfileEnd}, each checked from the other valleys of S (module docstring).

    Each end is fitted again (psi held at it) from those of the estimate's and the other ends' parameters with the
    least and the largest kappa, where that kappa differs from the end's own by more than ``VALLEY_RATIO``.  Where
    one of these fits has sqrt(LR) below sqrt(F) by more than ``ROOT_TOLERANCE``, the end lies inside the interval:
    ``search(kind, side, (psi, p))`` (``profile_end`` with ``start_from``) goes on outward from there.  Only the ends
    of C are checked: the valleys differ in T_s and kappa, and the data fix C to a few 1e-3, so holding T_s or
    y = kappa C (holding kappa) picks one valley, and those profiles run across the valleys, not along one (the
    ends of T_s and y were never lower from the other valley on the records above).  One round: the ends a search
    from another valley finds are not checked again.  Raises ``BetterMinimum`` as ``profile_end`` does."""
    target = math.sqrt(critical)
    found = [np.asarray(p_hat, dtype=float)] + [end.p for end in ends.values() if end.p is not None]
    checked = dict(ends)
    for (kind, side), end in ends.items():
        if end.value is None or end.p is None or kind != "compliance":
            continue
        # the valleys lie at the ends of kappa's range (at its bound, and at a small kappa): the points of least and
        # of largest kappa stand for them
        extremes = [min(found, key=lambda q: q[KAPPA]), max(found, key=lambda q: q[KAPPA])]
        others = [q for q in extremes if abs(math.log(q[KAPPA] / end.p[KAPPA])) > math.log(VALLEY_RATIO)]
        best = None
        for q in others:
            p, s, _ = fit(model, _start_at(q, kind, end.value, kappa_max), lower, upper, Constraint(kind, end.value),
                          kappa_max)
            lr = (s - s_min) / scale2
            if lr < -BETTER_MINIMUM_SLACK and better_minimum:
                raise BetterMinimum(p, s)
            if math.sqrt(max(lr, 0.0)) < target * (1 - ROOT_TOLERANCE) and (best is None or s < best[1]):
                best = (p, s)
        if best is not None:
            checked[(kind, side)] = search(kind, side, (end.value, best[0]))
    return checked

