"""Coverage study of the loop fit: do its 95 % intervals hold the true f, G and C at their nominal rate?

For each scenario (a synthetic rig from the exact solution, ``torsional_contact.fitting.synthetic``:
torque- or twist-controlled, an amplitude, white noise on both channels) the noise-free record is
made once and ``--draws`` noisy copies are fitted with ``fit_loop`` (noise levels estimated from
each record, as a user's would be).  For each parameter every draw ends in one of three ways: an
interval (the parameter is identified: a value and both ends from the data), a bound (not
identified: what the data do say, one end open or set by the model's bound on kappa), or nothing.
Per scenario and parameter the table gives, apart, the coverage of the reported intervals and that of
the reported bounds (a bound covers when the truth lies within it), each as k of n with its exact
(Clopper-Pearson) 95 % interval (``verification.fit_study.clopper_pearson``), n the draws that got an
interval or a bound, and, over the identified draws, the median relative bias of the value and the
median relative width of the interval.  For a loop in stick the rate at which slip is detected is the
slip test's false-alarm rate (its level is 5 %).

Units: torque N m, twist rad, friction 1, G Pa, compliance rad / (N m).  Output: a JSON data file
with provenance, the LaTeX table (results/tables/) and macros (results/macros/).  The noisy records
are drawn first, in order, from one random stream; ``--workers`` processes then fit them (each fit
depends on its record alone, so that the output is the same for any number of workers).
"""

import argparse
import concurrent.futures
import json
import math
import multiprocessing
import time
import warnings

import numpy as np
from scipy.stats import binom

from torsional_contact import fit_loop
from torsional_contact.diagnostics import NoiseLimitedFitWarning
from torsional_contact.fitting.synthetic import Rig, noisy, torque_controlled, twist_controlled
from torsional_contact.provenance import latex_escape, write_json, write_macros, write_text
from torsional_contact.typeset import sci
from torsional_contact.verification.fit_study import clopper_pearson

PARAMETERS = (("friction", "f"), ("shear_modulus", "G"), ("compliance", "C"))
CONFIDENCE = 0.95


def binomial_stderr(successes: int, trials: int) -> float:
    """Standard error of a rate from ``successes`` in ``trials`` (the rate smoothed to (k + 1) / (n + 2), so that 0 and
    n successes do not claim an error of 0)."""
    p = (successes + 1) / (trials + 2)
    return math.sqrt(p * (1 - p) / trials)


def rate(successes: int, trials: int) -> dict:
    """k of n with its exact (Clopper-Pearson) interval at ``CONFIDENCE`` (None without trials)."""
    interval = list(clopper_pearson(successes, trials, CONFIDENCE)) if trials else None
    return {"count": int(successes), "trials": int(trials), "interval": interval}


def outcome(estimate, truth: float) -> dict:
    """What one fit reported about one parameter: "interval", "bound" or "none", whether it covers, error, width."""
    lo, hi = estimate.interval
    if lo is None and hi is None:
        return {"status": "none"}
    covered = (lo is None or lo <= truth) and (hi is None or truth <= hi)
    if not estimate.identified:
        return {"status": "bound", "covered": covered}
    return {"status": "interval", "covered": covered, "error": (estimate.value - truth) / truth,
            "width": (hi - lo) / truth}


def summary(outcomes, draws: int) -> dict:
    counts = {s: sum(o["status"] == s for o in outcomes) for s in ("interval", "bound", "none")}
    reported = [o for o in outcomes if o["status"] != "none"]
    identified = [o for o in outcomes if o["status"] == "interval"]
    out = {"interval": counts["interval"] / draws, "bound": counts["bound"] / draws, "none": counts["none"] / draws}
    for name, group in (("coverage", reported), ("identified_coverage", identified)):
        covered = sum(o["covered"] for o in group)
        out[name] = covered / len(group) if group else None
        out[name + "_stderr"] = binomial_stderr(covered, len(group)) if group else None
        out[name + "_count"] = len(group)
    bounded = [o for o in outcomes if o["status"] == "bound"]
    for name, group in (("interval_coverage", identified), ("bound_coverage", bounded)):
        out[name] = rate(sum(o["covered"] for o in group), len(group))
    out["median_bias"] = float(np.median([o["error"] for o in identified])) if identified else None
    out["median_width"] = float(np.median([o["width"] for o in identified])) if identified else None
    return out


def scenario_draws(rig, scenario, draws, cycles, samples_per_cycle, rng):
    """The noise-free record of one scenario, its torque noise level (N m) and ``draws`` noisy copies (from ``rng``,
    in order: the random stream does not depend on how the fits are scheduled)."""
    if scenario["control"] == "torque":
        torque, twist = torque_controlled(rig, scenario["amplitude"] * rig.slip_torque, cycles, samples_per_cycle)
    else:
        torque, twist = twist_controlled(rig, scenario["amplitude"], cycles, samples_per_cycle)
    torque_noise = scenario["torque_noise"] * float(np.ptp(torque))
    copies = [noisy(torque, twist, torque_noise, scenario["twist_noise"], rng) for _ in range(draws)]
    return torque, torque_noise, copies


