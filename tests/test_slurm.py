"""The SLURM profile: it parses, a dry run plans every rule, and (opt-in) a real one-node SLURM run.

The real run (workflow/cluster/slurm_single_node.sh) needs root, Debian's SLURM packages (or apt-get
to install them) and the executor plugin; it is skipped unless TORSIONAL_SLURM_TEST=1.  The
comparison of two builds (workflow/cluster/compare_builds.py) is checked here on small files made
for the purpose.
"""

import fnmatch
import importlib.util
import json
import os
import re
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
PROFILE = ROOT / "workflow" / "profiles" / "slurm" / "config.yaml"
SCRIPT = ROOT / "workflow" / "cluster" / "slurm_single_node.sh"
RULE_FILES = [ROOT / "Snakefile", *sorted((ROOT / "workflow" / "rules").glob("*.smk"))]
HAS_PLUGIN = importlib.util.find_spec("snakemake_executor_plugin_slurm") is not None


def _load_compare_builds():
    spec = importlib.util.spec_from_file_location("compare_builds", ROOT / "workflow" / "cluster" / "compare_builds.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


compare_builds = _load_compare_builds()


def rule_blocks():
    """{rule name: its text} for every rule of the workflow.

    A rule defined in a loop (``rule:`` with a ``name:`` directive, e.g. one job per group of
    stick radii) is listed under its name pattern, its f-string fields as ``*``
    (``reference_abel_fredholm_*``).
    """
    blocks = {}
    for path in RULE_FILES:
        parts = re.split(r"^[ ]*rule(?: (\w+))?:\n", path.read_text(), flags=re.M)
        for name, text in zip(parts[1::2], parts[2::2], strict=True):
            if name is None:
                directive = re.search(r"^\s+name:\n\s+f?\"([^\"]+)\"", text, re.M)
                assert directive, f"a rule without a name in {path}"
                name = re.sub(r"\{[^}]*\}", "*", directive.group(1))
            blocks[name] = text
    return blocks


def rule_of(job_rule: str, names) -> str:
    """The rule name or loop pattern of ``rule_blocks`` that a planned job's rule belongs to."""
    matches = [name for name in names if fnmatch.fnmatchcase(job_rule, name)]
    assert len(matches) == 1, (job_rule, matches)
    return matches[0]


def test_profile_settings():
    profile = yaml.safe_load(PROFILE.read_text())
    assert profile["executor"] == "slurm"
    assert profile["jobs"] >= 1 and profile["latency-wait"] >= 5
    defaults = profile["default-resources"]
    # cpus_per_task in the defaults would override every rule's `threads` (plugin 2.8.0)
    assert "cpus_per_task" not in defaults
    assert {"runtime", "mem_mb", "slurm_partition"} <= set(defaults)
    # every set-resources entry names a rule of the workflow
    assert set(profile.get("set-resources", {})) <= set(rule_blocks())


def test_every_rule_declares_resources_and_paper_is_local():
    blocks = rule_blocks()
    assert len(blocks) >= 15
    for name, text in blocks.items():
        if name != "all":  # no command: never submitted
            assert re.search(r"^( +)resources:\n\1    runtime=\d+,\n\1    mem_mb=\d+,", text, re.M), name
    localrules = re.search(r"^localrules:\n((?:    \w+,\n)+)", (ROOT / "workflow/rules/paper.smk").read_text(), re.M)
    assert localrules and {"paper", "build_macros"} <= set(re.findall(r"\w+", localrules.group(1)))


@pytest.mark.skipif(not HAS_PLUGIN, reason="snakemake-executor-plugin-slurm not installed (environment-cluster.txt)")
def test_dry_run_with_the_slurm_profile_plans_every_rule(tmp_path):
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
               TORSIONAL_SLURM_PARTITION="probe_partition")
    run = subprocess.run(
        [sys.executable, "-m", "snakemake", "-n", "--forceall", "--profile", "workflow/profiles/slurm",
         "--configfile", "config/test.yaml", "--config", f"outdir={tmp_path}"],
        cwd=ROOT, env=env, capture_output=True, text=True,
    )
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    table = re.search(r"Job stats:\n(.*?)\n\n", out, re.S)
    planned = {row.split()[0] for row in table.group(1).splitlines()[2:] if row.strip()} - {"total"}
    blocks = rule_blocks()
    assert {rule_of(rule, blocks) for rule in planned} == set(blocks)
    resources = re.findall(r"^    resources: (.*)$", out, re.M)
    assert resources and all("slurm_partition=probe_partition" in r for r in resources)  # from the env var
    assert not any("cpus_per_task" in r for r in resources)


def _write(path: Path, data):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data if isinstance(data, bytes) else data.encode())


