"""Torque histories: memory rules, shakedown, hysteresis and dissipation.

Every memory-rule number is checked against something computed another way: the
direct weak-form solve of the incremental mixed problem (``verification.incremental``) at
the same truncation (N = 145, and N = 2000 where the two agree to better than 1e-6), the
conditions of the incremental problem on the exact (Abel-Fredholm) states, the elastic
unloading of the loaded traction, the friction-law closed form of the dissipation, the
frictional work of sampled paths, or the anti-plane edge-crack asymptotics.  The default
method is the Abel-Fredholm one; ``WEAK`` selects the paper's weak form at N = 145.
"""

from __future__ import annotations

import functools
import json
import math
import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from tolerances import (
    EPS,
    PROFILE_ACCURACY,
    ROTATION_ACCURACY,
    assert_beyond,
    assert_close,
    assert_within,
    onset_remainder,
    torque_accuracy,
)

from torsional_contact import ResolutionWarning, asymptotics, fields, solve
from torsional_contact import histories as H
from torsional_contact.curves import monotonic_curves
from torsional_contact.io.cli import main
from torsional_contact.quadrature import gauss_legendre_panels
from torsional_contact.verification.incremental import solve_mixed, solve_mixed_for_torque

N = 145
WEAK = {"method": "complete", "n_terms": N}
R = np.linspace(0.0, 1.0, 401)
#: Rounding of a state built by the memory rules: a superposition of a few monotonic profiles (values up to
#: |T*| + 1 < 3): 64 ulp of 3.
SUPERPOSITION = 64 * EPS * 3


def _torque_slope(b: float) -> float:
    """|dT*/db| from the curve table."""
    return abs(float(monotonic_curves().by_radius["torque"].derivative(b)))


@functools.cache
def _truncation_at(c: float, n_terms: int) -> tuple:
    """(T*, omega, traction, slip) truncation errors of the weak form at N for the monotonic solution at c."""
    weak, exact = solve(stick_radius=c, method="complete", n_terms=n_terms), solve(stick_radius=c)
    return (abs(weak.torque - exact.torque), abs(weak.rigid_rotation - exact.rigid_rotation),
            float(np.max(np.abs(weak.traction(R) - exact.traction(R))[_away(R, [c])])),
            float(np.max(np.abs(weak.slip(R) - exact.slip(R)))))


def _truncation(radii, n_terms=N):
    """The truncation error of the weak form at N for the monotonic solutions at ``radii`` (against the exact
    Abel-Fredholm solution), summed: T*, omega, traction (0.05 away from the fronts) and slip."""
    errors = np.sum([_truncation_at(float(c), n_terms) for c in radii], axis=0)
    return dict(zip(("torque", "rigid_rotation", "traction", "slip"), (float(e) for e in errors), strict=True))


def _direct(states, n_terms=N, solve_for_torque=True):
    """Direct incremental solve for the last step of ``states`` at the memory-rule stick radius."""
    previous, current = states[-2], states[-1]
    direction = current.direction

    def remembered(r):  # u_theta(r, 0+) of the previous state: no further slip on (0, c)
        return previous.slip(r) / 2.0

    def limit(r):  # the friction limit in the direction of the step
        return direction * np.ones_like(r)

    fronts = list(current.slip_fronts)
    at_c = solve_mixed(current.stick_radius, remembered, limit, n_terms=n_terms, breakpoints=fronts)
    if not solve_for_torque:
        return at_c, None
    at_t = solve_mixed_for_torque(
        current.torque, remembered, limit, bracket=(0.05, 0.99), n_terms=n_terms, breakpoints=fronts
    )
    return at_c, at_t


def _away(r, radii, gap=0.05):
    mask = np.ones(r.shape, dtype=bool)
    for x in radii:
        mask &= np.abs(r - x) > gap
    return mask


# --------------------------------------------------------------------------- direct solver
def test_direct_solver_reproduces_the_monotonic_solution():
    """g = 0, p = 1 is the paper's problem (7)-(8): same T*(b) and omega as ``solve``."""
    from torsional_contact.solvers.weak_form import solve_series

    for b in (0.3, 0.6, 0.9):
        direct = solve_mixed(b, np.zeros_like, np.ones_like, n_terms=N)
        series = solve_series(b, "complete", N)
        # the same N-term system assembled two ways: rounding amplified by its condition number (1 / rcond)
        rounding = N * EPS / series.rcond
        assert_within(abs(direct.torque - series.torque), rounding, "N EPS / rcond")
        assert_within(abs(direct.rigid_rotation - series.rigid_rotation), rounding, "N EPS / rcond")


