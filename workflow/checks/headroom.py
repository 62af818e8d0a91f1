"""Headroom report: every numerical comparison of the tests, its observed error and its tolerance.

Runs the numerical test files with TORSIONAL_HEADROOM set (tests/tolerances.py records each
``assert_within`` / ``assert_close`` / ``assert_beyond``: test id, line, observed, tolerance, reason),
under one or more floating-point variants (workflow/checks/variants.py), and prints the comparisons
with the smallest ratio tolerance / observed (for floors: observed / floor), worst over the variants.
Every tolerance should sit at least ten times above the error it bounds.

    .venv/bin/python workflow/checks/headroom.py                     # variant threads1, the 30 worst
    .venv/bin/python workflow/checks/headroom.py --variants threads1 threads2 baseline --worst 50
    .venv/bin/python workflow/checks/headroom.py --require 10        # exit status 1 below ratio 10

Bounds that are exact roundings (``exact=True``: a correctly rounded double next to 1 can be off by
half an ulp, no margin is possible) are listed separately, and so are sampled statistics
(``assert_sampled``: a rate or an estimate within k standard errors, whose margin is a false-alarm
probability).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from variants import NAMES, environment, pytest_seed_arguments  # noqa: E402 (the script's own directory)

ROOT = Path(__file__).resolve().parents[2]
#: Test files without numerical comparisons (layout, workflow builds, the SLURM check).
NOT_NUMERICAL = {"test_repository.py", "test_workflow.py", "test_slurm.py"}


def numerical_tests() -> list[str]:
    return sorted(str(p.relative_to(ROOT)) for p in (ROOT / "tests").glob("test_*.py") if p.name not in NOT_NUMERICAL)


def collect(variant: str, seed: int, workers: int, extra: list[str]) -> tuple[list[dict], int]:
    with tempfile.TemporaryDirectory(prefix="headroom-") as directory:
        env = {**os.environ, **environment(variant, seed), "TORSIONAL_HEADROOM": directory}
        command = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-n", str(workers),
                   "--dist", "loadgroup", *pytest_seed_arguments(variant, seed), *extra, *numerical_tests()]
        done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True)
        if done.returncode != 0:
            sys.stdout.write(done.stdout[-4000:])
        rows = []
        for path in Path(directory).glob("*.jsonl"):
            rows += [json.loads(line) for line in path.read_text().splitlines() if line.strip()]
    for row in rows:
        row["variant"] = variant
    return rows, done.returncode


def worst_by_comparison(rows: list[dict]) -> list[dict]:
    """One row per (test, line): the smallest ratio over variants and parametrisations' repeats."""
    best: dict = {}
    for row in rows:
        key = (row["test"], row["line"])
        if key not in best or row["ratio"] < best[key]["ratio"]:
            best[key] = row
    return sorted(best.values(), key=lambda r: (r["ratio"], r["test"]))


def line(row: dict) -> str:
    ratio = "inf" if math.isinf(row["ratio"]) else f"{row['ratio']:.3g}"
    return (f"{ratio:>8} {row['observed']:10.2e} {row['tolerance']:10.2e} {row['kind']:5s} {row['variant']:8s} "
            f"{row['test']}  [{row['line']}] {row['reason']}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--variants", nargs="+", default=["threads1"], help=f"any of {', '.join(NAMES)}")
    parser.add_argument("--worst", type=int, default=30, help="how many comparisons to print (default 30)")
    parser.add_argument("--require", type=float, default=None, help="exit status 1 if a ratio is below this")
    parser.add_argument("--seed", type=int, default=None, help="seed of the random draws (default: a fresh one)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--json", default=None, help="also write every record to this file")
    argv = sys.argv[1:] if argv is None else list(argv)
    extra = argv[argv.index("--") + 1 :] if "--" in argv else []  # after --: extra pytest arguments
    args = parser.parse_args(argv[: argv.index("--")] if "--" in argv else argv)
    seed = random.randrange(1, 2**31) if args.seed is None else args.seed
    rows, failures = [], 0
    for variant in args.variants:
        found, code = collect(variant, seed, args.workers, extra)
        failures += code != 0
        print(f"headroom: variant {variant} (seed {seed}): {len(found)} comparisons recorded, pytest exit {code}",
              flush=True)
        rows += found
    if args.json:
        from torsional_contact.provenance import write_text  # the one writer of user-named files

        write_text(args.json, json.dumps(rows, indent=0, allow_nan=True), label="--json")
    merged = worst_by_comparison(rows)
    exact = [r for r in merged if r["kind"] == "exact"]
    sampled = [r for r in merged if r["kind"] == "sampled"]
    checked = [r for r in merged if r["kind"] not in ("exact", "sampled")]
    print(f"\n{len(checked)} comparisons (worst over {', '.join(args.variants)}); the {args.worst} smallest ratios "
          "tolerance/observed (floors: observed/floor):")
    print(f"{'ratio':>8} {'observed':>10} {'tolerance':>10} kind  variant  test  [line] reason")
    for row in checked[: args.worst]:
        print(line(row))
    below = [r for r in checked if r["ratio"] < 10]
    print(f"\nbelow 10: {len(below)}; below 1 (failing): {sum(r['ratio'] < 1 for r in checked)}")
    if exact:
        print(f"\nexact roundings (half an ulp, no margin possible): {len(exact)}")
        for row in exact:
            print(line(row))
    if sampled:
        print(f"\nsampled statistics (observed: |z| in standard errors, tolerance: k; the margin is a false-alarm "
              f"probability): {len(sampled)}, the {min(args.worst, len(sampled))} largest |z|")
        for row in sampled[: args.worst]:
            print(line(row))
    if failures:
        return 1
    if args.require is not None and checked and checked[0]["ratio"] < args.require:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
