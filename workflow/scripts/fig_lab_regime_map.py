"""Slip regime map of a specimen in physical units: stick, partial slip and gross slip against the
normal force and the amplitude of a torque cycling between -T_a and T_a, with the energy
dissipated per cycle in the partial-slip band.

Units: normal force N, torque N m, energy J.  Slip starts at T_a = f F a / 2 (T* = 1), the
cylinders spin at T_a = 2 f F a / 3 (T* = 4/3); between them a cycle dissipates
W(2 T*_a) (f F)^2 / (pi^2 G a) (``histories``, rule 5).  The specimen (a, f, G) is the lab
record's (notebooks/data/lab_loop.json).
"""

import json

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import Specimen
from torsional_contact.curves import monotonic_curves


def main():
    p = figure_parser(__doc__)
    p.add_argument("--specimen", required=True, help="JSON with radius, normal_force, friction, shear_modulus")
    p.add_argument("--max-force", type=float, required=True, help="largest normal force (N)")
    a = p.parse_args()
    data = json.loads(open(a.specimen, encoding="utf-8").read())
    radius, friction, modulus = data["radius"], data["friction"], data["shear_modulus"]
    force = np.linspace(0.0, a.max_force, 301)[1:]
    use_style(a.style)
    # the torque amplitude in units of the slip-onset torque f F a / 2: the regimes are bands of the same
    # height at every force (stick below 1, partial slip up to 4/3, gross slip above), and the energy
    # contours fill the partial-slip band instead of a thin wedge
    fig, ax = subplots(figsize=(4.6, 3.9))
    low, top = 0.85, 1.45
    ax.axhspan(low, 1.0, color="#d9ecd9", label="stick (shakedown)")
    ax.axhspan(1.0, 4.0 / 3.0, color="#fde9c8", label="partial slip")
    ax.axhspan(4.0 / 3.0, top, color="#f6d0d0", label="gross slip (spinning)")
    # energy per cycle in the partial-slip band: W(2 T*_a) (f F)^2 / (pi^2 G a)
    grid_force, ratio = np.meshgrid(force, np.linspace(1.0005, 4.0 / 3.0 - 1e-6, 200))
    work = 4.0 * monotonic_curves().work(ratio) * (friction * grid_force) ** 2 / (np.pi**2 * modulus * radius)
    # decades up to 1e-3 J (a 1e-2 J line would hug the gross-slip boundary at these forces)
    levels = 10.0 ** np.arange(-8, -2)
    lines = ax.contour(grid_force, ratio, work, levels=levels, colors="0.25", linewidths=0.6)
    # labels staggered along the force axis, where neighbouring lines are far enough apart for them
    places = []
    for path, target in zip(lines.get_paths(), np.linspace(0.2, 0.9, levels.size) * a.max_force, strict=True):
        if path.vertices.size:  # one path per level: the vertex nearest the target force
            places.append(tuple(path.vertices[np.argmin(np.abs(path.vertices[:, 0] - target))]))
    ax.clabel(lines, fmt=lambda v: f"$10^{{{round(np.log10(v))}}}$ J", fontsize=7.5, manual=places)
    example = Specimen(radius=radius, normal_force=data["normal_force"], friction=friction, shear_modulus=modulus)
    amplitude = 1.8  # N m, the example of the text
    example_ratio = amplitude / (0.5 * friction * data["normal_force"] * radius)
    ax.plot([data["normal_force"]], [example_ratio], "k*", ms=8,
            label=f"{amplitude:g} N m at {data['normal_force']:g} N: "
            f"{example.energy_per_cycle(amplitude) * 1e6:.3g} $\\mu$J/cycle")
    ax.set_xlim(0, a.max_force)
    ax.set_ylim(low, top)
    ax.set_xlabel(r"normal force $F$ [N]")
    ax.set_ylabel(r"torque amplitude $2T_a/(fFa)$")
    ax.set_title(f"$a$ = {radius * 1e3:g} mm, $f$ = {friction:g}, $G$ = {modulus / 1e9:g} GPa; "
                 "contours: energy per cycle", fontsize=8)
    ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)  # off the data
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
