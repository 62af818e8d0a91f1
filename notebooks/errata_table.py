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
# Formulas are checked at 40 digits against independent computations; solutions against the
# Abel-Fredholm solution (the truth).  Reads `errata/errata.json` written by the workflow; set
# `RESULTS_DIR` for another folder.

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
# ## The verdict rules and the reconstruction caveat
#
# The 'published' results are the printed equations plus this project's closure (T* fixed by
# traction continuity at r = b), which the paper does not state.

# %%
print(data["rules"]["text"], "\n")
print(data["closure_caveat"]["text"])

# %% [markdown]
# ## Coverage of the paper's equations 1-53

# %%
coverage = data["coverage"]
print(f"{len(coverage['checked'])} of {len(coverage['equations'])} equations have a row")
print("not checked (with reasons):", coverage["unchecked"] or "none")
print("without a row or a reason:", coverage["missing"] or "none")

# %% [markdown]
# ## Everything that is not `correct`

# %%
for row in table:
    if row["verdict"] != "correct":
        print(f"({row['equation']}) {row['verdict'].upper()}, max rel. discrepancy {row['max_rel_discrepancy']}")
        print("  check:", row["check"])
        print("  note: ", row["note"], "\n")

# %% [markdown]
# ## Rows that depend on the closure

# %%
for row in table:
    if row["details"].get("depends_on_closure"):
        print(f"({row['equation']}) {row['verdict']}")

# %% [markdown]
# ## The rest, one line each (definitions marked)

# %%
for row in table:
    if row["verdict"] == "correct":
        d = row["max_rel_discrepancy"]
        kind = " (definition)" if row["details"].get("kind") == "definition" else ""
        print(f"({row['equation']}) correct{kind}" + ("" if d is None else f", {d:.1e}"))

# %% [markdown]
# ## Conclusion
#
# Every numbered equation of the paper has been checked by an independent computation. The closed
# forms of Appendices A and B and the derivation of the weak form are exact; the hypergeometric form
# of eq. (51) is numerically hazardous in double precision; the eigenfunction series (21) is
# incomplete (the rigid-rotation mode is missing), so the printed weak form is inconsistent, and
# 'evaluating the torque actually present' cannot fix the stick radius. The numbers the paper quotes
# (b/a = 0.6 at T* = 1.23, reverse slip at -0.77, shakedown below a range of 2) are right for the
# converged solution.
