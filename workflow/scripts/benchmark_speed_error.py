"""Speed against error: published and complete weak forms (n_terms) and the Abel-Fredholm solver.

For each stick radius, every method is timed (median of repeated solves, one thread) and
its error measured against the Abel-Fredholm solution at twice its default resolution:
|T* error|, |omega error| (complete and fast only) and the max interface-traction error
on a grid of r in [0, 1] (series tractions T* r - sum c_n lam_n J1(lam_n r), eq. 26).
Ratios are relative to the complete formulation at n_terms = 145 measured in the same
run.  Prints a table; optionally writes JSON with the machine description.
"""

import argparse
import math
import os
import platform
import statistics
import time
import warnings

import numpy as np

from torsional_contact import fields, solve
from torsional_contact.diagnostics import TorsionalContactWarning
from torsional_contact.provenance import latex_escape, write_json, write_macros
from torsional_contact.solvers.abel_fredholm import default_nodes, solve_fast
from torsional_contact.solvers.weak_form import solve_series
from torsional_contact.verification import reference


def _median_time(function, repeats, budget=2.0):
    """Median wall time of ``function()`` over up to ``repeats`` calls (fewer if slow)."""
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = function()
        samples.append(time.perf_counter() - start)
        if sum(samples) > budget and len(samples) >= 3:
            break
    return statistics.median(samples), len(samples), result


def _cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as handle:
            for line in handle:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError as error:  # not Linux: say so in the record rather than guess
        return f"unknown ({error.__class__.__name__})"
    return "unknown"


def benchmark(b, n_terms_list, nodes_list, repeats, r_grid):
    reference = solve_fast(b, 2 * default_nodes(b))
    q_ref = reference.interface_traction(r_grid)
    rows = []
    for method in ("published", "complete"):
        for n in n_terms_list:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", TorsionalContactWarning)
                seconds, count, s = _median_time(lambda m=method, n=n: solve_series(b, m, n), repeats)
            lam = s.eigenvalues
            q = s.torque * r_grid - fields.series_sum(1, lam, s.amplitudes * lam, r_grid, 0.0, 0.0)
            omega_error = abs(s.rigid_rotation - reference.rigid_rotation) if method == "complete" else None
            rows.append({
                "method": method, "resolution": n, "seconds": seconds, "repeats": count,
                "torque": s.torque, "torque_error": abs(s.torque - reference.torque),
                "omega_error": omega_error, "traction_error": float(np.max(np.abs(q - q_ref))),
            })
    for n in nodes_list:
        seconds, count, s = _median_time(lambda n=n: solve_fast(b, n), max(repeats, 15))
        rows.append({
            "method": "fast", "resolution": n, "seconds": seconds, "repeats": count,
            "torque": s.torque, "torque_error": abs(s.torque - reference.torque),
            "omega_error": abs(s.rigid_rotation - reference.rigid_rotation),
            "traction_error": float(np.max(np.abs(s.interface_traction(r_grid) - q_ref))),
        })
    base = next(row for row in rows if row["method"] == "complete" and row["resolution"] == 145)
    for row in rows:  # (reference rows are appended later, without ratios)
        row["time_ratio_vs_complete145"] = row["seconds"] / base["seconds"]
        row["torque_error_ratio_vs_complete145"] = row["torque_error"] / base["torque_error"]
        row["traction_error_ratio_vs_complete145"] = row["traction_error"] / base["traction_error"]
    return {"stick_radius": b, "reference_torque": reference.torque,
            "reference_rigid_rotation": reference.rigid_rotation,
            "reference_nodes": reference.n_nodes, "rows": rows}


def reference_sweep(b, digits_list, n_terms, exact_torque, exact_omega):
    """The mpmath/flint reference of the complete system at N terms: time against error.

    Its error against the converged T* is the truncation error of N terms whatever the
    precision: arbitrary precision buys rounding-free digits of the truncated system only.
    """
    rows = []
    for digits in digits_list:
        start = time.perf_counter()
        solution = reference.solve_reference(repr(b), "complete", n_terms, digits)
        seconds = time.perf_counter() - start
        rows.append({"method": "reference", "resolution": digits, "n_terms": n_terms, "seconds": seconds,
                     "repeats": 1, "torque_error": abs(float(solution.torque) - exact_torque),
                     "omega_error": abs(float(solution.rigid_rotation) - exact_omega), "traction_error": None})
    return rows


def targets(repeats):
    """The speed targets, measured: per-radius time over b in [0.02, 0.98], a curve of
    200 radii, the inverse problem; with the complete formulation (N = 145) as baseline."""
    radii = np.linspace(0.02, 0.98, 49)
    per_radius = [_median_time(lambda b=b: solve_fast(b), repeats)[0] for b in radii]
    curve = np.linspace(0.005, 0.995, 200)
    fast_curve = _median_time(lambda: [solve_fast(b).torque for b in curve], 3, budget=10)[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TorsionalContactWarning)
        series_curve = _median_time(lambda: [solve_series(b, "complete", 145).torque for b in curve], 3,
                                    budget=10)[0]
    solve(torque=1.2)  # builds the once-per-process bracket table, timed separately below
    table_seconds = _median_time(lambda: solve(torque=1.2, method="fast"), 1)[0]
    inverse = [_median_time(lambda t=t: solve(torque=t), repeats)[0] for t in np.linspace(1.01, 1.33, 17)]
    errors = [abs(solve_fast(solve(torque=t).stick_radius).torque - t) for t in np.linspace(1.01, 1.33, 17)]
    return {"per_radius_max_seconds": max(per_radius), "per_radius_median_seconds": float(np.median(per_radius)),
            "per_radius_worst_b": float(radii[int(np.argmax(per_radius))]),
            "curve_200_seconds": fast_curve, "curve_200_complete145_seconds": series_curve,
            "inverse_median_seconds": float(np.median(inverse)), "inverse_max_seconds": max(inverse),
            "inverse_max_torque_error": max(errors), "first_inverse_seconds_after_table": table_seconds}


