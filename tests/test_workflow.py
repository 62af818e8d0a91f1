"""The Snakemake workflow end to end on the small test configuration (manuscript included).

Also: the DAG of the default configuration (dry run), a no-op second run, that deleting outputs
rebuilds exactly them and what depends on them, that editing a library module reruns exactly
the rules whose scripts import it, that the configuration schema rejects bad values, the executed
notebooks and Snakemake's report.  The build is clean and survives a hard kill: it is killed (SIGKILL)
as soon as its first job runs, which leaves a lock that ``--unlock`` clears, and restarted.  That a
second clean build gives byte-identical non-timing outputs is checked by the ``rebuild`` tier, which
CI runs once after the README's test command (``.ci/run``): it costs a whole second build.
"""

import importlib.util
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml
from tolerances import assert_within

ROOT = Path(__file__).resolve().parents[1]
TEST_CONFIG = "config/test.yaml"
OUT = ROOT / "results" / "ci"

pytestmark = [
    pytest.mark.skipif(shutil.which("latexmk") is None, reason="needs latexmk (workflow/ensure_tex.sh)"),
    pytest.mark.slow,
    pytest.mark.xdist_group("workflow"),  # one worker: the builds share results/ci and .snakemake
]

def _load_compare_builds():
    """workflow/cluster/compare_builds.py: the one definition of which outputs may differ between runs."""
    path = ROOT / "workflow" / "cluster" / "compare_builds.py"
    spec = importlib.util.spec_from_file_location("compare_builds", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


compare_builds = _load_compare_builds()


def snakemake(*args, check=True, config=TEST_CONFIG):
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    command = [sys.executable, "-m", "snakemake", "--profile", "workflow/profiles/default"]
    command += ["--configfile", config] if config else []
    command += list(args)
    run = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError(f"snakemake {' '.join(args)} failed:\n{run.stdout[-3000:]}\n{run.stderr[-3000:]}")
    return run


def planned_rules(run):
    """Rule names of a dry run's job table."""
    table = re.search(r"Job stats:\n(.*?)\n\n", run.stdout + run.stderr, re.S)
    if table is None:
        return set()
    rows = [line.split() for line in table.group(1).splitlines()[2:]]
    return {row[0] for row in rows if row and row[0] not in ("total", "job")}


@pytest.fixture(scope="module")
def interrupted_build():
    """A clean build of the test configuration, hard-killed (SIGKILL) as soon as its first job runs, then run
    again (which must stop at the lock and name ``--unlock``), unlocked and completed: (output folder, the run
    that met the lock)."""
    shutil.rmtree(OUT, ignore_errors=True)
    _hard_kill_once_a_job_runs(OUT)
    locked = snakemake(check=False)  # a dry run does not take the lock: try a real one
    snakemake("--unlock")
    snakemake()
    # a job killed between writing its temporary file and renaming it leaves the temporary file
    # (provenance.atomic_path, the manuscript's copy); no rule reads it
    for leftover in [p for p in OUT.rglob("*") if p.name.startswith(".tmp-") or p.name.endswith(".tmp")]:
        leftover.unlink()
    return OUT, locked


@pytest.fixture(scope="module")
def built(interrupted_build):
    return interrupted_build[0]


@pytest.fixture(scope="module")
def dry_run_when_built(built):
    """The output of one dry run of the test configuration right after the build (a Snakemake start costs about
    2 CPU-s; several tests read it)."""
    run = snakemake("-n")
    return run.stdout + run.stderr


def test_workflow_tests_run_on_one_worker(request):
    """Under ``--dist loadgroup`` every test here carries the group suffix, so one worker runs them
    all, one after the other (two builds at once would collide on Snakemake's lock).  pytest-xdist
    3.8 sets that suffix through a pytest-internal attribute that pytest 9 no longer reads: hence
    the pytest pin in environment.txt, and this test."""
    if getattr(request.config.option, "loadgroup", False):
        assert request.node.nodeid.endswith("@workflow"), request.node.nodeid


def test_default_configuration_dag_dry_run():
    rules = planned_rules(snakemake("-n", "--forceall", config=None))
    assert {"paper", "supplement", "companion", "response", "report", "notebook", "fig2_contours", "fig3_torque_curve",
            "fig4_interface", "fig5_cyclic",
            "torque_table", "errata", "reference_weak_form", "precision_crosscheck"} <= rules


def test_end_to_end_builds_every_deliverable(built):
    pdf = built / "paper" / "ms.pdf"
    assert pdf.stat().st_size > 50_000
    assert (built / "paper" / "companion.pdf").stat().st_size > 50_000
    for name in ("fig2_sigma_zt", "fig3_torque_curve", "fig4_slip", "fig5_cyclic", "hysteresis", "von_mises"):
        assert (built / "figures" / f"{name}.pdf").exists() and (built / "figures" / f"{name}.png").exists()
    for log in (built / "paper" / "build" / "ms.log", built / "paper" / "build-companion" / "companion.log"):
        text = log.read_text(errors="replace")
        assert "undefined result" not in text and "There were undefined references" not in text, log
    # no absolute path of this machine inside the outputs
    papers = (built / "paper").glob("*.pdf")
    for path in (*papers, *(built / "figures").glob("*.pdf"), *(built / "notebooks").glob("*")):
        assert str(ROOT).encode() not in path.read_bytes(), path
    for name in ("errata", "torque_table", "paper", "fig3_torque_curve"):
        assert (built / "logs" / f"{name}.log").exists()


def test_the_fit_study_writes_its_data_table_macros_and_figure(built):
    """The rig-defect study of the test configuration: every output, the CSV's metadata, both handling modes run
    (the fit has the switches), an inverted channel refused, a misspecified contact named by the model check with the
    handling on, the running-in record fitted per cycle, the 10^5-sample scenario left out (0 replicates)."""
    import json

    data = json.loads((built / "data" / "fit_study.json").read_text())
    rows = {(r["scenario"], r["mode"]): r for r in data["scenarios"]}
    names = ("offset", "inverted", "running-in", "model-hertz", "model-flat-punch")
    assert set(rows) == {(name, mode) for name in names for mode in ("on", "off")}
    assert all(r["summary"]["records"] == data["metadata"]["replicates"] for r in rows.values())
    assert rows["inverted", "on"]["summary"]["refused"]["count"] == data["metadata"]["replicates"]
    assert rows["model-hertz", "on"]["summary"]["named"]["count"] == data["metadata"]["replicates"]
    per_cycle = data["per_cycle"]
    assert per_cycle["scenario"] == "running-in" and per_cycle["cycles"] == 3 * data["metadata"]["replicates"]
    assert "res@fs-pc-range-cov" in (built / "macros" / "fit_study.tex").read_text()
    assert data["metadata"]["packages"]["numpy"] and len(data["window"]) == 2
    text = (built / "data" / "fit_study.csv").read_text()
    assert text.startswith("# method: ") and "# packages: " in text
    assert "Clopper" in (built / "tables" / "fit_study.tex").read_text()
    assert "res@fs-replicates" in (built / "macros" / "fit_study.tex").read_text()
    for suffix in ("pdf", "png"):
        assert (built / "figures" / f"fit_study.{suffix}").stat().st_size > 10_000


def test_the_papers_and_supplement_embed_every_font_as_an_outline_font(built):
    """No font of the PDFs is a Type 3 bitmap (TeX's pk fonts, e.g. the text companion's \\textmu or \\S where
    cm-super is missing: blurred glyphs, refused by journals) and every font is embedded (read with PyMuPDF, a
    pinned package: no poppler needed)."""
    pymupdf = pytest.importorskip("pymupdf")
    for name in ("ms", "supplement", "companion"):
        with pymupdf.open(built / "paper" / f"{name}.pdf") as document:
            fonts = {font[:4] for page in document for font in page.get_fonts(full=True)}  # xref, ext, type, name
        assert fonts, name
        assert not [font for font in fonts if font[2] == "Type3"], (name, fonts)
        assert not [font for font in fonts if font[1] == "n/a"], (name, fonts)  # n/a: not embedded


def test_every_text_of_the_papers_prints_at_seven_points_or_more(built):
    """Figures are drawn at the width they are included: every label, tick, legend and caption of the papers and
    the supplement prints at 7 pt or more (scripts next to full-size text at 70 % of it; tests/pdf_fonts.py)."""
    pytest.importorskip("pymupdf")
    from pdf_fonts import too_small

    for name in ("ms", "supplement", "companion"):
        offenders = too_small(built / "paper" / f"{name}.pdf")
        assert not offenders, f"{name}.pdf: " + "; ".join(
            f"p. {s.page} {s.size:.2f} pt {s.font} {s.text!r}" for s in offenders[:20])


def test_a_clean_build_survives_a_hard_kill(interrupted_build, dry_run_when_built):
    """The build killed while its first jobs ran left a lock: the next run stopped and named ``--unlock``; after
    it the restart completed (the interrupted jobs rebuilt) and a further run does nothing."""
    out, locked = interrupted_build
    assert locked.returncode != 0 and "--unlock" in locked.stdout + locked.stderr
    assert len(compare_builds.output_files(out)) > 40
    assert "Nothing to be done" in dry_run_when_built


def test_the_ladder_reuses_the_cross_checks_converged_weak_forms(built):
    """The test configuration's cross-check converges at the ladder's largest N: the ladder's rows there are the
    cross-check's numbers, bit for bit (not factorised again), and a fresh solve in this process (perhaps with
    other BLAS threads) agrees to rounding: two solves of the system differ by about twice the relative rounding
    EPS / rcond of one (the bound the cross-check records); ten times that."""
    import json

    from torsional_contact.verification import crosscheck

    shared = json.loads((built / "verification" / "weak_forms_converged.json").read_text())
    ladder = json.loads((built / "verification" / "precision_ladder.json").read_text())
    n = shared["n_terms"]
    radii = {s["stick_radius"] for s in shared["weak_forms"]}  # the weak-form references' (the ladder may have more)
    rows = [r for r in ladder["weak_forms"] if r["n_terms"] == n and r["stick_radius"] in radii]
    assert rows
    for row in rows:
        entry = next(s for s in shared["weak_forms"] if s["stick_radius"] == row["stick_radius"])
        assert row["torque"] == entry[f"{row['method']}_torque"]
        fresh = crosscheck.weak_forms_at(row["stick_radius"], n)
        assert_within(abs(fresh[row["method"]][0] - row["torque"]), 10 * entry["rounding_bound"] * abs(row["torque"]),
                      "a second factorisation: ten times the solve's rounding")


def test_the_papers_cite_every_reference_and_resolve_every_label(built):
    """The paper, its supplement and the companion paper share references.bib: every entry is cited by one of
    them, and none of them leaves a reference, a citation or a generated number undefined, or a box overfull."""
    cited = set()
    for build, name in (("build", "ms"), ("build-supplement", "supplement"), ("build-companion", "companion")):
        log = (built / "paper" / build / f"{name}.log").read_text(errors="replace")
        assert not re.search(r"(Reference|Citation) `[^']*' .*undefined", log), f"{name}: undefined reference"
        assert "There were undefined" not in log and "undefined result" not in log, name
        # nothing sticks out into the margin (a figure drawn wider than the text once did by 25 pt)
        assert not re.findall(r"Overfull \\[hv]box \(.*", log), f"{name}: {re.findall(r'Overfull .*', log)}"
        for keys in re.findall(r"\\citation\{([^}]*)\}", (built / "paper" / build / f"{name}.aux").read_text()):
            cited.update(k.strip() for k in keys.split(","))
    entries = set(re.findall(r"^@\w+\{([^,]+),", (ROOT / "paper" / "references.bib").read_text(), re.M))
    assert entries - cited == set(), f"uncited bibliography entries: {sorted(entries - cited)}"
    assert cited - entries == set(), f"citations without an entry: {sorted(cited - entries)}"


def test_numbers_in_the_manuscript_are_typeset_not_programmer_notation(built):
    offenders = []
    for macros in (built / "macros").glob("*.tex"):
        for line in macros.read_text().splitlines():
            if not line.startswith("%") and re.search(r"\d[eE][+-]?\d", line):
                offenders.append(f"{macros.name}: {line}")
    assert not offenders, offenders


def _cells_outside_math(text: str):
    """Table cells (split at & and \\\\) with a \\times or a superscript outside $...$."""
    for cell in re.split(r"&|\\\\", text):
        outside = re.sub(r"\$[^$]*\$", "", cell)
        if "\\times" in outside or "^{" in outside:
            yield cell.strip()


def test_table_numbers_in_scientific_notation_are_in_math_mode(built):
    offenders = [f"{table.name}: {cell}" for table in (built / "tables").glob("*.tex")
                 for cell in _cells_outside_math(table.read_text())]
    # and no programmer notation (2.8e+02) anywhere in a table
    offenders += [f"{table.name}: {line}" for table in (built / "tables").glob("*.tex")
                  for line in table.read_text().splitlines()
                  if not line.startswith("%") and re.search(r"\d[eE][+-]?\d", line)]
    assert not offenders, offenders


def test_half_space_table_entries_are_in_math_mode():
    """Every magnitude the half-space table prints, scientific notation included (a small value at the default
    configuration once stopped LaTeX with 'Missing $ inserted')."""
    spec = importlib.util.spec_from_file_location("half_space_table", ROOT / "workflow/scripts/half_space_table.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for value in (5.436e-3, 0.0359, 3.691, 2.5e4, -1e-7):
        assert not list(_cells_outside_math(module._num(value))), module._num(value)
    assert not list(_cells_outside_math("$5.4\\times10^{-3}$")) and list(_cells_outside_math("5.4\\times10^{-3}"))


def test_notebooks_are_executed_with_figures_inline_and_the_report_lists_the_figures(built):
    nbformat = pytest.importorskip("nbformat")
    for notebook in (ROOT / "notebooks").glob("*.py"):
        executed = nbformat.read(built / "notebooks" / f"{notebook.stem}.ipynb", as_version=4)
        outputs = [o for c in executed.cells if c.cell_type == "code" for o in c.outputs]
        assert not any(o.output_type == "error" for o in outputs)
        assert (built / "notebooks" / f"{notebook.stem}.html").stat().st_size > 10_000
    explore = nbformat.read(built / "notebooks" / "explore_solutions.ipynb", as_version=4)
    assert any("image/png" in o.get("data", {}) for c in explore.cells if c.cell_type == "code" for o in c.outputs)
    report = (built / "report.html").read_text(errors="replace")
    for name in ("fig2_sigma_zt.png", "fig3_torque_curve.png", "fig5_cyclic.png", "explore_solutions.html"):
        assert name in report


def test_second_run_does_nothing(dry_run_when_built):
    assert "Nothing to be done" in dry_run_when_built


def test_valid_configuration_validates_without_schema_warnings(dry_run_when_built):
    assert "may not be validated correctly" not in dry_run_when_built


#: A figure (shown by the report only), a verification table (read by the manuscript) and a data file (drawn by a
#: figure, read by a notebook): cheap rules, each with a different fan-out.
DELETED = ("figures/fig5_cyclic.png", "tables/errata_table.tex", "data/torque_curve.csv")


@pytest.fixture(scope="module")
def rebuilt_after_deleting(built):
    """``DELETED`` removed and the build run again: (the rules the dry run before it planned, the manuscript's PDF
    before and after, the output of a dry run after it)."""
    pdf = built / "paper" / "ms.pdf"
    before = pdf.read_bytes()
    for rel in DELETED:
        (built / rel).unlink()
    planned = planned_rules(snakemake("-n"))
    snakemake()
    after = snakemake("-n")
    return planned, before, pdf.read_bytes(), after.stdout + after.stderr


def test_deleting_outputs_rebuilds_exactly_them_and_their_dependants(built, rebuilt_after_deleting):
    planned, _, _, dry_run_after = rebuilt_after_deleting
    assert planned == {"fig5_cyclic", "errata_tables", "torque_curve", "fig3_torque_curve", "paper", "supplement",
                       "response", "notebook", "report", "all"}, planned
    assert all((built / rel).exists() for rel in DELETED)
    assert "Nothing to be done" in dry_run_after


@pytest.mark.parametrize(
    "module, expected",
    [
        # a verification module: only verification rules, their tables, the manuscript, its supplement,
        # notebook and report
        ("src/torsional_contact/verification/errata/appendix_a.py",
         {"errata", "errata_tables", "paper_tables", "paper", "supplement", "response", "notebook", "report", "all"}),
        # the figure helpers: every figure, the manuscript and the report (no data or verification rule)
        ("workflow/scripts/_plotting.py",
         {"fig_schematic", "fig2_contours", "fig3_torque_curve", "fig4_interface", "fig_published_vs_complete",
          "fig_von_mises",
          "fig5_cyclic", "fig_hysteresis", "fig_work_precision", "fig_convergence", "fig_precision_ladder",
          "fig_lab_loops", "fig_lab_regime_map", "fig_lab_fit", "fig_fit_study",
          "fig_half_space_curves", "fig_half_space_energy", "models_comparison",
              "paper", "supplement", "companion", "response", "report", "all"}),
    ],
)
def test_editing_a_module_reruns_exactly_the_rules_that_import_it(built, module, expected):
    path = ROOT / module
    original = path.read_bytes()
    try:  # Snakemake compares checksums of small inputs: the content must change, not only the mtime
        path.write_bytes(original + b"\n# probe: changed by tests/test_workflow.py\n")
        rules = planned_rules(snakemake("-n"))
    finally:
        path.write_bytes(original)
    assert rules == expected, rules


def test_changing_the_style_reruns_only_figures_and_what_shows_them(built):
    style = ROOT / "workflow" / "styles" / "paper.mplstyle"
    original = style.read_bytes()
    try:
        style.write_bytes(original + b"# probe: changed by tests/test_workflow.py\n")
        rules = planned_rules(snakemake("-n"))
    finally:
        style.write_bytes(original)
    shows = ("models_comparison", "paper", "supplement", "companion", "response", "report", "all")
    assert "paper" in rules and all(r.startswith("fig") or r in shows for r in rules), rules


#: Edits of the test configuration that the checks must reject, with what the error must name.
BAD_EDITS = [
    (("n_terms: 60", "n_terms: -3"), "n_terms"),
    (("n_terms: 60", "n_terms: 60.0"), "config.n_terms must be an integer"),
    (("contours: {stick_radius: 0.5", "contours: {stick_raduis: 0.5"), "stick_raduis"),
    (("style: workflow/styles/paper.mplstyle", "style: workflow/styles/missing.mplstyle"), "no such file"),
    (("quantities: [sigma_zt, sigma_rt, u_theta]", "quantities: [sigma_zt]"), "quantities"),
    (("  replicates: 1\n  long_replicates: 0", "  replicates: 0\n  long_replicates: 0"), "replicates"),
    (("defects: {torque_offset: 0.1}", "defects: {torque_ofset: 0.1}"), "torque_ofset"),
]


def _edited_test_config(edit) -> str:
    text = (ROOT / TEST_CONFIG).read_text()
    assert edit[0] in text
    return text.replace(edit[0], edit[1], 1)


@pytest.fixture(scope="module")
def config_checks():
    """workflow/rules/config_checks.py, the checks the Snakefile runs on its configuration."""
    spec = importlib.util.spec_from_file_location("config_checks", ROOT / "workflow" / "rules" / "config_checks.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("edit, message", BAD_EDITS)
def test_config_checks_reject_a_bad_configuration(config_checks, edit, message):
    """In-process, on the function the Snakefile calls (a Snakemake start costs about 2 CPU-s)."""
    from snakemake.exceptions import WorkflowError

    config = yaml.safe_load(_edited_test_config(edit))
    with pytest.raises((WorkflowError, ValueError)) as error:
        config_checks.check(config, ROOT)
    assert message in str(error.value)


def test_config_checks_accept_the_shipped_configurations(config_checks):
    for name in ("config/config.yaml", TEST_CONFIG):
        config_checks.check(yaml.safe_load((ROOT / name).read_text()), ROOT)


@pytest.mark.parametrize("edit, message", [BAD_EDITS[1], BAD_EDITS[4]])
def test_snakemake_stops_at_a_bad_configuration(tmp_path, edit, message):
    """End to end: the Snakefile runs the checks before any rule (an integer written with a decimal point, which
    only the checks beyond JSON Schema catch, and a list the schema itself rejects)."""
    bad = tmp_path / "bad.yaml"
    bad.write_text(_edited_test_config(edit))
    run = snakemake("-n", config=str(bad), check=False)
    assert run.returncode != 0 and message in (run.stdout + run.stderr)


def test_latex_output_is_deterministic(rebuilt_after_deleting):
    """The manuscript built again (one of its tables deleted and made again) is the same PDF, byte for byte: no
    date, ID or path in it, and the table made again is the same."""
    planned, before, after, _ = rebuilt_after_deleting
    assert "paper" in planned and "errata_tables" in planned
    assert after == before


def _hard_kill_once_a_job_runs(out: Path):
    """Start a build, SIGKILL Snakemake and its jobs as soon as the first job has started."""
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    command = [sys.executable, "-m", "snakemake", "--profile", "workflow/profiles/default", "--configfile",
               TEST_CONFIG]
    process = subprocess.Popen(command, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True)
    deadline = time.time() + 120
    while time.time() < deadline and not any((out / "logs").glob("*.log")) and process.poll() is None:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()


#: Outputs of the timing benchmarks (every number in them a time or a ratio of times) and the
#: figure drawn from their times: expected to differ between builds, so the second build takes them
#: from the first instead of timing everything again (compare_builds checks they are timing outputs).
TIMING_ONLY = ("data/benchmark_speed_error.json", "macros/benchmark.tex", "data/benchmark_scenes.json",
               "tables/scenes.tex", "macros/scenes.tex", "data/benchmark_histories.json",
               "macros/benchmark_histories.tex", "figures/work_precision.pdf", "figures/work_precision.png")


@pytest.mark.rebuild
def test_a_second_clean_build_gives_identical_non_timing_outputs(built, tmp_path):
    """A second clean build (the first one interrupted by a hard kill and restarted, the fixture) gives every
    non-timing output byte for byte: no time stamp, random cell id, absolute path or scheduling order leaks into
    an output.  CI runs it once after the README's test command (marker ``rebuild``)."""
    first = tmp_path / "first"
    shutil.copytree(built, first)
    assert len(compare_builds.output_files(first)) > 40
    shutil.rmtree(built)
    for rel in TIMING_ONLY:
        assert compare_builds.is_timing_output(rel), rel
        (built / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(first / rel, built / rel)  # with its time stamp: up to date, not rerun
    snakemake()
    assert "Nothing to be done" in (lambda r: r.stdout + r.stderr)(snakemake("-n"))
    verdicts = compare_builds.compare_builds(first, built)
    # byte for byte: unlike the local/SLURM comparison, no normalisation of non-timing outputs
    failures = [(rel, verdict) for rel, verdict in verdicts
                if verdict != "identical" and not compare_builds.is_timing_output(rel)]
    assert not failures, compare_builds.report(first, built, verdicts)
