# A reproducible report on classical rigid-body dynamics and vibrations.
#
#   snakemake -c all                 everything: every scene of every study, then the report
#   snakemake -c all chains          one study (its scenes only); also: precession, chandler, self_excited, solvers
#   snakemake -c all report          the HTML and PDF report
#   snakemake -c1 dist               a citable archive with SHA256SUMS
#   snakemake -c1 verify             rebuild that archive with this checkout, compare every number
#   snakemake --report results/snakemake-report.zip   Snakemake's own report: every figure and table, captioned
#   snakemake -c all --config quick=1    a reduced build (what the tests run)
#   snakemake --profile profiles/slurm               all of it on a Slurm cluster
#
# Run from the repository's root, Snakemake finds this file and its default profile (profiles/default). From
# elsewhere: snakemake -s path/to/Snakefile -d somewhere: results/ and .snakemake/ are made in the working
# directory (-d), everything else is read from the checkout. The rules are in workflow/rules/, the scenes in
# workflow/scenes/<study>/; the studies, in report order, are those of src/classical_dynamics/studies/registry.py.

import os
from pathlib import Path

# The checkout and its workflow folder, as paths from the working directory ("." and "workflow" from the root,
# as every scene's provenance records them)
ROOT = Path(os.path.relpath(workflow.basedir))
WORKFLOW = ROOT / "workflow"


configfile: WORKFLOW / "config.yaml"


# What `snakemake --report` says first; its figures and tables are flagged with report() where they are made
# (workflow/rules/scenes.smk, workflow/rules/self_excited_gallery.smk), the report itself below (rule all).
report: "workflow/report/workflow.rst"


include: "workflow/rules/common.smk"
include: "workflow/rules/scenes.smk"
include: "workflow/rules/self_excited_gallery.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/dist.smk"


rule all:
    default_target: True
    input:
        report(
            str(rules.report_html.output[0]),
            caption="workflow/report/report.rst",
            category=snakemake_report.REPORT,
            subcategory="report",
        ),
        report(
            str(rules.report_pdf.output[0]),
            caption="workflow/report/report.rst",
            category=snakemake_report.REPORT,
            subcategory="report",
        ),
        # the benchmarks' figures the report shows (already an input of the report)
        report(
            str(rules.measured.output[0]),
            caption="workflow/report/measured.rst",
            category=snakemake_report.REPORT,
            subcategory="measured",
            patterns=[r"{file,[^/]+\.svg}"],
        ),


# One target per study (`snakemake -c all chains`): its scenes and the steps drawn from them.
for _study in STUDIES:

    rule:
        name:
            _study
        input:
            scene_outputs(_study),
            STUDY_STEPS.get(_study, []),
