# The laboratory front door: the loop fit's coverage study (friction_test in the configuration).

FRICTION_TEST = config["friction_test"]


rule friction_test_coverage:
    input:
        script="workflow/scripts/friction_test_coverage.py",
        lib=lib("workflow/scripts/friction_test_coverage.py"),
    output:
        json=f"{OUT}/data/friction_test_coverage.json",
        tex=f"{OUT}/tables/friction_test_coverage.tex",
        macros=f"{OUT}/macros/friction_test.tex",
    params:
        specimen=json.dumps(FRICTION_TEST["specimen"]),
        scenarios=json.dumps(FRICTION_TEST["scenarios"]),
        draws=FRICTION_TEST["draws"],
        cycles=FRICTION_TEST["cycles"],
        samples=FRICTION_TEST["samples_per_cycle"],
        seed=FRICTION_TEST["seed"],
        blas=ONE_BLAS_THREAD,  # one BLAS thread in each worker: two would oversubscribe the two cores
    threads: 2  # the draws are fitted on two processes (the output does not depend on their number)
    priority: 110  # first, while both cores are free (a two-thread job waits until both are idle)
    log:
        logfile("friction_test_coverage"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        "{params.blas} python {input.script} --specimen '{params.specimen}' --scenarios '{params.scenarios}'"
        " --draws {params.draws} --cycles {params.cycles} --samples-per-cycle {params.samples}"
        " --seed {params.seed} --workers {threads} --json {output.json} --tex {output.tex} --macros {output.macros}"
        " > {log} 2>&1"


# Figures for experimenters (notebooks/friction_test.py, paper/companion/rig_defects.tex): the lab
# specimen and record are committed in notebooks/data/ (made by workflow/scripts/make_lab_loop.py).
LAB_LOOP = "notebooks/data/lab_loop.csv"
LAB_TRUTH = "notebooks/data/lab_loop.json"


# The European export of the same record (semicolons, decimal commas, metadata lines, the rig's own column
# names) that the README reads: rebuilt from the committed record, so that the committed copy
# notebooks/data/lab_export.csv can be compared with what the script writes (tests/test_lab_files.py does).
rule lab_export:
    input:
        script="workflow/scripts/make_lab_export.py",
        lib=lib("workflow/scripts/make_lab_export.py"),
        source=LAB_LOOP,
    output:
        csv=f"{OUT}/data/lab_export.csv",
    log:
        logfile("lab_export"),
    resources:
        runtime=1,
        mem_mb=200,
    shell:
        "python {input.script} --source {input.source} --csv {output.csv} > {log} 2>&1"


rule fig_lab_loops:
    input:
        script="workflow/scripts/fig_lab_loops.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_lab_loops.py"),
        specimen=LAB_TRUTH,
    output:
        **fig("lab_loops", "lab_loops"),
    params:
        amplitudes=FRICTION_TEST["figure_amplitudes"],
    log:
        logfile("fig_lab_loops"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --specimen {input.specimen} --amplitudes {params.amplitudes}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule fig_lab_regime_map:
    input:
        script="workflow/scripts/fig_lab_regime_map.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_lab_regime_map.py"),
        specimen=LAB_TRUTH,
    output:
        **fig("lab_regime_map", "lab_regime_map"),
    params:
        max_force=FRICTION_TEST["map_max_force"],
    log:
        logfile("fig_lab_regime_map"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --specimen {input.specimen} --max-force {params.max_force}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule fig_lab_fit:
    input:
        script="workflow/scripts/fig_lab_fit.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_lab_fit.py"),
        loop=LAB_LOOP,
        truth=LAB_TRUTH,
    output:
        **fig("lab_fit", "lab_fit"),
    log:
        logfile("fig_lab_fit"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --loop {input.loop} --truth {input.truth}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule lab_fit_macros:
    input:
        script="workflow/scripts/lab_fit_macros.py",
        lib=lib("workflow/scripts/lab_fit_macros.py"),
        loop=LAB_LOOP,
        truth=LAB_TRUTH,
    output:
        json=f"{OUT}/data/lab_fit.json",
        macros=f"{OUT}/macros/lab_fit.tex",
    log:
        logfile("lab_fit_macros"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --loop {input.loop} --truth {input.truth} --json {output.json}"
        " --macros {output.macros} > {log} 2>&1"


# The loop fit on rig records with defects (verification.fit_study): coverage with the fit's handling on and off,
# the gross-slip window against the plateau estimator.  A full study: see README ("The loop fit on rig records").
FIT_STUDY = config["fit_study"]


rule fit_study:
    input:
        script="workflow/scripts/fit_study.py",
        lib=lib("workflow/scripts/fit_study.py"),
    output:
        json=f"{OUT}/data/fit_study.json",
        csv=f"{OUT}/data/fit_study.csv",
        tex=f"{OUT}/tables/fit_study.tex",
        window=f"{OUT}/tables/fit_study_window.tex",
        macros=f"{OUT}/macros/fit_study.tex",
    params:
        config=json.dumps(FIT_STUDY),
        replicates=FIT_STUDY["replicates"],
        long_replicates=FIT_STUDY["long_replicates"],
        blas=ONE_BLAS_THREAD,
    log:
        logfile("fit_study"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        "{params.blas} python {input.script} --config '{params.config}' --replicates {params.replicates}"
        " --long-replicates {params.long_replicates} --json {output.json} --csv {output.csv}"
        " --tex {output.tex} --window-tex {output.window} --macros {output.macros} > {log} 2>&1"


rule fig_fit_study:
    input:
        script="workflow/scripts/fig_fit_study.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_fit_study.py"),
        data=f"{OUT}/data/fit_study.json",
    output:
        **fig("fit_study", "fit_study"),
    log:
        logfile("fig_fit_study"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --data {input.data} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"
