"""The floating-point variants the test suite must pass under (shared by fp_variants.py and headroom.py).

Different machines round differently: another BLAS thread count splits the dot products of LAPACK
differently, another SIMD width changes numpy's summation order and its transcendental functions,
another seed draws other random points.  We cannot test on every machine, so the suite is checked
under every variation this machine can make safely:

* ``threads1`` / ``threads2``: OPENBLAS_NUM_THREADS (and OMP, MKL) = 1 / 2;
* ``baseline``: numpy's SIMD dispatch limited to its baseline (NPY_DISABLE_CPU_FEATURES set to every
  dispatchable feature numpy reports for this CPU), one BLAS thread;
* every variant but ``default`` also draws fresh seeds for the tests that sample random points
  (TORSIONAL_TEST_SEEDS, hypothesis' --hypothesis-seed), printed so that a failure can be replayed.

OPENBLAS_CORETYPE and OPENBLAS_L2_SIZE are never set: machines set them where older BLAS builds need it.
"""

from __future__ import annotations

import os
import random
import subprocess
import sys

THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
NAMES = ("default", "threads1", "threads2", "baseline")


def dispatched_features(python: str = sys.executable) -> list[str]:
    """numpy's dispatchable SIMD features that this CPU has (what NPY_DISABLE_CPU_FEATURES may switch off)."""
    code = ("from numpy._core._multiarray_umath import __cpu_dispatch__ as d, __cpu_features__ as f\n"
            "print(' '.join(x for x in d if f.get(x)))")
    run = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True,
                         env={k: v for k, v in os.environ.items() if k != "NPY_DISABLE_CPU_FEATURES"})
    return run.stdout.split()


def environment(name: str, seed: int | None = None, python: str = sys.executable) -> dict:
    """Environment variables of variant ``name`` (on top of the current environment)."""
    if name not in NAMES:
        raise ValueError(f"variant must be one of {', '.join(NAMES)}, got {name!r}")
    env = {}
    if name in ("threads1", "baseline"):
        env.update({k: "1" for k in THREAD_VARIABLES})
    elif name == "threads2":
        env.update({k: "2" for k in THREAD_VARIABLES})
    if name == "baseline":
        features = dispatched_features(python)
        if features:
            env["NPY_DISABLE_CPU_FEATURES"] = " ".join(features)
    if name != "default" and seed is not None:
        rng = random.Random(seed)
        env["TORSIONAL_TEST_SEEDS"] = ",".join(str(rng.randrange(1, 2**31)) for _ in range(3))
    return env


def pytest_seed_arguments(name: str, seed: int | None) -> list[str]:
    """Hypothesis' seed for the variant (fresh per variant, printed; none for ``default``)."""
    return [] if name == "default" or seed is None else [f"--hypothesis-seed={seed}"]
