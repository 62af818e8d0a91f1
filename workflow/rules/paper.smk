# The manuscript: paper/ms.tex with generated figures, tables and macros, compiled by latexmk.
# Its inputs are read off the LaTeX source itself: every \resultsdir/... path and every
# \loadresults{name} (results/macros/name.tex), so nothing is listed twice by hand.
import re

MANUSCRIPT = "paper/ms.tex"


def manuscript_inputs():
    """Generated files the manuscript reads (parsed from paper/ms.tex)."""
    text = Path(MANUSCRIPT).read_text()
    text = "\n".join(line.split("%", 1)[0] for line in text.splitlines())  # drop comments
    paths = {f"{OUT}/{p}" for p in re.findall(r"\\resultsdir/([\w/-]+\.\w+)", text)}
    paths |= {f"{OUT}/macros/{name}.tex" for name in re.findall(r"\\loadresults\{([\w.-]+)\}", text)}
    return sorted(paths)


rule build_macros:
    input:
        script="workflow/scripts/build_macros.py",
        lib=lib("workflow/scripts/build_macros.py"),
    output:
        f"{OUT}/macros/build.tex",
    params:
        n=config["n_terms"],
        method=config["method"],
        contour_b=config["contours"]["stick_radius"],
    log:
        logfile("build_macros"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --n-terms {params.n} --method {params.method} --contour-stick-radius {params.contour_b}"
        " --output {output} > {log} 2>&1"


rule paper:
    input:
        tex=MANUSCRIPT,
        bib="paper/references.bib",
        results=manuscript_inputs(),
    output:
        PAPER_PDF,
    params:
        build=f"{OUT}/paper/build",
        results=os.path.relpath(OUT, "paper"),  # \resultsdir as seen from paper/ (latexmk -cd)
    log:
        logfile("paper"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        # -cd: run in paper/ so references.bib is found; \resultsdir is relative to paper/
        "mkdir -p {params.build} && latexmk -cd -pdf -interaction=nonstopmode -halt-on-error"
        " -outdir=$(realpath {params.build}) -usepretex='\\def\\resultsdir{{{params.results}}}'"
        " {input.tex} > {log} 2>&1"
        " && cp {params.build}/ms.pdf {output}.tmp && mv {output}.tmp {output}"




REPORT = f"{OUT}/report.html"


def report_targets(wildcards):
    """Every deliverable except the report itself."""
    return [t for t in deliverables(wildcards) if t != REPORT]


rule report:
    input:
        script="workflow/scripts/build_report.py",
        lib=lib("workflow/scripts/build_report.py"),
        captions=sorted(str(p) for p in Path("workflow/report").glob("*.rst")),
        targets=report_targets,
    output:
        REPORT,
    params:
        config=lambda wildcards: json.dumps(config),
    log:
        logfile("report"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        "python {input.script} --config-json '{params.config}' --targets {input.targets} --output {output}"
        " > {log} 2>&1"


localrules:
    all,
    build_macros,
    paper,
    report,
