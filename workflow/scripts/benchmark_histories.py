"""Speed of the torque-history tools: long signals through the CLI, turning points through the API,
and ``solve(torque=...)`` in a fresh process.

Every timing is the median of ``--repeats`` runs (spread: min and max), the runs of the
different cases interleaved; each case is also given relative to a baseline measured in the
same run: the bare start of the interpreter with the package imported (CLI cases), and the
complete weak form at N = 145, the former default, on a few turning points (API case).
Signals: 10^6 samples of 1000 cycles of a sine of amplitude 1.25, and a reflected random walk
with ~10^4 reversals (seeded).  Units: seconds (s) or milliseconds (ms), wall time.
"""

from __future__ import annotations

import argparse
import importlib
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

from torsional_contact.provenance import write_json, write_macros

SOLVE_FIRST = (
    "import time\n"
    "from torsional_contact import solve\n"
    "import torsional_contact.solution\n"
    "t = time.perf_counter(); solve(torque={t}); first = time.perf_counter() - t\n"
    "t = time.perf_counter(); solve(torque={t2}); second = time.perf_counter() - t\n"
    "print(first, second)\n"
)


def signals(samples: int, cycles: int, seed: int) -> dict:
    t = np.arange(samples)
    sine = 1.25 * np.sin(2 * np.pi * cycles * t / samples)
    rng = np.random.default_rng(seed)
    direction = np.where(np.cumsum(rng.random(samples) < 0.01) % 2 == 0, 1.0, -1.0)
    walk = np.cumsum(rng.uniform(0.0, 0.004, samples) * direction)
    walk = np.abs((walk + 1.3) % 5.2 - 2.6) - 1.3  # reflected into [-1.3, 1.3]
    return {"sine": sine, "walk": walk}


def run(argv, env) -> float:
    start = time.perf_counter()
    subprocess.run(argv, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def summary(values) -> dict:
    return {"median": statistics.median(values), "min": min(values), "max": max(values), "runs": list(values)}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--samples", type=int, default=1_000_000)
    p.add_argument("--cycles", type=int, default=1000)
    p.add_argument("--turning-points", type=int, default=1000)
    p.add_argument("--baseline-points", type=int, default=10, help="turning points of the weak-form baseline")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--json", required=True)
    p.add_argument("--macros")
    a = p.parse_args()
    from torsional_contact import histories as H

    env = {**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)}
    py = [sys.executable]
    data = signals(a.samples, a.cycles, a.seed)
    reversals = {k: int(H.turning_point_indices(v).size) for k, v in data.items()}
    times: dict[str, list] = {}
    with tempfile.TemporaryDirectory() as tmp:
        files = {}
        for name, values in data.items():
            files[name] = os.path.join(tmp, f"{name}.txt")
            np.savetxt(files[name], values, fmt="%.17g")
        output = os.path.join(tmp, "out.csv")
        cases = {"startup": py + ["-c", "import torsional_contact.io.cli"]}
        for name, path in files.items():
            cli = py + ["-m", "torsional_contact", "history", "--signal", path, "--no-progress"]
            cases[f"{name}_states"] = cli + ["--json"]
            cases[f"{name}_per_sample"] = cli + ["--json", "--output", output]
        rng = np.random.default_rng(a.seed + 1)
        torques = rng.uniform(-1.3, 1.3, a.turning_points)
        for _ in range(a.repeats):  # interleaved
            for case, argv in cases.items():
                times.setdefault(case, []).append(run(argv, env))
            t = time.perf_counter()
            H.history(torques)
            times.setdefault("api_history", []).append(time.perf_counter() - t)
            t = time.perf_counter()
            H.analyse_signal(torques)
            times.setdefault("api_analyse", []).append(time.perf_counter() - t)
            out = subprocess.run(py + ["-c", SOLVE_FIRST.format(t=1.23, t2=1.25)], check=True, env=env,
                                 capture_output=True, text=True).stdout.split()
            times.setdefault("solve_first_ms", []).append(1e3 * float(out[0]))
            times.setdefault("solve_second_ms", []).append(1e3 * float(out[1]))
        baseline = []
        for _ in range(max(1, a.repeats // 2)):
            t = time.perf_counter()
            H.history(torques[: a.baseline_points], method="complete", n_terms=145)
            baseline.append((time.perf_counter() - t) / a.baseline_points)
            M = importlib.import_module("torsional_contact.histories.monotonic")
            M._SOLUTIONS.clear()  # noqa: SLF001 - a cold cache for every baseline run
            M._series_point.cache_clear()  # noqa: SLF001
    result = {name: summary(v) for name, v in times.items()}
    result["baseline_weak_form_per_point"] = summary(baseline)
    startup = result["startup"]["median"]
    ratios = {case: result[case]["median"] / startup for case in result if case.endswith(("states", "per_sample"))}
    per_point = result["api_history"]["median"] / a.turning_points
    payload = {
        "timings": result,
        "ratios_to_startup": ratios,
        "api_speedup_per_turning_point": result["baseline_weak_form_per_point"]["median"] / per_point,
        "reversals": reversals,
        "samples": a.samples,
        "turning_points_api": a.turning_points,
        "targets": {"cli_states_s": 5.0, "cli_per_sample_s": 10.0, "api_1000_s": 0.5, "solve_first_ms": 20.0},
        "load_average": os.getloadavg(),
    }
    write_json(a.json, payload, repeats=a.repeats, cpu=os.cpu_count())
    if a.macros:
        m = {case: result[case]["median"] for case in result}
        write_macros(a.macros, {
            "bench-hist-samples": f"{a.samples:,}".replace(",", "\\,"),
            "bench-hist-walk-reversals": f"{reversals['walk']:,}".replace(",", "\\,"),
            "bench-hist-sine-s": f"{m['sine_states']:.1f}",
            "bench-hist-walk-s": f"{m['walk_states']:.1f}",
            "bench-hist-sine-output-s": f"{m['sine_per_sample']:.1f}",
            "bench-hist-walk-output-s": f"{m['walk_per_sample']:.1f}",
            "bench-hist-startup-s": f"{startup:.2f}",
            "bench-hist-api-s": f"{m['api_history']:.2f}",
            "bench-hist-api-points": a.turning_points,
            "bench-hist-api-speedup": f"{payload['api_speedup_per_turning_point']:.0f}",
            "bench-hist-solve-first-ms": f"{m['solve_first_ms']:.0f}",
            "bench-hist-solve-second-ms": f"{m['solve_second_ms']:.1f}",
        }, "workflow/scripts/benchmark_histories.py")


if __name__ == "__main__":
    main()
