"""Check a cited number: rebuild a dist archive and compare every number with it, or compare two builds.

Both read only the results contract (docs/design.md): the numbers of results/<study>/<scene>/summary.json
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

import contextlib
import gzip
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

from . import io, limits
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
    """Bounded whatever the file (io.read_json_checked): a hostile one is one line, never a traceback."""
    try:
        return io.read_json_checked(path)
    except (OSError, ValueError) as error:
        raise VerifyError(f"{path}: unreadable or not JSON: {error}") from None


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
        cases = summary.get("stability") or []
        if not isinstance(cases, list) or not all(isinstance(c, dict) and "name" in c for c in cases):
            raise VerifyError(f"{path}: 'stability' is not a list of hard cases with names")
        for case in cases:
            numbers[study, scene, f"hard_case:{case['name']}"] = {
                "value": case.get("measured"),
                "unit": case.get("unit", ""),
            }
    return numbers


def read_provenance(folder: Path, study: str, scene: str) -> dict:
    path = Path(folder) / study / scene / "provenance.json"
    if not path.is_file():
        raise VerifyError(f"{path}: missing (every scene carries its provenance)")
    record = _read_json(path)
    if not isinstance(record, dict):
        raise VerifyError(f"{path}: not a provenance record (a JSON object)")
    return record


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


class _CappedReads:
    """The unpacked gzip stream as tarfile reads it, refusing any one read over limits.MAX_TAR_HEADER_BYTES:
    tarfile reads a header's own data (a long name, PAX records) whole, whatever size the header declares."""

    def __init__(self, raw, archive: Path):
        self.raw, self.archive = raw, archive

    def read(self, size=-1):
        if size is None or size < 0 or size > limits.MAX_TAR_HEADER_BYTES:
            raise VerifyError(
                f"{self.archive}: a tar header of {size} bytes, over the limit of "
                f"{limits.MAX_TAR_HEADER_BYTES} (limits.MAX_TAR_HEADER_BYTES); not unpacked"
            )
        return self.raw.read(size)

    def seek(self, *args):
        return self.raw.seek(*args)

    def tell(self):
        return self.raw.tell()


def _not_an_archive(given: Path) -> str | None:
    """Why what is given is no archive file, in its own words: a typo, a folder, a device; None for a file."""
    if given.is_file():
        return None
    if not given.exists():
        return f"{given}: no such file"
    if given.is_dir():
        return f"{given}: a folder, not a dist archive (.tar.gz made by snakemake -c1 dist)"
    return f"{given}: not a regular file (a device, pipe or socket), not a dist archive"


def _checked_members(archive: Path, tar):
    """The archive's members, each refused with one line from its header alone: past the member count, the
    size of one or of all (limits.py), not a plain file, leaving the one top folder, or named twice."""
    names, prefix, total = set(), None, 0
    while (member := tar.next()) is not None:
        tar.members.clear()  # one header held at a time, not every one read
        if len(names) >= limits.MAX_MEMBERS:
            raise VerifyError(
                f"{archive}: more than {limits.MAX_MEMBERS} members (limits.MAX_MEMBERS); not unpacked"
            )
        path = PurePosixPath(member.name)
        top = path.parts[0] if path.parts else ""
        if prefix is None:
            prefix = top
            if not PREFIX.match(prefix):
                raise VerifyError(f"{archive}: not a classical-dynamics archive (top folder {top[:60]!r})")
        if path.is_absolute() or ".." in path.parts or top != prefix or len(path.parts) < 2:
            raise VerifyError(f"{archive}: member {member.name[:80]!r} is outside {prefix}/")
        if not member.isfile():
            raise VerifyError(f"{archive}: member {member.name!r} is not a plain file")
        if member.name in names:
            raise VerifyError(f"{archive}: member {member.name!r} appears twice")
        if member.size > limits.MAX_MEMBER_BYTES:
            raise VerifyError(
                f"{archive}: member {member.name!r} is {io._size(member.size)}, over the limit of "
                f"{io._size(limits.MAX_MEMBER_BYTES)} (limits.MAX_MEMBER_BYTES); not unpacked"
            )
        total += member.size
        if total > limits.MAX_ARCHIVE_BYTES:
            raise VerifyError(
                f"{archive}: members of more than {io._size(limits.MAX_ARCHIVE_BYTES)} in all, over the "
                "limit (limits.MAX_ARCHIVE_BYTES); not unpacked"
            )
        names.add(member.name)
        yield prefix, path, member
    if prefix is None:
        raise VerifyError(f"{archive}: empty archive")


