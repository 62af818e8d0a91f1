"""The errata table of the paper: every checked statement with its computed verdict.

Writes errata.json (the table, the thresholds of the verdict rules, the time per check) and
errata.md (the same as a report).  Thin driver over ``torsional_contact.verification.errata``.
"""

import argparse
import time

from torsional_contact.provenance import write_json, write_text
from torsional_contact.verification import errata


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--json", required=True)
    p.add_argument("--md", required=True)
    a = p.parse_args()
    start = time.perf_counter()
    table = errata.errata_table(progress=True)
    payload = {
        "thresholds": {
            "TOL_FORMULA": errata.TOL_FORMULA,
            "TOL_DOUBLE": errata.TOL_DOUBLE,
            "TOL_DIFF": errata.TOL_DIFF,
            "HAZARD_DIGITS_KEPT": errata.HAZARD_DIGITS_KEPT,
            "NEGLIGIBLE_CHANGE": errata.NEGLIGIBLE_CHANGE,
            "N_CONVERGED": errata.N_CONVERGED,
        },
        "errata": table,
    }
    write_json(a.json, payload, method="independent computation per statement (see each row's check)",
               precision="40 digits (mpmath) for formulas, IEEE double for solver-based checks")
    write_text(a.md, errata.markdown_report(table))
    counts = {v: sum(r["verdict"] == v for r in table) for v in errata.VERDICTS}
    print(f"errata: {len(table)} checks, {counts} in {time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
