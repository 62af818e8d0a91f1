r"""Arbitrary torque histories: memory, shakedown, hysteresis and dissipation.

Units (docs/conventions.md): r in a; torque T* = 2T/(f F a) (eq. 32); tractions in f p0;
displacements and slip in f p0 a / mu; omega (rigid rotation of the upper cylinder
beyond uniform twist) in f p0 / mu; energies in (f p0)^2 a^3 / mu
(= (f F)^2 / (pi^2 mu a)).

Memory rules (Cattaneo-Mindlin, Masing)
---------------------------------------
Write mono(tau) for the monotonic solution of ``solve`` at torque 0 <= tau <= 4/3
(friction limit 1, eqs. 7-8): traction q_m(r; tau), displacement u_m, rigid rotation
omega_m(tau), stick radius b(tau) (b = 1 for tau <= 1).

1. *The contact pressure never changes.*  The torsion problem is uncoupled (section 4):
   u_theta does not alter sigma_zz = -p0 (eq. 1), so the friction limit is f p0 at every
   point and for every torque.  The problem for (u_theta, traction) is then linear
   and positively homogeneous in the pair (torque, friction limit): the solution with
   torque k tau and friction limit k is k mono(tau).

2. *Reversal.*  Load monotonically to T_k > 1 (state S_k = mono(T_k): stick disc r <
   b_k, traction 1 on b_k < r <= 1) and reverse.  Try

       S(T) = S_k - 2 mono((T_k - T)/2),                                          (M)

   i.e. the increment is the monotonic solution for torque decrement T_k - T and
   friction limit 2.  Write tau = (T_k - T)/2 and c = b(tau).
   * On r < c the increment has zero displacement: those points do not slip, the
     traction is q_k - 2 q_m.
   * On c < r <= 1 the increment carries traction -2, so q = q_k - 2.  This is the
     reversed friction limit -1 *only where q_k = 1*, i.e. if the reverse-slip annulus
     lies inside the previous slip annulus: c >= b_k.  Because b(.) decreases and
     tau <= T_k while T >= -T_k, c = b(tau) >= b(T_k) = b_k: the reverse-slip annulus
     always stays outside the previous stick disc, so (M) satisfies the boundary
     conditions exactly (not approximately) and, by uniqueness of the mixed problem,
     is *the* solution.  The slip increment -2 s_m(r; tau) is <= 0 where the traction
     is -1 (slip opposes the friction force), and |q| <= 1 on r < c because q_m grows
     with tau at every r: 2 q_m(tau) <= q_m(tau) + q_m(T_k) <= 1 + q_k (checked
     numerically in the tests).
   * In stick (2 tau <= 2, i.e. a torque range |T - T_k| <= 2) the increment is the
     elastic field -(T_k - T) r: no point slips.  The first reverse slip appears at
     r = a when the range reaches 2: after loading to 1.23 (b = 0.6, Fig. 5) reverse
     slip starts at T* = 1.23 - 2 = -0.77, as the paper states.  The traction when the
     torque returns to zero, q_k(r) - T_k r, is the residual traction of Fig. 5.
3. *Shakedown (Melan, section 4).*  A torque oscillating over a range A = T_max -
   T_min <= 2 after the first loading to T_max never slips again (by 2.: every
   reversal after the first one has range <= 2), so the interface shakes down to full
   stick after the first loading.  A > 2 gives reverse slip over c = b(A/2) < r <= 1 on
   every half cycle: cyclic slip, closed hysteresis loops, dissipation.
4. *Nested reversals, the stack (Masing closure).*  Keep the stack of remembered
   turning points T_1, T_2, ..., T_k (ranges |T_{j+1} - T_j| strictly decreasing; T_1
   lies on the virgin ("skeleton") curve S = sign(T) mono(|T|)).  The current branch
   is S(T) = S(T_k) + d 2 mono(|T - T_k|/2), d = sign(T - T_k), valid while the
   branch has not passed T_{k-1}: the argument of 2. applies with S_k replaced by the
   branch state from T_{k-1}, whose slip annulus is where its traction equals -d.  At
   T = T_{k-1} the branch returns *exactly* to S(T_{k-1}) (two opposite, equal
   increments), so the inner loop T_{k-1} -> T_k -> T_{k-1} is closed and erased: T_k
   and T_{k-1} are popped, and the continuation is the branch that led to T_{k-1}.
   For k = 1 the limit is -T_1: there the branch meets the mirrored skeleton,
   S(-T_1) = mono(T_1) - 2 mono(T_1) = -mono(T_1), T_1 is popped and the state
   continues on the skeleton.  The rules are the rainflow stack rules.

Each state is thus a short linear combination of monotonic solutions (one per stack
level); traction, slip, stresses and omega are the same combinations.  The numbers of a
state need only b(tau), omega_m(tau) and W_mono(tau) (``histories.monotonic``: interpolants
of ``curves`` for the default method), the profiles the solutions themselves, built on
first use.  The stick
radius of a state is b of its current branch (1 when the current branch has not
slipped); the slip fronts remembered are the stick radii at which the remembered
branches ended.  A loop is erased when its branch *reaches* the earlier turning point
(equality included, so repeated cycles between the same torques keep a bounded
stack); the state there is the earlier state itself, with the stick radius of the
closing branch (1 for a range <= 2: no slip during that half cycle).

5. *Dissipated energy.*  On the virgin curve every slipping point carries traction +-1 and
   the slip grows monotonically: the work against friction up to |T| is W_mono(|T|).  On
   a branch from T_k the traction is -+1 where the increment 2 d mono(tau) slips and the
   slip increment is 2 d s_m(r; tau): the work is 2 pi int 1 * 2 s_m r dr = 2 W_mono(tau)
   (the friction limit is the old one reversed, not twice it).  So a stretch of a
   branch (g = 2) or of the virgin curve (g = 1, origin 0) from tau_a to tau_b adds
   g [W_mono(tau_b) - W_mono(tau_a)], a closed loop of range A adds
   W(A) = 4 W_mono(A/2), and ``dissipated_energy`` of a state is the sum over its whole
   path since the virgin state (it does not return when a loop closes).

Independent check: ``verification.incremental`` solves the incremental mixed problem (no slip on
0 <= r < c relative to the remembered displacement, traction -+1 on c < r <= 1)
directly in the weak form; tests/test_history.py compares it with (M) and its
nested versions.

Models.  The rules use only the uncoupling (rule 1: a pressure that never changes), a stick
radius b(tau) that falls and a traction q_m(r; tau) that grows with tau, with the friction
limit f p(r) of the model's pressure in place of f p0: they hold as they stand for every contact
model of ``models`` (the half-space models slip at any torque, b < 1 for every tau > 0, so every
reversal slips and nothing shakes down; the range 2 above is twice the model's slip onset,
``ContactModel.reversal_slip_range``, and 4/3 its gross-slip torque).  A state reaches the
monotonic solutions only through its model's ``monotonic`` (``state.source``: ``point`` /
``solution``).

Energies, loops and dissipation: ``energy`` and ``loops``.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass, field

import numpy as np

from .. import models, validation
from ..contact_models.base import ContactModel
from ..contact_models.cylinder import DEFAULT_METHOD, monotonic_solution
from ..records import StateRecord
from ..solution import Solution
from .masing import MasingStack

__all__ = [
    "DEFAULT_METHOD",
    "CYCLIC_SLIP_RANGE",
    "TurningPoint",
    "InterfaceState",
    "initial_state",
    "monotonic_solution",
    "advance",
    "history",
    "turning_points",
]

#: Torque range above which a reversal of the cylinders slips again (twice the slip-onset torque; every model:
#: ``ContactModel.reversal_slip_range``).
CYCLIC_SLIP_RANGE = models.get().reversal_slip_range


# --------------------------------------------------------------------------- states
@dataclass(frozen=True)
class TurningPoint:
    """A remembered reversal: its torque, the slip front of the branch that ended there, its state."""

    torque: float
    slip_front: float
    state: InterfaceState = field(repr=False, compare=False)


@dataclass(frozen=True)
class InterfaceState:
    """Interface state after a torque history (see the module docstring).

    Attributes
    ----------
    torque : float
        Current T*.
    stick_radius : float
        Radius (units a) inside which no slip has occurred during the current loading
        branch: b(|T - T_k|/2) after a reversal at T_k, b(|T|) on the virgin curve.
    direction : int
        +1 (torque increasing), -1 (decreasing), 0 (virgin state, no step yet).
    memory : tuple of TurningPoint
        The stack of remembered turning points, oldest first.
    terms : tuple of (float, float)
        The state as sum_j w_j mono(tau_j): pairs (w_j, tau_j) (weights +-1 on the virgin
        curve, +-2 on branches).
    method, n_terms :
        The monotonic solutions' method (``fast``: n_terms None) and resolution (None, None
        for a model without methods).
    front : float
        Slip front of the (Masing) branch the state lies on; remembered as the slip
        front of this state if the torque reverses here.  Equal to ``stick_radius``
        except where a branch has just closed a loop exactly at an earlier turning
        point: the state is then that earlier state (with its front) while the stick
        radius is that of the closing branch (1 if its range was <= 2).
    rigid_rotation : float
        omega (f p0 / mu): the same combination of the monotonic omegas; +-inf after spinning.
    dissipated_energy : float
        Work against friction since the virgin state, first loading included
        ((f p0)^2 a^3 / mu; rule 5 of the module docstring); +inf after spinning.
    contact : ContactModel
        The contact model (``models``) whose monotonic solutions the state combines; ``model`` is its name.
    """

    torque: float
    stick_radius: float
    direction: int
    memory: tuple[TurningPoint, ...]
    terms: tuple[tuple[float, float], ...] = field(repr=False)
    method: str = DEFAULT_METHOD
    n_terms: int | None = None
    front: float = 1.0
    rigid_rotation: float = 0.0
    dissipated_energy: float = 0.0
    contact: ContactModel = field(default_factory=models.get, repr=False)

    @property
    def model(self) -> str:
        """The name of the state's contact model."""
        return self.contact.name

    @property
    def source(self):
        """The contact model's monotonic solution for this state's (method, n_terms)."""
        return self.contact.monotonic(self.method, self.n_terms)

    @property
    def regime(self) -> str:
        """Of the current branch: "stick" (no slip since the last reversal), "partial-slip", "gross-slip"."""
        if self.stick_radius >= 1.0:
            return "stick"
        return "gross-slip" if self.stick_radius <= 0.0 else "partial-slip"

    @property
    def slip_fronts(self) -> tuple[float, ...]:
        """Radii of the slip fronts remembered from earlier branches (< 1 only), stack order."""
        return tuple(tp.slip_front for tp in self.memory if tp.slip_front < 1.0)

    @property
    def turning_torques(self) -> tuple[float, ...]:
        return tuple(tp.torque for tp in self.memory)

    @functools.cached_property
    def components(self) -> tuple[tuple[float, Solution], ...]:
        """The pairs (w_j, mono(tau_j)) with the monotonic solutions (built on first use, cached)."""
        source = self.source
        return tuple((w, source.solution(tau)) for w, tau in self.terms)

    def traction(self, r):
        """sigma_zt(r, 0) / (f p0)."""
        return sum(w * s.traction(r) for w, s in self.components)

    def slip(self, r):
        """Net slip s(r) = 2 u_theta(r, 0+) (f p0 a / mu) accumulated over the whole history."""
        return sum(w * s.slip(r) for w, s in self.components)

    def residual_traction(self, r):
        """Traction (f p0) left when the torque is taken back to zero from this state.

        The traction of the state that the memory rules give at T* = 0 from here (``advance``):
        for the cylinders a change of |T| <= 4/3 < 2 never slips (memory rule 2) and this is
        traction - T r, but a half-space slips at any reversal, so the unloading is solved, not
        assumed elastic.
        """
        return advance(self, 0.0).traction(r)

    def stress(self, r, z):
        """(sigma_zt, sigma_rt) / (f p0) at (r, z), z >= 0, by superposition (eqs. 2, 3, 23, 24)."""
        parts = [s.stress(r, z) for _, s in self.components]
        return (
            sum(w * p[0] for (w, _), p in zip(self.components, parts, strict=True)),
            sum(w * p[1] for (w, _), p in zip(self.components, parts, strict=True)),
        )

    def displacement(self, r, z):
        """u_theta(r, z) of the upper cylinder (f p0 a / mu), eqs. (4), (22), by superposition."""
        return sum(w * s.displacement(r, z) for w, s in self.components)

    def record(self) -> StateRecord:
        """The state's result record (``records``: keys and their quantities)."""
        return StateRecord(self.torque, self.stick_radius, list(self.slip_fronts), list(self.turning_torques),
                           self.rigid_rotation, self.regime, self.dissipated_energy, self.direction, self.method,
                           self.n_terms, self.model)

    def as_dict(self) -> dict:
        """JSON-ready summary (non-finite numbers -> None)."""
        return self.record().as_dict()


