"""Work-precision diagram: wall time (median of repeats) against the error in T* and in the
interface traction (units f p0), for each method; reads the benchmark JSON."""


import numpy as np
from _plotting import figure_parser, load_data, save_figure, subplots, use_style

STYLE = {"published": ("s:", "reconstructed printed scheme, N sweep"), "complete": ("o-", "complete, N sweep"),
         "fast": ("D-", "Abel-Fredholm, node sweep"),
         "reference": ("^--", "complete, N = 145, digits sweep (T* only)")}
FLOOR = 1e-16  # errors at the rounding level (exact zeros included) are drawn here, with open markers


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    data = load_data(a.data)
    results = data["results"]
    mid = results[len(results) // 2]
    use_style(a.style)
    fig, (left, right) = subplots(1, 2, figsize=(6.3, 3.4))  # printed at the text width
    for method, (marker, label) in STYLE.items():
        rows = [r for r in mid["rows"] if r["method"] == method]
        if not rows:
            continue
        ms = [1e3 * r["seconds"] for r in rows]
        line = left.loglog([max(r["torque_error"], FLOOR) for r in rows], ms, marker, label=label)[0]
        low = [(FLOOR, t) for r, t in zip(rows, ms, strict=True) if r["torque_error"] <= FLOOR]
        if low:
            left.plot(*zip(*low, strict=True), marker[0], color=line.get_color(), mfc="white", ms=7, zorder=5)
        with_traction = [r for r in rows if r["traction_error"] is not None]
        if with_traction:
            right.loglog([max(r["traction_error"], FLOOR) for r in with_traction],
                         [1e3 * r["seconds"] for r in with_traction], marker, label=label)
    for ax, what in ((left, r"$|T^*$ error$|$"), (right, r"max$_r$ |traction error| / $f p_0$")):
        ax.set_xlabel(what)
        ax.set_ylabel("wall time per stick radius [ms]")
        ax.invert_xaxis()
    floor = f"$10^{{{round(np.log10(FLOOR))}}}$"  # FLOOR in the figure's notation, not code's
    left.plot([], [], "D", color="0.4", mfc="white", label=f"at rounding level (drawn at {floor})")
    # two columns: three would make the legend wider than the text width, and the figure would be shrunk
    fig.legend(*left.get_legend_handles_labels(), fontsize=8, title=f"$b/a = {mid['stick_radius']:g}$",
               title_fontsize=8, loc="lower center", ncol=2, frameon=False)
    fig.tight_layout(rect=(0, 0.24, 1, 1))  # one legend for both panels, below them
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
