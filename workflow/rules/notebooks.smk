# Notebooks for readers: each notebooks/NAME.py (jupytext percent source) is executed on this
# build's results and written as results/notebooks/NAME.ipynb (outputs, figures inline) and
# NAME.html.  The results a notebook reads are listed in its first cell ("Results read: `...`"),
# from which the rule's inputs are derived.

NOTEBOOKS = sorted(p.stem for p in Path("notebooks").glob("*.py"))


def notebook_results(wildcards):
    """The result files named in the notebook's "Results read:" line."""
    text = Path(f"notebooks/{wildcards.notebook}.py").read_text()
    paragraph = text.partition("Results read:")[2].partition("\n#\n")[0]  # up to the next blank comment line
    return [f"{OUT}/{p}" for p in re.findall(r"`([\w-]+/[\w./-]+\.\w+)`", paragraph)]


rule notebook:
    input:
        source="notebooks/{notebook}.py",
        script="workflow/scripts/run_notebook.py",
        lib=lambda wildcards: lib(f"notebooks/{wildcards.notebook}.py"),
        runner=lib("workflow/scripts/run_notebook.py"),
        results=notebook_results,
    output:
        ipynb=f"{OUT}/notebooks/{{notebook}}.ipynb",
        html=report(f"{OUT}/notebooks/{{notebook}}.html", caption="../report/notebook.rst", category="Notebooks"),
    params:
        timeout=config["notebooks"]["timeout"],
    log:
        logfile("notebook_{notebook}"),
    wildcard_constraints:
        notebook="[a-z_]+",
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --notebook {input.source} --results {OUT} --ipynb {output.ipynb}"
        " --timeout {params.timeout}"
        " --html {output.html} > {log} 2>&1"


WILDCARDS["notebook"] = {"notebook": NOTEBOOKS}
