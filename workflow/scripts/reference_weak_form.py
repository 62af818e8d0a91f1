"""High-precision reference of the truncated weak form (published or complete) at the reference radii.

Writes a JSON with T*, omega and c_n as decimal strings (``verification.reference``) and
provenance metadata.  Thin driver over ``torsional_contact.verification.reference``.
"""

import argparse

from torsional_contact.provenance import write_json
from torsional_contact.verification import reference


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--method", choices=("published", "complete"), required=True)
    p.add_argument("--stick-radii", nargs="+", required=True, help="b/a, read as decimals")
    p.add_argument("--n-terms", type=int, required=True)
    p.add_argument("--digits", type=int, required=True)
    p.add_argument("--json", required=True)
    p.add_argument("--timing", required=True, help="JSON of the wall times (kept apart from the data)")
    a = p.parse_args()
    solutions, seconds = reference.reference_set(a.stick_radii, methods=(a.method,), n_terms=a.n_terms,
                                                 digits=a.digits, progress=True)
    reference.write_reference_json(a.json, solutions)
    write_json(a.timing, {"seconds_total": seconds,
                          "solutions": [{"stick_radius": str(s.stick_radius), **s.seconds} for s in solutions]},
               method=f"wall time of the {a.method} reference, N = {a.n_terms}, {a.digits} digits")
    print(f"reference ({a.method}): {len(solutions)} radii, N = {a.n_terms}, {a.digits} digits, {seconds:.1f} s")


if __name__ == "__main__":
    main()
