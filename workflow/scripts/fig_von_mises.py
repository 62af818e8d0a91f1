"""Design map: von Mises onset of plastic flow (eq. 6) against slip onset (eq. 5) and spinning.

Axes: normal stress F/(pi a^2 tau_Y) and torsional stress 2T/(pi a^3 tau_Y) (tau_Y: yield stress in
shear, the paper's notation).  Drawn at the size it is printed (legend beside the axes).  Slip
starts on tau = f sigma (T* = 1), the cylinders spin on tau = 4 f sigma / 3 (T* = 4/3); yield
(eq. 6) is the ellipse tau^2 + sigma^2 / 3 = 1.
"""


import numpy as np
from _plotting import figure_parser, rcParams, save_figure, subplots, use_style

from torsional_contact.criteria import von_mises_torque_limit


def main():
    p = figure_parser(__doc__)
    p.add_argument("--friction", type=float, nargs="+", required=True)
    a = p.parse_args()

    sigma = np.linspace(0, np.sqrt(3), 400)  # F / (pi a^2 tau_Y)
    normal_force = np.pi * sigma  # with a = tau_Y = 1
    tau_yield = 2 * von_mises_torque_limit(normal_force, 1.0, 1.0) / np.pi  # 2T/(pi a^3 tau_Y)
    use_style(a.style)
    fig, ax = subplots(figsize=(4.9, 2.7))  # with the legend beside it: about 6.1 in, printed at its size
    ax.plot(sigma, tau_yield, "k", lw=1.8, label="von Mises onset of yield")
    for f, color in zip(a.friction, rcParams["axes.prop_cycle"].by_key()["color"], strict=False):
        ax.plot(sigma, f * sigma, color=color, label=f"slip onset $T^*=1$, $f = {f:g}$")
        ax.plot(sigma, 4 * f * sigma / 3, "--", color=color, label=f"spinning $T^*=4/3$, $f = {f:g}$")
    ax.set_xlim(0, 1.8)
    ax.set_ylim(0, 1.1)
    ax.set_xlabel(r"$F/(\pi a^2 \tau_Y)$")
    ax.set_ylabel(r"$2T/(\pi a^3 \tau_Y)$")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
