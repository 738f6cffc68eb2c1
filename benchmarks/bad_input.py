"""How bad scenes are refused: every case of tests/bad_scenes, tallied (printed, not asserted).

For each case: refused with a SceneError of one line naming the expected field (clean), the seconds to refuse,
and the peak resident memory of this process while refusing (VmHWM, reset before each case). With --snakemake,
each case is also dropped into a scratch copy of the repository with its results and refused by `snakemake
-n`, and results/ is compared byte for byte before and after (results touched must be 0).

    python benchmarks/bad_input.py [--snakemake]
"""

from __future__ import annotations

import argparse
import hashlib
import shutil
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "src"), str(ROOT)]
from classical_dynamics.scenes import SceneError  # noqa: E402
from classical_dynamics.scenes.cost import Budget  # noqa: E402
from classical_dynamics.studies import validate  # noqa: E402
from tests.bad_scenes import all_cases  # noqa: E402


def peak_mb() -> float:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    return float("nan")


def reset_peak() -> None:
    Path("/proc/self/clear_refs").write_text("5")  # the kernel's peak-RSS counter starts again from now


def digest(folder: Path) -> str:
    h = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        h.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--snakemake", action="store_true", help="also refuse each case through snakemake -n")
    args = parser.parse_args()
    budget, cases = Budget.from_file(ROOT / "workflow/config.yaml"), all_cases()
    for study in sorted({c.study for c in cases}):  # warm imports and caches
        validate(study, next((ROOT / "workflow/scenes" / study).glob("*.yaml")), budget)
    rows, tally = [], defaultdict(lambda: [0, 0, 0.0, 0.0, 0, 0.0])
    scratch = None
    if args.snakemake:
        scratch = Path(tempfile.mkdtemp()) / "repo"
        shutil.copytree(ROOT, scratch, symlinks=True, ignore=shutil.ignore_patterns(".git", ".venv", "dist"))
        before = digest(scratch / "results")
    for case in cases:
        with tempfile.TemporaryDirectory() as folder:
            path = case.write(Path(folder))
            reset_peak()
            start = time.perf_counter()
            try:
                validate(case.study, path, budget)
                message = None
            except SceneError as error:
                message = str(error)
            seconds, memory = time.perf_counter() - start, peak_mb()
        clean = (
            message is not None and "\n" not in message and message.startswith(f"{path}: field '{case.field}")
        )
        touched, snake_s = 0, 0.0
        if scratch is not None:
            path = case.write(scratch / "workflow/scenes" / case.study)
            start = time.perf_counter()
            try:
                out = subprocess.run(
                    [str(Path(sys.executable).parent / "snakemake"), "-n"],
                    cwd=scratch,
                    capture_output=True,
                    text=True,
                    timeout=120,
                )
            finally:
                snake_s = time.perf_counter() - start
                shutil.rmtree(path) if path.is_dir() and not path.is_symlink() else path.unlink()
            clean = clean and out.returncode == 1 and f"field '{case.field}" in out.stderr
            touched = int(digest(scratch / "results") != before)
        row = tally[case.kind]
        row[0] += 1
        row[1] += clean
        row[2] = max(row[2], seconds)
        row[3] = max(row[3], memory)
        row[4] += touched
        row[5] = max(row[5], snake_s)
        if not clean:
            rows.append(f"  not clean: {case.id}: {message}")
    print(
        "max s: the validator's time to refuse; max MB: this process's peak resident memory while refusing;"
        "\nsnakemake s: the whole `snakemake -n` that refused it (--snakemake only)"
    )
    print(
        f"{'kind':<10} {'tried':>6} {'refused cleanly':>16} {'max s':>7} {'max MB':>7} "
        f"{'results touched':>16}"
        f" {'snakemake s':>12}"
    )
    total = [0, 0, 0.0, 0.0, 0, 0.0]
    for kind, (tried, clean, seconds, memory, touched, snake_s) in sorted(tally.items()):
        print(
            f"{kind:<10} {tried:>6} {clean:>16} {seconds:>7.3f} {memory:>7.0f} {touched:>16} {snake_s:>12.2f}"
        )
        total = [
            total[0] + tried,
            total[1] + clean,
            max(total[2], seconds),
            max(total[3], memory),
            total[4] + touched,
            max(total[5], snake_s),
        ]
    print(
        f"{'all':<10} {total[0]:>6} {total[1]:>16} {total[2]:>7.3f} {total[3]:>7.0f} {total[4]:>16} "
        f"{total[5]:>12.2f}"
    )
    print("\n".join(rows))
    if scratch is not None:
        shutil.rmtree(scratch.parent)
    return 0 if total[0] == total[1] and total[4] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