@pytest.mark.parametrize("torques", [[1.23, -0.9], [1.3, -1.2, 1.1], [1.3, -1.2, 1.1, -1.0]])
def test_memory_rule_matches_direct_incremental_solve(torques):
    """Both are N = 145 truncations of the same incremental problem (the memory rules superpose monotonic N = 145
    solutions): they differ by less than the truncation error of those monotonic solutions (``_truncation``,
    computed against the exact solution; the discrepancy shrinks with N, next test)."""
    states = H.history(torques, **WEAK)
    current = states[-1]
    assert current.regime == "partial-slip"
    at_c, at_t = _direct(states)
    bound = _truncation([current.stick_radius, *current.slip_fronts])
    reason = "truncation of the N = 145 monotonic solutions superposed"
    assert_within(abs(at_c.torque - current.torque), bound["torque"], reason)
    assert_within(abs(at_c.rigid_rotation - current.rigid_rotation), bound["rigid_rotation"], reason)
    mask = _away(R, [current.stick_radius, *current.slip_fronts])
    assert_close(at_c.traction(R)[mask], current.traction(R)[mask], reason, atol=bound["traction"])
    assert_close(at_c.slip(R), current.slip(R), reason, atol=bound["slip"])
    assert_within(abs(at_t.stick_radius - current.stick_radius), bound["torque"] / _torque_slope(current.stick_radius),
                  reason + ", over |dT*/db|")


def test_memory_rule_discrepancy_shrinks_with_n_terms():
    errors = []
    for n in (60, 200):
        states = H.history([1.23, -0.9], method="complete", n_terms=n)
        at_c, _ = _direct(states, n)
        errors.append(abs(at_c.torque - states[-1].torque))
    # a convergence order, not a tolerance: at least 1.15 ((60/200)^1.15 = 1/4; the slip's (r - b)^(3/2) edges
    # limit the weak form to about one), the discrepancy falls faster (~N^-2)
    assert errors[1] < errors[0] / 4


def test_forgetting_the_locked_in_slip_fails_the_direct_check():
    """Power of the check: the same direct solve with g = 0 (no memory) is far off."""
    states = H.history([1.3, -0.9], **WEAK)
    current = states[-1]
    forgetful = solve_mixed(current.stick_radius, np.zeros_like, lambda r: -np.ones_like(r), n_terms=N)
    # far outside the bound the memory rule meets (test_memory_rule_matches_direct_incremental_solve)
    bound = _truncation([current.stick_radius, *current.slip_fronts])["torque"]
    assert_beyond(abs(forgetful.torque - current.torque), bound, "forgetting the locked-in slip fails the check")


@pytest.mark.parametrize("torques", [[1.23, -0.9], [1.3, -1.2, 1.1], [1.3, -1.2, 1.1, -1.0]])
def test_exact_state_solves_the_incremental_problem(torques):
    """The Abel-Fredholm state after a step satisfies the incremental mixed problem to ~1e-12.

    No further slip on the stick disc of the step (displacement = the previous state's),
    traction d on the slip annulus, |q| <= 1 inside, slip increment of the sign d, and the
    torque balance T* = 4 int q r^2 dr (computed from the profile, not from the bookkeeping).
    """
    states = H.history(torques)
    previous, current = states[-2], states[-1]
    d, c = current.direction, current.stick_radius
    fronts = {c, *current.slip_fronts, *previous.slip_fronts, previous.stick_radius} - {1.0}
    graded = [f + side * 0.05 * 4.0**-k for f in fronts for side in (-1, 1) for k in range(13)]  # sqrt ends
    nodes, weights = gauss_legendre_panels(0.0, 1.0, 0.05, [*fronts, *graded])
    q = current.traction(nodes)
    inside = nodes < c
    # the memory rules superpose exact monotonic profiles: every condition holds to their rounding
    assert_close(current.slip(nodes[inside]), previous.slip(nodes[inside]), "superposition rounding",
                 atol=SUPERPOSITION)
    assert_close(q[~inside], d, "superposition rounding", atol=SUPERPOSITION)
    assert_within(max(0.0, float(np.max(np.abs(q))) - 1), SUPERPOSITION, "stick bound, superposition rounding")
    assert_within(max(0.0, -float(np.min(d * (current.slip(nodes) - previous.slip(nodes))))), SUPERPOSITION,
                  "slip increment of the sign d, superposition rounding")
    # torque balance by the graded Gauss rule: the square-root edges leave their innermost panels (0.05 x 4^-12
    # = 3e-9 wide) unresolved, ~ (3e-9)^(3/2) each; plus the profiles' accuracy integrated
    assert_within(abs(4 * np.sum(q * nodes**2 * weights) - current.torque), 4 * PROFILE_ACCURACY / 3 + 1e-12,
                  "profile accuracy integrated + the graded rule's innermost panels")
    # and the step's increment is -d 2 mono(tau) with 2 tau = |range| (not, say, mono(range)): the same table and
    # solver on both sides, up to the solver's T* accuracy over |dT*/db|
    tau = abs(current.torque - previous.torque) / 2
    assert_within(abs(c - solve(torque=tau).stick_radius), 2 * torque_accuracy(c) / _torque_slope(c),
                  "2 x T* accuracy / |dT*/db|")


