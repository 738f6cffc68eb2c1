"""How the pipeline's cost grows with the number of scenes (issue 21), with the fitted slope of each: a dry
run (beside Snakemake's floor for as many jobs), building the new scenes, and rendering the report (HTML, then
PDF).

A copy of the working tree gets a quick build, then a generated sweep of chain scenes (loaded strings of 10 to
99 particles, pipeline_build.add_sweep) in steps. Writes benchmarks/results/pipeline_scaling.json and .svg,
which the report's appendix shows with the commit, machine and date they were measured on; prints the table.
Measured times: rerun it on a quiet machine; it takes about 8 minutes on 2 cores.

    python benchmarks/pipeline_scaling.py [--dry 0,100,300,1000] [--built 0,10,30,100] [--redraw]
"""

from __future__ import annotations

import argparse
import json
import platform
import shutil
import sys
import tempfile
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from pipeline_build import ROOT, add_sweep, floor, jobs_of, snakemake

sys.path.insert(0, str(ROOT))
from tests.conftest import copy_repository

OUT = ROOT / "benchmarks" / "results" / "pipeline_scaling"
QUICK = ["--config", "quick=1"]


def remove_sweep(tree: Path) -> None:
    for scene in (tree / "workflow/scenes/chains").glob("sweep_*.yaml"):
        scene.unlink()
    for folder in (tree / "results/chains").glob("sweep_*"):
        shutil.rmtree(folder)
    for folder in (tree / "results/chains/timings").glob("sweep_*"):
        shutil.rmtree(folder)


def dry_runs(tree: Path, counts: list[int], scratch: Path) -> list[dict]:
    """A dry run with `count` sweep scenes pending (their validation cached by a first dry run), and the floor
    with as many jobs pending (the new scenes, the results archive, the HTML, the PDF and `all`)."""
    rows = []
    for count in counts:
        remove_sweep(tree)
        add_sweep(tree, count)
        first = snakemake(tree, "-n", *QUICK)  # validates the new scenes once
        again = min(snakemake(tree, "-n", *QUICK) for _ in range(2))
        jobs = jobs_of(tree, QUICK)
        rows.append(
            {
                "scenes_added": count,
                "jobs": jobs,
                "dry_run_first_s": first,
                "dry_run_s": again,
                "floor_s": floor(jobs, scratch / f"floor{count}", pending=count + 4 if count else 0),
            }
        )
        print(rows[-1], flush=True)
    remove_sweep(tree)
    return rows


def builds(tree: Path, counts: list[int]) -> list[dict]:
    """Build `count` sweep scenes (from none), then the report's HTML and PDF with them."""
    rows = []
    for count in counts:
        remove_sweep(tree)
        add_sweep(tree, count)
        targets = [f"results/chains/sweep_{i:04d}" for i in range(count)]
        build = snakemake(tree, "-c", "2", *targets, *QUICK) if targets else None
        html = snakemake(tree, "-c", "2", "results/report.html", "--forcerun", "report_html", *QUICK)
        pdf = snakemake(tree, "-c", "2", "results/report.pdf", "--forcerun", "report_pdf", *QUICK)
        rows.append({"scenes_added": count, "build_s": build, "report_html_s": html, "report_pdf_s": pdf})
        print(rows[-1], flush=True)
    remove_sweep(tree)
    return rows


def slope(rows: list[dict], x: str, y: str) -> float:
    """Least-squares slope of y against x over the rows that have y."""
    rows = [r for r in rows if r[y] is not None]
    return float(np.polyfit([r[x] for r in rows], [r[y] for r in rows], 1)[0])


def slopes(dry: list[dict], built: list[dict]) -> dict:
    return {
        "dry_run_s_per_1000_scenes": 1000 * slope(dry, "scenes_added", "dry_run_s"),
        "floor_s_per_1000_scenes": 1000 * slope(dry, "scenes_added", "floor_s"),
        "build_s_per_scene": slope(built, "scenes_added", "build_s"),
        "report_html_s_per_scene": slope(built, "scenes_added", "report_html_s"),
        "report_pdf_s_per_scene": slope(built, "scenes_added", "report_pdf_s"),
    }


