"""Finite-element validation of T*, omega and the fields against the Abel-Fredholm and direct methods.

For each stick radius b, the axisymmetric finite-element solution
(torsional_contact.verification.finite_element: weighted Laplacian for w = u_theta / r,
Lagrange P4 triangles on meshes graded toward the stick/slip front and the corner, T*
from the regularity condition by an interaction integral, omega from the torque-free
Dini modes) is computed on a sequence of mesh levels, and compared with the Abel-Fredholm
solution (``solve``, the default method) and, for T* and omega, the direct collocation
method (``solve_direct``).  The FEM's own error estimate is the change between the two
finest levels; its observed order comes from the three finest levels (no reference
needed) and, separately, from the errors against the Abel-Fredholm values.

Writes JSON (all levels and metadata; the timings go to the log only, so the data file is the same
from one build to the next), a booktabs table body and LaTeX macros.
Bad input: exit status 2, one line on stderr, nothing on stdout.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from importlib import metadata

import numpy as np

from torsional_contact import solve
from torsional_contact.provenance import write_json, write_macros, write_text
from torsional_contact.typeset import sci
from torsional_contact.verification.collocation import solve_direct
from torsional_contact.verification.finite_element import ELEMENTS, solve_finite_element

SOURCE = "workflow/scripts/fem_validation.py"
#: Interior points (r, z) where the stresses are compared.
STRESS_POINTS = ((0.5, 0.1), (0.9, 0.05), (0.95, 0.2), (0.3, 0.3))
#: Point where u_theta is compared.
DISPLACEMENT_POINT = (0.5, 0.1)
#: Stick-disc radii, as fractions of b, where the interface traction is compared.
TRACTION_FRACTIONS = (0.25, 0.5, 0.75)


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line on stderr, exit status 2, nothing on stdout
        sys.stderr.write(f"fem_validation.py: error: {message}\n")
        sys.exit(2)


def parse_arguments(argv=None):
    p = _Parser(description=__doc__.splitlines()[0])
    p.add_argument("--stick-radii", type=float, nargs="+", default=[0.3, 0.6, 0.9], help="b values in (0, 1)")
    p.add_argument("--mesh-levels", type=int, nargs="+", default=[4, 8, 16],
                   help="increasing mesh levels >= 3, best a geometric sequence (the observed order assumes one); "
                        "the last is the reported solution")
    p.add_argument("--degree", type=int, required=True, help=f"Lagrange degree, one of {sorted(ELEMENTS)}")
    p.add_argument("--truncation", type=float, required=True, help="height L of the meshed cylinder (> 1)")
    p.add_argument("--direct", action=argparse.BooleanOptionalAction, required=True,
                   help="also run the direct collocation method (about 10 s per radius)")
    p.add_argument("--json")
    p.add_argument("--tex")
    p.add_argument("--macros")
    a = p.parse_args(argv)
    if not all(0.0 < b < 1.0 for b in a.stick_radii):  # also rejects nan
        p.error(f"--stick-radii must lie in (0, 1), got {a.stick_radii}")
    if len(a.mesh_levels) < 2 or a.mesh_levels[0] < 3 or any(np.diff(a.mesh_levels) <= 0):
        p.error(f"--mesh-levels must be at least two increasing integers >= 3, got {a.mesh_levels}")
    if a.degree not in ELEMENTS:
        p.error(f"--degree must be one of {sorted(ELEMENTS)}, got {a.degree}")
    if not (math.isfinite(a.truncation) and a.truncation > 1.0):
        p.error(f"--truncation must be a number > 1, got {a.truncation}")
    return a


def _order(coarse, fine, levels):
    """ln(coarse / fine) / ln(level ratio), None when undefined."""
    if coarse > 0 and fine > 0:
        return math.log(coarse / fine) / math.log(levels[1] / levels[0])
    return None


def self_order(values, levels):
    """Observed order from the three finest levels (geometric level ratio assumed), None if fewer."""
    if len(values) < 3:
        return None
    v = np.asarray(values[-3:], dtype=float)
    coarse = float(np.max(np.abs(v[1] - v[0])))
    fine = float(np.max(np.abs(v[2] - v[1])))
    return _order(coarse, fine, levels[-2:])


def fields_of(solution, b):
    """Stresses at STRESS_POINTS, u_theta at DISPLACEMENT_POINT, stick traction, as plain lists."""
    r, z = (np.array(c) for c in zip(*STRESS_POINTS, strict=True))
    sigma_zt, sigma_rt = solution.stress(r, z)
    radii = b * np.array(TRACTION_FRACTIONS)
    return {
        "sigma_zt": [float(x) for x in sigma_zt],
        "sigma_rt": [float(x) for x in sigma_rt],
        "u_theta": float(solution.displacement(*DISPLACEMENT_POINT)),
        "stick_traction": [float(x) for x in solution.traction(radii)],
    }


def study_radius(b, levels, degree, truncation, direct):
    """All levels of the FEM for one b, the Abel-Fredholm and direct values, and the comparison."""
    reference = solve(stick_radius=b)
    ref = {"torque": reference.torque, "rigid_rotation": reference.rigid_rotation, **fields_of(reference, b)}
    runs = []
    for level in levels:
        start = time.perf_counter()
        fem = solve_finite_element(b, level=level, degree=degree, truncation=truncation)
        seconds = time.perf_counter() - start
        runs.append({"level": level, "n_dofs": fem.n_dofs, "torque": fem.torque,
                     "torque_alternative_cutoff": fem.torque_alternative, "rigid_rotation": fem.rigid_rotation,
                     "torque_balance": fem.torque_from_traction - fem.torque,
                     "front_coefficients": list(fem.front_coefficients), **fields_of(fem, b)})
        print(f"b = {b:g}, level {level}: {fem.n_dofs} unknowns, {seconds:.2f} s, T* = {fem.torque:.14f}, "
              f"omega = {fem.rigid_rotation:.14f}", flush=True)
    record = {"stick_radius": b, "levels": runs, "abel_fredholm": ref}
    if direct:
        collocation = solve_direct(b)
        record["direct"] = {"torque": collocation.torque, "rigid_rotation": collocation.rigid_rotation,
                            "residual": collocation.residual}
    record["comparison"] = compare(record, levels)
    return record


def compare(record, levels):
    """Finest FEM value, differences, error estimate and observed orders for each compared quantity."""
    runs, ref = record["levels"], record["abel_fredholm"]
    out = {}
    for name in ("torque", "rigid_rotation", "u_theta", "stress", "stick_traction"):
        if name == "stress":
            values = [np.r_[run["sigma_zt"], run["sigma_rt"]] for run in runs]
            exact = np.r_[ref["sigma_zt"], ref["sigma_rt"]]
        else:
            values = [np.atleast_1d(run[name]) for run in runs]
            exact = np.atleast_1d(ref[name])
        errors = [float(np.max(np.abs(v - exact))) for v in values]
        entry = {
            "fem_minus_abel_fredholm": errors[-1],
            "estimate": float(np.max(np.abs(values[-1] - values[-2]))),
            "order_self": self_order(values, levels),
            "order_vs_abel_fredholm": [_order(errors[k], errors[k + 1], levels[k:k + 2]) for k in range(len(runs) - 1)],
            "errors_by_level": errors,
        }
        if values[-1].size == 1:
            entry.update(fem=float(values[-1][0]), abel_fredholm=float(exact[0]),
                         fem_minus_abel_fredholm=float(values[-1][0] - exact[0]))
        if name in ("torque", "rigid_rotation") and "direct" in record:
            entry["direct"] = record["direct"][name]
            entry["direct_minus_abel_fredholm"] = record["direct"][name] - float(exact[0])
        out[name] = entry
    balance = [abs(run["torque_balance"]) for run in runs]
    out["torque_balance"] = {"fem": runs[-1]["torque_balance"],
                             "order_vs_exact": [_order(balance[k], balance[k + 1], levels[k:k + 2])
                                                for k in range(len(runs) - 1)]}
    return out


def _sci(x):
    """A signed difference for the table: 1.2e-13 as $1.2\\times10^{-13}$; None as a dash."""
    if x is None:
        return "---"
    return f"${sci(x, 0, always=True)}$"


def _fixed(x):
    return "---" if x is None else f"{x:.12f}"


def _ord(x):
    return "---" if x is None else f"{x:.1f}"


def table(records, levels, degree):
    """Booktabs table body: one block of rows per stick radius."""
    lines = [
        f"% generated by {SOURCE}",
        r"\setlength{\tabcolsep}{4pt}%",
        r"\begin{tabular}{rlrrrrrr}",
        r"\toprule",
        r"& & \multicolumn{2}{c}{value} & \multicolumn{2}{c}{$-$ Abel--Fredholm} & FEM & \\",
        r"\cmidrule(lr){3-4}\cmidrule(lr){5-6}",
        r"$b/a$ & quantity & FEM & Abel--Fredholm & FEM & direct & est. & order\\",
        r"\midrule",
    ]
    labels = {"torque": "$T^*$", "rigid_rotation": r"$\omega\mu/fp_0$",
              "u_theta": rf"$u_\theta({DISPLACEMENT_POINT[0]:g}, {DISPLACEMENT_POINT[1]:g})$",
              "stress": r"$\sigma_{z\theta}, \sigma_{r\theta}$", "stick_traction": r"stick traction $q$"}
    for k, record in enumerate(records):
        comparison = record["comparison"]
        for j, name in enumerate(("torque", "rigid_rotation", "u_theta", "stress", "stick_traction")):
            c = comparison[name]
            first = f"{record['stick_radius']:.2f}" if j == 0 else ""
            lines.append(f"{first} & {labels[name]} & {_fixed(c.get('fem'))} & {_fixed(c.get('abel_fredholm'))} & "
                         f"{_sci(c['fem_minus_abel_fredholm'])} & {_sci(c.get('direct_minus_abel_fredholm'))} & "
                         f"{_sci(c['estimate'])} & {_ord(c['order_self'])}\\\\")
        balance = comparison["torque_balance"]["fem"]
        lines.append(rf" & torque balance & {_sci(balance)} & & & & & \\")
        if k < len(records) - 1:
            lines.append(r"\addlinespace")
    lines += [r"\bottomrule", r"\end{tabular}",
              f"% P{degree} elements, mesh levels {', '.join(map(str, levels))}; FEM est. = change between the two "
              "finest levels; order from the three finest levels (no reference); stresses: max over "
              f"{len(STRESS_POINTS)} points {STRESS_POINTS} and both components; stick traction: max over the radii "
              f"{TRACTION_FRACTIONS} times b; torque balance: "
              "4 int_0^1 sigma_zt(r, 0) r^2 dr - T* of the FEM traction"]
    return "\n".join(lines) + "\n"


def macros(records, levels, degree):
    """Numbers quoted in the text: accuracies, orders, sizes and timings."""
    def worst(name, key="fem_minus_abel_fredholm"):
        return max(abs(r["comparison"][name][key]) for r in records)

    orders = [r["comparison"][q]["order_self"] for r in records for q in ("torque", "rigid_rotation")]
    orders = [o for o in orders if o is not None]
    values = {
        "fem-degree": degree,
        "fem-levels": ", ".join(map(str, levels)),
        "fem-dofs-max": max(r["levels"][-1]["n_dofs"] for r in records),
        "fem-error-torque": sci(worst("torque"), 0),
        "fem-error-omega": sci(worst("rigid_rotation"), 0),
        "fem-error-displacement": sci(worst("u_theta"), 0),
        "fem-error-stress": sci(worst("stress"), 0),
        "fem-estimate-torque": sci(worst("torque", "estimate"), 0),
        "fem-torque-balance": sci(max(abs(r["comparison"]["torque_balance"]["fem"]) for r in records), 0),
        "fem-order-min": f"{min(orders):.1f}" if orders else "---",
        "fem-order-max": f"{max(orders):.1f}" if orders else "---",
    }
    if all("direct" in r for r in records):
        values["fem-direct-difference-torque"] = sci(worst("torque", "direct_minus_abel_fredholm"), 0)
        values["fem-direct-difference-omega"] = sci(worst("rigid_rotation", "direct_minus_abel_fredholm"), 0)
    for r in records:
        b = f"{r['stick_radius']:g}"
        values[f"fem-torque-b{b}"] = f"{r['comparison']['torque']['fem']:.12f}"
        values[f"fem-omega-b{b}"] = f"{r['comparison']['rigid_rotation']['fem']:.12f}"
    return values


def main(argv=None):
    a = parse_arguments(argv)
    records = [study_radius(b, a.mesh_levels, a.degree, a.truncation, a.direct) for b in a.stick_radii]
    for r in records:
        c = r["comparison"]
        error = {name: c[name]["fem_minus_abel_fredholm"] for name in ("torque", "rigid_rotation", "u_theta", "stress")}
        print(f"b = {r['stick_radius']:g}: FEM - AF: T* {error['torque']:.1e}, omega {error['rigid_rotation']:.1e}, "
              f"u {error['u_theta']:.1e}, stresses {error['stress']:.1e}; estimate T* {c['torque']['estimate']:.1e}; "
              f"order {_ord(c['torque']['order_self'])}; torque balance {c['torque_balance']['fem']:.1e}")
    if a.json:
        write_json(a.json, {"stick_radii": a.stick_radii, "mesh_levels": a.mesh_levels, "degree": a.degree,
                            "truncation": a.truncation, "stress_points": STRESS_POINTS,
                            "displacement_point": DISPLACEMENT_POINT, "traction_fractions": TRACTION_FRACTIONS,
                            "radii": records},
                   method="axisymmetric finite elements (scikit-fem, Lagrange triangles, graded meshes; T* by an "
                          "interaction integral for the square-root term at the stick/slip front) vs the "
                          "Abel-Fredholm method (solve) and the direct collocation method (solve_direct)",
                   resolution=f"P{a.degree}, mesh levels {a.mesh_levels}, truncation L = {a.truncation}",
                   precision="IEEE double", scikit_fem=metadata.version("scikit-fem"))
    if a.tex:
        write_text(a.tex, table(records, a.mesh_levels, a.degree))
    if a.macros:
        write_macros(a.macros, macros(records, a.mesh_levels, a.degree), SOURCE)


if __name__ == "__main__":
    main()
