"""What the benchmarks against a baseline commit share: the baseline's tree and a fresh interpreter per run.

``baseline_tree(commit)`` checks COMMIT out as a detached ``git worktree`` in a temporary directory and removes it
afterwards; ``run_child(src, code, *args)`` runs ``code`` in a fresh interpreter importing the library from ``src``
(one BLAS thread, nothing else from this environment) and returns the JSON object of its last line of output.
"""

from __future__ import annotations

import contextlib
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]


@contextlib.contextmanager
def baseline_tree(commit: str):
    """The source tree (its ``src`` directory's parent) of ``commit``, for the duration of the block."""
    with tempfile.TemporaryDirectory() as tmp:
        tree = pathlib.Path(tmp) / "baseline"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(tree), commit], check=True,
                       capture_output=True)
        try:
            yield tree
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(tree)], check=False,
                           capture_output=True)


def run_child(src: pathlib.Path, code: str, *args, timeout: float = 600.0) -> dict:
    """The JSON object that ``code`` prints last, run with ``args`` in a fresh interpreter on the library in ``src``."""
    env = {"PYTHONPATH": str(src), "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"}
    out = subprocess.run([sys.executable, "-c", code, *map(str, args)], capture_output=True, text=True, env=env,
                         timeout=timeout, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])
