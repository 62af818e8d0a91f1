# Rebuild every figure, table, data file, the errata and the manuscript (see README):
#   snakemake --profile workflow/profiles/default [--configfile config/test.yaml]
import json
import os
import sys
from pathlib import Path

from snakemake.utils import min_version

min_version("9.0")

# validate() imports jsonschema, which imports the optional rfc3987-syntax when it is installed
# (Jupyter pulls it in) and that compiles 38 grammars on import: 1.5 CPU-s per Snakemake start,
# for "iri" format checks that config/schema.json does not use.  Skip that one import.
sys.modules.setdefault("rfc3987_syntax", None)


configfile: "config/config.yaml"


sys.path.insert(0, str(Path(workflow.basedir) / "workflow" / "rules"))
from config_checks import check as check_config  # noqa: E402
from scheduling import cancel_pending_timers  # noqa: E402

check_config(config, workflow.basedir)  # the schema, integers written as integers, the style file

# Deterministic numerics: one BLAS thread per job (the last digit of LAPACK estimates
# depends on the thread count); jobs inherit the environment of this process.
for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"
# Reproducible PDFs and a headless matplotlib in every job.
os.environ.setdefault("SOURCE_DATE_EPOCH", "0")
os.environ["MPLBACKEND"] = "Agg"


report: "workflow/report/workflow.rst"


include: "workflow/rules/common.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/tables.smk"
include: "workflow/rules/verification.smk"
include: "workflow/rules/half_space.smk"
include: "workflow/rules/models.smk"
include: "workflow/rules/paper.smk"
include: "workflow/rules/friction_test.smk"
include: "workflow/rules/notebooks.smk"


rule all:
    default_target: True
    input:
        deliverables,


# the scheduler's pending re-evaluation timers (workflow/rules/scheduling.py): the process would wait for them
onsuccess:
    cancel_pending_timers()


onerror:
    cancel_pending_timers()
