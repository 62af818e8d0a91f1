# The three LaTeX documents: the paper (paper/ms.tex), its supplement (paper/supplement.tex) and the
# companion paper on reading friction from torsion loops (paper/companion.tex, its sections in
# paper/companion/), with generated figures, tables and macros, compiled by latexmk.  Their inputs
# are read off the LaTeX sources themselves: every \resultsdir/... path and every \loadresults{name}
# (results/macros/name.tex), in the main file and in every paper/*.tex file it \input's (recursively:
# paper/preamble.tex, paper/companion/NAME.tex), so nothing is listed twice by hand and a section
# added with one \input{companion/NAME} brings its figures and macros into the rule.
import re

MANUSCRIPT = "paper/ms.tex"
SUPPLEMENT = "paper/supplement.tex"
SUPPLEMENT_PDF = f"{OUT}/paper/supplement.pdf"
COMPANION = "paper/companion.tex"
COMPANION_PDF = f"{OUT}/paper/companion.pdf"


def _uncommented(path):
    """The LaTeX source without its comments (an escaped \\% is kept)."""
    lines = Path(path).read_text().splitlines()
    return "\n".join(re.split(r"(?<!\\)%", line, maxsplit=1)[0] for line in lines)


def tex_sources(main):
    """``main`` and the paper/*.tex files it \\input's (recursively), in order of first appearance.

    An \\input of a generated file (``\\resultsdir/...``) starts with a backslash and is not followed."""
    found, queue = [], [main]
    while queue:
        path = queue.pop(0)
        if path in found:
            continue
        found.append(path)
        for name in re.findall(r"\\input\{(\w[\w./-]*?)(?:\.tex)?\}", _uncommented(path)):
            queue.append(f"paper/{name}.tex")
    return found


def latex_inputs(main):
    """Generated files a LaTeX document reads (parsed from ``main`` and its sections)."""
    text = "\n".join(_uncommented(path) for path in tex_sources(main))
    paths = {f"{OUT}/{p}" for p in re.findall(r"\\resultsdir/([\w/.-]+\.\w+)", text)}
    paths |= {f"{OUT}/macros/{name}.tex" for name in re.findall(r"\\loadresults\{([\w.-]+)\}", text)}
    return sorted(paths)


def manuscript_inputs():
    """Generated files the manuscript reads (parsed from paper/ms.tex and its sections)."""
    return latex_inputs(MANUSCRIPT)


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


rule paper_tables:
    input:
        script="workflow/scripts/paper_tables.py",
        lib=lib("workflow/scripts/paper_tables.py"),
        errata=f"{OUT}/errata/errata.json",
        fem=f"{OUT}/verification/fem_validation.json",
    output:
        findings=f"{OUT}/tables/errata_findings.tex",
        closures=f"{OUT}/tables/closures.tex",
        macros=f"{OUT}/macros/paper_tables.tex",
    log:
        logfile("paper_tables"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --errata {input.errata} --fem {input.fem} --findings {output.findings}"
        " --closures {output.closures}"
        " --macros {output.macros} > {log} 2>&1"


# -cd: latexmk runs in paper/ so references.bib, preamble.tex and companion/ are found; \resultsdir is relative to paper/
LATEXMK = ("mkdir -p {params.build} && latexmk -cd -pdf -interaction=nonstopmode -halt-on-error"
           " -outdir=$(realpath {params.build}) -usepretex='\\def\\resultsdir{{{params.results}}}'"
           " {input.tex} > {log} 2>&1")


rule paper:
    input:
        tex=MANUSCRIPT,
        sections=tex_sources(MANUSCRIPT)[1:],
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
        LATEXMK + " && cp {params.build}/ms.pdf {output}.tmp && mv {output}.tmp {output}"


rule companion:
    input:
        tex=COMPANION,
        sections=tex_sources(COMPANION)[1:],
        bib="paper/references.bib",
        results=latex_inputs(COMPANION),
    output:
        COMPANION_PDF,
    params:
        build=f"{OUT}/paper/build-companion",
        results=os.path.relpath(OUT, "paper"),
    log:
        logfile("companion"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        LATEXMK + " && cp {params.build}/companion.pdf {output}.tmp && mv {output}.tmp {output}"


rule supplement:
    input:
        tex=SUPPLEMENT,
        sections=tex_sources(SUPPLEMENT)[1:],
        bib="paper/references.bib",
        results=latex_inputs(SUPPLEMENT),
    output:
        SUPPLEMENT_PDF,
    params:
        build=f"{OUT}/paper/build-supplement",
        results=os.path.relpath(OUT, "paper"),
    log:
        logfile("supplement"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        LATEXMK + " && cp {params.build}/supplement.pdf {output}.tmp && mv {output}.tmp {output}"




RESPONSE = "paper/response_to_referee.md"


def response_macros():
    """The macro files of the three documents: the response quotes their numbers."""
    paths = set()
    for document in (MANUSCRIPT, SUPPLEMENT, COMPANION):
        paths |= {p for p in latex_inputs(document) if p.startswith(f"{OUT}/macros/")}
    return sorted(paths)


rule response:
    input:
        script="workflow/scripts/build_response.py",
        lib=lib("workflow/scripts/build_response.py"),
        template=RESPONSE,
        macros=response_macros(),
        # the documents' numbers of sections, equations, tables and figures come from their .aux files,
        # written beside each PDF by its rule
        pdfs=[PAPER_PDF, SUPPLEMENT_PDF, COMPANION_PDF],
    output:
        f"{OUT}/paper/response_to_referee.md",
    params:
        aux=[f"{OUT}/paper/build/ms.aux", f"{OUT}/paper/build-supplement/supplement.aux",
             f"{OUT}/paper/build-companion/companion.aux"],
    log:
        logfile("response"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --template {input.template} --macros {input.macros} --aux {params.aux}"
        " --output {output} > {log} 2>&1"


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
    paper_tables,
    paper,
    supplement,
    companion,
    response,
    report,
