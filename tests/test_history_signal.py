"""Long sampled signals: the array engine against the state objects, rainflow counts, the gate, files and the CLI.

Independent checks: ``analyse_signal`` against ``history`` of the same samples (state by state
and sample by sample); closed loops against the ``rainflow`` package (ASTM E1049-85), exactly
and with ties, and against hand counts of textbook signals; the gate against the loops of the
ungated signal; the rainflow matrix against a direct count; the energy of a sine against W(A)
of the torque-twist loop area; table files against the arrays written; the CLI against the API.

Tolerances.  The engine and ``history`` evaluate the same formulas.  They differ in evaluating
the interpolants of ``curves`` as scalars (``point``) or arrays (``points``), a few ulps apart
(``ULPS`` eps), and in how they group sums.  b (<= 1) is compared to ``ULPS`` eps.  omega is a sum
of terms w_j omega_m(tau_j), one per stack level, so it is compared to ``ULPS`` eps times
sum_j |w_j omega_m(tau_j)| (``_rotation_tolerance``).  The energy is a sum of non-negative
increments g [W(tau_b) - W(tau_a)], ``history`` one per sample step and loop closed, the engine
one per piece, each within ``ULPS`` eps of W: compared to ``ULPS`` eps times the number of
increments (samples + pieces) relative (``_energy_tolerance``).  Tables hold 16 significant digits:
a relative rounding of at most 5e-16, plus half an ulp reading back (``DIGITS16``).
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections import Counter

import numpy as np
import pytest
import rainflow
from tolerances import EPS, ROTATION_ACCURACY, assert_close, assert_within

from torsional_contact import histories as H
from torsional_contact.contact_models.cylinder import point
from torsional_contact.histories.signal import gated_signal
from torsional_contact.io.cli import main
from torsional_contact.io.history_command import DEFAULT_BIN_WIDTH, STATES_IN_JSON
from torsional_contact.io.signal_files import format_columns, read_signal, read_table, write_table

SCALE = 1.3 / 5  # the ASTM E1049-85 example (peaks -2 .. 5) scaled into [-4/3, 4/3]
ULPS = 16  # scalar and vectorised interpolants: the same coefficients, a few ulps apart (see the docstring)
#: Relative rounding of a number written with 16 significant digits and read back: half a unit of the 16th digit
#: (5e-16 of a leading 1) and half an ulp.  An exact statement about rounding: no margin is possible.
DIGITS16 = 5e-16 + EPS / 2


def _loops(result, count=1.0):
    keep = result.cycle_count == count
    return Counter(zip(np.round(result.cycle_range[keep], 12), np.round(result.cycle_mean[keep], 12), strict=True))


def _all_loops(result):
    return Counter(zip(result.cycle_range.tolist(), result.cycle_mean.tolist(), result.cycle_count.tolist(),
                       strict=True))


def _rotation_tolerance(states):
    """ULPS eps times sum_j |w_j omega_m(tau_j)| over the terms of each state (module docstring)."""
    return np.array([ULPS * EPS * sum(abs(w) * point(tau, "fast", None)[1] for w, tau in s.terms) for s in states])


def _energy_tolerance(result, samples):
    """ULPS eps per increment summed by either side (module docstring)."""
    return ULPS * EPS * (samples + result._pieces["g"].size)  # noqa: SLF001 - the number of pieces


def _same_rotation(engine, reference, tolerance):
    """omega equal within ``tolerance`` where finite; +-inf or nan (spinning) at the same places."""
    finite = np.isfinite(reference)
    np.testing.assert_array_equal(engine[~finite], reference[~finite])  # nan == nan here
    assert_close(engine[finite], reference[finite], "ULPS eps x sum |w_j omega_m(tau_j)|",
                 atol=np.max(tolerance[finite], initial=0))


def _compare_with_states(signal):
    """analyse_signal against history(signal): every state and every sample (tolerances: module docstring)."""
    states = H.history(signal)
    result = H.analyse_signal(signal)
    np.testing.assert_array_equal(result.index, H.turning_point_indices(signal))
    energy_tol = _energy_tolerance(result, signal.size)
    at_turning_points = [states[i] for i in result.index]
    for k, s in enumerate(at_turning_points):
        assert result.torque[k] == s.torque and result.direction[k] == s.direction
        assert_close(result.stick_radius[k], s.stick_radius, "ULPS eps (b <= 1)", atol=ULPS * EPS)
        assert_close(result.dissipated_energy[k], s.dissipated_energy, "ULPS eps per increment",
                     rtol=energy_tol, atol=1e-300)
        assert_close(result.slip_fronts(k), list(s.slip_fronts), "ULPS eps (b <= 1)", atol=ULPS * EPS)
        assert [result.torque[j] for j in result.memory[k]] == list(s.turning_torques)
        assert result.memory_depth[k] == len(s.memory)
    _same_rotation(result.rigid_rotation, np.array([s.rigid_rotation for s in at_turning_points]),
                   _rotation_tolerance(at_turning_points))
    omega, energy = result.sample_values()
    _same_rotation(omega, np.array([s.rigid_rotation for s in states]), _rotation_tolerance(states))
    assert_close(energy, [s.dissipated_energy for s in states], "ULPS eps per increment", rtol=energy_tol,
                 atol=1e-300)
    return result


@pytest.mark.parametrize("seed", range(4))
def test_engine_matches_the_state_objects(seed):
    rng = np.random.default_rng(seed)
    signal = np.round(rng.uniform(-1.32, 1.32, 300), 3 if seed % 2 else 1)  # ties: exact loop closures happen
    _compare_with_states(signal)


@pytest.mark.parametrize(
    "signal",
    [
        [0.0],
        [0.7],
        [4 / 3],
        [-4 / 3, 4 / 3, -4 / 3, 4 / 3],  # the ends: spinning, infinite energy
        [0.0, 4 / 3, 0.0, -4 / 3, 1.0],
        [0.0, 1.2, -1.2, 1.2, -1.2, 1.2, -1.2],  # exact ties with the mirrored virgin curve
        [0.0, 1.3, -0.5, 0.7, -0.5, 0.7, -0.5, 1.3, -1.3, 1.3, -1.3],  # ties with earlier turning points
        list(np.linspace(0.5, -1.3, 40)),  # monotonic
        [0.0, 1.25, 1.25, -1.1, -1.1, 1.25, 0.3, 0.3, 1.25, 1.25, 1.25],  # plateaus, ending in one
    ],
)
def test_engine_on_special_signals(signal):
    _compare_with_states(np.array(signal, dtype=float))


def test_dense_samples_between_turning_points():
    """Samples inside branches (and across loop closures) lie on the right pieces."""
    coarse = [0.0, 1.3, -1.2, 1.1, -0.5, 1.25, -1.3, 0.2]
    dense = np.concatenate([np.linspace(a, b, 37)[:-1] for a, b in zip(coarse[:-1], coarse[1:], strict=True)]
                           + [[coarse[-1]]])
    result = _compare_with_states(dense)
    assert np.all(np.diff(result.sample_values()[1]) >= 0)


def test_sine_energy_is_999_loops():
    """1000 cycles of a sine of amplitude 1.25: energy from the first to the last maximum = 999 W(2.5)."""
    n = 100_000
    signal = 1.25 * np.sin(2 * np.pi * 1000 * np.arange(n) / n)
    result = H.analyse_signal(signal)
    maxima = np.flatnonzero(result.torque > 1.2)
    assert maxima.size == 1000
    gained = result.dissipated_energy[maxima[-1]] - result.dissipated_energy[maxima[0]]
    # independent: pi x the loop area of the torque-twist loop, pi [2 A omega_m(A/2) - 8 int omega_m dT*], each
    # omega within ROTATION_ACCURACY, weights <= 6 A, times pi, 999 times; plus the recursive-summation bound of
    # the 2000 increments of the engine's energy
    w = H.dissipation_from_loop_area(2.5)
    assert_close(gained, 999 * w, "rotation accuracy of the loop area x 999 + summation",
                 atol=999 * 6 * np.pi * 2.5 * ROTATION_ACCURACY + 2000 * EPS * result.dissipated_energy[maxima[-1]])
    # the half loops of range 2.5 account for it, one per half cycle after the first loading
    assert result.closed_loops == 999.5 and result.half_loops == 1999
    # 1999 equal terms summed: the recursive-summation bound 1999 EPS, and ULPS eps of each term
    assert_close(result.loop_energy, 999.5 * H.dissipation_per_cycle(2.5), "recursive summation of 1999 terms",
                 rtol=(1999 + ULPS) * EPS)


def test_astm_example_by_hand():
    """ASTM E1049-85 example (-2, 1, -3, 5, -1, 3, -4, 4, -2), scaled into [-4/3, 4/3].

    The package reproduces the standard's table (ranges 3, 4, 6, 8, 9 with counts 1/2, 3/2, 1/2,
    1, 1/2).  The memory rules, by hand (stack of rule 4, virgin curve as skeleton, limits
    T_(k-1) or -T_1): -2 (virgin); 1: stack [-2]; -3 passes -2: loop (-2, 1) closes (range 3,
    mean -1/2), back on the virgin curve; 5 passes 3 = -(-3): half loop of range 6; -1, 3: stack
    [5, -1]; -4 passes -1: loop (-1, 3) closes (range 4, mean 1), the branch from 5 goes on;
    4, -2: stack [5, -4, 4], nothing closes.  Full loops: (3, -1/2) and (4, 1); the package
    counts the first as a half cycle (it involves its starting point) and the second as full.
    """
    raw = np.array([-2, 1, -3, 5, -1, 3, -4, 4, -2], dtype=float)
    assert rainflow.count_cycles(raw) == [(3, 0.5), (4, 1.5), (6, 0.5), (8, 1.0), (9, 0.5)]
    signal = SCALE * raw
    result = H.analyse_signal(signal)
    expected = Counter({(round(3 * SCALE, 12), round(-0.5 * SCALE, 12)): 1, (round(4 * SCALE, 12),
                                                                            round(1 * SCALE, 12)): 1})
    assert _loops(result) == expected
    assert np.round(result.cycle_range[result.cycle_count == 0.5] / SCALE, 9).tolist() == [6.0]
    assert result.closed_loops == 2.5 and result.half_loops == 1
    astm = Counter((round(r, 12), round(m, 12)) for r, m, c, *_ in rainflow.extract_cycles(signal) if c == 1.0)
    assert astm == Counter({(round(4 * SCALE, 12), round(1 * SCALE, 12)): 1})


@pytest.mark.parametrize("seed", range(8))
def test_loops_against_the_rainflow_package(seed):
    """Any signal: every full ASTM cycle is a closed loop here; the extra loops are ASTM half cycles.

    They are the loops that involve ASTM's first sample, which the memory rules replace by the
    mirrored virgin curve (the exact correspondence: ``test_loops_equal_astm_cycles_with_ties``).
    """
    rng = np.random.default_rng(seed)
    signal = np.round(rng.uniform(-1.3, 1.3, 400), 2)
    signal[0] = 0.0
    result = H.analyse_signal(signal)
    astm_full, astm_half = Counter(), Counter()
    for r, m, c, *_ in rainflow.extract_cycles(signal):
        (astm_full if c == 1.0 else astm_half)[(round(r, 12), round(m, 12))] += 1
    mine = _loops(result)
    assert not astm_full - mine  # every ASTM cycle is a closed loop
    assert not (mine - astm_full) - astm_half  # the others ASTM counts as halves


def _astm_equivalent(signal, result):
    """ASTM's cycles of -T_1, T_1, T_2, ... without its final residue (module docstring of histories.signal)."""
    first = signal[np.flatnonzero(signal)[0]]
    cycles = list(rainflow.extract_cycles(np.concatenate([[-first], signal])))
    residue = len(result.memory[-1]) + 1
    return Counter((r, m, c) for r, m, c, *_ in cycles[:-residue])


