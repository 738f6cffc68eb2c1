# Shared by every study: scene discovery, and validation of every scene before anything runs. The studies are
# those of classical_dynamics/studies/registry.py. (Rules live in their own files: Snakemake's linter wants them
# apart.) Paths: WORKFLOW (workflow/) and ROOT (the checkout) are set in the Snakefile; results/ and .snakemake/
# are in the working directory.

import atexit
import gc
import os
import sys
import time
from pathlib import Path

import yaml
from snakemake_interface_executor_plugins.settings import ExecMode

from classical_dynamics import code_graph, jobserver
from classical_dynamics.io import stale_reason
from classical_dynamics.limits import rule_resources
from classical_dynamics.report import snakemake_report
from classical_dynamics.scenes import SceneError
from classical_dynamics.scenes.loader import is_leftover
from classical_dynamics.scenes.cost import Budget
from classical_dynamics.scenes.targets import needed_scenes
from classical_dynamics.scenes.validated import validate_all
from classical_dynamics.studies import STUDIES, validate
from classical_dynamics.workflow_config import ConfigError, check_config

# Jobs call `python3` by name, never a path fixed when this file was read (which would fail on a node where the
# path differs, and mark every result stale under another interpreter): the environment Snakemake runs in comes
# first on their PATH, as activating it would. Each job's provenance records the versions it ran with.
jobserver.put_interpreter_first_on_path()
# Snakemake's process and Python's cyclic collector: its objects (the rules, the DAG, a thousand scenes' jobs)
# live for the whole run, so the collector passes over them less often (every 10 000 new objects, not 700: a
# 1000-scene sweep's dry run 1.9 -> 1.6 s), and not at all at the exit (0.4 to 0.6 s after the last job).
gc.set_threshold(10_000, 50, 50)
atexit.register(jobserver.skip_last_collections)
# --config and workflow/config.yaml, checked before anything else: a bad key or value is one line (the key, the
# value, where it came from), never a Python error from inside the workflow.
try:
    FLAGS = check_config(config, WORKFLOW / "config.yaml")
except ConfigError as _error:
    sys.stderr.write(f"{_error}\n")
    sys.exit(1)
QUICK = "--quick" if FLAGS["quick"] else ""
VALIDATED = Path(".snakemake/validated-scenes.json")


SCENES = WORKFLOW / "scenes"


def here(path):
    """A file of the package (a schema, a template) as a path from the working directory, as Snakemake records
    inputs: a checkout moved or copied elsewhere does not look changed."""
    return os.path.relpath(path)


def scenes(study):
    """Every scene file of a study: dropping a YAML file in workflow/scenes/<study>/ adds it."""
    return sorted(p.stem for p in (SCENES / study).glob("*.yaml") if not is_leftover(p))


def scene_outputs(study):
    return expand("results/{study}/{scene}", study=study, scene=scenes(study))


# Steps of a study drawn from its scenes' results (the self-excited gallery): {study: [output folder, ...]}, part
# of the study's target and of the report's inputs.
STUDY_STEPS = {}


def every_result():
    """Every scene of every study, and the steps drawn from them: what the report and the archives read."""
    return [out for study in STUDIES for out in scene_outputs(study) + STUDY_STEPS.get(study, [])]


# A scene's results are checked against what they claim before Snakemake compares file times (io.stale_reason):
# every file against the checksums in its provenance, the scene file's SHA-256 against the one it was built
# from, quick against full. Snakemake alone would miss a figure deleted or a number edited when .snakemake/ is
# absent (results copied or restored) and a scene restored with its old time (cp -p, rsync -a, tar x). Each
# scene has a marker in .snakemake/result-checks/, an input of its job: dated 1970 while its results are whole,
# rewritten now with the reason when they are not, so that every Snakemake command, dry run included, sees an
# input newer than the results and unlike the one it recorded (Snakemake ignores a newer input whose checksum it
# has seen), with or without its records. All are written while the Snakefile is read, before Snakemake lists
# the folder (it caches what a folder holds and each file's time).
RESULT_CHECKS = Path(".snakemake/result-checks")


def check_results():
    for study in STUDIES:
        for scene in scenes(study):
            marker, folder = RESULT_CHECKS / study / scene, Path("results", study, scene)
            reason = stale_reason(folder, SCENES / study / f"{scene}.yaml", bool(QUICK)) if folder.exists() else None
            marker.parent.mkdir(parents=True, exist_ok=True)
            if reason:
                sys.stderr.write(f"note: {reason}: rerunning it\n")
                marker.write_text(f"{reason}\n{time.time_ns()}\n")
            elif not marker.exists() or marker.stat().st_mtime_ns:
                marker.touch()
                os.utime(marker, ns=(0, 0))  # 1970: older than any result (and whole again if put right by hand)


