r"""Arbitrary torque histories: memory, shakedown, hysteresis and dissipation.

Units (CONTRACT.md): r in a; torque T* = 2T/(f F a) (eq. 32); tractions in f p0;
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
level); traction, slip, stresses and omega are the same combinations.  The stick
radius of a state is b of its current branch (1 when the current branch has not
slipped); the slip fronts remembered are the stick radii at which the remembered
branches ended.  A loop is erased when its branch *reaches* the earlier turning point
(equality included, so repeated cycles between the same torques keep a bounded
stack); the state there is the earlier state itself, with the stick radius of the
closing branch (1 for a range <= 2: no slip during that half cycle).

Independent check: ``incremental`` solves the incremental mixed problem (no slip on
0 <= r < c relative to the remembered displacement, traction -+1 on c < r <= 1)
directly in the weak form; tests/test_history.py compares it with (M) and its
nested versions.

Energy
------
The torque does work T dphi on the relative rotation phi = 2 omega f p0 / mu of the
far ends beyond the uniform twist (the lower cylinder rotates by -omega), and
T = pi a^3 f p0 T* / 2, so the work per cycle is

    W = pi * oint T* d omega          [(f p0)^2 a^3 / mu].

The frictional work is int over the cycle of int_0^a sigma_zt ds 2 pi r dr, i.e.

    W = 2 pi * oint int_0^1 q(r) ds(r) r dr,

and with q = +-1 on the slip annulus of each branch and slip monotonic on a branch,
W(A) = 8 pi int_0^1 s_m(r; A/2) r dr for a loop of range A (Masing: independent of
the mean torque).  Just above the cyclic-slip threshold, A = 2 (1 + eps): the slip
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

import dataclasses
import functools
import math
import numbers
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy import special

from .formulations import GROSS_SLIP_TORQUE, resolution_limit
from .incremental import gauss_legendre_panels
from .solution import DEFAULT_N_TERMS, Solution, solve
from .warnings import ResolutionWarning
from .zeros import bessel_j2_zeros

__all__ = [
    "TurningPoint",
    "InterfaceState",
    "Loop",
    "initial_state",
    "validate_torques",
    "advance",
    "history",
    "turning_points",
    "sample_path",
    "monotonic",
    "slip_increments",
    "cumulative_slip",
    "hysteresis_loop",
    "loop_work",
    "frictional_work",
    "dissipation_per_cycle",
    "tangent_compliance",
    "relaxation_profiles",
    "threshold_asymptotics",
    "CYCLIC_SLIP_RANGE",
]

#: Default formulation of the histories: the complete weak form at the paper's N.  Its
#: truncated series makes the loop-area / frictional-work identity exact and is what the
#: direct incremental solve (``incremental``) checks; ``method="fast"`` is accepted
#: everywhere and gives the more accurate monotonic solutions of ``fast``.
DEFAULT_METHOD = "complete"

#: Torque range above which a reversal slips again (twice the slip-onset torque).
CYCLIC_SLIP_RANGE = 2.0
_LIMIT_TOL = 4 * np.finfo(float).eps
_ONSET_ULPS = 8


# --------------------------------------------------------------------------- validation
def _torque(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise ValueError(f"{name} must be a real number in [-4/3, 4/3], got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite and lie in [-4/3, 4/3], got {value!r}")
    if abs(value) > GROSS_SLIP_TORQUE * (1 + _LIMIT_TOL):
        raise ValueError(
            f"{name} must lie in [-4/3, 4/3], got {value!r}: above 4/3 the cylinders spin "
            "(gross slip), there is no static solution"
        )
    return max(-GROSS_SLIP_TORQUE, min(GROSS_SLIP_TORQUE, value))


def validate_torques(name: str, values) -> list[float]:
    """``values`` as a non-empty list of finite torques in [-4/3, 4/3], or ValueError naming ``name[i]``."""
    try:
        items = list(np.asarray(values, dtype=object).ravel()) if not isinstance(values, (str, bytes)) else None
    except TypeError as exc:  # not iterable
        raise ValueError(f"{name} must be a sequence of torques in [-4/3, 4/3], got {values!r}") from exc
    if items is None:
        raise ValueError(f"{name} must be a sequence of torques in [-4/3, 4/3], got {values!r}")
    if not items:
        raise ValueError(f"{name} must contain at least one torque in [-4/3, 4/3]")
    return [_torque(f"{name}[{i}]", v) for i, v in enumerate(items)]


# --------------------------------------------------------------------------- monotonic
@functools.lru_cache(maxsize=4096)
def _monotonic_cached(tau: float, method: str, n_terms: int) -> Solution:
    return solve(torque=tau, method=method, n_terms=n_terms)


def monotonic(tau: float, *, method=None, n_terms=None) -> Solution:
    """mono(tau): the monotonic solution at torque tau in [0, 4/3], friction limit 1 (cached).

    A tau within a few ulps of the slip onset 1 (e.g. (1.23 - (1.23 - 2)) / 2) is taken
    as 1: rounding must not open an unresolvable slip annulus.
    """
    tau = _torque("tau", tau)
    if tau < 0:
        raise ValueError(f"tau must lie in [0, 4/3], got {tau!r}")
    if abs(tau - 1.0) <= _ONSET_ULPS * np.finfo(float).eps:
        tau = 1.0
    method = DEFAULT_METHOD if method is None else method
    n_terms = DEFAULT_N_TERMS if n_terms is None else n_terms
    return _monotonic_cached(tau, method, n_terms)


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
    components : tuple of (float, Solution)
        The state as sum_j w_j mono(tau_j) (weights +-1 on the virgin curve, +-2 on
        branches).
    front : float
        Slip front of the (Masing) branch the state lies on; remembered as the slip
        front of this state if the torque reverses here.  Equal to ``stick_radius``
        except where a branch has just closed a loop exactly at an earlier turning
        point: the state is then that earlier state (with its front) while the stick
        radius is that of the closing branch (1 if its range was <= 2).
    """

    torque: float
    stick_radius: float
    direction: int
    memory: tuple[TurningPoint, ...]
    components: tuple[tuple[float, Solution], ...] = field(repr=False)
    method: str = DEFAULT_METHOD
    n_terms: int = DEFAULT_N_TERMS
    front: float = 1.0

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

    @property
    def rigid_rotation(self) -> float:
        """omega (f p0 / mu): the same combination of the monotonic omegas; +-inf after spinning."""
        return float(sum(w * s.rigid_rotation for w, s in self.components))

    def traction(self, r):
        """sigma_zt(r, 0) / (f p0)."""
        return sum(w * s.traction(r) for w, s in self.components)

    def slip(self, r):
        """Net slip s(r) = 2 u_theta(r, 0+) (f p0 a / mu) accumulated over the whole history."""
        return sum(w * s.slip(r) for w, s in self.components)

    def residual_traction(self, r):
        """Traction (f p0) left when the torque is taken back to zero from this state.

        Going to zero is a torque change of |T| <= 4/3 < 2, either a reversal or the
        continuation of a branch whose total range stays below 2; in both cases no
        point slips (memory rule 2) and the traction changes by -T r.
        """
        r = np.asarray(r, dtype=float)
        return self.traction(r) - self.torque * r

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

    def as_dict(self) -> dict:
        """JSON-ready summary (non-finite rotation -> None)."""
        omega = self.rigid_rotation
        return {
            "torque": self.torque,
            "stick_radius": self.stick_radius,
            "slip_fronts": list(self.slip_fronts),
            "turning_points": list(self.turning_torques),
            "rigid_rotation": omega if math.isfinite(omega) else None,
            "regime": self.regime,
            "direction": self.direction,
            "method": self.method,
            "n_terms": self.n_terms,
        }


