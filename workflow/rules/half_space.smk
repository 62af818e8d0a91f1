# The half-space comparison model against the finite cylinders (the manuscript section
# paper/companion/models.tex): two figures, a table and the numbers the text quotes.

HALF_SPACE = config["half_space"]


rule half_space_table:
    input:
        script="workflow/scripts/half_space_table.py",
        lib=lib("workflow/scripts/half_space_table.py"),
    output:
        json=f"{OUT}/data/half_space.json",
        tex=f"{OUT}/tables/half_space.tex",
        macros=f"{OUT}/macros/half_space.tex",
    params:
        torques=HALF_SPACE["table_torques"],
        ranges=HALF_SPACE["fit_ranges"],
        radius=HALF_SPACE["example"]["radius"],
        force=HALF_SPACE["example"]["normal_force"],
        modulus=HALF_SPACE["example"]["shear_modulus"],
        friction=HALF_SPACE["example"]["friction"],
        torque_range=HALF_SPACE["example"]["torque_range"],
    log:
        logfile("half_space_table"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --torques {params.torques} --fit-ranges {params.ranges} --radius {params.radius}"
        " --normal-force {params.force} --shear-modulus {params.modulus} --friction {params.friction}"
        " --torque-range {params.torque_range} --json {output.json} --tex {output.tex} --macros {output.macros}"
        " > {log} 2>&1"


rule fig_half_space_curves:
    input:
        script="workflow/scripts/fig_half_space_curves.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_half_space_curves.py"),
    output:
        **fig("half_space_curves", "half_space_curves"),
    params:
        points=HALF_SPACE["n_points"],
    log:
        logfile("fig_half_space_curves"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --n-points {params.points}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"


rule fig_half_space_energy:
    input:
        script="workflow/scripts/fig_half_space_energy.py",
        style=STYLE,
        lib=lib("workflow/scripts/fig_half_space_energy.py"),
    output:
        **fig("half_space_energy", "half_space_energy"),
    params:
        points=HALF_SPACE["n_points"],
        fit_points=HALF_SPACE["fit_points"],
    log:
        logfile("fig_half_space_energy"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --n-points {params.points} --fit-points {params.fit_points}"
        " --style {input.style} --pdf {output.pdf} --png {output.png} > {log} 2>&1"
