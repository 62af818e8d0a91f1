"""Printed eq. (38) against the complete weak form and the converged solution: slip and traction at one b/a.

Left: slip s(r) (units f p0 a / mu); right: traction sigma_zt(r, 0) (units f p0).  The printed
weak form (closed by traction continuity at r = b) slips backwards on the stick disc
(u = alpha r, alpha < 0) and carries traction 1 - alpha r > 1 on the slip annulus (see the
docstring of solvers/weak_form.py); the complete weak form at the same N lies close to the
converged Abel-Fredholm solution.
"""


import numpy as np

from torsional_contact import solve
from torsional_contact.io.plotting import figure_parser, plt, save_figure, use_style


def main():
    p = figure_parser(__doc__)
    p.add_argument("--stick-radius", type=float, required=True)
    p.add_argument("--n-terms", type=int, required=True)
    a = p.parse_args()

    r = np.linspace(0, 1, 1001)
    use_style(a.style)
    fig, (left, right) = plt.subplots(1, 2, figsize=(7.0, 3.4))
    cases = (("fast", None, "k-", "converged (Abel-Fredholm)"),
             ("complete", a.n_terms, "-.", f"complete weak form, N = {a.n_terms}"),
             ("published", a.n_terms, "--", f"printed eq. (38), N = {a.n_terms}"))
    for method, n_terms, style, name in cases:
        s = solve(stick_radius=a.stick_radius, method=method, n_terms=n_terms)
        label = f"{name}: $T^* = {s.torque:.4f}$"
        left.plot(r, s.slip(r), style, lw=2.0 if method == "fast" else 1.2, label=label)
        right.plot(r, s.traction(r), style, lw=2.0 if method == "fast" else 1.2, label=label)
    for ax in (left, right):
        ax.axvline(a.stick_radius, color="0.5", lw=0.8)
        ax.set_xlabel(r"$r/a$")
        ax.set_xlim(0, 1)
    left.axhline(0, color="k", lw=0.6)
    right.axhline(1, color="k", lw=0.6)
    left.set_ylabel(r"slip $s\,\mu/(f p_0 a)$")
    right.set_ylabel(r"$\sigma_{\theta z}(r,0)/f p_0$")
    right.set_ylim(0.6 * a.stick_radius, 1.08)
    right.set_xlim(0.5 * a.stick_radius, 1)
    handles, labels = right.get_legend_handles_labels()
    fig.legend(handles, labels, title=f"$b/a = {a.stick_radius:g}$", fontsize=7, title_fontsize=8, ncol=3,
               loc="lower center", frameon=False)
    fig.tight_layout(rect=(0, 0.16, 1, 1))  # the legend below the panels, off the data
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
