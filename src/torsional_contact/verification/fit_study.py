r"""The loop fit on rig records with defects: coverage with the fit's handling on and off, and the plateau estimator.

Units: friction 1, shear modulus Pa, compliance rad/(N m), torque N m, twist rad, time s.

The records come from ``verification.rig_records`` (the models' monotonic numbers and a Masing walk of its own,
independent of ``fitting``).  For each scenario (a drive and the defects of ``RigDefects``) and each handling mode
the study draws ``replicates`` noisy records and fits each with ``fit_loop``:

* handling **on**: the fit's options that look for and model the defects of rigs, as far as ``fit_loop`` offers
  them (``HANDLING``; the time column passed when the fit takes one);
* handling **off**: the same options set to leave the record as it comes.

An option that ``fit_loop`` does not take is named in the row as *not available* (nothing is faked: without a
switch the mode is not run).  Each fit ends, for each of f, G and C, in an *interval* (identified: a value and
both ends), a *bound* (one end open or set by an assumption) or *nothing*; a record the fit refuses with a clear
error (an inverted channel) is *refused*.  Per scenario, mode and parameter the study reports, apart, the coverage
of the intervals and the coverage of the bounds, each as k of n with its exact (Clopper-Pearson) 95 % interval
(``clopper_pearson``), the median relative bias of the identified values with its standard error, and the
warning rate (a fit whose ``warnings`` is not empty) with the rate at which a warning names the defect
(``DEFECT_WORDS``).  A record is treated honestly when every reported interval or bound covers the truth, or a
warning names its defect, or the fit refuses it.  A scenario whose records come from another contact model than
the one the fit assumes (``Scenario.model``) has that misspecification as its defect ("model").

Gross slip (``plateau_friction``): a twist-controlled rig that drives the contact into gross slip reads the
friction from the plateau torque T_gs, f = T_gs / (T*_gs F a / 2) with T*_gs the model's gross-slip torque
(4/3 for the cylinders: f = 3 T_gs / (2 F a)).  ``window_study`` compares it with the loop fit over the largest
torque T*_max of the record: below the gross-slip torque the plateau estimator reads torques at most the peak
and is biased low by at least 1 - T*_max / T*_gs, while the loop fit identifies f from partial slip only near
gross slip and G only while the loop's partial-slip curvature is seen.
"""

from __future__ import annotations

import inspect
import math
import time as timing
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy import special

from .. import models
from .rig_records import RigDefects, RigSpecimen, rig_record

__all__ = ["clopper_pearson", "plateau_friction", "Scenario", "HANDLING", "handling_options", "fit_record",
           "summarise", "run_study", "per_cycle_study", "window_study", "DEFECT_WORDS", "PARAMETERS"]

#: The fitted quantities, by the name of the ``LoopFit`` attribute and the truth's key.
PARAMETERS = ("friction", "shear_modulus", "compliance")

#: The fit's options that handle rig defects: keyword -> (value with the handling on, value with it off).  The value
#: "time" stands for the record's time column.
HANDLING = {"check_defects": (True, False), "time": ("time", None)}

#: Words of a warning that names each defect (case-insensitive).
DEFECT_WORDS = {"lag": ("lag",), "drift": ("drift",), "torque_offset": ("offset",), "spikes": ("spike",),
                "exact_torque": ("exact", "noise floor", "resolution"), "skip_half_cycle": ("virgin",),
                "invert_twist": ("sign", "inverted"), "torque_step": ("quantis", "resolution", "step"),
                "twist_step": ("quantis", "resolution", "step"), "friction_end": ("cycle", "running", "drift"),
                "model": ("model:",)}


def clopper_pearson(successes: int, trials: int, confidence: float = 0.95) -> tuple[float, float]:
    """The exact (Clopper-Pearson) interval of a binomial rate: the beta quantiles
    B(alpha/2; k, n - k + 1) and B(1 - alpha/2; k + 1, n - k), 0 and 1 at the ends.  ValueError naming the argument
    for counts outside 0 <= k <= n, n >= 1."""
    if isinstance(trials, bool) or int(trials) != trials or trials < 1:
        raise ValueError(f"trials must be an integer >= 1, got {trials!r}")
    if isinstance(successes, bool) or int(successes) != successes or not 0 <= successes <= trials:
        raise ValueError(f"successes must be an integer in [0, trials = {trials}], got {successes!r}")
    if not 0 < confidence < 1:
        raise ValueError(f"confidence must lie in (0, 1), got {confidence!r}")
    alpha = 1.0 - confidence
    k, n = int(successes), int(trials)
    lower = 0.0 if k == 0 else float(special.betaincinv(k, n - k + 1, alpha / 2))
    upper = 1.0 if k == n else float(special.betaincinv(k + 1, n - k, 1 - alpha / 2))
    return lower, upper


