# A citable archive: the report, every summary, table and figure, with a SHA256SUMS manifest;
# and verify, which rebuilds an archive with this checkout and compares every number with it.

ARCHIVE = f"results/dist/{_project['name']}-{_project['version']}.tar.gz"


rule dist:
    input:
        rules.report_html.output,
        rules.report_pdf.output,
        [out for study in STUDIES for out in scene_outputs(study)],
    output:
        archive=ARCHIVE,
        sums="results/dist/SHA256SUMS",
    params:
        python=PY,
    log:
        "results/logs/dist.log",
    conda:
        "../envs/pipeline.yaml"
    shell:
        "{params.python:q} -m classical_dynamics.jobserver"
        " classical_dynamics dist results {output.archive:q} > {log:q} 2>&1"


rule verify:
    """Rebuild the archive's scenes with this checkout and compare every number with it (always runs:
    no output; nothing is written but the log). Another archive: --config archive=PATH."""
    params:
        python=PY,
        archive=config.get("archive", ARCHIVE),
    threads: workflow.cores
    log:
        "results/logs/verify.log",
    conda:
        "../envs/pipeline.yaml"
    shell:
        "{params.python:q} -m classical_dynamics verify {params.archive:q} --cores {threads} 2>&1 | tee {log:q}"
