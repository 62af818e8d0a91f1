"""The loop fit on records with the defects rigs have: each gives an interval that covers the truth or a warning
that names the defect; a stuck contact never gets a friction value; the slip statistic is never negative.

Records from ``rig_records`` (the model's monotonic solution and a Masing composition of its own, independent of
the fitting code): a = 5 mm, L = 20 mm, G = 80 GPa, f = 0.6, F = 1 kN, noise 0.5 % of the torque range and 1e-5 rad.
"""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest
from rig_records import Rig, torque_controlled, twist_controlled
from scipy import signal

from torsional_contact import fit_loop, models
from torsional_contact.contact_models.base import ContactModel
from torsional_contact.fitting import lag as lag_module
from torsional_contact.fitting import record_checks
from torsional_contact.verification.rig_records import RigDefects, rig_record

RIG = Rig()
TWIST_NOISE = 1e-5


def _noise(amplitude):
    return 0.005 * 2.0 * amplitude * RIG.slip_torque


def _fit(clock, torque, twist, rig=RIG, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return fit_loop(torque, twist, radius=rig.radius, normal_force=rig.normal_force, **kwargs)


def _covers_or_warns(fit, truth: float, word: str) -> None:
    lo, hi = fit.friction.interval
    covered = fit.friction.value is not None and lo <= truth <= hi
    named = any(word in w for w in fit.warnings)
    assert covered or named, (fit.friction, fit.warnings)


def test_clean_record_has_no_warnings_and_covers():
    fit = _fit(*torque_controlled(RIG, 1.3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE, seed=1))
    assert fit.warnings == ()
    lo, hi = fit.friction.interval
    assert lo <= RIG.friction <= hi


@pytest.mark.parametrize("seed", [2, 3])
def test_spikes_are_removed_and_counted(seed):
    size = 60 * TWIST_NOISE
    rig = RIG.with_(spikes=((57, size), (171, -size), (303, size)))
    fit = _fit(*torque_controlled(rig, 1.3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE, seed=seed))
    assert fit.spikes == 3
    assert any(w.startswith("spikes: 3") for w in fit.warnings)
    assert fit.stick_test >= 0.0
    lo, hi = fit.friction.interval
    assert lo <= RIG.friction <= hi


def test_spike_detection_leaves_smooth_reversals_and_knees_alone():
    # an exact channel (no noise at all) and a twist-controlled gross-slip record, whose torque has knees in time
    time, torque, twist = twist_controlled(RIG, 2.5e-3, cycles=2, samples_per_cycle=100)
    assert not record_checks.find_spikes(torque).any()
    assert not record_checks.find_spikes(twist).any()
    time, torque, twist = torque_controlled(RIG, 1.3, cycles=2, samples_per_cycle=60, twist_noise=1e-7, seed=4)
    assert not record_checks.find_spikes(twist).any()
    assert not record_checks.find_spikes(torque).any()


def test_inverted_twist_channel_is_a_clear_error():
    for amplitude in (0.8, 1.3):  # stick and partial slip
        time, torque, twist = torque_controlled(RIG.with_(twist_sign=-1.0), amplitude,
                                                torque_noise=_noise(amplitude), twist_noise=TWIST_NOISE, seed=5)
        with pytest.raises(ValueError, match="inverted"):
            _fit(time, torque, twist)


def test_loop_work_is_the_energy_of_the_loop():
    # the work of whole cycles of an elastic-slip loop from the independent records: positive, and zero (within its
    # noise) in stick
    time, torque, twist = torque_controlled(RIG, 1.3, cycles=2)
    reversals = np.array([50, 150, 250, 350])
    work, sd = record_checks.loop_work(torque, twist, reversals, 0.0, 0.0)
    assert work > 0 and sd == 0
    time, torque, twist = torque_controlled(RIG, 0.8, cycles=2)
    work = record_checks.loop_work(torque, twist, reversals, 0.0, 0.0)[0]
    assert abs(work) < 1e-12 * np.ptp(torque) * np.ptp(twist)


@pytest.mark.parametrize("seed", [6, 7, 8])
@pytest.mark.parametrize("amplitude", [0.8, 0.95])
def test_slip_statistic_is_never_negative(amplitude, seed):
    # stuck contacts, with and without spikes left in (a spike too small for the detector, 6 noise levels)
    rig = RIG.with_(spikes=((40, 6 * TWIST_NOISE), (260, -6 * TWIST_NOISE)))
    for r in (RIG, rig):
        fit = _fit(*torque_controlled(r, amplitude, torque_noise=_noise(amplitude), twist_noise=TWIST_NOISE,
                                      seed=seed))
        assert fit.stick_test >= 0.0
        assert fit.friction.value is None or fit.slip_detected


def test_exact_torque_channel_does_not_collapse_the_likelihood():
    for kind, amplitude in ((torque_controlled, 1.3), (twist_controlled, 2.5e-3)):
        time, torque, twist = kind(RIG, amplitude, twist_noise=1e-7, seed=9)
        fit = _fit(time, torque, twist)
        assert fit.slip_detected
        lo, hi = fit.friction.interval
        assert lo <= RIG.friction <= hi
        assert fit.noise["torque"] > 0


def test_quantised_channel_noise_floor():
    rng = np.random.default_rng(10)
    step = 1e-3
    values = np.round(np.sin(np.linspace(0, 12, 2000)) / step) * step
    assert record_checks.quantisation_step(values) == pytest.approx(step, rel=1e-9)
    assert record_checks.noise_floor(values, 0.0, 1.0) == pytest.approx(step / np.sqrt(12.0), rel=1e-9)
    assert record_checks.quantisation_step(rng.standard_normal(100)) == 0.0


@pytest.mark.parametrize("defect, word", [
    ({"drift": 1e-5}, "drift"),
    ({"torque_offset": 0.1}, "torque offset"),
    ({"lag": 5e-3}, "lag"),
    ({"lag": 5e-3, "drift": 1e-5}, "lag"),
    ({"start_phase": 0.5}, "non-virgin start"),
])
def test_rig_defects_are_covered_or_named(defect, word):
    rig = RIG.with_(**defect)
    for seed in (11, 12):
        time, torque, twist = torque_controlled(rig, 1.3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE,
                                                seed=seed)
        fit = _fit(time, torque, twist, time=time)
        _covers_or_warns(fit, RIG.friction, word)


def test_defects_found_are_named_with_their_size():
    rig = RIG.with_(torque_offset=0.1, lag=5e-3)
    time, torque, twist = torque_controlled(rig, 1.3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE, seed=13)
    fit = _fit(time, torque, twist, time=time)
    named = {w.split(" (")[0].split(":")[0]: w for w in fit.warnings}
    # a torque offset is not told from a record that starts after a history: both are fitted on the steady branches
    assert {"torque offset or non-virgin start", "lag"} <= named.keys()
    lag = float(named["lag"].split(":")[1].split()[0])
    # within a few times its resolution: 1e-5 rad of twist noise over a twist rate of about 1e-3 rad per 0.1 s
    assert abs(lag - 5e-3) < 1.5e-3
    lo, hi = fit.friction.interval
    assert lo <= RIG.friction <= hi
    unhandled = _fit(time, torque, twist, time=time, check_defects=False)
    assert unhandled.warnings == ()


@pytest.mark.parametrize("seed", range(20, 23))
def test_clean_records_raise_no_defect(seed):
    for kind, amplitude in ((torque_controlled, 1.3), (torque_controlled, 0.8), (twist_controlled, 2.5e-3)):
        time, torque, twist = kind(RIG, amplitude, twist_noise=TWIST_NOISE, seed=seed)
        time, torque, twist = kind(RIG, amplitude, torque_noise=0.005 * np.ptp(torque), twist_noise=TWIST_NOISE,
                                   seed=seed)
        assert _fit(time, torque, twist, time=time).warnings == ()


@pytest.mark.parametrize("seed", [14, 15])
@pytest.mark.parametrize("lag", [2e-3, 5e-3])
def test_stuck_contact_with_a_lag_never_gets_a_friction_value(lag, seed):
    # T* 0.8 at 1 Hz: the lag opens the straight loop into an ellipse that a partial-slip loop imitates
    rig = RIG.with_(lag=lag)
    time, torque, twist = torque_controlled(rig, 0.8, torque_noise=_noise(0.8), twist_noise=TWIST_NOISE, seed=seed)
    fit = _fit(time, torque, twist, time=time)
    assert fit.friction.value is None
    assert fit.stick_test >= 0.0
    if fit.slip_detected:
        assert any(w.startswith("lag") for w in fit.warnings)


class _Toy(ContactModel):
    """A contact model of the test's own (not in the package): bonded below T* = 1/2 with a linear rotation, slipping
    up to spinning at T* = 1 with omega_m = 0.3 T* + 0.2 u^3 / (1 - u), u = 2 T* - 1; one elastic body, no shafts."""

    name = "toy-bonded"
    description = "a bonded toy contact for the fit's tests"
    bodies = "the toy bodies"
    slip_onset_torque = 0.5
    gross_slip_torque = 1.0
    gross_slip_text = "1"
    elastic_bodies = 1
    shaft = False

    def monotonic_points(self, tau):
        tau = np.asarray(tau, dtype=float)
        u = np.clip(2.0 * tau - 1.0, 0.0, 1.0)
        with np.errstate(divide="ignore"):
            omega = 0.3 * tau + np.where(u < 1.0, 0.2 * u**3 / np.maximum(1.0 - u, 1e-300), np.inf)
        return np.where(u > 0, 1.0 - u, 1.0), omega, np.zeros_like(tau)


@pytest.mark.parametrize("model, amplitude", [("half-space", 1.3), ("toy", 0.85)])
def test_fit_through_the_contact_model_interface(model, amplitude):
    toy = _Toy()
    if model == "toy":
        models.register(toy, replace=True)
    try:
        rig = RIG.with_(model=toy if model == "toy" else model)
        for seed in (16, 17):
            time, torque, twist = torque_controlled(rig, amplitude, twist_noise=TWIST_NOISE, seed=seed)
            time, torque, twist = torque_controlled(rig, amplitude, torque_noise=0.005 * np.ptp(torque),
                                                    twist_noise=TWIST_NOISE, seed=seed)
            # 99.9 % intervals: a single record's 95 % interval misses one time in twenty
            fit = _fit(time, torque, twist, time=time, model=toy.name if model == "toy" else model,
                       confidence=0.999)
            assert fit.slip_detected and fit.warnings == ()
            lo, hi = fit.friction.interval
            assert lo <= RIG.friction <= hi
            g_lo, g_hi = fit.shear_modulus.interval
            assert (g_lo is None or g_lo <= RIG.shear_modulus) and (g_hi is None or RIG.shear_modulus <= g_hi)
    finally:
        models.unregister(toy.name)


def _running_in(cycles: int, sample_rate: float, seed: int):
    from torsional_contact.verification.rig_records import RigDefects, rig_record

    record = rig_record(control="twist", amplitude=2.5e-3, cycles=cycles, sample_rate=sample_rate,
                        defects=RigDefects(friction_end=0.45, running_in_cycles=cycles), rng=seed)
    fit = _fit(record.time, record.torque, record.twist, time=record.time, per_cycle=True)
    assert len(fit.cycles) == cycles - 1  # whole cycles from the first turning point on
    truth = record.truth["friction_per_cycle"]
    step = abs(truth[1] - truth[0])  # the change over one cycle: its two branches' friction differ by half of it
    for entry in fit.cycles:
        lo, hi = entry["friction"]["interval"]
        f = truth[entry["cycle"] - 1]
        # the interval meets the range of the friction of the cycle's two branches (one f per cycle is fitted)
        assert lo - 0.25 * step <= f <= hi + 0.25 * step, (entry, f)
        assert {"cycle", "friction", "compliance", "regime", "warnings"} <= entry.keys()
        assert {"value", "stderr", "interval"} <= entry["compliance"].keys()


def test_per_cycle_fit_follows_running_in():
    _running_in(6, 100.0, 18)


@pytest.mark.sweep
def test_per_cycle_fit_follows_twenty_cycles_of_running_in():
    _running_in(20, 200.0, 19)


def test_known_modulus_fits_friction_and_takes_the_shafts_out():
    for seed in (21, 22):
        time, torque, twist = torque_controlled(RIG, 1.3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE, seed=seed)
        fit = _fit(time, torque, twist, time=time, shear_modulus="80 GPa", gauge_length="20 mm", confidence=0.999)
        lo, hi = fit.friction.interval
        assert lo <= RIG.friction <= hi and fit.friction.stderr > 0
        assert fit.shear_modulus.value == RIG.shear_modulus
        lo, hi = fit.rig_compliance.interval
        assert lo <= RIG.rig_compliance <= hi
        # the shafts' L / (G J) is what separates the two compliances
        shafts = fit.compliance.value - fit.rig_compliance.value
        assert shafts == pytest.approx(RIG.shaft_compliance, rel=1e-12)
        data = fit.as_dict()
        assert {"value", "stderr", "interval"} <= data["rig_compliance"].keys()


def test_known_modulus_bad_input():
    time, torque, twist = torque_controlled(RIG, 1.3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE, seed=23)
    with pytest.raises(ValueError, match="gauge_length needs shear_modulus"):
        _fit(time, torque, twist, gauge_length="20 mm")
    with pytest.raises(ValueError, match="not shafts"):
        _fit(time, torque, twist, shear_modulus="80 GPa", gauge_length="20 mm", model="half-space")
    with pytest.raises(ValueError, match="shear_modulus"):
        _fit(time, torque, twist, shear_modulus="-1 GPa")


def test_cli_per_cycle_and_model(tmp_path, capsys):
    from torsional_contact.io.cli import main

    time, torque, twist = torque_controlled(RIG, 1.3, cycles=3, torque_noise=_noise(1.3), twist_noise=TWIST_NOISE,
                                            seed=24)
    path = tmp_path / "loop.csv"
    path.write_text("time [s],torque [N m],twist [rad]\n" + "".join(
        f"{s:.17g},{t:.17g},{w:.17g}\n" for s, t, w in zip(time, torque, twist, strict=True)))
    base = ["fit", "--loop", str(path), "--radius", "5 mm", "--normal-force", "1 kN", "--json"]
    assert main([*base, "--per-cycle", "--shear-modulus", "80 GPa", "--gauge-length", "20 mm"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert len(data["cycles"]) == 2 and data["cycles"][0]["cycle"] == 1
    assert {"cycle", "friction", "compliance", "regime", "warnings"} <= data["cycles"][0].keys()
    assert "rig_compliance" in data and data["warnings"] == []
    assert main([*base, "--model", "half-space", "--gauge-length", "20 mm", "--shear-modulus", "80 GPa"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "--gauge-length does not apply" in err and len(err.strip().splitlines()) == 1


def _lagged_sine(samples_per_cycle: int, cycles: int, noise: float, seed: int):
    """A twist theta = A sin(2 pi t) (A = 5e-4 rad, 1 Hz) with white noise, its exact rate and its turning points."""
    clock = np.arange(cycles * samples_per_cycle + 1) / samples_per_cycle
    amplitude = 5e-4
    exact = amplitude * np.sin(2.0 * np.pi * clock)
    rate = 2.0 * np.pi * amplitude * np.cos(2.0 * np.pi * clock)
    turning = np.arange(samples_per_cycle // 4, clock.size - 1, samples_per_cycle // 2)
    twist = exact + noise * np.random.default_rng(seed).standard_normal(clock.size)
    return clock, exact, rate, twist, turning


@pytest.mark.parametrize("window", [5, 41, 101])
def test_local_cubic_is_savitzky_golay(window):
    # the product's own filter (scipy.signal loads scipy.stats) against scipy's, edges included ("interp"): both are
    # the cubic least-squares operator applied to the same samples, equal to rounding (a pseudo-inverse of a window
    # of offsets up to 50 has a condition number ~1e5: tolerance 1e-11 of the data, observed 1.1e-13)
    values = np.sin(np.linspace(0.0, 20.0, 1001)) + 0.01 * np.random.default_rng(1).standard_normal(1001)
    for derivative in (False, True):
        ours = lag_module.local_cubic(values, window, derivative)
        theirs = signal.savgol_filter(values, window, 3, deriv=int(derivative), mode="interp")
        assert np.max(np.abs(ours - theirs)) < 1e-11


@pytest.mark.parametrize("seed", [1, 2])
def test_twist_rate_does_not_attenuate_the_lag(seed):
    # a lag is a regression on the twist's rate: the rate's noise shrinks it by var(rate) / (var(rate) + var(noise))
    # (errors in the variable).  The predicted shrink from the derivative filter's own coefficients, against the
    # measured slope of the exact rate on the estimate; the filter's bias on a sine is below 1e-3 at a window of a
    # sixth of a branch, the slope's sampling error ~ 1e-3 at 10^4 samples: tolerance 0.01.
    clock, _, rate, twist, turning = _lagged_sine(500, 20, 1e-5, seed)
    estimate = lag_module.twist_rate(twist, clock, turning)
    window = lag_module.rate_window(clock.size, turning)
    assert window % 2 == 1 and abs(window - 250 * lag_module.RATE_WINDOW) <= 2
    noise_gain = float(np.sum(signal.savgol_coeffs(window, 3, deriv=1, use="dot") ** 2)) * (1e-5 * 500) ** 2
    predicted = float(np.mean(rate**2)) / (float(np.mean(rate**2)) + noise_gain)
    inner = slice(window, -window)
    slope = float(rate[inner] @ estimate[inner] / (estimate[inner] @ estimate[inner]))
    assert predicted > 0.99
    assert abs(slope - predicted) < 0.01
    # the five-sample running mean's differences it replaced shrank the same lag by about a fifth
    smooth = np.convolve(np.pad(twist, 2, mode="edge"), np.ones(5) / 5.0, mode="valid")
    old = np.gradient(smooth, clock)
    assert float(rate @ old / (old @ old)) < 0.9


@pytest.mark.parametrize("shift", [0.5, 1.5, 2.0])
def test_shifted_twist_keeps_each_samples_noise(shift):
    # interpolating raw samples by half a sample averages two noises (variance halved): the residual sum of a fit then
    # depends on the lag's fraction of a sample.  The shift moves the smooth part only: the noise's variance stays
    # sigma^2 within its sampling error (sd sqrt(2/N) = 1.4 % at N = 10^4) and the signal moves by the lag.
    samples_per_cycle, noise = 500, 1e-5
    clock, exact, _, twist, turning = _lagged_sine(samples_per_cycle, 20, noise, 3)
    lag = shift / samples_per_cycle
    moved = lag_module.shifted_twist(twist, clock, turning, lag)
    target = 5e-4 * np.sin(2.0 * np.pi * (clock + lag))
    inner = slice(50, -50)
    residual = moved[inner] - target[inner]
    assert abs(float(np.var(residual)) / noise**2 - 1.0) < 0.07
    assert abs(float(np.mean(residual))) < 5.0 * noise / math.sqrt(residual.size)
    interpolated = np.interp(clock + lag, clock, twist)[inner] - target[inner]
    expected = 0.5 if shift % 1.0 else 1.0  # the raw interpolation's noise variance, (1 - p)^2 + p^2 of sigma^2
    assert abs(float(np.var(interpolated)) / noise**2 - expected) < 0.07


def test_shifted_twist_reaches_past_the_ends():
    # noise-free: the shifted twist must be the sine at t + lag everywhere, the last samples included (held at the
    # end value, a lag of 6 samples left an error of omega tau A = 0.075 A there).  Bound: the end cubic's
    # extrapolation error, max|d4 theta / dt4| / 24 (window + lag)^4 = A (2 pi)^4 / 24 (47 / 500)^4 = 5e-3 A
    samples_per_cycle = 500
    clock, exact, _, _, turning = _lagged_sine(samples_per_cycle, 4, 0.0, 1)
    for lag in (6.0 / samples_per_cycle, -6.0 / samples_per_cycle):
        moved = lag_module.shifted_twist(exact, clock, turning, lag)
        target = 5e-4 * np.sin(2.0 * np.pi * (clock + lag))
        assert float(np.max(np.abs(moved - target))) < 1e-2 * 5e-4


@pytest.mark.parametrize("seed", [1, 3])
@pytest.mark.parametrize("lag", [0.02, 0.03])
def test_stuck_contact_with_a_long_lag_gets_no_friction(lag, seed):
    # T* 0.9 at 1 Hz, 200 Hz, lags of 4 and 6 samples (omega tau 0.13 and 0.19): the straight loop's lag found to
    # first order only, and the record's end held flat, read seed 3 at 30 ms as slip, f 0.41 [0.40, 0.42]
    record = rig_record(control="torque", amplitude=0.9, cycles=2, frequency=1.0, sample_rate=200.0, rng=seed,
                        defects=RigDefects(lag=lag))
    fit = _fit(record.time, record.torque, record.twist, time=record.time)
    assert fit.friction.value is None and fit.stick_test >= 0.0
    lo = fit.friction.interval[0]
    assert lo is None or lo <= record.truth["friction"]


@pytest.mark.sweep
@pytest.mark.parametrize("seed", [1, 3])
def test_long_stuck_record_with_a_lag_gets_no_friction(seed):
    # 20 cycles at 500 samples per cycle of the independent rig generator (10^4 samples), T* 0.8 (stuck), twist
    # lagging by 2 ms: the lag estimated with the slip fit was shrunk by the noisy rate (1.7 ms), and the 0.3 ms left
    # opened the loop into "slip" with f 0.38 [0.36, 0.44]; seed 3 needs the comparison of both hypotheses each with
    # its own lag
    record = rig_record(control="torque", amplitude=0.8, cycles=20, frequency=1.0, sample_rate=500.0, rng=seed,
                        defects=RigDefects(lag=2e-3))
    fit = _fit(record.time, record.torque, record.twist, time=record.time)
    assert fit.friction.value is None
    assert not fit.slip_detected
    assert fit.stick_test >= 0.0
    lag = [w for w in fit.warnings if w.startswith("lag:")]
    assert len(lag) == 1 and abs(float(lag[0].split()[1]) - 2e-3) < 2e-4
    lo = fit.friction.interval[0]
    assert lo is not None and lo <= record.truth["friction"]
