r"""Friction per cycle: each closed cycle of a record fitted on its own, to follow running-in and wear.

Units: friction 1, compliance rad / (N m), torque N m, twist rad.

A cycle is the stretch of the record from a turning point of the twist to the second turning
point after it (two branches: ``samples.turning_points``; cycle k from turning point 2k to 2k + 2).
No cycle but the first starts from the virgin state, and none needs to: each is fitted on the
steady Masing branches from its first turning point on (``fitting.defects``: the state at a
turning point reached by steady cycling is that of a monotonic loading to it, Masing's memory
erasure; the cycle's mean torque is taken out, so that the torque channel's zero does not
matter).  Each cycle's fit is a full fit (``loop_fit``): its own noise scale, slip test and
profile-likelihood intervals; the record's spikes are removed once, before the cycles are cut, and
its noise levels are the record's.  The per-cycle fits do not look for a lag or a drift (a cycle
is too short to tell them from the loop's own shape): the whole record's fit does, and its
warnings apply to every cycle.

``cycle_fits`` returns one dict per cycle: ``cycle`` (1, 2, ...), ``friction`` and ``compliance``
({value, stderr, interval}, ``Estimate.as_dict``), ``regime``, ``warnings`` (the cycle's own),
``start`` and ``end`` (sample indices in the record as given) and ``time`` (the time of its middle
sample, when the record has a time column).
"""

from __future__ import annotations

import numpy as np

from .samples import MIN_SAMPLES

__all__ = ["cycle_fits", "cycle_bounds", "cycles_with_progress", "withheld_cycles"]


def cycle_bounds(reversals: np.ndarray, size: int) -> list[tuple[int, int]]:
    """(first, last) sample of every whole cycle: from turning point 2k to turning point 2k + 2, with at least
    ``MIN_SAMPLES`` samples."""
    bounds = []
    for k in range(0, reversals.size - 2, 2):
        first, last = int(reversals[k]), int(reversals[k + 2])
        if last - first + 1 >= MIN_SAMPLES and last < size:
            bounds.append((first, last))
    return bounds


def cycle_fits(record, settings, fit_prepared, clock=None, progress=None) -> list[dict]:
    """The fits of the whole cycles of a prepared record (``record_checks.PreparedRecord``; module docstring).

    ``settings`` and ``fit_prepared`` as ``loop_fit`` passes them; ``clock``: the samples' times (s) or None;
    ``progress``: a callable taking the number of cycles done and their total, or None.
    """
    bounds = cycle_bounds(record.reversals, record.torque.size)
    out = []
    for number, (first, last) in enumerate(bounds, start=1):
        torque = record.torque[first:last + 1]
        twist = record.twist[first:last + 1]
        inner = record.reversals[(record.reversals > first) & (record.reversals < last)] - first
        reversals = np.concatenate([[0], inner]).astype(int)
        centre = 0.5 * (float(np.max(torque)) + float(np.min(torque)))
        fitted = fit_prepared(torque - centre, twist, reversals, record.torque_noise, record.twist_noise, [], 0,
                              settings)
        result = fitted.result
        entry = {"cycle": number, "friction": result.friction.as_dict(), "compliance": result.compliance.as_dict(),
                 "regime": result.regime, "warnings": list(result.warnings),
                 "start": int(record.kept[first]), "end": int(record.kept[last])}
        if clock is not None:
            entry["time"] = float(clock[(first + last) // 2])
        out.append(entry)
        if progress is not None:
            progress(number, len(bounds))
    return out


def cycles_with_progress(record, settings, fit_prepared, clock):
    """``per_cycle.cycle_fits`` with a progress bar (tqdm, on a terminal) for ten cycles or more."""
    total = len(cycle_bounds(record.reversals, record.torque.size))
    if total < 10:
        return cycle_fits(record, settings, fit_prepared, clock)
    from tqdm import tqdm

    with tqdm(total=total, desc="fit per cycle", unit="cycle", disable=None, leave=False) as bar:
        return cycle_fits(record, settings, fit_prepared, clock, progress=lambda done, _: bar.update(1))


def withheld_cycles(cycles, check: str | None) -> tuple:
    """``cycles`` as a tuple; when the whole record's check ``check`` withheld its friction (``Estimate.withheld``:
    a lag that explains the loop as well as slip, a contact model the loop rejects), every cycle's friction and
    compliance are withheld too (each cycle is fitted under the same model and lag) and say so."""
    if check is None:
        return tuple(cycles)
    withheld = {"value": None, "stderr": None, "interval": [None, None], "identified": False, "withheld": check}
    note = (f"withheld: the whole record's {check} check withheld f, G and the compliance; this cycle's values "
            "would be read under what it rejected")
    return tuple({**entry, "friction": dict(withheld), "compliance": dict(withheld),
                  "warnings": [*entry["warnings"], note]} for entry in cycles)
