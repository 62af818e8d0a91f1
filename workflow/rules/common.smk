# Shared definitions: output folder, the matplotlib style (an input of every figure rule),
# the library files each script really imports (so that changing one module reruns only the
# rules whose scripts use it), logs and resources.
import sys
from pathlib import Path

from snakemake.io import strip_wildcard_constraints

OUT = config["outdir"]
STYLE = config["style"]
PAPER_PDF = f"{OUT}/paper/ms.pdf"
from dependencies import library_files  # noqa: E402 (workflow/rules is on sys.path: Snakefile)


def lib(script):
    """Library files a workflow script depends on (see workflow/rules/dependencies.py)."""
    return library_files(script)


def fig(name, caption, category="Figures"):
    """PDF and PNG of one figure; the PNG goes into the report with ``workflow/report/<caption>.rst``."""
    png = report(f"{OUT}/figures/{name}.png", caption=f"../report/{caption}.rst", category=category)
    return {"pdf": f"{OUT}/figures/{name}.pdf", "png": png}


def figs(names, caption, category="Figures"):
    """PDFs and PNGs of the figures one job draws (``fig`` of each, as lists in the order of ``names``)."""
    each = [fig(name, caption, category) for name in names]
    return {"pdf": [f["pdf"] for f in each], "png": [f["png"] for f in each]}


#: For the timing benchmarks, which time one BLAS thread.  They run on one core beside one other job:
#: measured beside the heaviest neighbour (the cross-check's dense LUs on the other core), the medians
#: of the speed benchmark moved by 0.1 % (median over its cases, at most 6.5 %) and its ratios by
#: 1.3 %, those of the histories benchmark by 2.5 % (at most 10 %), against a spread of 2-3.5 %
#: between two runs alone; holding both cores left one idle for about 30 s of every build.
ONE_BLAS_THREAD = "OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1"


def logfile(name):
    """The log file of one job (stdout and stderr of its script)."""
    return f"{OUT}/logs/{name}.log"


wildcard_constraints:
    quantity="[a-z_]+",


#: rule name -> {wildcard: values}: how the default target expands each rule's outputs
WILDCARDS = {}


def deliverables(wildcards):
    """Every output of every rule (wildcards expanded from the configuration): the default target.

    Deleting any of them and rerunning rebuilds exactly it and what depends on it.
    """
    targets = []
    for rule in workflow.rules:
        if rule.name == "all":
            continue
        for pattern in rule.output:
            values = WILDCARDS.get(rule.name, {})
            if rule.wildcard_names:
                targets.extend(expand(strip_wildcard_constraints(str(pattern)), **values))
            else:
                targets.append(str(pattern))
    return targets
