"""Check a cited number: rebuild a dist archive and compare every number with it, or compare two builds.

Both read only the results contract (design.md): the numbers of results/<study>/<scene>/summary.json
(headline numbers and the hard cases' measured values) and, for notes, provenance.json. Nothing is
written outside temporary folders.

Tolerance of a number (verify; diff reports every change):
  declared in summary.json   {"absolute": a} or {"relative": r}; a bare number is absolute, in the
                             number's own unit (the same forms as a claim's check)
  otherwise                  exact for integers, booleans and strings; floats within 1e-9 relative,
                             or 1e-15 absolute for values at zero (a deterministic rebuild meets it)
Lists are compared element by element, each element named name[i].
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import re
import subprocess
import sys
import tarfile
import tempfile
import zlib
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from . import io
from .provenance import git, sha256_file

DEFAULT_RELATIVE = 1e-9
ABSOLUTE_FLOOR = 1e-15
PREFIX = re.compile(r"^classical-dynamics-[A-Za-z0-9._+-]+$")
MISSING = object()  # a number (or scene) present on one side only


class VerifyError(Exception):
    """A bad archive or input: one line naming what is wrong."""


# --- reading the results contract --------------------------------------------------------------


def scenes_of(folder: Path) -> list[tuple[str, str]]:
    """(study, scene) of every results/<study>/<scene>/summary.json; refuse a folder without any."""
    folder = Path(folder)
    if not folder.is_dir():
        raise VerifyError(f"{folder}: not a folder")
    found = sorted(
        (p.parent.parent.name, p.parent.name)
        for p in folder.glob("*/*/summary.json")
        if p.parent.name != "timings" and not io.is_staging(p.parent)
    )
    if not found:
        raise VerifyError(f"{folder}: not a results folder (no <study>/<scene>/summary.json)")
    return found


def _read_json(path: Path):
    try:
        return io.read_json(path)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise VerifyError(f"{path}: unreadable or not JSON ({error})") from None


def read_numbers(folder: Path, scenes=None) -> dict[tuple[str, str, str], dict]:
    """{(study, scene, name): {"value", "unit", "tolerance"?...}} for the given (or every) scene."""
    numbers = {}
    for study, scene in scenes if scenes is not None else scenes_of(folder):
        path = Path(folder) / study / scene / "summary.json"
        summary = _read_json(path)
        if not isinstance(summary, dict) or not isinstance(summary.get("numbers"), dict):
            raise VerifyError(f"{path}: no 'numbers' object (not a summary of the results contract)")
        for name, entry in summary["numbers"].items():
            if not isinstance(entry, dict) or "value" not in entry:
                raise VerifyError(f"{path}: number {name!r} has no value")
            numbers[study, scene, name] = entry
        # a hard case's measured value is printed in the report too
        for case in summary.get("stability") or []:
            numbers[study, scene, f"hard_case:{case['name']}"] = {
                "value": case.get("measured"),
                "unit": case.get("unit", ""),
            }
    return numbers


def read_provenance(folder: Path, study: str, scene: str) -> dict:
    path = Path(folder) / study / scene / "provenance.json"
    if not path.is_file():
        raise VerifyError(f"{path}: missing (every scene carries its provenance)")
    return _read_json(path)


# --- comparing -----------------------------------------------------------------------------------


@dataclass
class Change:
    where: str  # study/scene
    number: str  # name, name[i] for an element of a list
    old: object
    new: object
    tolerance: str = ""

    @property
    def relative(self):
        """(new - old)/|old|; None when either side is not a number."""
        if not (_is_number(self.old) and _is_number(self.new)):
            return None
        if self.old == self.new:
            return 0.0
        return (self.new - self.old) / abs(self.old) if self.old else math.copysign(math.inf, self.new)


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def parse_tolerance(entry: dict, where: str) -> tuple[str, float] | None:
    """A declared tolerance as ("absolute" | "relative", value); None for the default rule."""
    tol = entry.get("tolerance")
    if tol is None:
        return None
    if _is_number(tol) and tol >= 0:
        return "absolute", float(tol)
    if isinstance(tol, dict) and len(tol) == 1:
        ((kind, value),) = tol.items()
        if kind in ("absolute", "relative") and _is_number(value) and value >= 0:
            return kind, float(value)
    raise VerifyError(f"{where}: tolerance {tol!r} is not a number >= 0, {{absolute: a}} or {{relative: r}}")


def _describe(tol) -> str:
    return "default" if tol is None else f"{tol[0][:3]} {tol[1]:.3g}"


def _close(a, b, tol) -> bool:
    """Whether two leaf values agree within tol (None: the default rule; ("absolute", 0): exact)."""
    if not (_is_number(a) and _is_number(b)):
        return type(a) is type(b) and a == b  # strings, booleans, None (NaN), "inf"
    if tol is None:
        if isinstance(a, int) and isinstance(b, int):
            return a == b
        return abs(a - b) <= max(DEFAULT_RELATIVE * max(abs(a), abs(b)), ABSOLUTE_FLOOR)
    kind, value = tol
    scale = max(abs(a), abs(b)) if kind == "relative" else 1.0
    return abs(a - b) <= value * scale


def _leaves(name, a, b, tol):
    """(name, a, b) of every element that differs; lists element by element."""
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            yield from _leaves(f"{name}[{i}]", x, y, tol)
    elif isinstance(a, dict) and isinstance(b, dict) and a.keys() == b.keys():
        for key in sorted(a):
            yield from _leaves(f"{name}.{key}", a[key], b[key], tol)
    elif isinstance(a, (list, dict)) or isinstance(b, (list, dict)):
        if a != b:
            yield name, a, b  # shape changed: the whole value
    elif not _close(a, b, tol):
        yield name, a, b


def compare(old: dict, new: dict, *, exact: bool = False) -> list[Change]:
    """Every number that moved between two {(study, scene, name): entry} maps; exact=True for diff."""
    changes = []
    for key in sorted(old.keys() | new.keys()):
        where, name = f"{key[0]}/{key[1]}", key[2]
        if key not in old or key not in new:
            changes.append(
                Change(
                    where,
                    name,
                    old[key]["value"] if key in old else MISSING,
                    new[key]["value"] if key in new else MISSING,
                    "exact" if exact else "",
                )
            )
            continue
        tol = (
            ("absolute", 0.0)
            if exact
            else (
                parse_tolerance(old[key], f"{where} {name}") or parse_tolerance(new[key], f"{where} {name}")
            )
        )
        for label, a, b in _leaves(name, old[key]["value"], new[key]["value"], tol):
            changes.append(Change(where, label, a, b, "exact" if exact else _describe(tol)))
    return changes


def _show(value) -> str:
    if value is MISSING:
        return "(none)"
    if isinstance(value, float):
        return f"{value:.15g}"
    text = json.dumps(value, ensure_ascii=False) if not isinstance(value, str) else value
    return text if len(text) <= 40 else text[:39] + "…"


def _show_relative(change: Change) -> str:
    rel = change.relative
    if change.old is MISSING:
        return "added"
    if change.new is MISSING:
        return "removed"
    return "—" if rel is None else f"{rel:+.3e}"


def table(changes: list[Change], old_label: str, new_label: str, tolerance: bool) -> str:
    header = ["study/scene", "number", old_label, new_label, "relative change"] + (
        ["tolerance"] if tolerance else []
    )
    rows = [
        [c.where, c.number, _show(c.old), _show(c.new), _show_relative(c)]
        + ([c.tolerance] if tolerance else [])
        for c in changes
    ]
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(len(header))]
    return "\n".join(
        "  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() for row in [header, *rows]
    )


def _count(changes) -> str:
    scenes = {c.where for c in changes}
    return (
        f"{len(changes)} number{'s' if len(changes) != 1 else ''} in "
        f"{len(scenes)} scene{'s' if len(scenes) != 1 else ''}"
    )


# --- the dist archive ----------------------------------------------------------------------------


def unpack_archive(archive: Path, into: Path) -> Path:
    """Check a dist archive whole and unpack it into `into`; return its results folder.

    Refused with one line: unreadable or truncated gzip/tar, a member that is not a plain file or
    leaves the archive's one classical-dynamics-<version>/ folder, a member missing from or not
    matching the SHA256SUMS inside, an archive not matching a SHA256SUMS beside it, no summaries.
    """
    archive = Path(archive)
    if not archive.is_file():  # each its own line: a typo, a folder given for an archive, a device
        if not archive.exists():
            raise VerifyError(f"{archive}: no such file")
        if archive.is_dir():
            raise VerifyError(f"{archive}: a folder, not a dist archive (.tar.gz made by snakemake -c1 dist)")
        raise VerifyError(f"{archive}: not a regular file (a device, pipe or socket), not a dist archive")
    digests, prefix = {}, None
    try:
        with tarfile.open(archive, "r:gz") as tar:
            for member in tar:
                path = PurePosixPath(member.name)
                top = path.parts[0] if path.parts else ""
                if prefix is None:
                    prefix = top
                    if not PREFIX.match(prefix):
                        raise VerifyError(f"{archive}: not a classical-dynamics archive (top folder {top!r})")
                if path.is_absolute() or ".." in path.parts or top != prefix or len(path.parts) < 2:
                    raise VerifyError(f"{archive}: member {member.name!r} is outside {prefix}/")
                if not member.isfile():
                    raise VerifyError(f"{archive}: member {member.name!r} is not a plain file")
                if member.name in digests:
                    raise VerifyError(f"{archive}: member {member.name!r} appears twice")
                data = tar.extractfile(member).read()
                digests[member.name] = hashlib.sha256(data).hexdigest()
                target = Path(into, *path.parts)
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_bytes(data)
    except (tarfile.TarError, EOFError, zlib.error, OSError) as error:
        what = "truncated" if isinstance(error, EOFError) else "not a readable tar.gz"
        raise VerifyError(f"{archive}: {what} ({error})") from None
    if prefix is None:
        raise VerifyError(f"{archive}: empty archive")
    listed = _read_sums(Path(into, prefix, "SHA256SUMS"), archive, prefix)
    for name, digest in digests.items():
        if name == f"{prefix}/SHA256SUMS":
            continue
        if name not in listed:
            raise VerifyError(f"{archive}: member {name} is not listed in its SHA256SUMS")
        if listed[name] != digest:
            raise VerifyError(f"{archive}: checksum mismatch for {name} (tampered or corrupted)")
    missing = sorted(listed.keys() - digests.keys())
    if missing:
        raise VerifyError(f"{archive}: {missing[0]} is listed in SHA256SUMS but missing (truncated?)")
    beside = archive.parent / "SHA256SUMS"  # the one dist writes next to the archive
    if beside.is_file():
        for line in beside.read_text(errors="replace").splitlines():
            digest, _, name = line.partition("  ")
            if name == archive.name and digest != sha256_file(archive):
                raise VerifyError(f"{archive}: checksum mismatch with {beside}")
    results = Path(into, prefix)
    try:
        scenes_of(results)
    except VerifyError:
        raise VerifyError(
            f"{archive}: not a classical-dynamics archive (no <study>/<scene>/summary.json)"
        ) from None
    return results


def _read_sums(path: Path, archive: Path, prefix: str) -> dict[str, str]:
    if not path.is_file():
        raise VerifyError(f"{archive}: not a classical-dynamics archive (no {prefix}/SHA256SUMS inside)")
    listed = {}
    for line in path.read_text(errors="replace").splitlines():
        digest, sep, name = line.partition("  ")
        if not sep or not re.fullmatch(r"[0-9a-f]{64}", digest):
            raise VerifyError(f"{archive}: malformed line in {prefix}/SHA256SUMS: {line[:60]!r}")
        # Members are named relative to <prefix>/ (earlier archives named them with the prefix).
        listed[name if name.startswith(prefix + "/") else f"{prefix}/{name}"] = digest
    return listed


# --- rebuilding ----------------------------------------------------------------------------------


def checkout_commit(root: Path) -> str:
    commit = git(root, "rev-parse", "HEAD")
    if commit is None:
        return "unknown (not a git checkout)"
    return commit + (" (dirty)" if git(root, "status", "--porcelain", "--untracked-files=no") else "")


def run_scene(root: Path, study: str, scene: str, quick: bool, out: Path) -> str | None:
    """Run one scene as the Snakemake scene rule does, with the checkout's code; an error line or None."""
    scene_file = root / "workflow" / "scenes" / study / f"{scene}.yaml"
    if not scene_file.is_file():
        return f"no scene file {scene_file.relative_to(root)} in the checkout"
    env = dict(os.environ)
    env["PYTHONPATH"] = str(root / "src") + os.pathsep + env.get("PYTHONPATH", "")
    command = [
        sys.executable,
        "-m",
        "classical_dynamics",
        "run",
        study,
        str(scene_file),
        str(out / study / scene),
        str(out / "timings" / study / scene),
    ] + (["--quick"] if quick else [])
    done = subprocess.run(command, cwd=root, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        lines = (done.stderr or done.stdout).strip().splitlines()
        return "rebuild failed: " + (lines[-1] if lines else f"exit status {done.returncode}")
    return None


def select(available: list[tuple[str, str]], wanted: str | None, archive: Path) -> list[tuple[str, str]]:
    """--scenes "study/scene,study,...": the archive's scenes it names (all when not given)."""
    if not wanted:
        return available
    chosen = []
    for item in filter(None, (w.strip() for w in wanted.split(","))):
        matches = [s for s in available if "/".join(s) == item or s[0] == item]
        if not matches:
            raise VerifyError(f"{archive}: has no scene {item!r}")
        chosen += [m for m in matches if m not in chosen]
    return chosen


def verify(
    archive: Path, root: Path, scenes: str | None = None, quick: bool | None = None, cores: int = 1, out=None
) -> int:
    """Rebuild the archive's scenes with the checkout at root and compare: 0 all held, 1 something moved."""
    out = out or sys.stdout
    root = Path(root).resolve()
    with tempfile.TemporaryDirectory(prefix="classical-dynamics-verify-") as tmp:
        archived = unpack_archive(archive, Path(tmp, "archive"))  # the archive is checked first
        if not (root / "workflow" / "scenes").is_dir():
            raise VerifyError(f"{root}: not a checkout of this project (no workflow/scenes)")
        chosen = select(scenes_of(archived), scenes, archive)
        provenance = {s: read_provenance(archived, *s) for s in chosen}
        # A step drawn from other scenes' results (the self-excited gallery) is no scene: rebuilding its
        # input scenes checks what it draws, so it is named, not rerun.
        derived = [s for s in chosen if "input_scenes" in provenance[s]]
        chosen = [s for s in chosen if s not in derived]
        provenance = {s: provenance[s] for s in chosen}
        modes = {}
        for (study, scene), record in provenance.items():
            modes[study, scene] = quick if quick is not None else record.get("quick")
            if modes[study, scene] is None:
                raise VerifyError(
                    f"{archive}: provenance of {study}/{scene} does not say whether it was a "
                    "quick build; pass --quick or --full"
                )
        notes = _input_notes(root, provenance)
        rebuilt = Path(tmp, "rebuilt")
        with ThreadPoolExecutor(max(1, cores)) as pool:
            errors = dict(zip(chosen, pool.map(lambda s: run_scene(root, *s, modes[s], rebuilt), chosen)))
        failed = [s for s in chosen if errors[s]]
        ok = [s for s in chosen if not errors[s]]
        changes = compare(read_numbers(archived, ok), read_numbers(rebuilt, ok))
        kinds = sorted({"quick" if q else "full" for q in modes.values()})
        print(
            f"verify {Path(archive).name}: {len(chosen)} scene{'s' if len(chosen) != 1 else ''} "
            f"({' and '.join(kinds)} build) rebuilt with the checkout at {root}",
            file=out,
        )
        for note in notes:
            print(f"note: {note}", file=out)
        for study, scene in derived:
            print(
                f"note: {study}/{scene} is drawn from other scenes' results; not rebuilt (its input scenes "
                "are)",
                file=out,
            )
        for study, scene in failed:
            print(f"FAILED {study}/{scene}: {errors[study, scene]}", file=out)
        if changes:
            print(table(changes, "archived", "rebuilt", tolerance=True), file=out)
            print(f"MOVED: {_count(changes)} outside tolerance", file=out)
        if failed:
            print(f"FAILED: {len(failed)} scene{'s' if len(failed) != 1 else ''} not rebuilt", file=out)
        if not changes and not failed:
            total = len(read_numbers(archived, ok))
            print(
                f"OK: all {total} numbers of {len(ok)} scene{'s' if len(ok) != 1 else ''} reproduced "
                "within tolerance",
                file=out,
            )
            return 0
        return 1


def _input_notes(root: Path, provenance: dict) -> list[str]:
    """What differs in the inputs: the checkout's commit, and scene files edited since the archive."""
    notes = []
    commits = sorted(
        {
            str(p.get("commit", "unknown")) + (" (dirty)" if p.get("dirty") else "")
            for p in provenance.values()
        }
    )
    here = checkout_commit(root)
    if commits != [here]:
        notes.append(f"archive built at commit {', '.join(commits)}; checkout at {here}")
    for (study, scene), record in provenance.items():
        path = root / "workflow" / "scenes" / study / f"{scene}.yaml"
        if path.is_file() and sha256_file(path) != record.get("scene_sha256"):
            notes.append(
                f"{study}/{scene}: scene file changed since the archive "
                f"(sha256 {str(record.get('scene_sha256'))[:12]} -> {sha256_file(path)[:12]})"
            )
    return notes


# --- diff ----------------------------------------------------------------------------------------


def diff(a: Path, b: Path, out=None) -> int:
    """Every number that changed between two builds (folders or dist archives): 0 none, 1 some."""
    out = out or sys.stdout
    with (
        tempfile.TemporaryDirectory(prefix="classical-dynamics-diff-") as tmp_a,
        tempfile.TemporaryDirectory(prefix="classical-dynamics-diff-") as tmp_b,
    ):
        folder_a = unpack_archive(a, Path(tmp_a)) if Path(a).is_file() else Path(a)
        folder_b = unpack_archive(b, Path(tmp_b)) if Path(b).is_file() else Path(b)
        scenes_a, scenes_b = set(scenes_of(folder_a)), set(scenes_of(folder_b))
        both = sorted(scenes_a & scenes_b)
        changes = [
            Change(
                "/".join(s),
                "(whole scene)",
                "present" if s in scenes_a else MISSING,
                "present" if s in scenes_b else MISSING,
                "exact",
            )
            for s in sorted(scenes_a ^ scenes_b)
        ]
        changes += compare(read_numbers(folder_a, both), read_numbers(folder_b, both), exact=True)
        if not changes:
            print(
                f"no numbers changed ({len(read_numbers(folder_a, both))} numbers in {len(both)} scenes)",
                file=out,
            )
            return 0
        print(table(changes, "A", "B", tolerance=False), file=out)
        print(f"changed: {_count(changes)} (A = {a}, B = {b})", file=out)
        return 1
