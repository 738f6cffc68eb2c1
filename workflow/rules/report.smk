# The report: every study's results through the Jinja templates into HTML, then the same HTML to PDF.

import tomllib

from pathlib import PurePosixPath

from classical_dynamics.report import assets as report_assets
from classical_dynamics.report import crate as report_crate

with open(ROOT / "pyproject.toml", "rb") as _handle:
    _project = tomllib.load(_handle)["project"]
# Every result but the report, archived before the report so that the report can print its SHA-256.
RESULTS_ARCHIVE = f"results/dist/{_project['name']}-{_project['version']}-results.tar.gz"
# What an archive packs from the checkout for its RO-Crate (the Snakefile, the configuration, the licence, the
# citation, the lock): inputs of the archives, so an edit to one of them rebuilds them.
ARCHIVED_CHECKOUT = [
    os.path.relpath(ROOT / path)
    for path in report_crate.checkout_members(
        ROOT, PurePosixPath(os.path.relpath(workflow.main_snakefile, ROOT))
    )
]


# What the benchmarks measured that the report shows (benchmarks/results/), and the script that measured each,
# copied beside the results: the report links them there, so a results folder copied or unpacked elsewhere
# still holds what it links.
BENCHMARK_DATA = sorted(p for p in (ROOT / "benchmarks/results").glob("*") if p.is_file())
BENCHMARK_SCRIPTS = sorted(
    {ROOT / "benchmarks" / f"{p.stem}.py" for p in BENCHMARK_DATA} & set((ROOT / "benchmarks").glob("*.py"))
)


localrules:
    measured,


rule measured:
    input:
        data=BENCHMARK_DATA,
        scripts=BENCHMARK_SCRIPTS,
    output:
        directory("results/measured"),
    log:
        "results/logs/measured.log",
    conda:
        "../envs/pipeline.yaml"
    shell:
        "(mkdir -p {output:q} && cp {input.data:q} {input.scripts:q} {output:q}/) > {log:q} 2>&1"


rule results_archive:
    input:
        every_result(),
        rules.measured.output,
        snakefile=ARCHIVED_CHECKOUT[0],  # the crate's workflow, the Snakefile that ran
        checkout=ARCHIVED_CHECKOUT[1:],
    output:
        archive=RESULTS_ARCHIVE,
        sums=RESULTS_ARCHIVE.removesuffix(".tar.gz") + ".SHA256SUMS",
    threads: 1
    resources:
        **measured_resources("results_archive"),
    params:
        code=job_code("report.dist"),
    log:
        "results/logs/results_archive.log",
    conda:
        "../envs/pipeline.yaml"
    benchmark:
        "results/benchmarks/results_archive.tsv"
    shell:
        "python3 -m classical_dynamics.jobserver"
        " classical_dynamics.report.dist results {output.archive:q} --snakefile {input.snakefile:q} > {log:q} 2>&1"


rule report_html:
    input:
        results=every_result(),
        archive=RESULTS_ARCHIVE,
        templates=[here(path) for path in report_assets.asset_files()],
        measured=rules.measured.output,     # its appendix's measured figure, and what it links
    # update(): Snakemake keeps the last good report while this one renders and restores it if the render fails
    # (it would otherwise delete it when the job starts); the job writes the new one atomically.
    output:
        update("results/report.html"),
    params:
        quick=QUICK,
        root=ROOT,
        code=job_code("report.build"),
    threads: 1
    resources:
        **measured_resources("report_html"),
    log:
        "results/logs/report_html.log",
    conda:
        "../envs/pipeline.yaml"
    benchmark:
        "results/benchmarks/report_html.tsv"
    # --cache: the equations and compiled templates of this code, kept between runs (Snakemake's folder)
    shell:
        "python3 -m classical_dynamics.jobserver"
        " classical_dynamics.report.build results {output:q} --root {params.root:q} {params.quick}"
        " --cache .snakemake/report-cache/{params.code} 2>&1 | tee {log:q}"


rule report_pdf:
    input:
        "results/report.html",
    output:
        update("results/report.pdf"),
    params:
        code=job_code("report.pdf"),
    threads: 1
    resources:
        **measured_resources("report_pdf"),
    log:
        "results/logs/report_pdf.log",
    conda:
        "../envs/pipeline.yaml"
    benchmark:
        "results/benchmarks/report_pdf.tsv"
    shell:
        "python3 -m classical_dynamics.jobserver"
        " classical_dynamics.report.pdf {input:q} {output:q} > {log:q} 2>&1"


rule report:
    """The HTML and the PDF."""
    input:
        rules.report_html.output,
        rules.report_pdf.output,
