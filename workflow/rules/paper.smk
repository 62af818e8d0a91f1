# The manuscript: paper/ms.tex with generated figures, tables and macros, compiled by latexmk.

FIGURES = (
    [f"{OUT}/figures/fig2_{q}.pdf" for q in config["contours"]["quantities"]]
    + [f"{OUT}/figures/fig3_torque_curve.pdf"]
    + [f"{OUT}/figures/fig4_{q}.pdf" for q in config["interface"]["quantities"]]
    + [f"{OUT}/figures/published_vs_complete.pdf", f"{OUT}/figures/von_mises.pdf"]
    + [f"{OUT}/figures/fig5_cyclic.pdf", f"{OUT}/figures/hysteresis.pdf"]
    + [f"{OUT}/figures/work_precision.pdf", f"{OUT}/figures/convergence.pdf"]
)
TABLES = [f"{OUT}/tables/torque_table.tex", f"{OUT}/tables/errata_table.tex", f"{OUT}/tables/scenes.tex"]
MACROS = [f"{OUT}/macros/torque_table.tex", f"{OUT}/macros/convergence.tex", f"{OUT}/macros/build.tex", f"{OUT}/macros/history.tex", f"{OUT}/macros/errata.tex", f"{OUT}/macros/benchmark.tex", f"{OUT}/macros/scenes.tex"]


rule build_macros:
    input:
        script="workflow/scripts/build_macros.py",
    output:
        f"{OUT}/macros/build.tex",
    params:
        n=config["n_terms"],
        method=config["method"],
        outdir=OUT,
    shell:
        "python {input.script} --n-terms {params.n} --method {params.method} --outdir {params.outdir} --output {output}"


rule paper:
    input:
        tex="paper/ms.tex",
        bib="paper/references.bib",
        figures=FIGURES,
        tables=TABLES,
        macros=MACROS,
    output:
        PAPER_PDF,
    params:
        build=f"{OUT}/paper/build",
        outdir=OUT,
    log:
        f"{OUT}/paper/latexmk.log",
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        # -cd: run in paper/ so references.bib is found; results are reached by absolute path
        "mkdir -p {params.build} && latexmk -cd -pdf -interaction=nonstopmode -halt-on-error"
        " -outdir=$(realpath {params.build}) -usepretex='\\def\\resultsdir{{'$(realpath {params.outdir})'}}'"
        " {input.tex} > {log} 2>&1"
        " && cp {params.build}/ms.pdf {output}.tmp && mv {output}.tmp {output}"