@pytest.mark.parametrize("seed", range(12))
def test_loops_equal_astm_cycles_with_ties(seed):
    """First turning point = the largest |T*|: the loops are exactly ASTM's cycles of -T_1, T_1, T_2, ...

    Samples on a coarse grid (0.1 or 0.05) make exact ties the rule: loops closing exactly at an
    earlier turning point, at the mirror -T_1, repeated extremes.  Full and half, range and mean,
    all equal (no rounding: both compute |a - b| and (a + b)/2 of the same two samples).
    """
    rng = np.random.default_rng(seed)
    peak = [1.3, -1.3, 1.2, -0.8][seed % 4]
    step = 0.1 if seed % 2 else 0.05
    rest = np.round(rng.uniform(-abs(peak), abs(peak), 500) / step) * step
    rest = np.clip(rest, -abs(peak), abs(peak))
    rest[rng.random(rest.size) < 0.1] = -peak  # reaching the mirror exactly
    signal = np.concatenate([[0.0, peak], rest])
    result = H.analyse_signal(signal)
    assert _all_loops(result) == _astm_equivalent(signal, result)
    assert result.half_loops > 0 and np.any(result.cycle_count == 1.0)


@pytest.mark.parametrize("periods", [1, 2, 5, 50])
def test_periodic_signal_with_exact_ties(periods):
    """0, 1.2, -1.2, 1.2, ...: every half cycle is half a loop of range 2.4; loops counted as rainflow does.

    ``rainflow.count_cycles`` gives the first loading as half a cycle of range 1.2 (not a loop
    of the memory rules: the virgin curve) and 2 x periods halves of range 2.4, i.e. ``periods``
    cycles; so do the memory rules (the last half loop closes exactly at -T_1).
    """
    signal = np.array([0.0] + [1.2, -1.2] * periods + [1.2])
    result = H.analyse_signal(signal)
    counts = dict(rainflow.count_cycles(signal))
    assert counts == {1.2: 0.5, 2.4: periods}
    assert result.closed_loops == periods and result.half_loops == 2 * periods
    (cycle,) = result.cycles()
    energy = cycle.pop("dissipated_energy")
    assert cycle == {"range": 2.4, "mean": 0.0, "count": float(periods)}
    # 2 x periods half loops of W(2.4)/2 summed (recursive summation) and ULPS eps of each W
    summation = (2 * periods + 1 + ULPS) * EPS
    assert_close(energy, periods * H.dissipation_per_cycle(2.4), "recursive summation of the half loops",
                 rtol=summation)
    # the energy: the first loading, then W(2.4)/2 per half cycle (rule 5): 2 x periods + 1 terms
    expected = H.loading_work(1.2) + periods * H.dissipation_per_cycle(2.4)
    assert_close(result.total_dissipated_energy, expected, "recursive summation of the increments", rtol=summation)


