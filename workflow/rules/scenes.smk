# The one rule that runs a scene of any study.


wildcard_constraints:
    study="|".join(STUDIES),
    scene="[a-z0-9_]+",


rule scene:
    """Run one scene of one study: results/<study>/<scene>/ and its timings."""
    input:
        scene=f"{SCENES}/{{study}}/{{scene}}.yaml",
        schema=lambda wc: here(STUDIES[wc.study].schema),
        checked=result_check,
    # report(): what `snakemake --report` shows of the scene, its figures and tables with their captions, in its
    # chapter's category (classical_dynamics/report/snakemake_report.py). A flag: neither what the job writes nor
    # what reruns it changes.
    output:
        results=report(
            directory("results/{study}/{scene}"),
            caption="../report/result.rst",
            category=snakemake_report.category("results"),
            subcategory="{scene}",
            patterns=snakemake_report.PATTERNS,
        ),
        timings=report(
            directory("results/{study}/timings/{scene}"),
            caption="../report/timing.rst",
            category=snakemake_report.category("timings"),
            subcategory="{scene}",
            patterns=snakemake_report.PATTERNS,
        ),
    params:
        quick=QUICK,
        budget=BUDGET_ARGS,
        code=lambda wc: code_graph.code_digest(*code_graph.scene_job_entries(wc.study)),
    # Longest first (by the scene's cost estimate), so the heaviest scene does not start last and run alone.
    priority: lambda wc: round(limits(wc).seconds, 1)
    threads: 1
    resources:
        runtime=lambda wc: -(-limits(wc).time_limit_s // 60),     # minutes, as Snakemake and Slurm count them
        mem_mb=lambda wc: limits(wc).memory_limit_mb,
    # On a cluster, light scenes run in batches (the slurm profile's group-components), so that the scheduler's
    # few seconds a job do not outweigh them; heavier ones are jobs of their own. Locally, groups are ignored.
    group: lambda wc: LIGHT_SCENES if limits(wc).seconds < LIGHT_SCENE_S else None
    log:
        "results/logs/{study}/{scene}.log",
    conda:
        "../envs/pipeline.yaml"
    benchmark:
        "results/benchmarks/{study}/{scene}.tsv"
    shell:
        "python3 -m classical_dynamics.jobserver"
        " classical_dynamics.scene_job {wildcards.study:q} {input.scene:q}"
        " {output.results:q} {output.timings:q} {params.quick} {params.budget}"
        " --time-limit-min {resources.runtime} --memory-limit-mb {resources.mem_mb} > {log:q} 2>&1"
