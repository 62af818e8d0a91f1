"""The coverage study's script (workflow/scripts/friction_test_coverage.py): its output does not depend on how many
processes fit the draws (the records are drawn first, in order, from one random stream; each fit depends on its record
alone)."""

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = ROOT / "workflow" / "scripts" / "friction_test_coverage.py"
SPECIMEN = {"radius": 0.005, "normal_force": 1000.0, "friction": 0.6, "shear_modulus": 8.0e10, "compliance": 4.0e-4}
#: A slipping loop (profile intervals) and a loop in stick (the slip test's early exit): both paths of the fit.
SCENARIOS = [
    {"name": "partial-slip", "control": "torque", "amplitude": 1.3, "torque_noise": 0.005, "twist_noise": 1e-5},
    {"name": "stick", "control": "torque", "amplitude": 0.8, "torque_noise": 0.005, "twist_noise": 1e-5}]


def run(out: Path, *extra):
    out.mkdir()
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    return subprocess.run(
        [sys.executable, str(SCRIPT), "--specimen", json.dumps(SPECIMEN), "--scenarios", json.dumps(SCENARIOS),
         "--draws", "3", "--cycles", "1.5", "--samples-per-cycle", "60", "--seed", "5", "--json", str(out / "c.json"),
         "--tex", str(out / "c.tex"), "--macros", str(out / "m.tex"), *extra],
        capture_output=True, text=True, env=env, cwd=ROOT)


def test_output_is_the_same_on_one_and_two_workers(tmp_path):
    serial = run(tmp_path / "one", "--workers", "1")
    parallel = run(tmp_path / "two", "--workers", "2")
    assert serial.returncode == 0, serial.stderr
    assert parallel.returncode == 0, parallel.stderr
    for name in ("c.json", "c.tex", "m.tex"):
        assert (tmp_path / "one" / name).read_bytes() == (tmp_path / "two" / name).read_bytes(), name
    rows = json.loads((tmp_path / "one" / "c.json").read_text())["scenarios"]
    assert [row["draws"] for row in rows] == [3, 3]


def test_bad_worker_count_is_rejected(tmp_path):
    result = run(tmp_path / "bad", "--workers", "0")
    assert result.returncode == 2
    assert "--workers" in result.stderr and result.stdout == ""
    assert not any((tmp_path / "bad").iterdir())


def test_interval_and_bound_coverage_are_reported_apart_with_clopper_pearson_intervals(tmp_path):
    sys.path.insert(0, str(ROOT / "src"))
    from torsional_contact.verification.fit_study import clopper_pearson

    result = run(tmp_path / "cp", "--workers", "1")
    assert result.returncode == 0, result.stderr
    rows = json.loads((tmp_path / "cp" / "c.json").read_text())["scenarios"]
    table = (tmp_path / "cp" / "c.tex").read_text()
    assert "interval coverage" in table and "bound coverage" in table and r"\pm" not in table
    for row in rows:
        for key in ("friction", "shear_modulus", "compliance"):
            e = row[key]
            for kind, status in (("interval_coverage", "interval"), ("bound_coverage", "bound")):
                rate = e[kind]
                assert rate["trials"] == round(e[status] * row["draws"])
                if rate["trials"]:
                    assert rate["interval"] == list(clopper_pearson(rate["count"], rate["trials"]))
                    assert f"{rate['count']}/{rate['trials']}" in table
                else:
                    assert rate["interval"] is None


def test_the_verdict_against_the_nominal_range_follows_the_binomial_quantiles():
    """'below' / 'within' / 'above' the counts a true 95 % coverage gives in 95 % of studies of that many trials:
    checked against the binomial distribution summed directly (the quantile is the least k with P(X <= k) >= q)."""
    sys.path.insert(0, str(SCRIPT.parent))
    try:
        from friction_test_coverage import nominal_verdict
    finally:
        sys.path.remove(str(SCRIPT.parent))
    from math import comb

    def cdf(k, n, p=0.95):
        return sum(comb(n, j) * p**j * (1 - p) ** (n - j) for j in range(k + 1))

    for trials in (1, 20, 61, 64):
        lowest = next(k for k in range(trials + 1) if cdf(k, trials) >= 0.025)
        highest = next(k for k in range(trials + 1) if cdf(k, trials) >= 0.975)
        for count in range(trials + 1):
            expected = "below" if count < lowest else "above" if count > highest else "within"
            assert nominal_verdict({"count": count, "trials": trials}) == expected, (count, trials)
    assert nominal_verdict({"count": 0, "trials": 0}) == "--"
