"""The rig-defect study's code paths: exact binomial intervals, coverage counts kept apart, handling switches that
the fit lacks, the plateau estimator on every contact model, and one real fit on a tiny replicate count."""

import numpy as np
import pytest
import scipy.stats
from tolerances import assert_close, assert_sampled, assert_within

from torsional_contact import fit_loop, models
from torsional_contact.fitting.results import Estimate
from torsional_contact.verification.fit_study import (
    HANDLING,
    Scenario,
    clopper_pearson,
    handling_options,
    median_with_stderr,
    per_cycle_study,
    plateau_friction,
    run_study,
    summarise,
)
from torsional_contact.verification.rig_records import RigSpecimen, rig_record


@pytest.mark.parametrize("k, n", [(0, 1), (1, 1), (0, 5), (3, 5), (5, 5), (19, 20), (57, 64), (1, 200)])
def test_clopper_pearson_against_beta_quantiles(k, n):
    """Against scipy.stats.beta.ppf (a different route to the regularised incomplete beta inverse)."""
    lo, hi = clopper_pearson(k, n)
    expected_lo = 0.0 if k == 0 else scipy.stats.beta.ppf(0.025, k, n - k + 1)
    expected_hi = 1.0 if k == n else scipy.stats.beta.ppf(0.975, k + 1, n - k)
    assert_close([lo, hi], [expected_lo, expected_hi], "two inversions of the incomplete beta function",
                 rtol=1e-10, atol=1e-14)
    # and its defining property: the binomial tail at the ends is alpha/2
    if k > 0:
        assert_within(abs(scipy.stats.binom.sf(k - 1, n, lo) - 0.025), 1e-10, "tail probability at the lower end")
    if k < n:
        assert_within(abs(scipy.stats.binom.cdf(k, n, hi) - 0.025), 1e-10, "tail probability at the upper end")


@pytest.mark.parametrize("k, n", [(-1, 3), (4, 3), (1, 0), (1.5, 3)])
def test_clopper_pearson_bad_counts(k, n):
    with pytest.raises(ValueError, match="successes|trials"):
        clopper_pearson(k, n)


def fake(status_f, covered_f, warned=False, refused=False):
    entry = {"status": status_f}
    if status_f != "none":
        entry["covered"] = covered_f
    if status_f == "interval":
        entry["error"] = 0.01 if covered_f else -0.2
    other = {"status": "interval", "covered": True, "error": 0.0}
    return {"refused": refused, "warned": warned, "named": warned, "cpu": 0.0, "friction": entry,
            "shear_modulus": other, "compliance": other}


def test_summary_counts_intervals_and_bounds_apart():
    fits = [fake("interval", True), fake("interval", False), fake("interval", True), fake("bound", True),
            fake("bound", False, warned=True), fake("none", None, refused=True)]
    s = summarise(fits)["friction"]
    assert (s["interval_coverage"]["count"], s["interval_coverage"]["trials"]) == (2, 3)
    assert (s["bound_coverage"]["count"], s["bound_coverage"]["trials"]) == (1, 2)
    assert s["identified"]["count"] == 3 and s["bounded"]["count"] == 2
    assert s["interval_coverage"]["interval"] == list(clopper_pearson(2, 3))
    whole = summarise(fits)
    # honest: every reported interval or bound covers, or a warning names the defect, or a refusal
    assert whole["honest"]["count"] == 5 and whole["warned"]["count"] == 1 and whole["refused"]["count"] == 1
    assert s["median_bias"] == pytest.approx(0.01)


def test_median_standard_error_of_a_normal_sample():
    """sqrt(pi/2) sigma / sqrt(n) for the median of a normal sample: with sigma from a large sample's MAD (relative
    standard error 1.65 / sqrt(n)), and the formula itself against the spread of many medians."""
    rng = np.random.default_rng(7)
    n = 20001
    _, stderr = median_with_stderr(rng.normal(0.0, 2.0, size=n))
    expected = np.sqrt(np.pi / 2) * 2.0 / np.sqrt(n)
    assert_sampled(stderr / expected, 1.0, 1.65 / np.sqrt(n), 5, "MAD estimate of sigma")
    medians = np.median(rng.normal(0.0, 2.0, size=(4000, 101)), axis=1)
    formula = np.sqrt(np.pi / 2) * 2.0 / np.sqrt(101)
    assert_sampled(np.std(medians) / formula, 1.0, 1 / np.sqrt(2 * 4000) + 0.02, 5,
                   "spread of 4000 medians (and the formula's O(1/n) error at n = 101)")
    assert median_with_stderr([1.0, 2.0]) == (1.5, None) and median_with_stderr([]) == (None, None)


