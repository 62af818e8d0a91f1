# Tables, data files and the numbers quoted in the manuscript (as LaTeX macros).


rule torque_curve:
    input:
        script="workflow/scripts/torque_curve.py",
        lib=lib("workflow/scripts/torque_curve.py"),
    output:
        csv=f"{OUT}/data/torque_curve.csv",
    params:
        n=config["n_terms"],
        n_radii=config["torque_curve"]["n_radii"],
    log:
        logfile("torque_curve"),
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --n-terms {params.n} --n-radii {params.n_radii} --csv {output.csv} > {log} 2>&1"


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
    priority: 20  # long: start early (the manuscript waits for every job)
    log:
        logfile("torque_table"),
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --stick-radii {params.radii} --n-terms {params.n}"
        " --csv {output.csv} --tex {output.tex} --macros {output.macros} > {log} 2>&1"


rule limit_problem_table:
    input:
        script="workflow/scripts/limit_problem_table.py",
        lib=lib("workflow/scripts/limit_problem_table.py"),
    output:
        json=f"{OUT}/data/limit_problem.json",
        tex=f"{OUT}/tables/limit_problem.tex",
        macros=f"{OUT}/macros/limit_problem.tex",
    params:
        radii=config["limit_problem"]["stick_radii"],
        n=config["limit_problem"]["n_terms"],
    log:
        logfile("limit_problem_table"),
    resources:
        runtime=5,
        mem_mb=1000,
    shell:
        "python {input.script} --stick-radii {params.radii} --n-terms {params.n}"
        " --json {output.json} --tex {output.tex} --macros {output.macros} > {log} 2>&1"


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
        method=config["convergence"]["method"],
    log:
        logfile("convergence_table"),
    resources:
        runtime=10,
        mem_mb=3000,
    shell:
        "python {input.script} --stick-radius {params.b} --max-n {params.n} --method {params.method}"
        " --json {output.json}"
        " --macros {output.macros} > {log} 2>&1"


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
        method=config["history"]["method"],
        t_max=config["history"]["t_max"],
        stages=config["history"]["stages"],
        loops=[t for pair in config["history"]["loops"] for t in pair],
    log:
        logfile("history_data"),
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --method {params.method} --n-terms {params.n} --fit-n-terms {params.fit_n} --n-points {params.points}"
        " --t-max {params.t_max} --stages {params.stages} --loops {params.loops}"
        " --json {output.json} --macros {output.macros} > {log} 2>&1"


rule benchmark_speed_error:
    input:
        script="workflow/scripts/benchmark_speed_error.py",
        lib=lib("workflow/scripts/benchmark_speed_error.py"),
    output:
        json=f"{OUT}/data/benchmark_speed_error.json",
        macros=f"{OUT}/macros/benchmark.tex",
    params:
        blas=ONE_BLAS_THREAD,
        radii=config["benchmark"]["stick_radii"],
        n=config["benchmark"]["n_terms"],
        nodes=config["benchmark"]["nodes"],
        repeats=config["benchmark"]["repeats"],
        digits=config["benchmark"]["reference_digits"],
        per_radius=config["benchmark"]["per_radius_radii"],
        curve=config["benchmark"]["curve_radii"],
        inverse=config["benchmark"]["inverse_torques"],
    threads: 1  # one core, beside one other job (a neighbour moves the medians by about the run-to-run spread)
    priority: 100  # first: long, and it needs no other job's output
    log:
        logfile("benchmark_speed_error"),
    resources:
        runtime=15,
        mem_mb=3000,
    shell:
        "{params.blas} python {input.script} --stick-radius {params.radii} --n-terms {params.n}"
        " --nodes {params.nodes} --repeats {params.repeats} --reference-digits {params.digits}"
        " --per-radius-radii {params.per_radius} --curve-radii {params.curve} --inverse-torques {params.inverse}"
        " --json {output.json} --macros {output.macros} > {log} 2>&1"


