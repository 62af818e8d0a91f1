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
    log:
        logfile("friction_test_coverage"),
    resources:
        runtime=10,
        mem_mb=1000,
    shell:
        "python {input.script} --specimen '{params.specimen}' --scenarios '{params.scenarios}'"
        " --draws {params.draws} --cycles {params.cycles} --samples-per-cycle {params.samples}"
        " --seed {params.seed} --json {output.json} --tex {output.tex} --macros {output.macros} > {log} 2>&1"