def initial_state(*, method=None, n_terms=None, model=None) -> InterfaceState:
    """The virgin interface: T* = 0, no slip, nothing remembered, no energy dissipated."""
    contact = models.get(model)
    source = contact.monotonic(method, n_terms)
    return InterfaceState(0.0, 1.0, 0, (), ((1.0, 0.0),), source.method, source.n_terms, 1.0, 0.0, 0.0, contact)


def _stack(state: InterfaceState) -> MasingStack:
    """The Masing engine's stack of ``state``: its remembered turning points (labels: the ``TurningPoint``s)."""
    return MasingStack([tp.torque for tp in state.memory], state.memory, state.direction, state.torque)


def _reversal(state: InterfaceState):
    """The label remembered if the step from ``state`` reverses (made only then)."""
    return lambda: TurningPoint(state.torque, state.front, state)


def _origin_torque(origin) -> float:
    return origin.torque if isinstance(origin, TurningPoint) else 0.0


def _memory(origin) -> tuple:
    """The stack a branch from ``origin`` lies on: the one of its state when it was reached, and itself (or none:
    the virgin curve)."""
    return (*origin.state.memory, origin) if isinstance(origin, TurningPoint) else ()


def _compose(memory, direction, tau, torque, energy, source) -> InterfaceState:
    """State on the branch from the newest point of ``memory`` (or the virgin curve) at increment tau.

    ``source``: the model's monotonic solution (``ContactModel.monotonic``)."""
    b, omega, _ = source.point(tau)
    if memory:
        origin = memory[-1].state
        terms = origin.terms + ((2.0 * direction, tau),)
        omega = origin.rigid_rotation + 2.0 * direction * omega
    else:
        terms = ((float(direction), tau),)
        omega = direction * omega
    return InterfaceState(torque, b, direction, tuple(memory), terms, source.method, source.n_terms, b, omega, energy,
                          source.contact)


