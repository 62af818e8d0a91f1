"""Fitting measured loops: the inverted skeleton, the twist-driven memory rules, recovery, stick, bad input."""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

from torsional_contact import fit_loop
from torsional_contact.curves import monotonic_curves
from torsional_contact.fitting import loop_fit
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


def test_model_jacobian_against_finite_differences():
    torque, twist = twist_controlled(RIG, 2.5e-3, cycles=1.5, samples_per_cycle=80)
    reversals = turning_points(twist, reversal_threshold(twist, 0.0))
    model = loop_fit._Model(torque, twist, reversals, 0.01, 1e-6)
    p = np.concatenate([[1.45, 0.35, 3.9e-4, 1.1e-4], twist[reversals] * 0.999])
    analytic = model.evaluate(p, jacobian=True)[3]
    for j in range(p.size):
        h = 1e-6 * max(abs(p[j]), 1e-4 * np.ptp(twist))
        up, down = p.copy(), p.copy()
        up[j] += h
        down[j] -= h
        numeric = (model.evaluate(up)[0] - model.evaluate(down)[0]) / (2 * h)
        scale = np.max(np.abs(analytic[:, j])) + 1e-300
        # central differences: truncation ~ h^2 and rounding ~ eps |T| / h, relative ~1e-6 of the column at most
        assert np.max(np.abs(numeric - analytic[:, j])) <= 1e-5 * scale + 1e-9 * np.ptp(torque) / h * 1e-6, j


def _recovery_bound(fit, torque, twist, torque_noise, twist_noise):
    """Largest parameter change the model's own error can cause: |row_k((W J)^+)| ||W|| sqrt(N) dT, dT = T_s 1e-9."""
    reversals = turning_points(twist, reversal_threshold(twist, twist_noise))
    model = loop_fit._Model(torque, twist, reversals, torque_noise, twist_noise)
    slip_torque = fit.friction.value * fit.normal_force * fit.radius / 2
    kappa = 4.0 / (math.pi * fit.radius**3 * fit.shear_modulus.value * fit.compliance.value)
    p = np.concatenate([[slip_torque, kappa, fit.compliance.value, fit.twist_offset.value], twist[reversals]])
    w = model.weights(p)
    pinv = np.linalg.pinv(w[:, None] * model.evaluate(p, jacobian=True)[3])
    error = math.sqrt(torque.size) * np.max(w) * slip_torque * SKELETON_BOUND
    return np.linalg.norm(pinv, axis=1)[:4] * error, slip_torque, kappa


@pytest.mark.parametrize("rig_kind", ["torque-controlled partial slip", "twist-controlled gross slip"])
def test_noise_free_loops_are_recovered(rig_kind):
    if rig_kind.startswith("torque"):
        torque, twist = torque_controlled(RIG, 1.3 * RIG.slip_torque, cycles=2, samples_per_cycle=120)
    else:
        torque, twist = twist_controlled(RIG, 2.5e-3, cycles=2, samples_per_cycle=120)
    noise = (1e-3, 1e-7)  # weights only: the data are exact
    fit = fit_loop(torque, twist, radius="5 mm", normal_force="1 kN", torque_noise=noise[0], twist_noise=noise[1])
    assert fit.slip_detected and fit.friction.identified and fit.shear_modulus.identified
    bound, slip_torque, kappa = _recovery_bound(fit, torque, twist, *noise)
    true_kappa = RIG.contact_twist / (RIG.compliance * RIG.slip_torque)
    assert abs(slip_torque - RIG.slip_torque) <= bound[0]
    assert abs(kappa - true_kappa) <= bound[1]
    assert abs(fit.compliance.value - RIG.compliance) <= bound[2]
    assert abs(fit.twist_offset.value - RIG.offset) <= bound[3]
    assert fit.regime == ("partial-slip" if rig_kind.startswith("torque") else "gross-slip")


def test_noisy_gross_slip_loop_within_its_interval():
    """One realistic record (0.5 % of the torque range, 1e-5 rad): the truth within 4 standard errors (p ~ 6e-5)."""
    torque, twist = twist_controlled(RIG, 2.5e-3, cycles=2, samples_per_cycle=200)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(7))
    fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0)
    assert abs(fit.friction.value - RIG.friction) <= 4 * fit.friction.stderr
    assert abs(fit.shear_modulus.value - RIG.shear_modulus) <= 4 * fit.shear_modulus.stderr
    assert abs(fit.compliance.value - RIG.compliance) <= 4 * fit.compliance.stderr
    assert 0.8 < fit.noise_scale < 1.2 and fit.noise["estimated"]
    lo, hi = fit.friction.interval
    assert lo < fit.friction.value < hi
    assert -1 <= fit.correlation <= 1


def test_a_loop_that_never_slips_gives_only_a_lower_bound():
    amplitude = 0.8 * RIG.slip_torque
    torque, twist = torque_controlled(RIG, amplitude, cycles=2, samples_per_cycle=120)
    torque, twist = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-6, np.random.default_rng(3))
    fit = fit_loop(torque, twist, radius=0.005, normal_force=1000.0)
    assert not fit.slip_detected and fit.regime == "stick"
    assert fit.friction.value is None and fit.shear_modulus.value is None
    bound = 2 * np.max(np.abs(torque)) / (1000.0 * 0.005)
    assert fit.friction.lower_bound == pytest.approx(bound, rel=1e-15)
    assert fit.friction.lower_bound <= RIG.friction
    assert abs(fit.compliance.value - RIG.compliance) <= 4 * fit.compliance.stderr
    record = fit.as_dict()
    assert record["friction"]["value"] is None and record["friction"]["lower_bound"] == pytest.approx(bound)
    json.dumps(record, allow_nan=False)


def test_chance_detections_of_slip_in_stick_are_flagged():
    """The slip test has a false-alarm rate of about 5 % (more: its null sits on a boundary, Davies' problem);
    every such fit must flag itself as noise-limited rather than report a friction coefficient silently."""
    from torsional_contact.diagnostics import NoiseLimitedFitWarning

    torque, twist = torque_controlled(RIG, 0.8 * RIG.slip_torque, cycles=2, samples_per_cycle=120)
    alarms = 0
    for seed in range(40):
        record = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-6, np.random.default_rng(seed))
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            fit = fit_loop(*record, radius=0.005, normal_force=1000.0)
        if fit.slip_detected:
            alarms += 1
            assert fit.noise_limited and any(w.category is NoiseLimitedFitWarning for w in caught), seed
    assert alarms <= 8  # 40 draws at a 5-8 % rate (mean 2-3): 9 or more has probability about 0.3 %


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
    assert {"residual_rms", "correlation"} <= data.keys()
    bad = tmp_path / "bad.csv"
    bad.write_text("torque [N m],twist [rad]\n" + "1,2\n" * 5)
    assert main(["fit", "--loop", str(bad), "--radius", "5 mm", "--normal-force", "1 kN", "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "at least 20 needed" in err and len(err.strip().splitlines()) == 1
