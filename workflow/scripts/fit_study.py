"""The loop fit on rig records with defects (``torsional_contact.verification.fit_study``): data, table, macros.

Reads the ``fit_study`` section of the configuration (JSON on the command line), runs every scenario with the fit's
handling on and off and the gross-slip window (loop fit against the plateau estimator), and writes a JSON data
file and a CSV (both with metadata: method, replicates, seed, package versions), the LaTeX tables (scenarios;
window) and the macros of the text.  ``--replicates`` and ``--long-replicates`` override the configuration's
counts (a full study run).
Units: friction 1, G Pa, compliance rad/(N m), bias and rates in per cent in the table.
"""

import argparse
import csv
import io
import json
import time

from torsional_contact.provenance import latex_escape, provenance, write_json, write_macros, write_text
from torsional_contact.typeset import sci
from torsional_contact.verification.fit_study import (
    PARAMETERS,
    Scenario,
    clopper_pearson,
    per_cycle_study,
    run_study,
    window_study,
)
from torsional_contact.verification.rig_records import RigSpecimen

SYMBOLS = {"friction": "f", "shear_modulus": "G", "compliance": "C"}
#: The scenarios of the configuration in words, for the text (the tables name them by their identifiers).
DESCRIPTIONS = {
    "clean": "the clean record",
    "stuck-lag": "the lag on a contact that stays stuck",
    "lag": "the lag of the twist channel",
    "spikes": "the spikes on the twist",
    "exact-torque": "the commanded (exact) torque channel",
    "exact-gross": "the commanded (exact) torque channel of a twist-controlled record into gross slip",
    "drift": "the drift of the twist",
    "offset": "the zero offset of the torque",
    "non-virgin": "the record without its first half cycle",
    "inverted": "the inverted twist channel",
    "quantised": "the quantised channels",
    "running-in": "the running-in record",
    "model-hertz": "the record of a sphere on a flat read with the cylinders' model",
    "model-flat-punch": "the record of a flat punch read with the cylinders' model",
    "long": "the long record",
    "long-lag": "the long record whose twist lags",
    "long-stuck-lag": "the long record of a stuck contact whose twist lags",
}


def _pct(x, digits=0):
    return "--" if x is None else f"{100 * x:.{digits}f}"


def _kn(rate):
    """'k/n [lo, hi]' of a rate with its Clopper-Pearson interval (per cent), '--' without trials."""
    if not rate["trials"]:
        return "--"
    lo, hi = rate["interval"]
    return f"{rate['count']}/{rate['trials']} [{100 * lo:.0f}, {100 * hi:.0f}]"


def _bias(entry):
    if entry["median_bias"] is None:
        return "--"
    b = 100 * entry["median_bias"]
    if abs(b) < 1e-3:  # scientific notation in LaTeX, not Python's "e-07"
        text = ("+" if b >= 0 else "") + sci(b, 1)
    else:
        text = f"{b:+.2g}" if abs(b) < 10 else f"{b:+.0f}"
    if entry["median_bias_stderr"] is not None:
        text += f" \\pm {100 * entry['median_bias_stderr']:.2g}"
    return f"${text}$"


def scenario_table(rows, replicates: int) -> str:
    # a long table (one block of rows per record and handling runs over a page): its caption is the paper's
    # \fitstudycaption, its head repeated on each page, no page break inside a block
    header = r"record & handling & samples & & interval coverage & bound coverage & median bias [\%] & warned \\"
    lines = [r"\setlength{\tabcolsep}{3pt}", r"\begin{longtable}{llrllllr}",
             r"\caption{\fitstudycaption}\label{tab:fit-study}\\", r"\hline", header, r"\hline", r"\endfirsthead",
             r"\hline", header, r"\hline", r"\endhead"]
    for row in rows:
        head = [latex_escape(row["scenario"]), row["mode"], str(row["samples"])]
        if row["summary"] is None:
            missing = ", ".join(row["not_available"]) or "no switch"
            cell = rf"\multicolumn{{5}}{{l}}{{handling not available ({latex_escape(missing)})}}"
            lines.append(" & ".join(head + [cell]) + r" \\")
            continue
        s = row["summary"]
        for j, key in enumerate(PARAMETERS):
            e = s[key]
            cells = (head if j == 0 else ["", "", ""]) + [f"${SYMBOLS[key]}$", _kn(e["interval_coverage"]),
                                                           _kn(e["bound_coverage"]), _bias(e),
                                                           _kn(s["warned"]) if j == 0 else ""]
            lines.append(" & ".join(cells) + (r" \\*" if j < len(PARAMETERS) - 1 else r" \\"))
        if s["refused"]["count"]:
            lines.append(rf" & & & \multicolumn{{5}}{{l}}{{refused with an error: {_kn(s['refused'])}}} \\")
        lines.append(r"\hline")
    word = "record" if replicates == 1 else "records"
    lines += [r"\end{longtable}",
              rf"\par\footnotesize {replicates} {word} per row: rates as $k/n$ with exact 95\,\% "
              r"(Clopper--Pearson) intervals in per cent."]
    return "\n".join(lines) + "\n"


