"""Fig. 5: interface traction (units f p0) after loading to T*max and relaxing in stages.

Reads the history data (workflow/scripts/history_data.py); computes nothing itself.  Solid:
the converged (Abel-Fredholm) memory rules; dashed: the residual traction of the paper's
setting (complete weak form, N = 145), when the data carry it.
"""


import numpy as np
from _plotting import figure_parser, load_data, save_figure, subplots, use_style


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    f5 = load_data(a.data)["fig5"]
    r = np.array(f5["radii"])
    use_style(a.style)
    fig, ax = subplots(figsize=(4.6, 3.4))  # printed at its size, the legend below it
    for torque, traction in zip(f5["stages"], f5["traction"], strict=True):
        style = "k-" if torque == 0 else "-"
        label = f"$T^* = {torque:g}$" + (" (residual)" if torque == 0 else "")
        ax.plot(r, traction, style, label=label, lw=1.8 if torque == 0 else 1.2)
    weak = load_data(a.data).get("fig5_weak")
    if weak is not None:  # the paper's setting beside the converged curves, labelled as such
        ax.plot(np.array(weak["radii"]), weak["residual_traction"], "--", color="0.45", lw=1.0,
                label=f"residual, complete weak form, $N = {weak['n_terms']}$ (the original's truncation)")
    ax.axhline(1, color="0.5", lw=0.7)
    ax.axhline(-1, color="0.5", lw=0.7)
    ax.axvline(f5["loading_stick_radius"], color="0.5", ls=":", lw=0.8)
    ax.set_xlabel(r"$r/a$")
    ax.set_ylabel(r"$\sigma_{\theta z}(r,0)/f p_0$")
    ax.set_xlim(0, 1)
    ax.set_ylim(-1.1, 1.1)
    ax.legend(title=f"loaded to $T^* = {f5['t_max']:g}$ ($b/a = {f5['loading_stick_radius']:.4f}$)", ncol=2,
              loc="upper center", bbox_to_anchor=(0.5, -0.2), fontsize=7.5, title_fontsize=8, frameon=False)
    fig.tight_layout()  # makes room for the legend below the axes
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