def truth_of(rig) -> dict:
    return {"friction": rig.friction, "shear_modulus": rig.shear_modulus, "compliance": rig.compliance}


def fit_draw(task):
    """Fit one noisy record: (slip detected, outcome per parameter, CPU-s).  ``task``: (rig, torque, twist)."""
    rig, torque, twist = task
    started = time.process_time()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NoiseLimitedFitWarning)  # counted in the summary, from the result
        fit = fit_loop(torque, twist, radius=rig.radius, normal_force=rig.normal_force, confidence=CONFIDENCE)
    outcomes = {key: outcome(getattr(fit, key), true) for key, true in truth_of(rig).items()}
    return bool(fit.slip_detected), outcomes, time.process_time() - started


def fit_all(tasks, workers: int) -> list:
    """``fit_draw`` of every task, in order, on ``workers`` processes (each fit depends on its record alone: the
    results do not depend on the number of workers)."""
    if workers <= 1:
        return [fit_draw(task) for task in tasks]
    context = multiprocessing.get_context("fork")  # the workers share the parent's imports
    with concurrent.futures.ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        return list(pool.map(fit_draw, tasks))


def scenario_record(rig, scenario, torque, torque_noise, fits):
    """The summary of one scenario's draws (``fits``: their ``fit_draw`` results, in order)."""
    truth = truth_of(rig)
    draws = len(fits)
    slips = sum(slip for slip, _, _ in fits)
    out = {"name": scenario["name"], "control": scenario["control"], "amplitude": scenario["amplitude"],
           "torque_noise": torque_noise, "torque_noise_fraction": scenario["torque_noise"],
           "twist_noise": scenario["twist_noise"],
           "max_torque_ratio": float(np.max(np.abs(torque)) / rig.slip_torque), "draws": draws,
           "slip_detected": slips / draws, "slip_detected_stderr": binomial_stderr(slips, draws),
           "slip_detected_rate": rate(slips, draws)}
    for key in truth:
        out[key] = summary([outcomes[key] for _, outcomes, _ in fits], draws)
    cpu = sum(seconds for _, _, seconds in fits)
    print(f"{scenario['name']}: {cpu:.2f} CPU-s of fits", flush=True)  # the log, not the data
    return out


def _percent(x, digits=0):
    return "--" if x is None else f"{100 * x:.{digits}f}"


def _kn(entry):
    """'k/n' of a rate, '--' without trials."""
    return "--" if not entry["trials"] else f"{entry['count']}/{entry['trials']}"


def nominal_verdict(entry) -> str:
    """'below', 'within' or 'above' the range of counts a true coverage of ``CONFIDENCE`` gives in 95 % of studies
    with the entry's trials (binomial quantiles, as ``ft-nominal-lo`` / ``-hi`` for all draws); '--' without trials."""
    trials = entry["trials"]
    if not trials:
        return "--"
    count = entry["count"]
    lowest, highest = (binom.ppf(q, trials, CONFIDENCE) for q in ((1 - CONFIDENCE) / 2, (1 + CONFIDENCE) / 2))
    return "below" if count < lowest else "above" if count > highest else "within"


def _cp(entry):
    """'[lo, hi]' of a rate's Clopper-Pearson interval in per cent, empty without trials."""
    if not entry["trials"]:
        return ""
    lo, hi = entry["interval"]
    return f"[{100 * lo:.0f}, {100 * hi:.0f}]"


def _signed(x):
    if x is None:
        return "--"
    if abs(x) >= 10:
        return "$>10^3$"
    percent = 100 * x
    return f"${percent:+.0f}$" if abs(percent) >= 10 else f"${percent:+.2g}$"  # never 2.8e+02


def _width(x):
    if x is None:
        return "--"
    percent = 100 * x
    if percent >= 10:
        return f"{percent:.0f}"
    return f"{percent:.2g}" if percent >= 0.01 else "$<0.01$"  # never 1e-05


