"""Coverage study of the loop fit: do its 95 % intervals hold the true f, G and C at their nominal rate?

For each scenario (a synthetic rig from the exact solution, ``torsional_contact.fitting.synthetic``:
torque- or twist-controlled, an amplitude, white noise on both channels) the noise-free record is
made once and ``--draws`` noisy copies are fitted with ``fit_loop`` (noise levels estimated from
each record, as a user's would be).  Per parameter: the fraction of draws whose interval holds the
truth (with its binomial standard error), the median relative error, and how often the fit reports
the parameter at all (stick: no friction value, only a lower bound; G unresolved: only a lower
bound, counted as covering when the bound lies below the truth).

Units: torque N m, twist rad, friction 1, G Pa, compliance rad / (N m).  Output: a JSON data file
with provenance, the LaTeX table (results/tables/) and macros (results/macros/).
"""

import argparse
import json
import math
import time
import warnings

import numpy as np

from torsional_contact import fit_loop
from torsional_contact.diagnostics import NoiseLimitedFitWarning
from torsional_contact.fitting.synthetic import Rig, noisy, torque_controlled, twist_controlled
from torsional_contact.provenance import latex_escape, write_json, write_macros, write_text
from torsional_contact.typeset import sci


def scenario_record(rig, scenario, draws, cycles, samples_per_cycle, rng):
    if scenario["control"] == "torque":
        torque, twist = torque_controlled(rig, scenario["amplitude"] * rig.slip_torque, cycles, samples_per_cycle)
    else:
        torque, twist = twist_controlled(rig, scenario["amplitude"], cycles, samples_per_cycle)
    torque_noise = scenario["torque_noise"] * float(np.ptp(torque))
    truth = {"friction": rig.friction, "shear_modulus": rig.shear_modulus, "compliance": rig.compliance}
    tallies = {key: {"reported": 0, "bounded": 0, "covered": 0, "errors": []} for key in truth}
    regimes, bounds, flagged, started = {}, [], 0, time.process_time()
    for _ in range(draws):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", NoiseLimitedFitWarning)  # counted below, from the result
            fit = fit_loop(*noisy(torque, twist, torque_noise, scenario["twist_noise"], rng), radius=rig.radius,
                           normal_force=rig.normal_force)
        flagged += int(fit.noise_limited)
        regimes[fit.regime] = regimes.get(fit.regime, 0) + 1
        if fit.friction.lower_bound is not None:
            bounds.append(fit.friction.lower_bound)
        for key, true in truth.items():
            estimate = getattr(fit, key)
            tally = tallies[key]
            lo, hi = estimate.interval
            if estimate.value is not None:
                tally["reported"] += 1
                tally["errors"].append((estimate.value - true) / true)
            if lo is not None:  # an interval or a lower bound
                tally["bounded"] += 1
                tally["covered"] += int(lo <= true and (hi is None or true <= hi))
    out = {"name": scenario["name"], "control": scenario["control"], "amplitude": scenario["amplitude"],
           "torque_noise": torque_noise, "torque_noise_fraction": scenario["torque_noise"],
           "twist_noise": scenario["twist_noise"],
           "max_torque_ratio": float(np.max(np.abs(torque)) / rig.slip_torque), "draws": draws,
           "regimes": regimes, "noise_limited": flagged / draws,
           "friction_lower_bound_median": float(np.median(bounds)) if bounds else None}
    for key, tally in tallies.items():
        bounded = tally["bounded"]
        covered = tally["covered"] / bounded if bounded else None
        errors = np.abs(tally["errors"])
        out[key] = {"coverage": covered, "coverage_stderr": None if covered is None else math.sqrt(
                        max(covered * (1 - covered), 0.25 / bounded) / bounded),
                    "reported": tally["reported"] / draws, "bounded": bounded / draws,
                    "median_abs_rel_error": float(np.median(errors)) if errors.size else None}
    print(f"{scenario['name']}: {time.process_time() - started:.2f} CPU-s", flush=True)  # the log, not the data
    return out


