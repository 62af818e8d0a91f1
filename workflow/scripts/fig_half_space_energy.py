"""Energy per cycle against the torque range for half-spaces and cylinders (log-log), and the
friction coefficient a half-space fit of the cylinders' energy returns.

Units: torque range A = Delta T* = 2 Delta T/(f F a); energy per cycle in (f p0)^2 a^3 / G (G the shear modulus).
Half-spaces: W = (27 pi^4/131072) A^4 at small A (eq. H13 of ``half_space.closed_form``);
cylinders: W = 0 for A <= 2, (pi^4/3)(A/2 - 1)^3 just above (``histories.energy``).  Right:
f_fit / f solving kappa^2 W_hs(A/kappa) = W_cyl(A) (``half_space.comparison``).
"""

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import models
from torsional_contact.half_space import closed_form as hs
from torsional_contact.model_comparison import apparent_friction_ratio


def main():
    p = figure_parser(__doc__)
    p.add_argument("--n-points", type=int, required=True, help="ranges A on the energy curves")
    p.add_argument("--fit-points", type=int, required=True, help="ranges A of the friction-fit curve")
    a = p.parse_args()
    top = 8 / 3
    # both energies rise steeply (the half-spaces' without bound) as A -> 8/3, where the stick disc vanishes: points
    # crowd towards the top, or the last interval of a geometric grid from small A shows as a kink
    near_top = top - np.geomspace(1e-6, 0.2, a.n_points // 3)
    ranges = np.union1d(np.geomspace(1e-2, top * (1 - 1e-6), a.n_points), near_top)
    above = np.union1d(2 + np.geomspace(1e-4, top - 2 - 1e-6, a.n_points), near_top)
    w_hs = models.get("half-space").energy_per_cycle(ranges)  # W(A) = 4 W_mono(A/2), the one Masing energy
    w_cyl = models.get("cylinder").energy_per_cycle(above)
    use_style(a.style)
    fig, (left, right) = subplots(1, 2, figsize=(6.2, 3.0))  # printed at its size (text width 6.3 in)
    # a linear range axis: the cylinders dissipate only on 2 < A < 8/3, a quarter of it (a log axis squeezed it)
    left.semilogy(ranges, w_hs, label="half-spaces")
    left.semilogy(ranges, hs.SMALL_AMPLITUDE_COEFFICIENT * ranges**4, ":", label=r"$(27\pi^4/131072)\,A^4$")
    left.semilogy(above, w_cyl, label="cylinders")  # W = 0 for A <= 2 (the caption)
    left.semilogy(above, np.pi**4 / 3 * (above / 2 - 1) ** 3, "--", label=r"$(\pi^4/3)(A/2 - 1)^3$")
    left.set_xlim(0, top)
    left.set_ylim(1e-8, 1e2)
    left.set_xlabel(r"torque range $A = \Delta T^*$")
    left.set_ylabel(r"energy per cycle $WG/((fp_0)^2a^3)$")
    # below the half-spaces' curve and left of the cylinders' rise at A = 2: the empty part of the panel
    left.legend(fontsize=7.5, loc="lower left", bbox_to_anchor=(0.12, 0.0))
    fit = 2 + np.geomspace(1e-3, top - 2 - 1e-9, a.fit_points)
    kappa = np.array([apparent_friction_ratio(x) for x in fit])
    right.loglog(fit - 2, kappa)
    right.axhline(1.0, color="0.5", lw=0.8)
    right.set_xlabel(r"$A - 2$ (beyond the cylinders' threshold)")
    right.set_ylabel(r"half-space fit $f_\mathrm{fit}/f$")
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
