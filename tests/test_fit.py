"""Fitting measured loops: the inverted skeleton, the twist-driven memory rules, the orthogonal distances and
their Jacobian, the profile intervals, the slip test, the bootstrap, recovery, coverage, bad input."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest
from scipy import optimize, stats
from scipy.optimize import brentq

from torsional_contact import fit_loop
from torsional_contact.curves import monotonic_curves
from torsional_contact.diagnostics import NoiseLimitedFitWarning
from torsional_contact.fitting import loop_fit, loop_model, profile, slip_test
from torsional_contact.fitting.bootstrap import bias_corrected_percentiles
from torsional_contact.fitting.loop_model import LoopModel
from torsional_contact.fitting.masing import torque_along, walk
from torsional_contact.fitting.samples import reversal_threshold, turning_points
from torsional_contact.fitting.skeleton import Skeleton
from torsional_contact.fitting.synthetic import Rig, noisy, torque_controlled, twist_controlled
from torsional_contact.histories import analyse_signal, turning_point_indices
from torsional_contact.io.cli import main

RIG = Rig(radius=0.005, normal_force=1000.0, friction=0.6, shear_modulus=80e9, compliance=4e-4, offset=1e-4)
#: The inverted skeleton's error bound in T* for 0 <= kappa <= KAPPA_MAX (skeleton docstring: < 1e-10; the
#: cubic Hermite error h^4 max|T*''''| / 384 on the nodes), times 10.
SKELETON_BOUND = 1e-9


def _true_parameters(twist, reversals, rig=RIG):
    kappa = rig.contact_twist / (rig.compliance * rig.slip_torque)
    return np.concatenate([[rig.slip_torque, kappa, rig.compliance, rig.offset], twist[reversals]])


def _model(torque, twist, torque_noise, twist_noise):
    return LoopModel(torque, twist, turning_points(twist, reversal_threshold(twist, twist_noise)), torque_noise,
                     twist_noise)


def _coverage_band(draws: int, level: float = 0.95) -> float:
    """Three binomial standard errors of a coverage measured over ``draws`` records at its nominal ``level``."""
    return 3.0 * math.sqrt(level * (1.0 - level) / draws)


@pytest.mark.parametrize("kappa", [0.0, 0.01, 0.3, 1.0, loop_fit.KAPPA_MAX])
def test_skeleton_inverse_against_root_finding(kappa):
    curves = monotonic_curves()
    top = 4.0 / 3.0 - float(curves.torque_gap(2e-5))  # omega_m finite there (5.08)
    skeleton = Skeleton(kappa)
    x = np.concatenate([np.linspace(0.0, 1.0, 5), 1.0 + max(kappa, 1e-3) * np.geomspace(1e-4, 4.0, 40)])
    t, slope = skeleton(x)
    for xi, ti in zip(x, t, strict=True):
        def excess(s, xi=xi):
            return s + kappa * curves.state(s)[1] - xi

        exact = xi if xi <= 1 else 4.0 / 3.0 if excess(top) <= 0 else brentq(excess, 1.0, top, xtol=1e-16,
                                                                                rtol=1e-15)
        assert abs(ti - exact) <= SKELETON_BOUND, (kappa, xi)
    # the slope against central differences: truncation h^2 |T*'''| / 6 and rounding 1e-16 / h, h = 1e-6
    h = 1e-6
    numeric = (skeleton(x + h)[0] - skeleton(x - h)[0]) / (2 * h)
    assert np.max(np.abs(numeric - slope)) <= 1e-7  # T*' is continuous at x = 1 (omega_m ~ (T* - 1)^3)
    assert np.all(np.diff(t) >= 0) and np.all(t <= 4.0 / 3.0)
    assert np.array_equal(skeleton(-x)[0], -t)
    # the curvature of the cubic pieces against central differences of their slope, away from the nodes (where it
    # jumps): truncation h^2 |T*''''| / 6 on a piece, rounding 1e-16 / h, h = 1e-7 of the piece
    nodes = skeleton._x
    wide = np.flatnonzero(np.diff(nodes) > 1e-5)[::5]  # pieces wide enough for the differences' rounding
    middle = 0.5 * (nodes[wide] + nodes[wide + 1])
    step = 1e-3 * (nodes[wide + 1] - nodes[wide])
    second = skeleton(middle, curvature=True)[2]
    numeric = (skeleton(middle + step)[1] - skeleton(middle - step)[1]) / (2 * step)
    assert np.max(np.abs(numeric - second)) <= 1e-6 * max(1.0, np.max(np.abs(second)))


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_twist_driven_memory_rules_match_the_torque_driven_ones(seed):
    """Torques from a twist history (fitting.masing) against histories.analyse_signal on the same history."""
    rng = np.random.default_rng(seed)
    slip_torque, compliance, k = 1.5, 4e-4, 2e-4
    skeleton = Skeleton(k / (compliance * slip_torque))

    def branch(v):
        t, s = skeleton(v / (compliance * slip_torque))
        return slip_torque * t, s / compliance

    points = np.concatenate([[0.0], rng.uniform(-1.33, 1.33, 14)])
    path = np.concatenate([np.linspace(a, b, 40, endpoint=False) for a, b in zip(points[:-1], points[1:],
                                                                                 strict=True)] + [[points[-1]]])
    omega, _ = analyse_signal(path).sample_values()
    twist = compliance * slip_torque * path + k * omega
    reversal = turning_point_indices(path)[1:]
    segment = np.minimum(np.searchsorted(reversal, np.arange(path.size), side="left"), reversal.size - 1)
    torque, _, turning = torque_along(walk(twist[reversal]), twist, segment, branch)
    # each branch adds at most one skeleton error (g = 2: twice) to its origin's: <= 2 M SKELETON_BOUND in T*
    bound = 2 * reversal.size * SKELETON_BOUND
    assert np.max(np.abs(torque / slip_torque - path)) <= bound
    assert np.max(np.abs(turning / slip_torque - path[reversal[:-1]])) <= bound


@pytest.mark.parametrize("rig_kind", ["torque-controlled partial slip", "twist-controlled gross slip"])
def test_foot_points_minimise_each_samples_distance(rig_kind):
    """Every d_i^2 against a brute-force minimisation of the sample's misfit over the true twist (a grid of 2001
    twists over +-8 noise levels, then Brent's method on the best cell)."""
    if rig_kind.startswith("torque"):
        torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=1.5, samples_per_cycle=80)
    else:
        torque, twist = twist_controlled(RIG, 2.5e-3, cycles=1.5, samples_per_cycle=80)
    s_t, s_w = 0.005 * np.ptp(torque), 1e-5
    torque, twist = noisy(torque, twist, s_t, s_w, np.random.default_rng(4))
    model = _model(torque, twist, s_t, s_w)
    p = _true_parameters(twist, model.reversals)
    distances = model.sample_distances(p)
    reach = 8.0 * math.hypot(s_w, RIG.compliance * s_t)
    for i in range(torque.size):
        def misfit(u, i=i):
            g = model.torque_at(p, np.atleast_1d(u), index=np.array([i]))[0][0]
            return ((torque[i] - g) / s_t) ** 2 + ((twist[i] - u) / s_w) ** 2

        grid = twist[i] + np.linspace(-reach, reach, 2001)
        values = ((torque[i] - model.torque_at(p, grid, index=np.full(grid.size, i))[0]) / s_t) ** 2 + (
            (twist[i] - grid) / s_w) ** 2
        j = int(np.argmin(values))
        cell = (grid[max(j - 1, 0)], grid[min(j + 1, grid.size - 1)])
        best = optimize.minimize_scalar(misfit, bounds=cell, method="bounded", options={"xatol": 1e-14}).fun
        # the foot point stops when a step would gain less than FOOT_GAIN; at the exact foot point d_i^2 is the
        # minimum itself (the residual is normal to the curve): 100 FOOT_GAIN covers the rest
        assert abs(distances[i] ** 2 - min(best, values[j])) <= 100 * loop_model.FOOT_GAIN, i