def plateau_friction(torque, twist, *, radius: float, normal_force: float, model=None, tail: float = 0.25,
                     confidence: float = 0.95) -> dict:
    """f from the gross-slip plateau: T_gs / (T*_gs F a / 2), T_gs the mean |T| over the last ``tail`` of the twist
    travel of every branch between two twist reversals (the virgin loading and a last, unfinished branch left
    out), T*_gs the model's gross-slip torque.  Returns {value, stderr, interval, samples}: the standard error
    from the scatter of the plateau samples about their branch means (what the estimator's noise gives; the
    rounding of the knee, a bias, is not in it).  Reversals: the extremes of a moving average of the twist, each
    moved to the extreme sample near it.
    Meaningful only when the record slid: below gross slip it reads the peak torque (``window_study``)."""
    torque = np.asarray(torque, dtype=float)
    twist = np.asarray(twist, dtype=float)
    if torque.shape != twist.shape or torque.ndim != 1 or torque.size < 8:
        raise ValueError("torque and twist must be 1-d arrays of equal length >= 8")
    if not 0 < tail <= 0.5:
        raise ValueError(f"tail must lie in (0, 0.5], got {tail!r}")
    contact = models.get(model)
    # twist reversals of the drive: the extremes of a smoothed twist (the noise must not make reversals)
    width = max(3, torque.size // 200)
    smooth = np.convolve(twist, np.ones(width) / width, mode="same")
    step = np.sign(np.diff(smooth))
    moving = np.flatnonzero(step)  # a flat step at an extreme is no direction: compare the moving steps
    change = np.flatnonzero(step[moving[1:]] != step[moving[:-1]])
    turns = moving[change] + 1
    turns = turns[(turns > width) & (turns < torque.size - width)]
    # each reversal at the extreme sample of the twist near the smoothed one (the branches must not overlap)
    rising = step[turns - 1] > 0 if turns.size else np.empty(0, dtype=bool)
    windows = turns[:, None] + np.arange(-width, width + 1)
    pick = np.where(rising, np.argmax(twist[windows], axis=1), np.argmin(twist[windows], axis=1))
    turns = windows[np.arange(turns.size), pick]
    edges = np.unique(turns)  # whole branches only: the virgin loading and a last branch cut short are left out
    values, residuals = [], []
    for begin, end in zip(edges[:-1], edges[1:], strict=True):
        travel = twist[begin:end + 1]
        if travel.size < 3:
            continue
        span = travel[-1] - travel[0]
        if span == 0:
            continue
        late = (travel - travel[0]) / span >= 1.0 - tail
        branch = np.abs(torque[begin:end + 1][late])
        if branch.size >= 2:
            values.append(branch.mean())
            residuals.append(branch - branch.mean())
    if not values:
        return {"value": None, "stderr": None, "interval": [None, None], "samples": 0}
    all_residuals = np.concatenate(residuals)
    count = all_residuals.size
    plateau = float(np.average(values, weights=[r.size for r in residuals]))
    dof = max(count - len(values), 1)
    stderr_t = float(np.sqrt(np.sum(all_residuals**2) / dof / count))
    unit = contact.gross_slip_torque * normal_force * radius / 2
    t = float(special.stdtrit(dof, 0.5 + confidence / 2))
    value, stderr = plateau / unit, stderr_t / unit
    return {"value": value, "stderr": stderr, "interval": [value - t * stderr, value + t * stderr],
            "samples": int(count)}


@dataclass(frozen=True)
class Scenario:
    """A record to study: ``name``, the drive (``control`` "torque": ``amplitude`` in T*; "twist": rad), noise
    (torque: fraction of its range; twist: rad), ``defects`` (``RigDefects`` keywords), length (``cycles``,
    ``frequency`` Hz, ``sample_rate`` per s) and the contact ``model``."""

    name: str
    control: str
    amplitude: float
    torque_noise: float = 0.005
    twist_noise: float = 1e-5
    defects: dict = field(default_factory=dict)
    cycles: float = 2.0
    frequency: float = 1.0
    sample_rate: float = 200.0
    model: str | None = None

    def record(self, specimen: RigSpecimen, rng):
        specimen = RigSpecimen(**{**specimen.__dict__, "model": self.model or specimen.model})
        return rig_record(specimen, control=self.control, amplitude=self.amplitude, cycles=self.cycles,
                          frequency=self.frequency, sample_rate=self.sample_rate, torque_noise=self.torque_noise,
                          twist_noise=self.twist_noise, defects=RigDefects(**self.defects), rng=rng)


def handling_options(fit, mode: str, record=None) -> tuple[dict, list[str]]:
    """The keyword arguments of ``fit`` for ``mode`` ("on" or "off") and the names of the ``HANDLING`` options it does
    not take (not available)."""
    if mode not in ("on", "off"):
        raise ValueError(f"mode must be 'on' or 'off', got {mode!r}")
    accepted = inspect.signature(fit).parameters
    options, missing = {}, []
    for key, (on, off) in HANDLING.items():
        if key not in accepted:
            missing.append(key)
            continue
        value = on if mode == "on" else off
        options[key] = record.time if (value == "time" and record is not None) else value
    return options, missing


def _named(messages, defects: dict) -> bool:
    text = " ".join(messages).lower()
    active = [k for k, v in defects.items() if v and k in DEFECT_WORDS]
    return bool(active) and any(word in text for k in active for word in DEFECT_WORDS[k])


def fit_record(fit, record, options: dict, truth: dict, defects: dict) -> dict:
    """One fit of one record: per parameter {status, covered, error}, plus warned, named, refused and ``cpu`` (s, for
    logs: ``summarise`` leaves it out)."""
    started = timing.process_time()
    specimen = record.specimen
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # counted from the result
            result = fit(record.torque, record.twist, radius=specimen.radius, normal_force=specimen.normal_force,
                         **options)
    except ValueError as exc:
        return {"refused": True, "message": str(exc).splitlines()[0], "warned": False,
                "named": _named([str(exc)], defects), "cpu": timing.process_time() - started,
                **{key: {"status": "none"} for key in PARAMETERS}}
    messages = list(getattr(result, "warnings", ()) or ())
    out = {"refused": False, "warned": bool(messages), "named": _named(messages, defects),
           "slip_detected": bool(result.slip_detected), "cpu": timing.process_time() - started}
    for key in PARAMETERS:
        estimate = getattr(result, key)
        lo, hi = estimate.interval
        if lo is None and hi is None:
            out[key] = {"status": "none"}
            continue
        covered = bool((lo is None or lo <= truth[key]) and (hi is None or truth[key] <= hi))
        if not estimate.identified:
            out[key] = {"status": "bound", "covered": covered}
        else:
            out[key] = {"status": "interval", "covered": covered, "error": (estimate.value - truth[key]) / truth[key]}
    return out


def _rate(k: int, n: int) -> dict:
    if n == 0:
        return {"count": 0, "trials": 0, "rate": None, "interval": [None, None]}
    lo, hi = clopper_pearson(k, n)
    return {"count": int(k), "trials": int(n), "rate": k / n, "interval": [lo, hi]}


def median_with_stderr(values) -> tuple[float | None, float | None]:
    """The median and its large-sample standard error sqrt(pi/2) sigma / sqrt(n), sigma from the median absolute
    deviation (1.4826 MAD; None below three values)."""
    values = np.asarray(values, dtype=float)
    if values.size == 0:
        return None, None
    median = float(np.median(values))
    if values.size < 3:
        return median, None
    sigma = 1.4826 * float(np.median(np.abs(values - median)))
    return median, math.sqrt(math.pi / 2) * sigma / math.sqrt(values.size)


def summarise(fits: list[dict]) -> dict:
    """Per parameter: interval and bound coverage apart (k of n with Clopper-Pearson intervals), identified and
    bound rates, median relative bias with its standard error; the warning, naming, refusal and honesty rates."""
    n = len(fits)
    out = {"records": n}  # no CPU time: the data must be the same in every build
    for key in PARAMETERS:
        entries = [f[key] for f in fits]
        intervals = [e for e in entries if e["status"] == "interval"]
        bounds = [e for e in entries if e["status"] == "bound"]
        bias, bias_se = median_with_stderr([e["error"] for e in intervals])
        out[key] = {"identified": _rate(len(intervals), n), "bounded": _rate(len(bounds), n),
                    "interval_coverage": _rate(sum(e["covered"] for e in intervals), len(intervals)),
                    "bound_coverage": _rate(sum(e["covered"] for e in bounds), len(bounds)),
                    "median_bias": bias, "median_bias_stderr": bias_se}
    honest = 0
    for f in fits:
        reported = [f[k] for k in PARAMETERS if f[k]["status"] != "none"]
        honest += bool(f["refused"] or f["named"] or all(e["covered"] for e in reported))
    out["warned"] = _rate(sum(f["warned"] for f in fits), n)
    out["named"] = _rate(sum(f["named"] for f in fits), n)
    out["refused"] = _rate(sum(f["refused"] for f in fits), n)
    out["honest"] = _rate(honest, n)
    return out


def _truth(record) -> dict:
    truth = {key: record.truth[key] for key in PARAMETERS}
    if "friction_per_cycle" in record.truth:  # running-in: the record's mean friction
        truth["friction"] = float(np.mean(record.truth["friction_per_cycle"]))
    return truth


def run_study(scenarios, *, replicates: int, seed: int, specimen: RigSpecimen | None = None, fit=None,
              modes=("on", "off"), progress=None) -> list[dict]:
    """Every scenario with every handling mode: ``replicates`` records each (the same records for both modes, drawn
    from one stream seeded by ``seed``), fitted and summarised (module docstring).  ``fit`` defaults to
    ``torsional_contact.fit_loop``.  Returns one row per scenario and mode."""
    if fit is None:
        from .. import fit_loop as fit
    if isinstance(replicates, bool) or int(replicates) != replicates or replicates < 1:
        raise ValueError(f"replicates must be an integer >= 1, got {replicates!r}")
    specimen = RigSpecimen() if specimen is None else specimen
    rng = np.random.default_rng(seed)
    rows = []
    for scenario in scenarios:
        records = [scenario.record(specimen, rng) for _ in range(int(replicates))]
        for mode in modes:
            options, missing = handling_options(fit, mode, records[0])
            row = {"scenario": scenario.name, "mode": mode, "control": scenario.control,
                   "amplitude": scenario.amplitude, "defects": dict(scenario.defects),
                   "model": records[0].truth["model"], "samples": int(records[0].time.size),
                   "max_torque_ratio": records[0].truth["max_torque_ratio"],
                   "options": sorted(options), "not_available": missing}
            if mode == "off" and not options:
                row["summary"] = None  # no switch to turn the handling off: nothing to run
                rows.append(row)
                continue
            fits = []
            # a record of another contact than the fit's (the default model): misspecified, its own defect
            misspecified = scenario.model is not None and models.get(scenario.model) is not models.get(None)
            named_defects = {**scenario.defects, "model": misspecified}
            for record in records:
                chosen = {k: (record.time if k == "time" and v is not None else v) for k, v in options.items()}
                fits.append(fit_record(fit, record, chosen, _truth(record), named_defects))
            row["summary"] = summarise(fits)
            rows.append(row)
            if progress is not None:
                progress(row)
    return rows


def per_cycle_study(scenario: Scenario, *, replicates: int, seed: int, specimen: RigSpecimen | None = None,
                    fit=None) -> dict:
    """The per-cycle fit (``fit_loop(..., per_cycle=True)``, handling on) on ``replicates`` records of ``scenario``,
    a running-in record (its truth has ``friction_per_cycle``): each cycle's friction against the cycle's true
    friction, the mean of its two branches'.  Returns, apart, the interval coverage and the bound coverage over all
    cycles of all records (k of n with Clopper-Pearson intervals), the median relative bias of the values with its
    standard error, the cycles fitted, ``within``: the largest relative spread of the true friction between a
    cycle's two branches (one f is fitted per cycle while the branches differ by that much), and
    ``range_coverage``: how often the interval meets the cycle's range of friction (its two branches', the mean
    +- a quarter of the change from one cycle to the next)."""
    if fit is None:
        from .. import fit_loop as fit
    if isinstance(replicates, bool) or int(replicates) != replicates or replicates < 1:
        raise ValueError(f"replicates must be an integer >= 1, got {replicates!r}")
    specimen = RigSpecimen() if specimen is None else specimen
    rng = np.random.default_rng(seed)
    intervals, bounds, errors, within, in_range = [], [], [], 0.0, []
    for _ in range(int(replicates)):
        record = scenario.record(specimen, rng)
        truth = np.asarray(record.truth.get("friction_per_cycle", ()), dtype=float)
        if truth.size < 2:
            raise ValueError(f"scenario {scenario.name!r} is not a running-in record (defects need friction_end)")
        within = max(within, float(np.max(np.abs(np.diff(truth)) / 2.0 / truth[1:])))
        quarter = 0.25 * np.abs(np.gradient(truth))  # half the spread of the cycle's two branches' friction
        options, _ = handling_options(fit, "on", record)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # counted from the result
            result = fit(record.torque, record.twist, radius=specimen.radius, normal_force=specimen.normal_force,
                         per_cycle=True, **options)
        for entry in result.cycles:
            friction = entry["friction"]
            lo, hi = friction["interval"]
            value = truth[entry["cycle"] - 1]
            covered = bool((lo is None or lo <= value) and (hi is None or value <= hi))
            if friction["value"] is not None:
                intervals.append(covered)
                errors.append((friction["value"] - value) / value)
                spread = quarter[entry["cycle"] - 1]
                in_range.append(bool((lo is None or lo - spread <= value) and (hi is None or value <= hi + spread)))
            elif lo is not None or hi is not None:
                bounds.append(covered)
    bias, bias_se = median_with_stderr(errors)
    return {"scenario": scenario.name, "records": int(replicates), "cycles": len(intervals) + len(bounds),
            "interval_coverage": _rate(sum(intervals), len(intervals)),
            "bound_coverage": _rate(sum(bounds), len(bounds)), "median_bias": bias, "median_bias_stderr": bias_se,
            "within": within, "range_coverage": _rate(sum(in_range), len(in_range))}


def window_study(levels, plateau_twists, *, replicates: int, seed: int, specimen: RigSpecimen | None = None,
                 fit=None, cycles: float = 2.0, sample_rate: float = 200.0, torque_noise: float = 0.005,
                 twist_noise: float = 1e-5) -> list[dict]:
    """Twist-controlled records whose largest torque is T*_max = each of ``levels`` (below gross slip: the twist
    amplitude is the skeleton's twist there) or that ride the plateau (``plateau_twists``, rad): f and G by the
    loop fit (handling on) against f by ``plateau_friction``.  One row per drive: coverage and median bias of each."""
    if fit is None:
        from .. import fit_loop as fit
    specimen = RigSpecimen() if specimen is None else specimen
    rng = np.random.default_rng(seed)
    drives = [("level", float(level), float(specimen.skeleton(level))) for level in levels]
    drives += [("plateau", None, float(t)) for t in plateau_twists]
    rows = []
    for kind, level, amplitude in drives:
        fits, plateau = [], []
        for _ in range(int(replicates)):
            record = rig_record(specimen, control="twist", amplitude=amplitude, cycles=cycles,
                                sample_rate=sample_rate, torque_noise=torque_noise, twist_noise=twist_noise, rng=rng)
            options, _ = handling_options(fit, "on", record)
            fits.append(fit_record(fit, record, options, _truth(record), {}))
            estimate = plateau_friction(record.torque, record.twist, radius=specimen.radius,
                                        normal_force=specimen.normal_force, model=specimen.model)
            truth = specimen.friction
            lo, hi = estimate["interval"]
            plateau.append({"status": "interval", "covered": bool(lo <= truth <= hi),
                            "error": (estimate["value"] - truth) / truth} if estimate["value"] is not None
                           else {"status": "none"})
        covered = sum(p.get("covered", False) for p in plateau)
        reported = sum(p["status"] == "interval" for p in plateau)
        bias, bias_se = median_with_stderr([p["error"] for p in plateau if p["status"] == "interval"])
        rows.append({"kind": kind, "level": level, "twist_amplitude": amplitude,
                     "max_torque_ratio": float(record.truth["max_torque_ratio"]),
                     "fit": summarise(fits),
                     "plateau": {"interval_coverage": _rate(covered, reported), "median_bias": bias,
                                 "median_bias_stderr": bias_se}})
    return rows
