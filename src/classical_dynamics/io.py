"""Atomic, deterministic writing of results files.

Every write goes to a temporary name in the same folder and is renamed into place,
so an interrupted build never leaves a half-written file that looks finished.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import io as _io
import json
import math
import os
import shutil
import stat
import tempfile
from pathlib import Path

import numpy as np

from . import limits

SIGNIFICANT_DIGITS = 15  # stored values keep 15 significant figures: stable across runs, ample for reporting


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def make_shareable(path: Path | str, directory: bool = False) -> None:
    """mkstemp/mkdtemp create private (0600/0700) paths; results are ordinary files."""
    os.chmod(path, (0o777 if directory else 0o666) & ~_umask())


# A full disk (or quota) is a condition the user fixes, said in one line naming the file (no_space_line).
NO_SPACE = (errno.ENOSPC, errno.EDQUOT)
RO_CRATE = "ro-crate-metadata.json"  # an archive's RO-Crate (report/crate.py writes it, verify reads it)


def no_space_line(error: BaseException) -> str | None:
    """The one line for a write that found the disk full, naming the file; None for any other error."""
    if isinstance(error, OSError) and error.errno in NO_SPACE:
        return (
            f"{error.filename or 'a file'}: no space left on device; nothing half-written was kept: free "
            "some space and run again"
        )
    return None


def _named(error: OSError, path: Path) -> OSError:
    """A full disk's error named for the file being written (a write's own error names no file)."""
    return OSError(error.errno, os.strerror(error.errno), str(path))


class _FdSink:
    """A file descriptor as a writable file object: every byte through os.write, none left in a buffer
    (so a full disk is met by the write that fills it, not later by a close)."""

    def __init__(self, fd: int):
        self.fd = fd

    def write(self, data) -> int:
        view = memoryview(data).cast("B")
        while view:
            view = view[os.write(self.fd, view) :]
        return len(data)

    def flush(self) -> None:
        pass


@contextlib.contextmanager
def atomic_writer(path: Path | str):
    """A binary file object whose bytes become `path` only when the block ends without an error; on any
    error (a full disk included) the temporary file is removed and the previous `path` is left as it was."""
    path = Path(path)
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        for leftover in path.parent.glob(f".{path.name}.*.tmp"):  # a write of this file that was killed
            leftover.unlink(missing_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        try:
            yield _FdSink(fd)
        finally:
            os.close(fd)
        make_shareable(tmp)
        os.replace(tmp, path)
    except BaseException as error:
        if tmp is not None:
            Path(tmp).unlink(missing_ok=True)
        if isinstance(error, OSError) and error.errno in NO_SPACE:
            raise _named(error, path) from None
        raise


def atomic_write_bytes(path: Path | str, data: bytes) -> None:
    with atomic_writer(path) as handle:
        handle.write(data)


def write_new_file(path: Path | str, data: bytes) -> None:
    """A file in a folder being staged (not yet in place): created, written whole, or an error naming it."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    try:
        _FdSink(fd).write(data)
    except OSError as error:
        if error.errno in NO_SPACE:
            raise _named(error, Path(path)) from None
        raise
    finally:
        os.close(fd)


def atomic_write_text(path: Path | str, text: str) -> None:
    atomic_write_bytes(path, text.encode("utf-8"))


def _plain(value):
    """Convert numpy scalars/arrays to JSON-ready Python values, rounding floats to 15 digits."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, np.ndarray)):
        return [_plain(v) for v in value]
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        value = float(value)
        if not math.isfinite(value):
            return None if math.isnan(value) else ("inf" if value > 0 else "-inf")
        return float(f"{value:.{SIGNIFICANT_DIGITS}g}")
    return value


def dumps_json(data) -> str:
    return json.dumps(_plain(data), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def write_json(path: Path | str, data) -> None:
    atomic_write_text(path, dumps_json(data))


def read_json(path: Path | str):
    return json.loads(Path(path).read_text(encoding="utf-8"))


# --- reading what a user hands in (verify, diff, dist): bounded whatever the file ---------------------------


def _size(count: int) -> str:
    return f"{count / (1 << 20):.0f} MiB" if count >= 1 << 20 else f"{count} bytes"


def regular_size(path: Path | str, limit: int) -> int:
    """A regular file's size; ValueError for what is not a regular file or is over `limit` bytes."""
    info = os.stat(path)
    if not stat.S_ISREG(info.st_mode):
        raise ValueError("not a regular file (a folder, device, pipe or socket)")
    if info.st_size > limit:
        raise ValueError(f"{_size(info.st_size)}, over the limit of {_size(limit)} (limits.py)")
    return info.st_size


