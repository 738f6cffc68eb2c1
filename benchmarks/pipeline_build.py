"""Build and test times of this commit beside a baseline commit, measured in one run (issue 21).

Both commits are checked out as git worktrees in a temporary folder (the working tree is untouched) and
measured one after the other with the same interpreter and packages. Absolute times drift with the machine's
load; the ratios between the two columns, taken minutes apart, are what to read. Prints; asserts nothing.

    python benchmarks/pipeline_build.py [--baseline b99490e] [--quick] [--sweep 1000] [--no-tests]

Rows: the full build from clean (Snakemake's own log gives its elapsed time), its longest job; a no-op dry run
beside Snakemake's floor (a Snakefile with as many jobs and no work); one job's overhead (the interpreter and
its imports, or the job server's fork: the job's wall time less the same work in a warm process); the rebuild
after editing one scene; a dry run with a generated sweep of scenes added, beside the floor for as many jobs;
and the test suite (`python -m pytest`, as `make test` runs it).
"""

from __future__ import annotations

import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
sys.path.insert(0, str(ROOT))
from tests.conftest import run_env as env_for  # noqa: E402  (each tree runs its own package)


def timed(tree: Path, *command: str) -> float:
    start = time.perf_counter()
    subprocess.run(command, cwd=tree, env=env_for(tree), check=True, capture_output=True)
    return time.perf_counter() - start


def snakemake(tree: Path, *args: str) -> float:
    return timed(tree, str(BIN / "snakemake"), *args)


def floor(jobs: int, folder: Path, pending: int = 0) -> float:
    """A dry run of a Snakefile with `jobs` jobs that do no work, `pending` of them not yet run: what
    Snakemake itself costs for as many jobs (min of 3)."""
    folder.mkdir(parents=True)
    (folder / "Snakefile").write_text(
        f"N = {jobs}\n"
        "rule all:\n    input: expand('out/{i}', i=range(N))\n"
        "rule one:\n    output: 'out/{i}'\n    shell: 'touch {output}'\n"
    )
    subprocess.run([str(BIN / "snakemake"), "-c", "1", "-q"], cwd=folder, check=True, capture_output=True)
    for i in range(pending):
        (folder / "out" / str(i)).unlink()
    return min(timed(folder, str(BIN / "snakemake"), "-n") for _ in range(3))


