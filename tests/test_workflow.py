"""The Snakemake workflow end to end on the small test configuration (PDF included).

Also: the DAG of the default configuration (dry run), a no-op second run, that
touching the matplotlib style reruns only figures and the manuscript, and that the
config schema rejects bad values.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TEST_CONFIG = "config/test.yaml"
OUT = ROOT / "results" / "ci"

pytestmark = pytest.mark.skipif(shutil.which("latexmk") is None, reason="needs latexmk (workflow/ensure_tex.sh)")


def snakemake(*args, check=True):
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    run = subprocess.run(
        [sys.executable, "-m", "snakemake", "--cores", "2", "--rerun-incomplete", *args],
        cwd=ROOT, env=env, capture_output=True, text=True,
    )
    if check and run.returncode != 0:
        raise AssertionError(f"snakemake {' '.join(args)} failed:\n{run.stdout[-3000:]}\n{run.stderr[-3000:]}")
    return run


def planned_rules(dry_run_output):
    """Rule names of a dry run's job table."""
    table = re.search(r"Job stats:\n(.*?)\n\n", dry_run_output, re.S)
    if table is None:
        return set()
    rows = [line.split() for line in table.group(1).splitlines()[2:]]
    return {row[0] for row in rows if row and row[0] not in ("total", "job")}


@pytest.fixture(scope="module")
def built():
    snakemake("--configfile", TEST_CONFIG)
    return OUT


def test_default_configuration_dag_dry_run():
    run = snakemake("-n", "--forceall")
    rules = planned_rules(run.stdout + run.stderr)
    assert {"paper", "fig2_contours", "fig3_torque_curve", "fig4_interface", "fig5_cyclic", "torque_table"} <= rules


def test_end_to_end_builds_the_manuscript(built):
    pdf = built / "paper" / "ms.pdf"
    assert pdf.stat().st_size > 50_000
    for name in ("fig2_sigma_zt", "fig3_torque_curve", "fig4_slip", "fig5_cyclic", "hysteresis", "von_mises"):
        assert (built / "figures" / f"{name}.pdf").exists() and (built / "figures" / f"{name}.png").exists()
    log = (built / "paper" / "build" / "ms.log").read_text(errors="replace")
    assert "undefined result" not in log and "There were undefined references" not in log


def test_second_run_does_nothing(built):
    run = snakemake("--configfile", TEST_CONFIG, "-n")
    assert "Nothing to be done" in run.stdout + run.stderr


def test_changing_the_style_reruns_only_figures_and_paper(built):
    # Snakemake compares checksums of small inputs, so the content must change (not the mtime)
    style = ROOT / "workflow" / "styles" / "paper.mplstyle"
    original = style.read_bytes()
    try:
        style.write_bytes(original + b"# probe: changed by tests/test_workflow.py\n")
        run = snakemake("--configfile", TEST_CONFIG, "-n")
        rules = planned_rules(run.stdout + run.stderr)
        assert "paper" in rules and all(r.startswith("fig") or r in ("paper", "all") for r in rules), rules
        assert "torque_table" not in rules and "history_data" not in rules
    finally:
        style.write_bytes(original)


def test_schema_rejects_a_bad_configuration(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text((ROOT / TEST_CONFIG).read_text().replace("n_terms: 60", "n_terms: -3"))
    run = snakemake("--configfile", str(bad), "-n", check=False)
    assert run.returncode != 0 and "n_terms" in (run.stdout + run.stderr)


@pytest.mark.parametrize("notebook", sorted(p.name for p in (ROOT / "notebooks").glob("*.py")))
def test_notebooks_run_on_the_test_results(built, notebook, monkeypatch):
    jupytext = pytest.importorskip("jupytext")
    nbclient = pytest.importorskip("nbclient")
    monkeypatch.setenv("RESULTS_DIR", str(built))
    nb = jupytext.read(ROOT / "notebooks" / notebook)
    client = nbclient.NotebookClient(nb, kernel_name="python3", timeout=300,
                                     resources={"metadata": {"path": str(ROOT / "notebooks")}})
    client.execute()  # raises CellExecutionError on any failing cell
