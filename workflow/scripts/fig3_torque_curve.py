"""Fig. 3: stick radius b/a against T* = 2T/(f F a), both formulations; CSV of the curve.

One series solve per stick radius (the resolution-limited ends are left out with a
note: outside [10/lam_N, 1 - 10/lam_N] the N terms do not resolve the zones).
"""

import argparse
import warnings

import numpy as np

from torsional_contact import solve
from torsional_contact.formulations import resolution_limit
from torsional_contact.output import provenance, write_text
from torsional_contact.plotting import plt, save_figure, use_style


def curve(method, n_terms, radii):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # published T* > 4/3: plotted, not hidden
        return np.array([solve(stick_radius=b, method=method, n_terms=n_terms).torque for b in radii])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n-terms", type=int, required=True)
    p.add_argument("--reference-n-terms", type=int, required=True, help="larger N drawn for comparison")
    p.add_argument("--n-radii", type=int, default=200)
    p.add_argument("--style")
    p.add_argument("--csv", required=True)
    p.add_argument("--pdf", required=True)
    p.add_argument("--png")
    a = p.parse_args()

    lo, hi = resolution_limit(a.n_terms)
    radii = np.linspace(lo, hi, a.n_radii)
    complete = curve("complete", a.n_terms, radii)
    published = curve("published", a.n_terms, radii)
    ref_radii = np.linspace(*resolution_limit(a.reference_n_terms), 60)
    reference = curve("complete", a.reference_n_terms, ref_radii)

    meta = provenance(method="weak form, regularity by traction continuity at r = b", precision="IEEE double",
                      n_terms=a.n_terms)
    lines = [f"# {k}: {v}" for k, v in meta.items()]
    lines.append("stick_radius,torque_complete,torque_published")
    lines += [f"{b:.17g},{c:.17g},{q:.17g}" for b, c, q in zip(radii, complete, published, strict=True)]
    write_text(a.csv, "\n".join(lines) + "\n")

    use_style(a.style)
    fig, ax = plt.subplots()
    ax.plot(complete, radii, label=f"complete, N = {a.n_terms}")
    ax.plot(reference, ref_radii, "--", label=f"complete, N = {a.reference_n_terms}")
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