def draw(data: dict) -> bytes:
    from classical_dynamics import io
    from classical_dynamics.figure_style import FULL_WIDTH_IN
    from classical_dynamics.results import subplots

    fig, (left, right) = subplots(1, 2, figsize=(FULL_WIDTH_IN, 2.6))
    dry, built, fits = data["dry_runs"], data["builds"], data["slopes"]
    n = [r["scenes_added"] for r in dry]
    left.plot(
        n,
        [r["dry_run_s"] for r in dry],
        "o-",
        label=f"this pipeline: {fits['dry_run_s_per_1000_scenes']:.2f} s per 1000",
    )
    left.plot(
        n,
        [r["floor_s"] for r in dry],
        "s--",
        label=f"Snakemake alone, same jobs: {fits['floor_s_per_1000_scenes']:.2f} s per 1000",
    )
    left.set(xlabel="scenes added to a quick build", ylabel="dry run (s)", ylim=(0, None), title="dry run")
    left.legend()
    for key, label in (
        ("build_s", "building the new scenes"),
        ("report_html_s", "report HTML"),
        ("report_pdf_s", "report PDF"),
    ):
        rows = [r for r in built if r[key] is not None]
        right.plot(
            [r["scenes_added"] for r in rows],
            [r[key] for r in rows],
            "o-",
            label=f"{label}: {fits[key + '_per_scene']:.2f} s/scene",
        )
    right.set(
        xlabel="scenes added to a quick build",
        ylabel="wall time (s)",
        ylim=(0, None),
        title="build and report",
    )
    right.legend()
    return io.svg_bytes(fig)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dry", default="0,100,300,1000", help="sweep sizes for the dry runs")
    parser.add_argument("--built", default="0,10,30,100", help="sweep sizes built and reported")
    parser.add_argument("--redraw", action="store_true", help="refit and redraw the saved measurement only")
    args = parser.parse_args()
    if args.redraw:
        return redraw()
    from classical_dynamics.provenance import git_state, machine, package_versions

    with tempfile.TemporaryDirectory(prefix="scaling-") as tmp:
        tree = copy_repository(Path(tmp) / "tree")
        base = snakemake(tree, "-c", "2", *QUICK)
        print(f"quick build: {base:.1f} s", flush=True)
        dry = dry_runs(tree, [int(c) for c in args.dry.split(",")], Path(tmp))
        built = builds(tree, [int(c) for c in args.built.split(",")])
    state, host = git_state(), machine()
    data = {
        "what": "pipeline cost against the number of scenes (benchmarks/pipeline_scaling.py)",
        "commit": state["commit"],
        "dirty": bool(state["dirty"]),
        "measured": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        "machine": {"cpu_model": host["cpu_model"], "cores": host["cores"], "platform": platform.platform()},
        "packages": {
            k: v for k, v in package_versions().items() if k in ("snakemake", "weasyprint", "numpy")
        },
        "quick_build_s": base,
        "dry_runs": dry,
        "builds": built,
        "slopes": slopes(dry, built),
    }
    save(data)


def save(data: dict) -> None:
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.with_suffix(".json").write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    OUT.with_suffix(".svg").write_bytes(draw(data))
    print(json.dumps(data["slopes"], indent=1))


def redraw() -> None:
    """The saved measurement's slopes and figure again, without measuring (after a change to either)."""
    data = json.loads(OUT.with_suffix(".json").read_text(encoding="utf-8"))
    for row in data["builds"]:
        row["build_s"] = row["build_s"] or None  # nothing built for no scenes added
    data["slopes"] = slopes(data["dry_runs"], data["builds"])
    save(data)


if __name__ == "__main__":
    main()
