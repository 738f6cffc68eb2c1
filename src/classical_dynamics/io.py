"""Atomic, deterministic writing of results files.

Every write goes to a temporary name in the same folder and is renamed into place,
so an interrupted build never leaves a half-written file that looks finished.
"""

from __future__ import annotations

import hashlib
import io as _io
import json
import math
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

SIGNIFICANT_DIGITS = 15  # stored values keep 15 significant figures: stable across runs, ample for reporting


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def make_shareable(path: Path | str, directory: bool = False) -> None:
    """mkstemp/mkdtemp create private (0600/0700) paths; results are ordinary files."""
    os.chmod(path, (0o777 if directory else 0o666) & ~_umask())


def atomic_write_bytes(path: Path | str, data: bytes) -> None:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    for leftover in path.parent.glob(f".{path.name}.*.tmp"):  # a write of this file that was killed
        leftover.unlink(missing_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        make_shareable(tmp)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


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
        provenance = json.loads((folder / "provenance.json").read_bytes())
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
        try:
            data = (folder / name).read_bytes()
        except OSError:
            raise ResultError(
                f"{folder}/{name}: missing (listed in provenance.json); rebuild the scene"
            ) from None
        if hashlib.sha256(data).hexdigest() != digests[name]:
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
