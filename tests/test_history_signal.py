"""Long sampled signals: the array engine against the state objects, rainflow counts, energy, files and the CLI.

Independent checks: ``analyse_signal`` against ``history`` of the same samples (state by state
and sample by sample); closed loops against the ``rainflow`` package (ASTM E1049-85) and
against hand counts of textbook signals; the energy of a sine against W(A) of the
torque-twist loop area; file reading against the samples written; the per-sample table
against the states.
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections import Counter

import numpy as np
import pytest
import rainflow

from torsional_contact import histories as H
from torsional_contact.io.cli import main
from torsional_contact.io.signal_files import format_columns, read_signal

SCALE = 1.3 / 5  # the ASTM E1049-85 example (peaks -2 .. 5) scaled into [-4/3, 4/3]


def _loops(result, count=1.0):
    keep = result.cycle_count == count
    return Counter(zip(np.round(result.cycle_range[keep], 12), np.round(result.cycle_mean[keep], 12), strict=True))


def test_engine_matches_the_state_objects():
    rng = np.random.default_rng(7)
    signal = np.round(rng.uniform(-1.32, 1.32, 300), 3)  # ties: exact loop closures happen
    states = H.history(signal)
    result = H.analyse_signal(signal)
    np.testing.assert_array_equal(result.index, H.turning_point_indices(signal))
    for k, i in enumerate(result.index):
        s = states[i]
        assert result.torque[k] == s.torque and result.direction[k] == s.direction
        assert result.stick_radius[k] == pytest.approx(s.stick_radius, abs=1e-15)
        assert result.rigid_rotation[k] == pytest.approx(s.rigid_rotation, abs=1e-14)
        assert result.dissipated_energy[k] == pytest.approx(s.dissipated_energy, rel=1e-13)
        assert result.slip_fronts(k) == pytest.approx(list(s.slip_fronts), abs=1e-15)
        assert [result.torque[j] for j in result.memory[k]] == list(s.turning_torques)
    omega, energy = result.sample_values()
    np.testing.assert_allclose(omega, [s.rigid_rotation for s in states], atol=1e-14)
    np.testing.assert_allclose(energy, [s.dissipated_energy for s in states], rtol=1e-13, atol=1e-15)


def test_dense_samples_between_turning_points():
    """Samples inside branches (and across loop closures) lie on the right pieces."""
    coarse = [0.0, 1.3, -1.2, 1.1, -0.5, 1.25, -1.3, 0.2]
    dense = np.concatenate([np.linspace(a, b, 37)[:-1] for a, b in zip(coarse[:-1], coarse[1:], strict=True)]
                           + [[coarse[-1]]])
    result = H.analyse_signal(dense)
    omega, energy = result.sample_values()
    states = H.history(dense)
    np.testing.assert_allclose(omega, [s.rigid_rotation for s in states], atol=1e-14)
    np.testing.assert_allclose(energy, [s.dissipated_energy for s in states], rtol=1e-13)
    assert np.all(np.diff(energy) >= 0)


def test_sine_energy_is_999_loops():
    """1000 cycles of a sine of amplitude 1.25: energy from the first to the last maximum = 999 W(2.5)."""
    n = 100_000
    signal = 1.25 * np.sin(2 * np.pi * 1000 * np.arange(n) / n)
    result = H.analyse_signal(signal)
    maxima = np.flatnonzero(result.torque > 1.2)
    assert maxima.size == 1000
    gained = result.dissipated_energy[maxima[-1]] - result.dissipated_energy[maxima[0]]
    # independent: pi x the loop area of the torque-twist loop
    assert gained == pytest.approx(999 * H.dissipation_from_loop_area(2.5), rel=1e-10)
    # the half loops of range 2.5 account for it, one per half cycle after the first loading
    assert result.cycle_count.sum() == pytest.approx(999.5)
    assert np.sum(result.cycle_energy) == pytest.approx(999.5 * H.dissipation_per_cycle(2.5), rel=1e-12)


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
    astm = Counter((round(r, 12), round(m, 12)) for r, m, c, *_ in rainflow.extract_cycles(signal) if c == 1.0)
    assert astm == Counter({(round(4 * SCALE, 12), round(1 * SCALE, 12)): 1})


@pytest.mark.parametrize("seed", range(8))
def test_loops_against_the_rainflow_package(seed):
    """Every full ASTM cycle is a closed loop here; the extra loops are ASTM's pairs of half cycles."""
    rng = np.random.default_rng(seed)
    signal = np.round(rng.uniform(-1.3, 1.3, 400), 2)
    signal[0] = 0.0
    result = H.analyse_signal(signal)
    astm_full, astm_half = Counter(), Counter()
    for r, m, c, *_ in rainflow.extract_cycles(signal):
        (astm_full if c == 1.0 else astm_half)[(round(r, 12), round(m, 12))] += 1
    mine = _loops(result)
    assert not astm_full - mine  # every ASTM cycle is a closed loop
    extra = mine - astm_full
    assert sum(extra.values()) <= len(result.memory[-1]) + 2  # only loops touching the oldest points
    assert not extra - astm_half  # and those ASTM counts as halves


def test_closed_loop_energy_matches_the_state_energies():
    rng = np.random.default_rng(3)
    signal = rng.uniform(-1.3, 1.3, 2000)
    result = H.analyse_signal(signal)
    total = result.total_dissipated_energy
    # loops + what is still open: the energy of the remaining branches (rule 5) is the rest
    assert 0 < np.sum(result.cycle_energy) < total
    assert np.sum(result.cycle_energy) == pytest.approx(
        sum(H.dissipation_per_cycle(a) * c for a, c in zip(result.cycle_range, result.cycle_count, strict=True)),
        rel=1e-13)


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
    np.testing.assert_allclose(back, x, rtol=1e-15)


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
    assert record["cycles"] == [{"range": 2.35, "mean": pytest.approx(0.075), "count": 1.0,
                                 "dissipated_energy": pytest.approx(w, rel=1e-14)}]
    states = H.history(signal)
    assert record["dissipated_energy"] == pytest.approx(states[-1].dissipated_energy, rel=1e-13)
    rows = np.loadtxt(table, delimiter=",", skiprows=1)
    assert rows.shape == (signal.size, 4)
    np.testing.assert_allclose(rows[:, 2], [s.rigid_rotation for s in states], atol=1e-15, rtol=1e-14)
    np.testing.assert_allclose(rows[:, 3], [s.dissipated_energy for s in states], atol=1e-15, rtol=1e-14)
    assert table.read_text().splitlines()[0] == "sample,torque,rigid_rotation,dissipated_energy"


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
