"""The rig-record generator against physics: Masing's identities, loop area = energy per cycle, the gross-slip
plateau, and each defect doing what it says (every contact model of the table)."""

import math

import numpy as np
import pytest
from tolerances import assert_close, assert_sampled, assert_within

from torsional_contact import models
from torsional_contact.verification.rig_records import MasingWalk, RigDefects, RigSpecimen, rig_record

MODEL_NAMES = tuple(models.MODELS)
EPS = np.finfo(float).eps
#: Twist residual of the inverse skeleton away from the log-steep gross-slip end (rad; the generator's docstring).
INVERSE_TWIST = 1e-11


def quiet(specimen, **kwargs):
    return rig_record(specimen, torque_noise=0.0, twist_noise=0.0, **kwargs)


def energy_unit(specimen: RigSpecimen) -> float:
    """(f p-bar)^2 a^3 / G in J."""
    p = specimen.normal_force / (math.pi * specimen.radius**2)
    return (specimen.friction * p) ** 2 * specimen.radius**3 / specimen.shear_modulus


def cycle_area(record, start: float) -> float:
    """The closed integral of T d theta over one cycle from ``start`` (J), trapezoids on the samples."""
    m = (record.time >= start - 1e-12) & (record.time <= start + 1.0 / record.frequency + 1e-12)
    torque, twist = record.clean_torque[m], record.clean_twist[m]
    return abs(float(np.sum(0.5 * (torque[1:] + torque[:-1]) * np.diff(twist))))


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_loop_area_is_energy_per_cycle(name):
    """The area of a steady loop in (T, theta) is W(A) of the model (Masing: W(A) = 4 W_mono(A/2)), computed by the
    model from its loading work, not from the rotation the generator walks.  Trapezoid error ~ 1/N^2: the error
    bound is ten times the difference between N and 2N samples per cycle."""
    specimen = RigSpecimen(model=name)
    amplitude = 0.9 * specimen.contact.gross_slip_torque
    coarse, fine = (cycle_area(quiet(specimen, amplitude=amplitude, cycles=2.0, sample_rate=n), 1.0)
                    for n in (800, 1600))
    expected = specimen.contact.energy_per_cycle(2 * amplitude) * energy_unit(specimen)
    assert expected > 0
    assert_within(abs(fine - expected), 10 * abs(coarse - fine) + 1e-9 * expected,
                  "trapezoid error, bounded by ten times the N against 2N difference")


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_no_dissipation_below_the_slip_onset(name):
    specimen = RigSpecimen(model=name)
    onset = specimen.contact.slip_onset_torque
    if not onset > 0:
        pytest.skip(f"model {name!r} slips at any torque")
    record = quiet(specimen, amplitude=0.8 * onset, cycles=2.0, sample_rate=400)
    scale = float(np.max(np.abs(record.clean_torque)) * np.max(np.abs(record.clean_twist)))
    assert_within(cycle_area(record, 1.0), 1e-12 * scale, "a loop in stick is a line: rounding of the sums")


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_twist_control_follows_masing_branches(name):
    """Under twist control the torque is found by inverting the skeleton; the twist computed back from the torque
    with the skeleton itself obeys the virgin curve and the branch rule theta_r - theta = 2 h((T_r - T)/2)."""
    specimen = RigSpecimen(model=name)
    amplitude = float(specimen.skeleton(min(1.2, 0.95 * specimen.contact.gross_slip_torque)))  # within every model's
    record = quiet(specimen, control="twist", amplitude=amplitude, cycles=1.0, sample_rate=400)
    ts = specimen.slip_torque()
    t = record.time
    virgin = t <= 0.25
    torque, twist = record.clean_torque / ts, record.clean_twist
    assert_close(np.sign(torque[virgin]) * specimen.skeleton(np.abs(torque[virgin])), twist[virgin],
                 "inverse skeleton to its stated residual", atol=INVERSE_TWIST)
    down = (t >= 0.25) & (t <= 0.75)
    top_torque, top_twist = torque[t == 0.25][0], twist[t == 0.25][0]
    assert_close(top_twist - 2 * specimen.skeleton((top_torque - torque[down]) / 2), twist[down],
                 "branch rule, inverse skeleton to its stated residual", atol=2 * INVERSE_TWIST)
    # point symmetry of the steady loop: the branch reaches -T_max at -theta_max
    assert_close(torque[t == 0.75][0], -top_torque, "a symmetric loop closes on the mirror", rtol=1e-9)