def _cell(entry):
    if entry["coverage"] is None or entry["bounded"] < 0.2:  # too few intervals to count
        return "--"
    return f"{100 * entry['coverage']:.0f}"


def _error(entry):
    e = entry["median_abs_rel_error"]
    if e is None:
        return "--"
    return "$>1000$" if e >= 10 else f"{100 * e:.2g}"  # an unresolved G runs off towards infinity


def table(rows) -> str:
    lines = [r"\begin{tabular}{lrrrrrrrrrrr}", r"\hline",
             r"scenario & $\max|T^*|$ & $s_T$ [N\,m] & $s_\theta$ [rad] & \multicolumn{3}{c}{coverage [\%]}"
             r" & \multicolumn{3}{c}{median $|$error$|$ [\%]} & $G$ found & flagged \\",
             r" & & & & $f$ & $G$ & $C$ & $f$ & $G$ & $C$ & [\%] & [\%] \\", r"\hline"]
    for r in rows:
        cells = [latex_escape(r["name"]), f"{r['max_torque_ratio']:.3g}", f"${sci(r['torque_noise'], 1)}$",
                 f"${sci(r['twist_noise'], 1)}$"]
        cells += [_cell(r[k]) for k in ("friction", "shear_modulus", "compliance")]
        cells += [_error(r[k]) for k in ("friction", "shear_modulus", "compliance")]
        cells += [f"{100 * r['shear_modulus']['reported']:.0f}", f"{100 * r['noise_limited']:.0f}"]
        lines.append(" & ".join(cells) + r" \\")
    lines += [r"\hline", r"\end{tabular}"]
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
    args = parser.parse_args()
    specimen = json.loads(args.specimen)
    rig = Rig(**specimen, offset=1e-4)
    rng = np.random.default_rng(args.seed)
    rows = []
    for scenario in json.loads(args.scenarios):
        rows.append(scenario_record(rig, scenario, args.draws, args.cycles, args.samples_per_cycle, rng))
        print(json.dumps({k: rows[-1][k] for k in ("name", "friction", "shear_modulus", "compliance")}), flush=True)
    write_json(args.json, {"specimen": specimen, "scenarios": rows, "confidence": 0.95},
               method="fit_loop on synthetic rigs (torsional_contact.fitting.synthetic)", draws=args.draws,
               seed=args.seed, cycles=args.cycles, samples_per_cycle=args.samples_per_cycle)
    write_text(args.tex, table(rows))
    macros = {"ft-draws": str(args.draws), "ft-samples": str(int(round(args.cycles * args.samples_per_cycle)) + 1),
              "ft-cycles": f"{args.cycles:g}", "ft-friction": f"{specimen['friction']:g}",
              "ft-modulus-gpa": f"{specimen['shear_modulus'] / 1e9:g}",
              "ft-compliance": f"{sci(specimen['compliance'], 1)}", "ft-radius-mm": f"{specimen['radius'] * 1e3:g}",
              "ft-force-n": f"{specimen['normal_force']:g}"}
    for r in rows:
        key = r["name"]
        for short, name in (("f", "friction"), ("g", "shear_modulus"), ("c", "compliance")):
            macros[f"ft-{key}-cov-{short}"] = _cell(r[name])
            macros[f"ft-{key}-err-{short}"] = _error(r[name])
        macros[f"ft-{key}-twist-noise"] = sci(r["twist_noise"], 1)
        macros[f"ft-{key}-flagged"] = f"{100 * r['noise_limited']:.0f}"
        macros[f"ft-{key}-g-found"] = f"{100 * r['shear_modulus']['reported']:.0f}"
        macros[f"ft-{key}-torque-noise-pct"] = f"{100 * r['torque_noise_fraction']:.2g}"
    write_macros(args.macros, macros, "workflow/scripts/friction_test_coverage.py")


if __name__ == "__main__":
    main()
