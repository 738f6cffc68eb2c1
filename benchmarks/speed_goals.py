"""Issue 37's goals, each measured in one run and printed beside its goal (printed, not asserted).

This commit and the baseline 997fc6d (the issue's "today") are checked out as git worktrees in a temporary
folder (the working tree is untouched) and measured one after the other with the same interpreter and
packages.
On a noisy machine the ratios hold better than the seconds; a goal stated in seconds is printed beside the
baseline's seconds in the same run.

1. The PDF: the same report.html (this commit's full build) rendered by each commit's PDF job, alternately,
   each in a process of its own; the CPU seconds of the process (minimum of --repeats); goal baseline / this
   >= 3.5. The two PDFs are then compared as page images at 100 dpi.
2. The edit loop: a light chains scene's title edited in a fully built tree, `snakemake results/report.html`
   (seconds to the HTML, goal <= 5), then `snakemake` (the PDF; the loop's whole seconds, goal <= 15); the
   minimum of two edits.
3. The full build from clean on two cores, against its floor read from the same build's benchmark files
   (Snakemake's wall seconds of each job): the larger of the other jobs' summed seconds / cores and the
   longest of them, plus the serial report chain (archive, HTML, PDF); goal <= 1.15. (A fresh machine's
   `make report`, goal <= 3 min, needs a fresh machine: CI's log gives it.)
4. A 1000-scene sweep of new chain scenes in the built tree: the first dry run (every new scene validated)
   and the next against Snakemake's floor for as many jobs, as many of them pending; goals <= 2 and <= 1.5.
5. The test suite as `make test` runs it (`python -m pytest`), goal <= 180 s; the suite's shared quick build
   (`snakemake -c 2 --config quick=1` in a clean copy), goal <= 40 s.
6. The compiled integrators on the HNW rigid body (benchmarks/solver_speed.py, this commit): the specialized
   dop853 through solve() against the hand-written adaptive loop at the same tolerance, goal <= 1.3;
   solve_ivp's DOP853 against it, goal >= 200.

    python benchmarks/speed_goals.py [--baseline 997fc6d] [--only pdf,loop,build,sweep,tests,solvers]
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))
from pdf_render import compare_pages, pages  # noqa: E402
from pipeline_build import add_sweep, floor, jobs_of, restore, snakemake, worktree  # noqa: E402

from tests.conftest import copy_repository, run_env  # noqa: E402

PARTS = ("pdf", "loop", "build", "sweep", "tests", "solvers")
EDITED = "workflow/scenes/chains/two_masses_three_springs.yaml"
REPORT_RULES = ("results_archive", "report_html", "report_pdf")


def suite_seconds(tree: Path) -> float:
    """`python -m pytest` in the tree, as `make test` runs it: its seconds, a failure printed, not raised."""
    start = time.perf_counter()
    command = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"]
    done = subprocess.run(command, cwd=tree, env=run_env(tree), capture_output=True, text=True)
    if done.returncode:
        print(f"  the test suite failed ({done.returncode}):\n{done.stdout[-2000:]}", flush=True)
    return time.perf_counter() - start


def full_build(tree: Path) -> dict:
    """Seconds of the full build from clean and of its floor, from the build's own benchmark files."""
    seconds = snakemake(tree, "-c", "2")
    jobs = {}
    for path in (tree / "results/benchmarks").rglob("*.tsv"):
        with path.open() as handle:
            jobs[path.relative_to(tree / "results/benchmarks").with_suffix("").as_posix()] = float(
                next(csv.DictReader(handle, delimiter="\t"))["s"]
            )
    chain = sum(jobs.pop(rule) for rule in REPORT_RULES)
    work = max(sum(jobs.values()) / 2, max(jobs.values()))
    return {"build": seconds, "floor": work + chain, "jobs": len(jobs) + len(REPORT_RULES)}


def edit_loop(tree: Path, edits: int = 2) -> tuple[float, float]:
    """(seconds to the HTML, seconds to the PDF) after one scene's title is edited: minima of `edits`."""
    scene = tree / EDITED
    original = scene.read_text()
    to_html, to_pdf = [], []
    try:
        for i in range(edits):
            scene.write_text(
                re.sub(r"^title: (.*)$", rf"title: \1 (edit {i})", original, count=1, flags=re.M)
            )
            to_html.append(snakemake(tree, "results/report.html", "-c", "2"))
            to_pdf.append(to_html[-1] + snakemake(tree, "-c", "2"))
    finally:
        scene.write_text(original)
    snakemake(tree, "-c", "2")  # back to the committed scene's report
    return min(to_html), min(to_pdf)


