"""Precision ladder: every double-precision method against the converged 30-digit solution.

Reads the per-radius JSONs of workflow/scripts/reference_abel_fredholm.py (the truth: the
Abel-Fredholm method in arbitrary precision) and compares
  (a) the truth's own convergence in the number of Nystrom nodes at two working precisions;
  (b) the double-precision solve() (default method, Abel-Fredholm) over all stick radii:
      T*, omega, interface traction and slip at the profile radii;
  (c) the weak forms (published eq. 38 and complete) at N = 145 ... 4640, and the complete
      form extrapolated in N (T_N = T + (a + c ln N)/N, an independent check of the truth);
      both forms from one factorisation per (b, N) (``crosscheck.weak_forms_at``: the published
      solve is solve()'s own, bit for bit; the complete one, by block elimination on its factors,
      agrees with solve()'s dense solve to the rounding bound of a stable solve, 1e-11 of T* at
      N = 4640, far below the truncation errors this rung measures);
  (d) the ladder at the reference radii: (i) double fast vs truth, (ii) N = 145 double vs
      the same system in 50 digits (reference.solve_reference: rounding only), (iii) N = 145
      vs truth (truncation and formulation).
Writes a JSON (metadata), two LaTeX tables and LaTeX macros.
"""

import argparse
import decimal
import json
import math
import warnings

import mpmath
import numpy as np

from torsional_contact import solve
from torsional_contact.diagnostics import TorsionalContactWarning
from torsional_contact.provenance import write_json, write_macros, write_text
from torsional_contact.typeset import sci
from torsional_contact.verification import crosscheck
from torsional_contact.verification.reference import load_reference_json, solve_reference

mpmath.mp.dps = 60


def load_references(paths):
    refs = []
    for path in paths:
        with open(path, encoding="utf-8") as handle:
            refs.append(json.load(handle))
    return sorted(refs, key=lambda r: mpmath.mpf(r["stick_radius"]))


def truth(ref, key):
    return mpmath.mpf(ref["extended"][key])


def convergence_rows(refs):
    rows = []
    for ref in refs:
        for row in ref.get("convergence", []):
            rows.append({
                "stick_radius": float(ref["stick_radius"]),
                "working_digits": row["working_digits"],
                "n_nodes": row["n_nodes"],
                "torque_error": float(abs(mpmath.mpf(row["torque"]) - truth(ref, "torque"))),
                "rigid_rotation_error": float(abs(mpmath.mpf(row["rigid_rotation"]) - truth(ref, "rigid_rotation"))),
            })
    return rows


def double_fast_rows(refs):
    """Default solve() (double precision) against the truth at every stick radius."""
    rows = []
    for ref in refs:
        b = float(ref["stick_radius"])
        double = solve(stick_radius=b)
        radii = np.array([float(r) for r in ref["radii"]])
        row = {"stick_radius": b, "n_radii": len(radii)}
        for name in ("torque", "rigid_rotation"):
            exact = truth(ref, name)
            error = mpmath.mpf(getattr(double, name)) - exact
            row[f"{name}_error"] = float(abs(error))
            row[f"{name}_relative_error"] = float(abs(error / exact))
        for name in ("traction", "slip"):
            exact = [mpmath.mpf(v) for v in ref["extended"][name]]
            values = getattr(double, name)(radii)
            errors = [abs(mpmath.mpf(float(v)) - e) for v, e in zip(values, exact, strict=True)]
            worst = int(np.argmax([float(e) for e in errors]))
            row[f"{name}_error"] = float(errors[worst])
            row[f"{name}_worst_radius"] = ref["radii"][worst]
        rows.append(row)
    return rows


def worst(rows, key):
    row = max(rows, key=lambda r: r[key])
    return {"value": row[key], "stick_radius": row["stick_radius"],
            **({"radius": row[key.replace("_error", "_worst_radius")]} if key.replace("_error", "_worst_radius") in row
               else {})}


def solved_elsewhere(path) -> dict:
    """{(b, N): ``crosscheck.weak_forms_at(b, N)``} from the cross-check's JSON of its converged systems (its
    --converged-json; {} without one): the same numbers, not factorised twice."""
    if not path:
        return {}
    with open(path) as handle:
        data = json.load(handle)
    n = int(data["n_terms"])
    return {(float(row["stick_radius"]), n): {"published": (row["published_torque"], math.nan),
                                              "complete": (row["complete_torque"], row["complete_rigid_rotation"]),
                                              "rounding_bound": row["rounding_bound"]}
            for row in data["weak_forms"]}


