# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # The torsion test as a friction test: for experimenters
#
# Results read: `data/friction_test_coverage.json`
# (from the build's output folder, `RESULTS_DIR`).
#
# Also read: the lab record committed beside this notebook, data/lab_loop.csv, with its
# generating parameters in data/lab_loop.json.
#
# Two cylinders of radius a pressed end to end by F and twisted by T: slip starts at the rim when
# T reaches f F a / 2 and the cylinders spin at 2 f F a / 3, with a uniform pressure and no
# leading edge.  This notebook goes (1) from a specimen in millimetres, newtons and gigapascals to
# the loop a rig would record, the energy per cycle and the slip regime, and (2) from a measured
# loop back to the friction coefficient f and the shear modulus G with their 95 % intervals.
# Everything is in SI units; the solvers underneath work in the normalised units of
# docs/conventions.md.

# %%
import json
import os
import warnings
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from torsional_contact import Specimen, fit_loop
from torsional_contact.io.lab_files import read_lab_columns

RESULTS = Path(os.environ.get("RESULTS_DIR", "../results"))
truth = json.loads(Path("data/lab_loop.json").read_text())
specimen = Specimen(radius="5 mm", normal_force="1 kN", friction=0.6, shear_modulus="80 GPa",
                    gauge_length="20 mm")
print(f"slip onset {specimen.slip_onset_torque:.3f} N m, gross slip {specimen.gross_slip_torque:.3f} N m")
print(f"p0 = {specimen.pressure / 1e6:.2f} MPa; twist unit f p0 / G = {specimen.rotation_scale:.3g} rad")

# %% [markdown]
# ## 1. From a specimen to its loop
#
# `specimen.solve(torque="1.8 N m")` gives the state in SI units: the stick radius (m), the
# rigid rotation of each cylinder (rad) and the twist between two sections 20 mm apart
# (rad): the elastic shaft, T L / (G J), plus twice the contact's rotation.

# %%
state = specimen.solve(torque="1.8 N m")
print(state.regime, f"stick radius {state.stick_radius * 1e3:.3f} mm")
print(f"twist {state.twist * 1e3:.5f} mrad, of which the contact {2 * state.rigid_rotation * 1e6:.2f} urad;"
      f" shaft alone {1.8 * specimen.shaft_compliance() * 1e3:.5f} mrad")

# %% [markdown]
# A torque cycling between -1.8 and 1.8 N m: the memory rules give the twist at every sample
# and the energy of every closed cycle, in joules.

# %%
phase = np.linspace(0.0, 3.0, 1201)
torque = 1.8 * np.sin(2 * np.pi * phase)
signal = specimen.signal(torque)
values = signal.sample_values()
print("cycles:", [{k: f"{v:.4g}" for k, v in c.items()} for c in signal.cycles()])
print(f"energy per cycle {specimen.energy_per_cycle(1.8) * 1e6:.3f} uJ; total {signal.dissipated_energy * 1e6:.3f} uJ")
fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.2))
a.plot(values["twist"] * 1e3, torque)
a.set_xlabel("twist over 20 mm [mrad]")
a.set_ylabel("torque [N m]")
a.set_title("as the rig sees it: the hysteresis is thin")
a.plot([], [])
b.plot((values["twist"] - specimen.shaft_compliance() * torque) * 1e6, torque)
b.set_xlabel("contact twist 2 omega f p0 / G [urad]")
b.set_title("the contact's share")
plt.tight_layout()
plt.show()

# %% [markdown]
# ## Slip regime and energy per cycle against the torque amplitude and the normal force

# %%
forces = np.linspace(100.0, 3000.0, 59)  # N
amplitudes = np.linspace(0.05, 4.5, 90)  # N m
regime_code = {"stick": 0, "partial-slip": 1, "gross-slip": 2}
regimes = np.zeros((amplitudes.size, forces.size))
energy = np.full((amplitudes.size, forces.size), np.nan)
for j, force in enumerate(forces):
    s = Specimen(radius="5 mm", normal_force=force, friction=0.6, shear_modulus="80 GPa")
    for i, t in enumerate(amplitudes):
        regimes[i, j] = regime_code[s.regime(t)]
        if regimes[i, j] == 1 and s.energy_per_cycle(t) > 0:  # zero right at the slip onset
            energy[i, j] = s.energy_per_cycle(t)