@pytest.mark.slow
@pytest.mark.parametrize("radii", [(0.6, 0.82), (0.45, 0.7, 0.8)])
def test_memory_rule_matches_direct_incremental_solve_to_1e6(radii):
    """At N = 2000 the memory rules and the direct incremental solve agree to better than 1e-6.

    The monotonic solutions are found by their stick radii (weak form, N = 2000) and handed to
    ``history`` (no inversion); the direct solve prescribes the previous state's displacement on
    the last stick disc.  The discrepancy is truncation and falls at least like N^-2
    (test_memory_rule_discrepancy_shrinks_with_n_terms): from the truncation of the N = 145 monotonic solutions
    (its bound in test_memory_rule_matches_direct_incremental_solve, ~5e-3) times (145/2000)^2 = 5e-3 x 5e-3.
    """
    from torsional_contact.contact_models.cylinder import register

    n = 2000
    monos = [solve(stick_radius=b, method="complete", n_terms=n) for b in radii]
    torques, direction = [monos[0].torque], -1
    for mono in monos[1:]:
        torques.append(torques[-1] + direction * 2 * mono.torque)
        direction = -direction
    register(monos[0])
    for k, mono in enumerate(monos[1:], start=1):
        register(mono, abs(torques[k] - torques[k - 1]) / 2)
    states = H.history(torques, method="complete", n_terms=n)
    assert [s.stick_radius for s in states] == list(radii)
    at_c, _ = _direct(states, n_terms=n, solve_for_torque=False)
    current = states[-1]
    bound = _truncation(radii)
    scale = (145 / n) ** 2
    reason = "N = 145 truncation x (145/N)^2"
    assert_within(abs(at_c.torque - current.torque), bound["torque"] * scale, reason)
    assert_within(abs(at_c.rigid_rotation - current.rigid_rotation), bound["rigid_rotation"] * scale, reason)
    assert_close(at_c.slip(R), current.slip(R), reason, atol=bound["slip"] * scale)


# --------------------------------------------------------------------------- Fig. 5, shakedown
def test_fig5_numbers():
    data = H.relaxation_profiles(1.23, (1.23, 0.9, 0.5, 0.0, -0.5, -0.76, -0.82))
    # the paper's b/a = 0.6: one printed digit, half a unit of it
    assert_within(abs(data["loading_stick_radius"] - 0.6), 0.05, "the paper's 0.6: half a unit of its last digit")
    assert data["regime"] == ["partial-slip", "stick", "stick", "stick", "stick", "stick", "partial-slip"]
    assert_within(abs(data["reverse_slip_onset"] + 0.77), np.spacing(0.77), "1.23 - 2 in doubles: one ulp",
                  exact=True)
    loaded = H.history([1.23])[-1]
    # independent: elastic unloading of the loaded traction, q_k(r) - (1.23 - T) r
    for t, q in zip(data["torque"][:6], data["traction"][:6], strict=True):
        assert_close(q, loaded.traction(data["radii"]) - (1.23 - t) * data["radii"], "superposition rounding",
                     atol=SUPERPOSITION)
    residual = data["residual_traction"]
    assert_within(abs(residual[-1] - (1.0 - 1.23)), SUPERPOSITION, "slip annulus: 1 - T_max r at r = 1")
    # the peak sits at the old stick front (converged b = 0.60388; the paper's N = 145 gives 0.609): the converged
    # value printed to six digits, half a unit of the sixth, plus the solver's accuracy over |dT*/db| ~ 0.4
    assert_within(abs(data["loading_stick_radius"] - 0.603880), 5e-7 + torque_accuracy(0.6) / 0.4,
                  "0.603880: half a unit of the sixth digit", exact=True)
    assert abs(data["radii"][np.argmax(residual)] - data["loading_stick_radius"]) <= 0.005  # the profile's grid step
    assert_within(abs(data["min_traction_at_onset"] + 1.0), SUPERPOSITION, "q(1) = 1 - 2 at the onset")


@pytest.mark.parametrize("t_max", [1.1, 1.23, 1.3])
def test_reverse_slip_onset_at_t_max_minus_two(t_max):
    loaded = H.history([t_max])[-1]
    before = H.advance(loaded, t_max - 2.0 + 0.01)
    after = H.advance(loaded, t_max - 2.0 - 0.05)
    assert before.regime == "stick" and after.regime == "partial-slip"
    # independent: the elastically unloaded traction first touches -1 at r = 1 when the range is 2
    q = loaded.traction(R)
    assert np.min(q - 1.98 * R) > -1.0
    assert np.argmin(q - 2.0 * R) == R.size - 1
    assert np.min(q[R < 0.95] - 2.0 * R[R < 0.95]) > -0.95


