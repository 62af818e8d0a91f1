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
# # Exploring T*(b), the interface fields and the unloading experiment
#
# Results read: `data/torque_curve.csv`, `data/torque_table.csv`, `data/history.json`
# (from the build's output folder, `RESULTS_DIR`).
#
# This notebook reads the workflow's results (it recomputes nothing heavy). Build them with
# `bash workflow/main.sh` (default configuration, `results/`) or set `RESULTS_DIR` to another
# output folder, e.g. `results/ci` from the test configuration. Units: T* = 2T/(f F a),
# traction in f p0, slip in f p0 a / mu, omega in f p0 / mu.

# %%
import io
import json
import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

RESULTS = Path(os.environ.get("RESULTS_DIR", "../results"))
if not RESULTS.is_absolute() and not RESULTS.exists():
    RESULTS = Path.cwd().parent / RESULTS
assert (RESULTS / "data").is_dir(), f"no build found in {RESULTS}: run bash workflow/main.sh first"


def read_csv(path):
    """A CSV of the workflow: '#' metadata lines, then a header and rows."""
    lines = Path(path).read_text().splitlines()
    meta = [line for line in lines if line.startswith("#")]
    data = [line for line in lines if not line.startswith("#")]
    return np.genfromtxt(io.StringIO("\n".join(data)), delimiter=",", names=True), meta

# %% [markdown]
# ## T*(b): converged, complete weak form and the reconstructed printed scheme
# The CSV carries its metadata as comment lines. Its rows are the union of two b-grids (the
# converged curve on [0, 1], the weak forms on their resolved range); each weak-form column is
# nan on the rows of the other grid, so every curve is drawn through its own finite rows.

# %%
path = RESULTS / "data" / "torque_curve.csv"
curve, meta = read_csv(path)
print("\n".join(meta))


def finite(column):
    """(T*, b/a) of the rows where ``column`` is defined."""
    keep = np.isfinite(curve[column])
    return curve[column][keep], curve["stick_radius"][keep]


fig, ax = plt.subplots()
ax.plot(*finite("torque_fast"), "k", lw=2.2, label="converged (Abel-Fredholm)")
ax.plot(*finite("torque_complete"), "--", label="complete weak form, N = 145")
ax.plot(*finite("torque_published"), "-", label="reconstructed printed scheme, closure q(b) = 1")
if "torque_published_torque_closure" in curve.dtype.names:
    ax.plot(*finite("torque_published_torque_closure"), ":", label="reconstructed printed scheme, torque closure")
ax.axvline(4 / 3, color="0.5")
ax.set_xlim(0.98, 1.6)
ax.set_xlabel("$T^*$")
ax.set_ylabel("$b/a$")
ax.legend(fontsize=8)
over = curve["stick_radius"][curve["torque_published"] > 4 / 3]
print(f"reconstructed printed scheme (closure q(b) = 1): T* exceeds 4/3 on this grid up to b/a = {over.max():.3f}"
      if over.size
      else "reconstructed printed scheme: T* stays below 4/3")

# %% [markdown]
# ## Table of T*(b) and omega(b): converged (Abel-Fredholm) against the weak forms at N = 145

# %%
table, _ = read_csv(RESULTS / "data" / "torque_table.csv")
for row in np.atleast_1d(table):
    print(f"b/a = {row['stick_radius']:.2f}: T* = {row['torque_fast']:.12f} (converged), "
          f"{row['torque_complete']:.6f} (complete, N = 145), reconstructed printed scheme "
          f"{row['torque_published']:.6f}")
assert np.all(np.diff(np.atleast_1d(table["torque_fast"])) < 0), "T*(b) must decrease with b"

# %% [markdown]
# ## Unloading after T* = 1.23 (Fig. 5) and the dissipation law
# Memory rules on the converged (Abel-Fredholm) monotonic solution; the dashed curve of the
# manuscript's Fig. 5 is the same experiment at the published truncation N = 145.

# %%
hist = json.loads((RESULTS / "data" / "history.json").read_text())
f5 = hist["fig5"]
r = np.array(f5["radii"])
fig, ax = plt.subplots()
for torque, traction in zip(f5["stages"], f5["traction"], strict=True):
    ax.plot(r, traction, label=f"T* = {torque:g}")
ax.set_xlabel("r/a")
ax.set_ylabel("traction / f p0")
ax.legend(ncol=2)
exact_peak = f5.get("residual_peak_exact")  # 1 - T*_max b_max at r = b_max (elastic unloading)
print("residual traction peak", exact_peak or f5["residual_peak"], "(largest sampled value:",
      f"{f5['residual_peak']['value']:.5f})", "; reverse slip onset at T* =", f5["reverse_slip_onset"])
law = hist["dissipation_law"]
print(f"dissipation ~ eps^{law['fitted_exponent']:.2f} (predicted 3)")
weak = hist["fig5_weak"]
print(f"stick radius at T* = {f5['t_max']}: {f5['loading_stick_radius']:.5f} (converged), "
      f"{weak['loading_stick_radius']:.5f} (complete weak form at the published truncation)")

# %% [markdown]
# ## Conclusion
#
# The converged torque decreases monotonically from 4/3 (spinning) to 1 (slip onset) as the stick
# disc grows; the complete weak form at the published truncation follows it to a few parts per
# thousand, while the printed weak form (38) exceeds the spinning torque for small stick discs and so
# cannot be right there. Unloading from T* = 1.23 leaves a residual traction peaking at the old stick
# front, reverse slip starts after a torque range of exactly 2, and the energy dissipated per cycle
# grows like the cube of the excess range just above that threshold, as the crack analogy predicts.
