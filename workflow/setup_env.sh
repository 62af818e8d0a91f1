#!/usr/bin/env bash
# Create or update the project virtual environment .venv from environment.txt.
# CLUSTER=1 also installs environment-cluster.txt (the SLURM executor plugin, pinned) into it.
# Idempotent: reinstalls only when environment.txt, environment-cluster.txt or pyproject.toml changed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
python="${PYTHON:-python3}"
cluster="${CLUSTER:-0}"
if [ "$cluster" != "0" ] && [ "$cluster" != "1" ]; then
  echo "setup_env: CLUSTER must be 0 or 1 (got '$cluster')" >&2
  exit 2
fi
if ! "$python" -c 'import sys; sys.exit(sys.version_info[:2] < (3, 11))' 2>/dev/null; then
  echo "setup_env: need Python >= 3.11 (set PYTHON=/path/to/python3.11)" >&2
  exit 1
fi
[ -x .venv/bin/python ] || "$python" -m venv .venv
stamp=".venv/.installed-$(cat environment.txt pyproject.toml | sha256sum | cut -c1-16)"
if [ ! -f "$stamp" ]; then
  .venv/bin/python -m pip install --quiet --upgrade pip
  .venv/bin/python -m pip install --quiet -r environment.txt
  .venv/bin/python -m pip install --quiet --no-deps -e .
  rm -f .venv/.installed-*
  touch "$stamp"
fi
if [ "$cluster" = "1" ]; then
  # both files in one pip call, so the resolver checks the extra against the base pins
  cluster_stamp=".venv/.cluster-$(cat environment.txt environment-cluster.txt | sha256sum | cut -c1-16)"
  if [ ! -f "$cluster_stamp" ]; then
    .venv/bin/python -m pip install --quiet -r environment.txt -r environment-cluster.txt
    rm -f .venv/.cluster-*
    touch "$cluster_stamp"
  fi
fi
# Bytecode of the project's own modules (the installed packages have theirs from pip).  Without it, a
# machine that sets PYTHONDONTWRITEBYTECODE (as some CI images do) compiles src/ again in every job:
# about 0.4 CPU-s per Python process that imports the library, ~100 of them per build.  Python still
# checks each cache against its source (time stamp and size), so an edited module is never run stale.
if ! .venv/bin/python -m compileall -q -j 0 src workflow tests notebooks >/dev/null; then
  echo "setup_env: could not write the bytecode caches (__pycache__ under src/, workflow/, tests/);" \
       "every job will compile the sources itself (slower, same results)" >&2
fi
