# Tables and the numbers quoted in the manuscript (as LaTeX macros).


rule torque_table:
    input:
        script="workflow/scripts/torque_table.py",
        lib=lib("workflow/scripts/torque_table.py"),
    output:
        csv=f"{OUT}/data/torque_table.csv",
        tex=f"{OUT}/tables/torque_table.tex",
        macros=f"{OUT}/macros/torque_table.tex",
    params:
        radii=config["torque_table"]["stick_radii"],
        n=config["n_terms"],
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --stick-radii {params.radii} --n-terms {params.n}"
        " --csv {output.csv} --tex {output.tex} --macros {output.macros}"


rule convergence_table:
    input:
        script="workflow/scripts/convergence_table.py",
        lib=lib("workflow/scripts/convergence_table.py"),
    output:
        json=f"{OUT}/data/convergence_n_terms.json",
        macros=f"{OUT}/macros/convergence.tex",
    params:
        b=config["convergence"]["stick_radius"],
        n=config["convergence"]["max_n_terms"],
    resources:
        runtime=10,
        mem_mb=3000,
    shell:
        "python {input.script} --stick-radius {params.b} --max-n {params.n} --json {output.json} --macros {output.macros}"


rule history_data:
    input:
        script="workflow/scripts/history_data.py",
        lib=lib("workflow/scripts/history_data.py"),
    output:
        json=f"{OUT}/data/history.json",
        macros=f"{OUT}/macros/history.tex",
    params:
        n=config["history"]["n_terms"],
        fit_n=config["history"]["fit_n_terms"],
        points=config["history"]["n_points"],
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --n-terms {params.n} --fit-n-terms {params.fit_n} --n-points {params.points}"
        " --json {output.json} --macros {output.macros}"


rule errata_report:
    input:
        script="workflow/scripts/errata_report.py",
        lib=lib("workflow/scripts/errata_report.py"),
    output:
        json=f"{OUT}/errata/errata.json",
        md=f"{OUT}/errata/errata.md",
        complete=f"{OUT}/errata/reference_complete.json",
        published=f"{OUT}/errata/reference_published.json",
    params:
        radii=config["reference"]["stick_radii"],
        n=config["reference"]["n_terms"],
        digits=config["reference"]["digits"],
        converged=config["reference"]["converged_n_terms"],
        conditions=config["reference"]["condition_n_terms"],
        out=f"{OUT}/errata",
    resources:
        runtime=20,
        mem_mb=4000,
    shell:
        "OMP_NUM_THREADS=1 python {input.script} --out {params.out} --stick-radii {params.radii} --n-terms {params.n}"
        " --digits {params.digits} --converged-n-terms {params.converged} --condition-n-terms {params.conditions}"


rule errata_tables:
    input:
        script="workflow/scripts/errata_tables.py",
        lib=lib("workflow/scripts/errata_tables.py"),
        errata=f"{OUT}/errata/errata.json",
        reference=f"{OUT}/errata/reference_complete.json",
    output:
        tex=f"{OUT}/tables/errata_table.tex",
        macros=f"{OUT}/macros/errata.tex",
    shell:
        "python {input.script} --errata {input.errata} --reference {input.reference} --tex {output.tex}"
        " --macros {output.macros}"


rule benchmark_speed_error:
    input:
        script="workflow/scripts/benchmark_speed_error.py",
        lib=lib("workflow/scripts/benchmark_speed_error.py"),
    output:
        json=f"{OUT}/data/benchmark_speed_error.json",
        macros=f"{OUT}/macros/benchmark.tex",
    params:
        radii=config["benchmark"]["stick_radii"],
        n=config["benchmark"]["n_terms"],
        nodes=config["benchmark"]["nodes"],
        repeats=config["benchmark"]["repeats"],
        digits=config["benchmark"]["reference_digits"],
    threads: 2  # runs alone: timings are not disturbed by a parallel job
    resources:
        runtime=15,
        mem_mb=3000,
    shell:
        "OMP_NUM_THREADS=1 python {input.script} --stick-radius {params.radii} --n-terms {params.n}"
        " --nodes {params.nodes} --repeats {params.repeats} --reference-digits {params.digits}"
        " --json {output.json} --macros {output.macros}"


rule benchmark_scenes:
    input:
        script="workflow/scripts/benchmark_scenes.py",
        lib=lib("workflow/scripts/benchmark_scenes.py"),
    output:
        json=f"{OUT}/data/benchmark_scenes.json",
        tex=f"{OUT}/tables/scenes.tex",
        macros=f"{OUT}/macros/scenes.tex",
    params:
        b=config["contours"]["stick_radius"],
        tol=config["contours"]["tolerance"],
        nr=config["contours"]["nr"],
        nz=config["contours"]["nz"],
        z_max=config["contours"]["z_max"],
    threads: 2  # runs alone: timings are not disturbed by a parallel job
    shell:
        "OMP_NUM_THREADS=1 python {input.script} --stick-radius {params.b} --plot-tolerance {params.tol}"
        " --nr {params.nr} --nz {params.nz} --z-max {params.z_max}"
        " --json {output.json} --tex {output.tex} --macros {output.macros}"
