"""Benchmark of reading a lab's export against a baseline commit, in the same run: CPU seconds.

    .venv/bin/python workflow/checks/benchmark_lab_files.py [--baseline COMMIT] [--rows 1000 100000] [--repeats 5]

The export is what a European rig writes: metadata lines above the header, ``;`` separators, decimal
commas, three columns (time, torque, twist), written once per size by this script (plain Python, through
the library's writer) into a temporary directory and read by ``read_text_table`` plus ``TextTable.column`` of
every column, in this tree and in the baseline (a detached ``git worktree`` of COMMIT, removed
afterwards), each read in a fresh interpreter whose own CPU time (``time.process_time``, the read
alone) is measured; the median of ``--repeats`` runs, interleaved (baseline, current, ...) so that
the machine's load falls on both alike, and the ratio current / baseline.  Both trees must read
the same numbers (checked through a checksum of the columns).
"""

from __future__ import annotations

import argparse
import json
import math
import pathlib
import statistics
import sys
import tempfile

from baseline import ROOT, baseline_tree, run_child

from torsional_contact.provenance import write_text

CHILD = r"""
import json, sys, time
import numpy as np
from torsional_contact.io.text_tables import read_text_table
start = time.process_time()
table = read_text_table(sys.argv[1])
columns = [table.column(j, name) for j, name in enumerate(table.header)]
cpu = time.process_time() - start
print(json.dumps({"cpu": cpu, "rows": len(table.rows), "checksum": float(sum(np.sum(c) for c in columns))}))
"""


def write_export(path: pathlib.Path, rows: int) -> None:
    """A 1 Hz torsion test sampled at 1 kHz, as a European spreadsheet exports it."""
    lines = ["Rig: torsion rig 2", "Date: 2026-11-29", "Operator: benchmark", "",
             "Zeit [s];Drehmoment [N m];Winkel [rad]"]
    for i in range(rows):
        t = i * 1e-3
        lines.append(f"{t:.3f};{3.0 * math.sin(2 * math.pi * t):.6f};{2.5e-3 * math.sin(2 * math.pi * t):.6e}"
                     .replace(".", ","))
    write_text(path, "\n".join(lines) + "\n")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", default="84f8038", help="the commit whose reader is the baseline")
    parser.add_argument("--rows", type=int, nargs="+", default=[1000, 100_000])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    if args.repeats < 1 or any(rows < 1 for rows in args.rows):
        parser.error("--repeats and --rows: at least 1")
    with tempfile.TemporaryDirectory() as tmp, baseline_tree(args.baseline) as baseline:
        for rows in args.rows:
            export = pathlib.Path(tmp) / f"export_{rows}.csv"
            write_export(export, rows)
            runs = {"baseline": [], "current": []}
            for _ in range(args.repeats):
                runs["baseline"].append(run_child(baseline / "src", CHILD, export))
                runs["current"].append(run_child(ROOT / "src", CHILD, export))
            checksums = {r["checksum"] for results in runs.values() for r in results}
            if len(checksums) != 1:
                raise SystemExit(f"the two readers disagree on {rows} rows: checksums {sorted(checksums)}")
            row = {"rows": rows, "repeats": args.repeats}
            for name, results in runs.items():
                row[name] = {"cpu_s": statistics.median(r["cpu"] for r in results)}
            row["cpu_ratio"] = row["current"]["cpu_s"] / row["baseline"]["cpu_s"]
            print(json.dumps(row), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