PDF_CHILD = """
import resource, sys
from pathlib import Path
from classical_dynamics.report import pdf
pdf.html_to_pdf(Path(sys.argv[1]), Path(sys.argv[2]))
usage = resource.getrusage(resource.RUSAGE_SELF)
print(usage.ru_utime + usage.ru_stime)
"""


def pdf_seconds(tree: Path, html: Path, out: Path) -> float:
    """CPU seconds of `tree`'s PDF job on `html` (its own process: imports and fonts included)."""
    result = subprocess.run(
        [sys.executable, "-c", PDF_CHILD, str(html), str(out)],
        cwd=tree,
        env=run_env(tree),
        check=True,
        capture_output=True,
        text=True,
    )
    return float(result.stdout.split()[-1])


def pdf_goal(trees: dict, repeats: int, scratch: Path) -> dict:
    html = trees["this"] / "results/report.html"
    out = {label: html.parent / f".speed_goals_{label}.pdf" for label in trees}
    cpu = {label: [] for label in trees}
    try:
        for _ in range(repeats):
            for label, tree in trees.items():
                cpu[label].append(pdf_seconds(tree, html, out[label]))
        shown = {label: pages(out[label], scratch / f"pages-{label}") for label in trees}
    finally:
        for path in out.values():
            path.unlink(missing_ok=True)
    base, this = shown["baseline"], shown["this"]
    differing = compare_pages(base, this)[0] if len(base) == len(this) else None
    return {
        "baseline": min(cpu["baseline"]),
        "this": min(cpu["this"]),
        "pages": len(this),
        "differing": differing,
    }


def quick_build(tree: Path, scratch: Path) -> float:
    """The test suite's shared build: a copy of the tree with its compiled code, as conftest copies the
    checkout (warm), built by `snakemake -c 2 --config quick=1`."""
    copy = copy_repository(scratch / f"quick-{tree.name}", tree)
    try:
        return snakemake(copy, "-c", "2", "--config", "quick=1")
    finally:
        shutil.rmtree(copy, ignore_errors=True)


def sweep(tree: Path, scratch: Path, count: int = 1000) -> tuple[float, float, float]:
    """(first dry run, next dry run, Snakemake's floor) in seconds, with `count` new scenes: the floor is a
    dry run of a Snakefile with as many jobs, as many of them pending (the new scenes and the report's four
    jobs, as benchmarks/pipeline_scaling.py counts them). A dry run first, before the sweep: in a tree not
    built yet the first parse pays once for the checkout itself (its import graph, its own scenes)."""
    snakemake(tree, "-n")
    add_sweep(tree, count)
    try:
        first = snakemake(tree, "-n")
        again = min(snakemake(tree, "-n") for _ in range(2))
        jobs = jobs_of(tree, [])
    finally:
        restore(tree)
    return first, again, floor(jobs, scratch / "floor", pending=count + 4)


def solvers(rounds: int = 3) -> tuple[float, float]:
    """(specialized dop853 / hand-written loop, solve_ivp DOP853 / specialized dop853) in this process: each
    the minimum of `rounds` measurements taken in turn (solver_speed's own minima over repeated calls)."""
    import solver_speed

    times: dict[str, list[float]] = {"ours": [], "hand": [], "scipy": []}
    for _ in range(rounds):
        fastest = solver_speed.fastest_adaptive()
        _, rtol, ours, _ = fastest["dop853, specialized"]
        times["ours"].append(ours)
        times["scipy"].append(fastest["scipy:DOP853"][2])
        times["hand"].append(solver_speed.hand_written_adaptive(rtol)[0])
    best = {key: min(values) for key, values in times.items()}
    print("  " + ", ".join(f"{key} {seconds * 1e6:.1f} us" for key, seconds in best.items()), flush=True)
    return best["ours"] / best["hand"], best["scipy"] / best["ours"]


class Measured(dict):
    """The measurements, each printed as it is taken (a later failure loses none of them)."""

    def __setitem__(self, key, value):
        print(f"  measured {key}: {value}", flush=True)
        super().__setitem__(key, value)


