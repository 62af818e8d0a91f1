"""T*(b) curves for Fig. 3: the converged curve (Abel-Fredholm method) on [0, 1] and the weak forms at N
terms where N resolves both zones ([10/lam_N, 1 - 10/lam_N]); a CSV with metadata.

Columns: stick_radius, torque_fast, torque_complete, torque_published,
torque_published_torque_closure.  The rows are the union of two grids: a uniform grid on
[0, 1] for the converged curve and a uniform grid on the resolved range for the weak forms;
the weak-form columns are nan on the rows of the first grid outside that range, so a plot
must drop the nan rows of each column (``finite_rows``).  ``torque_published`` is the
reconstructed printed scheme (eq. (38) closed by traction continuity at r = b),
``torque_published_torque_closure`` the same equations closed by the torque of the traction
actually present (closures of ``solvers.weak_form``).  Units: b in a, T* = 2T/(f F a).
"""

import argparse
import warnings

import numpy as np

from torsional_contact import solve
from torsional_contact.diagnostics import UnphysicalResultWarning
from torsional_contact.provenance import provenance, write_text
from torsional_contact.solvers.weak_form import resolution_limit, solve_series


def curve(method, n_terms, radii):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnphysicalResultWarning)  # published T* > 4/3: kept, not hidden
        return np.array([solve(stick_radius=b, method=method, n_terms=n_terms).torque for b in radii])


def closure_curve(closure, n_terms, radii):
    """The printed system (eq. 38) at n_terms with another closure (see solvers.weak_form)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnphysicalResultWarning)
        return np.array([solve_series(b, "published", n_terms, closure).torque for b in radii])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n-terms", type=int, required=True)
    p.add_argument("--n-radii", type=int, default=200)
    p.add_argument("--csv", required=True)
    a = p.parse_args()
    lo, hi = resolution_limit(a.n_terms)
    resolved = np.linspace(lo, hi, a.n_radii)
    radii = np.union1d(np.linspace(0.0, 1.0, a.n_radii), resolved)
    inside = np.isin(radii, resolved)
    complete = np.full(radii.shape, np.nan)
    published = np.full(radii.shape, np.nan)
    torque_closure = np.full(radii.shape, np.nan)
    complete[inside] = curve("complete", a.n_terms, radii[inside])
    published[inside] = curve("published", a.n_terms, radii[inside])
    torque_closure[inside] = closure_curve("torque", a.n_terms, radii[inside])
    fast = curve("fast", None, radii)
    meta = provenance(method="weak forms at n_terms on their resolved range (torque_complete, torque_published: "
                      "regularity closure, traction continuity at r = b; torque_published_torque_closure: the "
                      "printed system closed by the torque of the traction actually present); torque_fast: the "
                      "Abel-Fredholm method (converged); the weak-form columns are nan outside the resolved range",
                      precision="IEEE double", n_terms=a.n_terms)
    lines = [f"# {k}: {v}" for k, v in meta.items()]
    lines.append("stick_radius,torque_fast,torque_complete,torque_published,torque_published_torque_closure")
    lines += [f"{b:.17g},{f:.17g},{c:.17g},{q:.17g},{t:.17g}"
              for b, f, c, q, t in zip(radii, fast, complete, published, torque_closure, strict=True)]
    write_text(a.csv, "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
