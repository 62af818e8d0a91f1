r"""Build the table of the monotonic curves (build time only: never imported by the run-time package).

Piecewise Chebyshev coefficients from the Abel-Fredholm solver, written to ``curves.table.TABLE_PATH``
and read at run time by ``curves.table.read_table``; the by-torque panels (``add_by_torque``) are
interpolated from the radius panels without further solves (``curves.interpolant`` describes them).

Units: b in a; T* = 2T/(f F a); omega in f p0 / mu; W_mono in (f p0)^2 a^3 / mu.

Layout
------
The curves T*(b), omega(b) and W_mono(b) (``curves.work``) are analytic on 0 < b < 1 but
not at the ends: near b = 1 the slip annulus delta = 1 - b is an edge crack and the
expansions carry delta^k ln(delta) terms (T* - 1 ~ (2/pi) delta, omega and W_mono ~ delta^3);
near b = 0 omega ~ (1/2) ln(1/b) and 4/3 - T* ~ (16/(9 pi)) b^3 with b^2 ln b corrections.
A polynomial in b converges only algebraically across such points, so the range
[B_LOW, b_max] is cut into panels that are geometric toward both ends (ratio 4: each
panel [x, 4x] in b or delta sees its end singularity at 5/3 half-widths from its centre,
Bernstein parameter 3, ~33 points for 1e-16) and a few in the middle.  b_max = 1 - 1.6e-6
is the largest stick radius the Abel-Fredholm method resolves (``MAX_NODES``); B_LOW = 1e-6
has T*(B_LOW) = 4/3 in double precision, so every torque below 4/3 is covered.

On every panel each curve is sampled at Chebyshev-Lobatto points, 9, 17, 33 or 65 of them
(nested: doubling reuses the solves), until the last three Chebyshev coefficients fall
below the tolerance (absolute 1e-15 for T* and omega, relative 1e-14 for W_mono); trailing
coefficients below it are then dropped.  Building takes a few minutes (solves near b = 1
take up to a second each), so the table is shipped with the package
(``monotonic_curves.json``) and rebuilt by ``python -m torsional_contact.curves``; its
accuracy at points that are not nodes is measured by tests/test_curves.py and by
workflow/scripts/curve_accuracy.py.
"""

from __future__ import annotations

import json
import time
import warnings

import numpy as np

from ...diagnostics import ResolutionWarning
from ...provenance import atomic_path, provenance
from ...solvers.abel_fredholm import MAX_NODES, default_nodes, solve_abel_fredholm
from ..interpolant import CURVES_BY_TORQUE, U_SPLIT_RADIUS, MonotonicCurves
from ..table import FORMAT, TABLE_PATH
from ..work import abel_fredholm_loading_work

__all__ = ["B_LOW", "CURVES", "panel_edges", "largest_resolved_radius", "lobatto_coefficients", "build_table",
           "add_by_torque", "write_table", "main"]

#: Smallest stick radius of the table (T*(B_LOW) rounds to 4/3).
B_LOW = 1e-6
#: Panel ratio of the geometric gradings toward b = 0 and b = 1.
GRADING = 4.0
#: Inner edges of the middle panels.
MIDDLE = (0.45, 0.65)
#: Tabulated curves: name -> (absolute tolerance, relative tolerance) of the Chebyshev tail.
CURVES = {
    "torque": (5e-15, 0.0),
    "torque_gap": (0.0, 5e-15),
    "rigid_rotation": (5e-15, 2e-15),
    "loading_work": (0.0, 5e-14),
}
_POINTS = (9, 17, 33, 65)
#: Points per by-torque panel.
_BY_TORQUE_POINTS = 65


def largest_resolved_radius() -> float:
    """Largest b whose default Nystrom resolution fits in MAX_NODES (about 1 - 1.6e-6)."""
    lo, hi = 0.99, 1.0 - 1e-12
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if default_nodes(mid) <= MAX_NODES else (lo, mid)
    return lo


def panel_edges(b_max: float) -> np.ndarray:
    """Increasing panel edges from B_LOW to b_max (see the module docstring)."""
    low = [B_LOW]
    while low[-1] * GRADING < 0.3:
        low.append(low[-1] * GRADING)
    slip = [1.0 - b_max]
    while slip[-1] * GRADING < 0.15:
        slip.append(slip[-1] * GRADING)
    high = sorted(1.0 - d for d in slip)
    return np.array([*low, *MIDDLE, *high])


def lobatto_coefficients(values: np.ndarray) -> np.ndarray:
    """Chebyshev coefficients of the interpolant through values at x_j = cos(pi j / (n - 1)), j = 0..n-1."""
    values = np.asarray(values, dtype=float)
    n = values.size - 1
    j = np.arange(n + 1)
    weights = np.ones(n + 1)
    weights[[0, n]] = 0.5
    coefficients = (2.0 / n) * (np.cos(np.pi * np.outer(j, j) / n) @ (weights * values))
    coefficients[[0, n]] *= 0.5
    return coefficients


def _sample(b: float) -> tuple[float, float, float, float]:
    with warnings.catch_warnings():  # the tail check near b_max; accuracy is measured against the table
        warnings.simplefilter("ignore", ResolutionWarning)
        solution = solve_abel_fredholm(b)
    return solution.torque, solution.torque_deficit, solution.rigid_rotation, abel_fredholm_loading_work(solution)


def _converged(coefficients: np.ndarray, values: np.ndarray, tolerance: tuple[float, float]) -> bool:
    bound = tolerance[0] + tolerance[1] * float(np.max(np.abs(values)))
    return float(np.max(np.abs(coefficients[-3:]))) <= bound