def _format(result):
    lines = [f"b = {result['stick_radius']}: T* = {result['reference_torque']:.15f}, "
             f"omega = {result['reference_rigid_rotation']:.15g} (fast, {result['reference_nodes']} nodes)",
             f"{'method':>9} {'res':>6} {'ms':>9} {'x145':>8} {'|dT*|':>9} {'|domega|':>9} {'max|dq|':>9}"]
    for row in result["rows"]:
        omega = "-" if row["omega_error"] is None else f"{row['omega_error']:.1e}"
        ratio = f"{row['time_ratio_vs_complete145']:8.3f}" if "time_ratio_vs_complete145" in row else " " * 8
        traction = "-" if row["traction_error"] is None else f"{row['traction_error']:.1e}"
        lines.append(f"{row['method']:>9} {row['resolution']:>6} {1e3 * row['seconds']:9.3f} "
                     f"{ratio} {row['torque_error']:9.1e} {omega:>9} {traction:>9}")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--stick-radius", type=float, nargs="+", default=[0.3, 0.6, 0.9])
    p.add_argument("--n-terms", type=int, nargs="+", default=[145, 290, 580, 1160, 2320])
    p.add_argument("--nodes", type=int, nargs="+", default=[6, 10, 14, 18, 24, 32])
    p.add_argument("--repeats", type=int, default=7)
    p.add_argument("--reference-digits", type=int, nargs="*", default=[20, 30, 50])
    p.add_argument("--json", help="JSON file (written atomically)")
    p.add_argument("--macros", help="LaTeX macros of the quoted numbers")
    a = p.parse_args()
    if 145 not in a.n_terms:
        p.error("--n-terms must include 145 (the ratios are relative to it)")
    r_grid = np.linspace(0.0, 1.0, 201)
    results = []
    for b in a.stick_radius:
        result = benchmark(b, sorted(a.n_terms), sorted(a.nodes), a.repeats, r_grid)
        if a.reference_digits and b == a.stick_radius[len(a.stick_radius) // 2]:
            result["rows"] += reference_sweep(b, a.reference_digits, 145, result["reference_torque"],
                                              result["reference_rigid_rotation"])
        print(_format(result), flush=True)
        results.append(result)
    goals = targets(a.repeats)
    print(goals)
    if a.json:
        threads = {k: os.environ.get(k) for k in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")}
        write_json(a.json, {"results": results, "targets": goals},
                   method="median wall time of repeated solves; errors against solve_fast at twice the default "
                   "nodes; traction on 201 equispaced r",
                   cpu=_cpu_model(), platform=platform.platform(), threads=threads,
                   load_average=list(os.getloadavg()) if hasattr(os, "getloadavg") else None,
                   precision="IEEE double", timer_resolution=time.get_clock_info("perf_counter").resolution,
                   nan_policy="none" if all(math.isfinite(r["reference_torque"]) for r in results) else "present")
    if a.macros:
        mid = results[len(results) // 2]

        def row(method, resolution):
            return next(r for r in mid["rows"] if r["method"] == method and r["resolution"] == resolution)

        fast_default = min((r for r in mid["rows"] if r["method"] == "fast"), key=lambda r: abs(
            r["resolution"] - default_nodes(mid["stick_radius"])))
        base = row("complete", 145)
        write_macros(a.macros, {
            "bench-b": f"{mid['stick_radius']:g}",
            "bench-complete145-ms": f"{1e3 * base['seconds']:.2f}",
            "bench-complete145-error": f"{base['torque_error']:.1e}",
            "bench-complete145-traction-error": f"{base['traction_error']:.1e}",
            "bench-fast-ms": f"{1e3 * fast_default['seconds']:.2f}",
            "bench-fast-error": f"{max(fast_default['torque_error'], 1e-16):.0e}",
            "bench-fast-ratio": f"{fast_default['time_ratio_vs_complete145']:.2f}",
            "bench-per-radius-max-ms": f"{1e3 * goals['per_radius_max_seconds']:.1f}",
            "bench-curve-ms": f"{1e3 * goals['curve_200_seconds']:.0f}",
            "bench-curve-complete-ms": f"{1e3 * goals['curve_200_complete145_seconds']:.0f}",
            "bench-inverse-ms": f"{1e3 * goals['inverse_median_seconds']:.1f}",
            "bench-inverse-error": f"{goals['inverse_max_torque_error']:.0e}",
            "bench-cpu": latex_escape(_cpu_model()),
        }, "workflow/scripts/benchmark_speed_error.py")


if __name__ == "__main__":
    main()
