"""Speed and memory of the torque-history tools: long signals through the CLI, turning points through the API,
and ``solve(torque=...)`` in a fresh process.

Every figure is the median of ``--repeats`` runs (spread: min and max), the runs of the
different cases interleaved.  Each command-line case is a fresh process, measured by the
operating system (``os.wait4``): wall time, CPU time (user + system, the robust figure on a
shared machine) and peak resident memory (``ru_maxrss``) of the whole process.  Baselines
measured in the same run: the start of the interpreter with the command line imported
(measured inside the fresh process that then times ``solve``, at the end of the import), and
a sine of 1000 cycles (``--cycles``) over the same number of samples (few turning points:
the cost of reading the file and of the per-sample work); the API case against the complete
weak form at N = 145, the former default, on a few turning points.
Signals (text files, one value per line, as labs write them): the sine, and a reflected random
walk whose direction flips with probability ``--walk-reversals`` / ``--samples`` per sample
(seed ``--seed``), i.e. about that many reversals.  The per-sample table of the sine (``--output``,
.npz) is a secondary case, run in max(1, repeats // 2) of the repeats (as the weak-form baseline),
to keep the benchmark's own cost near 15 CPU-s at the default configuration.  Targets for the walk at 10^6 samples and
2 x 10^5 reversals (``history --signal FILE --json``): ``TARGET_CPU_S`` CPU-s, ``TARGET_PEAK_MB`` MB.
Units: seconds (s), milliseconds (ms), megabytes (MB = 10^6 bytes).
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

from torsional_contact.io.signal_files import format_columns
from torsional_contact.provenance import write_json, write_macros

TARGET_CPU_S = 3.0
TARGET_PEAK_MB = 300.0

# a fresh process: the start of the interpreter with the command line imported (wall clock time at the
# end, CPU time and peak memory so far), then the first and second solve(torque=...)
STARTUP_AND_SOLVE = (
    "import resource, time\n"
    "import torsional_contact.io.cli\n"
    "started = time.time(); usage = resource.getrusage(resource.RUSAGE_SELF)\n"
    "from torsional_contact import solve\n"
    "t = time.perf_counter(); solve(torque={t}); first = time.perf_counter() - t\n"
    "t = time.perf_counter(); solve(torque={t2}); second = time.perf_counter() - t\n"
    "print(started, usage.ru_utime + usage.ru_stime, usage.ru_maxrss, first, second)\n"
)


def signals(samples: int, cycles: int, reversals: int, seed: int) -> dict:
    """The sine and the reflected random walk (module docstring)."""
    t = np.arange(samples)
    sine = 1.25 * np.sin(2 * np.pi * cycles * t / samples)
    rng = np.random.default_rng(seed)
    direction = np.where(np.cumsum(rng.random(samples) < reversals / samples) % 2 == 0, 1.0, -1.0)
    walk = np.cumsum(rng.uniform(0.0, 0.004, samples) * direction)
    walk = np.abs((walk + 1.3) % 5.2 - 2.6) - 1.3  # reflected into [-1.3, 1.3]
    return {"sine": sine, "walk": walk}


# Runs argv[2:] and prints, as JSON, its wall time, CPU time (user + system), peak RSS (``ru_maxrss``) and, if
# argv[1] is "keep", its standard output.  A forked child inherits its parent's peak RSS (Linux keeps the
# high-water mark across fork and exec), so each case starts from this small fresh interpreter, not from
# the benchmark process with its signals in memory.
MEASURE = """
import json, os, subprocess, sys, tempfile, time
with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
    start = time.perf_counter()
    process = subprocess.Popen(sys.argv[2:], stdout=out, stderr=err)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    out.seek(0)
    err.seek(0)
    print(json.dumps({"wall_s": wall, "cpu_s": usage.ru_utime + usage.ru_stime, "maxrss": usage.ru_maxrss,
                      "code": process.returncode, "err": err.read().decode(errors="replace")[-2000:],
                      "out": out.read().decode() if sys.argv[1] == "keep" else ""}))
