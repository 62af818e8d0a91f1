"""Oscillating torque: hysteresis loops T* against omega, dissipation per cycle against the
torque range (with the threshold law), and the torsional compliance d omega / d T*.

Units: omega in f p0 / mu; energy per cycle in (f p0)^2 a^3 / mu.  Reads the history data.
"""


from _plotting import figure_parser, load_data, save_figure, subplots, use_style


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    data = load_data(a.data)
    use_style(a.style)
    # three panels at the width of the text column (16 cm): the fonts print at their nominal size
    fig, (loops, law, compliance) = subplots(1, 3, figsize=(6.3, 2.9))
    for loop in data["loops"]:
        label = f"$[{loop['t_min']:g}, {loop['t_max']:g}]$"
        if loop["t_max"] - loop["t_min"] <= 2.0:
            # a range below 2 is elastic: a vertical segment that lies on the sides of the wider loops, so it is
            # drawn wide and translucent on top of them, with its two ends marked
            label += " (elastic)"
            loops.plot(loop["rigid_rotation"], loop["torque"], lw=5, alpha=0.45, solid_capstyle="butt", zorder=3,
                       marker="o", markevery=[0, -1], ms=5, label=label)
        else:
            loops.plot(loop["rigid_rotation"], loop["torque"], label=label)
    loops.set_xlabel(r"rigid rotation $\omega\mu/f p_0$")
    loops.set_ylabel(r"$T^*$")
    handles, labels = loops.get_legend_handles_labels()
    d = data["dissipation_law"]
    law.loglog(d["eps"], d["dissipation"], "o", label="memory rules")
    law.loglog(d["eps"], d["asymptote"], "-", label=r"$(\pi^4/3)\,\epsilon^3$")
    law.set_xlabel(r"$\epsilon = \Delta T^*/2 - 1$")
    law.set_ylabel(r"energy per cycle $W\mu/((fp_0)^2a^3)$")
    law.legend(fontsize=8, loc="lower right")  # the data rise from lower left to upper right
    c = data["compliance"]
    compliance.semilogy(c["torque"], c["d_omega_d_torque"], "o-", label="first loading")
    compliance.semilogy(c["torque"], c["asymptote"], "--", label=r"$(\pi^3/4)(T^*-1)^2$")
    compliance.set_xlabel(r"$T^*$")
    compliance.set_ylabel(r"$d\omega/dT^*$")
    compliance.legend(fontsize=8, loc="lower right")
    fig.legend(handles, labels, title=r"loops $[T^*_{\min}, T^*_{\max}]$", loc="lower center",
               ncol=min(len(labels), 4), fontsize=8, title_fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.22, 1, 1))  # the legend of the loops below the panels, off the data
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
