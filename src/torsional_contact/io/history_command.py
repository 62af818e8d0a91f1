"""``history --signal``: a sampled torque signal from a file through the memory rules; a summary and table files.

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.

The JSON object (``--json``) is a summary whatever the length of the signal: ``samples``,
``turning_points`` (after the gate), ``dropped_turning_points`` and ``gate``,
``dissipated_energy`` (total), ``closed_loops`` (rainflow count: full loops 1, half loops
1/2), ``half_loops``, ``loop_energy`` (dissipated in those loops), ``method``,
``n_terms``, ``bin_width`` and ``cycles``: the loops grouped by exact (range, mean) for a
short signal (at most ``STATES_IN_JSON`` turning points) unless a bin width is given, else
as a rainflow matrix of bins of range and mean (``SignalHistory.rainflow_bins``, width
``DEFAULT_BIN_WIDTH`` unless given), each with its count and energy.  A short signal
also gets ``states`` (one per turning point).  The states of any signal go to a table
file with ``--states``, the twist and energy at every sample with ``--output``: ``.npz``
(recommended for long signals: binary, exact, with the provenance), ``.npy`` (a structured
array) or CSV (any other name) (``io.signal_files.write_table``).
A progress bar on standard error accompanies signals of ``PROGRESS_SAMPLES`` samples or more
(when tqdm, the ``progress`` extra, is installed).
"""

from __future__ import annotations

import contextlib
import importlib.util
import sys

import numpy as np

from .. import models, validation
from ..histories.signal import MIN_BIN_WIDTH, analyse_signal
from ..records import SignalSummary
from .signal_files import read_signal, write_table

__all__ = ["analyse_file", "analyse_values", "PROGRESS_SAMPLES", "STATES_IN_JSON", "DEFAULT_BIN_WIDTH", "UNITS"]

#: Signals at least this long show a progress bar (unless disabled).
PROGRESS_SAMPLES = 100_000
#: Signals with at most this many turning points (after the gate) get ``states`` in the JSON object
#: and their loops grouped by exact (range, mean); longer ones a rainflow matrix and no states.
STATES_IN_JSON = 1000
#: Width (in T*) of the range and mean bins of the rainflow matrix when none is given.
DEFAULT_BIN_WIDTH = 0.05
#: Units of the table columns (written into the metadata of ``.npz`` files).
UNITS = {"torque": "T* = 2T/(f F a)", "gated_torque": "T*", "stick_radius": "a", "slip_front": "a",
         "rigid_rotation": "f p0 / mu", "dissipated_energy": "(f p0)^2 a^3 / mu"}


@contextlib.contextmanager
def _progress(enabled: bool, total: int):
    """A callable (stage, samples) advancing a tqdm bar on stderr, or a no-op (disabled, or tqdm, the
    ``progress`` extra, not installed: the analysis is the same without a bar)."""
    if not enabled or importlib.util.find_spec("tqdm") is None:
        yield lambda stage, count=0: None
        return
    from tqdm import tqdm

    bar = tqdm(total=total, unit="sample", unit_scale=True, file=sys.stderr, leave=False, mininterval=0.2)

    def advance(stage: str, count: int = 0):
        bar.set_description(stage)
        if count:
            bar.update(count)

    try:
        yield advance
    finally:
        bar.close()


def analyse_file(path: str, *, method=None, n_terms=None, model=None, output=None, states=None, gate=0.0,
                 bin_width=None, progress: bool = True, full: bool = True, column=None,
                 parents: bool = False) -> SignalSummary:
    """Read the T* samples of ``path`` (``io.signal_files.read_signal``; ``column``: of a CSV with
    several columns) and analyse them with ``analyse_values`` (the other arguments are its own)."""
    label = f"--signal {path}"
    values = read_signal(path, label=label, column=column, model=model)
    return analyse_values(values, source=path, method=method, n_terms=n_terms, model=model, output=output,
                          states=states, gate=gate, bin_width=bin_width, progress=progress, full=full, parents=parents)