"""


def run(argv, env, keep: bool = False) -> dict:
    """Wall time, CPU time and peak memory (MB) of one fresh process running ``argv`` (``MEASURE``)."""
    launcher = [sys.executable, "-I", "-S", "-c", MEASURE, "keep" if keep else "drop"]  # -I -S: a bare start
    record = json.loads(subprocess.run(launcher + list(argv), env=env, check=True, capture_output=True,
                                       text=True).stdout)
    if record["code"] != 0:
        raise RuntimeError(f"{' '.join(argv)} failed ({record['code']}): {record['err']}")
    scale = 1 if sys.platform == "darwin" else 1024  # ru_maxrss: bytes on macOS, KiB on Linux
    return {"wall_s": record["wall_s"], "cpu_s": record["cpu_s"], "peak_mb": record["maxrss"] * scale / 1e6,
            "out": record["out"]}


def summary(values) -> dict:
    return {"median": statistics.median(values), "min": min(values), "max": max(values), "runs": list(values)}


def model_cases(names, walk, repeats: int, env, tmp) -> dict:
    """Per contact model: CPU-s, wall-s and peak MB of ``history --signal FILE --json --model NAME`` on the walk
    scaled to 0.9 of the model's gross-slip torque (fresh process: the model's interpolants are built inside it),
    and the warm ``solve(torque=...)`` time (median of 200 calls at torques spread over partial slip, after one
    call that builds the interpolants); medians of ``repeats`` interleaved runs, ratios to the cylinders'."""
    from torsional_contact import models

    names = ["cylinder", *[n for n in names if n != "cylinder"]]
    files, runs, solves = {}, {}, {}
    for name in names:
        contact = models.get(name)
        files[name] = os.path.join(tmp, f"walk_{name}.txt")
        with open(files[name], "wb") as handle:
            handle.write(format_columns([0.9 * contact.gross_slip_torque * walk / np.max(np.abs(walk))]))
    for _ in range(repeats):
        for name in names:
            measured = run([sys.executable, "-m", "torsional_contact", "history", "--signal", files[name], "--json",
                            "--no-progress", "--model", name], env)
            del measured["out"]
            runs.setdefault(name, []).append(measured)
            contact = models.get(name)
            torques = contact.gross_slip_torque * np.linspace(0.05, 0.95, 200)
            contact.solve(torque=float(torques[0]))
            elapsed = []
            for t in torques:
                start = time.perf_counter()
                contact.solve(torque=float(t))
                elapsed.append(time.perf_counter() - start)
            solves.setdefault(name, []).append(1e3 * statistics.median(elapsed))
    out = {}
    for name in names:
        cpu = statistics.median(r["cpu_s"] for r in runs[name])
        out[name] = {"walk_signal": {key: summary([r[key] for r in runs[name]]) for key in runs[name][0]},
                     "solve_warm_ms": summary(solves[name]),
                     "walk_cpu_ratio_to_cylinder": cpu / statistics.median(r["cpu_s"] for r in runs["cylinder"]),
                     "solve_ratio_to_cylinder": statistics.median(solves[name]) / statistics.median(solves["cylinder"])}
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--samples", type=int, default=1_000_000)
    p.add_argument("--cycles", type=int, default=1000)
    p.add_argument("--walk-reversals", type=int, default=200_000)
    p.add_argument("--turning-points", type=int, default=1000)
    p.add_argument("--baseline-points", type=int, required=True, help="turning points of the weak-form baseline")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--json", required=True)
    p.add_argument("--macros")
    p.add_argument("--models", nargs="*", required=True,
                   help="also time each contact model (by name; the cylinders are the baseline of the ratios): the "
                        "walk through history --signal --model, scaled to 0.9 of the model's gross-slip torque, in a "
                        "fresh process, and a warm solve(torque=...) in this one (``model_cases``)")
    a = p.parse_args()
    from torsional_contact import histories as H

    env = {**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)}
    py = [sys.executable]
    data = signals(a.samples, a.cycles, a.walk_reversals, a.seed)
    turning = {k: int(H.turning_point_indices(v).size) for k, v in data.items()}
    processes: dict[str, list] = {}
    times: dict[str, list] = {}
    with tempfile.TemporaryDirectory() as tmp:
        files = {}
        for name, values in data.items():
            files[name] = os.path.join(tmp, f"{name}.txt")
            with open(files[name], "wb") as handle:  # 16 significant digits, one value per line
                handle.write(format_columns([values]))
        cases = {}
        for name, path in files.items():
            cases[f"{name}_json"] = py + ["-m", "torsional_contact", "history", "--signal", path, "--json",
                                          "--no-progress"]
        secondary = {"sine_per_sample": cases["sine_json"] + ["--output", os.path.join(tmp, "samples.npz")]}
        rng = np.random.default_rng(a.seed + 1)
        torques = rng.uniform(-1.3, 1.3, a.turning_points)
        for repeat in range(a.repeats):  # interleaved; the secondary cases in the first half of the repeats only
            for case, argv in {**cases, **(secondary if repeat < max(1, a.repeats // 2) else {})}.items():
                measured = run(argv, env)
                del measured["out"]
                processes.setdefault(case, []).append(measured)
            t = time.perf_counter()
            H.history(torques)
            times.setdefault("api_history", []).append(time.perf_counter() - t)
            t = time.perf_counter()
            H.analyse_signal(torques)
            times.setdefault("api_analyse", []).append(time.perf_counter() - t)
            spawned = time.time()
            out = run(py + ["-c", STARTUP_AND_SOLVE.format(t=1.23, t2=1.25)], env, keep=True)["out"].split()
            scale = 1 if sys.platform == "darwin" else 1024
            processes.setdefault("startup", []).append(
                {"wall_s": float(out[0]) - spawned, "cpu_s": float(out[1]), "peak_mb": float(out[2]) * scale / 1e6})
            times.setdefault("solve_first_ms", []).append(1e3 * float(out[3]))
            times.setdefault("solve_second_ms", []).append(1e3 * float(out[4]))
        baseline = []
        for _ in range(max(1, a.repeats // 2)):
            t = time.perf_counter()
            H.history(torques[: a.baseline_points], method="complete", n_terms=145)
            baseline.append((time.perf_counter() - t) / a.baseline_points)
            M = importlib.import_module("torsional_contact.contact_models.cylinder")
            M._SOLUTIONS.clear()  # noqa: SLF001 - a cold cache for every baseline run
            M._series_point.cache_clear()  # noqa: SLF001
        per_model = model_cases(a.models, data["walk"], a.repeats, env, tmp) if a.models else None
    cli = {case: {key: summary([r[key] for r in runs]) for key in runs[0]} for case, runs in processes.items()}
    result = {name: summary(v) for name, v in times.items()}
    result["baseline_weak_form_per_point"] = summary(baseline)
    median = {case: {key: value["median"] for key, value in c.items()} for case, c in cli.items()}
    per_point = result["api_history"]["median"] / a.turning_points
    walk = median["walk_json"]
    payload = {
        "cli": cli,
        "timings": result,
        "ratios_to_sine": {case: {key: median[case][key] / median["sine_json"][key] for key in ("cpu_s", "peak_mb")}
                           for case in median},
        "ratios_to_startup": {case: median[case]["wall_s"] / median["startup"]["wall_s"] for case in median},
        "api_speedup_per_turning_point": result["baseline_weak_form_per_point"]["median"] / per_point,
        "turning_points": turning,
        "samples": a.samples,
        "walk_reversals": a.walk_reversals,
        "seed": a.seed,
        "turning_points_api": a.turning_points,
        "targets": {"walk_json_cpu_s": TARGET_CPU_S, "walk_json_peak_mb": TARGET_PEAK_MB,
                    "applies_to": "10^6 samples, 2 x 10^5 reversals", "api_1000_s": 0.5, "solve_first_ms": 20.0},
        "walk_meets_targets": walk["cpu_s"] <= TARGET_CPU_S and walk["peak_mb"] <= TARGET_PEAK_MB,
        "load_average": os.getloadavg(),
    }
    if per_model is not None:
        payload["models"] = per_model
        for name, entry in per_model.items():
            print(f"model {name}: walk {entry['walk_signal']['cpu_s']['median']:.2f} CPU-s "
                  f"(x{entry['walk_cpu_ratio_to_cylinder']:.2f} of the cylinders), warm solve "
                  f"{entry['solve_warm_ms']['median']:.3f} ms (x{entry['solve_ratio_to_cylinder']:.2f})")
    write_json(a.json, payload, repeats=a.repeats, cpu=os.cpu_count())
    print(f"walk ({turning['walk']} turning points): {walk['cpu_s']:.2f} CPU-s, {walk['peak_mb']:.0f} MB; "
          f"sine: {median['sine_json']['cpu_s']:.2f} CPU-s, {median['sine_json']['peak_mb']:.0f} MB; "
          f"startup: {median['startup']['cpu_s']:.2f} CPU-s")
    if a.macros:
        m = {case: result[case]["median"] for case in result}
        write_macros(a.macros, {
            "bench-hist-samples": f"{a.samples:,}".replace(",", "\\,"),
            "bench-hist-walk-reversals": f"{turning['walk']:,}".replace(",", "\\,"),
            "bench-hist-sine-s": f"{median['sine_json']['wall_s']:.1f}",
            "bench-hist-walk-s": f"{walk['wall_s']:.1f}",
            "bench-hist-sine-output-s": f"{median['sine_per_sample']['wall_s']:.1f}",
            "bench-hist-startup-s": f"{median['startup']['wall_s']:.2f}",
            "bench-hist-sine-cpu-s": f"{median['sine_json']['cpu_s']:.1f}",
            "bench-hist-walk-cpu-s": f"{walk['cpu_s']:.1f}",
            "bench-hist-sine-mb": f"{median['sine_json']['peak_mb']:.0f}",
            "bench-hist-walk-mb": f"{walk['peak_mb']:.0f}",
            "bench-hist-startup-cpu-s": f"{median['startup']['cpu_s']:.2f}",
            "bench-hist-api-s": f"{m['api_history']:.2f}",
            "bench-hist-api-points": a.turning_points,
            "bench-hist-api-speedup": f"{payload['api_speedup_per_turning_point']:.0f}",
            "bench-hist-solve-first-ms": f"{m['solve_first_ms']:.0f}",
            "bench-hist-solve-second-ms": f"{m['solve_second_ms']:.1f}",
        }, "workflow/scripts/benchmark_histories.py")


if __name__ == "__main__":
    main()
