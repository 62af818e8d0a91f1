# Rebuild every figure, table and the manuscript: snakemake --cores 2 (see README).
from snakemake.utils import min_version, validate

min_version("9.0")


configfile: "config/config.yaml"


validate(config, "config/schema.json")


include: "workflow/rules/common.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/tables.smk"
include: "workflow/rules/paper.smk"


rule all:
    input:
        PAPER_PDF,