def test_closed_loop_energy_matches_the_state_energies():
    rng = np.random.default_rng(3)
    signal = rng.uniform(-1.3, 1.3, 2000)
    result = H.analyse_signal(signal)
    total = result.total_dissipated_energy
    # loops + what is still open: the energy of the remaining branches (rule 5) is the rest
    assert 0 < result.loop_energy < total
    # the same W per loop (within ULPS eps: scalar and array interpolants), summed over the loops: the
    # recursive-summation bound of positive terms, (loops + ULPS) eps
    loops = result.cycle_range.size
    assert_close(result.loop_energy,
                 sum(H.dissipation_per_cycle(a) * c for a, c in zip(result.cycle_range, result.cycle_count,
                                                                    strict=True)),
                 "recursive summation of positive terms", rtol=(loops + ULPS) * EPS)


def test_remembered_points_are_a_chain():
    rng = np.random.default_rng(11)
    result = H.analyse_signal(np.round(rng.uniform(-1.3, 1.3, 500), 1))
    states = H.history(result.torque)
    for k in range(result.index.size):
        assert [result.torque[j] for j in result.memory[k]] == list(states[k].turning_torques)
    assert list(result.memory[3:6]) == [result.memory[3], result.memory[4], result.memory[5]]
    assert len(result.memory) == result.index.size


