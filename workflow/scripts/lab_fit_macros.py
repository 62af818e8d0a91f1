"""The lab record's fit as numbers for the manuscript: f, G, C with their 95 % intervals, and the truth.

Units: G in GPa, C in mrad / (N m) as printed.  Reads notebooks/data/lab_loop.csv and its generating
parameters (lab_loop.json); writes the fit as a JSON data file with provenance and LaTeX macros.
"""

import argparse
import json

import numpy as np

from torsional_contact import fit_loop
from torsional_contact.io.fit_report import residual_columns
from torsional_contact.io.lab_files import read_lab_columns
from torsional_contact.provenance import write_json, write_macros


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--loop", required=True)
    p.add_argument("--truth", required=True)
    p.add_argument("--json", required=True)
    p.add_argument("--macros", required=True)
    a = p.parse_args()
    truth = json.loads(open(a.truth, encoding="utf-8").read())
    columns = read_lab_columns(a.loop, ["torque", "twist"], ["time"])
    fit = fit_loop(columns["torque"], columns["twist"], radius=truth["radius"], normal_force=truth["normal_force"])
    record = fit.as_dict()
    write_json(a.json, {"fit": record, "truth": truth}, method="fit_loop", source=a.loop)
    f, g, c = fit.friction, fit.shear_modulus, fit.compliance
    macros = {
        "lab-f": f"{f.value:.4f}", "lab-f-lo": f"{f.interval[0]:.4f}", "lab-f-hi": f"{f.interval[1]:.4f}",
        "lab-g": f"{g.value / 1e9:.1f}", "lab-g-lo": f"{g.interval[0] / 1e9:.1f}",
        "lab-g-hi": f"{g.interval[1] / 1e9:.1f}",
        "lab-c": f"{c.value * 1e3:.4f}", "lab-c-lo": f"{c.interval[0] * 1e3:.4f}",
        "lab-c-hi": f"{c.interval[1] * 1e3:.4f}",
        "lab-true-f": f"{truth['friction']:g}", "lab-true-g": f"{truth['shear_modulus'] / 1e9:g}",
        "lab-true-c": f"{truth['compliance'] * 1e3:.4f}", "lab-samples": str(fit.samples),
        "lab-cycles": str(truth["cycles"]), "lab-amplitude-mrad": f"{truth['twist_amplitude'] * 1e3:g}",
        "lab-torque-noise": f"{truth['torque_noise']:g}", "lab-twist-noise-urad": f"{truth['twist_noise'] * 1e6:g}",
        "lab-correlation": f"{fit.correlation:.2f}",
    }
    # the residuals of Fig. lab_fit: distances from the fitted curve in noise units (the --residuals columns)
    distance = residual_columns(fit, columns)["normalized_residual"]
    distance = distance[np.isfinite(distance)]
    macros["lab-distance-rms"] = f"{np.sqrt(np.mean(distance**2)):.2f}"
    macros["lab-distance-beyond-two-pct"] = f"{100 * np.mean(np.abs(distance) > 2):.1f}"
    write_macros(a.macros, macros, "workflow/scripts/lab_fit_macros.py")


if __name__ == "__main__":
    main()
