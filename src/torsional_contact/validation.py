"""Argument checks shared by the API and the CLI: clear ValueErrors naming the argument."""

from __future__ import annotations

import math
import numbers

import numpy as np

__all__ = ["real_number", "positive_int", "choice", "coordinates"]


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


def positive_int(name: str, value) -> int:
    """Return ``value`` as an int >= 1 or raise ValueError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, np.integer)):
        raise ValueError(f"{name} must be an integer >= 1, got {value!r}")
    if value < 1:
        raise ValueError(f"{name} must be an integer >= 1, got {value!r}")
    return int(value)


def choice(name: str, value, options) -> str:
    """Return ``value`` if it is one of ``options`` or raise ValueError naming ``name``."""
    if not isinstance(value, str) or value not in options:
        raise ValueError(f"{name} must be one of {', '.join(repr(o) for o in options)}, got {value!r}")
    return value


def coordinates(r, z=None):
    """Validate field coordinates: 0 <= r <= 1, z >= 0, all finite; returns float arrays."""
    r = np.asarray(r, dtype=float)
    if not np.all(np.isfinite(r)) or np.any(r < 0) or np.any(r > 1):
        raise ValueError("r must be finite and lie in [0, 1] (units of the cylinder radius a)")
    if z is None:
        return r
    z = np.asarray(z, dtype=float)
    if not np.all(np.isfinite(z)) or np.any(z < 0):
        raise ValueError("z must be finite and >= 0 (the upper cylinder; units of a)")
    return r, z