# --------------------------------------------------------------------------- rainflow matrix
def test_rainflow_bins_against_a_direct_count():
    rng = np.random.default_rng(5)
    result = H.analyse_signal(np.round(rng.uniform(-1.3, 1.3, 3000), 2))
    width = 0.1
    direct: dict = {}
    for a, m, c, w in zip(result.cycle_range, result.cycle_mean, result.cycle_count, result.cycle_energy,
                          strict=True):
        i = next(i for i in range(100) if i * width <= a < (i + 1) * width)
        j = next(j for j in range(-50, 50) if j * width <= m < (j + 1) * width)
        entry = direct.setdefault((i, j), [0.0, 0.0])
        entry[0] += c
        entry[1] += w
    bins = result.rainflow_bins(width)
    assert [(round(b["range_bin"][0] / width), round(b["mean_bin"][0] / width)) for b in bins] == sorted(direct)
    for b in bins:
        i, j = round(b["range_bin"][0] / width), round(b["mean_bin"][0] / width)
        assert b["count"] == direct[(i, j)][0]  # halves and wholes: exact in binary
        # the bin's centre: (i + 1/2) width, by a product and a sum: two roundings of values <= 2.7
        assert_close(b["range"], (i + 0.5) * width, "two roundings", atol=2 * EPS * 2.7)
        assert_close(b["mean"], (j + 0.5) * width, "two roundings", atol=2 * EPS * 2.7)
        # energies: the same positive terms, summed: the recursive-summation bound of their number
        assert_close(b["dissipated_energy"], direct[(i, j)][1], "recursive summation of the bin's terms",
                     rtol=(4 * b["count"] + 2) * EPS)
    assert sum(b["count"] for b in bins) == result.closed_loops
    with pytest.raises(ValueError, match="bin_width must lie in"):
        result.rainflow_bins(0.0)