def window_table(rows) -> str:
    # the twist amplitude tells apart the records that ride the plateau (their max T* is the gross-slip torque)
    lines = [r"\begin{tabular}{rrllll}", r"\hline",
             r"$\max T^*$ & twist amplitude & \multicolumn{3}{l}{loop fit} & plateau \\",
             r" & [mrad] & $f$ coverage & $f$ bias [\%] & $G$ identified & $f$ bias [\%] \\",
             r"\hline"]
    for row in rows:
        fit = row["fit"]
        lines.append(" & ".join([f"{row['max_torque_ratio']:.4g}", f"{1e3 * row['twist_amplitude']:.3g}",
                                 _kn(fit["friction"]["interval_coverage"]),
                                 _bias(fit["friction"]), _kn(fit["shear_modulus"]["identified"]),
                                 _bias(row["plateau"])]) + r" \\")
    lines += [r"\hline", r"\end{tabular}"]
    return "\n".join(lines) + "\n"


def csv_text(rows, window, meta) -> str:
    out = io.StringIO()
    for key, value in meta.items():
        out.write(f"# {key}: {json.dumps(value, sort_keys=True)}\n")
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["study", "record", "handling", "samples", "max_torque_ratio", "parameter", "identified",
                     "interval_covered", "intervals", "interval_cp_low", "interval_cp_high", "bound_covered",
                     "bounds", "median_bias", "median_bias_stderr", "warned", "named", "refused", "records",
                     "not_available"])
    for row in rows:
        s = row["summary"]
        for key in PARAMETERS:
            if s is None:
                writer.writerow(["defects", row["scenario"], row["mode"], row["samples"], row["max_torque_ratio"], key]
                                + [""] * 13 + [";".join(row["not_available"]) or "no switch"])
                continue
            e = s[key]
            writer.writerow(["defects", row["scenario"], row["mode"], row["samples"], row["max_torque_ratio"], key,
                             e["identified"]["count"], e["interval_coverage"]["count"],
                             e["interval_coverage"]["trials"], e["interval_coverage"]["interval"][0],
                             e["interval_coverage"]["interval"][1], e["bound_coverage"]["count"],
                             e["bound_coverage"]["trials"], e["median_bias"], e["median_bias_stderr"],
                             s["warned"]["count"], s["named"]["count"], s["refused"]["count"], s["records"],
                             ";".join(row["not_available"])])
    for row in window:
        for method, entry in (("loop fit", row["fit"]["friction"]), ("plateau", row["plateau"])):
            cov = entry["interval_coverage"]
            writer.writerow(["window", f"twist amplitude {row['twist_amplitude']:.4g} rad", method, "",
                             row["max_torque_ratio"], "friction", "", cov["count"], cov["trials"], cov["interval"][0],
                             cov["interval"][1], "", "", entry["median_bias"], entry["median_bias_stderr"],
                             "", "", "", "", ""])
    return out.getvalue()


