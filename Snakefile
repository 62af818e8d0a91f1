# Rebuild every figure, table, data file, the errata and the manuscript (see README):
#   snakemake --profile workflow/profiles/default [--configfile config/test.yaml]
import os
import sys
from pathlib import Path

from snakemake.utils import min_version, validate

min_version("9.0")

# validate() imports jsonschema, which imports the optional rfc3987-syntax when it is installed
# (Jupyter pulls it in) and that compiles 38 grammars on import: 1.5 CPU-s per Snakemake start,
# for "iri" format checks that config/schema.json does not use.  Skip that one import.
sys.modules.setdefault("rfc3987_syntax", None)


configfile: "config/config.yaml"


validate(config, "config/schema.json")


def _check_integers(value, schema, where="config"):
    """JSON Schema accepts 145.0 as an integer; the scripts do not: reject it here, naming the key."""
    kind = schema.get("type")
    if "$ref" in schema:
        schema = SCHEMA["$defs"][schema["$ref"].rsplit("/", 1)[1]]
        kind = schema.get("type")
    if kind == "integer" and not isinstance(value, int):
        raise ValueError(f"{where} must be an integer (write it without a decimal point), got {value!r}")
    if kind == "object":
        for key, sub in schema.get("properties", {}).items():
            if key in value:
                _check_integers(value[key], sub, f"{where}.{key}")
    if kind == "array":
        prefix = schema.get("prefixItems", [])
        for i, item in enumerate(value):
            sub = prefix[i] if i < len(prefix) else schema.get("items") or {}
            _check_integers(item, sub, f"{where}[{i}]")


import json

SCHEMA = json.loads(Path("config/schema.json").read_text())
_check_integers(config, SCHEMA)
if not Path(config["style"]).is_file():
    raise ValueError(f"config style: no such file {config['style']!r} (a matplotlib style file)")

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
include: "workflow/rules/paper.smk"
include: "workflow/rules/friction_test.smk"
include: "workflow/rules/notebooks.smk"


rule all:
    default_target: True
    input:
        deliverables,