@contextlib.contextmanager
def _tar(archive: Path):
    with gzip.open(archive, "rb") as raw, tarfile.open(fileobj=_CappedReads(raw, archive), mode="r:") as tar:
        yield tar


def _unpack_members(archive: Path, into: Path) -> tuple[str, dict[str, str]]:
    """Stream the archive's members into `into`, each hashed as it is written, none held whole in memory:
    (its one top folder, {member name: sha256}). Every header is read and checked first (_checked_members,
    about 0.3 s for a full build's archive), so that a hostile archive is refused before a byte is written."""
    with _tar(archive) as tar:
        for _ in _checked_members(archive, tar):
            pass
    digests, prefix = {}, None
    with _tar(archive) as tar:  # checked again as it is unpacked: the file may have changed since
        for prefix, path, member in _checked_members(archive, tar):
            target = Path(into, *path.parts)
            target.parent.mkdir(parents=True, exist_ok=True)
            digest, source = hashlib.sha256(), tar.extractfile(member)
            with open(target, "wb") as out:
                while chunk := source.read(limits.READ_CHUNK_BYTES):
                    digest.update(chunk)
                    out.write(chunk)
            digests[member.name] = digest.hexdigest()
    return prefix, digests


def unpack_archive(archive: Path, into: Path) -> Path:
    """Check a dist archive whole and unpack it into `into`; return its results folder, checked as any results
    folder is (check_results).

    Refused with one line: what is not an archive file (each its own line), unreadable or truncated
    gzip/tar, a member over limits.py's bounds (count, size, total), not a plain file or leaving the archive's
    one classical-dynamics-<version>/ folder, a member missing from or not matching the SHA256SUMS inside,
    an RO-Crate missing or disagreeing with that SHA256SUMS, an archive not matching a SHA256SUMS beside it,
    no summaries.
    """
    archive = Path(archive)
    if why := _not_an_archive(archive):
        raise VerifyError(why)
    if archive.stat().st_size > limits.MAX_ARCHIVE_BYTES:
        raise VerifyError(
            f"{archive}: {io._size(archive.stat().st_size)}, over the limit of "
            f"{io._size(limits.MAX_ARCHIVE_BYTES)} for an archive (limits.MAX_ARCHIVE_BYTES)"
        )
    try:
        prefix, digests = _unpack_members(archive, into)
    except OSError as error:
        if error.errno in io.NO_SPACE:  # unpacking, not the archive: the temporary folder's disk is full
            raise OSError(error.errno, error.strerror, str(into)) from None
        raise VerifyError(f"{archive}: not a readable tar.gz ({error})") from None
    except (tarfile.TarError, zlib.error) as error:
        raise VerifyError(f"{archive}: not a readable tar.gz ({error})") from None
    except EOFError as error:
        raise VerifyError(f"{archive}: truncated ({error})") from None
    except RecursionError:  # a chain of extended headers, each read by tarfile through the next
        raise VerifyError(f"{archive}: not a readable tar.gz (headers chained too deep)") from None
    results = Path(into, prefix)
    if f"{prefix}/SHA256SUMS" not in digests:
        raise VerifyError(f"{archive}: not a classical-dynamics archive (no {prefix}/SHA256SUMS inside)")
    digests = {name.removeprefix(prefix + "/"): digest for name, digest in digests.items()}
    _check_sums(archive, results, digests, complete=True)
    _check_crate(archive, results, digests)
    beside = archive.parent / "SHA256SUMS"  # the one dist writes next to the archive
    if beside.is_file():
        for line in _read_lines(beside, archive):
            digest, _, name = line.partition("  ")
            if name == archive.name and digest != io.sha256_bounded(archive, limits.MAX_ARCHIVE_BYTES):
                raise VerifyError(f"{archive}: checksum mismatch with {beside}")
    try:
        scenes_of(results)
    except VerifyError:
        raise VerifyError(
            f"{archive}: not a classical-dynamics archive (no <study>/<scene>/summary.json)"
        ) from None
    check_results(results, archive)
    return results


