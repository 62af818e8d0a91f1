"""Argument checks shared by the API and the CLI: clear ValueErrors naming the argument."""

from __future__ import annotations

import math
import numbers

import numpy as np

from .criteria import GROSS_SLIP_TORQUE

#: Relative tolerance on |T*| = 4/3 that still counts as the spinning limit (rounding).
TORQUE_TOLERANCE = 4 * np.finfo(float).eps

__all__ = ["real_number", "positive_int", "choice", "coordinates", "torque", "torque_sequence", "TORQUE_TOLERANCE"]


def real_number(name: str, value, low: float | None = None, high: float | None = None, note: str = ""):
    """Return ``value`` as a finite float in [low, high] or raise ValueError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    value = float(value)
    bounds = f"[{low:g}, {high:g}]" if low is not None and high is not None else ""
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite{' and in ' + bounds if bounds else ''}, got {value!r}")
    if (low is not None and value < low) or (high is not None and value > high):
        raise ValueError(f"{name} must lie in {bounds}, got {value!r}{note}")
    return value


def positive_int(name: str, value, maximum: int | None = None, note: str = "") -> int:
    """Return ``value`` as an int in [1, maximum] (no maximum: >= 1) or raise ValueError naming ``name``."""
    valid = "an integer >= 1" + (f" and <= {maximum}" if maximum is not None else "")
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, np.integer)):
        raise ValueError(f"{name} must be {valid}{note}, got {value!r}")
    if value < 1 or (maximum is not None and value > maximum):
        raise ValueError(f"{name} must be {valid}{note}, got {value!r}")
    return int(value)


def choice(name: str, value, options) -> str:
    """Return ``value`` if it is one of ``options`` or raise ValueError naming ``name``."""
    if not isinstance(value, str) or value not in options:
        raise ValueError(f"{name} must be one of {', '.join(repr(o) for o in options)}, got {value!r}")
    return value


def _real_array(name: str, value, valid: str) -> np.ndarray:
    """``value`` (a real number or an array of them: no strings, no booleans) as a float array."""
    array = np.asarray(value)
    if not isinstance(value, np.ndarray) or array.dtype.kind == "O":  # numbers, lists: look at every element
        elements = np.asarray(value, dtype=object).ravel()
        if not all(isinstance(v, (numbers.Real, np.floating, np.integer)) and not isinstance(v, (bool, np.bool_))
                   for v in elements):
            raise ValueError(f"{name} must be a real number or an array of real numbers {valid}, got {value!r}")
    if array.dtype.kind not in "fiu":
        raise ValueError(f"{name} must be a real number or an array of real numbers {valid}, got {value!r}")
    return array.astype(float)


def _first(array: np.ndarray, bad: np.ndarray) -> str:
    """The first offending value of ``array`` (where ``bad``), for a message."""
    flat = np.flatnonzero(bad)
    value = float(array.ravel()[flat[0]])
    if array.size == 1:
        return f"{value!r}"
    index = flat[0] if array.ndim == 1 else tuple(int(k) for k in np.unravel_index(flat[0], array.shape))
    where = f"element {index}"
    return f"{value!r} ({where})"


def coordinates(r, z=None, *, names=("r", "z")):
    """Validate field coordinates: 0 <= r <= 1, z >= 0, all finite real numbers, r and z of broadcastable
    shapes; returns float arrays.  ``names``: how the messages call r and z (e.g. "--radii")."""
    r_name, z_name = names if len(names) == 2 else (names[0], "z")
    r = _real_array(r_name, r, "in [0, 1]")
    bad = ~(np.isfinite(r) & (r >= 0) & (r <= 1))
    if bad.any():
        raise ValueError(f"{r_name} must be finite and lie in [0, 1] (units of the cylinder radius a), "
                         f"got {_first(r, bad)}")
    if z is None:
        return r
    z = _real_array(z_name, z, ">= 0")
    bad = ~(np.isfinite(z) & (z >= 0))
    if bad.any():
        raise ValueError(f"{z_name} must be finite and >= 0 (the upper cylinder; units of a), got {_first(z, bad)}")
    try:
        np.broadcast_shapes(r.shape, z.shape)
    except ValueError:
        raise ValueError(f"{r_name} and {z_name} must have shapes that broadcast together (numpy rules), got "
                         f"{r_name} of shape {r.shape} and {z_name} of shape {z.shape}") from None
    return r, z


def torque(name: str, value, *, limit: float = GROSS_SLIP_TORQUE, limit_text: str = "4/3",
           spinning: str = "the cylinders spin") -> float:
    """``value`` as a finite T* in [-limit, limit] (a rounding of a few ulp beyond ``limit`` clipped to it), or
    ValueError naming ``name``.

    ``limit`` is the gross-slip torque of the contact model (4/3 for the cylinders, written ``limit_text`` in
    messages); ``spinning`` says what happens beyond it.  Values within ``TORQUE_TOLERANCE`` (4 ulp) past the
    limit are taken as the limit itself: the rounding of a torque computed as, e.g., 2 x (2/3).
    """
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise ValueError(f"{name} must be a real number in [-{limit_text}, {limit_text}], got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite and lie in [-{limit_text}, {limit_text}], got {value!r}")
    if abs(value) > limit * (1 + TORQUE_TOLERANCE):
        side = "above" if value > 0 else "below"
        bound = limit_text if value > 0 else f"-{limit_text}"
        raise ValueError(
            f"{name} must lie in [-{limit_text}, {limit_text}], got {value!r}: {side} {bound} {spinning} "
            "(gross slip), there is no static solution"
        )
    return max(-limit, min(limit, value))


def torque_sequence(name: str, values, checked=None) -> list[float]:
    """``values`` as a non-empty list of finite torques, or ValueError naming ``name[i]``.

    ``checked(name, value)`` checks one torque (default ``torque``: the cylinders' [-4/3, 4/3]; a contact
    model's ``checked_torque`` for its own gross-slip torque).  A flat sequence or 1-d array only: a nested
    one (e.g. [[0, 1.2], [1.3, 0]]) is refused, not flattened, since its order of turning points would be a
    guess.
    """
    checked = torque if checked is None else checked
    if isinstance(values, (str, bytes)) or np.ndim(values) == 0 and not hasattr(values, "__iter__"):
        raise ValueError(f"{name} must be a sequence of torques (T*), got {values!r}")
    if isinstance(values, np.ndarray):
        if values.ndim != 1:
            raise ValueError(
                f"{name} must be a flat (1-d) sequence of torques (T*), got shape {values.shape}")
        items = list(values)
    else:
        try:
            items = list(values)
        except TypeError as exc:  # not iterable
            raise ValueError(f"{name} must be a sequence of torques (T*), got {values!r}") from exc
    if not items:
        raise ValueError(f"{name} must contain at least one torque (T*)")
    for i, v in enumerate(items):
        if isinstance(v, (str, bytes)) or np.ndim(v) != 0:
            raise ValueError(f"{name}[{i}] must be a real number (T*; a flat sequence), got {v!r}")
    return [checked(f"{name}[{i}]", v) for i, v in enumerate(items)]