def macros(rows, window, config, replicates, long_replicates) -> dict:
    out = {"fs-replicates": str(replicates), "fs-long-replicates": str(long_replicates),
           "fs-records-word": "record" if replicates == 1 else "records",
           "fs-friction": f"{config['specimen']['friction']:g}",
           "fs-modulus-gpa": f"{config['specimen']['shear_modulus'] / 1e9:g}",
           "fs-radius-mm": f"{config['specimen']['radius'] * 1e3:g}",
           "fs-gauge-mm": f"{config['specimen']['gauge_length'] * 1e3:g}",
           "fs-force-n": f"{config['specimen']['normal_force']:g}",
           "fs-scenarios": str(len({r['scenario'] for r in rows})),
           "fs-samples": str(min(r["samples"] for r in rows))}
    for row in rows:
        if row["summary"] is None:
            continue
        s, key = row["summary"], f"fs-{row['scenario']}-{row['mode']}"
        f = s["friction"]
        out[f"{key}-f-cov"] = (f"{f['interval_coverage']['count']}/{f['interval_coverage']['trials']}"
                               if f["interval_coverage"]["trials"] else "--")
        out[f"{key}-f-bias"] = _pct(f["median_bias"], 1)
        out[f"{key}-honest"] = f"{s['honest']['count']}/{s['honest']['trials']}"
        out[f"{key}-warned"] = f"{s['warned']['count']}/{s['warned']['trials']}"
        for name in ("shear_modulus", "compliance"):
            e = s[name]["interval_coverage"]
            out[f"{key}-{SYMBOLS[name].lower()}-cov"] = f"{e['count']}/{e['trials']}" if e["trials"] else "--"
            out[f"{key}-{SYMBOLS[name].lower()}-bias"] = _pct(s[name]["median_bias"], 1)
    for mode in ("on", "off"):
        honest = [r["summary"]["honest"] for r in rows if r["mode"] == mode and r["summary"]]
        out[f"fs-honest-{mode}"] = str(sum(h["count"] for h in honest))
        out[f"fs-records-{mode}"] = str(sum(h["trials"] for h in honest))
    lo, hi = clopper_pearson(replicates, replicates)
    out["fs-cp-all-lo"], out["fs-cp-all-hi"] = f"{100 * lo:.0f}", f"{100 * hi:.0f}"
    clean = Scenario("clean", "torque", 1.0)  # the noise of a scenario that states none
    out["fs-torque-noise-pct"] = f"{100 * clean.torque_noise:g}"
    out["fs-twist-noise-urad"] = f"{1e6 * clean.twist_noise:g}"
    out["fs-long-samples"] = str(int(round(config["long"]["cycles"] * config["long"]["sample_rate"]
                                           / config["long"]["frequency"])))
    out["fs-record-cycles"] = f"{config['cycles']:g}"
    out["fs-sample-rate"] = f"{config['sample_rate']:g}"
    failing = sorted({r["scenario"] for r in rows if r["mode"] == "on" and r["summary"]
                      and r["summary"]["honest"]["count"] < r["summary"]["honest"]["trials"]})
    out["fs-failing"] = latex_escape(", ".join(failing) if failing else "none")
    # the same in words, with the parameters whose interval or bound missed the truth
    words = []
    for name in failing:
        row = next(r for r in rows if r["scenario"] == name and r["mode"] == "on")
        missed = [f"${SYMBOLS[key]}$" for key in PARAMETERS
                  if any(row["summary"][key][kind]["count"] < row["summary"][key][kind]["trials"]
                         for kind in ("interval_coverage", "bound_coverage"))]
        text = latex_escape(DESCRIPTIONS.get(name, name))
        words.append(text + (f" (the interval or bound on {' and '.join(missed)} missed the truth)" if missed else ""))
    out["fs-failing-words"] = "; ".join(words) if words else "none"
    for j, row in enumerate(window):
        out[f"fs-window-{j}-tmax"] = f"{row['max_torque_ratio']:.3g}"
        out[f"fs-window-{j}-plateau-bias"] = _pct(row["plateau"]["median_bias"], 1)
        out[f"fs-window-{j}-fit-bias"] = _pct(row["fit"]["friction"]["median_bias"], 1)
    out["fs-window-count"] = str(len(window))
    gross = RigSpecimen(**config["specimen"]).contact.gross_slip_torque
    for tag, row in (("first", window[0]), ("last", window[-1])):
        out[f"fs-window-{tag}-tmax"] = f"{row['max_torque_ratio']:.4g}"
        # the plateau estimator's least bias below gross slip, 1 - max T* / T*_gs (it reads at most the peak)
        out[f"fs-window-{tag}-bound"] = _pct(max(1.0 - row["max_torque_ratio"] / gross, 0.0), 1)
        out[f"fs-window-{tag}-plateau-bias"] = _pct(row["plateau"]["median_bias"], 1)
        out[f"fs-window-{tag}-fit-bias"] = _pct(row["fit"]["friction"]["median_bias"], 1)
        out[f"fs-window-{tag}-twist-mrad"] = f"{1e3 * row['twist_amplitude']:.3g}"
    return out


