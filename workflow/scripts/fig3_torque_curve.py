"""Fig. 3: stick radius b/a against T* = 2T/(f F a), both formulations; CSV of the curve.

The converged curve is the Abel-Fredholm (fast) solution on [0, 1]; the weak forms at N
terms are drawn where N resolves both zones ([10/lam_N, 1 - 10/lam_N]).
"""

import warnings

import numpy as np

from torsional_contact import solve
from torsional_contact.diagnostics import UnphysicalResultWarning
from torsional_contact.io.plotting import figure_parser, plt, save_figure, use_style
from torsional_contact.provenance import provenance, write_text
from torsional_contact.solvers.weak_form import resolution_limit


def curve(method, n_terms, radii):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnphysicalResultWarning)  # published T* > 4/3: plotted, not hidden
        return np.array([solve(stick_radius=b, method=method, n_terms=n_terms).torque for b in radii])


def main():
    p = figure_parser(__doc__)
    p.add_argument("--n-terms", type=int, required=True)
    p.add_argument("--n-radii", type=int, default=200)
    p.add_argument("--csv", required=True)
    a = p.parse_args()

    lo, hi = resolution_limit(a.n_terms)
    radii = np.linspace(lo, hi, a.n_radii)
    complete = curve("complete", a.n_terms, radii)
    published = curve("published", a.n_terms, radii)
    fast_radii = np.linspace(0.0, 1.0, a.n_radii)
    fast = curve("fast", None, fast_radii)

    meta = provenance(method="weak forms at n_terms (regularity: traction continuity at r = b) and the "
                      "Abel-Fredholm method", precision="IEEE double", n_terms=a.n_terms)
    lines = [f"# {k}: {v}" for k, v in meta.items()]
    lines.append("stick_radius,torque_complete,torque_published,torque_fast")
    fast_here = curve("fast", None, radii)
    lines += [f"{b:.17g},{c:.17g},{q:.17g},{f:.17g}"
              for b, c, q, f in zip(radii, complete, published, fast_here, strict=True)]
    write_text(a.csv, "\n".join(lines) + "\n")

    use_style(a.style)
    fig, ax = plt.subplots()
    ax.plot(fast, fast_radii, "k-", lw=2.2, label="converged (Abel-Fredholm)")
    ax.plot(complete, radii, "--", label=f"complete, N = {a.n_terms}")
    ax.plot(published, radii, ":", label=f"published eq. (38), N = {a.n_terms}")
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