@pytest.mark.parametrize("rig_kind", ["torque-controlled partial slip", "twist-controlled gross slip"])
def test_residual_jacobian_against_finite_differences(rig_kind, monkeypatch):
    """d(residuals)/dp (the envelope theorem at the foot points, and the turning points' torques) against central
    differences of the residuals with every foot point converged to rounding."""
    monkeypatch.setattr(loop_model, "FOOT_GAIN", 1e-26)
    if rig_kind.startswith("torque"):
        torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=1.5, samples_per_cycle=80)
    else:
        torque, twist = twist_controlled(RIG, 2.5e-3, cycles=1.5, samples_per_cycle=80)
    s_t, s_w = 0.005 * np.ptp(torque), 1e-5
    torque, twist = noisy(torque, twist, s_t, s_w, np.random.default_rng(2))
    model = _model(torque, twist, s_t, s_w)
    p = _true_parameters(twist, model.reversals) * np.concatenate([[1.01, 1.05, 0.99, 1.02],
                                                                    np.ones(model.reversals.size)])
    residual, analytic = model.distances(p, jacobian=True)
    assert residual.size == torque.size + model.reversals.size
    scales = np.concatenate([p[:3], [1e-4], np.full(model.reversals.size, 1e-4)])
    for j in range(p.size):
        h = 1e-6 * scales[j]
        up, down = p.copy(), p.copy()
        up[j] += h
        down[j] -= h
        numeric = (model.distances(up) - model.distances(down)) / (2 * h)
        column = np.max(np.abs(analytic[:, j])) + 1e-300
        # central differences of a function that is C^1 (the cubic pieces' curvature jumps at their nodes): an
        # error of order h times that jump, h = 1e-6 of the parameter's scale, far below 1e-5 of the column
        assert np.max(np.abs(numeric - analytic[:, j])) <= 1e-5 * column, j