def weak_form_rows(refs, radii, n_terms_list, known=None):
    """Both weak forms at every N in ``n_terms_list`` and b in ``radii`` against the truth: one factorisation per
    (b, N) for both (``crosscheck.weak_forms_at``; ``rounding_bound`` = EPS / rcond of the equilibrated system),
    except the (b, N) in ``known`` (``solved_elsewhere``)."""
    known = known or {}
    rows = []
    for ref in refs:
        if float(ref["stick_radius"]) not in radii:
            continue
        b = float(ref["stick_radius"])
        with warnings.catch_warnings():  # published T* > 4/3, Gibbs overshoot: reported, not hidden
            warnings.simplefilter("ignore", TorsionalContactWarning)
            solved = {n: known[b, n] if (b, n) in known else crosscheck.weak_forms_at(b, n) for n in n_terms_list}
        for method in ("published", "complete"):
            for n in n_terms_list:
                torque, rigid_rotation = solved[n][method]
                omega = None if method == "published" else float(abs(mpmath.mpf(rigid_rotation)
                                                                     - truth(ref, "rigid_rotation")))
                rows.append({"stick_radius": b, "method": method, "n_terms": n, "torque": torque,
                             "torque_error": float(abs(mpmath.mpf(torque) - truth(ref, "torque"))),
                             # to 3 digits: the last bits of LAPACK's condition estimate vary from run to run and
                             # with the BLAS build, and the data files are the same from one build to the next
                             "rigid_rotation_error": omega,
                             "rounding_bound": float(f"{solved[n]['rounding_bound']:.3g}")})
            print(f"  weak forms b={b} {method}: T* error at N={n_terms_list[-1]}: {rows[-1]['torque_error']:.2e}",
                  flush=True)
    return rows


def extrapolated_rows(refs, weak_rows, radii):
    """Least-squares fit T_N = T + (a + c ln N)/N to the complete form at the three largest N."""
    out = []
    for ref in refs:
        b = float(ref["stick_radius"])
        if b not in radii:
            continue
        rows = [r for r in weak_rows if r["stick_radius"] == b and r["method"] == "complete"][-3:]
        n = np.array([r["n_terms"] for r in rows], dtype=float)
        design = np.column_stack([np.ones(n.size), 1 / n, np.log(n) / n])
        torque = np.linalg.lstsq(design, np.array([r["torque"] for r in rows]), rcond=None)[0][0]
        out.append({"stick_radius": b, "n_terms": [int(x) for x in n], "torque_extrapolated": float(torque),
                    "torque_error": float(abs(mpmath.mpf(torque) - truth(ref, "torque")))})
    return out


def weak_references(paths) -> dict:
    """{(method, b, N, digits): ReferenceSolution} of the reference_weak_form.py JSONs."""
    out = {}
    for path in paths:
        for solution in load_reference_json(path):
            out[(solution.method, float(solution.stick_radius), solution.n_terms, solution.digits)] = solution
    return out


def ladder_rows(refs, radii, double_rows, digits_weak, known=None):
    """Rungs (i)-(iii) at the weak radii.  The N = 145 systems in ``digits_weak`` digits are taken from
    ``known`` (the workflow's weak-form references, when they are those systems) or solved here."""
    known = known or {}
    out = []
    for ref in refs:
        b = float(ref["stick_radius"])
        if b not in radii:
            continue
        fast = next(r for r in double_rows if r["stick_radius"] == b)
        for method in ("complete", "published"):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                double = solve(stick_radius=b, method=method, n_terms=145)
            exact145 = known.get((method, b, 145, digits_weak))
            if exact145 is None:
                exact145 = solve_reference(ref["stick_radius"], method, 145, digits_weak)
            row = {"stick_radius": b, "method": method, "fast_vs_truth_torque": fast["torque_error"],
                   "fast_vs_truth_rigid_rotation": fast["rigid_rotation_error"],
                   "double145_vs_exact145_torque": float(abs(mpmath.mpf(double.torque) - exact145.torque)),
                   "exact145_vs_truth_torque": float(abs(exact145.torque - truth(ref, "torque"))),
                   "double145_vs_exact145_rigid_rotation": None, "exact145_vs_truth_rigid_rotation": None}
            if method == "complete":
                row["double145_vs_exact145_rigid_rotation"] = float(abs(mpmath.mpf(double.rigid_rotation)
                                                                        - exact145.rigid_rotation))
                row["exact145_vs_truth_rigid_rotation"] = float(abs(exact145.rigid_rotation
                                                                    - truth(ref, "rigid_rotation")))
            out.append(row)
    return out