@pytest.mark.parametrize("t_max", [1.1, 1.3])
def test_shakedown_boundary_range_two(t_max):
    below = H.history([t_max, t_max - 1.98, t_max, t_max - 1.98])
    r = np.linspace(0.0, 1.0, 101)
    assert all(s.regime == "stick" for s in below[1:])
    assert np.max(np.abs(H.slip_increments(below[1:], r, start=below[0]))) == 0.0
    assert H.dissipation_per_cycle(1.98) == 0.0
    above = H.history([t_max, t_max - 2.05, t_max])
    assert above[1].regime == "partial-slip" and above[2].regime == "partial-slip"
    assert H.dissipation_per_cycle(2.05) > 0.0


# --------------------------------------------------------------------------- rules
def test_sign_symmetry():
    plus = H.history([1.25, -1.1, 0.9])
    minus = H.history([-1.25, 1.1, -0.9])
    for p, m in zip(plus, minus, strict=True):
        assert m.torque == -p.torque and m.stick_radius == p.stick_radius
        assert m.slip_fronts == p.slip_fronts
        # mirrored histories superpose the same profiles with opposite signs, in another order: their rounding
        assert_within(abs(m.rigid_rotation + p.rigid_rotation), SUPERPOSITION * abs(p.rigid_rotation) + 1e-300,
                      "superposition rounding")
        assert_close(m.traction(R), -p.traction(R), "superposition rounding", atol=SUPERPOSITION)
        assert_close(m.slip(R), -p.slip(R), "superposition rounding", atol=SUPERPOSITION)


def test_masing_closure_recovers_earlier_states():
    states = H.history([1.3, -1.1, 0.8, -0.2, 0.8])
    earlier, later = states[2], states[4]
    assert later.turning_torques == earlier.turning_torques == (1.3, -1.1)
    # the same state reached along two paths: the superpositions differ by their rounding
    assert_within(abs(later.rigid_rotation - earlier.rigid_rotation), SUPERPOSITION, "superposition rounding")
    assert_close(later.traction(R), earlier.traction(R), "superposition rounding", atol=SUPERPOSITION)
    assert_close(later.slip(R), earlier.slip(R), "superposition rounding", atol=SUPERPOSITION)
    # passing an earlier turning point continues the outer branch: back on the virgin curve
    through = H.history([1.2, -1.0, 1.3])[-1]
    virgin = H.history([1.3])[-1]
    assert through.memory == () and through.stick_radius == virgin.stick_radius
    assert_close(through.traction(R), virgin.traction(R), "superposition rounding", atol=SUPERPOSITION)
    assert_within(abs(through.rigid_rotation - virgin.rigid_rotation), SUPERPOSITION * virgin.rigid_rotation,
                  "superposition rounding")
    # reaching -T_1 joins the mirrored virgin curve
    mirrored = H.history([1.25, -1.25])[-1]
    assert mirrored.memory == ()
    omega = H.history([1.25])[-1].rigid_rotation
    assert_within(abs(mirrored.rigid_rotation + omega), SUPERPOSITION * omega, "superposition rounding")


def test_residual_traction_is_elastic_unloading():
    for state in H.history([1.3, -1.2, 1.1, -0.3]):
        assert_close(state.residual_traction(R), H.advance(state, 0.0).traction(R), "superposition rounding",
                     atol=SUPERPOSITION)


def test_monotonic_traction_grows_with_torque():
    """Supports |q| <= 1 on the stick disc of a reversal: q_m(r; tau) nondecreasing in tau."""
    taus = np.linspace(1.02, 1.3, 8)
    q = np.array([H.monotonic_solution(t).traction(R) for t in taus])
    # exact (Abel-Fredholm) profiles: nondecreasing to twice their accuracy
    assert_within(max(0.0, -float(np.min(np.diff(q, axis=0)))), 2 * PROFILE_ACCURACY, "traction accuracy, twice")


def test_cumulative_slip_of_symmetric_cycles():
    states = H.history([1.25, -1.25, 1.25, -1.25])
    mono = H.monotonic_solution(1.25)
    # seven increments of 2 s_m (up to 0.5 each), summed: 7 x the superposition rounding of slips up to 1
    assert_close(H.cumulative_slip(states, R), 7.0 * np.abs(mono.slip(R)), "rounding of 7 superposed increments",
                 atol=7 * SUPERPOSITION)