def test_a_fit_without_the_switches_says_handling_not_available():
    def bare_fit(torque, twist, *, radius, normal_force):
        raise AssertionError("the 'off' mode of a fit without switches must not run")

    options, missing = handling_options(bare_fit, "off")
    assert options == {} and set(missing) == set(HANDLING)
    calls = []

    def stick_fit(torque, twist, *, radius, normal_force):
        calls.append(len(torque))
        whole = Estimate(0.6, 0.01, (0.55, 0.65))

        class Result:
            slip_detected = True
            friction = whole
            shear_modulus = Estimate(None, None, (1e9, None), identified=False)
            compliance = Estimate(4e-4, 1e-6, (3e-4, 5e-4))
        return Result()

    rows = run_study([Scenario("clean", "torque", 1.2, cycles=1.0, sample_rate=50)], replicates=2, seed=0,
                     fit=stick_fit)
    on, off = rows
    assert off["summary"] is None and set(off["not_available"]) == set(HANDLING)
    assert on["summary"]["friction"]["interval_coverage"]["count"] == 2 and len(calls) == 2
    assert on["summary"]["shear_modulus"]["bound_coverage"]["count"] == 2  # 80 GPa lies in [1 GPa, inf)


def test_per_cycle_study_counts_against_each_cycles_truth():
    # a manufactured per-cycle fit: cycle k's interval is the truth shifted by +0.6 of the change per cycle with a
    # half-width of 0.5 of it, so it misses the cycle's mean (strict) but meets its branches' range (mean +- a quarter
    # of the change); the last cycle's friction is only a bound below the truth (counted apart)
    scenario = Scenario("running-in", "twist", 2.5e-3, cycles=6, sample_rate=40.0,
                        defects={"friction_end": 0.45, "running_in_cycles": 6})
    seen = {}

    def per_cycle_fit(torque, twist, *, radius, normal_force, per_cycle, check_defects, time):
        assert per_cycle and check_defects and time is not None
        truth = seen["truth"]
        step = abs(truth[1] - truth[0])
        cycles = [{"cycle": k, "friction": {"value": f + 0.6 * step, "interval": (f + 0.1 * step, f + 1.1 * step)}}
                  for k, f in enumerate(truth[:-1], start=1)]
        cycles.append({"cycle": len(truth), "friction": {"value": None, "interval": (truth[-1] - step, None)}})

        class Result:
            pass
        result = Result()
        result.cycles = cycles
        return result

    original = Scenario.record

    def record(self, specimen, rng):
        out = original(self, specimen, rng)
        seen["truth"] = out.truth["friction_per_cycle"]
        return out

    Scenario.record = record
    try:
        study = per_cycle_study(scenario, replicates=2, seed=1, fit=per_cycle_fit)
    finally:
        Scenario.record = original
    assert study["cycles"] == 12 and study["records"] == 2
    assert study["interval_coverage"]["count"] == 0 and study["interval_coverage"]["trials"] == 10
    assert study["range_coverage"]["count"] == 10
    assert study["bound_coverage"]["count"] == 2 and study["bound_coverage"]["trials"] == 2
    truth = np.asarray(seen["truth"])
    expected = float(np.median(0.6 * abs(truth[1] - truth[0]) / truth[:-1]))
    assert_close(study["median_bias"], expected, "the median of the manufactured errors", rtol=1e-12)
    with pytest.raises(ValueError, match="running-in"):
        per_cycle_study(Scenario("clean", "torque", 1.2, cycles=1.0, sample_rate=50), replicates=1, seed=0,
                        fit=per_cycle_fit)


