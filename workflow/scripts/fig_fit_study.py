"""The loop fit on rig records with defects: coverage of f with the handling on and off, and the gross-slip window.

Left: per record type, the rate at which the 95 % interval (or bound) of f covers the truth, with its exact
Clopper-Pearson interval, with the fit's handling on and off, and the rate of fits that warn.  Right: the relative
bias of f from the loop fit and from the plateau estimator f = T_gs / (T*_gs F a / 2) against the largest T* of a
twist-controlled record.  Reads results/data/fit_study.json (workflow/scripts/fit_study.py).
"""

import json

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style
from matplotlib import ticker

COLOURS = {"on": "C0", "off": "C3"}


def covered_rate(summary):
    """(k, n, [lo, hi]) of f: intervals and bounds that cover, and refusals counted as honest."""
    f = summary["friction"]
    k = f["interval_coverage"]["count"] + f["bound_coverage"]["count"]
    n = f["interval_coverage"]["trials"] + f["bound_coverage"]["trials"]
    return k, n


def main():
    p = figure_parser(__doc__)
    p.add_argument("--data", required=True)
    a = p.parse_args()
    data = json.loads(open(a.data, encoding="utf-8").read())
    rows, window = data["scenarios"], data["window"]
    names = list(dict.fromkeys(r["scenario"] for r in rows))
    use_style(a.style)
    fig, (cov, win) = subplots(1, 2, figsize=(6.3, 3.9), gridspec_kw={"width_ratios": [1.6, 1]})
    from scipy.special import betaincinv

    for offset, mode in ((-0.15, "on"), (0.15, "off")):
        first = True
        for j, name in enumerate(names):
            row = next((r for r in rows if r["scenario"] == name and r["mode"] == mode), None)
            if row is None or row["summary"] is None:
                continue
            k, n = covered_rate(row["summary"])
            y = j + offset
            if n:
                lo = 0.0 if k == 0 else betaincinv(k, n - k + 1, 0.025)
                hi = 1.0 if k == n else betaincinv(k + 1, n - k, 0.975)
                cov.errorbar([100 * k / n], [y], xerr=[[100 * (k / n - lo)], [100 * (hi - k / n)]], fmt="o",
                             color=COLOURS[mode], markersize=3, capsize=2, linewidth=0.8,
                             label=f"handling {mode}" if first else None)
                first = False
            else:
                refused = row["summary"]["refused"]["count"]
                # on its own mode's row (the other mode's bar may cross the row's middle)
                cov.text(25 if mode == "on" else 75, y, "refused: an error" if refused else "no interval",
                         fontsize=7, color=COLOURS[mode], va="center", ha="center")
            warned = row["summary"]["warned"]
            if warned["count"]:
                cov.plot([103], [y], marker="^", color=COLOURS[mode], markersize=4)
    cov.axvline(95, color="0.6", linewidth=0.6, linestyle="--")
    cov.set_yticks(range(len(names)), names, fontsize=7)
    cov.set_ylim(len(names) - 0.5, -0.5)  # first row on top, every row inside the axes
    cov.set_xlim(-5, 108)
    cov.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.13), ncol=2, frameon=False)
    cov.set_xlabel("f interval or bound covers the truth [%]")
    count = data["metadata"]["replicates"]
    cov.set_title(f"{count} {'record' if count == 1 else 'records'} per row;\ntriangles: the fit warned", fontsize=7)
    tmax = np.array([w["max_torque_ratio"] for w in window])
    amplitude = 1e3 * np.array([w["twist_amplitude"] for w in window])

    def bias(entry):
        return np.nan if entry["median_bias"] is None else 100 * entry["median_bias"]

    order = np.argsort(amplitude, kind="stable")
    win.plot(amplitude[order], [bias(window[i]["fit"]["friction"]) for i in order], "o-", markersize=3,
             label="loop fit", color="C0")
    win.plot(amplitude[order], [bias(window[i]["plateau"]) for i in order], "s--", markersize=4,
             markerfacecolor="none", label="plateau estimator", color="C2")  # open: the loop fit's dots show
    win.plot(amplitude[order], 100 * (tmax[order] / (4 / 3) - 1), "x", color="0.4", markersize=4,
             label="peak torque\nas plateau")
    low, high = win.get_ylim()
    win.set_ylim(low, high + 0.3 * (high - low))  # room for the T* labels above the curves
    for x, t in zip(amplitude, tmax, strict=True):
        win.annotate(f"{t:.4g}", (x, 0.97), xycoords=("data", "axes fraction"), fontsize=7, ha="center", va="top",
                     rotation=90, color="0.3")
    win.set_xscale("log")
    ticks = (0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0)
    win.set_xticks([t for t in ticks if amplitude.min() * 0.9 <= t <= amplitude.max() * 1.1])
    win.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    win.xaxis.set_minor_formatter(ticker.NullFormatter())
    win.tick_params(axis="x", labelsize=7)
    win.axhline(0, color="0.6", linewidth=0.6)
    win.set_xlabel("twist amplitude [mrad]")  # no sub- or superscripts: every glyph at 7 pt or more
    win.set_ylabel(r"median bias of $f$ [%]")
    win.set_title("gross-slip window (twist control);\nnumbers at the top: max T*", fontsize=7)
    win.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
