# The verification wing: arbitrary-precision references, precision cross-checks, the errata.

WEAK_FORMS = ["published", "complete"]


rule reference_weak_form:
    input:
        script="workflow/scripts/reference_weak_form.py",
        lib=lib("workflow/scripts/reference_weak_form.py"),
    output:
        json=f"{OUT}/verification/reference_{{method}}.json",
        timing=f"{OUT}/timings/reference_{{method}}.json",
    params:
        radii=config["reference"]["stick_radii"],
        n=config["reference"]["n_terms"],
        digits=config["reference"]["digits"],
    priority: 50  # at the head of the cross-check and the ladder: start early
    log:
        logfile("reference_{method}"),
    wildcard_constraints:
        method="published|complete",
    resources:
        runtime=10,
        mem_mb=2000,
    shell:
        "python {input.script} --method {wildcards.method} --stick-radii {params.radii} --n-terms {params.n}"
        " --digits {params.digits} --json {output.json} --timing {output.timing} > {log} 2>&1"


rule precision_crosscheck:
    input:
        script="workflow/scripts/precision_crosscheck.py",
        lib=lib("workflow/scripts/precision_crosscheck.py"),
        references=expand(f"{OUT}/verification/reference_{{method}}.json", method=WEAK_FORMS),
    output:
        json=f"{OUT}/verification/crosscheck.json",
        converged=f"{OUT}/verification/weak_forms_converged.json",
    params:
        converged=config["crosscheck"]["converged_n_terms"],
        conditions=config["crosscheck"]["condition_n_terms"],
    priority: 40  # long: start as soon as its inputs exist
    log:
        logfile("precision_crosscheck"),
    resources:
        runtime=15,
        mem_mb=4000,
    shell:
        "python {input.script} --references {input.references} --converged-n-terms {params.converged}"
        " --condition-n-terms {params.conditions} --json {output.json} --converged-json {output.converged}"
        " > {log} 2>&1"


rule errata:
    input:
        script="workflow/scripts/errata_report.py",
        lib=lib("workflow/scripts/errata_report.py"),
    output:
        json=f"{OUT}/errata/errata.json",
        md=f"{OUT}/errata/errata.md",
    priority: 20  # long: start early
    log:
        logfile("errata"),
    resources:
        runtime=15,
        mem_mb=2000,
    shell:
        "python {input.script} --json {output.json} --md {output.md} > {log} 2>&1"