def read_chunks(path: Path | str, limit: int | None = None):
    """A regular file's bytes in pieces of limits.READ_CHUNK_BYTES; ValueError (one line, no path) for what is
    not a regular file (a device such as /dev/zero never ends) or is over `limit` bytes."""
    limit = limits.MAX_MEMBER_BYTES if limit is None else limit
    regular_size(path, limit)
    seen = 0
    with open(path, "rb") as handle:
        while chunk := handle.read(limits.READ_CHUNK_BYTES):
            seen += len(chunk)
            if seen > limit:  # grew while read
                raise ValueError(f"over the limit of {_size(limit)} (limits.py)")
            yield chunk


def sha256_bounded(path: Path | str, limit: int | None = None) -> str:
    digest = hashlib.sha256()
    for chunk in read_chunks(path, limit):
        digest.update(chunk)
    return digest.hexdigest()


def _finite(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"number {text[:20]}{'…' if len(text) > 20 else ''} is out of a float's range")
    return value


def _bounded_int(text: str) -> int:
    digits = len(text.lstrip("-"))
    if digits > limits.MAX_INT_DIGITS:
        raise ValueError(f"an integer of {digits} digits (limits.MAX_INT_DIGITS: {limits.MAX_INT_DIGITS})")
    return int(text)


def _no_constant(name: str):
    raise ValueError(f"{name} is not a JSON number (results store NaN as null)")


def loads_checked(data: bytes):
    """JSON as a results file holds it, or ValueError (one line): UTF-8, finite numbers, integers of at most
    limits.MAX_INT_DIGITS digits, nesting at most limits.MAX_JSON_DEPTH deep."""
    try:
        value = json.loads(
            data.decode("utf-8"), parse_float=_finite, parse_int=_bounded_int, parse_constant=_no_constant
        )
    except RecursionError:
        raise ValueError(
            f"nested deeper than {limits.MAX_JSON_DEPTH} levels (limits.MAX_JSON_DEPTH)"
        ) from None
    stack = [(value, 0)]
    while stack:  # without recursion: the parser's own limit is the interpreter's, far above ours
        item, depth = stack.pop()
        if isinstance(item, (dict, list)):
            if depth >= limits.MAX_JSON_DEPTH:
                raise ValueError(f"nested deeper than {limits.MAX_JSON_DEPTH} levels (limits.MAX_JSON_DEPTH)")
            stack.extend((child, depth + 1) for child in (item.values() if isinstance(item, dict) else item))
    return value


def read_json_checked(path: Path | str):
    """A results file's JSON, bounded in size (limits.MAX_JSON_BYTES) and shape (loads_checked)."""
    return loads_checked(b"".join(read_chunks(path, limits.MAX_JSON_BYTES)))


def csv_text(frame) -> str:
    """A tidy table as CSV text with 15 significant figures (deterministic)."""
    buffer = _io.StringIO()
    frame.to_csv(buffer, index=False, float_format=f"%.{SIGNIFICANT_DIGITS}g", lineterminator="\n")
    return buffer.getvalue()


def write_csv(path: Path | str, frame) -> None:
    atomic_write_text(path, csv_text(frame))


def svg_bytes(figure) -> bytes:
    """A matplotlib figure as deterministic SVG (fixed hash salt, no date)."""
    import matplotlib

    buffer = _io.BytesIO()
    with matplotlib.rc_context({"svg.hashsalt": "classical-dynamics", "svg.fonttype": "path"}):
        figure.savefig(buffer, format="svg", metadata={"Date": None}, bbox_inches="tight", pad_inches=0.03)
    return buffer.getvalue()