def test_compare_builds_verdicts(tmp_path):
    a, b = tmp_path / "local", tmp_path / "slurm"
    def pdf(date, doc_id, content="1 2 l"):
        return (f"%PDF-1.4\n1 0 obj << /Producer (x) /CreationDate (D:{date}) /ModDate (D:{date}) >> endobj\n"
                f"stream {content} endstream\ntrailer << /ID [<{doc_id}><{doc_id}>] >>\n")

    _write(a / "figures/f.pdf", pdf("20260101", "AB12"))
    _write(b / "figures/f.pdf", pdf("20260202", "CD34"))
    _write(a / "figures/g.pdf", pdf("20260101", "AB12"))
    _write(b / "figures/g.pdf", pdf("20260101", "AB12", content="1 3 l"))
    _write(a / "data/t.json", json.dumps({"torque": 1.25, "metadata": {"seconds": 3.1}, "plot_seconds": [1]}))
    _write(b / "data/t.json", json.dumps({"torque": 1.25, "metadata": {"seconds": 9.7}, "plot_seconds": [2]}))
    _write(a / "data/u.json", json.dumps({"torque": 1.25, "seconds": 1}))
    _write(b / "data/u.json", json.dumps({"torque": 1.2500001, "seconds": 1}))
    markdown = "# E\n| 1 | ok |\n## Runs (seconds per stage)\n| {t} |\n## Next\nsame\nTotal run time {t} s\n"
    _write(a / "errata/e.md", markdown.format(t=0.1))
    _write(b / "errata/e.md", markdown.format(t=0.7))
    _write(a / "macros/benchmark.tex", "1.0 ms")
    _write(b / "macros/benchmark.tex", "2.0 ms")
    _write(a / "tables/same.tex", "x")
    _write(b / "tables/same.tex", "x")
    _write(a / "timings/abel_fredholm/b0.3.txt", "1.0 s")  # a whole folder of timings
    _write(b / "timings/abel_fredholm/b0.3.txt", "2.0 s")
    _write(a / "macros/reference_timing.tex", "1 s")
    _write(b / "macros/reference_timing.tex", "2 s")
    _write(a / "notebooks/n.ipynb", '{"id": "cell-000", "text": "<Legend at 0x7f01>"}')  # no normalisation
    _write(b / "notebooks/n.ipynb", '{"id": "cell-000", "text": "<Legend at 0x7f02>"}')
    _write(a / "paper/build/ms.log", "a")  # excluded
    _write(a / "logs/x.txt", "a")  # excluded
    _write(b / "only.csv", "1")
    verdicts = dict(compare_builds.compare_builds(a, b))
    assert verdicts == {
        "figures/f.pdf": "identical-normalised",
        "figures/g.pdf": "DIFFERS",
        "data/t.json": "identical-normalised",
        "data/u.json": "DIFFERS",
        "errata/e.md": "identical-normalised",
        "macros/benchmark.tex": "timing-differs",
        "timings/abel_fredholm/b0.3.txt": "timing-differs",
        "macros/reference_timing.tex": "timing-differs",
        "notebooks/n.ipynb": "DIFFERS",
        "tables/same.tex": "identical",
        "only.csv": "ONLY-IN-slurm",
    }
    assert compare_builds.main([str(a), str(b), "--report", str(tmp_path / "r.txt")]) == 1
    assert "; 4 deterministic outputs differ" in (tmp_path / "r.txt").read_text().splitlines()[-1]
    for name in ("figures/g.pdf", "data/u.json", "only.csv", "notebooks/n.ipynb"):
        (b / name).unlink()
        (a / name).unlink(missing_ok=True)
    assert compare_builds.main([str(a), str(b)]) == 0


def test_compare_builds_rejects_a_missing_folder(tmp_path, capsys):
    assert compare_builds.main([str(tmp_path / "nope"), str(tmp_path)]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and "nope" in captured.err


def _slurm_can_start():
    if os.environ.get("TORSIONAL_SLURM_TEST") != "1":
        return "set TORSIONAL_SLURM_TEST=1 to start a one-node SLURM cluster"
    if not HAS_PLUGIN:
        return "snakemake-executor-plugin-slurm not installed (environment-cluster.txt)"
    if os.geteuid() != 0:
        return "needs root (installs packages, starts munged, slurmctld, slurmd)"
    if not (shutil.which("slurmctld") or shutil.which("apt-get")):
        return "SLURM not installed and no apt-get"
    return None


@pytest.mark.cluster
@pytest.mark.slow
@pytest.mark.xdist_group("workflow")  # after, not beside, the other builds in this checkout
@pytest.mark.skipif(_slurm_can_start() is not None, reason=str(_slurm_can_start()))
def test_single_node_slurm_run_matches_the_local_build():
    env = dict(os.environ, VENV=sys.prefix, CHECK_DIR="results/slurm-check")
    proc = subprocess.Popen(["bash", str(SCRIPT)], cwd=ROOT, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=3600)
    except subprocess.TimeoutExpired:
        os.kill(proc.pid, signal.SIGTERM)  # the script's trap stops the daemons it started
        out, _ = proc.communicate(timeout=120)
        pytest.fail(f"single-node SLURM check timed out:\n{out[-3000:]}")
    assert proc.returncode == 0, out[-5000:]
    summary = (ROOT / "results" / "slurm-check" / "summary.txt").read_text()
    assert "failed checks: 0" in summary and " 0 deterministic outputs differ" in summary
    jobs = (ROOT / "results" / "slurm-check" / "jobs.txt").read_text().splitlines()
    assert len(jobs) >= 15 and all(line.split("|")[2] == "COMPLETED" for line in jobs)