# --------------------------------------------------------------------------- the gate
def _gate_cases():
    for seed in range(30):
        rng = np.random.default_rng(100 + seed)
        n = int(rng.integers(2, 400))
        if seed % 3 == 0:
            signal = np.round(rng.uniform(-1.3, 1.3, n), 1)  # ties
        elif seed % 3 == 1:
            signal = np.clip(np.cumsum(rng.normal(0, 0.2, n)), -4 / 3, 4 / 3)
        else:
            signal = np.round(np.clip(np.cumsum(rng.normal(0, 0.1, n)), -4 / 3, 4 / 3), 2)  # plateaus, ties
        yield signal, [0.01, 0.05, 0.2, 0.5, 1.0, 2.0, 2.5][seed % 7]


@pytest.mark.parametrize("signal, gate", list(_gate_cases()))
def test_gate_cuts_out_exactly_the_small_loops(signal, gate):
    """The loops of the gated signal are the loops of the signal with range >= gate, exactly."""
    gated = gated_signal(signal, gate)
    assert np.all(np.abs(gated - signal) < gate)
    path = np.concatenate([[0.0], gated])
    legs = np.abs(np.diff(path[H.turning_point_indices(path)]))
    assert np.all(legs[1:-1] >= gate)  # every reversal kept is at least the gate
    kept = Counter({loop: n for loop, n in _all_loops(H.analyse_signal(signal)).items() if loop[0] >= gate})
    result = H.analyse_signal(signal, gate=gate)
    assert _all_loops(result) == kept
    np.testing.assert_array_equal(result.signal, gated)
    assert result.dropped_turning_points == H.turning_point_indices(signal).size - result.index.size
    if gate <= 2.0:  # the loops cut out never slip: the states at the kept turning points are unchanged
        ungated = H.analyse_signal(signal)
        omega, energy = ungated.sample_values()
        states = H.history(signal)
        # both sides sum the same terms with different groupings: twice the tolerances of one comparison
        _same_rotation(result.rigid_rotation, omega[result.index],
                       2 * _rotation_tolerance([states[i] for i in result.index]))
        assert_close(result.dissipated_energy, energy[result.index], "ULPS eps per increment",
                     rtol=_energy_tolerance(ungated, signal.size), atol=1e-300)


def test_gate_by_hand():
    """Gate 0.5: 0 -> 0.1 -> -0.5 drops the first reversal (its half loop, 0.2, is below the gate)."""
    signal = np.array([0.1, -0.5, -0.3, -0.6, 0.2, 0.0, 0.3, 0.1])
    gated = gated_signal(signal, 0.5)
    # kept: -0.6 (reached after a dip of 0.2 < 0.5 back), 0.3 (0.9 above -0.6); the final dip 0.2 dropped
    np.testing.assert_array_equal(gated, [0.0, -0.5, -0.5, -0.6, 0.2, 0.2, 0.3, 0.3])
    assert np.array_equal(gated_signal(signal, 0.0), signal)
    # never spanning the gate: one loading to the torque farthest from zero
    np.testing.assert_array_equal(gated_signal([0.2, -0.3, 0.1], 0.6), [0.0, -0.3, -0.3])
    np.testing.assert_array_equal(gated_signal([0.2, 0.1], 0.6), [0.2, 0.2])
    for bad in (-0.1, 2.7, np.nan, "x"):
        with pytest.raises(ValueError, match="gate must"):
            gated_signal(signal, bad)
    with pytest.raises(ValueError, match="gate must"):
        H.analyse_signal(signal, gate=3.0)


