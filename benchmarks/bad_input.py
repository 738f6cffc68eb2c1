"""How bad scenes are refused: every case of tests/bad_scenes, tallied (printed, not asserted).

For each case: refused with a SceneError of one line naming the expected field (clean), the seconds to refuse,
and the peak resident memory of this process while refusing (VmHWM, reset before each case). With --snakemake,
each case is also dropped into a scratch copy of the repository with its results and refused by `snakemake
-n`, and results/ is compared byte for byte before and after (results touched must be 0).

With --files (or --files-only), the hostile files of verify and diff (tests/hostile_files.py: gzip bombs,
too many members, deep JSON, huge numbers, what is not results) and a full disk (a scene, dist and verify's
unpacking on a small tmpfs, when this process may mount one) are tallied too: each command run as a user runs
it, its time to refuse and its own peak resident memory (its rusage), and the input compared byte for byte
before and after (results touched must be 0).

    python benchmarks/bad_input.py [--snakemake] [--files | --files-only]
"""

from __future__ import annotations

import argparse
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "src"), str(ROOT)]
from classical_dynamics.scenes import SceneError  # noqa: E402
from classical_dynamics.scenes.cost import Budget  # noqa: E402
from classical_dynamics.studies import validate  # noqa: E402
from tests import hostile_files as hf  # noqa: E402
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


def _full_disk_cases():
    """(id, run(folder) -> (outcome, touched)) of a full disk: the command must say so in one line, leave the
    last whole result as it was and no temporary file."""
    scene = ROOT / "workflow/scenes/chains/two_masses_three_springs.yaml"

    def scene_write(base):
        with hf.small_disk(base / "disk") as disk:
            out = disk.path / "results/chains/s"
            run = [
                "run",
                "chains",
                str(scene),
                str(out),
                str(disk.path / "results/chains/timings/s"),
                "--quick",
            ]
            assert hf.run(run, base).returncode == 0
            before = hf.digest(disk.path / "results")
            disk.fill()
            done = hf.run(run, base)
            return done, int(hf.digest(disk.path / "results") != before or bool(list(disk.path.rglob(".*"))))

    def dist(base):
        results = hf.results_folder(base)
        with hf.small_disk(base / "disk") as disk:
            archive = disk.path / "dist" / hf.ARCHIVE
            assert hf.run(["dist", str(results), str(archive)], base).returncode == 0
            before = hf.digest(disk.path)
            (results / "report.html").write_bytes(os.urandom(8 << 20))
            done = hf.run(["dist", str(results), str(archive)], base)
            return done, int(hf.digest(disk.path) != before or bool(list(disk.path.rglob(".*"))))

    def verify_unpack(base):
        archive = hf.archive(base)
        before = hf.digest(base)
        with hf.small_disk(base / "disk", "1m") as disk:
            disk.fill(leave=1)
            done = hf.run(["verify", str(archive), "--root", str(hf.checkout(base))], disk.path)
            left = sorted(p.name for p in disk.path.iterdir()) != ["filler"]
        return done, int(left or hf.digest(base) != before)

    return [("scene-write", scene_write), ("dist", dist), ("verify-unpack", verify_unpack)]


def files_tally() -> tuple[dict, list[str]]:
    """{kind: [tried, handled, max s, max MB, touched]} of the hostile files and the full disk."""
    tally, rows = defaultdict(lambda: [0, 0, 0.0, 0.0, 0]), []

    def count(kind, case_id, done, touched, expect):
        clean = (
            done.returncode == 2
            and done.stderr.count("\n") == 1
            and "Traceback" not in done.stderr
            and expect in done.stderr
        )
        row = tally[kind]
        row[0] += 1
        row[1] += clean
        row[2] = max(row[2], done.seconds)
        row[3] = max(row[3], done.peak_mb)
        row[4] += touched
        if not clean or touched:
            rows.append(f"  not clean: {case_id}: {done.returncode} {done.stderr.strip()[-200:]}")

    for case in hf.all_cases():
        with tempfile.TemporaryDirectory() as folder:
            base, tmp = Path(folder, "base"), Path(folder, "tmp")
            base.mkdir()
            tmp.mkdir()
            args = case.make(base)
            before = hf.digest(base)
            done = hf.run(args, tmp)
            count(case.kind, case.id, done, int(hf.digest(base) != before or any(tmp.iterdir())), case.expect)
    if hf.can_mount():
        for case_id, make in _full_disk_cases():
            with tempfile.TemporaryDirectory() as folder:
                done, touched = make(Path(folder))
                count("full disk", case_id, done, touched, "no space left on device")
    else:
        rows.append("  full disk: not tried (this process may not mount a tmpfs)")
    return tally, rows


def print_files(tally, rows) -> bool:
    print(
        "\nverify, diff, dist and a full disk: max s, the command's time to refuse; max MB, its own peak"
        " resident memory"
    )
    print(f"{'kind':<17} {'tried':>6} {'handled':>8} {'max s':>7} {'max MB':>7} {'results touched':>16}")
    for kind, (tried, clean, seconds, memory, touched) in sorted(tally.items()):
        print(f"{kind:<17} {tried:>6} {clean:>8} {seconds:>7.2f} {memory:>7.0f} {touched:>16}")
    print("\n".join(rows))
    return all(row[0] == row[1] and row[4] == 0 for row in tally.values())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--snakemake", action="store_true", help="also refuse each case through snakemake -n")
    parser.add_argument("--files", action="store_true", help="also the hostile files and a full disk")
    parser.add_argument("--files-only", action="store_true", help="only the hostile files and a full disk")
    args = parser.parse_args()
    if args.files_only:
        return 0 if print_files(*files_tally()) else 1
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
    # the configuration (issue 35, item 5): each bad --config of the tests, refused by the workflow's check
    from classical_dynamics.workflow_config import ConfigError, check_config
    from tests.test_bad_input import BAD_CONFIG

    for setting, expected in BAD_CONFIG:
        key, _, raw = setting.partition("=")
        reset_peak()
        start = time.perf_counter()
        try:
            check_config({key: yaml.safe_load(raw)}, ROOT / "workflow/config.yaml")
            message = None
        except ConfigError as error:
            message = str(error)
        seconds, memory = time.perf_counter() - start, peak_mb()
        clean = message is not None and "\n" not in message and message.startswith(expected)
        row = tally["config"]
        row[0], row[1] = row[0] + 1, row[1] + clean
        row[2], row[3] = max(row[2], seconds), max(row[3], memory)
        if not clean:
            rows.append(f"  not clean: --config {setting}: {message}")
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
    files_ok = print_files(*files_tally()) if args.files else True
    return 0 if total[0] == total[1] and total[4] == 0 and files_ok else 1


if __name__ == "__main__":
    sys.exit(main())
