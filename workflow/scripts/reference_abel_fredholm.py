"""Converged partial-slip solution at one stick radius in arbitrary precision (one workflow job).

Writes a JSON with T*, omega, the interface traction and slip at fixed radii (decimal
strings with the requested significant digits, and the finer solve's values with all its
working digits for comparisons below 10^-digits), the error estimates and metadata;
optionally T* and omega against the number of Nystrom nodes at given working precisions
(the convergence study of the precision ladder).
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


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--stick-radius", required=True, help="b/a in (0, 1), an exact decimal")
    p.add_argument("--digits", type=int, default=30)
    p.add_argument("--convergence-nodes", type=int, nargs="*", default=[])
    p.add_argument("--convergence-digits", type=int, nargs="*", default=[30, 40])
    p.add_argument("--json", required=True)
    p.add_argument("--timing", help="JSON of the wall times (kept apart from the data, which stay the same)")
    a = p.parse_args()

    start = time.perf_counter()
    result = solve_reference_abel_fredholm(a.stick_radius, a.digits)
    radii = profile_radii(a.stick_radius)
    record = result.as_dict(radii, extended=True)
    record["stick_radius"] = a.stick_radius
    record["extended"]["note"] = "the finer solve with all its working digits (accurate to about the error estimates)"
    fine = result.fine
    if a.convergence_nodes:
        record["convergence"] = convergence(a.stick_radius, a.convergence_nodes, a.convergence_digits)
    timing = {"seconds_total": round(time.perf_counter() - start, 3), "seconds": record.pop("seconds", None),
              "cpu_seconds": record.pop("cpu_seconds", None),
              "convergence_seconds": [row.pop("seconds") for row in record.get("convergence", [])]}
    if a.timing:
        write_json(a.timing, timing, method="wall time of the arbitrary-precision Abel-Fredholm reference",
                   stick_radius=a.stick_radius, digits=a.digits)
    write_json(a.json, record, method="Abel-Fredholm method (F1)-(F7) in arbitrary precision (python-flint arb)",
               resolution=f"{result.n_nodes} Nystrom nodes (check solve {result.coarse.n_nodes})",
               precision=f"{fine.work_digits} working digits (check solve {result.coarse.work_digits})",
               script="workflow/scripts/reference_abel_fredholm.py")
    print(f"b={a.stick_radius}: T*={record['torque']} omega={record['rigid_rotation']} "
          f"(estimate {record['error_estimate']}, {timing['seconds']} s)")


if __name__ == "__main__":
    main()
