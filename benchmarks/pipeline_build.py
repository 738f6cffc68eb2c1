"""Build-time benchmark: a full build from clean, a no-op, and a rebuild after editing one scene.

Runs in a temporary copy of the repository so the working tree's results/ are untouched.
Prints measured wall times; asserts nothing. Goals (2-core machine): full < 3 min, and a no-op dry run within 1.5
times Snakemake's own floor, measured in the same run: a Snakefile with as many jobs that do nothing.

    python benchmarks/pipeline_build.py [--quick]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.conftest import copy_repository, run_env  # noqa: E402


def timed(repo: Path, *args: str) -> float:
    snakemake = str(Path(sys.executable).parent / "snakemake")
    start = time.perf_counter()
    subprocess.run([snakemake, *args], cwd=repo, env=run_env(repo), check=True, capture_output=True)
    return time.perf_counter() - start


def floor(jobs: int, folder: Path) -> float:
    """A no-op dry run of a Snakefile with `jobs` jobs and no work: what Snakemake itself costs (min of 3)."""
    folder.mkdir()
    (folder / "Snakefile").write_text(
        f"N = {jobs}\n"
        "rule all:\n    input: expand('out/{i}', i=range(N))\n"
        "rule one:\n    output: 'out/{i}'\n    shell: 'touch {output}'\n")
    snakemake = str(Path(sys.executable).parent / "snakemake")
    subprocess.run([snakemake, "-c", "1", "-q"], cwd=folder, check=True, capture_output=True)
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        subprocess.run([snakemake, "-n"], cwd=folder, check=True, capture_output=True)
        best = min(best, time.perf_counter() - start)
    return best


def jobs_of(repo: Path) -> int:
    """The number of jobs of a forced dry run (every rule instance of the build)."""
    out = subprocess.run([str(Path(sys.executable).parent / "snakemake"), "-n", "--forceall"], cwd=repo,
                         env=run_env(repo), check=True, capture_output=True, text=True).stdout
    return next(int(line.split()[-1]) for line in out.splitlines() if line.startswith("total"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the reduced build (quick=1)")
    args = parser.parse_args()
    config = ["--config", "quick=1"] if args.quick else []
    with tempfile.TemporaryDirectory() as tmp:
        repo = copy_repository(Path(tmp) / "repo")
        full = timed(repo, "-c", "all", *config)
        noop = min(timed(repo, "-c", "all", *config) for _ in range(3))
        dry = min(timed(repo, "-n", *config) for _ in range(3))
        jobs = jobs_of(repo)
        bare = floor(jobs, Path(tmp) / "floor")
        scene = repo / "workflow/scenes/chains/loaded_string.yaml"
        scene.write_text(scene.read_text().replace("newton: 1.0", "newton: 1.5"))
        edited = timed(repo, "-c", "all", *config)
    print(f"machine: {os.cpu_count()} cores; build: {'quick' if args.quick else 'full'}")
    print(f"full build from clean          {full:8.1f} s   (goal < 180 s)")
    print(f"no-op (min of 3)               {noop:8.2f} s")
    print(f"no-op dry run (min of 3)       {dry:8.2f} s   ({dry / bare:.2f} x Snakemake's floor of {bare:.2f} s for "
          f"{jobs} jobs; goal < 1.5 x)")
    print(f"after editing one scene        {edited:8.1f} s   (that scene and the report)")


if __name__ == "__main__":
    main()
