"""Time a clean build of one configuration and the test suite: wall and CPU seconds, per rule.

    .venv/bin/python workflow/checks/benchmark_build.py                   # config/config.yaml, then the suite
    .venv/bin/python workflow/checks/benchmark_build.py --no-tests --configfile config/test.yaml
    .venv/bin/python workflow/checks/benchmark_build.py --baseline /tmp/old-checkout --repeats 2

What is measured
----------------
* The build: ``snakemake --profile workflow/profiles/default --configfile CONFIG`` (the command
  ``workflow/main.sh`` runs) into a new, empty output folder (``results/.benchmark-build-*``, removed
  afterwards with its Snakemake metadata; the configuration's own ``outdir`` is not touched).  Wall
  time, and CPU time (user + system, from ``os.wait4``: Snakemake and every process it waited for).
* Each job: ``python`` and ``latexmk`` are put on the jobs' PATH behind a small shell wrapper that
  runs the real program and records its wall time and, from bash's ``times``, the CPU time of it and
  its children, keyed by the job's log file (every rule sends its output to its own log); Snakemake's
  metadata (``.snakemake/metadata``) names the rule of each log.  What no job accounts for (the
  scheduler, checksums, ``mkdir``/``cp`` in the shell commands) is listed as "Snakemake itself".
  Nothing in the workflow is changed for the measurement, so an older checkout is measured the
  same way (``--baseline``).
* The test suite: ``bash workflow/test.sh`` (the README's test command: lint and every tier on two
  workers), wall and CPU time, and the summed duration of each test module from pytest's JUnit XML
  (tests of one module may run on both workers at once).  The suite's own build folder
  (``results/ci``) is removed first, as from a fresh clone (the suite's build fixture removes it too).

``--baseline DIR`` measures another checkout of the repository (e.g. ``git archive`` of an older
commit, run with this .venv and ``PYTHONPATH=DIR/src``) interleaved with this one, ``--repeats``
times each; the medians and the ratios baseline/this are reported.

Writes JSON (default: ``<outdir>/timings/build_benchmark.json`` of the measured configuration; the
workflow's ``build_time_table`` rule turns it into the table of Snakemake's report, so run the main
command once more to refresh ``report.html``) and prints the table.  The machine's load average is
recorded before and after each run: the machine may be shared, and CPU seconds are the more robust
figure there.  Caches stay warm between runs (compiled bytecode, matplotlib's font list, TeX's
formats): a fresh clone pays a few seconds more once.
"""

from __future__ import annotations

import argparse
import base64
import binascii
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]
PROFILE = "workflow/profiles/default"

#: The wrapper put in front of python and latexmk on the jobs' PATH (see the module docstring).
#: ``times`` must run in this shell (not in a subshell, whose counters start at zero): its second
#: line is the CPU time of the waited-for children, grandchildren included.
SHIM = """#!/usr/bin/env bash
start=$EPOCHREALTIME
"{real}" "$@"
status=$?
end=$EPOCHREALTIME
record="{records}/$$.$RANDOM.rec"
printf '%s\\n%s\\n%s\\n%s\\n' "{name}" "$(readlink /proc/$$/fd/1)" "$start" "$end" > "$record"
times >> "$record"
exit $status
"""


def _seconds(text: str) -> float:
    """bash ``times`` field (e.g. 1m2.345s) in seconds."""
    minutes, seconds = re.fullmatch(r"(\d+)m([\d.]+)s", text).groups()
    return 60 * int(minutes) + float(seconds)


def make_shims(directory: Path, records: Path, path: str) -> None:
    """Write the timing wrappers of ``python`` and ``latexmk`` (found on ``path``) into ``directory``."""
    directory.mkdir(parents=True, exist_ok=True)
    for name in ("python", "latexmk"):
        real = shutil.which(name, path=path)
        if real is None:
            raise SystemExit(f"benchmark_build: {name} is not on PATH")
        shim = directory / name
        shim.write_text(SHIM.format(real=real, records=records, name=name))
        shim.chmod(0o755)


