"""Convergence: error of T* (against the converged fast solution) against the resolution,
with the weak forms (N sweep, beside the theoretical rate 1/N) and the exponential decay of the
Abel-Fredholm method (node sweep); reads the benchmark JSON."""


import numpy as np
from _plotting import figure_parser, load_data, rcParams, save_figure, subplots, use_style

FLOOR = 1e-16  # errors at or below it (rounding level, exact zeros included) are drawn here, open markers


def floored(ax, x, err, marker, color, label=None):
    """Plot errors; those at the rounding level at FLOOR with open markers (never silently clipped)."""
    err = np.asarray(err, dtype=float)
    shown = np.maximum(err, FLOOR)
    line = ax.plot(x, shown, marker, color=color, label=label, ms=4)[0]
    low = err <= FLOOR
    if low.any():
        ax.plot(np.asarray(x)[low], shown[low], marker[0], color=color, mfc="white", ms=5, zorder=5)
    return line


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    results = load_data(a.data)["results"]
    use_style(a.style)
    fig, (left, right) = subplots(1, 2, figsize=(6.3, 3.4))  # printed at the text width
    colors = rcParams["axes.prop_cycle"].by_key()["color"]
    for result, color in zip(results, colors, strict=False):
        b = result["stick_radius"]
        for method, marker in (("complete", "o-"), ("published", "s:")):
            rows = [r for r in result["rows"] if r["method"] == method]
            n = np.array([r["resolution"] for r in rows], dtype=float)
            err = np.array([r["torque_error"] for r in rows])
            name = "reconstructed printed scheme" if method == "published" else "complete weak form"
            floored(left, n, err, marker, color, f"{name}, $b/a={b:g}$")
            if method == "complete" and b == results[len(results) // 2]["stick_radius"] and n.size:
                # the theoretical rate 1/N through the first point (not a fit)
                left.plot(n, err[0] * n[0] / n, "--", color="k", lw=0.8, zorder=5, label=r"$\propto 1/N$ (theory)")
        rows = [r for r in result["rows"] if r["method"] == "fast"]
        floored(right, [r["resolution"] for r in rows], [r["torque_error"] for r in rows], "D-", color,
                f"$b/a = {b:g}$")
    left.set_xscale("log")
    left.set_yscale("log")
    right.set_yscale("log")
    floor = f"$10^{{{round(np.log10(FLOOR))}}}$"  # FLOOR in the figure's notation, not code's
    right.plot([], [], "D", color="0.4", mfc="white", label=f"at rounding level (drawn at {floor})")
    sizes = sorted({r["resolution"] for r in results[0]["rows"] if r["method"] == "complete"})
    left.set_xticks(sizes, [str(n) for n in sizes])
    left.minorticks_off()
    left.set_xlabel("weak forms: number of terms N")
    left.set_ylabel(r"$|T^* - T^*_{\rm converged}|$")
    # below the axes, under the x label (each axis label names its method: no legend title to collide with it)
    handles, labels = left.get_legend_handles_labels()
    last = [i for i, label in enumerate(labels) if "theory" in label]  # the theory line last, after the pairs
    order = [i for i in range(len(labels)) if i not in last] + last
    left.legend([handles[i] for i in order], [labels[i] for i in order], fontsize=7.5, ncol=1, loc="upper center",
                bbox_to_anchor=(0.5, -0.24), frameon=False)
    right.set_xlabel("Abel-Fredholm: Nystr\u00f6m nodes")
    right.set_ylabel(r"$|T^* - T^*_{\rm converged}|$")
    right.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.24), frameon=False)
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
