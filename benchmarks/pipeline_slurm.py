"""The quick build locally and through Slurm (profiles/slurm), and what one job costs beyond its own
work on each (issue 20). Needs a Slurm cluster that answers: `tools/local-slurm up` starts one on this
machine.

In copies of the working tree, one after the other: the quick build with `-c 2` (the local job server on),
then the same through Slurm; then one light scene forced to run again, alone, by each. A job's overhead is the
command's wall time less the job's own seconds (its Snakemake benchmark file); for Slurm also Slurm's own
elapsed time of the job (sacct), which leaves out the wait for the first status check. About 12 minutes on 2
cores.

    python benchmarks/pipeline_slurm.py
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from benchmarks.job_resources import used  # noqa: E402
from tests.conftest import copy_repository, snakemake  # noqa: E402

SCENE = "chains/loaded_string"
PROFILE = ("--profile", "profiles/slurm")


def timed(repo: Path, *args) -> tuple[float, str]:
    start = time.perf_counter()
    done = snakemake(repo, *args, timeout=3600)
    return time.perf_counter() - start, done.stdout + done.stderr


def own_seconds(repo: Path) -> float:
    return used(repo / "results" / "benchmarks" / f"{SCENE}.tsv")["seconds"]


def slurm_elapsed(job_id: str) -> float:
    out = subprocess.run(
        ["sacct", "-n", "-X", "-P", "-j", job_id, "-o", "ElapsedRaw"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    return float(out[0])


def main() -> int:
    with tempfile.TemporaryDirectory() as scratch:
        local, slurm = (copy_repository(Path(scratch) / name) for name in ("local", "slurm"))
        rows = []
        seconds, log = timed(local, "-c", "2", "--config", "quick=1")
        jobs = int(re.search(r"(\d+) of \1 steps \(100%\) done", log).group(1))
        rows.append(("quick build, local (-c 2)", seconds, f"{jobs} jobs"))
        seconds, log = timed(slurm, *PROFILE, "--config", "quick=1")
        submitted = re.findall(r"submitted with SLURM jobid (\d+)", log)
        rows.append(("quick build, Slurm", seconds, f"{jobs} jobs in {len(submitted)} Slurm jobs"))
        seconds, _ = timed(local, "-c", "2", f"results/{SCENE}", "--forcerun", "scene", "--config", "quick=1")
        rows.append((f"one scene ({SCENE}), local", seconds, f"its own work {own_seconds(local):.1f} s"))
        seconds, log = timed(
            slurm, *PROFILE, f"results/{SCENE}", "--forcerun", "scene", "--config", "quick=1"
        )
        job = re.findall(r"submitted with SLURM jobid (\d+)", log)[-1]
        rows.append(
            (
                f"one scene ({SCENE}), Slurm",
                seconds,
                f"its own work {own_seconds(slurm):.1f} s, {slurm_elapsed(job):.0f} s in Slurm",
            )
        )
    print(f"{'':<40} {'wall s':>8}")
    for name, seconds, note in rows:
        print(f"{name:<40} {seconds:>8.1f}   {note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