def initial_state(*, method=None, n_terms=None) -> InterfaceState:
    """The virgin interface: T* = 0, no slip, nothing remembered."""
    method = DEFAULT_METHOD if method is None else method
    n_terms = DEFAULT_N_TERMS if n_terms is None else n_terms
    zero = monotonic(0.0, method=method, n_terms=n_terms)
    return InterfaceState(0.0, 1.0, 0, (), ((1.0, zero),), method, n_terms, 1.0)


def _sign(x: float) -> int:
    return 1 if x > 0 else -1


def _limit(stack: Sequence[TurningPoint]) -> float:
    """Torque at which the current branch closes its loop (rule 4)."""
    return stack[-2].torque if len(stack) >= 2 else -stack[-1].torque


def _pop(stack: list[TurningPoint]) -> None:
    if len(stack) >= 2:
        del stack[-2:]
    else:
        stack.pop()


def _start(state: InterfaceState, direction: int) -> list[TurningPoint]:
    """The stack for a step in ``direction`` from ``state`` (pushes the state on a reversal)."""
    stack = list(state.memory)
    if state.direction != 0 and direction != state.direction:
        stack.append(TurningPoint(state.torque, state.front, state))
    return stack


def _compose(stack, direction, mono: Solution, torque: float, method, n_terms) -> InterfaceState:
    """State on the branch from the top of ``stack`` (or the virgin curve) with increment ``mono``."""
    if stack:
        origin = stack[-1].state
        components = origin.components + ((2.0 * direction, mono),)
    else:
        components = ((float(direction), mono),)
    return InterfaceState(
        torque, mono.stick_radius, direction, tuple(stack), components, method, n_terms, mono.stick_radius
    )