def result_check(wc):
    return (RESULT_CHECKS / wc.study / wc.scene).as_posix()


# What a job's result depends on besides its inputs: the package's modules its command runs (the job server, then
# the entry modules named), found from the package's import graph (classical_dynamics/code_graph.py), never
# listed by hand. A params value: Snakemake's params trigger reruns the job when that code changes. (As inputs,
# the ~50 source files of every scene job cost the DAG 53,000 file checks for a sweep of 1,000 scenes.)
code_graph.cache_parses_in(".snakemake/code-graph.json")


def job_code(*entries):
    """The digest of the modules that `python3 -m classical_dynamics.jobserver <entries[0]> ...` runs."""
    return code_graph.code_digest(*code_graph.job_entries(*entries))


def _command_line():
    """(targets, target jobs, whether it runs jobs) of the Snakemake command that reads this file."""
    from snakemake.cli import get_argument_parser
    try:
        args, _ = get_argument_parser().parse_known_args(sys.argv[1:])
    except BaseException:                   # not the snakemake command line (the API, a test): assume everything
        return [], [], True
    runs = not (args.unlock or args.cleanup_metadata or args.list_rules or args.list_target_rules)
    return list(args.targets or []), list(args.target_jobs or []), runs


# Validate the scenes this command needs before any job is scheduled: a bad scene stops the build with one line
# (file, field, expectation) and nothing under results/ is touched; one that this command does not need (a broken
# precession scene under `snakemake chains`) gets a one-line note. A scene valid with its present bytes, schema,
# code and budget is not validated again (scenes/validated.py). `--unlock` runs no job and validates nothing.
ESTIMATES = {}
_targets, _target_jobs, _runs = _command_line()
_needed = needed_scenes(_targets, _target_jobs, {study: set(scenes(study)) for study in STUDIES})
try:
    BUDGET = Budget.from_config(config.get("budget"))
    if _runs:
        ESTIMATES, _unneeded = validate_all(
            [(_study, _scene, STUDIES[_study].schema)
             for _study in STUDIES for _scene in sorted((SCENES / _study).glob("*"))
             if not is_leftover(_scene)],     # an editor's swap or backup file
            validate, VALIDATED, BUDGET, optional=lambda study, scene: not _needed(study, scene.stem))
        for _error in _unneeded:
            sys.stderr.write(f"note: not needed by this command, and not valid either: {_error}\n")
        check_results()
except SceneError as _error:
    sys.stderr.write(f"{_error}\n")
    sys.exit(1)
except Exception as _error:        # a fault of ours, not the user's; still one line
    sys.stderr.write(f"a scene could not be validated ({type(_error).__name__}: {_error})\n")
    sys.exit(1)


# A job validates its scene again (as a hand-typed command would) under this run's budget, --config included
BUDGET_ARGS = f"--budget-seconds {BUDGET.seconds!r} --budget-memory-mb {BUDGET.memory_mb!r}"


def limits(wc):
    """The job's Estimate (scenes/cost.py), from which its time and memory limits follow."""
    return ESTIMATES[(SCENES / wc.study / f"{wc.scene}.yaml").as_posix()]


# A scene estimated under this many seconds is light: on a cluster, light scenes run in batches (a group; the
# slurm profile says how many to a batch), since the scheduler's few seconds a job would outweigh them.
LIGHT_SCENE_S = 30
LIGHT_SCENES = "light_scenes"

# The jobs that are not scenes ask for memory and time from their measured peaks, with room to spare.
MEASURED = yaml.safe_load((WORKFLOW / "resources.yaml").read_text())["rules"]


def measured_resources(rule):
    """mem_mb and runtime (minutes) over the measured peak of a job that is not a scene."""
    return rule_resources(MEASURED[rule])


# Local jobs run as forked children of one warm process that has imported numpy, scipy, matplotlib, numba and the
# solvers once (classical_dynamics/jobserver.py): about 1.3 s less a job, for 2.6 s of imports once, so it is
# started for four jobs or more. Jobs of a cluster run start their own interpreter, as do jobs in an environment
# of their own (--use-conda) and all jobs with `--config jobserver=0` (so that Snakemake's benchmark files
# measure each job's own memory).
onstart:
    served = sum("classical_dynamics.jobserver" in (job.rule.shellcmd or "") for job in workflow.dag.needrun_jobs())
    wanted = FLAGS["jobserver"] and not workflow.deployment_settings.deployment_method
    if wanted and workflow.local_exec and workflow.exec_mode == ExecMode.DEFAULT and served >= 4:
        jobserver.start()


onsuccess:
    jobserver.stop()


onerror:
    jobserver.stop()
