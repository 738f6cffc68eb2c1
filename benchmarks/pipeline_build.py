"""Build-time benchmark: a full build from clean, a no-op, and a rebuild after editing one scene.

Runs in a temporary copy of the repository so the working tree's results/ are untouched.
Prints measured wall times; asserts nothing. Goals (2-core machine): full < 3 min, no-op < 3 s.

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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the reduced build (quick=1)")
    args = parser.parse_args()
    config = ["--config", "quick=1"] if args.quick else []
    with tempfile.TemporaryDirectory() as tmp:
        repo = copy_repository(Path(tmp) / "repo")
        full = timed(repo, "-c", "all", *config)
        noop = min(timed(repo, "-c", "all", *config) for _ in range(3))
        scene = repo / "workflow/scenes/chains/loaded_string.yaml"
        scene.write_text(scene.read_text().replace("newton: 1.0", "newton: 1.5"))
        edited = timed(repo, "-c", "all", *config)
    print(f"machine: {os.cpu_count()} cores; build: {'quick' if args.quick else 'full'}")
    print(f"full build from clean          {full:8.1f} s   (goal < 180 s)")
    print(f"no-op (min of 3)               {noop:8.2f} s   (goal < 3 s)")
    print(f"after editing one scene        {edited:8.1f} s   (that scene and the report)")


if __name__ == "__main__":
    main()
