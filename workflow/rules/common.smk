# Shared definitions: output folder, library sources (an input of every computing rule),
# the matplotlib style (an input of every figure rule).
OUT = config["outdir"]
LIB = sorted(glob_wildcards("src/torsional_contact/{name}.py").name)
LIB = [f"src/torsional_contact/{name}.py" for name in LIB]
STYLE = config["style"]
PAPER_PDF = f"{OUT}/paper/ms.pdf"


def fig(name):
    """PDF and PNG of one figure."""
    return {"pdf": f"{OUT}/figures/{name}.pdf", "png": f"{OUT}/figures/{name}.png"}


wildcard_constraints:
    quantity="[a-z_]+",
