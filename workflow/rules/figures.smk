# One rule per figure; each calls one script in workflow/scripts/ and writes PDF + PNG.
# --n-terms: N of a weak form; a method whose interface values are exact ignores it (_plotting.method_options).

rule fig2_contours:
    input:
        script="workflow/scripts/fig2_contours.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig2_contours.py"),
    output:
        **figs([f"fig2_{quantity}" for quantity in config["contours"]["quantities"]], "fig2"),
    params:
        quantities=config["contours"]["quantities"],
        b=config["contours"]["stick_radius"],
        n=config["n_terms"],
        method=config["method"],
        nr=config["contours"]["nr"],
        nz=config["contours"]["nz"],
        z_max=config["contours"]["z_max"],
        tol=config["contours"]["tolerance"],
    log:
        logfile("fig2_contours"),
    resources:
        runtime=5,
        mem_mb=1000,
    shell:
        "python {input.script} --quantity {params.quantities} --stick-radius {params.b} --method {params.method}"
        " --n-terms {params.n} --nr {params.nr} --nz {params.nz} --z-max {params.z_max} --tolerance {params.tol}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule fig3_torque_curve:
    input:
        script="workflow/scripts/fig3_torque_curve.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig3_torque_curve.py"),
        csv=f"{OUT}/data/torque_curve.csv",
    output:
        **fig("fig3_torque_curve", "fig3"),
    params:
        n=config["n_terms"],
    log:
        logfile("fig3_torque_curve"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --csv {input.csv} --n-terms {params.n}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule fig_schematic:
    input:
        script="workflow/scripts/fig_schematic.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_schematic.py"),
    output:
        **fig("fig1_schematic", "fig1"),
    params:
        b=config["schematic"]["stick_radius"],
    log:
        logfile("fig1_schematic"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --stick-radius {params.b} --style {input.style} --pdf {output.pdf}"
        " --png {output.png} > {log} 2>&1"


rule fig4_interface:
    input:
        script="workflow/scripts/fig4_interface.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig4_interface.py"),
    output:
        **figs([f"fig4_{quantity}" for quantity in config["interface"]["quantities"]], "fig4"),
    params:
        quantities=config["interface"]["quantities"],
        radii=config["interface"]["stick_radii"],
        n=config["n_terms"],
        method=config["method"],
        points=config["interface"]["n_points"],
    log:
        logfile("fig4_interface"),
    resources:
        runtime=5,
        mem_mb=1000,
    shell:
        "python {input.script} --quantity {params.quantities} --stick-radii {params.radii} --method {params.method}"
        " --n-terms {params.n} --n-points {params.points} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"


rule fig_published_vs_complete:
    input:
        script="workflow/scripts/fig_published_vs_complete.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_published_vs_complete.py"),
    output:
        **fig("published_vs_complete", "published_vs_complete"),
    params:
        b=config["comparison"]["stick_radius"],
        n=config["n_terms"],
    log:
        logfile("published_vs_complete"),
    resources:
        runtime=5,
        mem_mb=500,
    shell:
        "python {input.script} --stick-radius {params.b} --n-terms {params.n}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule fig_von_mises:
    input:
        script="workflow/scripts/fig_von_mises.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_von_mises.py"),
    output:
        **fig("von_mises", "von_mises"),
    params:
        friction=config["von_mises"]["friction"],
    log:
        logfile("von_mises"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --friction {params.friction} --style {input.style} --pdf {output.pdf}"
        " --png {output.png} > {log} 2>&1"


rule fig5_cyclic:
    input:
        script="workflow/scripts/fig5_cyclic.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig5_cyclic.py"),
        data=f"{OUT}/data/history.json",
    output:
        **fig("fig5_cyclic", "fig5"),
    log:
        logfile("fig5_cyclic"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --data {input.data} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"


rule fig_hysteresis:
    input:
        script="workflow/scripts/fig_hysteresis.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_hysteresis.py"),
        data=f"{OUT}/data/history.json",
    output:
        **fig("hysteresis", "hysteresis"),
    log:
        logfile("hysteresis"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --data {input.data} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"


rule fig_work_precision:
    input:
        script="workflow/scripts/fig_work_precision.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_work_precision.py"),
        data=f"{OUT}/data/benchmark_speed_error.json",
    output:
        **fig("work_precision", "work_precision"),
    log:
        logfile("work_precision"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --data {input.data} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"


rule fig_convergence:
    input:
        script="workflow/scripts/fig_convergence.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_convergence.py"),
        data=f"{OUT}/data/benchmark_speed_error.json",
    output:
        **fig("convergence", "convergence"),
    log:
        logfile("convergence"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --data {input.data} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"


rule fig_precision_ladder:
    input:
        script="workflow/scripts/fig_precision_ladder.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_precision_ladder.py"),
        data=f"{OUT}/verification/precision_ladder.json",
    output:
        **fig("precision_ladder", "precision_ladder"),
    log:
        logfile("precision_ladder_figure"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --data {input.data} --style {input.style} --pdf {output.pdf} --png {output.png}"
        " > {log} 2>&1"

