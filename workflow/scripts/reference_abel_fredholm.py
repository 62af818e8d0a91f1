"""Converged partial-slip solutions at given stick radii in arbitrary precision (one workflow job).

Writes one JSON per stick radius with T*, omega, the interface traction and slip at fixed radii
(decimal strings with the requested significant digits, and the finer solve's values with all its
working digits for comparisons below 10^-digits), the error estimates and metadata; optionally
T* and omega against the number of Nystrom nodes at given working precisions (the convergence
study of the precision ladder).  Several radii per job: the process start-up, the torque constant
and the xi-functions of shared quadrature panels are paid once (each file is the same as from a
job of its own).
"""

import argparse
import decimal
import time

import mpmath

from torsional_contact.provenance import write_json
from torsional_contact.verification.abel_fredholm_mp import solve_reference_abel_fredholm
from torsional_contact.verification.arbitrary_precision import arb_to_mp, working_digits
from torsional_contact.verification.nystrom_mp import solve_state

#: Radii of the traction and slip profiles: r = 0, 0.05, ..., 1 and four points at 10^-2 and
#: 10^-4 of the stick disc / slip annulus from the edge r = b.
GRID = [f"{k / 20:.2f}" for k in range(21)]


def profile_radii(stick_radius: str) -> list:
    """GRID plus b (1 - 10^-k) and b + (1 - b) 10^-k, k = 2, 4, as exact decimal strings."""
    b = decimal.Decimal(stick_radius)
    near = [b * (1 - decimal.Decimal(10) ** -k) for k in (2, 4)] + [b + (1 - b) * decimal.Decimal(10) ** -k
                                                                     for k in (2, 4)]
    return sorted(set(GRID) | {str(r) for r in near}, key=decimal.Decimal)


def convergence(stick_radius: str, nodes, digits_list) -> list:
    """T* and omega of single solves at each (working digits, n): the convergence in n."""
    rows = []
    for work in digits_list:
        for n in nodes:
            start = time.perf_counter()
            state = solve_state(stick_radius, int(n), int(work))
            with working_digits(int(work)):
                rows.append({
                    "working_digits": int(work),
                    "n_nodes": int(n),
                    "torque": mpmath.nstr(arb_to_mp(state.torque), int(work) + 5),
                    "rigid_rotation": mpmath.nstr(arb_to_mp(state.rigid_rotation), int(work) + 5),
                    "seconds": round(time.perf_counter() - start, 3),
                })
            print(f"  b={stick_radius} digits={work} n={n}: T*={rows[-1]['torque'][:24]}", flush=True)
    return rows


def reference(stick_radius: str, digits: int, nodes, digits_list, json_path: str, timing_path: str | None) -> None:
    """One stick radius: the reference, its profiles, the optional node sweep; writes its two files."""
    start = time.perf_counter()
    result = solve_reference_abel_fredholm(stick_radius, digits)
    radii = profile_radii(stick_radius)
    record = result.as_dict(radii, extended=True)
    record["stick_radius"] = stick_radius
    record["extended"]["note"] = "the finer solve with all its working digits (accurate to about the error estimates)"
    fine = result.fine
    if nodes:
        record["convergence"] = convergence(stick_radius, nodes, digits_list)
    timing = {"seconds_total": round(time.perf_counter() - start, 3), "seconds": record.pop("seconds", None),
              "cpu_seconds": record.pop("cpu_seconds", None),
              "convergence_seconds": [row.pop("seconds") for row in record.get("convergence", [])]}
    if timing_path:
        write_json(timing_path, timing, method="wall time of the arbitrary-precision Abel-Fredholm reference "
                   "(in a job that may hold several radii: the process start-up is not included)",
                   stick_radius=stick_radius, digits=digits)
    write_json(json_path, record, method="Abel-Fredholm method (F1)-(F7) in arbitrary precision (python-flint arb)",
               resolution=f"{result.n_nodes} Nystrom nodes (check solve {result.coarse.n_nodes})",
               precision=f"{fine.work_digits} working digits (check solve {result.coarse.work_digits})",
               script="workflow/scripts/reference_abel_fredholm.py")
    print(f"b={stick_radius}: T*={record['torque']} omega={record['rigid_rotation']} "
          f"(estimate {record['error_estimate']}, {timing['seconds']} s)", flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--stick-radii", nargs="+", required=True, help="b/a in (0, 1), exact decimals")
    p.add_argument("--digits", type=int, default=30)
    p.add_argument("--convergence", nargs="*", default=[], metavar="B:N1,N2,...",
                   help="node sweep at stick radius B (one of --stick-radii) with nodes N1, N2, ...")
    p.add_argument("--convergence-digits", type=int, nargs="*", default=[30, 40])
    p.add_argument("--json", nargs="+", required=True, help="one JSON per stick radius, in the same order")
    p.add_argument("--timing", nargs="*", default=[],
                   help="JSON of the wall times per stick radius (kept apart from the data, which stay the same)")
    a = p.parse_args()
    if len(a.json) != len(a.stick_radii) or (a.timing and len(a.timing) != len(a.stick_radii)):
        p.error("--json (and --timing, if given) need one file per stick radius")
    sweeps = {}
    for item in a.convergence:
        radius, _, nodes = item.partition(":")
        try:
            sweeps[radius] = [int(n) for n in nodes.split(",")]
        except ValueError:
            p.error(f"--convergence must be B:N1,N2,... with integer nodes, got {item!r}")
        if radius not in a.stick_radii:
            p.error(f"--convergence radius {radius} is not one of --stick-radii")
    timings = a.timing or [None] * len(a.stick_radii)
    for radius, json_path, timing_path in zip(a.stick_radii, a.json, timings, strict=True):
        reference(radius, a.digits, sweeps.get(radius, []), a.convergence_digits, json_path, timing_path)


if __name__ == "__main__":
    main()
