"""High-precision reference, precision cross-checks and the errata table of the paper.

Writes (into --out):
  reference_complete.json, reference_published.json  T*, omega, c_n at N terms, --digits digits
  errata.json                                         the errata table and all cross-check numbers
  errata.md                                           the same as a report

Thin driver: every number comes from torsional_contact.reference / torsional_contact.errata.
Run with OMP_NUM_THREADS=1 on a shared machine; N = 5000 condition numbers take ~1 min.
"""

import argparse
import os
import time
import warnings

from torsional_contact import errata, reference


def pick(rows, n, method, key):
    return next(r[key] for r in rows if r["n_terms"] == n and r["method"] == method)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default="results")
    p.add_argument("--stick-radii", type=float, nargs="+", default=[0.1, 0.3, 0.5, 0.6, 0.7, 0.9])
    p.add_argument("--n-terms", type=int, default=145)
    p.add_argument("--digits", type=int, default=50)
    p.add_argument("--converged-n-terms", type=int, default=4000)
    p.add_argument(
        "--condition-n-terms", type=int, nargs="+", default=[20, 50, 100, 145, 300, 600, 1000, 2000, 3000, 5000]
    )
    a = p.parse_args()

    t0 = time.perf_counter()
    solutions, seconds = reference.reference_set(a.stick_radii, n_terms=a.n_terms, digits=a.digits, progress=True)
    print(f"reference: {len(solutions)} solves (N = {a.n_terms}, {a.digits} digits) in {seconds:.1f} s")
    for method in ("complete", "published"):
        subset = [s for s in solutions if s.method == method]
        reference.write_reference_json(
            os.path.join(a.out, f"reference_{method}.json"), subset, sum(sum(s.seconds.values()) for s in subset)
        )
    timing_rows = [
        {
            "method": s.method,
            "stick_radius": float(s.stick_radius),
            **{k: round(v, 3) for k, v in s.seconds.items()},
            "torque": float(s.torque),
            "rigid_rotation": None if s.rigid_rotation is None else float(s.rigid_rotation),
            "solve_bound": float(s.solve_bound) if s.solve_bound is not None else None,
        }
        for s in solutions
    ]

    rounding = [reference.rounding_error(s) for s in solutions]
    print("scipy vs reference (same N): digits lost", [round(r["digits_lost"], 2) for r in rounding])

    truncation = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for method in ("complete", "published"):
            for b in a.stick_radii:
                truncation.append(reference.truncation_error(b, method, a.n_terms, a.converged_n_terms))
    print("truncation:", [(t["method"], t["stick_radius"], f"{t['torque_rel_change']:.2e}") for t in truncation])

    conditions = reference.condition_numbers(a.condition_n_terms, 0.6, progress=True)
    for c in conditions:
        print(f"  N = {c['n_terms']:5d} {c['method']:9s} raw {c['raw']:.3e} equilibrated {c['equilibrated']:.3e}")

    ratio = [
        {
            "n_terms": n,
            "complete_over_published_raw": pick(conditions, n, "complete", "raw")
            / pick(conditions, n, "published", "raw"),
            "complete_over_published_equilibrated": pick(conditions, n, "complete", "equilibrated")
            / pick(conditions, n, "published", "equilibrated"),
            "published_raw_over_equilibrated": pick(conditions, n, "published", "raw")
            / pick(conditions, n, "published", "equilibrated"),
        }
        for n in a.condition_n_terms
    ]
    gap = []
    for b in a.stick_radii:
        c = next(t for t in truncation if t["method"] == "complete" and t["stick_radius"] == b)
        q = next(t for t in truncation if t["method"] == "published" and t["stick_radius"] == b)
        gap.append(
            {
                "stick_radius": b,
                f"published_minus_complete_N{a.n_terms}": q["torque"] - c["torque"],
                f"published_minus_complete_N{a.converged_n_terms}": q["torque_converged"] - c["torque_converged"],
            }
        )

    table = errata.errata_table(progress=True)
    crosscheck = {
        f"Reference solutions (N = {a.n_terms}, {a.digits} digits; seconds per stage)": timing_rows,
        f"Rounding: scipy solve_series vs reference at the same N = {a.n_terms}": rounding,
        f"Truncation: T* at N = {a.n_terms} vs N = {a.converged_n_terms} (double precision)": truncation,
        "Condition numbers (1-norm, LAPACK dgecon), b = 0.6": conditions,
        "Condition number ratios": ratio,
        "Published minus complete T*(b)": gap,
    }
    payload = {
        "versions": reference.package_versions(),
        "thresholds": {
            "TOL_FORMULA": errata.TOL_FORMULA,
            "TOL_DOUBLE": errata.TOL_DOUBLE,
            "TOL_DIFF": errata.TOL_DIFF,
            "HAZARD_DIGITS_KEPT": errata.HAZARD_DIGITS_KEPT,
            "NEGLIGIBLE_CHANGE": errata.NEGLIGIBLE_CHANGE,
            "N_CONVERGED": errata.N_CONVERGED,
        },
        "seconds": {
            "reference_total": seconds,
            "errata_checks": errata.errata_timing(progress=True),
            "script_total": time.perf_counter() - t0,
        },
        "errata": table,
        "crosscheck": crosscheck,
    }
    reference.write_json(os.path.join(a.out, "errata.json"), payload)
    text = errata.markdown_report(table, crosscheck)
    text += f"\nTotal run time {time.perf_counter() - t0:.1f} s; versions: {payload['versions']}\n"
    reference.write_text(os.path.join(a.out, "errata.md"), text)
    counts = {v: sum(r["verdict"] == v for r in table) for v in errata.VERDICTS}
    print(f"errata: {len(table)} checks, {counts}; wrote {a.out}/errata.json, errata.md, reference_*.json")


if __name__ == "__main__":
    main()