def _closure(origin: TurningPoint, closure, direction, torque, energy, source) -> InterfaceState:
    """State where the branch from ``origin`` reaches its limit exactly (rule 4), ``closure`` the engine's label.

    It is the earlier state at that torque (the inner loop cancels exactly: the same
    monotonic solutions with opposite weights), or the mirrored virgin state (``masing.MIRROR``)
    for a single remembered point; the stick radius is that of the closing branch; the
    dissipated energy is the one accumulated on the way.
    """
    closing, _, _ = source.point(abs(torque - origin.torque) / 2.0)
    if isinstance(closure, TurningPoint):
        earlier = closure.state
    else:
        earlier = _compose((), direction, abs(torque), torque, energy, source)
    return dataclasses.replace(earlier, torque=torque, stick_radius=closing, direction=direction,
                               dissipated_energy=energy)


def advance(state: InterfaceState, torque) -> InterfaceState:
    """The state after a monotonic torque change from ``state.torque`` to ``torque``.

    Parameters
    ----------
    state : InterfaceState
    torque : float
        Target T*, within the model's gross-slip torque ([-4/3, 4/3] for the cylinders).

    Returns
    -------
    InterfaceState
        By the memory rules of the module docstring (the stack of ``histories.masing``: loops
        closed on the way are erased; the energy dissipated on the way is added, rule 5).

    Raises
    ------
    ValueError
        If ``torque`` is not finite or |torque| is above the model's gross-slip torque (4/3 for the
        cylinders: they spin).
    """
    t = state.contact.checked_torque("torque", torque)
    if t == state.torque:
        return state
    source, gross = state.source, state.contact.gross_slip_torque
    d = 1 if t > state.torque else -1
    stack = _stack(state)
    position, energy = state.torque, state.dissipated_energy
    pieces = stack.step(t, _reversal(state))
    for origin, g, end, _ in pieces:
        origin_torque = _origin_torque(origin)
        tau_a, tau_b = abs(position - origin_torque) / g, min(abs(end - origin_torque) / g, gross)
        energy += g * (source.point(tau_b)[2] - source.point(tau_a)[2])
        position = end
    origin, closure = pieces[-1][0], pieces[-1][3]
    if closure is None:  # the last piece: on a branch, or exactly at the point where its loop closed
        return _compose(_memory(origin), d, tau_b, t, energy, source)
    return _closure(origin, closure, d, t, energy, source)


