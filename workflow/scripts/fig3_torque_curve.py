"""Fig. 3: stick radius b/a against T* = 2T/(f F a): converged (Abel-Fredholm) and the weak forms at
the paper's N (reads the CSV of workflow/scripts/torque_curve.py)."""

import io

import numpy as np

from torsional_contact.io.plotting import figure_parser, plt, save_figure, use_style


def main():
    p = figure_parser(__doc__)
    p.add_argument("--csv", required=True)
    p.add_argument("--n-terms", type=int, required=True)
    a = p.parse_args()
    with open(a.csv, encoding="utf-8") as handle:
        rows = "".join(line for line in handle if not line.startswith("#"))
    data = np.genfromtxt(io.StringIO(rows), delimiter=",", names=True)
    use_style(a.style)
    fig, ax = plt.subplots()
    ax.plot(data["torque_fast"], data["stick_radius"], "k-", lw=2.2, label="converged (Abel-Fredholm)")
    ax.plot(data["torque_complete"], data["stick_radius"], "--", label=f"complete weak form, N = {a.n_terms}")
    ax.plot(data["torque_published"], data["stick_radius"], ":", label=f"published eq. (38), N = {a.n_terms}")
    ax.axvline(1.0, color="0.5", lw=0.8)
    ax.axvline(4 / 3, color="0.5", lw=0.8)
    ax.text(1.0, 1.02, " slip onset", transform=ax.get_xaxis_transform(), fontsize=8)
    ax.text(4 / 3, 1.02, " spinning", transform=ax.get_xaxis_transform(), fontsize=8)
    ax.set_xlim(0.98, 1.5)
    ax.set_ylim(0, 1.0)
    ax.set_xlabel(r"$T^* = 2T/(fFa)$")
    ax.set_ylabel(r"stick radius $b/a$")
    ax.legend(loc="lower left")
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
