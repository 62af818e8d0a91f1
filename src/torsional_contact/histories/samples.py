"""Sampled torque signals: validation and turning points (the reduction every history tool starts from).

Units: T* = 2T/(f F a).
"""

from __future__ import annotations

import numpy as np

from .. import validation
from ..criteria import GROSS_SLIP_TORQUE

__all__ = ["validated_signal", "turning_point_indices"]


def validated_signal(name: str, signal) -> np.ndarray:
    """``signal`` as a 1-d float array of finite torques in [-4/3, 4/3] (rounding beyond 4/3 clipped).

    Raises
    ------
    ValueError
        Naming ``name[i]`` of the first bad sample (not a real number, not finite, or
        |T*| > 4/3), or for an empty signal.
    """
    if isinstance(signal, (str, bytes)):
        raise ValueError(f"{name} must be a sequence of torques in [-4/3, 4/3], got {signal!r}")
    try:
        values = np.asarray(signal)
    except (TypeError, ValueError):  # ragged input: the element-wise check names the culprit
        values = np.asarray(validation.torque_sequence(name, signal), dtype=float)
    if values.dtype.kind not in "fiu":
        values = np.asarray(validation.torque_sequence(name, signal), dtype=float)
    values = values.astype(float, copy=False).ravel()
    if values.size == 0:
        raise ValueError(f"{name} must contain at least one torque in [-4/3, 4/3]")
    limit = GROSS_SLIP_TORQUE * (1.0 + validation.TORQUE_TOLERANCE)
    bad = ~(np.abs(values) <= limit)  # nan compares False
    if bad.any():
        i = int(np.argmax(bad))
        validation.torque(f"{name}[{i}]", values[i].item())  # raises the canonical message
    return np.clip(values, -GROSS_SLIP_TORQUE, GROSS_SLIP_TORQUE)


def turning_point_indices(values: np.ndarray) -> np.ndarray:
    """Sample indices of the turning points: the first sample, every reversal, the last value reached.

    Runs of equal samples count once, at their first sample.
    """
    values = np.asarray(values, dtype=float)
    starts = np.concatenate([[0], np.flatnonzero(np.diff(values) != 0) + 1])
    if starts.size <= 2:
        return starts
    step = np.sign(np.diff(values[starts]))
    reversals = np.flatnonzero(step[1:] != step[:-1]) + 1
    return starts[np.concatenate([[0], reversals, [starts.size - 1]])]