def history(torques, *, method=None, n_terms=None, model=None,
            start: InterfaceState | None = None) -> tuple[InterfaceState, ...]:
    """States after each step of a torque history, starting from the virgin interface.

    Parameters
    ----------
    torques : sequence or array of float
        T* after each step (turning points, or any points: consecutive points in the
        same direction are simply one branch sampled more finely).  Each within the model's
        gross-slip torque ([-4/3, 4/3] for the cylinders).
        A long sampled signal is better served by ``histories.signal.analyse_signal``
        (arrays instead of objects, the same numbers).
    method : {"fast", "complete", "published"}, optional
        The monotonic solutions: ``fast`` (default, the Abel-Fredholm method through the
        interpolants of ``curves``) or a weak form at ``n_terms`` (default 145).
    n_terms : int, optional
    model : str or ContactModel, optional
        The contact model (a name of ``models.MODELS`` or a model object; default the cylinders).
        The rules are the same for every model, with its monotonic solution.
    start : InterfaceState, optional
        Continue from this state instead of the virgin interface (its model and method are kept).

    Returns
    -------
    tuple of InterfaceState, one per entry of ``torques``.

    Raises
    ------
    ValueError
        Naming ``torques[i]`` for a non-finite entry or |T*| above the model's gross-slip torque; for an
        empty history; for an unknown method or n_terms < 1; for an unknown model, or a method or n_terms
        with a model that has no methods.
    """
    state = initial_state(method=method, n_terms=n_terms, model=model) if start is None else start
    values = validation.torque_sequence("torques", torques, checked=state.contact.checked_torque)
    out = []
    for t in values:
        state = advance(state, t)
        out.append(state)
    return tuple(out)


def turning_points(signal) -> np.ndarray:
    """Reduce a sampled torque signal to its turning points (first and last samples kept).

    Repeated samples are merged and samples where the signal keeps its direction are
    dropped; by the memory rules the states at the turning points, and the state at the
    end, do not depend on the dropped samples.

    Raises
    ------
    ValueError
        For an empty signal, non-finite samples or |T*| > 4/3 (naming ``signal[i]``).
    """
    from .signal import turning_point_indices, validated_signal

    values = validated_signal("signal", signal)
    return values[turning_point_indices(values)]
