# The contact models of the model table side by side (paper/companion/models.tex): one figure, a table,
# the numbers the text quotes and their data with metadata.

MODELS_CONFIG = config["models"]


rule models_comparison:
    input:
        script="workflow/scripts/models_comparison.py",
        style=STYLE,
        lib=lib("workflow/scripts/models_comparison.py"),
    output:
        **fig("models_comparison", "models_comparison"),
        json=f"{OUT}/data/models.json",
        tex=f"{OUT}/tables/models.tex",
        macros=f"{OUT}/macros/models.tex",
    params:
        points=MODELS_CONFIG["n_points"],
        fit_points=MODELS_CONFIG["fit_points"],
    log:
        logfile("models_comparison"),
    resources:
        runtime=3,
        mem_mb=500,
    shell:
        "python {input.script} --n-points {params.points} --fit-points {params.fit_points}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} --json {output.json} --tex {output.tex}"
        " --macros {output.macros} > {log} 2>&1"
