"""Torque histories in data: Fig. 5 (relaxation after loading to 1.23), hysteresis loops,
dissipation per cycle against the torque range, and the torsional compliance.

Units: T* = 2T/(f F a); traction in f p0; omega in f p0 / mu; energy per cycle in
(f p0)^2 a^3 / mu.  All numbers come from ``torsional_contact.histories`` (memory rules) with
``--method`` (default: the converged Abel-Fredholm method); Fig. 5 also carries the paper's
setting (complete weak form at ``--n-terms``, labelled as such).  The direct incremental
solve and the energy routes are checked in tests/test_history*.py and tests/test_curves.py.
"""

import argparse
import time
import warnings

import numpy as np

from torsional_contact import ResolutionWarning
from torsional_contact import histories as H
from torsional_contact.backends import METHODS
from torsional_contact.provenance import write_json, write_macros
from torsional_contact.typeset import sci


def fig5(t_max, stages, method, n_terms):
    data = H.relaxation_profiles(t_max, tuple(stages), np.linspace(0, 1, 201), method=method, n_terms=n_terms)
    residual = data["residual_traction"]
    peak = int(np.argmax(residual))
    b_max = data["loading_stick_radius"]
    # Unloading to 0 after t_max < 2 is elastic (no reverse slip): the residual traction is the
    # loading traction minus the bilateral t_max r.  The loading traction rises to the friction
    # limit 1 at r = b_max with infinite slope from the stick side and equals 1 beyond, so the
    # residual 1 - t_max r on the annulus falls from its peak 1 - t_max b_max, reached at r = b_max.
    exact_peak = {"value": 1.0 - data["t_max"] * b_max, "radius": b_max} if data["t_max"] < 2.0 else None
    return {
        "t_max": data["t_max"],
        "loading_stick_radius": data["loading_stick_radius"],
        "stages": data["torque"].tolist(),
        "regime": data["regime"],
        "radii": data["radii"].tolist(),
        "traction": data["traction"].tolist(),
        "residual_traction": residual.tolist(),
        "residual_peak": {"value": float(residual[peak]), "radius": float(data["radii"][peak])},
        "residual_peak_exact": exact_peak,
        "residual_at_edge": float(residual[-1]),
        "reverse_slip_onset": data["reverse_slip_onset"],
        "min_traction_at_onset": data["min_traction_at_onset"],
        "reverse_stick_radius": H.history([t_max, -1.0], method=method, n_terms=n_terms)[-1].stick_radius,
        "method": method,
        "n_terms": n_terms,
    }


def loops(pairs, method, n_terms, n_points):
    out = []
    for t_min, t_max in pairs:
        loop = H.hysteresis_loop(t_min, t_max, n_points=n_points, method=method, n_terms=n_terms)
        closed = H.dissipation_per_cycle(t_max - t_min, method=method, n_terms=n_terms)
        record = {
            "t_min": t_min,
            "t_max": t_max,
            "torque": loop.torque.tolist(),
            "rigid_rotation": loop.rigid_rotation.tolist(),
            "loop_work": H.loop_work(loop.torque, loop.rigid_rotation),  # trapezoidal area of the plotted samples
            "energy_increase": loop.states[-1].dissipated_energy - loop.states[0].dissipated_energy,
            "closed_form": closed,
        }
        if not METHODS[method].truncated:  # the two exact routes: friction over the slip annulus, pi x loop area
            record["frictional_work"] = closed
            record["loop_area_work"] = H.dissipation_from_loop_area(t_max - t_min)
        else:  # the series' discrete energy identity on the sampled states
            record["frictional_work"] = H.frictional_work(loop.states)
            record["loop_area_work"] = record["loop_work"]
        out.append(record)
    return out


def dissipation_law(method, n_terms):
    eps = np.geomspace(1e-3, 0.15, 12)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)  # weak forms: narrow annuli kept, flagged
        w = np.array([H.dissipation_per_cycle(2 * (1 + e), method=method, n_terms=n_terms) for e in eps])
    fit = slice(0, 6)
    exponent, log_c = np.polyfit(np.log(eps[fit]), np.log(w[fit]), 1)
    return {
        "eps": eps.tolist(),
        "torque_range": (2 * (1 + eps)).tolist(),
        "dissipation": w.tolist(),
        "asymptote": H.threshold_asymptotics(eps)["dissipation"].tolist(),
        "fit_range": [float(eps[fit][0]), float(eps[fit][-1])],
        "fitted_exponent": float(exponent),
        "fitted_prefactor": float(np.exp(log_c)),
        "predicted_exponent": 3,
        "predicted_prefactor": float(np.pi**4 / 3),
        "ratio_at_smallest": float(w[0] / H.threshold_asymptotics(eps[0])["dissipation"]),
        # W / ((pi^4/3) eps^3) over the grid: where the threshold law holds
        "ratio_to_law": (w / H.threshold_asymptotics(eps)["dissipation"]).tolist(),
    }


def law_ratios(law):
    """Macros: W / ((pi^4/3) eps^3) at the grid point nearest eps = 0.01, at the largest eps, and the largest eps
    at which the ratio is within 5 % of 1 (the threshold law's range of validity)."""
    eps, ratio = np.asarray(law["eps"]), np.asarray(law["ratio_to_law"])
    near = int(np.argmin(np.abs(np.log(eps / 0.01))))
    within = eps[np.abs(ratio - 1.0) <= 0.05]
    return {
        "hist-law-eps-small": f"{eps[near]:.3f}",
        "hist-law-ratio-small": f"{ratio[near]:.4f}",
        "hist-law-eps-large": f"{eps[-1]:.2f}",
        "hist-law-ratio-large": f"{ratio[-1]:.3f}",
        "hist-law-eps-five-percent": f"{within.max():.3f}" if within.size else "--",
    }