def _closure(stack, direction, torque, method, n_terms) -> InterfaceState:
    """State where the branch from the top of ``stack`` reaches its limit exactly (rule 4).

    It is the earlier state at that torque (the inner loop cancels exactly: the same
    monotonic solutions with opposite weights), or the mirrored virgin state for a
    single remembered point; the stick radius is that of the closing branch.
    """
    closing = monotonic(abs(torque - stack[-1].torque) / 2.0, method=method, n_terms=n_terms)
    if len(stack) >= 2:
        earlier = stack[-2].state
    else:
        virgin = monotonic(abs(torque), method=method, n_terms=n_terms)
        earlier = _compose([], direction, virgin, torque, method, n_terms)
    return dataclasses.replace(earlier, torque=torque, stick_radius=closing.stick_radius, direction=direction)


def advance(state: InterfaceState, torque) -> InterfaceState:
    """The state after a monotonic torque change from ``state.torque`` to ``torque``.

    Parameters
    ----------
    state : InterfaceState
    torque : float
        Target T* in [-4/3, 4/3].

    Returns
    -------
    InterfaceState
        By the memory rules of the module docstring (loops closed on the way are erased).

    Raises
    ------
    ValueError
        If ``torque`` is not finite or |torque| > 4/3 (the cylinders spin).
    """
    t = _torque("torque", torque)
    if t == state.torque:
        return state
    d = _sign(t - state.torque)
    stack = _start(state, d)
    while stack and d * (t - _limit(stack)) > 0:
        _pop(stack)
    if stack and t == _limit(stack):
        return _closure(stack, d, t, state.method, state.n_terms)
    tau = abs(t - stack[-1].torque) / 2.0 if stack else abs(t)
    mono = monotonic(min(tau, GROSS_SLIP_TORQUE), method=state.method, n_terms=state.n_terms)
    return _compose(stack, d, mono, t, state.method, state.n_terms)