# --------------------------------------------------------------------------- files
def test_read_signal_text_and_npy(tmp_path):
    values = np.array([0.0, 1.23, -1.0, 4.0 / 3.0, -0.5])
    text = tmp_path / "signal.csv"
    text.write_text("# torque record\n" + "\n".join(repr(v) for v in values.tolist()) + "\n\n")
    np.testing.assert_array_equal(read_signal(text), values)
    npy = tmp_path / "signal.npy"
    np.save(npy, values[:, None])
    np.testing.assert_array_equal(read_signal(npy), values)


@pytest.mark.parametrize(
    "content, match",
    [
        ("0.1\n0.2\nabc\n", "line 3: 'abc' is not a number"),
        ("0.1\nnan\n", "line 2: nan is not finite"),
        ("0.1\n\n-inf\n", "line 3: -inf is not finite"),
        ("0.1\n1.5\n", r"line 2: 1.5 lies outside \[-4/3, 4/3\]"),
        ("0.1\ntorque\n", "line 2: 'torque' is not a number"),  # a name on the first line only is a header
        ("0.1,0.2\n", "2 columns"),
        ("", "no samples"),
        ("\n# only a comment\n", "no samples"),
    ],
)
def test_bad_files(tmp_path, content, match):
    path = tmp_path / "bad.txt"
    path.write_text(content)
    with pytest.raises(ValueError, match=match):
        read_signal(path)


def test_bad_npy(tmp_path):
    path = tmp_path / "bad.npy"
    np.save(path, np.array([0.1, np.nan]))
    with pytest.raises(ValueError, match="element 1: nan is not finite"):
        read_signal(path)
    np.save(path, np.array(["a", "b"]))
    with pytest.raises(ValueError, match="1-d array of real numbers"):
        read_signal(path)


def test_bad_api_signals():
    with pytest.raises(ValueError, match=r"signal\[2\] must be finite"):
        H.analyse_signal([0.0, 1.0, np.nan])
    with pytest.raises(ValueError, match=r"signal\[1\] must lie in \[-4/3, 4/3\]"):
        H.analyse_signal(np.array([0.0, -1.4]))
    with pytest.raises(ValueError, match="at least one"):
        H.analyse_signal([])
    with pytest.raises(ValueError, match=r"signal\[0\] must be a real number"):
        H.analyse_signal(["x"])


def test_format_columns_round_trip():
    x = np.array([0.0, -0.0, 1.0, -2.5e-300, 123456.789, np.inf, -np.inf, 1 / 3, 9.9999999999999999e22])
    rows = format_columns([np.arange(x.size), x], integer_columns=(0,)).decode().splitlines()
    assert [int(r.split(",")[0]) for r in rows] == list(range(x.size))
    back = np.array([float(r.split(",")[1]) for r in rows])
    finite = np.isfinite(x) & (x != 0)
    assert np.array_equal(back[~finite], x[~finite])
    assert_within(np.max(np.abs(back[finite] / x[finite] - 1)), DIGITS16, "16 significant digits", exact=True)


@pytest.mark.parametrize("name", ["t.npz", "t.NPY", "t.csv", "t.txt"])
def test_tables_round_trip(tmp_path, name):
    columns = {"sample": np.arange(5), "torque": np.array([0.0, 1 / 3, -4 / 3, 1e-300, 1.0]),
               "energy": np.array([0.0, 0.1, np.inf, 2.0, 3.0])}
    path = tmp_path / name
    write_table(path, columns, metadata={"method": "fast"})
    back = read_table(path)
    exact = name.lower().endswith((".npz", ".npy"))
    for key, value in columns.items():
        if exact or key == "sample":
            np.testing.assert_array_equal(back[key], value)
        else:
            finite = np.isfinite(value) & (value != 0)
            np.testing.assert_array_equal(back[key][~finite], value[~finite])
            assert_within(np.max(np.abs(back[key][finite] / value[finite] - 1)), DIGITS16, "16 significant digits",
                          exact=True)
    assert ("metadata" in back) == name.endswith(".npz")
    if name.endswith(".npz"):
        assert back["metadata"]["method"] == "fast" and "packages" in back["metadata"]
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]  # no temporary file left


