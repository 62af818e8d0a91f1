# Sourced by workflow/main.sh and workflow/test.sh: go to the repository root, create or update
# .venv (workflow/setup_env.sh), make sure LaTeX is there (workflow/ensure_tex.sh) and put .venv
# first on PATH.  Sets $root.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash workflow/setup_env.sh
bash workflow/ensure_tex.sh
export PATH="$root/.venv/bin:$PATH"