def test_turning_point_extraction():
    signal = [0.0, 0.5, 1.0, 1.2, 1.2, 0.3, -0.4, -0.2, 0.1, 0.1, -0.5]
    np.testing.assert_array_equal(H.turning_points(signal), [0.0, 1.2, -0.4, 0.1, -0.5])
    full = H.history(signal)[-1]
    reduced = H.history(H.turning_points(signal))[-1]
    assert full.turning_torques == reduced.turning_torques
    assert_close(full.traction(R), reduced.traction(R), "superposition rounding", atol=SUPERPOSITION)


# --------------------------------------------------------------------------- energy
# Weak form (N = 145): the loop work (pi oint T* d omega) equals the frictional work of the
# sampled states to rounding (a discrete energy identity of the series, see ``frictional_work``);
# against the closed form W(A) = 8 pi int s_m r dr the sampled loop differs by its sampling error
# and the series error of the sampled states.
@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
@pytest.mark.parametrize("t_min, t_max", [(-1.2, 1.2), (-0.9, 1.25), (-1.3, 1.3)])
def test_energy_balance_weak_form(t_min, t_max):
    loop = H.hysteresis_loop(t_min, t_max, n_points=40, **WEAK)
    assert loop.torque[0] == loop.torque[-1]
    assert_within(abs(loop.rigid_rotation[-1] - loop.rigid_rotation[0]), SUPERPOSITION, "a closed loop's omega")
    area = H.loop_work(loop.torque, loop.rigid_rotation)
    friction = H.frictional_work(loop.states)
    closed = H.dissipation_per_cycle(t_max - t_min, **WEAK)
    assert area > 0
    # an identity of the sampled series (telescoping): the rounding of ~(2 x 40 states) x 145 terms
    assert_within(abs(friction / area - 1), 80 * N * EPS, "rounding of the discrete identity")
    # the sampled loop against the closed form: its sampling error (estimated by the change from 10 to 40 points
    # per stretch, second order) and the truncation of the N = 145 series (the closed form's distance from the
    # exact W(A)); the sampled states carry a truncation of the same kind: ten times the estimates
    coarse = H.hysteresis_loop(t_min, t_max, n_points=10, **WEAK)
    sampling = abs(H.loop_work(coarse.torque, coarse.rigid_rotation) - area)
    series = abs(H.dissipation_per_cycle(t_max - t_min) - closed)
    assert_within(abs(area - closed), 10 * (sampling + series), "ten times: sampling + series truncation")


@pytest.mark.parametrize("t_min, t_max", [(-1.2, 1.2), (-0.9, 1.25), (-1.3, 1.1)])
def test_energy_of_a_closed_cycle_is_w(t_min, t_max):
    """dissipated_energy grows by W(A) over a closed cycle; the sampled loop's area and frictional work agree.

    Independent routes: the state energies (rule 5, W_mono of curves.work), the trapezoidal loop
    area pi oint T* d omega of 400 states per stretch (second order) and the
    frictional work 2 pi oint int q ds r dr of the same states' profiles.
    """
    states = H.history([t_max, t_min, t_max, t_min, t_max])
    w = H.dissipation_per_cycle(t_max - t_min)
    # bookkeeping (rule 5) against W(A) = 4 W_mono(A/2): the same table values, summed; the rounding of a sum
    # of energies up to the total dissipated (~10 W)
    bookkeeping = 64 * EPS * states[4].dissipated_energy
    assert_within(abs(states[4].dissipated_energy - states[2].dissipated_energy - w), bookkeeping, "sum rounding")
    assert_within(abs(states[3].dissipated_energy - states[1].dissipated_energy - w), bookkeeping, "sum rounding")
    loop = H.hysteresis_loop(t_min, t_max, n_points=400)
    assert_within(abs(loop.states[-1].dissipated_energy - loop.states[0].dissipated_energy - w),
                  64 * EPS * loop.states[-1].dissipated_energy, "sum rounding")
    # the trapezoidal loop area is second order in the sampling: its error is below the change from 100 to 400
    # points per stretch (which is 15 times the 400-point error)
    area = H.loop_work(loop.torque, loop.rigid_rotation)
    quarter = H.hysteresis_loop(t_min, t_max, n_points=100)
    assert_within(abs(area - w), abs(H.loop_work(quarter.torque, quarter.rigid_rotation) - area),
                  "second order: the 100-point area's change bounds the 400-point error")
    # the frictional work of 12 states per stretch, second order too: below its change from 3 points
    coarse = H.hysteresis_loop(t_min, t_max, n_points=12)
    friction = H.frictional_work(coarse.states)
    coarser = H.frictional_work(H.hysteresis_loop(t_min, t_max, n_points=3).states)
    assert_within(abs(friction - w), abs(coarser - friction), "second order: the 3-point work's change")


