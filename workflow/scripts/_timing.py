"""Honest timings for the benchmark scripts: interleaved runs, medians with their spread, paired ratios.

A busy machine slows every method measured at the same moment alike, so the methods compared are
run in rounds (A, B, C, A, B, C, ...) and a ratio is taken per round before its median is
reported; an absolute time is always reported with its interquartile spread and the machine.
Times in seconds.
"""

from __future__ import annotations

import os
import platform
import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["Timing", "interleaved", "paired_ratio", "format_ratio", "format_seconds", "machine"]


@dataclass(frozen=True)
class Timing:
    """Wall-time samples of one case (seconds)."""

    samples: tuple[float, ...]

    @property
    def median(self) -> float:
        return statistics.median(self.samples)

    @property
    def spread(self) -> tuple[float, float]:
        """Interquartile range (the lowest and highest sample when there are fewer than four)."""
        if len(self.samples) < 4:
            return min(self.samples), max(self.samples)
        q = statistics.quantiles(self.samples, n=4)
        return q[0], q[2]

    def as_dict(self) -> dict:
        low, high = self.spread
        return {"median": self.median, "q25": low, "q75": high, "samples": len(self.samples)}


def interleaved(cases: dict[str, Callable[[], object]], rounds: int, budget: float | None = None,
                results: dict | None = None) -> dict:
    """Time every case once per round, in an order rotated from round to round.

    Parameters
    ----------
    cases : dict name -> callable
    rounds : int
        Rounds (samples per case), >= 1.
    budget : float, optional
        Stop after the round in which the total time exceeds this (at least three rounds).
    results : dict, optional
        If given, filled with name -> the value the case's last timed call returned, so that what a
        benchmark reports of a case (its error, its torque) is what was timed, not a second call.

    Returns
    -------
    dict name -> Timing
    """
    names = list(cases)
    samples = {name: [] for name in names}
    spent = 0.0
    for k in range(max(1, int(rounds))):
        shift = k % len(names)
        for name in names[shift:] + names[:shift]:
            start = time.perf_counter()
            value = cases[name]()
            elapsed = time.perf_counter() - start
            if results is not None:
                results[name] = value
            samples[name].append(elapsed)
            spent += elapsed
        if budget is not None and spent > budget and k >= 2:
            break
    return {name: Timing(tuple(values)) for name, values in samples.items()}


def paired_ratio(numerator: Timing, denominator: Timing) -> dict:
    """Median and interquartile range of the per-round ratios numerator / denominator."""
    ratios = [a / b for a, b in zip(numerator.samples, denominator.samples, strict=False)]
    return Timing(tuple(ratios)).as_dict()


def format_ratio(ratio: float) -> str:
    """A time ratio with two significant digits: ``1/240`` below one, ``2.3`` above (LaTeX-safe text)."""
    if ratio <= 0:
        raise ValueError(f"ratio must be positive, got {ratio!r}")
    if ratio < 1:
        return f"1/{float(f'{1 / ratio:.2g}'):g}"
    return f"{float(f'{ratio:.2g}'):g}"


def format_seconds(seconds: float) -> str:
    """A wall time with two significant digits and a unit (s, ms or us)."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if seconds >= scale or unit == "us":
            return f"{float(f'{seconds / scale:.2g}'):g} {unit}"
    raise AssertionError("unreachable")


def _cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as handle:
            for line in handle:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError as error:  # not Linux: say so rather than guess
        return f"unknown ({error.__class__.__name__})"
    return "unknown"


def machine() -> dict:
    """The machine a benchmark ran on: CPU, cores, load average, Python and the BLAS thread settings."""
    return {
        "cpu": _cpu_model(),
        "cores": os.cpu_count(),
        "load_average": list(os.getloadavg()) if hasattr(os, "getloadavg") else None,
        "platform": platform.platform(),
        "python": platform.python_version(),
        "threads": {k: os.environ.get(k) for k in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")},
        "timer_resolution": time.get_clock_info("perf_counter").resolution,
    }
