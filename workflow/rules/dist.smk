# A citable archive: the report, every summary, table and figure, with a SHA256SUMS manifest;
# and verify, which rebuilds an archive with this checkout and compares every number with it.

ARCHIVE = f"results/dist/{_project['name']}-{_project['version']}.tar.gz"


rule dist:
    input:
        rules.report_html.output,
        rules.report_pdf.output,
        every_result(),
        snakefile=ARCHIVED_CHECKOUT[0],  # the crate's workflow, the Snakefile that ran
        checkout=ARCHIVED_CHECKOUT[1:],
    output:
        archive=ARCHIVE,
        sums="results/dist/SHA256SUMS",
    threads: 1
    resources:
        **measured_resources("dist"),
    params:
        code=job_code("cli"),
    log:
        "results/logs/dist.log",
    conda:
        "../envs/pipeline.yaml"
    benchmark:
        "results/benchmarks/dist.tsv"
    shell:
        "python3 -m classical_dynamics.jobserver"
        " classical_dynamics dist results {output.archive:q} --snakefile {input.snakefile:q} > {log:q} 2>&1"


localrules:
    verify,


rule verify:
    """Rebuild the archive's scenes with this checkout and compare every number with it (always runs:
    no output; nothing is written but the log). Another archive: --config archive=PATH."""
    params:
        archive=config.get("archive", ARCHIVE),
        root=ROOT,
    threads: workflow.cores
    # It reruns every scene of the archive, `threads` at a time, here and never as a cluster job.
    resources:
        mem_mb=lambda wc, threads: threads * max(e.memory_limit_mb for e in ESTIMATES.values()),
        runtime=lambda wc, threads: -(-sum(e.time_limit_s for e in ESTIMATES.values()) // (60 * threads)),
    log:
        "results/logs/verify.log",
    conda:
        "../envs/pipeline.yaml"
    shell:
        "python3 -m classical_dynamics verify {params.archive:q} --root {params.root:q} --cores {threads} 2>&1 | tee {log:q}"