def analyse_values(values, *, source: str, method=None, n_terms=None, model=None, output=None, states=None,
                   gate=0.0, bin_width=None, progress: bool = True, full: bool = True,
                   parents: bool = False) -> SignalSummary:
    """Apply the gate and the memory rules to the T* samples ``values``, count the loops; the summary record
    (``records.SignalSummary``; ``.as_dict()`` is JSON-ready).

    Parameters
    ----------
    values : array
        The T* samples (checked by ``analyse_signal``).
    source : str
        The file they come from (``--signal``: named in errors, recorded in the tables' metadata,
        never overwritten by them).
    method, n_terms, model :
        The monotonic solutions (``analyse_signal``).
    output, states : str, optional
        Table files to write: the per-sample table (columns ``sample``, ``torque``,
        ``gated_torque`` with a gate, ``rigid_rotation``, ``dissipated_energy``) and the
        states (``SignalHistory.state_columns``); format by extension, through the one
        writer (``output``: never over the input; ``parents``: create missing directories).
    gate : float
        Hysteresis gate (torque range in [0, twice the gross-slip torque: 8/3 for the cylinders],
        ``histories.signal.gated_signal``).
    bin_width : float, optional
        Width of the rainflow bins (module docstring).
    full : bool
        With ``cycles`` (and ``states`` for short signals); otherwise the scalar summary.

    Raises
    ------
    ValueError
        Naming the option (``--gate``, ``--bin-width``) or the file and line of a bad sample.
    """
    widest = 2.0 * models.get(model).gross_slip_torque
    gate = validation.real_number("--gate", gate, 0.0, widest, " (a torque range; 0: no gate)")
    if bin_width is not None:
        bin_width = validation.real_number("--bin-width", bin_width, MIN_BIN_WIDTH, widest, " (a torque range)")
    label = f"--signal {source}"
    enabled = progress and values.size >= PROGRESS_SAMPLES
    with _progress(enabled, values.size * (1 + (output is not None))) as advance:
        advance("memory rules")
        result = analyse_signal(values, method=method, n_terms=n_terms, model=model, name=label, gate=gate,
                                gate_name="--gate")
        advance("memory rules", values.size)
        metadata = {"source": str(source), "model": result.model, "method": result.method, "n_terms": result.n_terms,
                    "gate": gate,
                    "samples": result.samples, "units": UNITS}
        if states is not None:
            advance("writing " + states)
            write_table(states, result.state_columns(), metadata={**metadata, "table": "states at the turning points"},
                        label="--states", inputs=(("--signal", source),), parents=parents)
        if output is not None:
            advance("per-sample table")
            omega, energy = result.sample_values()
            columns = {"sample": np.arange(values.size), "torque": values}
            if gate > 0.0:
                columns["gated_torque"] = result.signal
            columns.update(rigid_rotation=omega, dissipated_energy=energy)
            write_table(output, columns, metadata={**metadata, "table": "per sample"},
                        progress=lambda rows: advance("writing " + output, rows), label="--output",
                        inputs=(("--signal", source),), parents=parents)
    short = result.index.size <= STATES_IN_JSON
    summary = {
        "samples": result.samples,
        "turning_points": int(result.index.size),
        "dropped_turning_points": result.dropped_turning_points,
        "gate": gate,
        "dissipated_energy": result.total_dissipated_energy,
        "closed_loops": result.closed_loops,
        "half_loops": result.half_loops,
        "loop_energy": result.loop_energy,
        "method": result.method,
        "n_terms": result.n_terms,
        "model": result.model,
        "states_file": None if states is None else str(states),
        "output_file": None if output is None else str(output),
    }
    if full:
        if short and bin_width is None:
            summary.update(bin_width=None, cycles=result.cycle_records())
        else:
            width = DEFAULT_BIN_WIDTH if bin_width is None else bin_width
            summary.update(bin_width=width, cycles=result.bin_records(width))
        if short:
            summary["states"] = result.state_records()
    return SignalSummary(**summary)