def history(torques, *, method=None, n_terms=None, start: InterfaceState | None = None) -> tuple[InterfaceState, ...]:
    """States after each step of a torque history, starting from the virgin interface.

    Parameters
    ----------
    torques : sequence of float
        T* after each step (turning points, or any points: consecutive points in the
        same direction are simply one branch sampled more finely).  Each in [-4/3, 4/3].
    method, n_terms :
        Passed to ``solve`` for the monotonic solutions.
    start : InterfaceState, optional
        Continue from this state instead of the virgin interface.

    Returns
    -------
    tuple of InterfaceState, one per entry of ``torques``.

    Raises
    ------
    ValueError
        Naming ``torques[i]`` for a non-finite entry or |T*| > 4/3; for an empty history.
    """
    values = validate_torques("torques", torques)
    state = initial_state(method=method, n_terms=n_terms) if start is None else start
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
    values = np.array(validate_torques("signal", signal))
    keep = np.concatenate([[True], np.diff(values) != 0])
    values = values[keep]
    if values.size <= 2:
        return values
    step = np.sign(np.diff(values))
    reversal = step[1:] != step[:-1]
    return np.concatenate([[values[0]], values[1:-1][reversal], [values[-1]]])


# --------------------------------------------------------------------------- dense paths
def _stick_radius_grid(b_start: float, b_end: float, n_points: int, n_terms: int) -> np.ndarray:
    """Interior stick radii from b_start (exclusive) down to b_end (exclusive), resolved ones only."""
    _, b_max = resolution_limit(n_terms)
    upper = min(b_start, b_max)
    if upper <= b_end:
        return np.empty(0)
    return np.linspace(upper, b_end, n_points + 1)[:-1][1 if upper == b_start else 0 :]


def sample_path(state: InterfaceState, torque, n_points: int = 40) -> tuple[InterfaceState, ...]:
    """States along the monotonic path from ``state`` to ``torque`` (start excluded, end included).

    Stick stretches are represented by their end points (there omega and slip are
    constant and the traction is linear in T*); slipping stretches by ``n_points``
    states equally spaced in the stick radius (solved directly for b, no inversion)
    between the resolved limit 1 - 10/lam_N and the end.  Closed loops met on the way
    are erased exactly as in ``advance``.
    """
    t = _torque("torque", torque)
    if t == state.torque:
        return ()
    d = _sign(t - state.torque)
    stack = _start(state, d)
    current = state.torque
    out: list[InterfaceState] = []
    while True:
        limit = _limit(stack) if stack else None
        closes = limit is not None and d * (t - limit) >= 0
        end = limit if closes else t
        origin, factor = (stack[-1].torque, 2.0) if stack else (0.0, 1.0)
        tau_a, tau_b = abs(current - origin) / factor, abs(end - origin) / factor
        mono_a = monotonic(min(tau_a, GROSS_SLIP_TORQUE), method=state.method, n_terms=state.n_terms)
        mono_b = monotonic(min(tau_b, GROSS_SLIP_TORQUE), method=state.method, n_terms=state.n_terms)
        if tau_a < 1.0 < tau_b:  # stick stretch ends at the slip onset
            onset = monotonic(1.0, method=state.method, n_terms=state.n_terms)
            out.append(_compose(stack, d, onset, origin + d * factor, state.method, state.n_terms))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResolutionWarning)  # only resolved radii are requested
            for b in _stick_radius_grid(mono_a.stick_radius, mono_b.stick_radius, n_points, state.n_terms):
                mono = solve(stick_radius=float(b), method=state.method, n_terms=state.n_terms)
                out.append(_compose(stack, d, mono, origin + d * factor * mono.torque, state.method, state.n_terms))
        if closes:
            out.append(_closure(stack, d, end, state.method, state.n_terms))
            if end == t:
                return tuple(out)
            _pop(stack)
            current = end
            continue
        out.append(_compose(stack, d, mono_b, t, state.method, state.n_terms))
        return tuple(out)


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


# --------------------------------------------------------------------------- hysteresis
@dataclass(frozen=True)
class Loop:
    """One closed steady torque-twist loop, starting and ending at ``t_max``.

    Attributes
    ----------
    torque, rigid_rotation : ndarray
        T* and omega (f p0 / mu) along the loop (first and last points equal).
    states : tuple of InterfaceState
        The states behind the points.
    """

    t_min: float
    t_max: float
    torque: np.ndarray
    rigid_rotation: np.ndarray
    states: tuple[InterfaceState, ...] = field(repr=False)


