"""Sampled torque signals: validation and turning points (the reduction every history tool starts from).

Units: T* = 2T/(f F a).
"""

from __future__ import annotations

import numpy as np

from .. import models, validation

__all__ = ["validated_signal", "turning_point_indices"]


def validated_signal(name: str, signal, model=None) -> np.ndarray:
    """``signal`` as a 1-d float array of finite torques within the gross-slip torque of ``model`` (the
    cylinders' [-4/3, 4/3] by default; a rounding of a few ulp beyond it clipped).

    Raises
    ------
    ValueError
        Naming ``name[i]`` of the first bad sample (not a real number, not finite, or
        |T*| above the gross-slip torque), or for an empty signal.
    """
    contact = models.get(model)
    gross = contact.gross_slip_torque
    if isinstance(signal, (str, bytes)):
        raise ValueError(f"{name} must be a sequence of torques (T*), got {signal!r}")
    try:
        values = np.asarray(signal)
    except (TypeError, ValueError):  # ragged input: the element-wise check names the culprit
        values = np.asarray(validation.torque_sequence(name, signal, contact.checked_torque), dtype=float)
    if values.dtype.kind not in "fiu":
        values = np.asarray(validation.torque_sequence(name, signal, contact.checked_torque), dtype=float)
    values = values.astype(float, copy=False).ravel()
    if values.size == 0:
        raise ValueError(f"{name} must contain at least one torque (T*)")
    limit = gross * (1.0 + validation.TORQUE_TOLERANCE)
    bad = ~(np.abs(values) <= limit)  # nan compares False
    if bad.any():
        i = int(np.argmax(bad))
        contact.checked_torque(f"{name}[{i}]", values[i].item())  # raises the canonical message
    return np.clip(values, -gross, gross)


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
