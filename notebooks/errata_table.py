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
# # The errata table
#
# Results read: `errata/errata.json`
# (from the build's output folder, `RESULTS_DIR`).
#
# Every checked statement of the paper with its computed verdict (`correct`, `typo`,
# `numerically-hazardous`, `incorrect`), how it was checked, and the largest discrepancy.
# Reads `errata/errata.json` written by the workflow; set `RESULTS_DIR` for another folder.

# %%
import json
import os
from collections import Counter
from pathlib import Path

RESULTS = Path(os.environ.get("RESULTS_DIR", "../results"))
data = json.loads((RESULTS / "errata" / "errata.json").read_text())
table = data["errata"]
print(Counter(row["verdict"] for row in table))
print("thresholds:", data["thresholds"])

# %% [markdown]
# ## Everything that is not `correct`

# %%
for row in table:
    if row["verdict"] != "correct":
        print(f"({row['equation']}) {row['verdict'].upper()}, max rel. discrepancy {row['max_rel_discrepancy']}")
        print("  check:", row["check"])
        print("  note: ", row["note"], "\n")

# %% [markdown]
# ## The rest, one line each

# %%
for row in table:
    if row["verdict"] == "correct":
        d = row["max_rel_discrepancy"]
        print(f"({row['equation']}) correct" + ("" if d is None else f", {d:.1e}"))