def write_svg(path: Path | str, figure) -> None:
    atomic_write_bytes(path, svg_bytes(figure))


def replace_directory(staging: Path, target: Path) -> None:
    """Move a finished staging folder into place; an older target is removed first."""
    target = Path(target)
    make_shareable(staging, directory=True)
    if target.exists():
        shutil.rmtree(target)
    os.replace(staging, target)


# --- results folders: whole or refused ----------------------------------------------------------------------


class ResultError(ValueError):
    """A results folder that is incomplete or corrupted. str(error) is one line naming the file."""


def file_digests(files: dict[str, bytes]) -> dict[str, str]:
    """{name: sha256} of a results folder's files: provenance.json records them, written with them."""
    return {name: hashlib.sha256(data).hexdigest() for name, data in sorted(files.items())}


def is_staging(path: Path | str) -> bool:
    """A folder or file being written (or left by a kill): hidden, never a result."""
    return Path(path).name.startswith(".")


def result_folders(study_dir: Path | str) -> list[Path]:
    """The finished scene folders of results/<study>/ (staging folders and timings left out), sorted."""
    return sorted(
        p.parent
        for p in Path(study_dir).glob("*/summary.json")
        if not is_staging(p.parent) and p.parent.name != "timings"
    )


def check_result_folder(folder: Path | str) -> dict:
    """The folder's provenance, once every file it lists is there with its recorded SHA-256; ResultError names
    the first file that is not."""
    folder = Path(folder)
    try:
        provenance = read_json_checked(folder / "provenance.json")
    except (OSError, ValueError) as error:
        raise ResultError(
            f"{folder}/provenance.json: unreadable or not JSON ({error}); rebuild the scene"
        ) from None
    digests = provenance.get("files") if isinstance(provenance, dict) else None
    if not isinstance(digests, dict) or "summary.json" not in digests:
        raise ResultError(
            f"{folder}/provenance.json: lists no file checksums (written by an older version or cut "
            "short); rebuild the scene"
        )
    for name in sorted(digests):
        parts = Path(name).parts
        if Path(name).is_absolute() or ".." in parts or not parts:  # it names files of this folder only
            raise ResultError(f"{folder}/provenance.json: lists {name[:60]!r}, not a file of its folder")
        try:
            digest = sha256_bounded(folder / name)
        except FileNotFoundError:
            raise ResultError(
                f"{folder}/{name}: missing (listed in provenance.json); rebuild the scene"
            ) from None
        except (OSError, ValueError) as error:
            raise ResultError(f"{folder}/{name}: unreadable ({error}); rebuild the scene") from None
        if digest != digests[name]:
            raise ResultError(
                f"{folder}/{name}: does not match its checksum in provenance.json (truncated or "
                "edited); rebuild the scene"
            )
    return provenance


def stale_reason(folder: Path | str, scene_file: Path | str, quick: bool) -> str | None:
    """Why a scene's results folder no longer belongs to its scene, or None: a file missing or not matching
    the checksum its provenance records, a scene file whose bytes differ from those the results were built
    from (whatever the file times say: a scene restored with `cp -p` keeps its old time), or a quick build
    where a full one is asked for (or the reverse). Read by the workflow when it decides what to rerun."""
    try:
        provenance = check_result_folder(folder)
    except ResultError as error:
        return str(error)
    try:
        scene_sha256 = hashlib.sha256(Path(scene_file).read_bytes()).hexdigest()
    except OSError:
        return None  # no scene: the workflow says so itself
    if provenance.get("scene_sha256") != scene_sha256:
        return f"{folder}: built from other bytes of {scene_file} than it has now (provenance's scene_sha256)"
    if bool(provenance.get("quick")) != bool(quick):
        built, asked = ("quick", "full") if provenance.get("quick") else ("full", "quick")
        return f"{folder}: built as a {built} build; a {asked} build is asked for"
    return None
