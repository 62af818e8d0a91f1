"""Fig. 5: interface traction (units f p0) after loading to T*max and relaxing in stages.

Reads the history data (workflow/scripts/history_data.py); computes nothing itself.
"""


import numpy as np

from torsional_contact.io.plotting import figure_parser, load_data, plt, save_figure, use_style


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    f5 = load_data(a.data)["fig5"]
    r = np.array(f5["radii"])
    use_style(a.style)
    fig, ax = plt.subplots()
    for torque, traction in zip(f5["stages"], f5["traction"], strict=True):
        style = "k-" if torque == 0 else "-"
        label = f"$T^* = {torque:g}$" + (" (residual)" if torque == 0 else "")
        ax.plot(r, traction, style, label=label, lw=1.8 if torque == 0 else 1.2)
    ax.axhline(1, color="0.5", lw=0.7)
    ax.axhline(-1, color="0.5", lw=0.7)
    ax.axvline(f5["loading_stick_radius"], color="0.5", ls=":", lw=0.8)
    ax.set_xlabel(r"$r/a$")
    ax.set_ylabel(r"$\sigma_{\theta z}(r,0)/f p_0$")
    ax.set_xlim(0, 1)
    ax.set_ylim(-1.1, 1.1)
    ax.legend(title=f"loaded to $T^* = {f5['t_max']:g}$ ($b/a = {f5['loading_stick_radius']:.3f}$)", ncol=2,
              loc="lower left")
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
