#!/usr/bin/env bash
# The README's main command: set up .venv and build the results.
# (For now: the T*(b) table of both formulations and the n_terms convergence table;
#  the Snakemake build of every figure and the manuscript replaces this.)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash workflow/setup_env.sh
mkdir -p results
.venv/bin/python workflow/scripts/torque_table.py --output results/torque_table.csv
.venv/bin/python workflow/scripts/convergence_table.py --output results/convergence_n_terms.json
