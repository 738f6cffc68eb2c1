"""A citable archive of the report and its results, with a SHA256SUMS manifest."""

from __future__ import annotations

import gzip
import hashlib
import io as _io
import tarfile
from pathlib import Path

from .. import io

INCLUDE = ("report.html", "report.pdf")
SUFFIXES = {".json", ".csv", ".svg"}


def archive_members(results_dir: Path) -> list[Path]:
    results_dir = Path(results_dir)
    members = [results_dir / name for name in INCLUDE]
    for path in sorted(results_dir.rglob("*")):
        rel = path.relative_to(results_dir)
        if path.is_file() and path.suffix in SUFFIXES and rel.parts[0] not in ("dist", "logs"):
            members.append(path)
    return members


def make_archive(results_dir: Path, archive: Path) -> None:
    """Deterministic tar.gz (sorted, fixed times and owners) plus SHA256SUMS of its members."""
    results_dir, archive = Path(results_dir), Path(archive)
    prefix = archive.name.removesuffix(".tar.gz")
    members = archive_members(results_dir)
    sums = []
    buffer = _io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w", format=tarfile.PAX_FORMAT) as tar:
        for path in members:
            data = path.read_bytes()
            rel = path.relative_to(results_dir).as_posix()
            sums.append(f"{hashlib.sha256(data).hexdigest()}  {prefix}/{rel}")
            info = tarfile.TarInfo(f"{prefix}/{rel}")
            info.size, info.mtime, info.mode, info.uid, info.gid = len(data), 0, 0o644, 0, 0
            tar.addfile(info, _io.BytesIO(data))
        manifest = ("\n".join(sums) + "\n").encode()
        info = tarfile.TarInfo(f"{prefix}/SHA256SUMS")
        info.size, info.mtime, info.mode = len(manifest), 0, 0o644
        tar.addfile(info, _io.BytesIO(manifest))
    compressed = gzip.compress(buffer.getvalue(), mtime=0)
    io.atomic_write_bytes(archive, compressed)
    archive_sum = hashlib.sha256(compressed).hexdigest()
    io.atomic_write_text(archive.parent / "SHA256SUMS", manifest.decode() + f"{archive_sum}  {archive.name}\n")
