"""T*(b) for both formulations at the paper's n_terms (Fig. 3 as a table).

Usage: python workflow/scripts/torque_table.py [--n-terms 145] [--output results/torque_table.csv]
"""

import argparse
import os
import tempfile
import warnings
from importlib import metadata

import numpy as np

from torsional_contact import solve


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n-terms", type=int, default=145)
    parser.add_argument("--output", default=None, help="CSV file (written atomically)")
    args = parser.parse_args()
    radii = np.round(np.linspace(0.05, 0.95, 19), 2)
    rows = []
    for b in radii:
        complete = solve(stick_radius=b, method="complete", n_terms=args.n_terms)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # published T* > 4/3 is reported, not hidden
            published = solve(stick_radius=b, method="published", n_terms=args.n_terms)
        rows.append((b, complete.torque, complete.rigid_rotation, published.torque))
    header = "stick_radius,torque_complete,rigid_rotation_complete,torque_published"
    print(f"n_terms = {args.n_terms}\n{header.replace(',', '  ')}")
    for row in rows:
        print(f"{row[0]:.2f}  {row[1]:.10f}  {row[2]:.10f}  {row[3]:.10f}{'  (> 4/3!)' if row[3] > 4 / 3 else ''}")
    if args.output:
        versions = ", ".join(f"{p} {metadata.version(p)}" for p in ("numpy", "scipy", "torsional_contact"))
        directory = os.path.dirname(os.path.abspath(args.output))
        os.makedirs(directory, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", dir=directory, delete=False, suffix=".tmp") as handle:
            handle.write("# T*(b): weak form eq. (38) ('published') and with the rigid-rotation mode ('complete')\n")
            handle.write(f"# n_terms={args.n_terms}; regularity: traction continuity at r=b; IEEE double; {versions}\n")
            handle.write(header + "\n")
            for row in rows:
                handle.write(",".join(f"{v:.17g}" for v in row) + "\n")
        os.replace(handle.name, args.output)


if __name__ == "__main__":
    main()
