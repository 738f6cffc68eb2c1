"""Command-line entry points the Snakemake rules call.

  python -m classical_dynamics validate STUDY SCENE...
  python -m classical_dynamics run STUDY SCENE OUT_DIR TIMINGS_DIR [--quick]     (the scene job: scene_job.py)
  python -m classical_dynamics report RESULTS_DIR HTML PDF [--quick]
  python -m classical_dynamics dist RESULTS_DIR ARCHIVE [--snakefile SNAKEFILE]
  python -m classical_dynamics verify ARCHIVE|RESULTS [--scenes STUDY/SCENE,...] [--root .] [--cores N]
  python -m classical_dynamics diff RESULTS_A RESULTS_B      (results folders or dist archives)

Installed, the same commands are `classical-dynamics verify ...`, `classical-dynamics diff ...`.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import scene_job  # first: it sets one BLAS thread per job before numpy is imported
from .scenes import SceneError


def cmd_validate(args) -> int:
    from .scene_job import budget
    from .studies import validate

    for scene in args.scenes:
        validate(args.study, scene, budget(args))
    return 0


def cmd_report(args) -> int:
    from .report.build import main

    status = main([args.results, args.html, "--root", args.root] + (["--quick"] if args.quick else []))
    if status == 0 and args.pdf:
        from .report.pdf import html_to_pdf

        html_to_pdf(Path(args.html), Path(args.pdf))
    return status


def cmd_dist(args) -> int:
    from .report.dist import make_archive

    make_archive(Path(args.results), Path(args.archive), snakefile=args.snakefile and Path(args.snakefile))
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
    scene_job.study_argument(p)
    p.add_argument("scenes", nargs="+")
    scene_job.budget_arguments(p)
    p.set_defaults(func=cmd_validate)
    p = sub.add_parser("run", help="run one scene")
    scene_job.add_arguments(p)
    p.set_defaults(func=scene_job.run)
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
    p.add_argument(
        "--snakefile",
        help="the Snakefile that ran (the crate's workflow; default: found as Snakemake finds it)",
    )
    p.set_defaults(func=cmd_dist)
    p = sub.add_parser(
        "verify",
        help="rebuild the scenes of a dist archive (or a results folder) and compare every number with it; "
        "exit 1 if one moved beyond its tolerance, 2 for a bad archive or folder",
    )
    p.add_argument("archive", metavar="ARCHIVE", help="a dist archive or a results folder")
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


def _guarded(func, args) -> int:
    """func(args), with a user's mistake (a bad scene, archive or result), a full disk and exhausted memory as
    one line."""
    from .io import ResultError, no_space_line
    from .verify import VerifyError

    try:
        return func(args)
    except (SceneError, VerifyError, ResultError) as error:
        print(error, file=sys.stderr)
        return 2
    except OSError as error:
        if (line := no_space_line(error)) is None:
            raise
        print(line, file=sys.stderr)
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
