#!/usr/bin/env bash
# The README's main command: set up .venv and TeX, then run the whole Snakemake workflow
# (reference data, solutions, every figure and table, the manuscript results/paper/ms.pdf, its supplement and the companion paper).
# Extra arguments go to snakemake (e.g. --configfile config/test.yaml, -n).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/prepare.sh"
start=$(date +%s)
snakemake --profile workflow/profiles/default "$@"
echo "main: workflow finished in $(( $(date +%s) - start )) s; manuscript: results/paper/ms.pdf" >&2
