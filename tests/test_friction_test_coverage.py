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