def row(name: str, baseline, this, value: float, goal: str, holds: bool) -> None:
    show = lambda v: "" if v is None else f"{v:10.2f}"  # noqa: E731
    verdict = "yes" if holds else "NO"
    print(f"{name:46s}{show(baseline):>10s}{show(this):>10s}{value:10.2f}  {goal:10s} {verdict}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", default="997fc6d", help="the issue's 'today' (default 997fc6d)")
    parser.add_argument("--only", default=",".join(PARTS), help=f"a comma-separated subset of {PARTS}")
    parser.add_argument("--repeats", type=int, default=2, help="PDF renders of each commit")
    args = parser.parse_args()
    only = set(args.only.split(","))
    if only - set(PARTS):
        parser.error(f"unknown parts {only - set(PARTS)}; known: {PARTS}")
    measured = Measured()
    with tempfile.TemporaryDirectory() as tmp:
        scratch = Path(tmp)
        trees = {}
        try:
            for label, rev in (("baseline", args.baseline), ("this", "HEAD")):
                trees[label] = worktree(rev, scratch / label)
            if only & {"pdf", "loop", "build"}:
                for label, tree in trees.items():
                    print(f"building {label} from clean ...", flush=True)
                    measured[("build", label)] = full_build(tree)
                    if "loop" in only:
                        measured[("loop", label)] = edit_loop(tree)
                if "pdf" in only:
                    print("rendering the PDF with each commit's job ...", flush=True)
                    measured["pdf"] = pdf_goal(trees, args.repeats, scratch)
            if "sweep" in only:
                if ("build", "this") not in measured:  # the floor has the built tree's pending jobs only
                    print("building this from clean ...", flush=True)
                    full_build(trees["this"])
                print("dry runs with a 1000-scene sweep ...", flush=True)
                measured["sweep"] = sweep(trees["this"], scratch)
            if "tests" in only:
                print("the quick build and the test suite ...", flush=True)
                measured["quick"] = {label: quick_build(tree, scratch) for label, tree in trees.items()}
                measured["tests"] = suite_seconds(trees["this"])
            if "solvers" in only:
                print("the integrators ...", flush=True)
                measured["solvers"] = solvers()
        finally:
            for tree in trees.values():
                subprocess.run(
                    ["git", "worktree", "remove", "--force", str(tree)], cwd=ROOT, capture_output=True
                )
    print(f"\nIssue 37's goals: {args.baseline} (baseline) beside this commit, {os.cpu_count()} cores")
    print(f"{'':46s}{'baseline':>10s}{'this':>10s}{'measure':>10s}  {'goal':10s} holds")
    if "pdf" in measured:
        p = measured["pdf"]
        ratio = p["baseline"] / p["this"]
        row(
            "1. PDF, CPU s (measure: baseline / this)",
            p["baseline"],
            p["this"],
            ratio,
            ">= 3.5 x",
            ratio >= 3.5,
        )
        same = (
            "page count differs"
            if p["differing"] is None
            else f"{len(p['differing'])} of {p['pages']} differ"
        )
        print(f"{'':4s}the two PDFs as page images at 100 dpi: {same}")
    if ("loop", "this") in measured:
        (bh, bp), (th, tp) = measured[("loop", "baseline")], measured[("loop", "this")]
        row("2. edit loop: to the HTML (s)", bh, th, th, "<= 5 s", th <= 5)
        row("   edit loop: to the PDF (s)", bp, tp, tp, "<= 15 s", tp <= 15)
    if ("build", "this") in measured:
        b, t = measured[("build", "baseline")], measured[("build", "this")]
        ratio = t["build"] / t["floor"]
        row(
            "3. full build (s; measure: / its floor)",
            b["build"],
            t["build"],
            ratio,
            "<= 1.15 x",
            ratio <= 1.15,
        )
        row("   its floor (s)", b["floor"], t["floor"], t["floor"], "", True)
    if "sweep" in measured:
        first, again, snakemake_floor = measured["sweep"]
        first, again = first / snakemake_floor, again / snakemake_floor
        row("4. 1000-scene sweep: first dry run / floor", None, None, first, "<= 2 x", first <= 2)
        row("   next dry run / floor", None, None, again, "<= 1.5 x", again <= 1.5)
    if "tests" in measured:
        q = measured["quick"]
        row(
            "5. test suite (s)",
            None,
            measured["tests"],
            measured["tests"],
            "<= 180 s",
            measured["tests"] <= 180,
        )
        row("   its shared quick build (s)", q["baseline"], q["this"], q["this"], "<= 40 s", q["this"] <= 40)
    if "solvers" in measured:
        hand, scipy = measured["solvers"]
        row("6. dop853 / hand-written loop", None, None, hand, "<= 1.3 x", hand <= 1.3)
        row("   solve_ivp DOP853 / dop853", None, None, scipy, ">= 200 x", scipy >= 200)
    print(json.dumps({str(k): v for k, v in measured.items()}, default=str))
    return 0


if __name__ == "__main__":
    sys.exit(main())
