"""Fig. 2a-c: contours of sigma_zt, sigma_rt (units f p0) and u_theta (f p0 a / mu) for one b/a.

One figure per --quantity, all from one solution.  Computes only what the plots need: fields
on an (r, z) grid with the per-point series truncated at the plot tolerance (default 1e-4 of
f p0), the stresses once for both stress panels.
"""


import numpy as np
from _plotting import figure_files, figure_parser, method_options, save_figure, subplots, use_style
from matplotlib.ticker import MaxNLocator

from torsional_contact import solve

LABELS = {
    "sigma_zt": r"$\sigma_{\theta z}/f p_0$",
    "sigma_rt": r"$\sigma_{r\theta}/f p_0$",
    "u_theta": r"$u_\theta\,\mu/(f p_0 a)$",
}


def main():
    p = figure_parser(__doc__, quantities=LABELS)
    p.add_argument("--stick-radius", type=float, required=True)
    p.add_argument("--nr", type=int, default=121)
    p.add_argument("--nz", type=int, default=101)
    p.add_argument("--z-max", type=float, default=1.0)
    p.add_argument("--tolerance", type=float, default=1e-4)
    a = p.parse_args()

    figures = figure_files(p, a)

    # plot accuracy, not table accuracy: fewer Dini terms off the interface
    s = solve(stick_radius=a.stick_radius, tolerance=a.tolerance, **method_options(a))
    r = np.linspace(0.0, 1.0, a.nr)
    z = np.linspace(0.0, a.z_max, a.nz)
    rr, zz = np.meshgrid(r, z)
    fields = {}
    if {"sigma_zt", "sigma_rt"} & set(a.quantity):
        fields["sigma_zt"], fields["sigma_rt"] = s.stress(rr, zz)[:2]
    if "u_theta" in a.quantity:
        fields["u_theta"] = s.displacement(rr, zz)

    use_style(a.style)
    for quantity, pdf, png in figures:
        values = fields[quantity]
        fig, ax = subplots(figsize=(1.86, 2.3))  # three in a row at the text width: fonts at nominal size
        levels = 21
        filled = ax.contourf(rr, zz, values, levels=levels, cmap="viridis")
        ax.contour(rr, zz, values, levels=filled.levels, colors="k", linewidths=0.3)
        ax.axvline(a.stick_radius, color="w", ls="--", lw=0.8)
        # the zones are named above the frame, between it and the colour bar: inside, the labels would sit on the
        # contours (those of sigma_rt crowd at the interface in the slip zone)
        for x, zone in ((a.stick_radius / 2, "stick"), ((1 + a.stick_radius) / 2, "slip")):
            ax.text(x, 1.02, zone, transform=ax.get_xaxis_transform(), ha="center", va="bottom")
        ax.set_xlabel(r"$r/a$")
        ax.set_ylabel(r"$z/a$")
        bar = fig.colorbar(filled, ax=ax, label=LABELS[quantity], location="top", pad=0.14, aspect=25)
        bar.locator = MaxNLocator(4)  # legible ticks on a bar the width of a third of the text
        bar.update_ticks()
        ax.set_xticks([0.0, 0.5, 1.0])
        ax.grid(False)
        save_figure(fig, pdf, png)

if __name__ == "__main__":
    main()