def _recovery_bound(fit, torque, twist, torque_noise, twist_noise):
    """Largest parameter change the model's own error can cause: |row_k(J^+)| ||dr||, with dr the residuals of a
    torque error T_s SKELETON_BOUND at every sample (in torque noise units at most)."""
    model = _model(torque, twist, torque_noise, twist_noise)
    p = fit.parameters
    pinv = np.linalg.pinv(model.distances(p, jacobian=True)[1])
    error = math.sqrt(torque.size + model.reversals.size) * p[0] * SKELETON_BOUND / torque_noise
    return np.linalg.norm(pinv, axis=1)[:4] * error


@pytest.mark.parametrize("rig_kind", ["torque-controlled partial slip", "twist-controlled gross slip"])
def test_noise_free_loops_are_recovered(rig_kind):
    if rig_kind.startswith("torque"):
        torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=2, samples_per_cycle=120)
    else:
        torque, twist = twist_controlled(RIG, 2.5e-3, cycles=2, samples_per_cycle=120)
    noise = (1e-3, 1e-7)  # the metric only: the data are exact
    fit = fit_loop(torque, twist, radius="5 mm", normal_force="1 kN", torque_noise=noise[0], twist_noise=noise[1])
    assert fit.slip_detected and fit.friction.identified and fit.shear_modulus.identified
    bound = _recovery_bound(fit, torque, twist, *noise)
    true_kappa = RIG.contact_twist / (RIG.compliance * RIG.slip_torque)
    assert abs(fit.parameters[0] - RIG.slip_torque) <= bound[0]
    assert abs(fit.parameters[1] - true_kappa) <= bound[1]
    assert abs(fit.compliance.value - RIG.compliance) <= bound[2]
    assert abs(fit.twist_offset.value - RIG.offset) <= bound[3]
    assert fit.regime == ("partial-slip" if rig_kind.startswith("torque") else "gross-slip")