@pytest.mark.parametrize("name", MODEL_NAMES)
def test_gross_slip_plateau(name):
    """A twist-controlled rig driven far beyond the knee rides the model's gross-slip torque and never exceeds it."""
    specimen = RigSpecimen(model=name)
    amplitude = float(specimen.skeleton(specimen.contact.gross_slip_torque * (1 - 1e-6))) * 1.5
    record = quiet(specimen, control="twist", amplitude=amplitude, cycles=1.5, sample_rate=400)
    top = specimen.gross_slip_torque()
    assert np.max(np.abs(record.clean_torque)) <= top * (1 + 4 * EPS)
    assert_within(top - np.max(record.clean_torque), 1e-6 * top, "the skeleton is within 1e-6 of the plateau "
                  "at the drive's peak (the torque reaches it at a finite twist or logarithmically close)")
    assert record.truth["max_torque_ratio"] == pytest.approx(specimen.contact.gross_slip_torque, rel=1e-6)


def test_masing_walk_memory_on_a_manufactured_skeleton():
    """S(x) = x + x^3: closed forms for every branch; an inner loop closes where it opened (return-point memory)
    and the virgin curve is rejoined beyond the largest excursion."""
    walk = MasingWalk(lambda x, branch: x + x**3)
    drive = np.array([0.5, 1.2, 0.0, -0.4, 0.3, 0.8, 1.0, 1.2, 1.5, -1.5, -1.6])
    y = walk.walk(drive)

    def s(x):
        return x + x**3

    y_top = s(1.2)
    y_low = y_top - 2 * s((1.2 + 0.4) / 2)  # at -0.4 on the branch from the reversal at 1.2
    expected = [s(0.5), y_top, y_top - 2 * s(0.6), y_low,
                y_low + 2 * s(0.35), y_low + 2 * s(0.6), y_low + 2 * s(0.7),  # the branch from -0.4
                y_top,  # which reaches the outer reversal there (memory) ...
                s(1.5),  # ... and beyond it the virgin curve
                s(1.5) - 2 * s(1.5), -s(1.6)]  # down to the mirror, then the virgin curve again
    assert_close(y, np.array(expected), "closed forms of a cubic skeleton; rounding", rtol=1e-14, atol=1e-14)


def test_masing_walk_inner_loop_closes():
    walk = MasingWalk(lambda x, branch: np.tanh(x))
    drive = np.array([1.0, -0.2, 0.5, -0.2, 0.6, -1.0, -1.1])
    y = walk.walk(drive)
    assert_close(y[3], y[1], "return-point memory: the inner loop closes where it opened", rtol=1e-15, atol=1e-16)
    assert_close(y[5], -np.tanh(1.0), "the outer branch ends on the mirrored virgin curve", rtol=1e-15)
    assert_close(y[6], -np.tanh(1.1), "and then follows it", rtol=1e-15)


def test_noise_levels_and_time_column():
    specimen = RigSpecimen()
    record = rig_record(specimen, amplitude=1.2, cycles=4.0, sample_rate=500, rng=3)
    n = record.time.size
    assert n == 2001 and record.time[1] - record.time[0] == pytest.approx(1 / 500)
    assert record.torque_noise == pytest.approx(0.005 * np.ptp(record.clean_torque))
    for channel, clean, sd, shift in ((record.torque, record.clean_torque, record.torque_noise, 0.0),
                                      (record.twist, record.clean_twist, record.twist_noise, specimen.twist_zero)):
        sample = np.std(channel - clean - shift)
        assert_sampled(sample / sd, 1.0, 1 / math.sqrt(2 * n), 5, "sample standard deviation of Gaussian noise")


