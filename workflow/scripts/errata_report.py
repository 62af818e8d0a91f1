"""The errata table of the paper: every checked statement with its computed verdict.

Writes errata.json (the rows, the thresholds and the verdict rules they come from, the
reconstruction caveat and the coverage of the paper's equations 1-53) and errata.md (the
same as a report).  Seconds per check go to the log, not into the data.  Thin driver over
``torsional_contact.verification.errata``.
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
            "WORK_DPS": errata.WORK_DPS,
            "TOL_FORMULA": errata.TOL_FORMULA,
            "TOL_DOUBLE": errata.TOL_DOUBLE,
            "HAZARD_DIGITS_KEPT": errata.HAZARD_DIGITS_KEPT,
            "NEGLIGIBLE_CHANGE": errata.NEGLIGIBLE_CHANGE,
            "QUOTED_TORQUE_HALF_UNIT": errata.QUOTED_TORQUE_HALF_UNIT,
            "CONSISTENCY_FACTOR": errata.CONSISTENCY_FACTOR,
            "N_PAPER": errata.N_PAPER,
            "N_CONVERGED": errata.N_CONVERGED,
        },
        "rules": {"text": errata.verdict_rules(), "latex": errata.verdict_rules(latex=True)},
        "closure_caveat": {"text": errata.closure_caveat(), "latex": errata.closure_caveat(latex=True)},
        "coverage": errata.coverage(table),
        "errata": table,
    }
    write_json(a.json, payload, method="independent computation per statement (see each row's check); solutions "
               "compared with the Abel-Fredholm solution",
               precision="40 digits (mpmath) for formulas, IEEE double for solver-based checks")
    write_text(a.md, errata.markdown_report(table))
    counts = {v: sum(r["verdict"] == v for r in table) for v in errata.VERDICTS}
    print(f"errata: {len(table)} checks, {counts} in {time.perf_counter() - start:.1f} s")
    for name, seconds in errata.errata_timing(progress=True).items():
        print(f"  {name}: {seconds:.2f} s")


if __name__ == "__main__":
    main()
