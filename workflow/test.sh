#!/usr/bin/env bash
# The README's test command: set up .venv (and TeX), lint, run the whole test suite
# (slow marker included) and the end-to-end workflow on the small test configuration.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash workflow/setup_env.sh
bash workflow/ensure_tex.sh
export PATH="$root/.venv/bin:$PATH"
ruff check src tests workflow
python -m pytest -p no:cacheprovider -q "$@"