rule benchmark_scenes:
    input:
        script="workflow/scripts/benchmark_scenes.py",
        lib=lib("workflow/scripts/benchmark_scenes.py"),
    output:
        json=f"{OUT}/data/benchmark_scenes.json",
        tex=f"{OUT}/tables/scenes.tex",
        macros=f"{OUT}/macros/scenes.tex",
    params:
        blas=ONE_BLAS_THREAD,
        b=config["contours"]["stick_radius"],
        tol=config["contours"]["tolerance"],
        nr=config["contours"]["nr"],
        nz=config["contours"]["nz"],
        z_max=config["contours"]["z_max"],
        repeats=config["benchmark_scenes"]["repeats"],
    threads: 1  # one core, beside one other job (a neighbour moves the medians by about the run-to-run spread)
    priority: 100  # first: long, and it needs no other job's output
    log:
        logfile("benchmark_scenes"),
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "{params.blas} python {input.script} --stick-radius {params.b} --plot-tolerance {params.tol}"
        " --nr {params.nr} --nz {params.nz} --z-max {params.z_max} --repeats {params.repeats}"
        " --json {output.json} --tex {output.tex} --macros {output.macros} > {log} 2>&1"


rule benchmark_histories:
    input:
        script="workflow/scripts/benchmark_histories.py",
        lib=lib("workflow/scripts/benchmark_histories.py"),
        # the script times the ``history`` subcommand in subprocesses: the command line's entry
        # points and what that subcommand loads (not the lazily imported reference or errata)
        cli=["src/torsional_contact/__main__.py", "src/torsional_contact/io/cli.py",
             "src/torsional_contact/io/history_command.py", *lib("src/torsional_contact/io/history_command.py")],
    output:
        json=f"{OUT}/data/benchmark_histories.json",
        macros=f"{OUT}/macros/benchmark_histories.tex",
    params:
        blas=ONE_BLAS_THREAD,
        samples=config["benchmark_histories"]["samples"],
        cycles=config["benchmark_histories"]["cycles"],
        reversals=config["benchmark_histories"]["walk_reversals"],
        seed=config["benchmark_histories"]["seed"],
        points=config["benchmark_histories"]["turning_points"],
        repeats=config["benchmark_histories"]["repeats"],
        baseline=config["benchmark_histories"]["baseline_points"],
        models=" ".join(config["benchmark_histories"]["models"]),
    threads: 1  # one core, beside one other job (a neighbour moves the medians by about the run-to-run spread)
    priority: 100  # first: long, and it needs no other job's output
    log:
        logfile("benchmark_histories"),
    resources:
        runtime=20,
        mem_mb=1000,
    shell:
        "{params.blas} python {input.script} --samples {params.samples} --cycles {params.cycles}"
        " --walk-reversals {params.reversals} --seed {params.seed} --turning-points {params.points}"
        " --repeats {params.repeats} --baseline-points {params.baseline} --models {params.models}"
        " --json {output.json} --macros {output.macros} > {log} 2>&1"


rule curve_accuracy:
    input:
        script="workflow/scripts/curve_accuracy.py",
        lib=lib("workflow/scripts/curve_accuracy.py"),
    output:
        json=f"{OUT}/verification/curve_accuracy.json",
        macros=f"{OUT}/macros/curve_accuracy.tex",
    params:
        per_panel=config["curve_accuracy"]["per_panel"],
        seed=config["curve_accuracy"]["seed"],
    log:
        logfile("curve_accuracy"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        "python {input.script} --per-panel {params.per_panel} --seed {params.seed} --json {output.json} --macros {output.macros}"
        " > {log} 2>&1"


BUILD_BENCHMARK = f"{OUT}/timings/build_benchmark.json"  # written by workflow/checks/benchmark_build.py


def build_benchmark(wildcards):
    """The timing of a clean build of this configuration and of the test suite, if one was measured."""
    return [BUILD_BENCHMARK] if Path(BUILD_BENCHMARK).is_file() else []


rule build_time_table:
    input:
        script="workflow/scripts/build_time_table.py",
        lib=lib("workflow/scripts/build_time_table.py"),
        benchmark=build_benchmark,
    output:
        html=report(f"{OUT}/timings/build_time.html", caption="../report/build_time.rst", category="Build time"),
    log:
        logfile("build_time_table"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --benchmark {input.benchmark} --html {output.html} > {log} 2>&1"
