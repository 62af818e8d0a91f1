"""Predicted torsion test of a specimen in physical units: torque against the contact's twist for
several torque amplitudes (partial slip), and the energy dissipated per cycle against the amplitude.

Units: torque N m, twist urad (the contact's share 2 omega f p0 / G: the shaft's elastic twist,
linear in the torque, is left out so that the loops show), energy uJ.  The specimen is the lab
record's (notebooks/data/lab_loop.json).
"""

import json

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import Specimen


def main():
    p = figure_parser(__doc__)
    p.add_argument("--specimen", required=True, help="JSON with radius, normal_force, friction, shear_modulus")
    p.add_argument("--amplitudes", type=float, nargs="+", required=True, help="torque amplitudes (N m)")
    a = p.parse_args()
    data = json.loads(open(a.specimen, encoding="utf-8").read())
    s = Specimen(radius=data["radius"], normal_force=data["normal_force"], friction=data["friction"],
                 shear_modulus=data["shear_modulus"])
    use_style(a.style)
    fig, (loops, energy) = subplots(1, 2, figsize=(6.2, 3.2))  # printed at its size (text width 6.3 in)
    phase = np.linspace(0.0, 2.0, 801)
    for amplitude in a.amplitudes:
        torque = amplitude * np.sin(2 * np.pi * phase)
        contact = 2.0 * s.signal(torque).sample_values()["rigid_rotation"]
        steady = phase >= 0.25  # after the first loading: the closed loop
        loops.plot(contact[steady] * 1e6, torque[steady], label=f"{amplitude:g} N m ({s.regime(amplitude)})")
    loops.set_xlabel(r"contact twist $2\omega f p_0/G$ [$\mu$rad]")
    loops.set_ylabel(r"torque $T$ [N m]")
    handles, labels = loops.get_legend_handles_labels()
    amplitudes = np.linspace(s.slip_onset_torque * 1.0005, s.gross_slip_torque * 0.9999, 120)
    work = np.array([s.energy_per_cycle(t) for t in amplitudes])
    energy.semilogy(amplitudes, work * 1e6, "-", label="per cycle, $W(2T^*_a)(fp_0)^2a^3/G$")
    for torque, name in ((s.slip_onset_torque, "slip onset $fFa/2$"), (s.gross_slip_torque, "gross slip $2fFa/3$")):
        energy.axvline(torque, color="0.5", linestyle=":", linewidth=0.8)
        # left of the dotted line, clear of it and of the curve's steep foot just right of the onset
        energy.annotate(name, (torque, work[work > 0].min() * 1e6), xytext=(-3, 0), textcoords="offset points",
                        rotation=90, fontsize=7.5, ha="right", va="bottom")
    span = s.gross_slip_torque - s.slip_onset_torque
    energy.set_xlim(s.slip_onset_torque - 0.08 * span, s.gross_slip_torque + 0.04 * span)  # room for the labels
    energy.set_xlabel(r"torque amplitude $T_a$ [N m]")
    energy.set_ylabel(r"energy per cycle [$\mu$J]")
    energy.legend(fontsize=7.5)
    fig.suptitle(f"$a$ = {s.radius * 1e3:g} mm, $F$ = {s.normal_force:g} N, $f$ = {s.friction:g}, "
                 f"$G$ = {s.shear_modulus / 1e9:g} GPa", fontsize=8)
    fig.legend(handles, labels, title="torque amplitude", loc="lower center", ncol=len(labels), fontsize=7.5,
               title_fontsize=7.5, frameon=False)
    fig.tight_layout(rect=(0, 0.14, 1, 1))  # the loops' legend below the panels, off the data
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
