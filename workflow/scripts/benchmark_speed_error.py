"""Speed against error: the published and complete weak forms (N sweep) and the Abel-Fredholm method (nodes).

For each stick radius every case (method and resolution) is timed in interleaved rounds (one call
of each case per round, the order rotated from round to round, one BLAS thread), so that a busy
machine slows every case alike; each case gets its median and interquartile spread, and its time
ratio to the complete weak form at the paper's N = 145 is the median of the per-round ratios.
Errors are measured against the Abel-Fredholm solution at twice its default nodes: |T* error|,
|omega error| (complete and Abel-Fredholm) and the max interface-traction error on 201 equispaced r
(series tractions T* r - sum c_n lam_n J1(lam_n r), eq. 26), of the result of each case's last timed
call (no case is solved again for its errors).  The mpmath reference of the truncated system is timed
once per precision (it takes seconds).  Writes JSON (with the machine) and macros.

Times are shown at the middle stick radius only (the work-precision figure and the macros); at the
other radii the figures show errors (fig_convergence.py), so their cases run one round: their
``timing`` holds one sample (``rounds`` of each radius says how many), not a median to quote.
"""

import argparse
import warnings

import numpy as np
from _timing import format_ratio, format_seconds, interleaved, machine, paired_ratio

from torsional_contact import fields, solve
from torsional_contact.diagnostics import TorsionalContactWarning
from torsional_contact.provenance import latex_escape, write_json, write_macros
from torsional_contact.solvers.abel_fredholm import default_nodes, solve_abel_fredholm
from torsional_contact.solvers.weak_form import solve_series
from torsional_contact.typeset import sci
from torsional_contact.verification import reference

BASELINE = ("complete", 145)


def _series_solver(b, method, n):
    def run():
        with warnings.catch_warnings():  # the accuracy warnings are what the errors below measure
            warnings.simplefilter("ignore", TorsionalContactWarning)
            return solve_series(b, method, n)

    return run


def benchmark(b, n_terms_list, nodes_list, rounds, r_grid):
    """Every case at stick radius ``b``: ``rounds`` interleaved timings and the errors of the last result."""
    exact = solve_abel_fredholm(b, 2 * default_nodes(b))
    q_exact = exact.interface_traction(r_grid)
    cases = {(m, n): _series_solver(b, m, n) for m in ("published", "complete") for n in n_terms_list}
    cases.update({("fast", n): (lambda n=n: solve_abel_fredholm(b, n)) for n in nodes_list})
    solved = {}  # the errors are those of the timed calls' results (deterministic: a re-solve gives the same)
    timings = interleaved({f"{m}:{n}": run for (m, n), run in cases.items()}, rounds, budget=60.0, results=solved)
    base = timings[f"{BASELINE[0]}:{BASELINE[1]}"]
    rows = []
    for method, n in cases:
        s = solved[f"{method}:{n}"]
        timing = timings[f"{method}:{n}"]
        if method == "fast":
            traction = s.interface_traction(r_grid)
            omega_error = abs(s.rigid_rotation - exact.rigid_rotation)
        else:
            lam = s.eigenvalues
            traction = s.torque * r_grid - fields.series_sum(1, lam, s.amplitudes * lam, r_grid, 0.0, 0.0)
            omega_error = abs(s.rigid_rotation - exact.rigid_rotation) if method == "complete" else None
        rows.append({
            "method": method, "resolution": n, "seconds": timing.median, "timing": timing.as_dict(),
            "time_ratio_vs_complete145": paired_ratio(timing, base),
            "torque": s.torque, "torque_error": abs(s.torque - exact.torque), "omega_error": omega_error,
            "traction_error": float(np.max(np.abs(traction - q_exact))),
        })
    return {"stick_radius": b, "rounds": min(len(t.samples) for t in timings.values()),
            "reference_torque": exact.torque, "reference_rigid_rotation": exact.rigid_rotation,
            "reference_nodes": exact.n_nodes, "default_nodes": default_nodes(b), "rows": rows}