# --------------------------------------------------------------------------- CLI
def test_cli_signal(tmp_path):
    signal = np.concatenate([np.linspace(0, 1.25, 50), np.linspace(1.25, -1.1, 80), np.linspace(-1.1, 1.25, 80)])
    path = tmp_path / "signal.txt"
    np.savetxt(path, signal)
    table = tmp_path / "out.csv"
    run = subprocess.run([sys.executable, "-m", "torsional_contact", "history", "--signal", str(path), "--json",
                          "--output", str(table)], capture_output=True, text=True, check=True)
    record = json.loads(run.stdout)
    assert record["samples"] == signal.size and record["method"] == "fast"
    assert [s["index"] for s in record["states"]] == [0, 49, 129, 209]
    assert {"index", "torque", "stick_radius", "slip_fronts", "rigid_rotation", "regime",
            "dissipated_energy"} <= set(record["states"][0])
    w = H.dissipation_per_cycle(2.35)
    (cycle,) = record["cycles"]
    mean, energy = cycle.pop("mean"), cycle.pop("dissipated_energy")
    assert cycle == {"range": 2.35, "count": 1.0}
    # (1.25 + (-1.1)) / 2 against the literal: the rounding of 1.1 and of the sum, of values <= 1.25
    assert_close(mean, 0.075, "two roundings of values <= 1.25", atol=2 * EPS * 1.25)
    # two half loops of W/2 summed, each within ULPS eps of W
    assert_close(energy, w, "ULPS eps per half loop", rtol=2 * ULPS * EPS)
    assert record["closed_loops"] == 1.0 and record["half_loops"] == 0 and record["bin_width"] is None
    states = H.history(signal)
    result = H.analyse_signal(signal)
    energy_tol = _energy_tolerance(result, signal.size)
    assert_close(record["dissipated_energy"], states[-1].dissipated_energy, "ULPS eps per increment",
                 rtol=energy_tol)
    rows = np.loadtxt(table, delimiter=",", skiprows=1)
    assert rows.shape == (signal.size, 4)
    # the table: the engine's values (against history: the module docstring's tolerances) in 16 digits
    rotation = np.array([s.rigid_rotation for s in states])
    assert_close(rows[:, 2], rotation, "engine vs history, and 16 digits",
                 atol=np.max(_rotation_tolerance(states)), rtol=DIGITS16)
    assert_close(rows[:, 3], [s.dissipated_energy for s in states], "engine vs history, and 16 digits",
                 rtol=energy_tol + DIGITS16, atol=1e-300)
    assert table.read_text().splitlines()[0] == "sample,torque,rigid_rotation,dissipated_energy"


