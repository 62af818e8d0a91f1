"""Half-spaces against finite cylinders: torque against stick radius, slip-annulus width and the
contact's extra rotation against torque.

Units: b in a; T* = 2T/(f F a); rotations in f p0 / G (G the shear modulus).  Cylinders: the Abel-Fredholm curves
(``curves``); half-spaces: the closed forms of ``half_space.closed_form``.  The cylinders'
extra rotation is 2 omega (beyond the uniform twist of a monolithic shaft, 0 in stick); the
half-spaces' is their relative twist phi_h = 2 omega_h, which includes the bonded contact's
elastic compliance 3 pi T*/16, and phi_h - 3 pi T*/16 is the part due to slip.
"""

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact.curves import monotonic_curves
from torsional_contact.half_space import closed_form as hs


def main():
    p = figure_parser(__doc__)
    p.add_argument("--n-points", type=int, required=True)
    a = p.parse_args()
    curves = monotonic_curves()
    b = np.linspace(0.0, 1.0, a.n_points)
    tau = np.linspace(0.0, 4 / 3, a.n_points)[1:-1]
    use_style(a.style)
    # printed at its size (text width 6.3 in); the right panel wider for its legend
    fig, (left, middle, right) = subplots(1, 3, figsize=(6.2, 2.8), gridspec_kw={"width_ratios": [1, 1, 1.3]})
    left.plot(b, curves.torque(b), label="cylinders")
    left.plot(b, hs.torque(b), "--", label="half-spaces")
    left.set_xlabel(r"stick radius $b/a$")
    left.set_ylabel(r"$T^* = 2T/(fFa)$")
    left.legend(fontsize=7.5)
    middle.semilogy(tau, 1 - curves.stick_radius(tau), label="cylinders")
    middle.semilogy(tau, 1 - hs.stick_radius(tau), "--", label="half-spaces")
    middle.set_ylim(1e-6, 1.5)
    middle.set_xlabel(r"$T^*$")
    middle.set_ylabel(r"slip-annulus width $1 - b/a$")
    # no legend: the lines of the left panel (a legend here would cover the cylinders' line at T* = 1)
    right.plot(tau, 2 * curves.rotation(tau), label=r"cylinders $2\omega$")
    right.plot(tau, 2 * hs.rotation(tau), "--", label=r"half-spaces $\phi_\mathrm{h} = 2\omega_\mathrm{h}$")
    right.plot(tau, 2 * hs.rotation(tau) - 2 * hs.BONDED_COMPLIANCE * tau, ":",
               label=r"$\phi_\mathrm{h} - 3\pi T^*/16$")
    right.set_ylim(0, 3.4)  # room for the legend above the curves
    right.set_xlabel(r"$T^*$")
    right.set_ylabel(r"extra rotation [$fp_0/G$]")
    right.legend(fontsize=7.5, loc="upper left", borderaxespad=0.3)
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
