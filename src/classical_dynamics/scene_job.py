"""The job that runs one scene: validate it, run its study, write its results, provenance and timings.

  python -m classical_dynamics.scene_job STUDY SCENE OUT_DIR TIMINGS_DIR [--quick] [limits] [budget]
  (also `python -m classical_dynamics run ...`)

A module of its own, apart from the command line's other commands, so that what a scene's result depends on is
what this module and its study import (code_graph.py), not the report's or verify's code.
"""

from __future__ import annotations

import os

# One BLAS thread per job: Snakemake runs jobs side by side, and results stay bit-reproducible.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from datetime import datetime, timezone  # noqa: E402
from pathlib import Path  # noqa: E402

from .scenes import SceneError  # noqa: E402


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="seconds")


def budget_arguments(parser) -> None:
    parser.add_argument(
        "--budget-seconds", type=float, help="the most a scene may cost (default: workflow/config.yaml)"
    )
    parser.add_argument("--budget-memory-mb", type=float)


def study_argument(parser) -> None:
    from .studies.registry import STUDIES  # data only: no study's code is imported

    parser.add_argument("study", choices=sorted(STUDIES), help="the study the scenes belong to")


def add_arguments(parser) -> None:
    study_argument(parser)
    parser.add_argument("scene")
    parser.add_argument("out_dir")
    parser.add_argument("timings_dir")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--time-limit-min", type=float, help="stop the job past this wall time, minutes")
    parser.add_argument("--memory-limit-mb", type=float, help="stop the job past this resident memory")
    budget_arguments(parser)


def budget(args):
    """The budget the command line gives (a Snakemake job passes its run's), else workflow/config.yaml's."""
    from .scenes.cost import Budget

    if args.budget_seconds is None and args.budget_memory_mb is None:
        return Budget.from_file()
    return Budget.from_config(
        {
            key: value
            for key, value in (("seconds", args.budget_seconds), ("memory_mb", args.budget_memory_mb))
            if value is not None
        }
    )


def run(args) -> int:
    """Run the scene, under the limits the command line gives (a limited job runs in a child process)."""
    if args.time_limit_min or args.memory_limit_mb:
        from .limits import run_limited

        return run_limited(
            lambda: guarded(_run, args),
            args.scene,
            60 * (args.time_limit_min or float("inf")),
            args.memory_limit_mb or float("inf"),
        )
    return guarded(_run, args)


def guarded(func, args) -> int:
    """func(args), with a user's mistake (a bad scene or result), a full disk and exhausted memory as one
    line."""
    from .io import ResultError, no_space_line

    try:
        return func(args)
    except (SceneError, ResultError) as error:
        print(error, file=sys.stderr)
        return 2
    except OSError as error:
        if (line := no_space_line(error)) is None:
            raise
        print(line, file=sys.stderr)
        return 2
    except MemoryError:
        print(f"{args.scene}: stopped: out of memory (see budget: in workflow/config.yaml)", file=sys.stderr)
        return 3


def _git_state(args) -> dict:
    """The commit, and whether this result's own inputs (its scene, and the code its rule's digest covers)
    differ from it."""
    from . import code_graph, provenance

    return provenance.git_state_of(code_graph.scene_job_entries(args.study), Path(args.scene))


def _run(args) -> int:
    import hashlib
    import resource

    from . import provenance
    from .studies import study_module, validate

    scene_bytes = Path(args.scene).read_bytes()
    scene = validate(args.study, args.scene, budget(args))  # nothing is computed before this passes
    if hashlib.sha256(scene_bytes).hexdigest() != scene.sha256:
        raise SceneError(args.scene, "(file)", "a file that stays the same while it is read", "it changed")
    module = study_module(args.study)
    started, wall0, cpu0 = _now(), time.perf_counter(), time.process_time()
    results = module.run(scene, quick=args.quick)
    wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    record = {
        "study": args.study,
        "scene": scene.name,
        "scene_file": str(args.scene),
        "scene_sha256": scene.sha256,
        "effects_simulated": sorted(scene.effects),
        # what each listed effect is, from the study's registry (the report's table of effects reads it here)
        "effects_registry": {
            name: {"kind": module.EFFECTS[name].kind, "summary": module.EFFECTS[name].summary}
            for name in sorted(scene.effects)
        },
        "quick": bool(args.quick),
        **_git_state(args),
        "packages": provenance.package_versions(),
        "machine": provenance.machine(),
        "started": started,
        "finished": _now(),
        "wall_seconds": round(wall, 3),
        "cpu_seconds": round(cpu, 3),
    }
    timing = {
        "study": args.study,
        "scene": scene.name,
        "wall_seconds": wall,
        "cpu_seconds": cpu,
        "max_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
        "estimated_seconds": scene.estimate.seconds,
        "estimated_memory_mb": scene.estimate.memory_mb,
        "started": started,
        "cpu_model": record["machine"]["cpu_model"],
        "cores": record["machine"]["cores"],
    }
    results.write(Path(args.out_dir), Path(args.timings_dir), record, timing, {"scene.yaml": scene_bytes})
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m classical_dynamics.scene_job", description=__doc__)
    add_arguments(parser)
    return run(parser.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