def test_profile_ends_are_where_the_likelihood_ratio_reaches_its_critical_value():
    """Each end of the f, G and C intervals, refitted with that parameter held there, has LR = F(1, N - 4)."""
    torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=2, samples_per_cycle=100)
    s_t = 0.005 * np.ptp(torque)
    torque, twist = noisy(torque, twist, s_t, 1e-5, np.random.default_rng(8))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NoiseLimitedFitWarning)  # G may be a bound: its ends are checked all the same
        fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0, torque_noise=s_t, twist_noise=1e-5)
    model = _model(torque, twist, s_t, 1e-5)
    p = fit.parameters
    s_min = float(np.sum(model.distances(p) ** 2))
    scale2 = s_min / fit.dof
    critical = float(stats.f.ppf(0.95, 1, fit.dof))
    lower = np.full(p.size, -np.inf)
    upper = np.full(p.size, np.inf)
    lower[:3] = [1e-9, 0.0, 1e-9]
    upper[1] = loop_fit.KAPPA_MAX
    c_g = math.pi * 0.005**3 / 4
    ends = [("slip_torque", v * 1000.0 * 0.005 / 2) for v in fit.friction.interval if v is not None]
    ends += [("compliance", v) for v in fit.compliance.interval if v is not None]
    ends += [("product", 1.0 / (c_g * v)) for v in fit.shear_modulus.interval if v is not None]
    assert len(ends) >= 4
    assumed = fit.shear_modulus.assumed_end
    for kind, value in ends:
        constraint = profile.Constraint(kind, value)
        start = p.copy()
        if kind == "product":
            start[2] = max(start[2], value / loop_fit.KAPPA_MAX * (1 + 1e-9))
        s = profile.fit(model, start, lower, upper, constraint, loop_fit.KAPPA_MAX)[1]
        lr = (s - s_min) / scale2
        if kind == "product" and assumed == "lower" and value >= p[1] * p[2]:
            assert lr <= critical * (1 + 2 * profile.ROOT_TOLERANCE)  # the model's bound, inside the interval
            continue
        # the search stops within ROOT_TOLERANCE in sqrt(LR); the refit's own tolerance adds ~1e-6 S / s^2
        slack = 2 * profile.ROOT_TOLERANCE * math.sqrt(critical) + 1e-6 * s_min / scale2
        assert abs(math.sqrt(max(lr, 0.0)) - math.sqrt(critical)) <= slack, (kind, value, lr)


def test_critical_value_solves_davies_bound():
    # without the T_s search: the one-sided chi-square point, Phi^-1(0.95)^2 (brentq to 1e-10)
    assert slip_test.critical_value(0.0) == pytest.approx(stats.norm.isf(0.05) ** 2, abs=1e-9)
    for length in (0.5, 3.0, 40.0):
        c = slip_test.critical_value(length, 0.05)
        assert stats.norm.sf(math.sqrt(c)) + length / (2 * math.pi) * math.exp(-c / 2) == pytest.approx(0.05,
                                                                                                       abs=1e-9)
    with pytest.raises(ValueError, match="level must lie in"):
        slip_test.critical_value(1.0, 0.7)


def test_davies_bound_against_monte_carlo_of_the_score_process():
    """P(sup_T_s max(0, Z)^2 > c) for the record's own unit scores and white noise, by simulation, stays below the
    level that Davies' bound promises (it is an upper bound)."""
    torque, twist = torque_controlled(RIG, 0.8 * RIG.slip_torque, cycles=2, samples_per_cycle=100)
    s_t = 0.005 * np.ptp(torque)
    torque, twist = noisy(torque, twist, s_t, 1e-5, np.random.default_rng(5))
    model = _model(torque, twist, s_t, 1e-5)
    compliance, offset = loop_fit._stick_line(model).x
    foot = loop_fit._line_foot(torque, twist, compliance, offset, s_t, 1e-5)
    unit = slip_test.unit_scores(model, compliance, offset, foot)
    length = float(np.sum(np.linalg.norm(np.diff(unit, axis=0), axis=1)))
    assert length == pytest.approx(slip_test.path_length(model, compliance, offset, foot), rel=1e-12)
    c = slip_test.critical_value(length, 0.05)
    draws = 20000
    z = np.random.default_rng(6).standard_normal((draws, torque.size)) @ unit.T
    rate = float(np.mean(np.max(np.maximum(z, 0.0), axis=1) ** 2 > c))
    assert rate <= 0.05 + 3 * math.sqrt(0.05 * 0.95 / draws)  # three Monte Carlo standard errors
    assert rate > stats.norm.sf(math.sqrt(c))  # the T_s search matters: more than one direction's tail