fig, ax = plt.subplots(figsize=(5.5, 3.8))
ax.contourf(forces, amplitudes, regimes, levels=[-0.5, 0.5, 1.5, 2.5], colors=["#d9ecd9", "#fde9c8", "#f6d0d0"])
lines = ax.contour(forces, amplitudes, np.log10(energy), levels=np.arange(-7, -1), colors="0.3", linewidths=0.6)
ax.clabel(lines, fmt=lambda v: f"1e{v:.0f} J", fontsize=7)
ax.set_xlabel("normal force F [N]")
ax.set_ylabel("torque amplitude T_a [N m]")
ax.set_title("stick (green), partial slip (contours: energy per cycle), gross slip (red)", fontsize=8)
plt.show()

# %% [markdown]
# ## 2. From a measured loop to f and G
#
# The lab record: a twist-controlled test into gross slip, 3 cycles from the virgin state,
# exported with units in the header (`time [s],torque [N m],twist [mrad]`).  It was made from
# the exact solution with the parameters below and white noise on both channels
# (`workflow/scripts/make_lab_loop.py`).  The fit needs only the radius and the normal force;
# the noise levels are estimated from the record.

# %%
print({k: truth[k] for k in ("radius", "normal_force", "friction", "shear_modulus", "compliance",
                             "torque_noise", "twist_noise")})
columns = read_lab_columns("data/lab_loop.csv", ["torque", "twist"], ["time"])
with warnings.catch_warnings():
    warnings.simplefilter("error")  # a noise-limited fit would be flagged by a warning: make it an error here
    fit = fit_loop(columns["torque"], columns["twist"], radius="5 mm", normal_force="1 kN")
for name in ("friction", "shear_modulus", "compliance"):
    e = getattr(fit, name)
    print(f"{name:14s} {e.value:.6g} +- {e.stderr:.2g}  95 % [{e.interval[0]:.6g}, {e.interval[1]:.6g}]"
          f"  (true {truth[name]:.6g})")
print(fit.message, f"; correlation(f, G) = {fit.correlation:.2f}; residual rms {fit.residual_rms:.3g} rad")
plt.figure(figsize=(5, 3.5))
plt.plot(columns["twist"] * 1e3, columns["torque"], ".", markersize=2, color="0.6", label="record")
plt.plot(columns["twist"] * 1e3, fit.fitted_torque, "-", label="fit")
plt.xlabel("twist [mrad]")
plt.ylabel("torque [N m]")
plt.legend()
plt.show()

# %% [markdown]
# The same from the command line:
#
# ```bash
# python -m torsional_contact fit --loop notebooks/data/lab_loop.csv --radius "5 mm" --normal-force "1 kN" --json
# ```
#
# ## How far to trust the intervals: the coverage study
#
# The build fits many noisy synthetic records per scenario and counts how often the 95 %
# intervals hold the truth, with the binomial standard error of that rate; per parameter it
# also counts how often the fit gave an interval (a value) or only a bound (what the data do
# say when they cannot pin the parameter down), and the median bias and width of the intervals.
# The residuals are orthogonal distances from the model's curve (errors in both channels), the
# intervals profile-likelihood intervals, the slip test calibrated by Davies' bound.  Gross-slip
# loops and partial-slip loops at realistic noise cover at the nominal rate; in partial slip G
# is mostly only bounded, because the contact's own twist (a few tens of microradians) is not
# much larger than the twist noise.  A loop that never slips gives no friction value, only a
# bound, and slip is detected in a loop in stick at most at the test's level (5 %).

# %%
coverage = json.loads((RESULTS / "data" / "friction_test_coverage.json").read_text())
print(f"{'scenario':20s} {'max T*':>7s} {'slip':>5s}   " + "   ".join(
    f"{p + ': int/bound cov':>20s}" for p in ("f", "G", "C")))
for r in coverage["scenarios"]:
    cells = []
    for k in ("friction", "shear_modulus", "compliance"):
        e = r[k]
        cov = "--" if e["coverage"] is None else f"{100 * e['coverage']:.0f}+-{100 * e['coverage_stderr']:.0f}"
        cells.append(f"{100 * e['interval']:5.0f}/{100 * e['bound']:3.0f} {cov:>8s}")
    print(f"{r['name']:20s} {r['max_torque_ratio']:7.3f} {100 * r['slip_detected']:5.0f}   " + "   ".join(cells))

# %% [markdown]
# ## Conclusion
#
# A specimen in physical units gives the loop, the energy per cycle and the slip regime
# directly; a measured torque-twist loop gives f (to a fraction of a percent from a gross-slip
# plateau) and G (to several percent) with intervals that hold the truth at their nominal rate;
# where the twist noise hides the contact's own twist the fit reports bounds instead of values
# and says so.
