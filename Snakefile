# A reproducible report on classical rigid-body dynamics and vibrations.
# This file is the report's table of contents: one include per study, in report order.
#
#   snakemake -c all                 everything: every scene of every study, then the report
#   snakemake -c all chains          one study (its scenes only); also: precession, chandler, self_excited, solvers
#   snakemake -c all report          the HTML and PDF report
#   snakemake -c1 dist               a citable archive with SHA256SUMS
#   snakemake -c1 verify             rebuild that archive with this checkout, compare every number
#   snakemake -c all --config quick=1    a reduced build (what the tests run)

configfile: "workflow/config.yaml"


include: "workflow/rules/common.smk"
include: "workflow/rules/scenes.smk"
# Precession of the equinoxes: Lamb's secular formula, the averaged axis, the spin-resolved Earth
include: "workflow/rules/precession.smk"
# The Chandler wobble: Euler's rigid Earth, Lamb's elastic Earth, damping, excitation, the IERS data
include: "workflow/rules/chandler.smk"
# Vibrations of chains: the hanging chain, discrete chains, strings, springs, rotating chains
include: "workflow/rules/chains.smk"
# The self-excited rigid body (Lee 1964): phase planes under a body-fixed torque
include: "workflow/rules/self_excited.smk"
# The solver layer: what accuracy costs, against scipy's solve_ivp
include: "workflow/rules/solvers.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/dist.smk"


rule all:
    default_target: True
    input:
        rules.report_html.output,
        rules.report_pdf.output,
