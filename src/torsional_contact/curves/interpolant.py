r"""The monotonic curves as cheap exact functions: by stick radius and by torque.

Units: b in a; T* = 2T/(f F a); omega in f p0 / mu; W_mono in (f p0)^2 a^3 / mu.

Everything the memory rules of ``histories`` need from the monotonic solution, besides
the interface profiles, is the stick radius b(tau), the rigid rotation omega_m(tau) and the
work against friction W_mono(tau) of a monotonic loading to 0 <= tau <= 4/3 (``curves.work``).
They are piecewise Chebyshev series (``curves.piecewise``) of the shipped table
(``curves.table``), which ``curves._precompute.build_table`` builds from the Abel-Fredholm solver:

* by stick radius, on panels in b (the table's solves);
* by torque, on the images of those panels: in tau itself where b >= 0.26, and in
  u = (4/3 - tau)^(1/3) closer to spinning, where b is nearly proportional to u
  (4/3 - T* ~ (16/(9 pi)) b^3) and omega ~ (1/2) ln(1/b) is smooth on each geometric
  panel; 4/3 - tau is formed with a compensated product so that u keeps its relative
  accuracy next to 4/3.

Beyond the table
----------------
* Slip annuli delta = 1 - b < ``ONSET_DELTA`` = ``asymptotics.ONSET_SCALARS`` = 2e-5
  (1 < tau < 1 + 1.3e-5): the small-slip expansion of ``asymptotics``, exactly as ``solve``
  uses it: T* - 1 = (2/pi) delta + delta^2 / 8 (S1; the table's own fit gives 0.12500 +- 1e-5
  for the second coefficient), omega = (2/3) delta^3 + (pi/16) delta^4 (S2), and
  W_mono = (pi^4/12) e^3 (1 + (1/2 - 3 pi^2/64) e), e = T* - 1 (S8, derived from (S1), (S2)
  and the loop-area identity; relative error ~2.8 e^2 |ln e| < 6e-9 where used).  There the
  solver itself loses digits (T* noise up to 1.5e-12 next to b_max), so the expansion is the
  more accurate of the two.
* tau within 4 ulp of 4/3 is spinning (as in ``solve``): b = 0, omega = W_mono = +inf.
* By radius, 0 < b < 1e-6: 4/3 - T* and omega, W_mono continued from the first panel by
  their small-disc forms (b^3 and ln(1/b) growth, relative corrections O(b^2)).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .. import asymptotics
from ..criteria import GROSS_SLIP_TORQUE, spinning_deficit
from .piecewise import Piecewise
from .table import TABLE_PATH, read_table

__all__ = ["MonotonicCurves", "monotonic_curves"]

#: Relative distance to 4/3 that counts as spinning (``validation.TORQUE_TOLERANCE``).
SPIN_TOLERANCE = 4 * np.finfo(float).eps
#: e coefficient of W_mono / ((pi^4/12) e^3) - 1 at small slip annuli: 1/2 - 3 pi^2/64, eq. (S8) of ``asymptotics``.
ONSET_WORK = asymptotics.ONSET_WORK_COEFFICIENT
#: Slip annuli narrower than this use the small-slip expansion (``asymptotics``), as ``solve`` does.
ONSET_DELTA = asymptotics.ONSET_SCALARS
#: b at which the by-torque panels switch from tau to u = (4/3 - tau)^(1/3).
U_SPLIT_RADIUS = 0.262144
_OMEGA_ONSET = math.pi**3 / 12.0
#: The curves tabulated by torque.
CURVES_BY_TORQUE = ("stick_radius", "rigid_rotation", "loading_work")


def _onset_radius(excess):
    """delta = 1 - b for T* - 1 = excess, eq. (S1) of ``asymptotics`` inverted."""
    return asymptotics.onset_slip_width(excess)


def _onset_work(excess):
    """W_mono at small slip annuli, e = T* - 1: eq. (S8) of ``asymptotics``."""
    return asymptotics.onset_work(excess)


class MonotonicCurves:
    """T*(b), 4/3 - T*(b), omega(b), W_mono(b) and b(tau), omega_m(tau), W_mono(tau) (module docstring)."""

    def __init__(self, table: dict):
        panels = table["panels"]
        edges = [p["lo"] for p in panels] + [panels[-1]["hi"]]
        self.table = table
        self.b_low, self.b_high = table["domain"]
        self.by_radius = {name: Piecewise(edges, [p[name] for p in panels])
                          for name in ("torque", "torque_gap", "rigid_rotation", "loading_work")}
        self.onset_torque = float(self.by_radius["torque"](self.b_high))  # the solver's resolution limit
        self.trust_torque = float(asymptotics.onset_torque(ONSET_DELTA))
        low = self.by_radius
        self._small = {  # continuation below b_low (module docstring)
            "gap_ratio": float(low["torque_gap"](self.b_low)) / self.b_low**3,
            "rotation": float(low["rigid_rotation"](self.b_low)),
            "work": float(low["loading_work"](self.b_low)),
            "work_slope": -self.b_low * _first_panel_slope(low["loading_work"]),
        }
        by_torque = table.get("by_torque")
        if by_torque is None:  # the builder adds them (``_precompute.build_table.add_by_torque``)
            raise ValueError("curve table without by-torque panels: rebuild it with python -m torsional_contact.curves")
        self.u_curves = {n: Piecewise(by_torque["u_edges"], by_torque["u_panels"][n]) for n in CURVES_BY_TORQUE}
        self.t_curves = {n: Piecewise(by_torque["t_edges"], by_torque["t_panels"][n]) for n in CURVES_BY_TORQUE}
        self.u_split = by_torque["u_edges"][-1]
        self.t_split = by_torque["t_edges"][-1]

    # ------------------------------------------------------------------ by stick radius
    def _by_radius(self, name: str, b, onset, small, limits):
        b = np.asarray(b, dtype=float)
        out = np.asarray(self.by_radius[name](b), dtype=float)
        out = np.where(b >= 1.0, limits[1], out)
        out = np.where(b <= 0.0, limits[0], out)
        near = (b > 1.0 - ONSET_DELTA) & (b < 1.0)
        if near.any():
            out = np.where(near, onset(1.0 - np.where(near, b, 0.0)), out)
        tiny = (b > 0.0) & (b < self.b_low)
        if tiny.any():
            out = np.where(tiny, small(np.where(tiny, b, self.b_low)), out)
        return out if out.ndim else float(out)

    def torque(self, b):
        """T*(b) for 0 <= b <= 1 (4/3 at b = 0, 1 at b = 1)."""
        return self._by_radius(
            "torque", b, asymptotics.onset_torque,
            lambda x: GROSS_SLIP_TORQUE - self._small["gap_ratio"] * x**3, (GROSS_SLIP_TORQUE, 1.0))

    def torque_gap(self, b):
        """4/3 - T*(b), with relative accuracy for small stick discs."""
        return self._by_radius(
            "torque_gap", b, lambda d: GROSS_SLIP_TORQUE - asymptotics.onset_torque(d),
            lambda x: self._small["gap_ratio"] * x**3, (0.0, 1.0 / 3.0))

    def rotation_at_radius(self, b):
        """omega(b) (f p0 / mu); +inf at b = 0."""
        return self._by_radius(
            "rigid_rotation", b, asymptotics.onset_rotation,
            lambda x: self._small["rotation"] + 0.5 * np.log(self.b_low / x), (math.inf, 0.0))

    def work_at_radius(self, b):
        """W_mono(b) ((f p0)^2 a^3 / mu); +inf at b = 0."""
        s = self._small
        return self._by_radius(
            "loading_work", b, lambda d: _onset_work(asymptotics.onset_torque(d) - 1.0),
            lambda x: s["work"] + s["work_slope"] * np.log(self.b_low / x), (math.inf, 0.0))

    # ------------------------------------------------------------------ by torque
    def _by_torque(self, name: str, tau):
        tau = np.asarray(tau, dtype=float)
        stick, spin = {"stick_radius": (1.0, 0.0), "rigid_rotation": (0.0, math.inf),
                       "loading_work": (0.0, math.inf)}[name]
        out = np.full(tau.shape, np.nan)
        gap = np.asarray(spinning_deficit(tau), dtype=float)
        out[tau <= 1.0] = stick
        spinning = gap <= SPIN_TOLERANCE * GROSS_SLIP_TORQUE
        out[spinning] = spin
        onset = (tau > 1.0) & (tau < self.trust_torque)
        if onset.any():
            excess = tau[onset] - 1.0
            delta = _onset_radius(excess)
            out[onset] = {"stick_radius": 1.0 - delta, "rigid_rotation": asymptotics.onset_rotation(delta),
                          "loading_work": _onset_work(excess)}[name]
        middle = (tau >= self.trust_torque) & (tau <= self.t_split)
        if middle.any():
            out[middle] = self.t_curves[name](tau[middle])
        high = (tau > self.t_split) & ~spinning
        if high.any():
            out[high] = self.u_curves[name](np.cbrt(gap[high]))
        return out if out.ndim else float(out)

    def stick_radius(self, tau):
        """b(tau) for 0 <= tau <= 4/3 (1 in stick, 0 at spinning)."""
        return self._by_torque("stick_radius", tau)

    def rotation(self, tau):
        """omega_m(tau) of a monotonic loading to tau (0 in stick, +inf at spinning)."""
        return self._by_torque("rigid_rotation", tau)

    def work(self, tau):
        """W_mono(tau): work against friction of a monotonic loading to tau (``curves.work``)."""
        return self._by_torque("loading_work", tau)

    def state(self, tau: float) -> tuple[float, float, float]:
        """(b, omega_m, W_mono) at one torque 0 <= tau <= 4/3, without numpy overhead."""
        if tau <= 1.0:
            return 1.0, 0.0, 0.0
        gap = float(spinning_deficit(tau)) if tau > self.t_split else 0.0
        if tau > self.t_split:
            if gap <= SPIN_TOLERANCE * GROSS_SLIP_TORQUE:
                return 0.0, math.inf, math.inf
            u = gap ** (1.0 / 3.0)
            c = self.u_curves
            return c["stick_radius"].scalar(u), c["rigid_rotation"].scalar(u), c["loading_work"].scalar(u)
        if tau < self.trust_torque:
            excess = tau - 1.0
            delta = float(_onset_radius(excess))
            return 1.0 - delta, float(asymptotics.onset_rotation(delta)), float(_onset_work(excess))
        c = self.t_curves
        return c["stick_radius"].scalar(tau), c["rigid_rotation"].scalar(tau), c["loading_work"].scalar(tau)

    def rotation_integral(self, tau):
        """int_1^tau omega_m(t) dt = int_b^1 omega(c) |dT*/dc| dc (Gauss-Legendre per panel of the b table).

        Used for the torque-twist route of the loop energy: pi times the area of a loop of
        range A is pi [2 A omega_m(A/2) - 8 int_1^(A/2) omega_m dt] (``histories.energy``).
        """
        taus = np.atleast_1d(np.asarray(tau, dtype=float))
        x, w = np.polynomial.legendre.leggauss(48)
        torque, rotation = self.by_radius["torque"], self.by_radius["rigid_rotation"]
        slope = torque.derivative
        out = np.empty(taus.shape)
        for i, t in enumerate(taus):
            b = float(self.stick_radius(t))
            if b >= 1.0:
                out[i] = 0.0
                continue
            edges = [b, *[e for e in torque.edges if b < e < self.b_high], self.b_high]
            total = 0.0
            for lo, hi in zip(edges[:-1], edges[1:], strict=True):
                c = 0.5 * (hi - lo) * (x + 1.0) + lo
                total += 0.5 * (hi - lo) * float(np.sum(w * rotation(c) * -slope(c)))
            # the onset stretch b_high < c < 1: omega = (pi^3/12) e^3 with e = T* - 1
            total += _OMEGA_ONSET * (float(self.torque(self.b_high)) - 1.0) ** 4 / 4.0
            out[i] = total
        return out if np.ndim(tau) else float(out[0])


def _first_panel_slope(curve: Piecewise) -> float:
    """d/dv of ``curve`` at its lower edge (first panel only)."""
    c = curve.coefficients[0]
    k = np.arange(c.size)
    return float(np.sum(c * (-1.0) ** (k + 1) * k**2)) * 2.0 / (curve.edges[1] - curve.edges[0])


@functools.lru_cache(maxsize=1)
def monotonic_curves() -> MonotonicCurves:
    """The curves of the shipped table (``curves.table.TABLE_PATH``), loaded once per process."""
    return MonotonicCurves(read_table(TABLE_PATH))
