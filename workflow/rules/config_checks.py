"""The checks of a workflow configuration, run by the Snakefile before any rule is defined.

``check(config, root)``: Snakemake's ``validate`` against config/schema.json (types, ranges, required
and unknown keys), then what JSON Schema cannot say: an integer written with a decimal point (145.0,
which JSON Schema accepts as an integer and the scripts do not) and a style file that does not exist.
Each error names the key.  Used by the Snakefile and by tests/test_workflow.py (in-process, on the
same function).
"""

import json
from pathlib import Path

from snakemake.utils import validate

SCHEMA = Path("config") / "schema.json"


def _check_integers(value, schema, definitions, where="config"):
    """JSON Schema accepts 145.0 as an integer; the scripts do not: reject it here, naming the key."""
    kind = schema.get("type")
    if "$ref" in schema:
        schema = definitions[schema["$ref"].rsplit("/", 1)[1]]
        kind = schema.get("type")
    if kind == "integer" and not isinstance(value, int):
        raise ValueError(f"{where} must be an integer (write it without a decimal point), got {value!r}")
    if kind == "object":
        for key, sub in schema.get("properties", {}).items():
            if key in value:
                _check_integers(value[key], sub, definitions, f"{where}.{key}")
    if kind == "array":
        prefix = schema.get("prefixItems", [])
        for i, item in enumerate(value):
            sub = prefix[i] if i < len(prefix) else schema.get("items") or {}
            _check_integers(item, sub, definitions, f"{where}[{i}]")


def check(config: dict, root) -> None:
    """Validate ``config`` (a loaded configuration; the schema's defaults are filled in) for the checkout at
    ``root`` (the style path is relative to it).  Raises (snakemake's WorkflowError or ValueError) naming the key."""
    schema_path = Path(root) / SCHEMA
    validate(config, str(schema_path.resolve()))
    schema = json.loads(schema_path.read_text())
    _check_integers(config, schema, schema.get("$defs", {}))
    if not (Path(root) / config["style"]).is_file():
        raise ValueError(f"config style: no such file {config['style']!r} (a matplotlib style file)")
