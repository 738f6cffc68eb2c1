"""Citable archives of the results, with SHA256SUMS manifests.

Two archives, both deterministic: the results archive (every summary, table, figure and provenance
record, no report) is made before the report, which prints its SHA-256 so that a citation pins every
number; the dist archive adds the report itself (whose own SHA-256 it cannot contain).
"""

from __future__ import annotations

import argparse
import hashlib
import io as _io
import tarfile
import zlib
from pathlib import Path

from .. import io, limits
from . import crate

INCLUDE = ("report.html", "report.pdf")
SUFFIXES = {".json", ".csv", ".svg", ".yaml", ".py"}  # .yaml: each scene's file; .py: measured/'s scripts


def results_archive_name(results_dir: Path, root: Path = Path(".")) -> Path:
    """results/dist/<name>-<version>-results.tar.gz: the archive whose SHA-256 the report prints."""
    project = _project(root)
    return Path(results_dir) / "dist" / f"{project['name']}-{project['version']}-results.tar.gz"


def archive_members(results_dir: Path, with_report: bool = True) -> list[Path]:
    """The files to archive: nothing being written (hidden staging folders and files), and only scene folders
    that match the checksums their provenance records (io.ResultError names the first that does not)."""
    results_dir = Path(results_dir)
    members = [results_dir / name for name in INCLUDE] if with_report else []
    for path in sorted(results_dir.rglob("*")):
        rel = path.relative_to(results_dir)
        if (
            path.is_file()
            and path.suffix in SUFFIXES
            and rel.parts[0] not in ("dist", "logs")
            and not any(io.is_staging(part) for part in rel.parts)
        ):
            members.append(path)
    for folder in {p.parent for p in members if p.name == "summary.json"}:
        io.check_result_folder(folder)
    return members


class _Hashing:
    """A file object passed through, hashing every byte read from it or written to it."""

    def __init__(self, inner):
        self.inner, self.digest = inner, hashlib.sha256()

    def read(self, size=-1):
        data = self.inner.read(size)
        self.digest.update(data)
        return data

    def write(self, data):
        self.digest.update(data)
        return self.inner.write(data)

    def flush(self):
        self.inner.flush()


class _Gzip:
    """gzip as a stream, byte for byte what gzip.compress(data, level, mtime=0) makes of the whole (zlib's own
    gzip header, time 0), so that streaming changed no archive."""

    def __init__(self, out, level: int):
        self.out, self.count = out, 0
        self.compressor = zlib.compressobj(level, zlib.DEFLATED, 31)

    def write(self, data):
        self.count += len(data)
        self.out.write(self.compressor.compress(data))
        return len(data)

    def tell(self) -> int:
        return self.count

    def close(self) -> None:
        self.out.write(self.compressor.flush())


def _project(root: Path) -> dict:
    import tomllib

    with open(Path(root) / "pyproject.toml", "rb") as handle:
        return tomllib.load(handle)["project"]


def _provenance(results_dir: Path, sums: dict[str, str]) -> dict[str, dict]:
    """{scene folder: its provenance record} of the archived scene folders (the crate's per-job actions)."""
    records = {}
    for rel in sums:
        if rel.endswith("/provenance.json"):
            record = io.read_json_checked(Path(results_dir) / rel)
            if isinstance(record, dict):
                records[rel.removesuffix("/provenance.json")] = record
    return records