def compliance(method, n_terms):
    torques = np.linspace(1.02, 1.32, 16)
    states = [H.history([t], method=method, n_terms=n_terms)[-1] for t in torques]
    return {
        "torque": torques.tolist(),
        "stick_radius": [s.stick_radius for s in states],
        "rigid_rotation": [s.rigid_rotation for s in states],
        "d_omega_d_torque": [H.tangent_compliance(s) for s in states],
        "asymptote": H.threshold_asymptotics(torques - 1)["compliance"].tolist(),
        "note": "extra compliance d phi/dT = 4/(pi mu a^3) d omega/dT*: an added shaft length 2 a d omega/dT*",
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--method", required=True, help="method of the monotonic solutions (fast: converged)")
    p.add_argument("--n-terms", type=int, default=145, help="N of the weak form (Fig. 5 companion; --method)")
    p.add_argument("--fit-n-terms", type=int, default=400, help="N for the threshold fit with a weak-form --method")
    p.add_argument("--n-points", type=int, default=40, help="states per slipping stretch of a loop")
    p.add_argument("--t-max", type=float, required=True, help="Fig. 5: T* of the first loading")
    p.add_argument("--stages", type=float, nargs="+", required=True, help="Fig. 5: T* of the relaxation stages")
    p.add_argument("--loops", type=float, nargs="+", required=True, help="loops: T*_min T*_max pairs")
    p.add_argument("--json", required=True)
    p.add_argument("--macros", help="LaTeX macros of the quoted numbers")
    a = p.parse_args()
    start = time.perf_counter()
    fast = not METHODS[a.method].truncated  # interface values exact: no n_terms
    n_terms = None if fast else a.n_terms
    payload = {
        "fig5": fig5(a.t_max, a.stages, a.method, n_terms),
        "fig5_weak": fig5(a.t_max, a.stages, "complete", a.n_terms),
        "loops": loops(list(zip(a.loops[::2], a.loops[1::2], strict=True)), a.method, n_terms, a.n_points),
        "dissipation_law": dissipation_law(a.method, None if fast else a.fit_n_terms),
        "compliance": compliance(a.method, n_terms),
        "units": {
            "torque": "T* = 2T/(f F a)",
            "traction": "f p0",
            "rigid_rotation": "f p0 / mu",
            "energy": "(f p0)^2 a^3 / mu",
        },
    }
    write_json(a.json, payload, method=a.method, n_terms=n_terms, weak_form_n_terms=a.n_terms)
    print(f"history data in {time.perf_counter() - start:.1f} s")
    if a.macros:
        f5, weak, law = payload["fig5"], payload["fig5_weak"], payload["dissipation_law"]
        dissipating = [lp for lp in payload["loops"] if lp["closed_form"] > 0]  # range < 2: no dissipation
        loop_err = max(abs(lp["loop_area_work"] - lp["frictional_work"]) / lp["frictional_work"] for lp in dissipating)
        energy_err = max(abs(lp["energy_increase"] - lp["closed_form"]) / lp["closed_form"] for lp in dissipating)
        write_macros(a.macros, {
            "hist-tmax": f"{f5['t_max']:g}",
            "hist-b-at-tmax": f"{f5['loading_stick_radius']:.5f}",
            "hist-b-reverse": f"{f5['reverse_stick_radius']:.5f}",
            "hist-b-at-tmax-n145": f"{weak['loading_stick_radius']:.5f}",
            "hist-b-reverse-n145": f"{weak['reverse_stick_radius']:.5f}",
            # the exact peak 1 - T*_max b_max at r = b_max (the sampled maximum only approaches it)
            "hist-residual-peak": f"{(f5['residual_peak_exact'] or f5['residual_peak'])['value']:.4f}",
            "hist-residual-peak-r": f"{(f5['residual_peak_exact'] or f5['residual_peak'])['radius']:.5f}",
            "hist-residual-peak-sampled": f"{f5['residual_peak']['value']:.4f}",
            "hist-residual-edge": f"{f5['residual_at_edge']:.3f}",
            "hist-reverse-onset": f"{f5['reverse_slip_onset']:.2f}",
            "hist-fit-exponent": f"{law['fitted_exponent']:.3f}",
            "hist-fit-prefactor": f"{law['fitted_prefactor']:.1f}",
            "hist-predicted-prefactor": f"{law['predicted_prefactor']:.1f}",
            "hist-fit-eps-min": sci(law["fit_range"][0], 1),
            "hist-fit-eps-max": sci(law["fit_range"][1], 1),
            # the validity of W ~ (pi^4/3) eps^3: its ratio to W at about 0.01 and at the largest eps
            **law_ratios(law),
            "hist-loop-energy-agreement": sci(max(loop_err, 1e-16), 0),
            "hist-cycle-energy-agreement": sci(max(energy_err, 1e-16), 0),
            "hist-method": "Abel--Fredholm" if fast else f"{a.method} weak form",
            "hist-n-terms": a.n_terms,
        }, "workflow/scripts/history_data.py")


if __name__ == "__main__":
    main()