rule errata_tables:
    input:
        script="workflow/scripts/errata_tables.py",
        lib=lib("workflow/scripts/errata_tables.py"),
        errata=f"{OUT}/errata/errata.json",
        crosscheck=f"{OUT}/verification/crosscheck.json",
        reference=f"{OUT}/verification/reference_complete.json",
    output:
        tex=f"{OUT}/tables/errata_table.tex",
        macros=f"{OUT}/macros/errata.tex",
    log:
        logfile("errata_tables"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --errata {input.errata} --crosscheck {input.crosscheck}"
        " --reference {input.reference} --tex {output.tex} --macros {output.macros} > {log} 2>&1"


rule reference_timing:
    input:
        script="workflow/scripts/timing_macros.py",
        lib=lib("workflow/scripts/timing_macros.py"),
        timings=expand(f"{OUT}/timings/reference_{{method}}.json", method=WEAK_FORMS),
    output:
        macros=f"{OUT}/macros/reference_timing.tex",
    log:
        logfile("reference_timing"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --timings {input.timings} --key ref-seconds --statistic sum --field seconds_total"
        " --macros {output.macros} > {log} 2>&1"


WILDCARDS["reference_weak_form"] = {"method": WEAK_FORMS}


rule fem_validation:
    input:
        script="workflow/scripts/fem_validation.py",
        lib=lib("workflow/scripts/fem_validation.py"),
    output:
        json=f"{OUT}/verification/fem_validation.json",
        tex=f"{OUT}/tables/fem_validation.tex",
        macros=f"{OUT}/macros/fem_validation.tex",
    params:
        radii=config["fem_validation"]["stick_radii"],
        levels=config["fem_validation"]["mesh_levels"],
        degree=config["fem_validation"]["degree"],
        truncation=config["fem_validation"]["truncation"],
        direct="--direct" if config["fem_validation"]["direct"] else "--no-direct",
    priority: 20  # long: start early
    log:
        logfile("fem_validation"),
    resources:
        runtime=20,
        mem_mb=3000,
    shell:
        "python {input.script} --stick-radii {params.radii} --mesh-levels {params.levels} --degree {params.degree}"
        " --truncation {params.truncation} {params.direct}"
        " --json {output.json} --tex {output.tex} --macros {output.macros} > {log} 2>&1"


PRECISION = config["precision"]
PRECISION_RADII = [f"{b:g}" for b in PRECISION["stick_radii"]]
CONVERGENCE_NODES = {f"{row['stick_radius']:g}": row["nodes"] for row in PRECISION["convergence"]}
if not set(CONVERGENCE_NODES) <= set(PRECISION_RADII):
    raise ValueError(f"config precision.convergence: stick radii {sorted(set(CONVERGENCE_NODES) - set(PRECISION_RADII))}"
                     " are not in precision.stick_radii")


def reference_groups(radii, jobs):
    """The reference radii in ``jobs`` runs of neighbouring radii of about equal cost.

    Neighbours share working precisions (the torque constant, the xi-quadrature's first panels)
    and one process start-up.  Cost model (relative, fitted to the per-radius timings of the
    jobs): 1 + 0.06/(1 - b) per radius, times 1 + 0.12 per node count of its convergence study.
    """
    def cost(radius):
        return (1.0 + 0.06 / (1.0 - float(radius))) * (1.0 + 0.12 * len(CONVERGENCE_NODES.get(radius, [])))

    jobs = min(jobs, len(radii))
    ordered = sorted(radii, key=float)
    share = sum(cost(r) for r in ordered) / jobs
    groups, current, spent = [], [], 0.0
    for index, radius in enumerate(ordered):
        current.append(radius)
        spent += cost(radius)
        left = len(ordered) - index - 1
        if left and (spent >= share * (len(groups) + 1) or left == jobs - len(groups) - 1):
            groups.append(current)
            current = []
    groups.append(current)
    return groups


REFERENCE_GROUPS = reference_groups(PRECISION_RADII, PRECISION["jobs"])


def convergence_options(radii):
    """The node sweeps of the reference radii that have one (the configuration's convergence list)."""
    sweeps = [f"{r}:{','.join(str(n) for n in CONVERGENCE_NODES[r])}" for r in radii if CONVERGENCE_NODES.get(r)]
    if not sweeps:
        return ""
    digits = " ".join(str(d) for d in PRECISION["convergence_digits"])
    return f"--convergence {' '.join(sweeps)} --convergence-digits {digits}"


for _index, _radii in enumerate(REFERENCE_GROUPS, start=1):

    rule:
        # one job per run of neighbouring radii (reference_groups), one output file per radius
        name:
            f"reference_abel_fredholm_{_index}"
        input:
            script="workflow/scripts/reference_abel_fredholm.py",
            lib=lib("workflow/scripts/reference_abel_fredholm.py"),
        output:
            json=[f"{OUT}/verification/abel_fredholm/b{r}.json" for r in _radii],
            timing=[f"{OUT}/timings/abel_fredholm/b{r}.json" for r in _radii],
        params:
            radii=" ".join(_radii),
            digits=PRECISION["digits"],
            convergence=convergence_options(_radii),
        priority: 50  # long and at the head of the precision ladder: start early
        log:
            logfile(f"abel_fredholm_{_index}"),
        resources:
            runtime=15,
            mem_mb=1000,
        shell:
            "python {input.script} --stick-radii {params.radii} --digits {params.digits} {params.convergence}"
            " --json {output.json} --timing {output.timing} > {log} 2>&1"


rule precision_ladder:
    input:
        script="workflow/scripts/precision_ladder.py",
        lib=lib("workflow/scripts/precision_ladder.py"),
        references=expand(f"{OUT}/verification/abel_fredholm/b{{radius}}.json", radius=PRECISION_RADII),
        weak=expand(f"{OUT}/verification/reference_{{method}}.json", method=WEAK_FORMS),
        # both weak forms at the cross-check's converged N (the ladder's largest: not factorised twice)
        converged=f"{OUT}/verification/weak_forms_converged.json",
    output:
        json=f"{OUT}/verification/precision_ladder.json",
        tex=f"{OUT}/tables/precision_ladder.tex",
        weak=f"{OUT}/tables/weak_form_errors.tex",
        macros=f"{OUT}/macros/precision_ladder.tex",
    params:
        weak_radii=PRECISION["weak_radii"],
        weak_n=PRECISION["weak_n_terms"],
        weak_digits=PRECISION["weak_digits"],
        main=PRECISION["main_radius"],
    priority: 40  # long: start as soon as its inputs exist
    log:
        logfile("precision_ladder"),
    resources:
        runtime=20,
        mem_mb=3000,
    shell:
        "python {input.script} --references {input.references} --weak-references {input.weak}"
        " --weak-radii {params.weak_radii}"
        " --weak-n-terms {params.weak_n} --weak-digits {params.weak_digits} --main-radius {params.main}"
        " --converged {input.converged}"
        " --json {output.json} --tex {output.tex} --tex-weak {output.weak} --macros {output.macros} > {log} 2>&1"


rule precision_timing:
    input:
        script="workflow/scripts/timing_macros.py",
        lib=lib("workflow/scripts/timing_macros.py"),
        timings=expand(f"{OUT}/timings/abel_fredholm/b{{radius}}.json", radius=PRECISION_RADII),
    output:
        macros=f"{OUT}/macros/precision_timing.tex",
    log:
        logfile("precision_timing"),
    resources:
        runtime=2,
        mem_mb=500,
    shell:
        "python {input.script} --timings {input.timings} --key ladder-max-ref-seconds --statistic max"
        " --field seconds --macros {output.macros} > {log} 2>&1"