def make_archive(
    results_dir: Path, archive: Path, with_report: bool = True, snakefile: Path | None = None
) -> None:
    """Deterministic tar.gz (sorted, fixed times and owners) with a SHA256SUMS of its members inside, and
    beside it (SHA256SUMS for the dist archive, <prefix>.SHA256SUMS for the results archive) the archive's own
    sum.

    Each manifest names files relative to the folder it lies in, so `sha256sum -c` checks it there: beside the
    archive for the archive, inside the unpacked <prefix>/ for the members.

    With them, the checkout's files its RO-Crate describes (the Snakefile, found as Snakemake finds it unless
    `snakefile` names the one it ran, its configuration, LICENSE, CITATION.cff, the lock) and last the crate,
    ro-crate-metadata.json (report/crate.py), listed in SHA256SUMS like every member.
    """
    results_dir, archive = Path(results_dir), Path(archive)
    prefix = archive.name.removesuffix(".tar.gz")
    root, snakefile = crate.find_checkout(results_dir, snakefile)
    members = [
        (path, path.relative_to(results_dir).as_posix()) for path in archive_members(results_dir, with_report)
    ]
    members += [(root / rel, rel.as_posix()) for rel in crate.checkout_members(root, snakefile)]
    if len(members) + 1 >= limits.MAX_MEMBERS:  # verify would refuse the archive: refused here first
        raise io.ResultError(f"{results_dir}: {len(members)} files, over limits.MAX_MEMBERS for an archive")
    sums = {}
    # Streamed: each file read in pieces, hashed as it is packed, the archive hashed as it is written; nothing
    # is held whole (the same bytes as compressing the whole tar at once).
    with io.atomic_writer(archive) as out:
        written = _Hashing(out)
        # The citable archive at level 6: level 9 took 2.2 times as long (2.2 s against 1.0 s) for 1.8 % less,
        # on a full build's results. The results archive, packed again after every scene edit before the
        # report can print its SHA-256, at level 1: 0.26 s against 1.06 s, for 13.5 MB against 12.1 MB.
        packed = _Gzip(written, level=6 if with_report else 1)
        with tarfile.open(fileobj=packed, mode="w", format=tarfile.PAX_FORMAT) as tar:
            for path, rel in members:
                try:  # a regular file within limits.MAX_MEMBER_BYTES: verify refuses a larger one
                    size = io.regular_size(path, limits.MAX_MEMBER_BYTES)
                except ValueError as error:
                    raise io.ResultError(f"{path}: {error}; not archived") from None
                info = tarfile.TarInfo(f"{prefix}/{rel}")
                info.size, info.mtime, info.mode, info.uid, info.gid = size, 0, 0o644, 0, 0
                with open(path, "rb") as handle:
                    source = _Hashing(handle)
                    tar.addfile(info, source)
                sums[rel] = source.digest.hexdigest()
            metadata = crate.build(
                root, snakefile, sums, _provenance(results_dir, sums), _project(root), with_report
            )
            info = tarfile.TarInfo(f"{prefix}/{io.RO_CRATE}")
            info.size, info.mtime, info.mode = len(metadata), 0, 0o644
            tar.addfile(info, _io.BytesIO(metadata))
            sums[io.RO_CRATE] = hashlib.sha256(metadata).hexdigest()
            manifest = "".join(f"{digest}  {rel}\n" for rel, digest in sums.items()).encode()
            info = tarfile.TarInfo(f"{prefix}/SHA256SUMS")
            info.size, info.mtime, info.mode = len(manifest), 0, 0o644
            tar.addfile(info, _io.BytesIO(manifest))
        packed.close()
    archive_sum = written.digest.hexdigest()
    sums = archive.parent / ("SHA256SUMS" if with_report else f"{prefix}.SHA256SUMS")
    io.atomic_write_text(sums, f"{archive_sum}  {archive.name}\n")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(
        description="the results archive (no report) whose SHA-256 the report prints"
    )
    parser.add_argument("results")
    parser.add_argument("archive")
    parser.add_argument("--snakefile", help="the Snakefile that ran (default: found as Snakemake finds it)")
    args = parser.parse_args()
    try:
        make_archive(
            Path(args.results),
            Path(args.archive),
            with_report=False,
            snakefile=args.snakefile and Path(args.snakefile),
        )
    except io.ResultError as error:
        raise SystemExit(f"{error}")
    except OSError as error:  # a full disk: no archive half-written, the last one kept
        if (line := io.no_space_line(error)) is None:
            raise
        raise SystemExit(line)
