r"""Interpolants of a half-space model's monotonic numbers b(tau), Omega_m(tau), W_mono(tau) (built once, cached).

Units as ``half_space.jaeger``: tau = T*; b in a; Omega in f p-bar / mu; W in (f p-bar)^2 a^3 / mu.

Construction.  The torque interval [onset, gross] is cut into panels, geometric (ratio 2) toward
the slip onset and toward the gross-slip torque, where b ~ (gross - tau)^(1/3) and
Omega, W grow like a logarithm; on each panel the three numbers are Chebyshev interpolants of
degree ``DEGREE - 1`` at the first-kind Chebyshev nodes.  At each node the stick radius solves
T*(b) = tau (regula falsi, Illinois variant, on the exact quadrature of ``jaeger``, bracketed by a
table of T* on a graded grid), Omega = R(b) (J1) exactly, and W_mono comes from the loop-area form
dW/dtau = (pi n / 2)(tau dOmega/dtau - Omega), dOmega/dtau = 3 pi / (32 b^3) (J3), integrated
panel by panel (Chebyshev antiderivative) from W = 0 at the slip onset.  Below the slip onset the
contact is bonded: b = 1, Omega = 3 pi tau / 32, W = 0.  Within ``GROSS_CUTOFF`` of the range
below the gross-slip torque the leading asymptotics continue the last panel: b^3 proportional to
the torque deficit d, Omega and W growing like (3 pi C / 32) ln(1/d) (a tau there carries a
relative uncertainty of its own rounding / d, more than the asymptotics' error).

Error estimate (``error_estimate``): per panel the size of the last two Chebyshev coefficients
(the interpolation error of a converging Chebyshev series is below it), the largest over the
panels, for b (absolute), Omega and W (relative to the panel's values); tests compare the
interpolants with the quadrature at off-node torques against it.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial import chebyshev
from scipy.interpolate import CubicSpline

from ..curves.piecewise import Piecewise

__all__ = ["MonotonicTable", "DEGREE", "GROSS_CUTOFF"]

#: Chebyshev nodes per panel.
DEGREE = 20
#: Panels toward the slip onset (ratio 2: the first covers 2^-ONSET_PANELS of the range).
ONSET_PANELS = 14
#: Relative torque deficit below which the gross-slip asymptotics are used.
GROSS_CUTOFF = 2.0**-40
_ILLINOIS_STEPS = 80
#: Secant steps (from the grid spline's inverse) before the Illinois steps.
_SECANT_STEPS = 8
#: |T*(b) - tau| / tau (or |d(b) - d| / d) that ends the iterations: a few roundings of the quadrature.
_RESIDUAL = 4e-15
_NODES = np.cos(math.pi * (np.arange(DEGREE) + 0.5) / DEGREE)[::-1]  # first-kind Chebyshev nodes, ascending


def _geometric_edges(smallest: float, ratio: float) -> np.ndarray:
    """0, smallest, smallest * ratio, ... up to 1/2 (increasing)."""
    count = math.ceil(math.log(0.5 / smallest) / math.log(ratio))
    return np.concatenate([[0.0], 0.5 * ratio ** -np.arange(count, -1, -1, dtype=float)])


def _fit(edges, values) -> Piecewise:
    """Piecewise Chebyshev series through ``values`` (panels x DEGREE) at the first-kind nodes of ``edges``."""
    return Piecewise(edges, chebyshev.chebfit(_NODES, values.T, DEGREE - 1).T)


def _integrated(edges, rate, scale: float, start: float, reverse: bool) -> Piecewise:
    """int of ``rate`` (values at the nodes) times ``scale`` from the lowest edge (or the highest, ``reverse``)."""
    coefficients = chebyshev.chebfit(_NODES, rate.T, DEGREE - 1).T
    half = 0.5 * np.diff(edges) * scale
    pieces = [chebyshev.chebint(c, lbnd=-1.0) * h for c, h in zip(coefficients, half, strict=True)]
    totals = np.array([chebyshev.chebval(1.0, c) for c in pieces])
    if reverse:  # W(v) = start + int_v^(1/2): W at the upper end of panel j is start + sum of totals above j
        above = start + np.concatenate([np.cumsum(totals[::-1])[::-1][1:], [0.0]])
        pieces = [np.concatenate([[above[j] + totals[j]], np.zeros(c.size - 1)]) - c for j, c in enumerate(pieces)]
    else:
        below = start + np.concatenate([[0.0], np.cumsum(totals)[:-1]])
        pieces = [c + np.concatenate([[below[j]], np.zeros(c.size - 1)]) for j, c in enumerate(pieces)]
    return Piecewise(edges, pieces)


def _tail(piecewise: Piecewise, scale) -> float:
    """Largest |last two Chebyshev coefficients| / scale over the panels (the interpolation error estimate)."""
    return float(max(np.max(np.abs(c[-2:])) / s for c, s in zip(piecewise.coefficients, scale, strict=True)))


class MonotonicTable:
    """Piecewise-Chebyshev b(tau), Omega(tau), W(tau) of one half-space model (module docstring).

    ``rotation_and_torque(b, k)`` -> (R, T*) arrays (the quadrature), ``onset`` and ``gross`` the slip-onset
    and gross-slip torques, ``bodies`` the n of the slip s = n u.
    """

    def __init__(self, rotation_and_torque, torque_deficit, onset: float, gross: float, bodies: int):
        self.onset, self.gross, self.bodies = float(onset), float(gross), int(bodies)
        self._quadrature, self._deficit = rotation_and_torque, torque_deficit
        span = self.span = self.gross - self.onset
        near_onset = _geometric_edges(0.5**ONSET_PANELS, 2.0)  # in u = (tau - onset) / span
        near_gross = _geometric_edges(GROSS_CUTOFF, 2.0)[1:]  # in v = (gross - tau) / span
        self.onset_edges, self.gross_edges = near_onset, near_gross

        def nodes(edges):
            lo, hi = edges[:-1, None], edges[1:, None]
            return 0.5 * (lo + hi) + 0.5 * (hi - lo) * _NODES

        u, v = nodes(near_onset), nodes(near_gross)
        tau = np.concatenate([self.onset + span * u.ravel(), self.gross - span * v.ravel()])
        b_low, k_low = self._solve(tau[: u.size], self._torque_y, (self.onset, self.gross))
        b_high, k_high = self._solve(span * v.ravel(), self._deficit_z, (0.0, span), gross_side=True)
        b, k = np.concatenate([b_low, b_high]), np.concatenate([k_low, k_high])
        omega, _ = rotation_and_torque(b, k)
        rate = 0.5 * math.pi * self.bodies * (tau * 3.0 * math.pi / (32.0 * b**3) - omega)  # dW/dtau
        n = u.size
        shape_u, shape_v = u.shape, v.shape
        self._b = (_fit(near_onset, b[:n].reshape(shape_u)), _fit(near_gross, b[n:].reshape(shape_v)))
        self._omega = (_fit(near_onset, omega[:n].reshape(shape_u)), _fit(near_gross, omega[n:].reshape(shape_v)))
        onset_work = _integrated(near_onset, rate[:n].reshape(shape_u), span, 0.0, reverse=False)
        middle = float(onset_work(0.5))
        gross_work = _integrated(near_gross, rate[n:].reshape(shape_v), span, middle, reverse=True)
        self._work = (onset_work, gross_work)
        scales = [np.max(np.abs(x.reshape(shape)), axis=1) for x, shape in ((omega[:n], shape_u), (omega[n:], shape_v))]
        work_scale = [np.maximum(np.abs(w(e[1:])), 1e-300) for w, e in ((onset_work, near_onset),
                                                                         (gross_work, near_gross))]
        self.error_estimate = {
            "stick_radius": max(_tail(p, np.ones(len(p.coefficients))) for p in self._b),
            "rotation": max(_tail(p, s) for p, s in zip(self._omega, scales, strict=True)),
            "loading_work": max(_tail(p, s) for p, s in zip(self._work, work_scale, strict=True)),
        }
        # gross-slip asymptotics below v = GROSS_CUTOFF, matched at the cutoff (module docstring)
        d = span * near_gross[1]
        self._gross_d = d
        self._gross_c = d / float(self._b[1](near_gross[1])) ** 3
        self._gross_omega = float(self._omega[1](near_gross[1]))
        self._gross_work = float(gross_work(near_gross[1]))

    # ------------------------------------------------------------------ construction
    def _pair(self, y):
        """(b, k) for y in [0, 1]: b = cos(pi y / 2) for y <= 1/2, sin(pi (1 - y) / 2) above (relative accuracy)."""
        psi = 0.5 * math.pi * y
        chi = 0.5 * math.pi * (1.0 - y)
        low = y <= 0.5
        b = np.where(low, np.cos(psi), np.sin(chi))
        k = np.where(low, np.sin(psi), np.cos(chi))
        return b, k

    def _torque_y(self, y):
        b, k = self._pair(y)
        return self._quadrature(b, k)[1]

    @staticmethod
    def _pair_z(z):
        """(b, k) = (sin(pi z / 2), cos(pi z / 2)): the stick radius with relative accuracy near gross slip."""
        chi = 0.5 * math.pi * np.asarray(z, dtype=float)
        return np.sin(chi), np.cos(chi)

    def _deficit_z(self, z):
        return self._deficit(*self._pair_z(z))

    def _solve(self, tau, function, ends, gross_side: bool = False):
        """(b, k) with function(y) = tau for an array of targets inside ``ends`` = (function(0), function(1)):
        T*(b) = tau in y (b = cos(pi y / 2)), or near gross slip gross - T*(b) = d in z (b = sin(pi z / 2)),
        both increasing (Illinois, module docstring)."""
        inner = np.unique(np.concatenate([np.geomspace(1e-12, 0.05, 80), np.linspace(0.05, 0.95, 120),
                                          1.0 - np.geomspace(1e-12, 0.05, 80)]))
        grid = np.concatenate([[0.0], inner, [1.0]])
        t_grid = np.concatenate([[ends[0]], function(inner), [ends[1]]])
        i = np.clip(np.searchsorted(t_grid, tau) - 1, 0, grid.size - 2)
        ya, yb = grid[i], grid[i + 1]
        fa, fb = t_grid[i] - tau, t_grid[i + 1] - tau
        # the cubic-spline inverse of the grid narrows the bracket (T* saturates in double next to gross slip:
        # the strictly rising points only)
        rising = np.concatenate([[True], t_grid[1:] > np.maximum.accumulate(t_grid)[:-1]])
        spline = CubicSpline(t_grid[rising], grid[rising])
        guess, slope = np.clip(spline(tau), ya, yb), spline(tau, 1)

        def bracket(rows, y, f):  # narrow [ya, yb] with a new point
            low = f < 0
            ya[rows], fa[rows] = np.where(low, y, ya[rows]), np.where(low, f, fa[rows])
            yb[rows], fb[rows] = np.where(low, yb[rows], y), np.where(low, fb[rows], f)

        # secant steps from the spline's guess and a chord step with its slope dy/dtau (superlinear), kept inside
        # the bracket; the rows left (if any) go on by Illinois steps, which cannot leave it
        rows = np.arange(tau.size)
        y0 = guess
        f0 = function(y0) - tau
        bracket(rows, y0, f0)
        y1 = np.clip(y0 - f0 * slope, ya, yb)
        f1 = function(y1) - tau
        bracket(rows, y1, f1)
        for _ in range(_SECANT_STEPS):
            active = ~((np.abs(f1) <= _RESIDUAL * np.abs(tau))
                       | (np.abs(y1 - y0) <= 1e-15 * np.maximum(np.abs(y1), 1e-300)))
            rows = np.nonzero(active)[0]
            if not rows.size:
                break
            d = f1[rows] - f0[rows]
            step = np.where(d != 0, f1[rows] * (y1[rows] - y0[rows]) / np.where(d != 0, d, 1.0), 0.0)
            y2 = np.clip(y1[rows] - step, ya[rows], yb[rows])
            f2 = function(y2) - tau[rows]
            bracket(rows, y2, f2)
            y0[rows], f0[rows] = y1[rows], f1[rows]
            y1[rows], f1[rows] = y2, f2
        side = np.zeros(tau.shape, dtype=int)
        active = ~((np.abs(f1) <= _RESIDUAL * np.abs(tau))
                   | (np.abs(yb - ya) <= 1e-15 * np.maximum(np.abs(yb), 1e-300)))
        self.iterations = 0
        for _ in range(_ILLINOIS_STEPS):  # on the rows not yet converged only
            rows = np.nonzero(active)[0]
            if not rows.size:
                break
            self.iterations = _ + 1
            a_y, a_f, b_y, b_f, t = ya[rows], fa[rows], yb[rows], fb[rows], tau[rows]
            denominator = b_f - a_f
            safe = np.where(denominator != 0, denominator, 1.0)
            yc = np.where(denominator != 0, (a_y * b_f - b_y * a_f) / safe, 0.5 * (a_y + b_y))
            yc = np.clip(yc, np.minimum(a_y, b_y), np.maximum(a_y, b_y))
            fc = function(yc) - t
            keep_a = np.sign(fc) == np.sign(b_f)  # c replaces b; a stays (halve fa if it stayed before)
            a_f = np.where(keep_a & (side[rows] == -1), 0.5 * a_f, a_f)
            new_b_f = np.where(keep_a, fc, b_f)
            new_b_f = np.where(~keep_a & (side[rows] == 1), 0.5 * new_b_f, new_b_f)
            ya[rows], fa[rows] = np.where(keep_a, a_y, yc), np.where(keep_a, a_f, fc)
            yb[rows], fb[rows] = np.where(keep_a, yc, b_y), new_b_f
            side[rows] = np.where(keep_a, -1, 1)
            done = ((np.abs(yb[rows] - ya[rows]) <= 1e-15 * np.maximum(np.abs(yb[rows]), 1e-300))
                    | (np.abs(fc) <= _RESIDUAL * np.abs(t)))
            active[rows[done]] = False
        best = np.where(np.abs(fa) < np.abs(fb), ya, yb)
        best = np.where(np.abs(f1) <= np.minimum(np.abs(fa), np.abs(fb)), y1, best)
        return self._pair_z(best) if gross_side else self._pair(best)

    # ------------------------------------------------------------------ evaluation
    def point(self, tau: float) -> tuple[float, float, float]:
        """(b, Omega, W) at one onset < tau < gross: ``evaluate`` in scalar arithmetic (``Piecewise.scalar``)."""
        u = (tau - self.onset) / self.span
        v = (self.gross - tau) / self.span
        if u <= 0.5:
            return self._b[0].scalar(u), self._omega[0].scalar(u), self._work[0].scalar(u)
        if v >= self.gross_edges[1]:
            return self._b[1].scalar(v), self._omega[1].scalar(v), self._work[1].scalar(v)
        b, omega, work = self.evaluate(np.array([tau]))
        return float(b[0]), float(omega[0]), float(work[0])

    def evaluate(self, tau):
        """(b, Omega, W) for an array onset < tau < gross (no checks; the gross-slip end by its asymptotics)."""
        tau = np.asarray(tau, dtype=float)
        b, omega, work = (np.empty(tau.shape) for _ in range(3))
        u = (tau - self.onset) / self.span
        v = (self.gross - tau) / self.span
        low = u <= 0.5
        high = ~low & (v >= self.gross_edges[1])
        beyond = ~low & ~high
        for mask, x, side in ((low, u, 0), (high, v, 1)):
            if np.any(mask):
                b[mask] = self._b[side](x[mask])
                omega[mask] = self._omega[side](x[mask])
                work[mask] = self._work[side](x[mask])
        if np.any(beyond):
            d = np.maximum(self.gross - tau[beyond], 0.0)
            with np.errstate(divide="ignore"):
                rise = 3.0 * math.pi * self._gross_c / 32.0 * np.log(self._gross_d / d)
            b[beyond] = np.cbrt(d / self._gross_c)
            omega[beyond] = self._gross_omega + rise
            work[beyond] = self._gross_work + 0.5 * math.pi * self.bodies * self.gross * rise
        return b, omega, work