def reference_sweep(b, digits_list, n_terms, exact_torque, exact_omega):
    """The mpmath/flint reference of the complete system at N terms, once per precision.

    Its error against the converged T* is the truncation error of N terms whatever the precision:
    arbitrary precision buys rounding-free digits of the truncated system only.
    """
    rows = []
    for digits in digits_list:
        solved = {}  # the timed call's result is the one reported (it takes seconds: not solved twice)
        timing = interleaved({"reference": lambda d=digits: reference.solve_reference(repr(b), "complete", n_terms, d)},
                             1, results=solved)["reference"]
        solution = solved["reference"]
        rows.append({"method": "reference", "resolution": digits, "n_terms": n_terms, "seconds": timing.median,
                     "timing": timing.as_dict(), "torque_error": abs(float(solution.torque) - exact_torque),
                     "omega_error": abs(float(solution.rigid_rotation) - exact_omega), "traction_error": None})
    return rows


def targets(rounds, n_radii=49, n_curve=200, n_torques=17):
    """Per-radius time over ``n_radii`` b in [0.02, 0.98]; a curve of ``n_curve`` radii against the
    complete weak form at N = 145 (interleaved); the inverse problem (stick radius for each of
    ``n_torques`` torques) and its torque residual."""
    radii = np.linspace(0.02, 0.98, n_radii)
    per_radius = interleaved({f"{b:.4f}": (lambda b=b: solve_abel_fredholm(b)) for b in radii}, rounds)
    medians = np.array([per_radius[f"{b:.4f}"].median for b in radii])
    curve = np.linspace(0.005, 0.995, n_curve)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TorsionalContactWarning)
        curves = interleaved({"fast": lambda: [solve_abel_fredholm(b).torque for b in curve],
                              "complete145": lambda: [solve_series(b, "complete", 145).torque for b in curve]},
                             3, budget=30.0)
    solve(torque=1.2)  # the first inverse solve of a process may build tables; the steady state is timed here
    torques = np.linspace(1.01, 1.33, n_torques)
    inverted = {}
    inverse = interleaved({f"{t:.2f}": (lambda t=t: solve(torque=t)) for t in torques}, rounds, results=inverted)
    errors = [abs(solve_abel_fredholm(inverted[f"{t:.2f}"].stick_radius).torque - t) for t in torques]
    return {
        "per_radius": {"median": float(np.median(medians)), "max": float(medians.max()),
                       "worst_b": float(radii[int(np.argmax(medians))])},
        "curve_200": {"fast": curves["fast"].as_dict(), "complete145": curves["complete145"].as_dict(),
                      "ratio": paired_ratio(curves["fast"], curves["complete145"])},
        "inverse": {"median": float(np.median([inverse[f"{t:.2f}"].median for t in torques])),
                    "max": float(max(inverse[f"{t:.2f}"].median for t in torques)),
                    "max_torque_error": float(max(errors))},
    }


def _format(result):
    lines = [f"b = {result['stick_radius']}: T* = {result['reference_torque']:.15f}, "
             f"omega = {result['reference_rigid_rotation']:.15g} (Abel-Fredholm, {result['reference_nodes']} nodes)",
             f"{'method':>9} {'res':>6} {'ms':>9} {'x145':>8} {'|dT*|':>9} {'|domega|':>9} {'max|dq|':>9}"]
    for row in result["rows"]:
        omega = "-" if row["omega_error"] is None else f"{row['omega_error']:.1e}"
        ratio = row.get("time_ratio_vs_complete145")
        ratio = f"{ratio['median']:8.3g}" if ratio else " " * 8
        traction = "-" if row["traction_error"] is None else f"{row['traction_error']:.1e}"
        lines.append(f"{row['method']:>9} {row['resolution']:>6} {1e3 * row['seconds']:9.3f} "
                     f"{ratio} {row['torque_error']:9.1e} {omega:>9} {traction:>9}")
    return "\n".join(lines)