def _false_alarms(draws, cycles, samples_per_cycle, seed):
    torque, twist = torque_controlled(RIG, 0.8 * RIG.slip_torque, cycles=cycles, samples_per_cycle=samples_per_cycle)
    alarms = 0
    rng = np.random.default_rng(seed)
    for _ in range(draws):
        record = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, rng)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", NoiseLimitedFitWarning)
            alarms += fit_loop(*record, radius=0.005, normal_force=1000.0).slip_detected
    return alarms


def _most_alarms(draws: int, level: float = 0.05, tail: float = 0.003) -> int:
    """The largest number of alarms in ``draws`` records that a test of ``level`` exceeds with probability > tail."""
    return int(stats.binom.isf(tail, draws, level))


def test_slip_test_false_alarm_rate():
    """Loops in stick (|T*| <= 0.8): slip detected at most at the test's level, 5 % (Davies' bound is an upper
    bound).  40 records: more alarms than ``_most_alarms`` has probability below 0.3 % at a 5 % rate (the fixed
    5.99 of chi-square(2) with free reversal twists detected slip in a fifth of such records)."""
    assert _false_alarms(40, 1.5, 80, 21) <= _most_alarms(40)


@pytest.mark.sweep  # a statistical sweep (about a minute): CI runs it (.ci/run), the README's test command does not
def test_slip_test_false_alarm_rate_over_many_records():
    """300 full records (2 cycles of 200 samples): at most 26 alarms (8.7 %; more has probability < 0.3 % at 5 %)."""
    assert _false_alarms(300, 2, 200, 22) <= _most_alarms(300)


def test_noisy_gross_slip_loop_within_its_interval():
    """One realistic record (0.5 % of the torque range, 1e-5 rad): the truth within 4 standard errors (p ~ 6e-5)."""
    torque, twist = twist_controlled(RIG, 2.5e-3, cycles=2, samples_per_cycle=200)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(7))
    fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0)
    assert abs(fit.friction.value - RIG.friction) <= 4 * fit.friction.stderr
    assert abs(fit.shear_modulus.value - RIG.shear_modulus) <= 4 * fit.shear_modulus.stderr
    assert abs(fit.compliance.value - RIG.compliance) <= 4 * fit.compliance.stderr
    assert 0.8 < fit.noise_scale < 1.2 and fit.noise["estimated"]
    for estimate in (fit.friction, fit.shear_modulus, fit.compliance):
        lo, hi = estimate.interval
        assert lo < estimate.value < hi
    assert -1 <= fit.correlation <= 1
    assert fit.interval_method == "profile likelihood" and not fit.noise_limited


def test_a_loop_that_never_slips_gives_only_a_lower_bound():
    amplitude = 0.8 * RIG.slip_torque
    torque, twist = torque_controlled(RIG, amplitude, cycles=2, samples_per_cycle=120)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-6, np.random.default_rng(3))
    fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0)
    assert not fit.slip_detected and fit.regime == "stick"
    assert fit.stick_test < fit.stick_critical
    assert fit.friction.value is None and fit.shear_modulus.value is None
    bound = 2 * np.max(np.abs(torque)) / (1000.0 * 0.005)
    assert fit.friction.lower_bound == pytest.approx(bound, rel=1e-15)
    assert fit.friction.lower_bound <= RIG.friction
    assert abs(fit.compliance.value - RIG.compliance) <= 4 * fit.compliance.stderr
    record = fit.as_dict()
    assert record["friction"]["value"] is None and record["friction"]["lower_bound"] == pytest.approx(bound)
    json.dumps(record, allow_nan=False)


