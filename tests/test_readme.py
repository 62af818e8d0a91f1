"""What the README and the package's front door promise works as written.

The README's Python blocks run as pasted; the warning categories it tells users to filter are
importable from the package; the package docstring points to docs/conventions.md; the
JupyterLab command it gives for root in a container starts a server.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
import time
import urllib.error
import urllib.request
import warnings
from pathlib import Path

import pytest

import torsional_contact
from torsional_contact import diagnostics

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()


def code_blocks(text: str, language: str) -> list[str]:
    return re.findall(rf"^```{language}\n(.*?)^```", text, flags=re.MULTILINE | re.DOTALL)


def test_readme_python_blocks_run_as_pasted():
    blocks = code_blocks(README, "python")
    assert blocks, "the README shows the Python API"
    for block in blocks:
        namespace: dict = {}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", diagnostics.TorsionalContactWarning)  # as the README advises
            exec(compile(block, "README.md", "exec"), namespace)  # noqa: S102 - the README's own code
        if "s" in namespace:  # the quick-start block: its names hold what it says
            s, r, z = namespace["s"], namespace["r"], namespace["z"]
            assert s.stress(r, z)[0].shape == r.shape and s.displacement(r, z).shape == r.shape
            assert len(namespace["states"]) == 4


def test_readme_warning_filter_line_runs():
    line = re.search(r"`(from torsional_contact import ResolutionWarning; warnings\.simplefilter\(.*?\))`", README)
    assert line, "the README shows how to filter one category"
    with warnings.catch_warnings():
        exec(line.group(1), {"warnings": warnings})  # noqa: S102


def test_every_warning_category_is_exported_at_the_top_level():
    named_in_readme = set(re.findall(r"`(\w+Warning)`", README))
    assert {"TorsionalContactWarning", "UnphysicalResultWarning"} <= named_in_readme
    for name in set(diagnostics.__all__) | named_in_readme:
        assert getattr(torsional_contact, name) is getattr(diagnostics, name), name
        assert name in torsional_contact.__all__ and name in dir(torsional_contact)
    namespace: dict = {}
    exec("from torsional_contact import *", namespace)  # noqa: S102
    assert {"TorsionalContactWarning", "UnphysicalResultWarning"} <= set(namespace)


def test_package_docstring_points_to_the_conventions():
    doc = torsional_contact.__doc__
    assert "docs/conventions.md" in doc and (ROOT / "docs" / "conventions.md").is_file()
    assert "README" not in doc or "Conventions and public interface" not in doc  # the section moved


def readme_root_jupyter_command() -> list[str]:
    command = next((line for block in code_blocks(README, "bash") for line in block.splitlines()
                    if "jupyter lab" in line and "--allow-root" in line), None)
    assert command, "the README says how to start JupyterLab as root"
    argv = shlex.split(command)
    assert {"--allow-root", "--no-browser"} <= set(argv) and argv[argv.index("--ip") + 1] == "0.0.0.0"
    return argv


def test_readme_jupyter_command_for_root_in_a_container_starts_a_server(tmp_path):
    argv = readme_root_jupyter_command()
    if not (ROOT / argv[0]).exists():
        pytest.skip(f"{argv[0]} is not installed")
    env = {**os.environ, "HOME": str(tmp_path), "JUPYTER_RUNTIME_DIR": str(tmp_path / "runtime"),
           "JUPYTER_CONFIG_DIR": str(tmp_path / "config")}
    process = subprocess.Popen([str(ROOT / argv[0]), *argv[1:], "--port", "0"], cwd=ROOT, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        address, deadline, log = None, time.monotonic() + 120, []
        while address is None and time.monotonic() < deadline:
            line = process.stdout.readline()
            if not line:
                break
            log.append(line)
            match = re.search(r"(http://127\.0\.0\.1:\d+)/lab\?token=(\w+)", line)
            if match:
                address = match.groups()
        assert address, "".join(log)
        status = None
        while status is None and time.monotonic() < deadline:  # the address is printed before it listens
            try:
                with urllib.request.urlopen(f"{address[0]}/api/status?token={address[1]}", timeout=30) as answer:
                    status = answer.status
            except urllib.error.URLError:
                time.sleep(0.5)
        assert status == 200
    finally:
        process.terminate()
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
    if os.geteuid() == 0:  # and as root the flag is what makes it start
        without = [a for a in argv if a != "--allow-root"]
        run = subprocess.run([str(ROOT / without[0]), *without[1:], "--port", "0"], cwd=ROOT, env=env,
                             capture_output=True, text=True, timeout=120)
        assert run.returncode != 0 and "--allow-root" in run.stdout + run.stderr


def test_readme_names_the_cli_file_rules_where_the_conventions_are():
    conventions = (ROOT / "docs" / "conventions.md").read_text()
    for phrase in ("exit status 2", "one line naming the option and\nthe path", "`null`", "rigid_rotation",
                   "--column N|NAME", "--parents", "/dev/stdout"):
        assert phrase in conventions, phrase
    assert sys.modules["torsional_contact"] is torsional_contact


def test_readme_front_page_is_the_two_commands_then_what_this_is_then_the_two_paths():
    """The first code block is the two commands, exactly; then what this is (with the original paper), the lab
    path and the library path, before any section on methods, workflow or build times; the timings live in
    docs/build_times.md."""
    first = code_blocks(README, "bash")[0].splitlines()
    assert [line.split("#")[0].strip() for line in first] == ["bash workflow/main.sh", "bash workflow/test.sh"]
    order = [README.index(h) for h in ("## What this is", "## The lab path", "## The library path", "## The methods",
                                       "## The workflow")]
    assert order == sorted(order), order
    front = README[:README.index("## The methods")]
    assert "Torsional contact between elastically similar flat-ended cylinders" in front
    assert "benchmark_build" not in front and "| rule |" not in README  # the build's timing tables moved
    assert (ROOT / "docs" / "build_times.md").is_file() and "docs/build_times.md" in front


def test_readme_lists_every_notebook():
    section = README[README.index("## Notebooks"):README.index("## Layout")]
    for notebook in (ROOT / "notebooks").glob("*.py"):
        assert f"{notebook.stem}.html" in section, notebook.stem


def test_readme_examples_read_files_that_ship():
    """Every .csv or .json file an example reads exists in the repository (files the example writes, after
    --output, --states, --residuals or --plot, are not read)."""
    written = ("--output", "--states", "--residuals", "--plot")
    for block in code_blocks(README, "bash") + code_blocks(README, "python"):
        for line in block.splitlines():
            tokens = shlex.split(line.split("  #")[0], posix=True) if "python -m" in line else re.findall(
                r"[\"']([\w./-]+\.(?:csv|json))[\"']", line)
            for k, token in enumerate(tokens):
                if re.fullmatch(r"[\w./-]+\.(csv|json)", token) and not (k and tokens[k - 1] in written):
                    assert (ROOT / token).is_file(), f"{token} (README: {line.strip()[:80]})"
