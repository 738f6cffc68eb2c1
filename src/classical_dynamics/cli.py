"""Command-line entry points the Snakemake rules call.

  python -m classical_dynamics validate STUDY SCENE...
  python -m classical_dynamics run STUDY SCENE OUT_DIR TIMINGS_DIR [--quick]
  python -m classical_dynamics report RESULTS_DIR HTML PDF [--quick]
  python -m classical_dynamics dist RESULTS_DIR ARCHIVE
  python -m classical_dynamics verify ARCHIVE [--scenes STUDY/SCENE,...] [--root .] [--cores N]
  python -m classical_dynamics diff RESULTS_A RESULTS_B      (results folders or dist archives)

Installed, the same commands are `classical-dynamics verify ...`, `classical-dynamics diff ...`.
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


def _budget(args):
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


def cmd_validate(args) -> int:
    from .studies import validate

    for scene in args.scenes:
        validate(args.study, scene, _budget(args))
    return 0


def cmd_run(args) -> int:
    if args.time_limit_min or args.memory_limit_mb:
        from .limits import run_limited

        return run_limited(
            lambda: _guarded(_run, args),
            args.scene,
            60 * (args.time_limit_min or float("inf")),
            args.memory_limit_mb or float("inf"),
        )
    return _run(args)


def _run(args) -> int:
    import resource

    from . import provenance
    from .studies import study_module, validate

    scene = validate(args.study, args.scene, _budget(args))  # nothing is computed before this passes
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
        "quick": bool(args.quick),
        **provenance.git_state(),
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
    results.write(Path(args.out_dir), Path(args.timings_dir), record, timing)
    return 0


def cmd_report(args) -> int:
    from .report.build import build_report
    from .report.claims import ClaimFailure
    from .report.ledger import LedgerError

    try:
        build_report(
            Path(args.results),
            Path(args.html),
            Path(args.pdf) if args.pdf else None,
            quick=args.quick,
            root=Path(args.root),
        )
    except (ClaimFailure, LedgerError) as error:  # what the report's data say is wrong: no traceback
        print(f"report: {error}", file=sys.stderr)
        return 1
    return 0


def cmd_dist(args) -> int:
    from .report.dist import make_archive

    make_archive(Path(args.results), Path(args.archive))
    return 0


def cmd_verify(args) -> int:
    from .verify import verify

    return verify(Path(args.archive), Path(args.root), args.scenes, args.quick, args.cores)


def cmd_diff(args) -> int:
    from .verify import diff

    return diff(Path(args.a), Path(args.b))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="classical_dynamics")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("validate", help="validate scene files; one line per problem")
    p.add_argument("study")
    p.add_argument("scenes", nargs="+")
    _budget_arguments(p)
    p.set_defaults(func=cmd_validate)
    p = sub.add_parser("run", help="run one scene")
    p.add_argument("study")
    p.add_argument("scene")
    p.add_argument("out_dir")
    p.add_argument("timings_dir")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--time-limit-min", type=float, help="stop the job past this wall time, minutes")
    p.add_argument("--memory-limit-mb", type=float, help="stop the job past this resident memory")
    _budget_arguments(p)
    p.set_defaults(func=cmd_run)
    p = sub.add_parser("report", help="render the HTML and PDF report from results/")
    p.add_argument("results")
    p.add_argument("html")
    p.add_argument("pdf", nargs="?")
    p.add_argument("--root", default=".")
    p.add_argument("--quick", action="store_true")
    p.set_defaults(func=cmd_report)
    p = sub.add_parser("dist", help="a citable archive with SHA256SUMS")
    p.add_argument("results")
    p.add_argument("archive")
    p.set_defaults(func=cmd_dist)
    p = sub.add_parser(
        "verify",
        help="rebuild a dist archive's scenes and compare every number with it; "
        "exit 1 if one moved beyond its tolerance, 2 for a bad archive",
    )
    p.add_argument("archive")
    p.add_argument("--scenes", help="only these: study/scene or study, comma-separated")
    p.add_argument("--root", default=".", help="the checkout whose code and scene files rebuild it")
    p.add_argument("--cores", type=int, default=1, help="scenes rebuilt side by side")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument(
        "--quick",
        action="store_const",
        const=True,
        default=None,
        help="rebuild as a quick build (default: as each scene's provenance says)",
    )
    mode.add_argument("--full", action="store_const", const=False, dest="quick")
    p.set_defaults(func=cmd_verify)
    p = sub.add_parser("diff", help="every number that changed between two builds; exit 1 if any")
    p.add_argument("a", metavar="RESULTS_A", help="a results folder or a dist archive")
    p.add_argument("b", metavar="RESULTS_B")
    p.set_defaults(func=cmd_diff)
    args = parser.parse_args(argv)
    return _guarded(args.func, args)


def _budget_arguments(parser) -> None:
    parser.add_argument(
        "--budget-seconds", type=float, help="the most a scene may cost (default: workflow/config.yaml)"
    )
    parser.add_argument("--budget-memory-mb", type=float)


def _guarded(func, args) -> int:
    """func(args), with a user's mistake (a bad scene, archive or result) and exhausted memory as one line."""
    from .io import ResultError
    from .verify import VerifyError

    try:
        return func(args)
    except (SceneError, VerifyError, ResultError) as error:
        print(error, file=sys.stderr)
        return 2
    except MemoryError:
        print(
            f"{getattr(args, 'scene', args.command)}: stopped: out of memory (see budget: in "
            "workflow/config.yaml)",
            file=sys.stderr,
        )
        return 3


if __name__ == "__main__":
    sys.exit(main())