def _latex_seconds(seconds):
    return format_seconds(seconds).replace(" us", r"\,$\mu$s").replace(" ms", r"\,ms").replace(" s", r"\,s")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--stick-radius", type=float, nargs="+", default=[0.3, 0.6, 0.9])
    p.add_argument("--n-terms", type=int, nargs="+", default=[145, 290, 580, 1160, 2320])
    p.add_argument("--nodes", type=int, nargs="+", default=[6, 10, 14, 18, 24, 32])
    p.add_argument("--repeats", type=int, default=7, help="interleaved rounds (at the middle stick radius; the "
                   "others run one: only their errors are shown)")
    p.add_argument("--reference-digits", type=int, nargs="*", default=[20, 30, 50])
    p.add_argument("--per-radius-radii", type=int, default=49, help="stick radii in [0.02, 0.98] timed one by one")
    p.add_argument("--curve-radii", type=int, default=200, help="stick radii of the timed T*(b) curve")
    p.add_argument("--inverse-torques", type=int, default=17, help="torques in [1.01, 1.33] of the inverse solve")
    p.add_argument("--json", help="JSON file (written atomically)")
    p.add_argument("--macros", help="LaTeX macros of the quoted numbers")
    a = p.parse_args()
    if 145 not in a.n_terms:
        p.error("--n-terms must include 145 (the ratios are relative to it)")
    r_grid = np.linspace(0.0, 1.0, 201)
    results = []
    timed_radius = a.stick_radius[len(a.stick_radius) // 2]  # the radius whose times the figure and macros show
    for b in a.stick_radius:
        result = benchmark(b, sorted(a.n_terms), sorted(a.nodes), a.repeats if b == timed_radius else 1, r_grid)
        if a.reference_digits and b == timed_radius:
            result["rows"] += reference_sweep(b, a.reference_digits, 145, result["reference_torque"],
                                              result["reference_rigid_rotation"])
        print(_format(result), flush=True)
        results.append(result)
    goals = targets(a.repeats, a.per_radius_radii, a.curve_radii, a.inverse_torques)
    print(goals)
    host = machine()
    if a.json:
        write_json(a.json, {"results": results, "targets": goals, "machine": host},
                   method="interleaved rounds of wall times (median, interquartile range); ratios as medians of "
                   "per-round ratios; errors against the Abel-Fredholm method at twice its default nodes",
                   precision="IEEE double")
    if a.macros:
        mid = results[len(results) // 2]

        def row(method, resolution):
            return next(r for r in mid["rows"] if r["method"] == method and r["resolution"] == resolution)

        fast_default = min((r for r in mid["rows"] if r["method"] == "fast"),
                           key=lambda r: abs(r["resolution"] - mid["default_nodes"]))
        base = row(*BASELINE)
        curve = goals["curve_200"]
        write_macros(a.macros, {
            "bench-b": f"{mid['stick_radius']:g}",
            "bench-complete145-time": _latex_seconds(base["seconds"]),
            "bench-complete145-error": sci(base["torque_error"]),
            "bench-complete145-traction-error": sci(base["traction_error"]),
            "bench-fast-time": _latex_seconds(fast_default["seconds"]),
            "bench-fast-nodes": fast_default["resolution"],
            "bench-fast-error": sci(max(fast_default["torque_error"], 1e-16), 0),
            "bench-fast-ratio": format_ratio(fast_default["time_ratio_vs_complete145"]["median"]),
            "bench-fast-ratio-low": format_ratio(fast_default["time_ratio_vs_complete145"]["q25"]),
            "bench-fast-ratio-high": format_ratio(fast_default["time_ratio_vs_complete145"]["q75"]),
            "bench-per-radius-max": _latex_seconds(goals["per_radius"]["max"]),
            "bench-curve-ratio": format_ratio(curve["ratio"]["median"]),
            "bench-curve-radii": a.curve_radii,
            "bench-curve-time": _latex_seconds(curve["fast"]["median"]),
            "bench-inverse-time": _latex_seconds(goals["inverse"]["median"]),
            "bench-inverse-error": sci(max(goals["inverse"]["max_torque_error"], 1e-16), 0),
            "bench-cpu": latex_escape(f"{host['cpu']}, {host['cores']} cores"),
            "bench-load": f"{host['load_average'][0]:.1f}" if host["load_average"] else "unknown",
        }, "workflow/scripts/benchmark_speed_error.py")


if __name__ == "__main__":
    main()
