"""The core install: a wheel of the package in a clean virtual environment with numpy, scipy and pint only.

The wheel is built from this checkout (``pip wheel --no-deps``) and installed into a new virtual
environment (no system site packages, no pip: the development environment's pip installs into it) with its declared
dependencies, pinned to the versions of
environment.txt (``-c``), so that numpy and scipy are the versions of the development environment.
There ``solve``, ``history``, the specimen and the command line's ``solve``, ``history`` (turning points
and a signal file) and ``fit`` run, the extras' packages are not importable, and the subcommands
that need an extra exit with status 2 and one line naming it.  Every number printed is compared with
the same probe run in the development environment: the same code on the same numpy and scipy gives
the same digits, so the comparison is exact.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: Import names of the packages of the extras (``torsional_contact.extras``) and of the workflow.
NOT_IN_CORE = ("mpmath", "flint", "skfem", "tqdm", "matplotlib", "snakemake", "yaml")

PROBE = r'''
import importlib.util, json, subprocess, sys
import numpy as np
import torsional_contact as tc

loop_file, signal_file = sys.argv[1], sys.argv[2]
out = {"missing": sorted(m for m in sys.argv[3].split(",") if importlib.util.find_spec(m) is None)}
r, z = np.linspace(0.0, 1.0, 7), np.array([0.0, 0.05, 0.3])
for label, s in {"fast_torque": tc.solve(torque=1.23), "fast_radius": tc.solve(stick_radius=0.37),
                 "complete": tc.solve(stick_radius=0.6, method="complete"),
                 "published": tc.solve(torque=1.2, method="published", n_terms=200),
                 "half_space": tc.solve(torque=1.1, model="half-space")}.items():
    out[label] = {"state": s.as_dict(), "traction": s.traction(r).tolist(), "slip": s.slip(r).tolist(),
                  "stress": [a.tolist() for a in s.stress(r[:, None], z[None, :])],
                  "displacement": s.displacement(r[:, None], z[None, :]).tolist()}
out["history"] = [state.as_dict() for state in tc.history([0, 1.23, -1.0, 1.3, -0.5])]
specimen = tc.Specimen(radius="5 mm", normal_force="1 kN", friction=0.5, shear_modulus="80 GPa")
out["specimen"] = [specimen.solve(torque="1.5 N m").rigid_rotation, specimen.energy_per_cycle("1.6 N m")]


def cli(*args):
    run = subprocess.run([sys.executable, "-m", "torsional_contact", *args], capture_output=True, text=True)
    return {"status": run.returncode, "stdout": run.stdout, "stderr": run.stderr}


out["cli"] = {
    "solve": cli("solve", "--torque", "1.23", "--radii", "0.2", "0.9", "--json"),
    "history": cli("history", "--turning-points", "0", "1.23", "-1.0", "--json"),
    "signal": cli("history", "--signal", signal_file, "--json"),
    "fit": cli("fit", "--loop", loop_file, "--radius", "5 mm", "--normal-force", "1 kN", "--json"),
}
if out["missing"]:  # the core environment: what needs an extra says which
    out["extras"] = {"reference": cli("reference", "--stick-radius", "0.6", "--json"),
                     "errata": cli("errata", "--json")}
print(json.dumps(out))
'''


def _clean_environment() -> dict:
    """The environment without the development checkout's paths.  Python may write bytecode: the core
    environment is installed without it (``--no-compile``: compiling all of scipy costs more than the
    probes), and its first process leaves the bytecode of what it imports for the next ones."""
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONDONTWRITEBYTECODE")}


def _run_probe(python, folder: Path) -> dict:
    signal = folder / "signal.txt"
    signal.write_text("0\n1.2\n-0.8\n1.25\n-1.1\n0.3\n")
    probe = folder / "probe.py"
    probe.write_text(PROBE)
    env = _clean_environment()
    run = subprocess.run([str(python), str(probe), str(ROOT / "notebooks" / "data" / "lab_loop.csv"), str(signal),
                          ",".join(NOT_IN_CORE)], capture_output=True, text=True, cwd=folder, env=env)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


@pytest.fixture(scope="module")
def core_python(tmp_path_factory):
    """The python of a fresh virtual environment with the wheel and its core dependencies only."""
    folder = tmp_path_factory.mktemp("core")
    env = _clean_environment()
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "--wheel-dir", str(folder / "dist"),
                    str(ROOT)], check=True, capture_output=True, env=env)
    (wheel,) = (folder / "dist").glob("torsional_contact-*.whl")
    # no site packages, and no pip of its own (installing pip into it costs more than the rest): the development
    # environment's pip installs into it (``pip --python``), resolving the wheel's declared dependencies there
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(folder / "venv")], check=True, env=env)
    python = folder / "venv" / "bin" / "python"
    subprocess.run([sys.executable, "-m", "pip", "--python", str(python), "install", "--quiet", "--no-compile", "-c",
                    str(ROOT / "environment.txt"), str(wheel)], check=True, capture_output=True, env=env)
    return python


@pytest.mark.slow
def test_core_install_runs_solve_history_and_the_cli_with_the_same_numbers(core_python, tmp_path):
    installed = subprocess.run([sys.executable, "-m", "pip", "--python", str(core_python), "list", "--format", "json"],
                               check=True, capture_output=True, text=True).stdout
    names = {p["name"].lower() for p in json.loads(installed)}
    assert names - {"pip", "setuptools", "wheel"} == {"torsional_contact", "numpy", "scipy", "pint", "flexcache",
                                                      "flexparser", "platformdirs", "typing_extensions"}, names
    (tmp_path / "core").mkdir()
    (tmp_path / "dev").mkdir()
    core = _run_probe(core_python, tmp_path / "core")
    assert core["missing"] == sorted(NOT_IN_CORE)
    for name, run in core["cli"].items():
        assert run["status"] == 0 and run["stderr"] == "", (name, run)
    for name, run in core.pop("extras").items():
        assert run["status"] == 2 and run["stdout"] == "", (name, run)
        line, = run["stderr"].splitlines()
        assert f"{name} subcommand needs" in line and "pip install 'torsional_contact[reference]'" in line, line
    development = _run_probe(sys.executable, tmp_path / "dev")
    assert development["missing"] == []  # the development environment has everything (environment.txt)
    core.pop("missing"), development.pop("missing")
    assert core == development  # to the last digit: the same code on the same numpy and scipy
