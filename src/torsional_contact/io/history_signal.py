"""``history --signal``: a sampled torque signal from a file through the memory rules, as one JSON object.

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.  The per-sample
table (``--output``) has the columns sample, torque, rigid_rotation, dissipated_energy.
A progress bar on standard error accompanies signals of ``PROGRESS_SAMPLES`` samples or more.
"""

from __future__ import annotations

import contextlib
import sys

import numpy as np

from ..histories.signal import analyse_signal
from .signal_files import read_signal, write_sample_table

__all__ = ["analyse_file", "PROGRESS_SAMPLES"]

#: Signals at least this long show a progress bar (unless disabled).
PROGRESS_SAMPLES = 100_000
_HEADER = "sample,torque,rigid_rotation,dissipated_energy"


@contextlib.contextmanager
def _progress(enabled: bool):
    """A callable (stage, samples) advancing a tqdm bar on stderr, or a no-op."""
    if not enabled:
        yield lambda stage, count=0: None
        return
    from tqdm import tqdm

    bar = tqdm(total=None, unit="sample", unit_scale=True, file=sys.stderr, leave=False, mininterval=0.2)

    def advance(stage: str, count: int = 0):
        bar.set_description(stage)
        if count:
            bar.update(count)

    try:
        yield advance, bar
    finally:
        bar.close()


def analyse_file(path: str, *, method=None, n_terms=None, model=None, output=None, progress: bool = True,
                 full: bool = True):
    """Read ``path``, apply the memory rules, count closed loops; the JSON-ready result.

    With ``full`` the object has ``samples``, ``turning_points``, ``states`` (one per
    turning point), ``cycles`` (closed loops and half loops grouped by range and mean,
    ``histories.signal``), ``closed_loops``, ``half_loops`` and ``dissipated_energy``
    (total); otherwise only the scalar summary.  ``output``:
    also write the per-sample CSV table.
    """
    values = read_signal(path, label=f"--signal {path}")
    enabled = progress and values.size >= PROGRESS_SAMPLES
    with _progress(enabled) as handle:
        advance, bar = handle if enabled else (handle, None)
        if bar is not None:
            bar.total = values.size * (2 if output else 1)
            bar.refresh()
        advance("memory rules")
        result = analyse_signal(values, method=method, n_terms=n_terms, model=model, name=f"--signal {path}")
        advance("memory rules", values.size)
        if output is not None:
            advance("per-sample table")
            omega, energy = result.sample_values()
            write_sample_table(output, _HEADER, [range_of(values.size), values, omega, energy], integer_columns=(0,),
                               progress=lambda rows: advance("writing " + output, rows))
    summary = {
        "samples": result.samples,
        "turning_points": int(result.index.size),
        "closed_loops": int(np.sum(result.cycle_count == 1.0)),
        "half_loops": int(np.sum(result.cycle_count == 0.5)),
        "dissipated_energy": _finite(result.total_dissipated_energy),
        "method": result.method,
        "n_terms": result.n_terms,
        "model": result.model,
    }
    if not full:
        return summary
    return {**summary, "states": result.states(), "cycles": result.cycles()}


def range_of(n: int):
    return np.arange(n)


def _finite(value: float):
    return value if value == value and abs(value) != float("inf") else None
