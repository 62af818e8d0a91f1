"""Write the synthetic "lab" record of notebooks/data/lab_loop.csv (run by hand; the file is committed).

A twist-controlled torsion test of two steel cylinders, generated from the exact solution
(``torsional_contact.fitting.synthetic``) with white measurement noise, written the way a rig's
software would export it: a header with units, the time, the torque in N m and the twist in
mrad.  The generating parameters are written into the file's comment lines and into
notebooks/data/lab_loop.json, so that the notebook can show how far the fit lands from them.

    python workflow/scripts/make_lab_loop.py --csv notebooks/data/lab_loop.csv --json notebooks/data/lab_loop.json
"""

import argparse
import json
import math

import numpy as np

from torsional_contact.fitting.synthetic import Rig, noisy, twist_controlled
from torsional_contact.provenance import write_text

#: The specimen and rig (SI): 10 mm diameter steel cylinders under 1 kN, twist measured over 20 mm.
SPECIMEN = {"radius": 0.005, "normal_force": 1000.0, "friction": 0.6, "shear_modulus": 80e9}
GAUGE_LENGTH = 0.02
RIG_COMPLIANCE = 1.5e-4  # rad / (N m): grips, load cell and shafts outside the gauge length
OFFSET = 3.2e-4  # rad: the encoder's zero is not the virgin state
AMPLITUDE = 2.2e-3  # rad: twist amplitude (gross slip: the plateaus of a fretting test)
FREQUENCY = 0.5  # Hz
CYCLES, SAMPLES_PER_CYCLE = 3, 240
TORQUE_NOISE = 0.01  # N m: 0.25 % of the torque range
TWIST_NOISE = 1e-5  # rad
SEED = 20240601


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--csv", required=True)
    parser.add_argument("--json", required=True)
    args = parser.parse_args()
    shaft = GAUGE_LENGTH / (SPECIMEN["shear_modulus"] * math.pi * SPECIMEN["radius"] ** 4 / 2)
    rig = Rig(**SPECIMEN, compliance=shaft + RIG_COMPLIANCE, offset=OFFSET)
    torque, twist = twist_controlled(rig, AMPLITUDE, CYCLES, SAMPLES_PER_CYCLE)
    torque, twist = noisy(torque, twist, TORQUE_NOISE, TWIST_NOISE, np.random.default_rng(SEED))
    time = np.arange(torque.size) / (SAMPLES_PER_CYCLE * FREQUENCY)
    truth = {**SPECIMEN, "gauge_length": GAUGE_LENGTH, "compliance": rig.compliance, "shaft_compliance": shaft,
             "rig_compliance": RIG_COMPLIANCE, "twist_offset": OFFSET, "twist_amplitude": AMPLITUDE,
             "torque_noise": TORQUE_NOISE, "twist_noise": TWIST_NOISE, "seed": SEED, "cycles": CYCLES,
             "samples_per_cycle": SAMPLES_PER_CYCLE, "frequency": FREQUENCY,
             "generator": "torsional_contact.fitting.synthetic.twist_controlled + noisy",
             "units": {"radius": "m", "normal_force": "N", "shear_modulus": "Pa", "gauge_length": "m",
                       "compliance": "rad/(N m)", "twist_offset": "rad", "twist_amplitude": "rad",
                       "torque_noise": "N m", "twist_noise": "rad", "frequency": "Hz"}}
    comments = [
        "# Synthetic torsion test (twist-controlled, from the exact solution), workflow/scripts/make_lab_loop.py",
        f"# specimen: radius 5 mm, normal force 1 kN, friction {SPECIMEN['friction']}, shear modulus 80 GPa,"
        f" gauge length 20 mm",
        f"# rig: compliance {rig.compliance:.6g} rad/(N m) (shaft {shaft:.6g} + rig {RIG_COMPLIANCE:g}),"
        f" twist offset {OFFSET:g} rad",
        f"# test: twist amplitude {AMPLITUDE * 1e3:g} mrad, {FREQUENCY:g} Hz, {CYCLES} cycles from the virgin state",
        f"# noise: torque {TORQUE_NOISE:g} N m, twist {TWIST_NOISE:g} rad (white, Gaussian, seed {SEED})",
    ]
    rows = "".join(f"{t:.4f},{m:.5f},{w * 1e3:.5f}\n" for t, m, w in zip(time, torque, twist, strict=True))
    write_text(args.csv, "\n".join(comments) + "\ntime [s],torque [N m],twist [mrad]\n" + rows)
    write_text(args.json, json.dumps(truth, indent=1) + "\n")


if __name__ == "__main__":
    main()
