"""Print (and optionally save) the n_terms convergence table of T*(b), omega(b) and traction.

Usage: python workflow/scripts/convergence_table.py [--stick-radius 0.6] [--method complete]
                                                    [--max-n 2320] [--output results/convergence.json]
"""

import argparse
import json
import os
import platform
import tempfile
from importlib import metadata

import numpy as np

from torsional_contact.convergence import format_table, n_terms_study


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stick-radius", type=float, default=0.6)
    parser.add_argument("--method", default="complete")
    parser.add_argument("--max-n", type=int, default=2320)
    parser.add_argument("--output", default=None, help="JSON file (written atomically)")
    args = parser.parse_args()
    sizes = [n for n in (145, 290, 580, 1160, 2320, 4640) if n <= args.max_n]
    study = n_terms_study(args.stick_radius, sizes, method=args.method)
    print(f"b/a = {args.stick_radius}, method = {args.method}")
    print(format_table(study))
    if args.output:
        record = {key: (value.tolist() if isinstance(value, np.ndarray) else value) for key, value in study.items()}
        record["metadata"] = {
            "method": f"{args.method} weak form, regularity by traction continuity at r = b",
            "precision": "IEEE double",
            "packages": {p: metadata.version(p) for p in ("numpy", "scipy", "torsional_contact")},
            "python": platform.python_version(),
        }
        directory = os.path.dirname(os.path.abspath(args.output))
        os.makedirs(directory, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", dir=directory, delete=False, suffix=".tmp") as handle:
            json.dump(record, handle, indent=1)
        os.replace(handle.name, args.output)


if __name__ == "__main__":
    main()
