"""Accuracy of the monotonic-curve interpolants (``torsional_contact.curves``) against direct solves.

At random points that are not nodes (``--per-panel`` in every panel of the stick-radius table,
and torques mapped from random points of the torque table, including both ends), the
interpolants are compared with the Abel-Fredholm solver: T*(b), 4/3 - T*(b), omega(b),
W_mono(b) directly; b(T*), omega_m(T*), W_mono(T*) after a root search on the solver alone
(Brent's method; on 4/3 - T* next to spinning).  The loop energy by its two routes (friction
over the slip annulus, pi x loop area) is compared over a range of torque ranges.
Units: b in a, T* = 2T/(f F a), omega in f p0 / mu, energies in (f p0)^2 a^3 / mu.
"""

from __future__ import annotations

import argparse
import functools
import time
import warnings

import numpy as np
from scipy import optimize

from torsional_contact import ResolutionWarning
from torsional_contact.criteria import spinning_deficit
from torsional_contact.curves import abel_fredholm_loading_work, monotonic_curves
from torsional_contact.histories import dissipation_from_loop_area, dissipation_per_cycle
from torsional_contact.provenance import write_json, write_macros
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.typeset import sci


@functools.cache
def direct(b):
    """The Abel-Fredholm solution at b, kept: the root search's best point is one it evaluated, and is
    compared at once (33 of 262 solves at the default settings)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        return solve_abel_fredholm(b)


def by_radius(curves, per_panel, rng):
    edges = curves.by_radius["torque"].edges
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        for b in lo + (hi - lo) * rng.uniform(0.02, 0.98, per_panel):
            s = direct(b)
            w = abel_fredholm_loading_work(s)
            rows.append({"b": b, "torque": abs(curves.torque(b) - s.torque),
                         "torque_gap_rel": abs(curves.torque_gap(b) / s.torque_deficit - 1),
                         "rigid_rotation": abs(curves.rotation_at_radius(b) - s.rigid_rotation),
                         "loading_work_rel": abs(curves.work_at_radius(b) / w - 1)})
    return rows


def root(curves, tau):
    guess = float(curves.stick_radius(tau))
    lo, hi = max(guess * (1 - 1e-6) - 1e-12, 1e-7), min(guess * (1 + 1e-6) + 1e-12, curves.b_high)
    if tau > curves.t_split:
        gap = float(spinning_deficit(tau))
        return optimize.brentq(lambda b: direct(b).torque_deficit - gap, lo, hi, xtol=1e-17, rtol=1e-15)
    return optimize.brentq(lambda b: direct(b).torque - tau, lo, hi, xtol=1e-16, rtol=1e-15)


def by_torque(curves, per_panel, rng):
    taus = []
    for curve, to_tau in ((curves.t_curves["stick_radius"], lambda v: v),
                          (curves.u_curves["stick_radius"], lambda v: 4.0 / 3.0 - v**3)):
        edges = curve.edges
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            taus += [float(to_tau(v)) for v in lo + (hi - lo) * rng.uniform(0.02, 0.98, per_panel)]
    rows = []
    for tau in taus:
        if tau <= curves.trust_torque or curves.stick_radius(tau) == 0.0:  # asymptotes; spinning as in solve
            continue
        b = root(curves, tau)
        s = direct(b)
        slope = abs(float(curves.by_radius["torque"].derivative(b)))
        rows.append({"torque": tau, "b": b, "stick_radius": abs(curves.stick_radius(tau) - b),
                     # rounding of tau moves b by this much (None where dT*/db vanishes to rounding, b -> 0)
                     "conditioning": float(np.spacing(tau)) / slope if slope > 0 else None,
                     "rigid_rotation": abs(curves.rotation(tau) - s.rigid_rotation),
                     "loading_work_rel": abs(curves.work(tau) / abel_fredholm_loading_work(s) - 1)})
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--per-panel", type=int, default=2)
    p.add_argument("--seed", type=int, required=True, help="of the random test points")
    p.add_argument("--json", required=True)
    p.add_argument("--macros")
    a = p.parse_args()
    start = time.perf_counter()
    rng = np.random.default_rng(a.seed)
    curves = monotonic_curves()
    radius_rows, torque_rows = by_radius(curves, a.per_panel, rng), by_torque(curves, a.per_panel, rng)
    ranges = np.concatenate([2 + np.geomspace(1e-3, 0.6, 12), [2.66]])
    routes = [{"torque_range": float(r), "friction": dissipation_per_cycle(r),
               "loop_area": dissipation_from_loop_area(r)} for r in ranges]
    for row in routes:
        row["relative_difference"] = abs(row["loop_area"] / row["friction"] - 1)
    resolved = [r for r in radius_rows if 1 - r["b"] > 3e-4]

    def worst(rows, key):
        return float(max(r[key] for r in rows))

    summary = {
        "torque_abs": worst([r for r in radius_rows if 1 - r["b"] > 2e-5], "torque"),
        "torque_abs_next_to_b_max": worst(radius_rows, "torque"),
        "torque_gap_rel": worst(radius_rows, "torque_gap_rel"),
        "rigid_rotation_abs": worst(radius_rows, "rigid_rotation"),
        "loading_work_rel_resolved": worst(resolved, "loading_work_rel"),
        "loading_work_rel_all": worst(radius_rows, "loading_work_rel"),
        "stick_radius_abs": worst(torque_rows, "stick_radius"),
        "rotation_by_torque_abs": worst(torque_rows, "rigid_rotation"),
        "work_by_torque_rel": worst([r for r in torque_rows if r["torque"] > 1.0005], "loading_work_rel"),
        "loop_energy_routes_rel": worst([r for r in routes if r["friction"] > 1e-3], "relative_difference"),
        "loop_energy_routes_abs_near_threshold": float(max(abs(r["loop_area"] - r["friction"]) for r in routes
                                                           if r["friction"] <= 1e-3)),
        "points": len(radius_rows) + len(torque_rows),
    }
    write_json(a.json, {"summary": summary, "by_radius": radius_rows, "by_torque": torque_rows,
                        "loop_energy": routes, "table": {k: v for k, v in curves.table.items()
                                                         if k in ("domain", "solves", "method")}},
               seed=a.seed)
    print(f"curve accuracy in {time.perf_counter() - start:.1f} s")
    if a.macros:
        write_macros(a.macros, {f"curves-{k.replace('_', '-')}": sci(v, 0) if isinstance(v, float) else v
                                for k, v in summary.items()}, "workflow/scripts/curve_accuracy.py")
    print(summary)


if __name__ == "__main__":
    main()