def _chop(coefficients: np.ndarray, values: np.ndarray, tolerance: tuple[float, float]) -> list[float]:
    bound = tolerance[0] + tolerance[1] * float(np.max(np.abs(values)))
    keep = np.nonzero(np.abs(coefficients) > bound)[0]
    end = int(keep[-1]) + 1 if keep.size else 1
    return [float(c) for c in coefficients[:end]]


def _panel(lo: float, hi: float, cache: dict) -> dict:
    """Coefficients of every curve on [lo, hi] (affine variable x in [-1, 1])."""
    for n in _POINTS:
        x = np.cos(np.pi * np.arange(n) / (n - 1))
        radii = 0.5 * (hi - lo) * x + 0.5 * (hi + lo)
        radii[0], radii[-1] = hi, lo
        rows = np.array([cache.setdefault(float(b), _sample(float(b))) for b in radii])
        fits = {name: lobatto_coefficients(rows[:, k]) for k, name in enumerate(CURVES)}
        done = all(_converged(fits[name], rows[:, k], CURVES[name]) for k, name in enumerate(CURVES))
        if done:
            break
    tails = {name: float(np.max(np.abs(fits[name][-3:]))) for name in CURVES}
    panel = {"lo": lo, "hi": hi, "points": int(n), "tails": tails}
    for k, name in enumerate(CURVES):
        panel[name] = _chop(fits[name], rows[:, k], CURVES[name])
    return panel


def build_table(progress=None, cache: dict | None = None) -> dict:
    """Solve on every panel and return the table (a JSON-ready dict); ``cache`` maps b to samples."""
    start = time.perf_counter()
    b_max = largest_resolved_radius()
    edges = panel_edges(b_max)
    cache = {} if cache is None else cache
    panels = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        panels.append(_panel(float(lo), float(hi), cache))
        if progress is not None:
            progress(panels[-1])
    return {
        "format": FORMAT,
        "method": "fast (Abel-Fredholm, default nodes), W_mono by (W2)",
        "domain": [B_LOW, b_max],
        "solves": len(cache),
        "seconds": round(time.perf_counter() - start, 1),
        "panels": panels,
    }


def _fit(values: np.ndarray, tolerance: float) -> list[float]:
    coefficients = lobatto_coefficients(values)
    bound = tolerance * max(1e-300, float(np.max(np.abs(values))))
    keep = np.nonzero(np.abs(coefficients) > bound)[0]
    return coefficients[: int(keep[-1]) + 1 if keep.size else 1].tolist()


def _by_torque(curves: MonotonicCurves) -> dict:
    """Panels by torque (module docstring): images of the radius panels, values through b(tau)."""
    radius_edges = curves.by_radius["torque"].edges
    split = int(np.argmin(np.abs(radius_edges - U_SPLIT_RADIUS)))
    u_edges = np.cbrt(curves.torque_gap(radius_edges[: split + 1]))
    t_edges = np.sort(curves.by_radius["torque"](radius_edges[split:]))  # the table's own T*(b) at its edges
    x = np.cos(np.pi * np.arange(_BY_TORQUE_POINTS) / (_BY_TORQUE_POINTS - 1))
    out = {"u_edges": u_edges.tolist(), "t_edges": t_edges.tolist(), "u_panels": {}, "t_panels": {}}
    for key, edges, curve, target in (
        ("u_panels", u_edges, curves.by_radius["torque_gap"], lambda v: v**3),
        ("t_panels", t_edges, curves.by_radius["torque"], lambda v: v),
    ):
        lists = {name: [] for name in CURVES_BY_TORQUE}
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            v = 0.5 * (hi - lo) * x + 0.5 * (hi + lo)
            v[0], v[-1] = hi, lo
            b = curve.solve(target(v))
            lists["stick_radius"].append(_fit(b, 1e-16))
            lists["rigid_rotation"].append(_fit(curves.rotation_at_radius(b), 1e-16))
            lists["loading_work"].append(_fit(curves.work_at_radius(b), 1e-15))
        out[key] = lists
    return out


def add_by_torque(table: dict) -> dict:
    """The table with its by-torque panels (computed from the radius panels, no solves)."""
    table = {k: v for k, v in table.items() if k != "by_torque"}
    table["by_torque"] = _by_torque(MonotonicCurves({**table, "by_torque": {
        "u_edges": [0.0, 1.0], "t_edges": [0.0, 1.0],
        "u_panels": {n: [[0.0]] for n in CURVES_BY_TORQUE}, "t_panels": {n: [[0.0]] for n in CURVES_BY_TORQUE}}}))
    return table


def write_table(table: dict, path: str = TABLE_PATH) -> None:
    """Write ``table`` with provenance metadata (atomic)."""
    record = {**table, "metadata": provenance(purpose="monotonic curves of the Abel-Fredholm method")}
    with atomic_path(path) as tmp, open(tmp, "w", encoding="utf-8") as handle:
        json.dump(record, handle, allow_nan=False, separators=(",", ":"))  # compact: loaded on first use
        handle.write("\n")


def main() -> None:  # pragma: no cover - exercised by ``python -m torsional_contact.curves``
    def report(panel):
        print(f"[{panel['lo']:.6g}, {panel['hi']:.6g}] {panel['points']} points, tails "
              + ", ".join(f"{k} {v:.1e}" for k, v in panel["tails"].items()), flush=True)

    table = add_by_torque(build_table(report))
    write_table(table)
    print(f"{TABLE_PATH}: {table['solves']} solves, {table['seconds']} s; max tail "
          f"{max(max(p['tails'].values()) for p in table['panels']):.1e}", flush=True)
