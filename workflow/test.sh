#!/usr/bin/env bash
# The README's test command: set up .venv, lint, run the whole test suite (slow marker included).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash workflow/setup_env.sh
.venv/bin/ruff check src tests workflow
.venv/bin/python -m pytest -p no:cacheprovider -q "$@"
