"""Oscillating torque: hysteresis loops T* against omega, dissipation per cycle against the
torque range (with the threshold law), and the torsional compliance d omega / d T*.

Units: omega in f p0 / mu; energy per cycle in (f p0)^2 a^3 / mu.  Reads the history data.
"""


import numpy as np
from _plotting import figure_parser, load_data, save_figure, subplots, use_style

#: Legends inside the narrow centre and right panels: short handles and padding, so that they keep to the
#: empty upper left corner.
COMPACT = dict(fontsize=7.5, handlelength=1.4, handletextpad=0.4, borderpad=0.3, borderaxespad=0.3, labelspacing=0.3)


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
            # a range below 2 is elastic: a vertical segment that lies on a side of a wider loop (the unloading
            # branch from the same turning point), so it is drawn thin and dashed on top of it, the loop showing
            # through the gaps, with its two ends marked by bars
            label += " (elastic)"
            # (the path runs up and back down the same segment: drawn once, from its lowest to its highest torque,
            # else the dashes of the two passes fill each other's gaps)
            omega = loop["rigid_rotation"][int(np.argmax(loop["torque"]))]
            loops.plot([omega, omega], [min(loop["torque"]), max(loop["torque"])], color="k", lw=1.0,
                       ls=(0, (2.5, 2)), zorder=4, marker="_", ms=7, mew=1.4, label=label)
        else:
            loops.plot(loop["rigid_rotation"], loop["torque"], label=label)
    loops.margins(x=0.08)  # room for the end bars of a segment on the outermost branch
    loops.set_xlabel(r"rigid rotation $\omega\mu/f p_0$")
    loops.set_ylabel(r"$T^*$")
    handles, labels = loops.get_legend_handles_labels()
    d = data["dissipation_law"]
    law.loglog(d["eps"], d["dissipation"], "o", ms=4.5, label="memory rules")
    law.loglog(d["eps"], d["asymptote"], "-", label=r"$(\pi^4/3)\,\epsilon^3$")
    law.set_xlabel(r"$\epsilon = A/2 - 1$")
    law.set_ylabel(r"energy per cycle $W\mu/((fp_0)^2a^3)$")
    law.legend(loc="upper left", **COMPACT)  # the data rise from lower left to upper right: upper left is free
    c = data["compliance"]
    compliance.semilogy(c["torque"], c["d_omega_d_torque"], "o-", ms=4.5, label="first loading")
    compliance.semilogy(c["torque"], c["asymptote"], "--", label=r"$(\pi^3/4)(T^*-1)^2$")
    compliance.set_xlabel(r"$T^*$")
    compliance.set_ylabel(r"$d(\omega\mu/fp_0)/dT^*$")
    compliance.legend(loc="upper left", **COMPACT)  # as in the centre panel: the data leave upper left free
    fig.legend(handles, labels, title=r"loops $[T^*_{\min}, T^*_{\max}]$", loc="lower center",
               ncol=min(len(labels), 4), fontsize=8, title_fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.22, 1, 1))  # the legend of the loops below the panels, off the data
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