def jobs_of(tree: Path, config: list[str]) -> int:
    """The number of jobs of a forced dry run (every rule instance of the build)."""
    out = subprocess.run(
        [str(BIN / "snakemake"), "-n", "--forceall", *config],
        cwd=tree,
        env=env_for(tree),
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    return next(int(line.split()[-1]) for line in out.splitlines() if line.startswith("total"))


def longest_job(tree: Path) -> tuple[float, str]:
    """The scene whose own work took longest in the last build (run.csv of each scene)."""
    best = (0.0, "")
    for path in (tree / "results").glob("*/timings/*/run.csv"):
        row = next(csv.DictReader(path.open()))
        best = max(best, (float(row["wall_seconds"]), f"{row['study']}/{row['scene']}"))
    return best


WORK = """
import sys, tempfile, time
from pathlib import Path
from classical_dynamics.studies import study_module, validate
# the baseline's validate also takes a schema
scene, module = validate("chains", *sys.argv[1:]), study_module("chains")
with tempfile.TemporaryDirectory() as tmp:
    for attempt in range(2):                        # the first imports and compiles what the work uses
        start = time.perf_counter()
        module.run(scene, quick=True).write(Path(tmp, f"r{attempt}"), Path(tmp, f"t{attempt}"), {},
                                            {"study": "chains", "scene": scene.name})
print(time.perf_counter() - start)
"""


def job_overhead(tree: Path) -> float:
    """One cheap scene's job as the pipeline runs it, less the same work (computing, drawing, writing) in a
    process that has already done it once: interpreter start, the imports it uses, validation, provenance
    (min of 3, the compiled-code cache filled)."""
    scene, schema = (
        "workflow/scenes/chains/two_masses_three_springs.yaml",
        "workflow/schemas/chains.schema.yaml",
    )
    schema = [schema] if (tree / schema).exists() else []  # before the schemas moved into the package
    work = min(
        float(
            subprocess.run(
                [sys.executable, "-c", WORK, scene, *schema],
                cwd=tree,
                env=env_for(tree),
                check=True,
                capture_output=True,
                text=True,
            ).stdout
        )
        for _ in range(3)
    )
    with tempfile.TemporaryDirectory() as tmp:
        command = [sys.executable, "-m", "classical_dynamics"]
        server = None
        if (tree / "src/classical_dynamics/jobserver.py").exists():  # a local run's jobs go through it
            socket_path = f"{tmp}/jobs.sock"
            server = subprocess.Popen(
                [
                    sys.executable,
                    "-m",
                    "classical_dynamics.jobserver",
                    "--serve",
                    socket_path,
                    str(os.getpid()),
                ],
                cwd=tree,
                env=env_for(tree),
            )
            command = [sys.executable, "-m", "classical_dynamics.jobserver", "classical_dynamics"]
            os.environ["CLASSICAL_DYNAMICS_JOBSERVER"] = socket_path
        try:
            walls = [
                timed(
                    tree, *command, "run", "chains", *schema, scene, f"{tmp}/r{i}", f"{tmp}/t{i}", "--quick"
                )
                for i in range(4)
            ]
        finally:
            os.environ.pop("CLASSICAL_DYNAMICS_JOBSERVER", None)
            if server:
                server.terminate()
                server.wait()
    return min(walls[1:]) - work


def add_sweep(tree: Path, count: int) -> None:
    """`count` generated chain scenes (loaded strings of 10 ... particles), valid in either commit."""
    folder = tree / "workflow/scenes/chains"
    for i in range(count):
        n = 10 + i % 90
        (folder / f"sweep_{i:04d}.yaml").write_text(
            f"title: Sweep {i}\nchain: "
            f"{{model: particles, n: {n}, ends: fixed-fixed, length_m: 1.0, mass_kg: 1.0}}\n"
            f"effects:\n  tension: {{newton: {1 + i / count:.6f}}}\nanalysis:\n  modes: 10\n"
        )


def restore(tree: Path) -> None:
    subprocess.run(["git", "checkout", "--", "."], cwd=tree, check=True, capture_output=True)
    subprocess.run(["git", "clean", "-fdq", "workflow"], cwd=tree, check=True, capture_output=True)


def measure(tree: Path, scratch: Path, args) -> dict:
    config = ["--config", "quick=1"] if args.quick else []
    row = {}
    row["full build (s)"] = snakemake(tree, "-c", "all", *config)
    row["longest job (s)"], longest = longest_job(tree)
    row["no-op dry run (s)"] = min(snakemake(tree, "-n", *config) for _ in range(3))
    jobs = jobs_of(tree, config)
    row["Snakemake floor, same jobs (s)"] = floor(jobs, scratch / "floor")
    row["no-op / floor"] = row["no-op dry run (s)"] / row["Snakemake floor, same jobs (s)"]
    row["one job's overhead (s)"] = job_overhead(tree)
    scene = tree / "workflow/scenes/chains/loaded_string.yaml"
    scene.write_text(scene.read_text().replace("newton: 1.0", "newton: 1.5"))
    row["after editing one scene (s)"] = snakemake(tree, "-c", "all", *config)
    if args.sweep:  # the sweep's scenes not yet run: the dry run lists them, as the floor's does
        add_sweep(tree, args.sweep)
        row["sweep: dry run, scenes validated (s)"] = snakemake(tree, "-n", *config)
        row["sweep: dry run again (s)"] = again = min(snakemake(tree, "-n", *config) for _ in range(2))
        row["sweep: Snakemake floor (s)"] = sweep_floor = floor(
            jobs + args.sweep, scratch / "floor_sweep", pending=args.sweep
        )
        row["sweep: dry run / floor"] = again / sweep_floor
    restore(tree)
    if not args.no_tests:
        row["test suite (s)"] = timed(tree, sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider")
    row["jobs"] = jobs
    row["sweep: jobs"] = jobs + args.sweep
    print(f"  {tree.name}: longest job {longest}", flush=True)
    return row


def worktree(rev: str, path: Path) -> Path:
    subprocess.run(
        ["git", "worktree", "add", "--detach", str(path), rev], cwd=ROOT, check=True, capture_output=True
    )
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--baseline",
        default="b99490e",
        help="the commit to compare with (default b99490e; none: this commit alone)",
    )
    parser.add_argument("--rev", default="HEAD", help="the commit measured (default HEAD)")
    parser.add_argument("--quick", action="store_true", help="the reduced build (quick=1)")
    parser.add_argument("--sweep", type=int, default=1000, help="scenes in the generated sweep (0: none)")
    parser.add_argument("--no-tests", action="store_true", help="skip timing the test suite")
    args = parser.parse_args()
    columns = {}
    with tempfile.TemporaryDirectory() as tmp:
        trees = {}
        try:
            revisions = (("baseline", args.baseline), ("this", args.rev))
            for label, rev in revisions[args.baseline == "none" :]:
                name = subprocess.run(
                    ["git", "rev-parse", "--short", rev], cwd=ROOT, check=True, capture_output=True, text=True
                ).stdout.strip()
                trees[label] = worktree(rev, Path(tmp) / name)
                print(f"measuring {label} ({name}) ...", flush=True)
                columns[label] = measure(trees[label], Path(tmp) / f"scratch-{label}", args)
        finally:
            for tree in trees.values():
                subprocess.run(
                    ["git", "worktree", "remove", "--force", str(tree)], cwd=ROOT, capture_output=True
                )
    base, this = columns.get("baseline", {}), columns["this"]
    print(
        f"\nmachine: {os.cpu_count()} cores; build: {'quick' if args.quick else 'full'}; "
        f"baseline {trees['baseline'].name if base else 'none'}, this {trees['this'].name}"
    )
    print(f"{'':44s}{'baseline':>10s}{'this':>10s}{'baseline / this':>17s}")
    for key in this:
        b, t = base.get(key), this[key]
        count = key.endswith("jobs")
        ratio = f"{b / t:17.2f}" if b and t and "/" not in key and not count else ""
        fmt = (lambda v: f"{v:10.0f}") if count else (lambda v: f"{v:10.2f}")
        print(f"{key:44s}{fmt(b) if b is not None else '':>10s}{fmt(t)}{ratio}")


if __name__ == "__main__":
    main()
