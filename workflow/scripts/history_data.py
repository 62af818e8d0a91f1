"""Torque histories in data: Fig. 5 (relaxation after loading to 1.23), hysteresis loops,
dissipation per cycle against the torque range, and the torsional compliance.

Units: T* = 2T/(f F a); traction in f p0; omega in f p0 / mu; energy per cycle in
(f p0)^2 a^3 / mu.  All numbers come from ``torsional_contact.history`` (memory rules);
the direct incremental solve and the energy balance are checked in tests/test_history.py.
"""

import argparse
import time
import warnings

import numpy as np

from torsional_contact import ResolutionWarning
from torsional_contact import histories as H
from torsional_contact.provenance import write_json, write_macros


def fig5(t_max, stages, n_terms):
    data = H.relaxation_profiles(t_max, tuple(stages), np.linspace(0, 1, 201), n_terms=n_terms)
    residual = data["residual_traction"]
    peak = int(np.argmax(residual))
    return {
        "t_max": data["t_max"],
        "loading_stick_radius": data["loading_stick_radius"],
        "stages": data["torque"].tolist(),
        "regime": data["regime"],
        "radii": data["radii"].tolist(),
        "traction": data["traction"].tolist(),
        "residual_traction": residual.tolist(),
        "residual_peak": {"value": float(residual[peak]), "radius": float(data["radii"][peak])},
        "residual_at_edge": float(residual[-1]),
        "reverse_slip_onset": data["reverse_slip_onset"],
        "min_traction_at_onset": data["min_traction_at_onset"],
    }


def loops(pairs, n_terms, n_points):
    out = []
    for t_min, t_max in pairs:
        loop = H.hysteresis_loop(t_min, t_max, n_points=n_points, n_terms=n_terms)
        out.append(
            {
                "t_min": t_min,
                "t_max": t_max,
                "torque": loop.torque.tolist(),
                "rigid_rotation": loop.rigid_rotation.tolist(),
                "loop_work": H.loop_work(loop.torque, loop.rigid_rotation),
                "frictional_work": H.frictional_work(loop.states),
                "closed_form": H.dissipation_per_cycle(t_max - t_min, n_terms=n_terms),
            }
        )
    return out


def dissipation_law(n_terms):
    eps = np.geomspace(0.01, 0.15, 12)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)  # smallest eps below the resolved annulus: kept, flagged
        w = np.array([H.dissipation_per_cycle(2 * (1 + e), n_terms=n_terms) for e in eps])
    fit = slice(2, 8)
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
    }


def compliance(n_terms):
    torques = np.linspace(1.02, 1.32, 16)
    states = [H.history([t], n_terms=n_terms)[-1] for t in torques]
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
    p.add_argument("--n-terms", type=int, default=145)
    p.add_argument("--fit-n-terms", type=int, default=400, help="N for the threshold fit (narrow annuli)")
    p.add_argument("--n-points", type=int, default=40, help="states per slipping stretch of a loop")
    p.add_argument("--t-max", type=float, required=True, help="Fig. 5: T* of the first loading")
    p.add_argument("--stages", type=float, nargs="+", required=True, help="Fig. 5: T* of the relaxation stages")
    p.add_argument("--loops", type=float, nargs="+", required=True, help="loops: T*_min T*_max pairs")
    p.add_argument("--json", required=True)
    p.add_argument("--macros", help="LaTeX macros of the quoted numbers")
    a = p.parse_args()
    start = time.perf_counter()
    payload = {
        "fig5": fig5(a.t_max, a.stages, a.n_terms),
        "loops": loops(list(zip(a.loops[::2], a.loops[1::2], strict=True)), a.n_terms, a.n_points),
        "dissipation_law": dissipation_law(a.fit_n_terms),
        "compliance": compliance(a.n_terms),
        "units": {
            "torque": "T* = 2T/(f F a)",
            "traction": "f p0",
            "rigid_rotation": "f p0 / mu",
            "energy": "(f p0)^2 a^3 / mu",
        },
    }
    write_json(a.json, payload, n_terms=a.n_terms)
    print(f"history data in {time.perf_counter() - start:.1f} s")
    if a.macros:
        f5, law = payload["fig5"], payload["dissipation_law"]
        loop_err = max(abs(lp["loop_work"] - lp["closed_form"]) / lp["closed_form"]
                       for lp in payload["loops"] if lp["closed_form"] > 0)  # range < 2: no dissipation
        write_macros(a.macros, {
            "hist-tmax": f"{f5['t_max']:g}",
            "hist-b-at-tmax": f"{f5['loading_stick_radius']:.3f}",
            "hist-residual-peak": f"{f5['residual_peak']['value']:.3f}",
            "hist-residual-peak-r": f"{f5['residual_peak']['radius']:.2f}",
            "hist-residual-edge": f"{f5['residual_at_edge']:.3f}",
            "hist-reverse-onset": f"{f5['reverse_slip_onset']:.2f}",
            "hist-fit-exponent": f"{law['fitted_exponent']:.2f}",
            "hist-fit-prefactor": f"{law['fitted_prefactor']:.1f}",
            "hist-predicted-prefactor": f"{law['predicted_prefactor']:.1f}",
            "hist-loop-energy-agreement": f"{loop_err:.0e}",
            "hist-n-terms": a.n_terms,
        }, "workflow/scripts/history_data.py")


if __name__ == "__main__":
    main()
