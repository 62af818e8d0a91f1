"""Fig. 3: stick radius b/a against T* = 2T/(f F a): converged (Abel-Fredholm), the complete weak form
and the reconstructed printed scheme under two closures at the paper's N (reads the CSV of
workflow/scripts/torque_curve.py).

Each weak-form column of the CSV is defined on its own grid (nan elsewhere), so each curve is
drawn through its finite rows only.  Where a curve leaves the plotted T* range it is cut at the
frame and the exit is marked with an arrow head.
"""

import io

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

#: Plotted T* range: slip onset to a little beyond spinning.
T_RANGE = (0.98, 1.5)


def finite_rows(data, column):
    """(T*, b) of the rows where ``column`` is finite, in order of b."""
    keep = np.isfinite(data[column])
    return data[column][keep], data["stick_radius"][keep]


def main():
    p = figure_parser(__doc__)
    p.add_argument("--csv", required=True)
    p.add_argument("--n-terms", type=int, required=True)
    a = p.parse_args()
    with open(a.csv, encoding="utf-8") as handle:
        rows = "".join(line for line in handle if not line.startswith("#"))
    data = np.genfromtxt(io.StringIO(rows), delimiter=",", names=True)
    use_style(a.style)
    fig, ax = subplots(figsize=(4.4, 3.3))
    ax.axvspan(4 / 3, T_RANGE[1], color="0.92", lw=0)
    ax.text(0.5 * (4 / 3 + T_RANGE[1]), 0.97, "above spinning:\nimpossible", ha="center", va="top", fontsize=8,
            color="0.35")
    curves = (
        # the complete weak form lies on the converged curve at this scale: the converged curve is a wide grey band
        # and the complete weak form a dark line with markers on top of it, so that both stay visible
        ("torque_fast", dict(color="0.72", lw=5.0, solid_capstyle="butt", label="converged (Abel–Fredholm)")),
        ("torque_complete", dict(color="C0", lw=1.0, marker="o", ms=3.2, mfc="white", markevery=0.06,
                                 label=f"complete weak form, $N = {a.n_terms}$")),
        ("torque_published", dict(color="C1", lw=1.3, label="reconstructed printed scheme,\nclosure (C1), $q(b) = 1$")),
        ("torque_published_torque_closure",
         dict(color="C2", lw=1.3, ls=(0, (1, 1.2)), label="reconstructed printed scheme,\nclosure (C3), torque")),
    )
    for column, style in curves:
        if column not in data.dtype.names:
            continue
        torque, b = finite_rows(data, column)
        off = torque > T_RANGE[1]
        ax.plot(np.where(off, np.nan, torque), b, **style)
        if off.any():  # the curve leaves the frame: mark where, with the largest T* it reaches
            exit_b = b[off].max()
            ax.plot([T_RANGE[1]], [exit_b], marker=">", color=style["color"], ms=6, clip_on=False)
            # the largest T* on this curve's grid, and where: the grid reaches smaller b than the tables
            peak_b = b[int(np.argmax(torque))]
            ax.annotate(f"$T^*$ up to {torque.max():.2f}\nat $b/a = {peak_b:.3f}$", (T_RANGE[1], exit_b),
                        xytext=(-4, -10), textcoords="offset points", ha="right", va="top", fontsize=8,
                        color=style["color"])
    ax.axvline(1.0, color="0.5", lw=0.8)
    ax.axvline(4 / 3, color="0.5", lw=0.8)
    ax.text(1.0, 1.01, "slip onset", transform=ax.get_xaxis_transform(), ha="left", va="bottom")
    ax.text(4 / 3, 1.01, "spinning", transform=ax.get_xaxis_transform(), ha="center", va="bottom")
    ax.set_xlim(*T_RANGE)
    ax.set_ylim(0, 1.0)
    ax.set_xlabel(r"$T^* = 2T/(fFa)$")
    ax.set_ylabel(r"stick radius $b/a$")
    fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=2, fontsize=8, handlelength=2.6,
               frameon=False)
    fig.tight_layout(rect=(0, 0.22, 1, 1))  # the legend below the axes and its x label, off the curves
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