def _check_crate(label: Path, folder: Path, digests: dict[str, str]) -> None:
    """The archive's RO-Crate (report/crate.py), read back through rocrate, against its members (which
    _check_sums found to be those SHA256SUMS lists): every member but SHA256SUMS and the crate is a File of
    the crate with the same SHA-256, every File of the crate with a SHA-256 is a member, and the crate's
    mainEntity, the workflow, is one of them. Read bounded (io.read_json_checked); whatever rocrate makes of
    a hostile crate is one line."""
    name = f"{folder.name}/{io.RO_CRATE}"
    if io.RO_CRATE not in digests:
        raise VerifyError(f"{label}: no {name} inside (every dist archive carries its RO-Crate)")
    metadata = _read_json(folder / io.RO_CRATE)
    try:
        from rocrate.rocrate import ROCrate

        crate = ROCrate(metadata)
        files = {}
        for entity in crate.data_entities:
            types = entity.type if isinstance(entity.type, list) else [entity.type]
            if "File" in types:
                files[entity.id] = entity.get("sha256")
        main = crate.mainEntity
        main = main.id if main is not None else None
    except Exception as error:  # rocrate's own refusals are of many kinds: any is one line here
        raise VerifyError(
            f"{label}: {name} is not an RO-Crate ({type(error).__name__}: {str(error)[:80]})"
        ) from None
    for member in sorted(digests):
        if member in ("SHA256SUMS", io.RO_CRATE):
            continue
        if member not in files:
            raise VerifyError(
                f"{label}: {name} disagrees with SHA256SUMS: {member} is not a File of the crate"
            )
        if files[member] != digests[member]:
            raise VerifyError(
                f"{label}: {name} disagrees with SHA256SUMS for {member} (crate sha256 "
                f"{str(files[member])[:12]}, SHA256SUMS {digests[member][:12]})"
            )
    for entity_id, digest in sorted(files.items(), key=lambda item: str(item[0])):
        if digest is not None and entity_id not in digests:
            raise VerifyError(f"{label}: {name} lists {str(entity_id)[:60]!r}, which SHA256SUMS does not")
    if main is None or main not in digests:
        raise VerifyError(f"{label}: {name} names no workflow of the archive as its mainEntity")


def _read_lines(path: Path, label: Path) -> list[str]:
    try:
        data = b"".join(io.read_chunks(path, limits.MAX_MANIFEST_BYTES))
    except (OSError, ValueError) as error:
        raise VerifyError(f"{label}: {path.name} unreadable ({error})") from None
    return data.decode("utf-8", errors="replace").splitlines()


