"""What ``fit`` gives a lab to file: a text report, the residual table, the fit plot and the provenance.

Units: torque N m, twist rad, time s, as in ``fitting``.

* ``text_report(record)``: the fit's JSON record as a page of text (no Python reprs): the input as
  read (file, SHA-256, rows, separator, decimal mark, encoding, skipped metadata lines, the columns
  and their units as written), the estimates with their intervals, the regime, noise and residuals,
  the record's warnings and, when the fit reports them, its cycles.
* ``residual_columns(result, columns)``: every sample with the fitted torque and its residuals.
  The normalised residual of sample i is the effective-variance residual of errors in both variables,

      d_i = (T_i - g(theta_i)) / sqrt(s_T^2 + g'(theta_i)^2 s_theta^2),

  g(theta_i) the fitted torque at the measured twist, s_T and s_theta the noise levels of the fit
  and g' the slope of the fitted curve along the record (central differences of g over the
  twist; at a reversal, where the twist does not move, the slope of the neighbour).  It is the
  fit's orthogonal distance in noise units to first order in the noise (``fitting.loop_model``):
  about standard normal where the model and the noise levels hold.
* ``plot_fit(path, ...)``: the loop with the fitted model, and the normalised residuals against
  the sample number (matplotlib: the ``plots`` extra); one panel per cycle beside them when the
  record has several cycles, and with a per-cycle fit (``per_cycle``) the friction coefficient of
  each cycle against its number, with its interval (a lower bound where the cycle gives only one).
* ``fit_provenance(report)``: the input's report plus the package versions (``provenance``).
"""

from __future__ import annotations

import json
import math
import os

import numpy as np

__all__ = ["text_report", "residual_columns", "write_residuals", "plot_fit", "PLOT_FORMATS", "fit_provenance",
           "FitRecord"]

#: Formats ``--plot`` writes, by the file name's extension.
PLOT_FORMATS = (".png", ".pdf", ".svg")


class FitRecord(dict):
    """The fit's JSON record; printed as ``text_report`` without ``--json``."""

    def text(self) -> str:
        return text_report(self)


#: The packages a fit runs on (the core: no extra is imported to name its version).
FIT_PACKAGES = ("torsional_contact", "numpy", "scipy", "pint")


def fit_provenance(report: dict) -> dict:
    """The provenance of a fit: the input as read (``io.lab_files``), the versions of the packages it ran on,
    Python and the machine."""
    import platform
    from importlib import metadata

    versions = {}
    for name in FIT_PACKAGES:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = None
    return {"input": report, "packages": versions, "python": platform.python_version(),
            "machine": f"{platform.system()} {platform.machine()}, {os.cpu_count()} cores"}