def test_a_modulus_buried_in_the_twist_noise_is_not_identified():
    """Partial slip (T* = 1.3, the contact's twist about 33 urad) under a twist noise of 100 urad: G gets no value
    and no tight interval, and the fit says so."""
    torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=2, samples_per_cycle=200)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-4, np.random.default_rng(9))
    with pytest.warns(NoiseLimitedFitWarning):
        fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0)
    assert fit.noise_limited and not fit.shear_modulus.identified and fit.shear_modulus.value is None
    lo, hi = fit.shear_modulus.interval
    assert hi is None or lo is None or hi / lo > 3  # what the data say about G spans a factor of 3 at least
    assert "G is not identified" in fit.message or "f is not identified" in fit.message


def test_bias_corrected_percentiles_of_a_shifted_normal():
    """Replicates psi_hat + N(b, 1): z_0 = -b, so the interval is psi_hat - b -+ z (Efron's correction of the
    bias b).  Quantile error at 2e5 replicates: sqrt(q (1 - q) / n) / phi(z) ~ 0.01."""
    replicates = 3.0 + 0.4 + np.random.default_rng(1).standard_normal(200_000)
    lo, hi = bias_corrected_percentiles(replicates, 3.0, 0.95)
    z = stats.norm.ppf(0.975)
    assert lo == pytest.approx(3.0 - 0.4 - z, abs=0.02)
    assert hi == pytest.approx(3.0 - 0.4 + z, abs=0.02)


def test_bootstrap_intervals_bracket_the_estimates():
    torque, twist = twist_controlled(RIG, 2.5e-3, cycles=1.5, samples_per_cycle=100)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(12))
    fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0, bootstrap=40, seed=3)
    assert fit.bootstrap == 40
    for estimate in (fit.friction, fit.shear_modulus, fit.compliance):
        lo, hi = estimate.bootstrap_interval
        assert lo < estimate.value < hi
        p_lo, p_hi = estimate.interval
        # the same sampling distribution seen two ways: widths within a factor of 3 (40 refits place the 2.5 %
        # quantiles to about +-40 % of the half-width)
        assert 1 / 3 < (hi - lo) / (p_hi - p_lo) < 3
    assert "bootstrap_interval" in fit.as_dict()["friction"]
    again = fit_loop(torque, twist, radius=0.005, normal_force=1000.0, bootstrap=40, seed=3)
    assert again.friction.bootstrap_interval == fit.friction.bootstrap_interval


def _coverage(scenario, draws, cycles, samples_per_cycle, seed):
    control, amplitude, torque_fraction, twist_noise = scenario
    if control == "torque":
        torque, twist = torque_controlled(RIG, amplitude * RIG.slip_torque, cycles, samples_per_cycle)
    else:
        torque, twist = twist_controlled(RIG, amplitude, cycles, samples_per_cycle)
    truth = {"friction": RIG.friction, "shear_modulus": RIG.shear_modulus, "compliance": RIG.compliance}
    covered = {key: 0 for key in truth}
    reported = {key: 0 for key in truth}
    rng = np.random.default_rng(seed)
    for _ in range(draws):
        record = noisy(torque, twist, torque_fraction * np.ptp(torque), twist_noise, rng)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", NoiseLimitedFitWarning)
            fit = fit_loop(*record, radius=0.005, normal_force=1000.0)
        for key, true in truth.items():
            lo, hi = getattr(fit, key).interval
            if lo is None and hi is None:
                continue
            reported[key] += 1
            covered[key] += (lo is None or lo <= true) and (hi is None or true <= hi)
    return {key: covered[key] / reported[key] for key in truth}, reported


def test_coverage_of_a_gross_slip_loop():
    """40 records of a twist-controlled gross-slip test at realistic noise: the 95 % intervals of f, G and C hold
    the truth within three binomial standard errors of 95 % (+-10 %)."""
    coverage, reported = _coverage(("twist", 2.5e-3, 0.005, 1e-5), 40, 1.5, 100, 31)
    assert all(n == 40 for n in reported.values())
    for key, rate in coverage.items():
        assert abs(rate - 0.95) <= _coverage_band(40), (key, rate)


