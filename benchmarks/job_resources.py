"""Each job's measured wall time and peak memory beside what its rule asks a scheduler for (issue 20).

Snakemake's `benchmark:` directive writes, for every job, its seconds and its peak resident memory (max_rss,
MB) to results/benchmarks/ (a scene to <study>/<scene>.tsv, another rule to <rule>.tsv). Those figures are
right only for a job that runs in its own processes: on a cluster, or locally with `--config jobserver=0` (a
job the local job server runs is a forked child of the server, outside the process tree Snakemake measures).

    snakemake -c all --forceall --config jobserver=0     # measure (about 4 minutes on 2 cores)
    python benchmarks/job_resources.py                   # print measured against asked
    python benchmarks/job_resources.py --write           # record the peaks of the rules that are not scenes

--write stores the peaks in workflow/resources.yaml, from which those rules ask for memory and time
(limits.rule_resources: room over the peak); a scene asks from its own cost estimate (scenes/cost.py).
"""

from __future__ import annotations

import argparse
import csv
import platform
import subprocess
import sys
from datetime import datetime, timezone
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
from classical_dynamics.limits import rule_resources  # noqa: E402

RESOURCES = ROOT / "workflow" / "resources.yaml"


def used(path: Path) -> dict:
    """A job's seconds and peak resident memory (MB) from its Snakemake benchmark file."""
    with path.open() as handle:
        row = next(csv.DictReader(handle, delimiter="\t"))
    rss = row["max_rss"]
    return {
        "seconds": float(row["s"]),
        "max_rss_mb": float(rss) if rss not in ("", "NA", "-") else float("nan"),
    }


def measured(benchmarks: Path) -> dict[str, dict]:
    """{job: {"rule", "seconds", "max_rss_mb"}} from Snakemake's benchmark files under `benchmarks`."""
    jobs = {}
    for path in sorted(benchmarks.rglob("*.tsv")):
        rel = path.relative_to(benchmarks).with_suffix("")
        jobs[rel.as_posix()] = {"rule": "scene" if len(rel.parts) == 2 else rel.name, **used(path)}
    return jobs


def rule_peaks(jobs: dict[str, dict]) -> dict[str, dict]:
    """The largest seconds and memory of each rule that is not a scene."""
    peaks = {}
    for job in jobs.values():
        if job["rule"] == "scene":
            continue
        peak = peaks.setdefault(job["rule"], {"seconds": 0.0, "max_rss_mb": 0.0})
        peak["seconds"] = round(max(peak["seconds"], job["seconds"]), 1)
        peak["max_rss_mb"] = round(max(peak["max_rss_mb"], job["max_rss_mb"]))
    return peaks


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=ROOT / "results")
    parser.add_argument("--write", action="store_true", help="record the peaks in workflow/resources.yaml")
    args = parser.parse_args(argv)
    jobs = measured(args.results / "benchmarks")
    if not jobs:
        print(f"no benchmark files under {args.results / 'benchmarks'}: build first", file=sys.stderr)
        return 1
    recorded = yaml.safe_load(RESOURCES.read_text())["rules"]
    print(f"{'job':<44} {'seconds':>8} {'peak MB':>8} {'asks min':>9} {'asks MB':>8}")
    for name, job in sorted(jobs.items(), key=lambda item: -item[1]["seconds"]):
        asks = rule_resources(recorded[job["rule"]]) if job["rule"] in recorded else None
        asked = f"{asks['runtime']:>9} {asks['mem_mb']:>8}" if asks else f"{'(scene)':>9} {'':>8}"
        print(f"{name:<44} {job['seconds']:>8.1f} {job['max_rss_mb']:>8.0f} {asked}")
    total = sum(job["seconds"] for job in jobs.values())
    print(f"{len(jobs)} jobs, {total:.0f} s in all")
    served = [name for name, job in jobs.items() if job["max_rss_mb"] < 50]  # a client's, not its job's
    if served:
        print(
            f"{len(served)} jobs measured under 50 MB: run through the local job server, their memory is not "
            "theirs; build again with --config jobserver=0",
            file=sys.stderr,
        )
        if args.write:
            return 1
    if args.write:
        commit = subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True
        ).stdout.strip()
        header = RESOURCES.read_text().split("\nmeasured:", 1)[0]
        document = {
            "measured": {
                "commit": commit,
                "machine": f"{platform.machine()}, {platform.node()}",
                "date": datetime.now(timezone.utc).strftime("%Y-%m-%d"),
            },
            "rules": rule_peaks(jobs),
        }
        RESOURCES.write_text(header + "\n" + yaml.safe_dump(document, sort_keys=False))
        print(f"wrote {RESOURCES.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