def test_energy_of_first_loading_and_partial_branches():
    """Virgin curve: W_mono(T); a branch from T_k to T: 2 W_mono(|T - T_k| / 2) (rule 5), vs sampled paths."""
    loaded = H.history([1.27])[-1]
    assert_within(abs(loaded.dissipated_energy / H.loading_work(1.27) - 1), 4 * EPS, "the same table value")

    def sampled_work(start, torque, n_points):
        return H.frictional_work([start, *H.sample_path(start, torque, n_points=n_points)])

    # the frictional work of a sampled path is second order in the sampling: below its change from 6 points
    work = sampled_work(H.initial_state(), 1.27, 25)
    assert_within(abs(work - loaded.dissipated_energy), abs(sampled_work(H.initial_state(), 1.27, 6) - work),
                  "second order: the 6-point work's change bounds the 25-point error")
    branch = H.advance(loaded, -0.95)  # tau = 1.11
    gained = branch.dissipated_energy - loaded.dissipated_energy
    # rule 5 against the table at tau = (1.27 + 0.95)/2: a difference of energies up to ~W(1.27), rounded
    assert_within(abs(gained - 2 * H.loading_work(1.11)), 64 * EPS * branch.dissipated_energy, "rounding")
    steps = H.sample_path(loaded, -0.95, n_points=25)
    work = H.frictional_work([loaded, *steps])
    assert_within(abs(work - gained), abs(sampled_work(loaded, -0.95, 6) - work),
                  "second order: the 6-point work's change bounds the 25-point error")
    assert [s.dissipated_energy for s in steps] == sorted(s.dissipated_energy for s in steps)
    # passing an earlier turning point: the inner loop's W, then the outer branch goes on
    through = H.history([1.3, -1.2, 1.1, -1.25])
    outer = H.loading_work(1.3) + 2 * H.loading_work(1.275)  # virgin to 1.3, then the branch from 1.3 to -1.25
    expected = outer + H.dissipation_per_cycle(2.3)
    assert_within(abs(through[-1].dissipated_energy - expected), 64 * EPS * expected, "rounding of the sums")


def test_dissipation_depends_on_range_only():
    """Masing: an offset loop of range 2.4 dissipates as the symmetric one (sampled loop areas)."""
    symmetric = H.hysteresis_loop(-1.2, 1.2, n_points=200)
    offset = H.hysteresis_loop(-1.3, 1.1, n_points=200)
    w_sym = H.loop_work(symmetric.torque, symmetric.rigid_rotation)
    w_off = H.loop_work(offset.torque, offset.rigid_rotation)
    # the same branch shapes sampled alike: equal to the rounding of the 800-term trapezoidal sums, whose terms
    # T* d omega are up to |T*| |omega range| each; 800 x 8 EPS x |T*|max sum |d omega| / W
    terms = 1.3 * np.sum(np.abs(np.diff(offset.rigid_rotation)))
    assert_within(abs(w_off / w_sym - 1), 800 * 8 * EPS * math.pi * terms / w_sym, "rounding of the trapezoidal sums")


def test_dissipation_law_near_threshold():
    """W ~ (pi^4/3) eps^3 for a range 2 (1 + eps): fitted exponent 3 (anti-plane edge crack)."""
    eps = np.geomspace(1e-3, 1e-2, 5)
    w = np.array([H.dissipation_per_cycle(2 * (1 + e)) for e in eps])
    exponent = np.polyfit(np.log(eps), np.log(w), 1)[0]
    # W = (pi^4/3) eps^3 (1 + c1 eps + rho(eps)), c1 = 1/2 - 3 pi^2/64 = 0.037 (tests/test_curves.py::
    # test_threshold_law), rho the O(eps^2 ln eps) remainder inherited from (S1): d ln W / d ln eps - 3 is at most
    # c1 eps + 2 |rho| + ... over the fitted range
    c1 = 0.5 - 3 * math.pi**2 / 64
    asym = H.threshold_asymptotics(eps)["dissipation"]
    delta = np.pi / 2 * eps
    remainder = 3 * np.pi / 2 * np.array([onset_remainder(d) for d in delta]) / delta
    assert_within(abs(exponent - 3.0), c1 * eps[-1] + 2 * remainder[-1], "O(eps) and O(eps^2 ln eps) corrections")
    assert_close(w / asym - 1, c1 * eps, "(S1) remainder in the O(eps^2 ln eps) term", atol=remainder)