def per_cycle_macros(study) -> dict:
    """The text's numbers of the per-cycle study (none without one)."""
    if study is None:
        return {}
    strict, in_range = study["interval_coverage"], study["range_coverage"]
    out = {"fs-pc-records": str(study["records"]), "fs-pc-cycles": str(study["cycles"]),
           "fs-pc-records-word": "record" if study["records"] == 1 else "records",
           "fs-pc-cov": f"{strict['count']}/{strict['trials']}",
           "fs-pc-range-cov": f"{in_range['count']}/{in_range['trials']}",
           "fs-pc-bias": _pct(study["median_bias"], 2), "fs-pc-within": _pct(study["within"], 1)}
    if strict["trials"]:
        out["fs-pc-cov-lo"], out["fs-pc-cov-hi"] = (f"{100 * x:.0f}" for x in strict["interval"])
    return out


def scenarios_of(config, long_replicates: int):
    out = []
    for entry in config["scenarios"]:
        entry = dict(entry)
        long = entry.pop("long", False)
        if long:
            if not long_replicates:
                continue
            entry.update(cycles=config["long"]["cycles"], frequency=config["long"]["frequency"],
                         sample_rate=config["long"]["sample_rate"])
        else:
            entry.setdefault("cycles", config["cycles"])
            entry.setdefault("sample_rate", config["sample_rate"])
        out.append((Scenario(**entry), long))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--config", required=True, help="JSON: the fit_study section of the configuration")
    parser.add_argument("--replicates", type=int, help="records per scenario and handling (default: the config's)")
    parser.add_argument("--long-replicates", type=int, help="10^5-sample records per long scenario (default: the "
                        "config's)")
    for name in ("json", "csv", "tex", "window-tex", "macros"):
        parser.add_argument(f"--{name}", required=True)
    args = parser.parse_args()
    config = json.loads(args.config)
    replicates = config["replicates"] if args.replicates is None else args.replicates
    if replicates < 1:
        parser.error(f"--replicates must be >= 1, got {replicates}")
    long_replicates = config["long_replicates"] if args.long_replicates is None else args.long_replicates
    if long_replicates < 0:
        parser.error(f"--long-replicates must be >= 0, got {long_replicates}")
    cycled = None  # the scenario (a running-in record) whose cycles are fitted one by one, checked before any fit
    if config.get("per_cycle"):
        cycled = next((s for s, _ in scenarios_of(config, 0) if s.name == config["per_cycle"]), None)
        if cycled is None:
            parser.error(f"fit_study.per_cycle names no scenario of the configuration: {config['per_cycle']!r}")
    specimen = RigSpecimen(**config["specimen"])
    started = time.process_time()
    chosen = scenarios_of(config, long_replicates)
    rows = []
    short = [s for s, long in chosen if not long]
    rows += run_study(short, replicates=replicates, seed=config["seed"], specimen=specimen,
                      progress=lambda r: print(r["scenario"], r["mode"], json.dumps(r["summary"]["honest"]),
                                               flush=True))  # the log
    longs = [s for s, long in chosen if long]
    if longs:
        rows += run_study(longs, replicates=long_replicates, seed=config["seed"] + 1, specimen=specimen,
                          modes=("on",))
    window = window_study(config["window"]["levels"], config["window"]["plateau_twists"], replicates=replicates,
                          seed=config["seed"] + 2, specimen=specimen, cycles=config["cycles"],
                          sample_rate=config["sample_rate"])
    per_cycle = None
    if cycled is not None:
        per_cycle = per_cycle_study(cycled, replicates=replicates, seed=config["seed"] + 3, specimen=specimen)
    print(f"fit study: {time.process_time() - started:.1f} CPU-s", flush=True)  # the log, not the data
    meta = {"method": "fit_loop on rig records (verification.rig_records), handling on and off; plateau estimator",
            "replicates": replicates, "long_replicates": long_replicates, "seed": config["seed"],
            "specimen": config["specimen"]}
    write_json(args.json, {"scenarios": rows, "window": window, "per_cycle": per_cycle, "config": config}, **meta)
    write_text(args.csv, csv_text(rows, window, provenance(**meta)))
    write_text(args.tex, scenario_table(rows, replicates))
    write_text(args.window_tex, window_table(window))
    write_macros(args.macros, {**macros(rows, window, config, replicates, long_replicates),
                               **per_cycle_macros(per_cycle)}, "workflow/scripts/fit_study.py")


if __name__ == "__main__":
    main()
