"""Rounding against truncation of the weak forms: double precision against the mpmath reference.

Reads the two reference JSONs (same N, published and complete) and writes one JSON with
the rounding error of ``solve_series`` at the same N, the truncation error (N against a
larger N), condition numbers against N and their ratios, and published minus complete
T*(b).  Thin driver over ``torsional_contact.verification.crosscheck``.
"""

import argparse
import warnings

from torsional_contact.diagnostics import IllConditioningWarning, ResolutionWarning
from torsional_contact.provenance import write_json
from torsional_contact.verification import crosscheck
from torsional_contact.verification.reference import load_reference_json


def rounded(rows, digits=6):
    """Floats to ``digits`` significant digits: the last bits of a LAPACK estimate vary with the BLAS
    build and thread count, and the data files must be the same from one build to the next."""
    return [{k: float(f"{v:.{digits}g}") if isinstance(v, float) else v for k, v in row.items()} for row in rows]


def pick(rows, n, method, key):
    return next(r[key] for r in rows if r["n_terms"] == n and r["method"] == method)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--references", nargs="+", required=True, help="reference_*.json")
    p.add_argument("--converged-n-terms", type=int, required=True)
    p.add_argument("--condition-n-terms", type=int, nargs="+", required=True)
    p.add_argument("--json", required=True)
    p.add_argument("--converged-json", required=True, help="both weak forms at --converged-n-terms and every stick "
                   "radius, every bit (crosscheck.weak_forms_at; the precision ladder reuses them at that N)")
    a = p.parse_args()
    solutions = [s for path in a.references for s in load_reference_json(path)]
    n_terms = solutions[0].n_terms
    radii = sorted({float(s.stick_radius) for s in solutions})

    rounding = [crosscheck.rounding_error(s) for s in solutions]
    print("scipy vs reference (same N): digits lost", [round(r["digits_lost"], 2) for r in rounding])
    with warnings.catch_warnings():
        for category in (ResolutionWarning, IllConditioningWarning):  # measured, not hidden: see the JSON
            warnings.simplefilter("ignore", category)
        converged = {b: crosscheck.weak_forms_at(b, a.converged_n_terms) for b in radii}
        by_radius = [crosscheck.truncation_errors(b, n_terms, a.converged_n_terms, converged=converged[b])
                     for b in radii]
    truncation = [row for method in ("complete", "published") for rows in by_radius for row in rows
                  if row["method"] == method]
    conditions = crosscheck.condition_numbers(a.condition_n_terms, 0.6, progress=True)
    ratio = [
        {
            "n_terms": n,
            "complete_over_published_raw": pick(conditions, n, "complete", "raw")
            / pick(conditions, n, "published", "raw"),
            "complete_over_published_equilibrated": pick(conditions, n, "complete", "equilibrated")
            / pick(conditions, n, "published", "equilibrated"),
        }
        for n in a.condition_n_terms
    ]
    gap = []
    for b in radii:
        c = next(t for t in truncation if t["method"] == "complete" and t["stick_radius"] == b)
        q = next(t for t in truncation if t["method"] == "published" and t["stick_radius"] == b)
        gap.append({"stick_radius": b, "n_terms": n_terms, "converged_n_terms": a.converged_n_terms,
                    "published_minus_complete": q["torque"] - c["torque"],
                    "published_minus_complete_converged": q["torque_converged"] - c["torque_converged"]})
    payload = {
        "reference": {"n_terms": n_terms, "digits": solutions[0].digits, "stick_radii": radii},
        "rounding": rounded(rounding, 3),
        "truncation": rounded(truncation, 12),
        "condition_numbers": rounded(conditions),
        "condition_ratios": rounded(ratio),
        "published_minus_complete": rounded(gap, 12),
    }
    write_json(a.json, payload, method="double-precision weak forms against the mpmath reference of the same "
               "truncated system (rounding), and against N = converged_n_terms (truncation; both forms at "
               "converged_n_terms from one LU of the equilibrated published matrix, the complete one by block "
               "elimination; converged_rounding_bound = EPS / rcond, the relative rounding of such a dense solve); "
               "condition numbers: LAPACK dgecon's estimate (its Hager-Higham iteration, dlacn2, through triangular "
               "solves) from one LU per N (bordered and scaled for the other three)",
               precision="IEEE double vs the reference's digits", resolution={"n_terms": n_terms})
    write_json(a.converged_json, {"n_terms": a.converged_n_terms, "weak_forms": [
        {"stick_radius": b, "published_torque": out["published"][0], "complete_torque": out["complete"][0],
         "complete_rigid_rotation": out["complete"][1], "rounding_bound": out["rounding_bound"]}
        for b, out in converged.items()]},
        method="crosscheck.weak_forms_at: both weak forms from one LU of the equilibrated published matrix (the "
        "complete one by block elimination), in double precision; every bit (JSON floats round-trip), for the "
        "precision ladder", resolution={"n_terms": a.converged_n_terms})


if __name__ == "__main__":
    main()