def table(rows) -> str:
    # interval and bound coverage apart, each k/n and its Clopper-Pearson interval in its own column; two header
    # lines: the table fits the text width at \scriptsize (the size of the fit-study table)
    lines = [r"\setlength{\tabcolsep}{4pt}", r"\begin{tabular}{lrrrrlrlrlrr}", r"\hline",
             r"scenario & $\max|T^*|$ & $s_T$ & $s_\theta$ & slip & & \multicolumn{2}{c}{interval coverage}"
             r" & \multicolumn{2}{c}{bound coverage} & median & median \\",
             r" & & [N\,m] & [rad] & & & $k/n$ & [\%] & $k/n$ & [\%] & bias [\%] & width [\%] \\", r"\hline"]
    for r in rows:
        for j, (key, symbol) in enumerate(PARAMETERS):
            e = r[key]
            head = [latex_escape(r["name"]), f"{r['max_torque_ratio']:.3g}", f"${sci(r['torque_noise'], 1)}$",
                    f"${sci(r['twist_noise'], 1)}$", _kn(r["slip_detected_rate"])] if j == 0 else [""] * 5
            cells = head + [f"${symbol}$", _kn(e["interval_coverage"]), _cp(e["interval_coverage"]),
                            _kn(e["bound_coverage"]), _cp(e["bound_coverage"]),
                            _signed(e["median_bias"]), _width(e["median_width"])]
            lines.append(" & ".join(cells) + r" \\")
        lines.append(r"\hline")
    lines += [r"\end{tabular}"]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--specimen", required=True, help="JSON: radius, normal_force, friction, shear_modulus, "
                        "compliance (SI)")
    parser.add_argument("--scenarios", required=True, help="JSON list: name, control, amplitude, torque_noise, "
                        "twist_noise")
    parser.add_argument("--draws", type=int, required=True)
    parser.add_argument("--cycles", type=float, required=True)
    parser.add_argument("--samples-per-cycle", type=int, required=True)
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--json", required=True)
    parser.add_argument("--tex", required=True)
    parser.add_argument("--macros", required=True)
    parser.add_argument("--workers", type=int, default=1, help="processes fitting the draws (the output does not "
                        "depend on it)")
    args = parser.parse_args()
    if args.workers < 1:
        parser.error(f"--workers must be >= 1, got {args.workers}")
    specimen = json.loads(args.specimen)
    rig = Rig(**specimen, offset=1e-4)
    rng = np.random.default_rng(args.seed)
    scenarios = json.loads(args.scenarios)
    records = [scenario_draws(rig, scenario, args.draws, args.cycles, args.samples_per_cycle, rng)
               for scenario in scenarios]
    fits = fit_all([(rig, *copy) for _, _, copies in records for copy in copies], args.workers)
    rows = []
    for j, (scenario, (torque, torque_noise, _)) in enumerate(zip(scenarios, records, strict=True)):
        rows.append(scenario_record(rig, scenario, torque, torque_noise, fits[j * args.draws:(j + 1) * args.draws]))
        print(json.dumps({k: rows[-1][k] for k in ("name", "slip_detected", "friction", "shear_modulus",
                                                   "compliance")}), flush=True)
    write_json(args.json, {"specimen": specimen, "scenarios": rows, "confidence": CONFIDENCE},
               method="fit_loop on synthetic rigs (torsional_contact.fitting.synthetic)", draws=args.draws,
               seed=args.seed, cycles=args.cycles, samples_per_cycle=args.samples_per_cycle)
    write_text(args.tex, table(rows))
    macros = {"ft-draws": str(args.draws), "ft-samples": str(int(round(args.cycles * args.samples_per_cycle)) + 1),
              "ft-cycles": f"{args.cycles:g}", "ft-friction": f"{specimen['friction']:g}",
              "ft-modulus-gpa": f"{specimen['shear_modulus'] / 1e9:g}",
              "ft-compliance": f"{sci(specimen['compliance'], 1)}", "ft-radius-mm": f"{specimen['radius'] * 1e3:g}",
              "ft-force-n": f"{specimen['normal_force']:g}",
              # how many of the draws a nominal 95 % coverage gives, in 95 % of studies (binomial quantiles)
              "ft-nominal-lo": f"{binom.ppf((1 - CONFIDENCE) / 2, args.draws, CONFIDENCE):.0f}",
              "ft-nominal-hi": f"{binom.ppf((1 + CONFIDENCE) / 2, args.draws, CONFIDENCE):.0f}"}
    for r in rows:
        key = r["name"]
        for name, symbol in PARAMETERS:
            e = r[name]
            short = symbol.lower()
            for kind, tag in (("interval_coverage", "icov"), ("bound_coverage", "bcov")):
                c = e[kind]
                macros[f"ft-{key}-{tag}-{short}"] = _kn(c)
                lo, hi = c["interval"] if c["trials"] else (None, None)
                macros[f"ft-{key}-{tag}-lo-{short}"] = _percent(lo)
                macros[f"ft-{key}-{tag}-hi-{short}"] = _percent(hi)
                macros[f"ft-{key}-{tag}-verdict-{short}"] = nominal_verdict(c)
            macros[f"ft-{key}-interval-{short}"] = _percent(e["interval"])
            macros[f"ft-{key}-bound-{short}"] = _percent(e["bound"])
            macros[f"ft-{key}-width-{short}"] = _percent(e["median_width"], 1)
        macros[f"ft-{key}-twist-noise"] = sci(r["twist_noise"], 1)
        macros[f"ft-{key}-torque-noise"] = sci(r["torque_noise"], 1)
        macros[f"ft-{key}-torque-noise-pct"] = f"{100 * r['torque_noise_fraction']:.2g}"
        macros[f"ft-{key}-slip"] = _kn(r["slip_detected_rate"])
        macros[f"ft-{key}-slip-lo"] = _percent(r["slip_detected_rate"]["interval"][0])
        macros[f"ft-{key}-slip-hi"] = _percent(r["slip_detected_rate"]["interval"][1])
    write_macros(args.macros, macros, "workflow/scripts/friction_test_coverage.py")


if __name__ == "__main__":
    main()