def hysteresis_loop(t_min, t_max, *, n_points: int = 40, method=None, n_terms=None) -> Loop:
    """Steady loop T_max -> T_min -> T_max after the history 0 -> T_max -> T_min -> T_max.

    By Masing closure the loop is reached in the first cycle.  ``n_points`` states per
    slipping stretch (see ``sample_path``).
    """
    t_min = _torque("t_min", t_min)
    t_max = _torque("t_max", t_max)
    if not t_min < t_max:
        raise ValueError(f"t_min must be below t_max, got t_min={t_min!r}, t_max={t_max!r}")
    start = history([t_max, t_min, t_max], method=method, n_terms=n_terms)[-1]
    down = sample_path(start, t_min, n_points)
    up = sample_path(down[-1], t_max, n_points)
    states = (start, *down, *up)
    return Loop(
        t_min,
        t_max,
        np.array([s.torque for s in states]),
        np.array([s.rigid_rotation for s in states]),
        states,
    )


def loop_work(torque, rigid_rotation) -> float:
    """W = pi oint T* d omega by the trapezoidal rule along the path ((f p0)^2 a^3 / mu).

    For a closed path this is the enclosed area in the (omega, T*) plane times pi (see
    the module docstring for the factor).
    """
    torque = np.asarray(torque, dtype=float)
    omega = np.asarray(rigid_rotation, dtype=float)
    return float(math.pi * np.sum(0.5 * (torque[1:] + torque[:-1]) * np.diff(omega)))


def _radial_rule(n_terms: int | None):
    """Composite Gauss-Legendre rule on [0, 1] with panels of 20 / lam_N (32 nodes each).

    The truncated series are entire functions of r whose products oscillate at most like
    exp(2 i lam_N r), so this rule integrates them to rounding error.
    """
    return gauss_legendre_panels(0.0, 1.0, 20.0 / bessel_j2_zeros(n_terms)[-1])


