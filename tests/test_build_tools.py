"""The workflow's build tools: the dependency analysis of the rules, the build benchmark's job timing
and the build-time table of the report.

``workflow/rules/dependencies.py`` visits only statement lists (imports are statements): checked
against a walk over every node of the syntax tree, for every workflow script, notebook and library
module, and on a module that hides imports in nested blocks.  ``workflow/checks/benchmark_build.py``
times each job through a shell wrapper: checked on a real process with a known CPU load.
"""

import ast
import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from tolerances import EPS, assert_close

ROOT = Path(__file__).resolve().parents[1]


def _load(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


dependencies = _load(ROOT / "workflow" / "rules" / "dependencies.py", "dependencies")
benchmark_build = _load(ROOT / "workflow" / "checks" / "benchmark_build.py", "benchmark_build")
build_time_table = _load(ROOT / "workflow" / "scripts" / "build_time_table.py", "build_time_table")
scheduling = _load(ROOT / "workflow" / "rules" / "scheduling.py", "scheduling")


def _all_import_nodes(path):
    """Every Import/ImportFrom node of a file, by a walk over the whole tree (the reference)."""
    return sorted(ast.dump(node) for node in ast.walk(ast.parse(Path(path).read_text()))
                  if isinstance(node, ast.Import | ast.ImportFrom))


def test_statement_walk_finds_every_import_of_every_source(monkeypatch):
    monkeypatch.chdir(ROOT)
    files = sorted([*ROOT.glob("workflow/scripts/*.py"), *ROOT.glob("notebooks/*.py"),
                    *ROOT.glob("src/torsional_contact/**/*.py")])
    assert len(files) > 100
    for path in files:
        found = sorted(ast.dump(node) for node in dependencies._import_statements(ast.parse(path.read_text()).body))
        assert found == _all_import_nodes(path), path


def _sources():
    return sorted([*ROOT.glob("workflow/scripts/*.py"), *ROOT.glob("src/torsional_contact/**/*.py")])


def _as_data(records):
    return [[module, list(names), level] for module, names, level in records]


def test_cached_import_statements_are_those_of_the_text(tmp_path, monkeypatch):
    """The on-disk cache gives each source the statements a fresh parse gives; an edited file is parsed anew."""
    monkeypatch.setattr(dependencies, "CACHE", tmp_path / "cache" / "imports.json")
    first = dependencies._StatementCache()
    fresh = {path: _as_data(dependencies._statement_records(path.read_text())) for path in _sources()}
    assert all(_as_data(first.records(path)) == fresh[path] for path in fresh)
    first.save()
    second = dependencies._StatementCache()  # from the file
    assert not second.changed and all(_as_data(second.records(path)) == fresh[path] for path in fresh)
    assert not second.changed  # nothing parsed: every statement came from the file
    edited = tmp_path / "edited.py"
    edited.write_text("import json\n")
    assert _as_data(second.records(edited)) == [[None, ["json"], 0]]
    edited.write_text("from torsional_contact import fields\n")
    assert _as_data(second.records(edited)) == [["torsional_contact", ["fields"], 0]] and second.changed


def test_a_corrupt_import_cache_is_replaced_with_a_warning(tmp_path, monkeypatch):
    cache = tmp_path / "imports.json"
    cache.write_text("{not json")
    monkeypatch.setattr(dependencies, "CACHE", cache)
    with pytest.warns(UserWarning, match="parsed anew"):
        statements = dependencies._StatementCache()
    script = ROOT / "workflow" / "scripts" / "fig3_torque_curve.py"
    assert _as_data(statements.records(script)) == _as_data(dependencies._statement_records(script.read_text()))
    statements.save()
    assert len(json.loads(cache.read_text())) == 1


def test_imports_in_nested_blocks_are_dependencies(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    script = tmp_path / "nested.py"
    script.write_text(
        "class A:\n"
        "    def f(self, x):\n"
        "        try:\n"
        "            import torsional_contact.fields\n"
        "        except ImportError:\n"
        "            from torsional_contact.histories import memory\n"
        "        finally:\n"
        "            pass\n"
        "        match x:\n"
        "            case 1:\n"
        "                from torsional_contact.typeset import sci\n"
        "        with open(x) as h:\n"
        "            if h:\n"
        "                from torsional_contact import provenance\n"
    )
    files = dependencies.library_files(str(script))
    for module in ("fields.py", "histories/memory.py", "typeset.py", "provenance.py", "__init__.py"):
        assert f"src/torsional_contact/{module}" in files, module
    assert files == dependencies.library_files(str(script))  # cached: the same list, a new copy
    assert files is not dependencies.library_files(str(script))


def test_helper_modules_beside_a_script_are_dependencies(tmp_path, monkeypatch):
    """A workflow script's own helper module (imported by its bare name) and what it imports are dependencies;
    a package module of the same bare name elsewhere is not confused with it."""
    monkeypatch.chdir(ROOT)
    (tmp_path / "_helper.py").write_text("from torsional_contact.typeset import sci\n")
    script = tmp_path / "figure.py"
    script.write_text("import json\nfrom _helper import sci\n")
    files = dependencies.library_files(str(script))
    assert str(tmp_path / "_helper.py") in files and "src/torsional_contact/typeset.py" in files
    figure = dependencies.library_files("workflow/scripts/fig3_torque_curve.py")
    assert "workflow/scripts/_plotting.py" in figure and "src/torsional_contact/provenance.py" in figure
    assert not any("matplotlib" in f for f in figure)


def test_times_fields_and_records(tmp_path):
    # decimal text to seconds: a parse and a product and sum of two numbers, a few roundings of the result
    assert_close(benchmark_build._seconds("0m0.250s"), 0.25, "three roundings", rtol=3 * EPS)
    assert_close(benchmark_build._seconds("2m3.500s"), 123.5, "three roundings", rtol=3 * EPS)
    (tmp_path / "1.rec").write_text("python\n/ck/results/logs/a.log\n100.0\n102.5\n0m0.010s 0m0.002s\n"
                                    "1m1.000s 0m0.500s\n")
    (record,) = benchmark_build.read_records(tmp_path, Path("/ck"))
    assert record["log"] == "results/logs/a.log"
    # differences and sums of four parsed times (up to ~100 s): a few roundings of the largest of them
    assert_close(record["wall_seconds"], 2.5, "roundings of the parsed times", atol=8 * EPS * 102.5)
    assert_close(record["cpu_seconds"], 61.512, "roundings of the parsed times", atol=8 * EPS * 61.512)
    rows = benchmark_build.aggregate([{"rule": "r", "wall_seconds": 1.0, "cpu_seconds": 2.0},
                                      {"rule": "r", "wall_seconds": 3.0, "cpu_seconds": 1.0},
                                      {"rule": "s", "wall_seconds": 9.0, "cpu_seconds": 0.5}])
    assert rows[0] == {"rule": "r", "jobs": 2, "wall_seconds": 4.0, "cpu_seconds": 3.0, "longest_job_seconds": 3.0}
    assert rows[1]["rule"] == "s"


@pytest.mark.skipif(sys.platform != "linux", reason="the wrapper reads /proc/<pid>/fd/1")
def test_job_wrapper_records_the_cpu_time_of_the_job_and_its_log(tmp_path):
    """A job that burns about 0.3 CPU-s in a child process, output sent to its log: the wrapper
    records that log and at least that CPU time (bash's ``times`` counts waited-for children)."""
    records, shims = tmp_path / "records", tmp_path / "bin"
    records.mkdir()
    benchmark_build.make_shims(shims, records, os.environ["PATH"] + os.pathsep + str(Path(sys.executable).parent))
    burn = ("import subprocess, sys, time; subprocess.run([sys.executable, '-c', "
            "'import time\\nt = time.process_time()\\nwhile time.process_time() - t < 0.3: pass'])")
    log = tmp_path / "logs" / "job.log"
    log.parent.mkdir()
    env = dict(os.environ, PATH=f"{shims}{os.pathsep}{os.environ['PATH']}")
    subprocess.run(f'python -c "{burn}" > {log} 2>&1', shell=True, check=True, env=env, cwd=tmp_path)
    (record,) = benchmark_build.read_records(records, tmp_path)
    assert record["log"] == "logs/job.log" and record["program"] == "python"
    assert 0.3 <= record["cpu_seconds"] < 0.3 + 5.0  # plus two interpreter start-ups
    assert record["wall_seconds"] >= 0.3 * 0.5  # a shared machine: wall is not below the CPU of one core


def test_rules_of_logs_from_snakemake_metadata(tmp_path):
    metadata = tmp_path / ".snakemake" / "metadata"
    metadata.mkdir(parents=True)
    (metadata / "a").write_text(json.dumps({"rule": "fig", "log": ["results/logs/fig.log"], "endtime": 20.0}))
    (metadata / "b").write_text(json.dumps({"rule": "old", "log": ["results/logs/old.log"], "endtime": 5.0}))
    (metadata / "c").write_text("not json")
    assert benchmark_build.rules_of_logs(tmp_path, since=10.0) == {"results/logs/fig.log": "fig"}


def test_build_time_table_with_and_without_a_measurement():
    assert "was not timed" in build_time_table.render(None)
    build = {"configfile": "config/test.yaml", "wall_seconds_median": 40.0, "cpu_seconds_median": 70.0,
             "repeats": 1, "load_average_before": 0.5, "snakemake_cpu_seconds": 3.0,
             "rules": [{"rule": "paper", "jobs": 1, "wall_seconds": 2.0, "cpu_seconds": 1.5,
                        "longest_job_seconds": 2.0}]}
    tests = {"wall_seconds_median": 150.0, "cpu_seconds_median": 300.0, "repeats": 1, "status": 0,
             "files": [{"file": "tests", "tests": 10, "seconds": 20.0}]}
    page = build_time_table.render({"cores": 2, "this": {"build": build, "tests": tests},
                                    "baseline": {"build": {**build, "rules": []}}, "baseline_checkout": "/old",
                                    "ratios": {"build_cpu": 2.0}})
    for text in ("40 s wall, 70 CPU-s", "150 s wall, 300 CPU-s", "<td>paper</td>", "baseline", "build_cpu 2.00"):
        assert text in page, text


def test_pending_scheduler_timers_are_cancelled_and_never_fire():
    """``cancel_pending_timers`` (the Snakefile's onsuccess and onerror) stops a pending timer at once: its thread
    ends without running the action, so the process does not wait out the profile's timespan at exit."""
    import threading

    fired = threading.Event()
    timer = threading.Timer(60.0, fired.set)
    timer.start()
    assert scheduling.cancel_pending_timers() >= 1
    timer.join(timeout=5.0)
    assert not timer.is_alive()
    assert not fired.is_set()


def test_the_default_profile_spaces_the_scheduler_timers_and_the_snakefile_cancels_them():
    """The profile's long re-evaluation timespan is only harmless with the cancelling handlers in the Snakefile."""
    import yaml

    profile = yaml.safe_load((ROOT / "workflow" / "profiles" / "default" / "config.yaml").read_text())
    count, timespan = profile["max-jobs-per-timespan"].split("/")
    assert int(count) >= 100 and timespan.endswith("s")
    snakefile = (ROOT / "Snakefile").read_text()
    for handler in ("onsuccess:", "onerror:"):
        assert f"{handler}\n    cancel_pending_timers()" in snakefile