def test_compliance_near_onset_and_by_differences():
    for t in (1.04, 1.2):
        state = H.history([t])[-1]
        slope = H.tangent_compliance(state)

        def central(h, t=t):
            return (H.history([t + h])[-1].rigid_rotation - H.history([t - h])[-1].rigid_rotation) / (2 * h)

        # central differences with steps h and 2h, extrapolated (fourth order): their difference bounds the error
        # of the h-step one, which is three times the extrapolated one's
        h = 1e-5
        fine, coarse = central(h), central(2 * h)
        by_torque = (4 * fine - coarse) / 3
        assert_within(abs(slope - by_torque), abs(fine - coarse) + 64 * EPS * state.rigid_rotation / h,
                      "Richardson: |D(h) - D(2h)| bounds the error + rounding of the differences")
    # near onset: d omega / d T* from (S1), (S2) (exact in delta), with the remainder of (S1) differentiated:
    # (3 pi/2) delta^2 (A ln(1/delta) + B), twice for the derivative's extra terms (tolerances.onset_remainder)
    excess = 0.004
    delta = float(asymptotics.onset_slip_width(excess))
    expected = (2 * delta**2 + math.pi / 4 * delta**3) / (2 / math.pi + delta / 4)
    near = H.tangent_compliance(H.history([1 + excess])[-1])
    assert_within(abs(near / expected - 1), 2 * 3 * math.pi / 2 * onset_remainder(delta) / delta,
                  "(S1) remainder, differentiated")
    assert_beyond(abs(near / H.threshold_asymptotics(excess)["compliance"] - 1), 1e-4,
                  "the leading asymptote alone is off by O(delta): the correction is resolved")
    # the weak form at N = 145: its truncation error, below its changes to N = 72 and N = 290 (it changes sign)
    compliance = {n: H.tangent_compliance(H.history([1.2], method="complete", n_terms=n)[-1]) for n in (72, N, 290)}
    exact = H.tangent_compliance(H.history([1.2])[-1])
    change = max(abs(compliance[72] - compliance[N]), abs(compliance[290] - compliance[N]))
    assert_within(abs(compliance[N] - exact), change, "truncation at N = 145, below its changes to N = 72, 290")
    # on reversal the compliance drops to zero (stick) and regrows as on the virgin curve
    branch = H.history([1.3, 1.3 - 2.2])[-1]
    assert H.tangent_compliance(H.history([1.3, 0.5])[-1]) == 0.0
    virgin = H.tangent_compliance(H.history([1.1])[-1])
    assert_within(abs(H.tangent_compliance(branch) / virgin - 1), 16 * EPS, "the same curve at tau = 1.1 (rounded)")


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    "torques, match",
    [
        ([], "at least one"),
        ([0.0, math.nan], r"torques\[1\] must be finite"),
        ([1.5], r"torques\[0\] must lie in \[-4/3, 4/3\].*spin"),
        ([-1.34], "spin"),
        (["a"], "real number"),
        ([math.inf], "finite"),
    ],
)
def test_bad_input_api(torques, match):
    with pytest.raises(ValueError, match=match):
        H.history(torques)


def test_bad_input_other_functions():
    state = H.initial_state()
    with pytest.raises(ValueError, match="torque"):
        H.advance(state, 2.0)
    with pytest.raises(ValueError, match="signal"):
        H.turning_points([])
    with pytest.raises(ValueError, match="torque_range"):
        H.dissipation_per_cycle(3.0)
    with pytest.raises(ValueError, match="t_min"):
        H.hysteresis_loop(1.0, 0.0)


@pytest.mark.parametrize(
    "argv",
    [
        ["history", "--turning-points", "0", "nan", "--json"],
        ["history", "--turning-points", "0", "1.5", "--json"],
        ["history", "--turning-points", "--json"],
        ["history", "--json"],
        ["history", "--turning-points", "0", "1,5", "--json"],
        ["history", "--turning-points", "0", "-inf", "--json"],
        ["history", "--turning-points", "1.2", "--method", "exact", "--json"],
        ["history", "--turning-points", "1.2", "--output", "x.csv", "--json"],
        ["history", "--turning-points", "1.2", "--signal", "x.txt", "--json"],
    ],
)
def test_bad_input_cli(argv, capsys):
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1


def test_cli_history_json():
    run = subprocess.run(
        [sys.executable, "-m", "torsional_contact", "history", "--turning-points", "0", "1.23", "-1e0", "1.23",
         "--json"],
        capture_output=True,
        text=True,
        check=True,
    )
    records = json.loads(run.stdout)
    assert [r["torque"] for r in records] == [0.0, 1.23, -1.0, 1.23]
    assert [r["regime"] for r in records] == ["stick", "partial-slip", "partial-slip", "partial-slip"]
    assert {r["method"] for r in records} == {"fast"}
    assert records[2]["slip_fronts"] == [records[1]["stick_radius"]]  # the remembered front is the old stick radius
    # converged stick radii (the paper's N = 145 gives 0.60908 and 0.82340), independent: the solver
    # the CLI in a subprocess and the API here: the same computation, to its rounding (JSON keeps 17 digits)
    for record, tau in ((records[1], 1.23), (records[2], 1.115)):
        assert_within(abs(record["stick_radius"] - solve(torque=tau).stick_radius), 16 * EPS, "the same computation")
    assert round(records[1]["stick_radius"], 5) == 0.60388 and round(records[2]["stick_radius"], 5) == 0.81829
    expected = solve(torque=1.23).rigid_rotation - 2 * solve(torque=1.115).rigid_rotation
    # the CLI's state from the curve table, expected from two direct solves: three omega values' accuracy
    assert_within(abs(records[2]["rigid_rotation"] - expected), 3 * ROTATION_ACCURACY, "omega bound, three values")
    energies = [r["dissipated_energy"] for r in records]
    assert energies[0] == 0.0 and energies == sorted(energies)
    w = H.dissipation_per_cycle(2.23)
    assert_within(abs(energies[3] - energies[1] - w), 64 * EPS * energies[3], "rounding of the sums of energies")
    weak = main(["history", "--turning-points", "0", "1.23", "--method", "complete", "--json"])
    assert weak == 0


