r"""Frictional work, dissipation per cycle and slip records of torque histories.

Units: energies in (f p0)^2 a^3 / mu; slip in f p0 a / mu; T* = 2T/(f F a).

Energy
------
The torque does work T dphi on the relative rotation phi = 2 omega f p0 / mu of the
far ends beyond the uniform twist (the lower cylinder rotates by -omega), and
T = pi a^3 f p0 T* / 2, so the work per cycle is

    W = pi * oint T* d omega          [(f p0)^2 a^3 / mu].

The frictional work is int over the cycle of int_0^a sigma_zt ds 2 pi r dr, i.e.

    W = 2 pi * oint int_0^1 q(r) ds(r) r dr,

and with q = +-1 on the slip annulus of each branch and slip monotonic on a branch,
W(A) = 8 pi int_0^1 s_m(r; A/2) r dr = 4 W_mono(A/2) for a loop of range A (Masing:
independent of the mean torque; W_mono of ``curves.work``).  The torque-twist route gives
the same number from omega_m alone: with the branches omega = omega_max - 2 omega_m(tau),
T* = T_max - 2 tau down and their mirror images up,

    W(A) = pi oint T* d omega = pi [2 A omega_m(A/2) - 8 int_1^(A/2) omega_m(t) dt],

(``dissipation_from_loop_area``); the two routes share no computation beyond the
Abel-Fredholm solutions themselves (the slip on one side, omega(b) and T*(b) on the other).

Just above the cyclic-slip threshold, A = 2 (1 + eps): the slip
annulus is an edge crack of depth delta = 1 - b in anti-plane shear (the free
surface r = 1 reflects it into a centre crack of length 2 delta) loaded by
T* (1 - x) - 1 ~ eps - x; a bounded (K_III = 0) tip needs delta = pi eps / 2, the slip
is O(delta^2), and by reciprocity with the uniform load (crack opening 2 sqrt(delta^2
- x^2) per unit load, mu = 1) int s dx = 2 int (eps - |x|) sqrt(delta^2 - x^2) dx =
pi^3 eps^3 / 12 over the reflected crack.  Betti with the uniform twist gives
omega = 2 int_0^1 s r^2 dr ~ int s dx and W = 8 pi int s_m r dr ~ 4 pi int s dx.
Hence near the onset

    1 - b ~ (pi/2)(T* - 1),   omega_m ~ (pi^3/12)(T* - 1)^3,
    d omega_m / d T* ~ (pi^3/4)(T* - 1)^2,   W ~ (pi^4/3) eps^3 = (pi^4/24)(A - 2)^3.

The extra torsional compliance of the slipping interface, d phi / d T = (4 / (pi mu
a^3)) d omega / d T*, equals that of an added shaft length 2 a d omega / d T*.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from scipy import special

from .. import models, validation
from ..backends import METHODS, Series
from ..quadrature import gauss_legendre_panels
from ..special.zeros import bessel_j2_zeros
from .memory import InterfaceState

__all__ = [
    "slip_increments",
    "cumulative_slip",
    "frictional_work",
    "loading_work",
    "dissipation_per_cycle",
    "dissipation_from_loop_area",
    "threshold_asymptotics",
]


# --------------------------------------------------------------------------- slip records
def slip_increments(states: Sequence[InterfaceState], r, *, start: InterfaceState | None = None) -> np.ndarray:
    """Slip change (f p0 a / mu) over each step: array (len(states), *r.shape).

    The first step is measured from ``start`` (default: the virgin interface).
    """
    r = np.asarray(r, dtype=float)
    previous = np.zeros(r.shape) if start is None else start.slip(r)
    out = []
    for s in states:
        current = s.slip(r)
        out.append(current - previous)
        previous = current
    return np.array(out)


def cumulative_slip(states: Sequence[InterfaceState], r, *, start: InterfaceState | None = None) -> np.ndarray:
    """Total slip distance sum_k |s_k(r) - s_{k-1}(r)| (f p0 a / mu) along the history.

    Exact when every step is one monotonic branch segment: the slip at each r is then
    monotonic during the step (its rate has the sign of the traction, +-1).
    """
    return np.sum(np.abs(slip_increments(states, r, start=start)), axis=0)


def _radial_rule(states: Sequence[InterfaceState]):
    """Composite Gauss-Legendre on [0, 1] for products of interface fields of ``states``.

    Weak forms: panels of 20 / lam_N (the truncated series are entire functions of r whose
    products oscillate at most like exp(2 i lam_N r)).  Abel-Fredholm: panels of 0.05 split
    at every stick radius involved, where traction and slip have (r - b)^(1/2) and
    (r - b)^(3/2) end behaviour.
    """
    if states[0].n_terms is not None and METHODS[states[0].method].truncated:  # a weak form (cylinder model)
        return gauss_legendre_panels(0.0, 1.0, 20.0 / bessel_j2_zeros(states[0].n_terms)[-1])
    radii = {s.source.point(tau)[0] for s in states for _, tau in s.terms}
    return gauss_legendre_panels(0.0, 1.0, 0.05, sorted(radii))


def _interface_fields(states, nodes):
    """Traction and slip of every state at ``nodes``, each distinct monotonic solution evaluated once.

    Partial-slip weak-form solutions are summed with one shared matrix J1(lam_n r_i) (the
    same sums as ``Solution.traction`` / ``Solution.slip`` on z = 0, eqs. 25-26, without
    their per-call Bessel evaluations); other solutions use the ``Solution`` methods.
    """
    bessel = None
    memo: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    out = []
    for state in states:
        q = np.zeros(nodes.shape)
        s = np.zeros(nodes.shape)
        for w, sol in state.components:
            if id(sol) not in memo:
                if sol.regime == "partial-slip" and isinstance(sol.backend, Series):
                    series = sol.backend.solution
                    if bessel is None or bessel.shape[1] != series.eigenvalues.size:
                        bessel = special.j1(np.outer(nodes, series.eigenvalues))
                    rigid = sol.backend.rigid_rotation
                    memo[id(sol)] = (
                        sol.sign * (series.torque * nodes - bessel @ (series.amplitudes * series.eigenvalues)),
                        2.0 * sol.sign * (rigid * nodes + bessel @ series.amplitudes),
                    )
                else:
                    memo[id(sol)] = (sol.traction(nodes), sol.slip(nodes))
            q = q + w * memo[id(sol)][0]
            s = s + w * memo[id(sol)][1]
        out.append((q, s))
    return out


def frictional_work(states: Sequence[InterfaceState]) -> float:
    """2 pi sum_k int_0^1 (q_k + q_{k+1})/2 (s_{k+1} - s_k) r dr ((f p0)^2 a^3 / mu).

    The frictional work along the sampled path ``states`` (trapezoidal rule in time,
    composite Gauss-Legendre in r), from the tractions and slips of the states alone
    (omega is used only through the slip): an independent check of
    ``InterfaceState.dissipated_energy`` (second order in the sampling of the path).
    For the weak forms and a closed loop it equals ``loop_work`` to rounding whatever
    the sampling: with the traction (ii) and displacement (i) of ``solvers.weak_form`` the
    work of q on the eigenfunction part of the slip is the change of the elastic energy
    sum_n lam_n h_n c_n^2 / 2, which the trapezoidal rule telescopes exactly, and the work
    on the rigid part is pi T* d omega (int_0^1 r^2 J1(lam_n r) dr = 0).
    """
    if len(states) < 2:
        return 0.0
    nodes, weights = _radial_rule(states)
    fields = _interface_fields(states, nodes)
    total = 0.0
    for (q0, s0), (q1, s1) in zip(fields[:-1], fields[1:], strict=True):
        total += float(np.sum(0.5 * (q0 + q1) * (s1 - s0) * nodes * weights))
    return 2.0 * math.pi * total


def loading_work(tau, *, method=None, n_terms=None, model=None) -> float:
    """W_mono(tau) = 2 pi int_b^1 q s_m(r; tau) r dr: work against friction of a monotonic loading to tau.

    Units (f p0)^2 a^3 / mu; for the cylinders 0 for tau <= 1, +inf at tau = 4/3 (spinning).  The
    contact model's own (``ContactModel.loading_work``): for the cylinders' default method the
    interpolant of ``curves`` (eq. (W2) of ``curves.work``); weak forms: quadrature of their slip.

    Raises
    ------
    ValueError
        If tau is not finite or outside [0, gross-slip torque].
    """
    return models.get(model).loading_work(tau, method=method, n_terms=n_terms)


def dissipation_per_cycle(torque_range, *, method=None, n_terms=None, model=None) -> float:
    """W(A) = 4 W_mono(A/2) ((f p0)^2 a^3 / mu): the model's ``ContactModel.energy_per_cycle``.

    The energy dissipated per closed loop of range A (any mean torque): on each half
    cycle the traction is the friction limit on the slip annulus and the slip increment
    there is 2 s_m(r; A/2) (memory rule 2); zero for A <= 2 for the cylinders.

    Raises
    ------
    ValueError
        If A is not finite or outside [0, 2 x gross-slip torque].
    """
    return models.get(model).energy_per_cycle(torque_range, method=method, n_terms=n_terms)


def dissipation_from_loop_area(torque_range, *, method=None, n_terms=None, model=None) -> float:
    """(pi n / 2) times the area of the loop of range A in the (omega, T*) plane (module docstring).

    (pi n / 2) [2 A omega_m(A/2) - 8 int_0^(A/2) omega_m dt], n the model's elastic bodies (2 for
    the cylinders: pi [...]), from omega_m(tau) alone (``Monotonic.rotation_integral``: for the
    cylinders' default method the Abel-Fredholm curves omega(b) and T*(b),
    ``curves.MonotonicCurves.rotation_integral``; otherwise Gauss-Legendre panels of omega_m); no
    slip profile is used, so this is an independent route to W(A) = 4 W_mono(A/2).

    Raises
    ------
    ValueError
        If A is not finite or outside [0, 2 x gross-slip torque].
    """
    contact = models.get(model)
    value = validation.real_number("torque_range", torque_range, 0.0, 2.0 * contact.gross_slip_torque)
    tau = value / 2.0
    source = contact.monotonic(method, n_terms)
    omega = source.point(tau)[1]
    area = 2.0 * value * omega - 8.0 * source.rotation_integral(tau)
    return 0.5 * math.pi * contact.elastic_bodies * area


def threshold_asymptotics(eps):
    """Leading terms just above slip onset / the cyclic-slip threshold (module docstring).

    Parameters
    ----------
    eps : array_like
        T* - 1 for the monotonic curve, or A/2 - 1 for a loop of range A.

    Returns
    -------
    dict of ndarray: ``slip_annulus`` (1 - b), ``rigid_rotation`` (omega_m),
    ``compliance`` (d omega_m / d T*), ``dissipation`` (W per cycle).
    """
    eps = np.asarray(eps, dtype=float)
    return {
        "slip_annulus": 0.5 * math.pi * eps,
        "rigid_rotation": math.pi**3 / 12.0 * eps**3,
        "compliance": math.pi**3 / 4.0 * eps**2,
        "dissipation": math.pi**4 / 3.0 * eps**3,
    }
