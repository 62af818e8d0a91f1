"""The timing helpers of the benchmark scripts (workflow/scripts/_timing.py) and what the speed/error
benchmark reports of each timed case: the result of its timed calls, not of a second solve."""

import importlib
import json
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.special import j1

from torsional_contact.diagnostics import TorsionalContactWarning
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.solvers.weak_form import solve_series

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture
def scripts(monkeypatch):
    monkeypatch.syspath_prepend(str(ROOT / "workflow" / "scripts"))
    return importlib.import_module("_timing"), importlib.import_module("benchmark_speed_error")


def test_interleaved_rotates_the_order_and_keeps_each_case_s_last_result(scripts):
    timing, _ = scripts
    calls = []

    def case(name):
        def run():
            calls.append(name)
            return (name, sum(c == name for c in calls))  # the how-many-th call of this case

        return run

    results = {}
    timings = timing.interleaved({n: case(n) for n in "abc"}, 3, results=results)
    # rounds rotate: a b c, b c a, c a b (written out, not derived from the code)
    assert calls == list("abcbcacab")
    assert results == {"a": ("a", 3), "b": ("b", 3), "c": ("c", 3)}
    assert all(len(t.samples) == 3 and all(s >= 0 for s in t.samples) for t in timings.values())
    assert timing.interleaved({"a": case("a")}, 2).keys() == {"a"}  # results stays optional


def test_speed_error_benchmark_solves_each_case_only_in_its_timed_rounds(scripts, monkeypatch):
    """Every case is called exactly once per round (no second solve for the error column), and the
    errors reported are those of that solution: equal to the errors of an independent fresh solve,
    since the solvers are deterministic for the same inputs (same code path, one BLAS thread)."""
    _, bench = scripts
    counts = {"series": 0, "fast": 0}
    series, fast = bench.solve_series, bench.solve_abel_fredholm

    def counted_series(*args, **kwargs):
        counts["series"] += 1
        return series(*args, **kwargs)

    def counted_fast(*args, **kwargs):
        counts["fast"] += 1
        return fast(*args, **kwargs)

    monkeypatch.setattr(bench, "solve_series", counted_series)
    monkeypatch.setattr(bench, "solve_abel_fredholm", counted_fast)
    b, rounds, r_grid = 0.6, 3, np.linspace(0.0, 1.0, 201)
    result = bench.benchmark(b, [145, 290], [10, 14], rounds, r_grid)
    assert counts == {"series": 2 * 2 * rounds, "fast": 2 * rounds + 1}  # + 1: the reference at twice the nodes
    exact = solve_abel_fredholm(b, 2 * result["default_nodes"])
    q_exact = exact.interface_traction(r_grid)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TorsionalContactWarning)
        for row in result["rows"]:
            if row["method"] == "fast":  # the same calls as the script's: equal to the last bit
                s = solve_abel_fredholm(b, row["resolution"])
                assert row["traction_error"] == float(np.max(np.abs(s.interface_traction(r_grid) - q_exact)))
            else:  # the traction T* r - sum c_n lam_n J1(lam_n r) (eq. 26) by a plain sum here
                s = solve_series(b, row["method"], row["resolution"])
                terms = s.amplitudes * s.eigenvalues * j1(np.outer(r_grid, s.eigenvalues))
                traction = s.torque * r_grid - terms.sum(axis=1)
                # two summation orders of the same N terms differ by at most ~N eps sum|term| each;
                # x10 for the margin the guide asks
                bound = 10 * s.eigenvalues.size * np.finfo(float).eps * (s.torque + np.abs(terms).sum(axis=1).max())
                assert abs(row["traction_error"] - float(np.max(np.abs(traction - q_exact)))) <= bound
            assert row["torque"] == s.torque
            assert row["torque_error"] == abs(s.torque - exact.torque)


def test_speed_error_benchmark_repeats_only_the_radius_whose_times_are_shown(scripts, monkeypatch, tmp_path):
    """The figure and the macros show times at the middle stick radius only: it runs every round; the
    other radii (their errors are shown) run one, and the JSON says so per radius and per case."""
    _, bench = scripts
    out = tmp_path / "bench.json"
    monkeypatch.setattr("sys.argv", ["benchmark_speed_error.py", "--stick-radius", "0.3", "0.6", "0.9",
                                     "--n-terms", "145", "--nodes", "10", "--repeats", "3", "--reference-digits",
                                     "--per-radius-radii", "2", "--curve-radii", "2", "--inverse-torques", "1",
                                     "--json", str(out)])
    bench.main()
    results = json.loads(out.read_text())["results"]
    assert [r["stick_radius"] for r in results] == [0.3, 0.6, 0.9]
    assert [r["rounds"] for r in results] == [1, 3, 1]
    for result in results:
        assert {row["timing"]["samples"] for row in result["rows"]} == {result["rounds"]}