# --------------------------------------------------------------------------- properties
torque_values = st.floats(min_value=-1.3, max_value=1.3, allow_nan=False)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(torque_values, min_size=1, max_size=6))
def test_property_admissible_states(torques):
    """Every state obeys |q| <= 1 (friction limit) and the stack keeps shrinking ranges."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        states = H.history(torques)
    for s in states:
        # the friction limit, to the accuracy of the profiles superposed (one per turning point and the virgin one)
        bound = (len(s.turning_torques) + 1) * PROFILE_ACCURACY
        assert_within(max(0.0, float(np.max(np.abs(s.traction(R)))) - 1.0), bound, "profiles' accuracy, superposed")
        points = list(s.turning_torques)
        if points:
            ranges = [2 * abs(points[0]), *np.abs(np.diff([*points, s.torque]))]
            assert all(x > y for x, y in zip(ranges[:-2], ranges[1:-1], strict=True))
            assert ranges[-1] <= ranges[-2]  # equality: the loop has just closed
        assert list(s.slip_fronts) == sorted(s.slip_fronts)
        assert all(f <= s.stick_radius for f in s.slip_fronts)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(torque_values, min_size=2, max_size=5))
def test_property_dissipation_nonnegative(torques):
    """Frictional work along any sampled path is >= 0 (slip rate has the traction's sign)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        paths = {}
        for n_points in (3, 6):
            path = [H.initial_state()]
            for t in torques:
                path.extend(H.sample_path(path[-1], t, n_points=n_points))
            paths[n_points] = H.frictional_work(path)
        # the exact work is >= 0; the 6-point path's is second order in the sampling, within its change from 3 points
        assert_within(max(0.0, -paths[6]), abs(paths[6] - paths[3]) + 1e-15, "sampling error of the 6-point path")


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(torque_values.map(lambda x: round(x, 2)), min_size=1, max_size=8))  # ties: exact loop closures
def test_property_turning_points_suffice(signal):
    """The final state depends on the turning points only (rainflow memory)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        full = H.history(signal)[-1]
        reduced = H.history(H.turning_points(signal))[-1]
    assert full.turning_torques == reduced.turning_torques
    assert full.stick_radius == reduced.stick_radius
    bound = (len(full.turning_torques) + 1) * SUPERPOSITION  # the same profiles superposed along two paths
    assert_close(full.traction(R), reduced.traction(R), "superposition rounding", atol=bound)
    assert_close(full.slip(R), reduced.slip(R), "superposition rounding", atol=bound)


def test_fields_superpose():
    """Body fields of a history state: z = 0 gives the interface values, far away uniform torsion."""
    state = H.history([1.3, -1.0])[-1]
    r = np.linspace(0.0, 1.0, 51)
    assert_close(state.stress(r, 0.0)[0], state.traction(r), "interface values: superposition rounding",
                 atol=SUPERPOSITION)
    assert_close(2.0 * state.displacement(r, 0.0), state.slip(r), "interface values: superposition rounding",
                 atol=SUPERPOSITION)
    # far away only the slowest Dini mode is left: exp(-lam_1 z) (lam_1 = 5.1356) times the amplitudes of the
    # superposed corrections, below 1 each (three superposed states): 3 exp(-3 lam_1) = 6e-7, and the fields'
    # truncation tolerance (``fields.DEFAULT_TOLERANCE``)
    decay = 3 * math.exp(-3 * 5.1356) + fields.DEFAULT_TOLERANCE
    sigma_zt, sigma_rt = state.stress(r, 3.0)
    assert_close(sigma_zt, state.torque * r, "slowest Dini mode at z = 3", atol=decay)
    assert_close(sigma_rt, 0.0, "slowest Dini mode at z = 3", atol=decay)
    assert_close(state.displacement(r, 3.0), state.torque * r * 3.0 + state.rigid_rotation * r,
                 "slowest Dini mode at z = 3", atol=decay)