@pytest.mark.sweep  # a statistical sweep (a minute or two): CI runs it (.ci/run), the README's test command does not
@pytest.mark.parametrize("scenario", [("torque", 1.3, 0.005, 1e-5), ("torque", 1.3, 0.001, 1e-6),
                                      ("twist", 2.5e-3, 0.005, 1e-5)],
                         ids=["partial-slip", "partial-slip-quiet", "gross-slip"])
def test_coverage_over_many_records(scenario):
    """120 full records (2 cycles of 200 samples): coverage of the intervals and bounds within three binomial
    standard errors of 95 % (+-6 %); partial slip at realistic noise covered 41 % (f) and 55 % (G) with the
    first-order residuals and Wald intervals."""
    coverage, reported = _coverage(scenario, 120, 2, 200, 47)
    for key, rate in coverage.items():
        assert reported[key] >= 100 and abs(rate - 0.95) <= _coverage_band(reported[key]), (key, rate)


@pytest.mark.parametrize("kwargs, match", [
    ({"torque": [0.0] * 30, "twist": np.linspace(0, 1, 30)}, "torque must vary"),
    ({"torque": np.ones(10), "twist": np.ones(10)}, "at least 20 samples"),
    ({"torque": np.linspace(0, 1, 30), "twist": np.linspace(0, 1, 31)}, "same number of samples"),
    ({"torque": np.r_[np.linspace(0, 1, 29), np.nan], "twist": np.linspace(0, 1, 30)},
     r"torque\[29\] must be a finite number, got nan"),
    ({"radius": "1 kN"}, "radius must be a length"),
    ({"normal_force": -3.0}, "normal_force must be finite and > 0"),
    ({"confidence": 1.5}, "confidence must lie in"),
    ({"torque_noise": "1 mm", "twist_noise": 1e-6}, "torque_noise must be a torque"),
    ({"bootstrap": 5}, "bootstrap must be 0"),
    ({"bootstrap": 2.5}, "bootstrap must be 0"),
])
def test_bad_input(kwargs, match):
    arguments = {"torque": np.sin(np.linspace(0, 6, 40)), "twist": np.sin(np.linspace(0, 6, 40)),
                 "radius": 0.005, "normal_force": 1000.0, **kwargs}
    with pytest.raises(ValueError, match=match):
        fit_loop(**arguments)


def test_cli_fit(tmp_path, capsys):
    torque, twist = twist_controlled(RIG, 2.5e-3, cycles=2, samples_per_cycle=100)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(11))
    path = tmp_path / "loop.csv"
    path.write_text("# synthetic\ntime [s],torque [N m],twist [mrad]\n" + "".join(
        f"{i * 0.01:.2f},{t:.17g},{w * 1e3:.17g}\n" for i, (t, w) in enumerate(zip(torque, twist, strict=True))))
    assert main(["fit", "--loop", str(path), "--radius", "5 mm", "--normal-force", "1 kN", "--json"]) == 0
    out, err = capsys.readouterr()
    data = json.loads(out)
    direct = fit_loop(torque, twist, radius=0.005, normal_force=1000.0).as_dict()
    for key in ("friction", "shear_modulus", "compliance"):
        assert {"value", "stderr", "interval"} <= data[key].keys()
        assert data[key]["value"] == pytest.approx(direct[key]["value"], rel=1e-9)
        assert data[key]["interval"] == pytest.approx(direct[key]["interval"], rel=1e-9)
    assert {"residual_rms", "correlation", "stick_critical", "interval_method"} <= data.keys()
    bad = tmp_path / "bad.csv"
    bad.write_text("torque [N m],twist [rad]\n" + "1,2\n" * 5)
    assert main(["fit", "--loop", str(bad), "--radius", "5 mm", "--normal-force", "1 kN", "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "at least 20 needed" in err and len(err.strip().splitlines()) == 1
    assert main(["fit", "--loop", str(path), "--radius", "5 mm", "--normal-force", "1 kN", "--bootstrap", "3"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.startswith("--bootstrap") or "--bootstrap must be" in err
    assert len(err.strip().splitlines()) == 1
