# A step of the self-excited study drawn from its scenes: the gallery redraws the portraits as grids.

from classical_dynamics.studies.self_excited.gallery import portrait_scenes

GALLERY_SCENES = [s for s in scenes("self_excited") if s in portrait_scenes()]


rule self_excited_gallery:
    """The study's phase portraits as small-multiple grids, grouped as Lee groups his figures (no integration:
    it redraws each portrait scene's saved table)."""
    input:
        scenes=expand("results/self_excited/{scene}", scene=GALLERY_SCENES),
    output:
        results=report(
            directory("results/self_excited/gallery"),
            caption="../report/result.rst",
            category=snakemake_report.category("results", study="self_excited"),
            subcategory="gallery",
            patterns=snakemake_report.PATTERNS,
        ),
        timings=report(
            directory("results/self_excited/timings/gallery"),
            caption="../report/timing.rst",
            category=snakemake_report.category("timings", study="self_excited"),
            subcategory="gallery",
            patterns=snakemake_report.PATTERNS,
        ),
    params:
        quick=QUICK,
        code=job_code("studies.self_excited.gallery"),
    threads: 1
    resources:
        **measured_resources("self_excited_gallery"),
    log:
        "results/logs/self_excited/gallery.log",
    conda:
        "../envs/pipeline.yaml"
    benchmark:
        "results/benchmarks/self_excited_gallery.tsv"
    shell:
        "python3 -m classical_dynamics.jobserver"
        " classical_dynamics.studies.self_excited.gallery results/self_excited"
        " {output.results:q} {output.timings:q} {input.scenes:q} {params.quick} > {log:q} 2>&1"


# results/self_excited/gallery is no scene (there is no gallery.yaml): this rule makes it, not the scene rule.
ruleorder: self_excited_gallery > scene


STUDY_STEPS["self_excited"] = [rules.self_excited_gallery.output.results]
