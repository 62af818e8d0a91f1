#!/usr/bin/env bash
# The README's test command: set up .venv (and TeX), lint, run the whole test suite
# (slow tier included: the end-to-end workflow on the small test configuration).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/prepare.sh"
ruff check src tests workflow notebooks
# One BLAS thread, as the workflow pins it (Snakefile): the last digits of LAPACK estimates depend on the thread
# count.  The tests do not depend on the pin: workflow/checks/fp_variants.py runs them with one and two threads
# and with numpy's SIMD dispatch at its baseline (CI runs two of those variants after this command).
# pytest keeps its rewritten test modules as bytecode only where Python may write bytecode: without it each
# of the three processes (the controller and two workers) rewrites every test module again (~3 CPU-s each)
unset PYTHONDONTWRITEBYTECODE
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1
# the fast and slow tiers (the slow one: the end-to-end build), on two workers; the statistical sweeps and the
# second clean build compared byte for byte with the first run in CI (.ci/run: markers sweep and rebuild); the
# workflow tests share one worker (xdist group) because their builds share results/ci and Snakemake's lock
start=$(date +%s)
python -m pytest -p no:cacheprovider -q -n 2 --dist loadgroup -m "not sweep and not rebuild" "$@"
echo "test: suite finished in $(( $(date +%s) - start )) s" >&2