def test_defects_do_what_they_say():
    specimen = RigSpecimen()
    base = dict(amplitude=1.25, cycles=2.0, sample_rate=200, torque_noise=0.0, twist_noise=0.0)
    clean = rig_record(specimen, **base)
    zero = specimen.twist_zero
    # rounding of the added zero and of the times t - lag (the twist's rate times the rounding of t)
    rate = np.max(np.abs(np.gradient(clean.clean_twist, clean.time)))
    rounding = 4 * EPS * (zero + np.max(np.abs(clean.clean_twist)) + 1e-5 * clean.time[-1] + rate * clean.time[-1])
    lagged = rig_record(specimen, defects=RigDefects(lag=2 / 200), **base)
    assert_close(lagged.twist[2:] - zero, clean.clean_twist[:-2], "the twist two samples earlier", atol=rounding)
    assert np.all(lagged.twist[:2] == zero + 0.0)
    drift = rig_record(specimen, defects=RigDefects(drift=1e-5), **base)
    assert_close(drift.twist - clean.twist, 1e-5 * clean.time, "drift rate x time", atol=rounding)
    offset = rig_record(specimen, defects=RigDefects(torque_offset=0.1), **base)
    assert_close(offset.torque - clean.torque, 0.1, "zero offset", atol=4 * EPS * 2.5)
    spiky = rig_record(specimen, defects=RigDefects(spikes=3, spike_height=4e-4), rng=5, **base)
    jumps = np.flatnonzero(spiky.twist != clean.twist)
    assert jumps.tolist() == spiky.spike_indices.tolist() and jumps.size == 3
    assert_close(np.abs(spiky.twist[jumps] - clean.twist[jumps]), 4e-4, "spike height", atol=rounding)
    exact = rig_record(specimen, defects=RigDefects(exact_torque=True), amplitude=1.25, cycles=2.0,
                       sample_rate=200, twist_noise=1e-7, rng=1)
    assert np.array_equal(exact.torque, exact.clean_torque) and exact.torque_noise == 0.0
    late = rig_record(specimen, defects=RigDefects(skip_half_cycle=True), **base)
    assert late.time[0] == pytest.approx(0.5)
    assert_close(late.clean_twist[:301], clean.clean_twist[100:], "the same history, recorded from t = 1/2",
                 atol=rounding)
    inverted = rig_record(specimen, defects=RigDefects(invert_twist=True), **base)
    assert np.array_equal(inverted.twist, -clean.twist)
    coarse = rig_record(specimen, defects=RigDefects(torque_step=0.01, twist_step=1e-6), **base)
    assert_close(coarse.torque / 0.01, np.round(coarse.torque / 0.01), "multiples of the step", atol=1e-9)
    assert_within(np.max(np.abs(coarse.torque - clean.torque)), 0.005 * (1 + 1e-9), "half a step")
    assert set(RigDefects(lag=0.002, spikes=3).active()) == {"lag", "spikes"}


def test_running_in_follows_the_friction():
    """f from 0.6 to 0.45 over 6 cycles under twist control beyond the knee: each cycle's plateau is the gross-slip
    torque of that cycle's friction."""
    specimen = RigSpecimen()
    amplitude = 3 * float(specimen.skeleton(1.3))
    record = quiet(specimen, control="twist", amplitude=amplitude, cycles=8.0, sample_rate=200,
                   defects=RigDefects(friction_end=0.45, running_in_cycles=6.0))
    per_cycle = record.truth["friction_per_cycle"]
    assert len(per_cycle) == 8 and per_cycle[0] < 0.6 and per_cycle[-1] == pytest.approx(0.45)
    assert np.all(np.diff(per_cycle) <= 0)
    gross = specimen.contact.gross_slip_torque
    fa2 = 0.5 * specimen.normal_force * specimen.radius
    for cycle in (2, 4, 7):
        m = (record.time > cycle - 1) & (record.time <= cycle)
        plateau = np.max(np.abs(record.clean_torque[m]))
        # the plateau of the cycle lies between the frictions of its first and last branches
        f_first = 0.6 + (0.45 - 0.6) * min((2 * cycle - 2) / 12, 1)
        f_last = 0.6 + (0.45 - 0.6) * min((2 * cycle) / 12, 1)
        assert gross * fa2 * f_last * (1 - 1e-6) <= plateau <= gross * fa2 * f_first * (1 + 1e-12)


def test_long_record_shape():
    record = rig_record(RigSpecimen(), amplitude=1.25, cycles=50, frequency=0.5, sample_rate=1000, rng=0)
    assert record.time.size == 100_001
    assert np.all(np.isfinite(record.twist)) and np.all(np.isfinite(record.torque))


@pytest.mark.parametrize("kwargs, word", [
    (dict(amplitude=1.4), "gross-slip"), (dict(control="load"), "control"), (dict(twist_noise=-1.0), "twist_noise"),
    (dict(control="twist", amplitude=1e-3, mean=0.1), "mean"), (dict(cycles=0.0), "cycles"),
    (dict(defects=RigDefects(spikes=10_000)), "spikes")])
def test_bad_input(kwargs, word):
    with pytest.raises(ValueError, match=word):
        rig_record(RigSpecimen(), **kwargs)


@pytest.mark.parametrize("kwargs, word", [(dict(lag=-1.0), "lag"), (dict(spikes=1.5), "spikes"),
                                          (dict(friction_end=0.0), "friction_end")])
def test_bad_defects(kwargs, word):
    with pytest.raises(ValueError, match=word):
        RigDefects(**kwargs)


def test_bad_specimen():
    with pytest.raises(ValueError, match="shear_modulus"):
        RigSpecimen(shear_modulus=-1.0)
    with pytest.raises(ValueError, match="model"):
        RigSpecimen(model="no-such-model")