def read_records(records: Path, checkout: Path) -> list[dict]:
    """One dict per wrapped process: program, log (relative to the checkout), wall and CPU seconds."""
    out = []
    for path in sorted(records.glob("*.rec")):
        lines = path.read_text().splitlines()
        program, log, start, end = lines[:4]
        children = lines[5].split()  # line 5: the shell itself; line 6: its children
        shell = lines[4].split()
        cpu = sum(_seconds(v) for v in children + shell)
        log = os.path.relpath(log, checkout) if log.startswith("/") else log
        out.append({"program": program, "log": log, "start": float(start), "wall_seconds": float(end) - float(start),
                    "cpu_seconds": cpu})
    return out


def rules_of_logs(checkout: Path, since: float) -> dict[str, str]:
    """{log file: rule} from Snakemake's metadata of the jobs that finished after ``since``."""
    mapping = {}
    for path in (checkout / ".snakemake" / "metadata").glob("*"):
        try:
            record = json.loads(path.read_text())
        except (json.JSONDecodeError, UnicodeDecodeError):
            continue
        if (record.get("endtime") or 0) >= since:
            for log in record.get("log") or []:
                mapping[log] = record["rule"]
    return mapping


def timed(command, cwd: Path, env: dict, log: Path) -> tuple[float, float, int]:
    """Run ``command``; (wall seconds, CPU seconds of it and its waited-for descendants, status)."""
    start = time.perf_counter()
    with open(log, "w") as handle:
        process = subprocess.Popen(command, cwd=cwd, env=env, stdout=handle, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
    process.returncode = os.waitstatus_to_exitcode(status)
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime, process.returncode


def environment(checkout: Path) -> dict:
    """The environment of a run in ``checkout``: .venv first on PATH, the checkout's sources first."""
    venv_bin = str(Path(sys.executable).parent)
    env = dict(os.environ, PATH=f"{venv_bin}{os.pathsep}{os.environ['PATH']}")
    # the checkout's own sources, before the editable install (which may be another checkout's)
    env["PYTHONPATH"] = os.pathsep.join([str(checkout / "src"), *filter(None, [os.environ.get("PYTHONPATH")])])
    return env


def output_folder(checkout: Path, configfile: str) -> Path:
    return checkout / yaml.safe_load((checkout / configfile).read_text())["outdir"]


def aggregate(jobs: list[dict]) -> list[dict]:
    """Per rule: jobs, summed wall and CPU seconds, the longest job; sorted by CPU, largest first."""
    rules = {}
    for job in jobs:
        row = rules.setdefault(job["rule"], {"rule": job["rule"], "jobs": 0, "wall_seconds": 0.0, "cpu_seconds": 0.0,
                                             "longest_job_seconds": 0.0})
        row["jobs"] += 1
        row["wall_seconds"] += job["wall_seconds"]
        row["cpu_seconds"] += job["cpu_seconds"]
        row["longest_job_seconds"] = max(row["longest_job_seconds"], job["wall_seconds"])
    return sorted(rules.values(), key=lambda r: -r["cpu_seconds"])


def _forget_metadata(checkout: Path, outdir: str) -> None:
    """Remove Snakemake's metadata of the outputs under ``outdir`` (records named by the base64 path)."""
    for path in (checkout / ".snakemake" / "metadata").glob("*"):
        try:
            name = base64.urlsafe_b64decode(path.name.encode()).decode()
        except (binascii.Error, UnicodeDecodeError, ValueError):
            continue
        if name.startswith(outdir + "/"):
            path.unlink()


def benchmark_build(checkout: Path, configfile: str, scratch: Path) -> dict:
    """One clean build of ``configfile`` in ``checkout`` (see the module docstring)."""
    (checkout / "results").mkdir(exist_ok=True)
    outdir = Path(tempfile.mkdtemp(prefix=".benchmark-build-", dir=checkout / "results"))
    relative = outdir.relative_to(checkout).as_posix()
    records = scratch / "records"
    shutil.rmtree(records, ignore_errors=True)
    records.mkdir(parents=True)
    env = environment(checkout)
    make_shims(scratch / "bin", records, env["PATH"])
    env["PATH"] = f"{scratch / 'bin'}{os.pathsep}{env['PATH']}"
    command = [sys.executable, "-m", "snakemake", "--profile", PROFILE, "--configfile", configfile,
               "--config", f"outdir={relative}"]
    load_before = os.getloadavg()
    since = time.time()
    try:
        wall, cpu, status = timed(command, checkout, env, scratch / "snakemake.log")
        if status != 0:
            tail = "\n".join((scratch / "snakemake.log").read_text(errors="replace").splitlines()[-40:])
            # the scratch folder goes with the exit: the end of Snakemake's log is printed instead
            raise SystemExit(f"{tail}\nbenchmark_build: the build failed (status {status}); the end of Snakemake's "
                             "log is above")
        rules = rules_of_logs(checkout, since)
    finally:
        shutil.rmtree(outdir, ignore_errors=True)
        _forget_metadata(checkout, relative)
    jobs = []
    for record in read_records(records, checkout):
        if record["log"] not in rules:  # e.g. the report's own snakemake --report (inside the report job)
            continue
        jobs.append({**record, "rule": rules[record["log"]], "job": Path(record["log"]).stem})
    jobs.sort(key=lambda j: j["start"])
    for job in jobs:
        job["start"] = round(job["start"] - since, 3)
        job["log"] = job["log"].replace(relative, "<outdir>")
    job_cpu = sum(j["cpu_seconds"] for j in jobs)
    return {
        "configfile": configfile,
        "command": f"snakemake --profile {PROFILE} --configfile {configfile}",
        "wall_seconds": wall,
        "cpu_seconds": cpu,
        "job_cpu_seconds": job_cpu,
        "snakemake_cpu_seconds": cpu - job_cpu,
        "load_average_before": load_before[0],
        "load_average_after": os.getloadavg()[0],
        "rules": aggregate(jobs),
        "jobs": jobs,
    }


def benchmark_tests(checkout: Path, scratch: Path) -> dict:
    """The README's test command in ``checkout``: wall, CPU and the summed time of each test file."""
    scratch.mkdir(parents=True, exist_ok=True)
    shutil.rmtree(checkout / "results" / "ci", ignore_errors=True)  # as from a fresh clone
    junit = scratch / "junit.xml"
    load_before = os.getloadavg()
    wall, cpu, status = timed(["bash", "workflow/test.sh", f"--junitxml={junit}"], checkout, environment(checkout),
                              scratch / "tests.log")
    files, slowest, failed = {}, [], []
    if junit.exists():
        for case in ElementTree.parse(junit).iter("testcase"):
            if case.find("failure") is not None or case.find("error") is not None:
                failed.append(f"{case.get('classname')}::{case.get('name')}")
            slowest.append({"test": f"{case.get('classname')}::{case.get('name')}",
                            "seconds": float(case.get("time") or 0)})
            name = ".".join((case.get("classname") or "?").split(".")[:2])  # tests.test_module[.Class]
            row = files.setdefault(name, {"file": name, "tests": 0, "seconds": 0.0})
            row["tests"] += 1
            row["seconds"] += float(case.get("time") or 0.0)
    if status != 0:  # the scratch folder goes with the run: say what failed here
        tail = "\n".join((scratch / "tests.log").read_text(errors="replace").splitlines()[-30:])
        print(f"{tail}\nbenchmark_build: the test command failed (status {status}): {failed}", file=sys.stderr,
              flush=True)
    return {"command": "bash workflow/test.sh", "status": status, "failed": failed, "wall_seconds": wall,
            "cpu_seconds": cpu,
            "load_average_before": load_before[0], "load_average_after": os.getloadavg()[0],
            "files": sorted(files.values(), key=lambda r: -r["seconds"]),
            "slowest": sorted(slowest, key=lambda r: -r["seconds"])[:15]}


def median_run(runs: list[dict]) -> dict:
    """The run with the median CPU time (its per-rule table is a real run's, not a mixture)."""
    ordered = sorted(runs, key=lambda r: r["cpu_seconds"])
    return {**ordered[(len(ordered) - 1) // 2], "repeats": len(runs),
            "wall_seconds_all": [r["wall_seconds"] for r in runs], "cpu_seconds_all": [r["cpu_seconds"] for r in runs],
            "wall_seconds_median": statistics.median(r["wall_seconds"] for r in runs),
            "cpu_seconds_median": statistics.median(r["cpu_seconds"] for r in runs)}


def table(result: dict) -> str:
    """Plain-text summary of one checkout's measurement."""
    lines = []
    build = result.get("build")
    if build:
        lines.append(f"build of {build['configfile']}: {build['wall_seconds_median']:.0f} s wall, "
                     f"{build['cpu_seconds_median']:.0f} CPU-s (median of {build['repeats']}; "
                     f"load average {build['load_average_before']:.1f} before)")
        lines.append(f"  {'rule':28s} {'jobs':>4s} {'wall s':>8s} {'CPU s':>8s} {'longest':>8s}")
        for row in build["rules"]:
            lines.append(f"  {row['rule']:28s} {row['jobs']:4d} {row['wall_seconds']:8.1f} {row['cpu_seconds']:8.1f} "
                         f"{row['longest_job_seconds']:8.1f}")
        lines.append(f"  {'Snakemake itself':28s} {'':4s} {'':8s} {build['snakemake_cpu_seconds']:8.1f}")
    tests = result.get("tests")
    if tests:
        lines.append(f"tests: {tests['wall_seconds_median']:.0f} s wall, {tests['cpu_seconds_median']:.0f} CPU-s "
                     f"(median of {tests['repeats']}, status {tests['status']})")
        for row in tests["files"][:12]:
            lines.append(f"  {row['file']:40s} {row['tests']:4d} tests {row['seconds']:8.1f} s")
    return "\n".join(lines)


def measure(checkout: Path, a, scratch: Path, kind: str) -> dict:
    if kind == "build":
        return benchmark_build(checkout, a.configfile, scratch)
    return benchmark_tests(checkout, scratch)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--configfile", default="config/config.yaml", help="configuration to build (in the checkout)")
    p.add_argument("--no-build", action="store_true", help="time only the test suite")
    p.add_argument("--no-tests", action="store_true", help="time only the build")
    p.add_argument("--repeats", type=int, default=1, help="runs of each measurement (median reported), >= 1")
    p.add_argument("--baseline", type=Path, help="another checkout, measured interleaved with this one")
    p.add_argument("--json", type=Path, help="output JSON (default: <outdir>/timings/build_benchmark.json)")
    a = p.parse_args(argv)
    if a.repeats < 1:
        p.error(f"--repeats must be >= 1, got {a.repeats}")
    if a.baseline is not None and not (a.baseline / "Snakefile").is_file():
        p.error(f"--baseline must be a checkout of the repository (no Snakefile in {a.baseline})")
    kinds = [k for k, skip in (("build", a.no_build), ("tests", a.no_tests)) if not skip]
    checkouts = {"this": ROOT} | ({"baseline": a.baseline.resolve()} if a.baseline else {})
    runs = {name: {kind: [] for kind in kinds} for name in checkouts}
    with tempfile.TemporaryDirectory(prefix="benchmark_build-") as scratch:
        for _ in range(a.repeats):
            for kind in kinds:
                for name, checkout in reversed(checkouts.items()):  # baseline first, then this checkout
                    runs[name][kind].append(measure(checkout, a, Path(scratch) / name, kind))
                    print(f"{name} {kind}: {runs[name][kind][-1]['wall_seconds']:.0f} s wall, "
                          f"{runs[name][kind][-1]['cpu_seconds']:.0f} CPU-s", flush=True)
    results = {name: {kind: median_run(r) for kind, r in per.items()} for name, per in runs.items()}
    payload = {"this": results["this"], "cores": os.cpu_count()}
    if "baseline" in results:
        payload["baseline"] = results["baseline"]
        payload["baseline_checkout"] = str(a.baseline)
        payload["ratios"] = {f"{kind}_{clock}": results["baseline"][kind][f"{clock}_seconds_median"]
                             / results["this"][kind][f"{clock}_seconds_median"]
                             for kind in kinds for clock in ("wall", "cpu")}
    for name in results:
        print(f"== {name}\n{table(results[name])}")
    if "ratios" in payload:
        print("baseline / this: " + ", ".join(f"{k} {v:.2f}" for k, v in payload["ratios"].items()))
    target = a.json or output_folder(ROOT, a.configfile) / "timings" / "build_benchmark.json"
    sys.path.insert(0, str(ROOT / "src"))
    from torsional_contact.provenance import write_json

    write_json(target, payload, method="workflow/checks/benchmark_build.py: clean build and test suite, wall and CPU "
               "seconds (os.wait4), per job through PATH wrappers of python and latexmk",
               load_note="a shared machine: CPU seconds are the more robust figure")
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
