"""Benchmark of the loop fit against a baseline commit, in the same run: CPU seconds and peak memory.

    .venv/bin/python workflow/checks/benchmark_fit.py [--baseline COMMIT] [--sizes 1000 100000] [--repeats 5]
        [--control twist|torque] [--honesty RECORDS]

Each record (``--control twist``: a twist-controlled gross-slip loop of the synthetic rig, ``fitting.synthetic``;
``--control torque``: a torque-controlled partial-slip loop at T* 1.3 and 0.5 Hz of the independent rig generator,
``verification.rig_records``, with its time column; 50 cycles for the long records, two for the short ones, noise
0.5 % of the torque range and 1e-5 rad; made in each fitting process, the same code in both trees) is fitted by
``fit_loop`` of this tree
and of the baseline (a detached ``git worktree`` of COMMIT, default the commit this work started from,
removed afterwards), each fit in a
fresh interpreter whose own CPU time (``time.process_time``, the fit alone) and peak resident memory
(``ru_maxrss``) are measured; the median of ``--repeats`` runs, interleaved (baseline, current, ...)
so that the machine's load falls on both alike, and the ratios current / baseline.  Also reported:
the friction estimate and interval of each, against the truth f = 0.6, and (where the tree reports them) each
estimate's distance from the truth in its own standard errors (``z``: f, G and C) and the fit's warnings.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import statistics
import sys

from baseline import ROOT, baseline_tree, run_child

CHILD = r"""
import json, resource, sys, time, warnings
import numpy as np
warnings.simplefilter("ignore")
from torsional_contact import fit_loop
from torsional_contact.fitting.synthetic import Rig, noisy, twist_controlled
size, seed, control = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
cycles = 2 if size < 10_000 else 50
if control == "twist":
    rig = Rig(radius=0.005, normal_force=1000.0, friction=0.6, shear_modulus=80e9, compliance=4e-4, offset=1e-4)
    torque, twist = twist_controlled(rig, 2.5e-3, cycles=cycles, samples_per_cycle=size // cycles)
    data = noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(seed))
    clock = None
    truth = {"friction": rig.friction, "shear_modulus": rig.shear_modulus, "compliance": rig.compliance}
else:  # the independent rig generator, torque-controlled partial slip at T* 1.3, 0.5 Hz
    from torsional_contact.verification.rig_records import rig_record
    record = rig_record(control="torque", amplitude=1.3, cycles=cycles, frequency=0.5,
                        sample_rate=0.5 * (size - 1) / cycles, rng=seed)
    data, clock = (record.torque, record.twist), record.time
    truth = {name: record.truth[name] for name in ("friction", "shear_modulus", "compliance")}
start = time.process_time()
fit = fit_loop(data[0], data[1], radius=0.005, normal_force=1000.0, time=clock)
cpu = time.process_time() - start
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
# each estimate against the rig's truth in its own standard errors (None: no value or no standard error)
z = {name: None if getattr(fit, name).value is None or not getattr(fit, name).stderr else
     (getattr(fit, name).value - value) / getattr(fit, name).stderr for name, value in truth.items()}
print(json.dumps({"cpu": cpu, "rss_mb": rss, "friction": fit.friction.value,
                  "interval": list(fit.friction.interval), "z": z, "warnings": list(fit.warnings)}))
"""


def _run(src: pathlib.Path, size: int, timeout: float, control: str, seed: int | None = None) -> dict:
    return run_child(src, CHILD, size, size if seed is None else seed, control, timeout=timeout)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", default="c4591fe", help="the commit whose fit is the baseline")
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 100_000])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds per fit at most")
    parser.add_argument("--control", choices=("twist", "torque"), default="twist",
                        help="twist: the synthetic rig's gross-slip loops; torque: the independent rig generator's "
                             "torque-controlled partial-slip loops (T* 1.3), with their time column")
    parser.add_argument("--honesty", type=int, default=0, metavar="RECORDS",
                        help="then fit RECORDS more records of each size (seeds size + 1, ...) with this tree alone "
                             "and report each estimate's distance from the truth in standard errors")
    args = parser.parse_args(argv)
    if args.repeats < 1 or args.honesty < 0 or any(size < 100 for size in args.sizes):
        parser.error("--repeats: at least 1; --honesty: at least 0; --sizes: at least 100 samples each")
    with baseline_tree(args.baseline) as baseline:
        rows = []
        for size in args.sizes:
            runs = {"baseline": [], "current": []}
            repeats = args.repeats if size < 10_000 else max(1, args.repeats // 5)
            for _ in range(repeats):
                runs["baseline"].append(_run(baseline / "src", size, args.timeout, args.control))
                runs["current"].append(_run(ROOT / "src", size, args.timeout, args.control))
            row = {"samples": size, "repeats": repeats}
            for name, results in runs.items():
                row[name] = {"cpu_s": statistics.median(r["cpu"] for r in results),
                             "peak_rss_mb": statistics.median(r["rss_mb"] for r in results),
                             "friction": results[0]["friction"], "interval": results[0]["interval"],
                             "z": results[0].get("z"), "warnings": results[0].get("warnings")}
            row["cpu_ratio"] = row["current"]["cpu_s"] / row["baseline"]["cpu_s"]
            row["rss_ratio"] = row["current"]["peak_rss_mb"] / row["baseline"]["peak_rss_mb"]
            rows.append(row)
            print(json.dumps(row), flush=True)
    for size in args.sizes if args.honesty else []:
        runs = [_run(ROOT / "src", size, args.timeout, args.control, seed=size + k) for k in range(1, args.honesty + 1)]
        worst = {name: max(abs(r["z"][name]) for r in runs if r["z"][name] is not None) for name in runs[0]["z"]
                 if any(r["z"][name] is not None for r in runs)}
        print(json.dumps({"samples": size, "honesty_records": len(runs), "z": [r["z"] for r in runs],
                          "largest_abs_z": worst, "cpu_s": [r["cpu"] for r in runs],
                          "warnings": [r["warnings"] for r in runs]}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
