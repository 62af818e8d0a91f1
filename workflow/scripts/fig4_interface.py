"""Fig. 4a-c: interface traction sigma_zt(r,0), sigma_rt(r,0) (units f p0) and slip
(units f p0 a / mu) for several b/a.

One figure per --quantity, each b/a solved once for all of them."""


import numpy as np
from _plotting import figure_files, figure_parser, method_label, method_options, save_figure, subplots, use_style

from torsional_contact import solve

LABELS = {
    "traction": r"$\sigma_{\theta z}(r,0)/f p_0$",
    "sigma_rt": r"$\sigma_{r\theta}(r,0)/f p_0$",
    "slip": r"slip $s\,\mu/(f p_0 a)$",
}

#: Panel letters in the manuscript's order (its caption names the panels (a)-(c)).
PANELS = {"traction": "a", "sigma_rt": "b", "slip": "c"}


def main():
    p = figure_parser(__doc__, quantities=LABELS)
    p.add_argument("--stick-radii", type=float, nargs="+", required=True)
    p.add_argument("--n-points", type=int, default=801)
    a = p.parse_args()

    figures = figure_files(p, a)

    r = np.linspace(0.0, 1.0, a.n_points)
    use_style(a.style)
    panels = {quantity: subplots(figsize=(3.1, 2.2)) for quantity, _, _ in figures}  # half the text width
    for b in a.stick_radii:
        s = solve(stick_radius=b, **method_options(a))
        for quantity, (_, ax) in panels.items():
            if quantity == "traction":
                y = s.traction(r)
            elif quantity == "sigma_rt":
                y = s.stress(r, 0.0)[1]
            else:
                y = s.slip(r)
            ax.plot(r, y, label=f"$b/a = {b:g}$, $T^* = {s.torque:.4f}$")
    for quantity, pdf, png in figures:
        fig, ax = panels[quantity]
        if quantity == "traction":
            ax.axhline(1.0, color="0.5", lw=0.8)
        ax.set_xlabel(r"$r/a$")
        ax.set_ylabel(LABELS[quantity])
        ax.set_xlim(0, 1)
        ax.set_title(f"({PANELS[quantity]})", loc="left", pad=3)  # above the frame, off the curves
        if quantity == figures[-1][0]:
            # the panels share one legend: beside the last panel (the manuscript sets it alone in the row below
            # the other two), where it covers no curve (inside any panel it would)
            ax.legend(title=method_label(s), fontsize=7.5, title_fontsize=7.5, loc="center left",
                      bbox_to_anchor=(1.06, 0.5), frameon=False)
        save_figure(fig, pdf, png)

if __name__ == "__main__":
    main()