def _slope(fitted: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """dg/dtheta along the record (module docstring)."""
    if fitted.size < 2:
        return np.zeros_like(fitted)
    dg, dtheta = np.gradient(fitted), np.gradient(twist)
    scale = max(float(np.ptp(twist)), np.finfo(float).tiny)
    moving = np.abs(dtheta) > 1e-9 * scale
    slope = np.zeros_like(fitted)
    slope[moving] = dg[moving] / dtheta[moving]
    if moving.any() and not moving.all():  # reversals and repeated twists: the nearest sample that moves
        index = np.flatnonzero(moving)
        nearest = index[np.clip(np.searchsorted(index, np.arange(fitted.size)), 0, index.size - 1)]
        slope[~moving] = slope[nearest[~moving]]
    return slope


def _kept(result, torque, twist, torque_noise, twist_noise) -> np.ndarray:
    """The indices of the samples the fit kept (all but the spikes it removed, ``fitting.record_checks``)."""
    fitted = np.asarray(result.fitted_torque)
    if fitted.size == torque.size:
        return np.arange(torque.size)
    from ..fitting.record_checks import prepared_record

    kept = prepared_record(torque, twist, torque_noise, twist_noise, check=False).kept
    if kept.size != fitted.size:  # pragma: no cover - the fit and the check disagree on the spikes
        raise ValueError(f"the fit reports {fitted.size} fitted torques for {kept.size} samples kept")
    return kept


def residual_columns(result, columns: dict, torque_noise=None, twist_noise=None) -> dict:
    """name [unit] -> array: sample, time (if read), torque, twist, spike (1: removed before the fit), fitted
    torque, torque residual, normalised residual (module docstring; NaN for a spike).  ``result``: a ``LoopFit``;
    ``columns``: ``read_lab_columns``'s arrays (SI); ``torque_noise``, ``twist_noise``: the levels given to the fit
    (N m, rad; None: estimated), which decide the spikes it removed."""
    torque, twist = np.asarray(columns["torque"], float), np.asarray(columns["twist"], float)
    kept = _kept(result, torque, twist, torque_noise, twist_noise)
    fitted = np.full(torque.size, np.nan)
    fitted[kept] = np.asarray(result.fitted_torque, dtype=float)
    s_t, s_theta = float(result.noise["torque"]), float(result.noise["twist"])
    residual = torque - fitted
    normalised = np.full(torque.size, np.nan)
    slope = _slope(fitted[kept], twist[kept])
    normalised[kept] = residual[kept] / np.sqrt(s_t**2 + (slope * s_theta) ** 2)
    spike = np.ones(torque.size, dtype=np.int64)
    spike[kept] = 0
    out = {"sample": np.arange(torque.size)}
    if "time" in columns:
        out["time [s]"] = np.asarray(columns["time"], float)
    out.update({"torque [N m]": torque, "twist [rad]": twist, "spike": spike, "fitted_torque [N m]": fitted,
                "torque_residual [N m]": residual, "normalized_residual": normalised})
    return out


def write_residuals(path, table: dict, *, inputs=(), parents: bool = False) -> None:
    """The residual table (``residual_columns``) through the one writer: CSV, or .npz/.npy by the extension."""
    from .signal_files import write_table

    write_table(path, table, label="--residuals", inputs=inputs, parents=parents,
                metadata={"content": "fit residuals"})


def _cycles(record: dict) -> list[tuple[int, int]]:
    """(first, last + 1) sample of each cycle the record reports with sample ranges, else [].

    A cycle names its samples by ``start`` and ``end`` (both in it: ``per_cycle``), ``first_sample`` and
    ``last_sample`` (both in it), or ``start`` and ``stop`` (one past the last)."""
    spans = []
    for cycle in record.get("cycles") or []:
        if isinstance(cycle, dict):
            first = cycle.get("first_sample", cycle.get("start"))
            last = cycle.get("last_sample", cycle.get("end", cycle.get("stop")))
            inclusive = "last_sample" in cycle or "end" in cycle
            if isinstance(first, int) and isinstance(last, int) and last > first:
                spans.append((first, last + 1 if inclusive else last))
    return spans


def cycle_friction(record: dict) -> list[tuple[int, float | None, float | None, float | None]]:
    """(cycle number, f, lower end, upper end) of each cycle of a per-cycle fit that gives f or a bound on it."""
    out = []
    for number, cycle in enumerate(record.get("cycles") or [], start=1):
        friction = cycle.get("friction") if isinstance(cycle, dict) else None
        if not isinstance(friction, dict):
            continue
        lo, hi = (list(friction.get("interval") or [None, None]) + [None, None])[:2]
        if friction.get("value") is not None or lo is not None:
            out.append((int(cycle.get("cycle", number)), friction.get("value"), lo, hi))
    return out


def plot_fit(path, table: dict, record: dict, *, title: str, inputs=(), parents: bool = False) -> None:
    """The fit plot (module docstring) written to ``path`` (.png, .pdf or .svg) through the one writer."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..output import atomic_path

    torque, twist = table["torque [N m]"], table["twist [rad]"]
    fitted, normalised = table["fitted_torque [N m]"], table["normalized_residual"]
    spikes = table["spike"].astype(bool)
    spans = _cycles(record)
    extra = min(len(spans), 6) if len(spans) > 1 else 0
    per_cycle = cycle_friction(record)
    rows = 3 if per_cycle else 2
    figure = plt.figure(figsize=(7.0 + 2.4 * math.ceil(extra / 2), 3.2 * rows), constrained_layout=True)
    grid = figure.add_gridspec(rows, 1 + math.ceil(extra / 2), width_ratios=[3.0] + [1.0] * math.ceil(extra / 2))
    loop = figure.add_subplot(grid[0, 0])
    scale = 1e3  # mrad: the twists of a loop
    loop.plot(twist * scale, torque, ".", ms=2.5, color="0.55", label="measured")
    loop.plot(twist * scale, fitted, "-", lw=1.2, color="C0", label="fitted model")
    if spikes.any():
        loop.plot(twist[spikes] * scale, torque[spikes], "x", ms=5, color="C1", label="spikes (removed)")
    loop.set_xlabel("twist $\\theta$ [mrad]")
    loop.set_ylabel("torque $T$ [N m]")
    loop.set_title(title, fontsize=9)
    loop.legend(loc="best", fontsize=8)
    residuals = figure.add_subplot(grid[1, 0])
    samples = np.arange(torque.size)
    residuals.plot(samples, normalised, ".", ms=2.5, color="C3")
    for level in (-2.0, 2.0):
        residuals.axhline(level, color="0.6", lw=0.8, ls="--")
    residuals.axhline(0.0, color="0.3", lw=0.8)
    residuals.set_xlabel("sample")
    residuals.set_ylabel("normalised residual $d_i$ (noise units)")
    for k, (first, stop) in enumerate(spans[:extra]):
        axis = figure.add_subplot(grid[k % 2, 1 + k // 2])
        axis.plot(twist[first:stop] * scale, torque[first:stop], ".", ms=2, color="0.55")
        axis.plot(twist[first:stop] * scale, fitted[first:stop], "-", lw=1.0, color="C0")
        axis.set_title(f"cycle {k + 1}", fontsize=8)
        axis.set_xlabel("$\\theta$ [mrad]", fontsize=8)
        axis.tick_params(labelsize=7)
    if per_cycle:
        whole = record.get("friction") if isinstance(record.get("friction"), dict) else {}
        _plot_cycle_friction(figure.add_subplot(grid[2, :]), per_cycle, whole.get("value"))
    suffix = os.path.splitext(os.fspath(path))[1].lower()
    try:
        with atomic_path(path, suffix, label="--plot", inputs=inputs, parents=parents) as tmp:
            figure.savefig(tmp, format=suffix[1:], dpi=150)
    finally:
        plt.close(figure)


def _plot_cycle_friction(axis, per_cycle, whole: float | None) -> None:
    """f of each cycle with its interval; a cycle that gives only a lower bound as an upward triangle there; the
    whole record's f (``whole``, if any) as a line."""
    from matplotlib.ticker import MaxNLocator

    valued = [(n, v, lo, hi) for n, v, lo, hi in per_cycle if v is not None]
    bounded = [(n, lo) for n, v, lo, _ in per_cycle if v is None and lo is not None]
    if valued:
        numbers = np.array([n for n, *_ in valued], dtype=float)
        values = np.array([v for _, v, _, _ in valued], dtype=float)
        lower = np.array([v - lo if lo is not None else 0.0 for _, v, lo, _ in valued])
        upper = np.array([hi - v if hi is not None else 0.0 for _, v, _, hi in valued])
        axis.errorbar(numbers, values, yerr=[lower, upper], fmt="o", ms=3.5, color="C0", capsize=2,
                      label="f of the cycle, with its interval")
    if bounded:
        axis.plot([n for n, _ in bounded], [lo for _, lo in bounded], "^", ms=5, color="C1",
                  label="only a lower bound")
    if whole is not None:
        axis.axhline(whole, color="0.5", lw=0.9, ls="--", label="f of the whole record")
    axis.xaxis.set_major_locator(MaxNLocator(integer=True))
    axis.set_xlabel("cycle")
    axis.set_ylabel("friction coefficient $f$")
    axis.legend(loc="best", fontsize=8)


# --------------------------------------------------------------------------- the text report
def _number(value, unit: str = "") -> str:
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        text = f"{value:.6g}"
    else:
        text = str(value)
    return f"{text} {unit}".rstrip()


def _estimate_line(name: str, estimate: dict, unit: str, confidence: float) -> str:
    low, high = estimate.get("interval", [None, None])
    if estimate.get("identified", True):
        line = (f"  {name:<15} {_number(estimate.get('value'), unit):<22} +- {_number(estimate.get('stderr'))}"
                f"   {confidence:.0%} interval [{_number(low)}, {_number(high)}]")
    else:
        line = (f"  {name:<15} not identified: {confidence:.0%} interval [{_number(low)}, "
                f"{'unbounded' if high is None else _number(high)}]")
        if estimate.get("lower_bound") is not None:
            line += f", lower bound {_number(estimate['lower_bound'], unit)}"
    if estimate.get("assumed_end"):
        line += f" ({estimate['assumed_end']} end set by the model's bound)"
    if estimate.get("bootstrap_interval"):
        b_low, b_high = estimate["bootstrap_interval"]
        line += f"; bootstrap [{_number(b_low)}, {_number(b_high)}]"
    return line


def _input_lines(report: dict) -> list[str]:
    if not report:
        return []
    decimal = "decimal comma" if report.get("decimal_mark") == "," else "decimal point"
    skipped = report.get("skipped_lines", 0)
    lines = [f"input: {report.get('path')} ({report.get('rows')} rows; {report.get('delimiter')}-separated, {decimal}, "
             f"{report.get('encoding')}; header on line {report.get('header_line')}"
             + (f", {skipped} line(s) above it skipped)" if skipped else ")"),
             f"  sha256 {report.get('sha256')}"]
    for role, column in (report.get("columns") or {}).items():
        header, unit = (json.dumps(column[key], ensure_ascii=False) for key in ("header", "unit"))
        lines.append(f"  {role}: column {header}, unit {unit} (x {column['to_si']:.9g} -> {column['si_unit']})")
    return lines


def _plain(value) -> str:
    """A value of the record on one line: numbers as numbers, anything nested as JSON (never a Python repr)."""
    if isinstance(value, (dict, list, tuple)):
        return json.dumps(value, ensure_ascii=False, allow_nan=False)
    if value is None:
        return "-"
    return _number(value)


def text_report(record: dict) -> str:
    """The fit's record as text (module docstring)."""
    units = record.get("units", {})
    confidence = float(record.get("confidence", 0.95))
    lines = [f"torsional_contact fit ({record.get('provenance', {}).get('packages', {}).get('torsional_contact', '')})"
             .replace(" ()", "")]
    lines += _input_lines(record.get("input") or {})
    lines.append(f"specimen: radius {_number(record.get('radius'), 'm')}, normal force "
                 f"{_number(record.get('normal_force'), 'N')}")
    lines.append(f"samples {record.get('samples')}, reversals {record.get('reversals')}, degrees of freedom "
                 f"{record.get('dof')}")
    lines.append(f"regime: {record.get('regime')} (slip detected: {_number(record.get('slip_detected'))}; stick test "
                 f"{_number(record.get('stick_test'))} against {_number(record.get('stick_critical'))})")
    lines.append(f"estimates ({record.get('interval_method')} intervals):")
    for key, name in (("friction", "friction f"), ("shear_modulus", "shear modulus G"), ("compliance", "compliance C"),
                      ("rig_compliance", "rig compliance"), ("twist_offset", "twist offset")):
        if isinstance(record.get(key), dict):
            unit = units.get(key, "rad/(N m)" if key == "rig_compliance" else "")
            lines.append(_estimate_line(name, record[key], unit if isinstance(unit, str) else "", confidence))
    if record.get("correlation") is not None:
        lines.append(f"  correlation of f and G: {_number(record['correlation'])}")
    noise = record.get("noise") or {}
    lines.append(f"noise: torque {_number(noise.get('torque'), 'N m')}, twist {_number(noise.get('twist'), 'rad')} "
                 f"({'estimated from the record' if noise.get('estimated') else 'given'}); noise scale "
                 f"{_number(record.get('noise_scale'))}")
    if noise.get("torque_smoothed") is not None:
        lines.append(f"torque fitted as a smooth function of time ({noise.get('spline_coefficients')} spline "
                     f"coefficients): its noise {_number(noise['torque_smoothed'], 'N m')}; intervals widened for its "
                     "correlated errors")
    lines.append(f"residuals: rms {_number(record.get('residual_rms'), 'rad')} (twist), "
                 f"{_number(record.get('torque_residual_rms'), 'N m')} (torque)")
    if record.get("message"):
        lines.append(f"message: {record['message']}")
    if record.get("spikes"):
        lines.append(f"spikes removed before the fit: {record['spikes']} sample(s) (marked in --residuals)")
    warnings = record.get("warnings") or []
    lines.append("warnings: none" if not warnings else "warnings:")
    lines += [f"  - {w}" for w in warnings]
    shown = {"input", "provenance", "units", "friction", "shear_modulus", "compliance", "rig_compliance",
             "twist_offset", "correlation", "noise", "noise_scale", "residual_rms", "torque_residual_rms", "message",
             "warnings", "radius", "normal_force", "samples", "reversals", "dof", "regime", "slip_detected",
             "stick_test", "stick_critical", "interval_method", "confidence", "cycles", "outputs", "spikes"}
    cycles = record.get("cycles") or []
    if cycles:
        lines.append(f"cycles ({len(cycles)}):")
        for k, cycle in enumerate(cycles, start=1):
            if isinstance(cycle, dict):
                parts = [f"cycle {cycle.get('cycle', k)}"]
                for key in ("friction", "compliance"):
                    if isinstance(cycle.get(key), dict):
                        parts.append(f"{key} {_number(cycle[key].get('value'))} +- {_number(cycle[key].get('stderr'))}")
                if cycle.get("regime"):
                    parts.append(str(cycle["regime"]))
                parts += [f"warning: {w}" for w in cycle.get("warnings") or []]
                lines.append("  " + "; ".join(parts))
    rest = [(key, value) for key, value in record.items() if key not in shown]
    if rest:
        lines.append("other:")
        lines += [f"  {key}: {_plain(value)}" for key, value in rest]
    for option, path in (record.get("outputs") or {}).items():
        lines.append(f"wrote {option} {path}")
    return "\n".join(lines)