def test_the_real_fit_on_one_record_each_way():
    """One record with a torque zero offset: both modes run with the fit's switches, the same record for both."""
    rows = run_study([Scenario("offset", "torque", 1.3, cycles=1.5, sample_rate=100,
                               defects={"torque_offset": 0.1})], replicates=1, seed=4, fit=fit_loop)
    assert [r["mode"] for r in rows] == ["on", "off"]
    for row in rows:
        assert row["not_available"] == [] and row["summary"]["records"] == 1
        assert set(row["options"]) == set(HANDLING)


@pytest.mark.parametrize("name", tuple(models.MODELS))
def test_plateau_estimator_on_every_model(name):
    """A noise-free twist-controlled record far into gross slip: f = T_gs / (T*_gs F a / 2) with the model's T*_gs.
    The error bound: the torque deficit of the skeleton at the start of the averaged tail (the plateau is approached
    from below), from the skeleton itself."""
    specimen = RigSpecimen(model=name)
    top = specimen.contact.gross_slip_torque
    amplitude = 2 * float(specimen.skeleton(top * (1 - 1e-3)))
    record = rig_record(specimen, control="twist", amplitude=amplitude, cycles=2.0, sample_rate=400,
                        torque_noise=0.0, twist_noise=0.0)
    estimate = plateau_friction(record.torque, record.twist, radius=specimen.radius,
                                normal_force=specimen.normal_force, model=name)
    # the tail starts at 3/4 of a branch's travel 2 amplitude, where the Masing branch T_r - 2 h^-1(3/4 amplitude)
    # (T* units) falls short of the opposite plateau by 2 (T*_gs - h^-1(3/4 amplitude)); the torque approaches the
    # plateau monotonically, so the tail's mean is closer
    deficit = 2 * (1 - float(specimen.skeleton_inverse(0.75 * amplitude)) / top)
    assert_within(abs(estimate["value"] - specimen.friction) / specimen.friction, deficit + 1e-12,
                  "the skeleton's torque deficit where the tail starts")
    assert estimate["value"] <= specimen.friction * (1 + 1e-12)


def test_plateau_estimator_reads_the_peak_below_gross_slip():
    specimen = RigSpecimen()
    record = rig_record(specimen, control="twist", amplitude=float(specimen.skeleton(1.1)), cycles=2.0,
                        sample_rate=400, torque_noise=0.0, twist_noise=0.0)
    estimate = plateau_friction(record.torque, record.twist, radius=specimen.radius,
                                normal_force=specimen.normal_force)
    assert estimate["value"] <= specimen.friction * 1.1 / (4 / 3) * (1 + 1e-12)


def test_plateau_estimator_bad_input():
    with pytest.raises(ValueError, match="tail"):
        plateau_friction(np.arange(20.0), np.arange(20.0), radius=0.005, normal_force=1000, tail=0.9)
    with pytest.raises(ValueError, match="equal length"):
        plateau_friction(np.arange(20.0), np.arange(19.0), radius=0.005, normal_force=1000)


def test_the_study_script_refuses_an_unknown_per_cycle_scenario_before_any_fit(tmp_path):
    import json
    import pathlib
    import subprocess
    import sys

    root = pathlib.Path(__file__).resolve().parents[1]
    config = {"replicates": 1, "long_replicates": 0, "seed": 1, "cycles": 2, "sample_rate": 200.0,
              "long": {"cycles": 50, "frequency": 0.5, "sample_rate": 1000.0},
              "specimen": {"radius": 0.005, "gauge_length": 0.02, "shear_modulus": 8e10, "friction": 0.6,
                           "normal_force": 1000.0, "rig_compliance": 1.5e-4},
              "scenarios": [{"name": "clean", "control": "torque", "amplitude": 1.3}],
              "window": {"levels": [1.2], "plateau_twists": [2.5e-3]}, "per_cycle": "no-such"}
    outputs = [arg for name in ("json", "csv", "tex", "window-tex", "macros")
               for arg in (f"--{name}", str(tmp_path / f"out.{name}"))]
    run = subprocess.run([sys.executable, str(root / "workflow" / "scripts" / "fit_study.py"), "--config",
                          json.dumps(config), *outputs], capture_output=True, text=True, cwd=root, timeout=60)
    assert run.returncode == 2 and "fit_study.per_cycle names no scenario" in run.stderr and "'no-such'" in run.stderr
    assert list(tmp_path.iterdir()) == []  # nothing written