def _interface_fields(states, nodes):
    """Traction and slip of every state at ``nodes``, each distinct monotonic solution evaluated once.

    Partial-slip solutions are summed with one shared matrix J1(lam_n r_i) (the same
    sums as ``Solution.traction`` / ``Solution.slip`` on z = 0, eqs. 25-26, without
    their per-call Bessel evaluations); other regimes use the ``Solution`` methods.
    """
    bessel = None
    memo: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    out = []
    for state in states:
        q = np.zeros(nodes.shape)
        s = np.zeros(nodes.shape)
        for w, sol in state.components:
            if id(sol) not in memo:
                if sol.regime == "partial-slip" and sol.series is not None:
                    series = sol.series
                    if bessel is None or bessel.shape[1] != series.eigenvalues.size:
                        bessel = special.j1(np.outer(nodes, series.eigenvalues))
                    rigid = 0.0 if sol.method == "published" else series.rigid_rotation
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
    (omega is used only through the slip).  For a closed loop it equals ``loop_work``
    up to the r-quadrature error whatever the sampling: with the traction (ii) and
    displacement (i) of ``formulations`` the work of q on the eigenfunction part of the
    slip is the change of the elastic energy sum_n lam_n h_n c_n^2 / 2, which the
    trapezoidal rule telescopes exactly, and the work on the rigid part is pi T* d omega
    (int_0^1 r^2 J1(lam_n r) dr = 0).  The independent check of both is
    ``dissipation_per_cycle`` (friction law + memory rules).
    """
    if len(states) < 2:
        return 0.0
    nodes, weights = _radial_rule(states[0].n_terms)
    fields = _interface_fields(states, nodes)
    total = 0.0
    for (q0, s0), (q1, s1) in zip(fields[:-1], fields[1:], strict=True):
        total += float(np.sum(0.5 * (q0 + q1) * (s1 - s0) * nodes * weights))
    return 2.0 * math.pi * total


def dissipation_per_cycle(torque_range, *, method=None, n_terms=None) -> float:
    """W(A) = 8 pi int_0^1 s_m(r; A/2) r dr ((f p0)^2 a^3 / mu), zero for A <= 2.

    The energy dissipated per closed loop of range A (any mean torque): on each half
    cycle the traction is the friction limit on the slip annulus and the slip increment
    there is 2 s_m(r; A/2) (memory rule 2).

    Raises
    ------
    ValueError
        If A is not finite or outside [0, 8/3].
    """
    value = float(torque_range) if isinstance(torque_range, (numbers.Real, np.floating, np.integer)) else math.nan
    if isinstance(torque_range, bool) or not math.isfinite(value) or not 0 <= value <= 2 * GROSS_SLIP_TORQUE:
        raise ValueError(f"torque_range must be a finite number in [0, 8/3], got {torque_range!r}")
    mono = monotonic(value / 2.0, method=method, n_terms=n_terms)
    if mono.regime == "stick":
        return 0.0
    # the series' slip oscillates on the scale 1 / lam_N; the fast slip is smooth
    width = 20.0 / mono.series.eigenvalues[-1] if mono.series is not None else 0.05
    nodes, weights = gauss_legendre_panels(mono.stick_radius, 1.0, width, ())
    return float(8.0 * math.pi * np.sum(mono.slip(nodes) * nodes * weights))


def tangent_compliance(state: InterfaceState, *, step: float = 1e-4) -> float:
    """d omega / d T* (f p0 / mu per unit T*) along the current branch at ``state``.

    On a branch omega = omega_k + 2 d omega_m(tau), T* = T_k + 2 d tau, so the slope is
    omega_m'(tau) on every branch and on the virgin curve (zero while the branch
    sticks): central differences in the stick radius, omega_m'(b) / T*'(b).  At a
    loop-closure point (see ``InterfaceState.front``) it is the slope of the outer
    branch that continues beyond it.
    """
    mono = state.components[-1][1]
    b = mono.stick_radius
    if b >= 1.0:
        return 0.0
    if b <= 0.0:
        return math.inf
    h = min(step, b / 2, (1 - b) / 2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        lo = solve(stick_radius=b - h, method=state.method, n_terms=state.n_terms)
        hi = solve(stick_radius=b + h, method=state.method, n_terms=state.n_terms)
    return float((hi.rigid_rotation - lo.rigid_rotation) / (hi.torque - lo.torque))


# --------------------------------------------------------------------------- Fig. 5
def relaxation_profiles(
    t_max: float = 1.23,
    stages: Sequence[float] = (1.23, 0.9, 0.5, 0.0, -0.5, -0.77, -0.9),
    radii=None,
    *,
    method=None,
    n_terms=None,
) -> dict:
    """Fig. 5 in data: load to ``t_max``, relax through ``stages``; traction profiles.

    Returns
    -------
    dict with ``radii``, ``torque`` (stages), ``traction`` (rows per stage),
    ``stick_radius`` and ``regime`` per stage, ``residual_traction`` (at T* = 0),
    ``loading_stick_radius`` b(t_max), ``reverse_slip_onset`` = t_max - 2 (memory rule
    2) and ``min_traction_at_onset``, the least traction at that torque (-1 exactly
    when reverse slip is incipient, at r = 1).
    """
    radii = np.linspace(0.0, 1.0, 201) if radii is None else np.asarray(radii, dtype=float)
    loaded = history([t_max], method=method, n_terms=n_terms)[-1]
    states = history(list(stages), method=method, n_terms=n_terms, start=loaded)
    onset = t_max - CYCLIC_SLIP_RANGE
    at_onset = advance(loaded, onset)
    return {
        "t_max": t_max,
        "loading_stick_radius": loaded.stick_radius,
        "radii": radii,
        "torque": np.array([s.torque for s in states]),
        "stick_radius": np.array([s.stick_radius for s in states]),
        "regime": [s.regime for s in states],
        "traction": np.array([s.traction(radii) for s in states]),
        "residual_traction": loaded.residual_traction(radii),
        "reverse_slip_onset": onset,
        "min_traction_at_onset": float(np.min(at_onset.traction(radii))),
    }


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