def test_cli_periodic_signal_counts_loops(tmp_path, capsys):
    path = tmp_path / "periodic.txt"
    np.savetxt(path, [0.0] + [1.2, -1.2] * 5 + [1.2])
    assert main(["history", "--signal", str(path), "--json"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["closed_loops"] == 5.0 and record["half_loops"] == 10
    (cycle,) = record["cycles"]
    energy = cycle.pop("dissipated_energy")
    assert cycle == {"range": 2.4, "mean": 0.0, "count": 5.0}
    # ten half loops of W(2.4)/2 summed (recursive summation) and ULPS eps of each W
    assert_close(energy, 5 * H.dissipation_per_cycle(2.4), "recursive summation of the half loops",
                 rtol=(11 + ULPS) * EPS)


def test_cli_long_signal_summary_and_tables(tmp_path, capsys):
    """Beyond STATES_IN_JSON turning points: no states in the JSON, a rainflow matrix, states and samples in files."""
    rng = np.random.default_rng(2)
    signal = np.round(rng.uniform(-1.3, 1.3, 3 * STATES_IN_JSON), 3)
    path = tmp_path / "long.npy"
    np.save(path, signal)
    states_file, samples_file = tmp_path / "states.npz", tmp_path / "samples.npy"
    assert main(["history", "--signal", str(path), "--json", "--no-progress", "--states", str(states_file),
                 "--output", str(samples_file)]) == 0
    record = json.loads(capsys.readouterr().out)
    result = H.analyse_signal(signal)
    assert "states" not in record and record["turning_points"] == result.index.size > STATES_IN_JSON
    assert record["bin_width"] == DEFAULT_BIN_WIDTH
    assert record["cycles"] == json.loads(json.dumps(result.rainflow_bins(DEFAULT_BIN_WIDTH)))
    assert record["closed_loops"] == result.closed_loops and record["states_file"] == str(states_file)
    table = read_table(states_file)
    for key, value in result.state_columns().items():
        np.testing.assert_array_equal(table[key], value)
    assert table["metadata"]["units"]["rigid_rotation"] == "f p0 / mu"
    samples = read_table(samples_file)
    omega, energy = result.sample_values()
    np.testing.assert_array_equal(samples["sample"], np.arange(signal.size))
    np.testing.assert_array_equal(samples["torque"], signal)
    np.testing.assert_array_equal(samples["rigid_rotation"], omega)
    np.testing.assert_array_equal(samples["dissipated_energy"], energy)


def test_cli_gate_and_bin_width(tmp_path, capsys):
    signal = np.array([0.0, 1.25, 1.2, 1.25, -1.1, -1.0, -1.1, 1.25, -1.1])
    path = tmp_path / "signal.txt"
    np.savetxt(path, signal)
    table = tmp_path / "samples.csv"
    assert main(["history", "--signal", str(path), "--json", "--gate", "0.2", "--bin-width", "0.5",
                 "--output", str(table)]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["gate"] == 0.2 and record["dropped_turning_points"] == 4 and record["turning_points"] == 5
    assert [s["torque"] for s in record["states"]] == [0.0, 1.25, -1.1, 1.25, -1.1]
    # the gated history 0, 1.25, -1.1, 1.25, -1.1 closes one loop (1.25, -1.1): range 2.35, mean 0.075
    assert record["closed_loops"] == 1.0
    assert [(b["range_bin"], b["mean_bin"], b["count"], b["range"], b["mean"]) for b in record["cycles"]] == [
        ([2.0, 2.5], [0.0, 0.5], 1.0, 2.25, 0.25)]
    assert table.read_text().splitlines()[0] == "sample,torque,gated_torque,rigid_rotation,dissipated_energy"
    rows = np.loadtxt(table, delimiter=",", skiprows=1)
    # the running extreme since the last kept turning point: the dips 1.25 -> 1.2 -> 1.25 and -1.1 -> -1.0 -> -1.1
    # are cut out by starting the next leg at once (monotonic legs, within the gate of the samples)
    np.testing.assert_array_equal(rows[:, 2], [0.0, 1.25, 1.2, 1.2, -1.1, -1.0, -1.0, 1.25, -1.1])


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--gate", "-0.1"], "--gate must lie in"),
        (["--gate", "2.7"], "--gate must lie in"),
        (["--gate", "nan"], "--gate"),
        (["--bin-width", "0"], "--bin-width must lie in"),
        (["--bin-width", "3"], "--bin-width must lie in"),
    ],
)
def test_cli_bad_options(tmp_path, capsys, extra, message):
    path = tmp_path / "signal.txt"
    np.savetxt(path, [0.0, 1.2, -1.2])
    assert main(["history", "--signal", str(path), "--json", *extra]) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1 and message in err


@pytest.mark.parametrize("option", [["--states", "s.npz"], ["--gate", "0.1"], ["--bin-width", "0.1"],
                                    ["--output", "o.csv"]])
def test_cli_signal_options_need_a_signal(capsys, option):
    assert main(["history", "--turning-points", "0", "1.2", "--json", *option]) == 2
    out, err = capsys.readouterr()
    assert out == "" and f"{option[0]} needs --signal" in err


@pytest.mark.parametrize(
    "content, where",
    [("0\n1.2\nfoo\n", "line 3"), ("0\n1.2\n1.4\n", "line 3"), ("0\ninf\n", "line 2"), ("", "no samples")],
)
def test_cli_bad_signal(tmp_path, capsys, content, where):
    path = tmp_path / "bad.txt"
    path.write_text(content)
    assert main(["history", "--signal", str(path), "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1 and where in err


def test_cli_missing_file(capsys, tmp_path):
    assert main(["history", "--signal", str(tmp_path / "absent.txt"), "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "cannot read" in err
