"""Run the fast test tier under the floating-point variants of ``variants.py`` and print the pass counts.

    .venv/bin/python workflow/checks/fp_variants.py                       # all variants
    .venv/bin/python workflow/checks/fp_variants.py threads2 baseline     # some of them (what CI runs)
    .venv/bin/python workflow/checks/fp_variants.py --seed 7 -- -k curves # replay a seed; extra pytest arguments

Exit status 0 when every variant passes, 1 otherwise.  Each variant but ``default`` draws fresh seeds
for the tests that sample random points (printed with the variant; --seed replays them).
"""

from __future__ import annotations

import argparse
import os
import random
import re
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from variants import NAMES, environment, pytest_seed_arguments  # noqa: E402 (the script's own directory)

ROOT = Path(__file__).resolve().parents[2]


def counts(output: str) -> dict:
    """{'passed': n, 'failed': n, ...} from pytest's summary line."""
    tail = output.strip().splitlines()[-1] if output.strip() else ""
    return {word: int(number) for number, word in re.findall(r"(\d+) (passed|failed|skipped|errors?|xfailed)", tail)}


def run(name: str, seed: int, workers: int, extra: list[str]) -> tuple[bool, dict, float, dict]:
    env = {**os.environ, **environment(name, seed)}
    command = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-n", str(workers),
               "--dist", "loadgroup", *pytest_seed_arguments(name, seed), *extra]
    start = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.stdout.write(done.stdout[-6000:] + done.stderr[-2000:])
    shown = {k: v for k, v in environment(name, seed).items()}
    return done.returncode == 0, counts(done.stdout), seconds, shown


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("variants", nargs="*", default=list(NAMES), help=f"any of {', '.join(NAMES)} (default: all)")
    parser.add_argument("--seed", type=int, default=None, help="seed of the random draws (default: a fresh one)")
    parser.add_argument("--workers", type=int, default=2, help="pytest-xdist workers (default 2)")
    argv = sys.argv[1:] if argv is None else list(argv)
    extra = argv[argv.index("--") + 1 :] if "--" in argv else []  # after --: extra pytest arguments
    args = parser.parse_args(argv[: argv.index("--")] if "--" in argv else argv)
    unknown = [v for v in args.variants if v not in NAMES]
    if unknown:
        parser.error(f"unknown variant {unknown[0]!r}; choose from {', '.join(NAMES)}")
    seed = random.randrange(1, 2**31) if args.seed is None else args.seed
    print(f"fp_variants: seed {seed} (replay with --seed {seed})", flush=True)
    ok = True
    for name in args.variants:
        passed, summary, seconds, env = run(name, seed, args.workers, extra)
        ok &= passed
        settings = " ".join(f"{k}={v}" for k, v in env.items()) or "(environment as is)"
        print(f"{name:9s} {'PASS' if passed else 'FAIL'} {summary} in {seconds:.0f} s  {settings}", flush=True)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
