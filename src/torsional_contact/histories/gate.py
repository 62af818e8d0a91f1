r"""The hysteresis gate: removing the reversals of a sampled torque signal smaller than a torque range.

Units: T* = 2T/(f F a).

``gated_signal`` (``gate`` in ``analyse_signal``, ``--gate`` on the command line) removes
every reversal smaller than a torque range ``gate`` before the memory rules (hysteresis,
or rainflow, filtering), scanning the turning points from the virgin torque 0.  Until the
torque has spanned ``gate`` nothing is kept; then the earlier of the two extremes so far
becomes the first turning point T_1 (kept only if its half loop, of range 2 |T_1|,
reaches the gate; otherwise the loading goes straight on to the other extreme: beyond
-T_1 the states are the same) and the later one the tentative extreme.  From there a
turning point beyond the tentative extreme (in the direction of its leg) replaces it;
one at least ``gate`` back from it makes it final and becomes the tentative one; any
other is dropped with the excursion it ends.  The last tentative extreme ends the gated
history (a final excursion smaller than ``gate`` is dropped); a signal that never spans
``gate`` becomes one loading to its torque farthest from 0.

What this changes: at each sample the gated signal is the running extreme of the samples
since the last kept turning point (a monotonic path through the kept extremes), and after
the last one it holds that torque; it stays within ``gate`` of the measured torque.  Its
loops are exactly the loops of the signal whose range is at least ``gate``: every smaller
loop is cut out, nothing else changes (``tests/test_history_signal.py`` checks this on
random signals with ties).  For a gate <= 2 the states at the kept turning points are
those of the signal itself (the loops cut out never slip: they return exactly to where
they started and dissipate nothing); what changes is the path inside the small
excursions, and the end of the record if it ends inside one.  A gate above 2 also cuts
out slipping loops, and the energy they dissipate.
"""

from __future__ import annotations

import numpy as np

from .. import models, validation
from .samples import turning_point_indices, validated_signal

__all__ = ["gated_signal"]


def _hysteresis_filter(torques: list[float], gate: float) -> list[int]:
    """Positions of the turning points kept by the gate; ``torques[0]`` is the virgin torque 0 (module docstring)."""
    n = len(torques)
    low = high = 0  # until the torque has spanned ``gate``: the extremes so far
    i = 1
    while i < n:
        x = torques[i]
        if x > torques[high]:
            high = i
        elif x < torques[low]:
            low = i
        i += 1
        if torques[high] - torques[low] >= gate:
            break
    else:  # never a span of ``gate``: one monotonic loading to the torque farthest from zero
        far = high if torques[high] >= -torques[low] else low
        return [0] if far == 0 else [0, far]
    first, tentative = (high, low) if high < low else (low, high)
    # a first extreme T_1 is kept only if its half loop (T_1 -> -T_1, range 2 |T_1|) reaches the gate;
    # otherwise the loading goes straight to the other extreme (beyond -T_1: the same states from there)
    kept = [0, first, tentative] if first != 0 and 2.0 * abs(torques[first]) >= gate else [0, tentative]
    extreme = torques[tentative]
    leg = 1.0 if extreme > torques[kept[-2]] else -1.0
    for j in range(i, n):
        x = torques[j]
        if leg * (x - extreme) > 0:  # beyond the tentative extreme: it moves
            kept[-1] = j
            extreme = x
        elif leg * (extreme - x) >= gate:  # a reversal of at least ``gate``: the tentative extreme is kept
            kept.append(j)
            extreme, leg = x, -leg
    return kept


def gated_signal(signal, gate, *, name: str = "signal", gate_name: str = "gate", model=None) -> np.ndarray:
    """The signal with every reversal smaller than the torque range ``gate`` removed (module docstring).

    Parameters
    ----------
    signal : array_like
        T* samples within the gross-slip torque of ``model`` ([-4/3, 4/3] for the cylinders), the
        history starting from the virgin interface (T* = 0).
    gate : float
        Torque range in [0, twice the gross-slip torque]; 0 returns the (validated) signal unchanged.
    model : str or ContactModel, optional
        The contact model (``models``) whose gross-slip torque bounds the samples.

    Returns
    -------
    ndarray
        One torque per sample, within ``gate`` of the sample: between two kept turning points
        (the virgin state counts as the first) the running extreme of the samples since the
        first one, after the last kept turning point its torque.

    Raises
    ------
    ValueError
        For a bad sample (naming ``name[i]``) or a gate outside [0, 2 x gross-slip torque] (naming ``gate_name``).
    """
    contact = models.get(model)
    gate = validation.real_number(gate_name, gate, 0.0, 2.0 * contact.gross_slip_torque)
    values = validated_signal(name, signal, contact)
    if gate == 0.0:
        return values
    path = np.concatenate([[0.0], values])  # the history starts at the virgin torque
    index = turning_point_indices(path)
    kept = index[_hysteresis_filter(path[index].tolist(), gate)]
    out = np.empty_like(path)
    stop = int(kept[-1])
    out[stop:] = path[stop]
    if kept.size >= 2:
        leg = np.repeat(np.arange(kept.size - 1), np.diff(kept))  # leg of each sample before the last kept one
        sense = np.sign(np.diff(path[kept]))[leg]
        # the running extreme within each leg: ranks of (leg, sense * value) are ordered leg by leg,
        # so one running maximum of the ranks never crosses a leg boundary (exact: no arithmetic)
        order = np.lexsort((sense * path[:stop], leg))
        rank = np.empty(stop, dtype=np.int64)
        rank[order] = np.arange(stop)
        out[:stop] = path[order[np.maximum.accumulate(rank)]]
    return out[1:]