def plain(text: str) -> str:
    """A decimal string without exponent (for macros in running text)."""
    return format(decimal.Decimal(text), "f")


def cell(x):
    """A table cell: LaTeX scientific notation in math mode; exact zeros stay 0, None is a dash."""
    if x is None:
        return "--"
    text = sci(x, 1, always=True)
    if x != 0 and r"\times" not in text:  # sci drops a mantissa 1.0 (as text does); a column keeps it
        sign = "-" if text.startswith("-") else ""
        text = rf"{sign}1.0\times{text.removeprefix('-')}"
    return f"${text}$"


def ladder_table(ladder, b_main, digits, weak_digits):
    """The ladder as a compact booktabs table (fits the text width of an A4 page at 11 pt)."""
    rows = [r for r in ladder if r["stick_radius"] == b_main]
    comp = next(r for r in rows if r["method"] == "complete")
    pub = next(r for r in rows if r["method"] == "published")
    n_radii = len({r["stick_radius"] for r in ladder})
    lines = [
        "% generated by workflow/scripts/precision_ladder.py",
        r"\begin{tabular}{@{}l>{\raggedright\arraybackslash}p{0.44\linewidth}rrr@{}}",  # ragged: no hyphens
        r"\toprule",
        rf"& compared & \multicolumn{{2}}{{c}}{{$b/a={b_main:g}$}} & all {n_radii} radii\\",
        r"\cmidrule(lr){3-4}\cmidrule(l){5-5}",
        r"rung & & $|\Delta T^*|$ & $|\Delta\omega|\,\mu/fp_0$ & max $|\Delta T^*|$\\",
        r"\midrule",
        rf"(i) & Abel--Fredholm, double vs.\ {digits} digits & {cell(comp['fast_vs_truth_torque'])}"
        rf" & {cell(comp['fast_vs_truth_rigid_rotation'])} & {cell(max(r['fast_vs_truth_torque'] for r in ladder))}\\",
    ]
    rungs = (("(ii)", "double145_vs_exact145", rf"$N=145$: double vs.\ {weak_digits} digits"),
             ("(iii)", "exact145_vs_truth", rf"$N=145$ ({weak_digits} digits) vs.\ converged"))
    for rung, key, compared in rungs:
        for label, method, row in (("complete", "complete", comp), ("printed", "published", pub)):
            same = [r for r in ladder if r["method"] == method]
            lines.append(rf"{rung} & {label}, {compared} & {cell(row[f'{key}_torque'])}"
                         rf" & {cell(row[f'{key}_rigid_rotation'])} & {cell(max(r[f'{key}_torque'] for r in same))}\\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    return "\n".join(lines) + "\n"


def weak_table(weak, extrapolated, b_main):
    rows = [r for r in weak if r["stick_radius"] == b_main]
    n_list = sorted({r["n_terms"] for r in rows})
    lines = ["% generated by workflow/scripts/precision_ladder.py", r"\begin{tabular}{@{}lrrr@{}}", r"\toprule",
             rf"$b/a={b_main:g}$ & printed & \multicolumn{{2}}{{c}}{{complete}}\\",
             r"\cmidrule(lr){2-2}\cmidrule(l){3-4}",
             r"$N$ & $|\Delta T^*|$ & $|\Delta T^*|$ & $|\Delta\omega|\,\mu/fp_0$\\", r"\midrule"]
    for n in n_list:
        pub = next(r for r in rows if r["n_terms"] == n and r["method"] == "published")
        comp = next(r for r in rows if r["n_terms"] == n and r["method"] == "complete")
        lines.append(f"{n} & {cell(pub['torque_error'])} & {cell(comp['torque_error'])} & "
                     f"{cell(comp['rigid_rotation_error'])}\\\\")
    ext = next((r for r in extrapolated if r["stick_radius"] == b_main), None)
    if ext:
        lines.append(rf"\midrule extrapolated from $N={ext['n_terms'][0]}$--${ext['n_terms'][-1]}$ & -- & "
                     rf"{cell(ext['torque_error'])} & --\\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--references", nargs="+", required=True, help="JSONs of reference_abel_fredholm.py")
    p.add_argument("--weak-radii", type=float, nargs="+", default=[0.1, 0.3, 0.5, 0.6, 0.7, 0.9])
    p.add_argument("--weak-n-terms", type=int, nargs="+", default=[145, 290, 580, 1160, 2320, 4640])
    p.add_argument("--weak-digits", type=int, default=50, help="digits of the N = 145 reference (rung ii)")
    p.add_argument("--weak-references", nargs="*", default=[],
                   help="JSONs of reference_weak_form.py: their N = 145 systems in --weak-digits digits are "
                   "not solved again")
    p.add_argument("--main-radius", type=float, default=0.6)
    p.add_argument("--converged", default=None, help="the cross-check's JSON of both weak forms at its converged N "
                   "(precision_crosscheck.py --converged-json): the (b, N) it holds are not factorised again")
    p.add_argument("--json", required=True)
    p.add_argument("--tex", required=True, help="the ladder table")
    p.add_argument("--tex-weak", required=True, help="weak-form errors against N")
    p.add_argument("--macros", required=True)
    a = p.parse_args()

    refs = load_references(a.references)
    digits = refs[0]["digits"]
    convergence = convergence_rows(refs)
    double = double_fast_rows(refs)
    try:
        known = solved_elsewhere(a.converged)
    except (OSError, ValueError, KeyError, TypeError) as error:  # before any output is written
        p.error(f"--converged {a.converged}: not a JSON of precision_crosscheck.py --converged-json "
                f"({type(error).__name__}: {error})")
    weak = weak_form_rows(refs, a.weak_radii, a.weak_n_terms, known)
    extrapolated = extrapolated_rows(refs, weak, a.weak_radii)
    ladder = ladder_rows(refs, a.weak_radii, double, a.weak_digits, weak_references(a.weak_references))
    summary = {key: worst(double, key) for key in ("torque_error", "rigid_rotation_error", "traction_error",
                                                   "slip_error", "rigid_rotation_relative_error")}
    payload = {
        "description": "double-precision methods against the converged solution (Abel-Fredholm method in "
                       "arbitrary precision); errors absolute (T*, omega in f p0/mu, traction in f p0, slip in "
                       "f p0 a/mu) unless named relative",
        "digits": digits,
        "references": [{k: r[k] for k in ("stick_radius", "torque", "rigid_rotation", "error_estimate", "n_nodes",
                                          "working_digits")} for r in refs],
        "convergence": convergence,
        "double_fast": double,
        "double_fast_worst": summary,
        "weak_forms": weak,
        "weak_extrapolated": extrapolated,
        "ladder": ladder,
    }
    write_json(a.json, payload, method="comparison against the arbitrary-precision Abel-Fredholm reference",
               precision=f"truth: {digits} significant digits (error estimates in references); others IEEE double",
               script="workflow/scripts/precision_ladder.py")
    write_text(a.tex, ladder_table(ladder, a.main_radius, digits, a.weak_digits))
    write_text(a.tex_weak, weak_table(weak, extrapolated, a.main_radius))

    values = {"ladder-digits": digits, "ladder-n-radii": len(refs),
              "ladder-b-min": f"{min(r['stick_radius'] for r in double):g}",
              "ladder-b-max": f"{max(r['stick_radius'] for r in double):g}",
              "ladder-max-error-estimate": sci(max(float(r["error_estimate"]) for r in refs), 0)}
    for key, entry in summary.items():
        values[f"ladder-fast-{key.replace('_', '-')}"] = sci(entry["value"])
        values[f"ladder-fast-{key.replace('_', '-')}-b"] = f"{entry['stick_radius']:g}"
    for ref in refs:
        b = float(ref["stick_radius"])
        if b in a.weak_radii:
            values[f"ref{digits}-torque-b{b:g}"] = plain(ref["torque"])
            values[f"ref{digits}-omega-b{b:g}"] = plain(ref["rigid_rotation"])
    for row in weak:
        if row["stick_radius"] == a.main_radius and row["n_terms"] in (a.weak_n_terms[0], a.weak_n_terms[-1]):
            values[f"weak-{row['method']}-N{row['n_terms']}-torque-error"] = sci(row["torque_error"])
            if row["rigid_rotation_error"] is not None:
                values[f"weak-{row['method']}-N{row['n_terms']}-omega-error"] = sci(row["rigid_rotation_error"])
    write_macros(a.macros, values, "workflow/scripts/precision_ladder.py")
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