def _check_sums(label: Path, folder: Path, digests: dict[str, str], complete: bool) -> None:
    """The files of a results folder against the SHA256SUMS inside it, for an archive (digests: each member's,
    taken as it was unpacked; complete: every member must be listed) and for a folder (each listed file's,
    read now). Names are relative to the folder (earlier archives named them with the prefix)."""
    listed = {}
    for line in _read_lines(folder / "SHA256SUMS", label):
        digest, sep, name = line.partition("  ")
        if not sep or not re.fullmatch(r"[0-9a-f]{64}", digest):
            raise VerifyError(f"{label}: malformed line in SHA256SUMS: {line[:60]!r}")
        listed[name.removeprefix(folder.name + "/")] = digest
    if complete:
        for name in digests:
            if name != "SHA256SUMS" and name not in listed:
                raise VerifyError(f"{label}: member {folder.name}/{name} is not listed in its SHA256SUMS")
    for name in sorted(listed):
        digest = digests.get(name)
        if digest is None and not complete:
            parts = PurePosixPath(name).parts
            if PurePosixPath(name).is_absolute() or ".." in parts or not parts:
                raise VerifyError(f"{label}: SHA256SUMS lists {name[:60]!r}, outside the folder")
            try:
                digest = io.sha256_bounded(folder / name)
            except FileNotFoundError:
                digest = None
            except (OSError, ValueError) as error:
                raise VerifyError(f"{label}: {name} unreadable ({error})") from None
        if digest is None:
            raise VerifyError(
                f"{label}: {folder.name}/{name} is listed in SHA256SUMS but missing (truncated?)"
            )
        if digest != listed[name]:
            raise VerifyError(f"{label}: checksum mismatch for {folder.name}/{name} (tampered or corrupted)")


def check_results(folder: Path, archive: Path | None = None) -> list[tuple[str, str]]:
    """A results folder's scenes, once each is whole: every scene folder's files match the checksums its
    provenance records (as dist requires to pack it). The one check of archives (after their SHA256SUMS) and
    folders alike; an unpacked archive's files are named as members of `archive`."""
    scenes = scenes_of(folder)
    for study, scene in scenes:
        try:
            io.check_result_folder(Path(folder, study, scene))
        except io.ResultError as error:
            line = str(error).removesuffix("; rebuild the scene")
            if archive is not None:
                line = f"{archive}: member {line.removeprefix(str(folder.parent) + '/')}"
            raise VerifyError(line) from None
    return scenes


@contextlib.contextmanager
def _members_named(*unpacked: tuple[Path, Path]):
    """A refusal that names a file unpacked from an archive (given, into) names it as the archive's member,
    not by the temporary path that is gone when the command ends."""
    try:
        yield
    except VerifyError as error:
        line = str(error)
        for given, into in unpacked:
            line = line.replace(f"{into}/", f"{given}: member ")
        raise VerifyError(line) from None


def open_results(given: Path, into: Path, check: bool = True) -> Path:
    """The results folder a user names: a dist archive, checked and unpacked into `into`, or a results folder
    (or an unpacked archive), checked in place unless check=False (diff compares a folder edited by hand)."""
    given = Path(given)
    if not given.is_dir():
        return unpack_archive(given, into)
    if not any(given.glob("*/*/summary.json")):
        raise VerifyError(
            f"{given}: a folder, but not a results folder (no <study>/<scene>/summary.json) nor an archive"
        )
    if check:
        if (given / "SHA256SUMS").exists():  # an unpacked archive
            _check_sums(given, given, {}, complete=False)
        check_results(given)
    return given


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
    with (
        tempfile.TemporaryDirectory(prefix="classical-dynamics-verify-") as tmp,
        _members_named((archive, Path(tmp, "archive"))),
    ):
        archived = open_results(archive, Path(tmp, "archive"))  # the archive (or folder) is checked first
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
        archived_numbers = read_numbers(archived, chosen)  # a bad summary is refused before any rebuild
        rebuilt = Path(tmp, "rebuilt")
        with ThreadPoolExecutor(max(1, cores)) as pool:
            errors = dict(zip(chosen, pool.map(lambda s: run_scene(root, *s, modes[s], rebuilt), chosen)))
        failed = [s for s in chosen if errors[s]]
        ok = [s for s in chosen if not errors[s]]
        changes = compare(
            {k: v for k, v in archived_numbers.items() if k[:2] in ok}, read_numbers(rebuilt, ok)
        )
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
            total = sum(k[:2] in ok for k in archived_numbers)
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
        _members_named((a, Path(tmp_a)), (b, Path(tmp_b))),
    ):
        # folders as they are (diff shows what an edit changed); archives checked whole
        folder_a = open_results(a, Path(tmp_a), check=False)
        folder_b = open_results(b, Path(tmp_b), check=False)
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
