"""Hostile files for verify and diff (issue 35, item 4): gzip bombs, too many members, pathological JSON,
what is not an archive. Each case makes its input in a folder and names the command that must refuse it in
one line (exit 2). tests/test_hostile_files.py runs them; benchmarks/bad_input.py tallies them with their
time and memory.

A small synthetic results folder stands in for a build (one scene whose provenance lists its files' checksums,
as a scene job writes it): the refusals come before anything is rebuilt.
"""

from __future__ import annotations

import gzip
import hashlib
import io
import json
import tarfile
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from classical_dynamics import limits
from classical_dynamics.report.dist import make_archive

PREFIX = "classical-dynamics-0.1.0"
ARCHIVE = f"{PREFIX}.tar.gz"
KINDS = ("gzip bomb", "too many members", "deep JSON", "huge numbers", "not results")
SUMMARY = {"numbers": {"omega": {"value": [1.0, 2.64575131106459], "unit": "rad/s"}, "n": {"value": 3}}}


def results_folder(base: Path, summary: dict | bytes = SUMMARY) -> Path:
    """base/results with one scene, chains/fake, whole (its provenance lists its files' checksums); `summary`
    as given, bytes as they are."""
    scene = base / "results/chains/fake"
    scene.mkdir(parents=True)
    data = summary if isinstance(summary, bytes) else json.dumps(summary).encode()
    files = {"summary.json": data, "fake.csv": b"x_m,y_m\n0,1\n"}
    for name, content in files.items():
        (scene / name).write_bytes(content)
    provenance = {
        "study": "chains",
        "scene": "fake",
        "quick": True,
        "files": {name: hashlib.sha256(content).hexdigest() for name, content in files.items()},
    }
    (scene / "provenance.json").write_text(json.dumps(provenance))
    (base / "results/report.html").write_text("<html></html>")  # dist packs the report too
    (base / "results/report.pdf").write_bytes(b"%PDF-1.7\n")
    return base / "results"


def archive(base: Path, summary: dict | bytes = SUMMARY) -> Path:
    """A dist archive of results_folder(base, summary), as `dist` makes it."""
    target = base / "dist" / ARCHIVE
    make_archive(results_folder(base, summary), target)
    return target


def checkout(base: Path) -> Path:
    """What verify wants of --root before it rebuilds: a workflow/scenes folder (never reached)."""
    (base / "checkout/workflow/scenes").mkdir(parents=True)
    return base / "checkout"


def _gf2_times(matrix: list[int], vector: int) -> int:
    out, i = 0, 0
    while vector:
        if vector & 1:
            out ^= matrix[i]
        vector >>= 1
        i += 1
    return out


def crc32_zeros(crc: int, size: int) -> int:
    """zlib.crc32(bytes(size), crc) in log2(size) steps (as zlib's crc32_combine): the register's update by a
    zero bit is linear over GF(2), so `size` zero bytes are that 32 x 32 matrix raised to 8 size, by squaring.
    The 2 GiB of zeros of a bomb took 0.5 s to checksum byte by byte; tests/test_hostile_files.py holds this
    to zlib's own."""
    op = [0xEDB88320] + [1 << (i - 1) for i in range(1, 32)]  # one zero bit (the reflected polynomial)
    for _ in range(3):
        op = [_gf2_times(op, row) for row in op]  # 2, 4, then 8 bits: one zero byte
    register = crc ^ 0xFFFFFFFF
    while size:
        if size & 1:
            register = _gf2_times(op, register)
        size >>= 1
        if size:
            op = [_gf2_times(op, row) for row in op]
    return register ^ 0xFFFFFFFF


def _zeros_gzip(target: Path, header: bytes, size: int) -> None:
    """A valid gzip of `header` and then `size` zero bytes, made without compressing them all: after a full
    flush the compressor starts afresh, so every MiB of zeros compresses to the same bytes."""
    chunk = 1 << 20
    assert size % chunk == 0
    compressor = zlib.compressobj(9, zlib.DEFLATED, -15)
    first = compressor.compress(header) + compressor.flush(zlib.Z_FULL_FLUSH)
    block = compressor.compress(bytes(chunk)) + compressor.flush(zlib.Z_FULL_FLUSH)
    assert compressor.compress(bytes(chunk)) + compressor.flush(zlib.Z_FULL_FLUSH) == block
    crc = crc32_zeros(zlib.crc32(header), size)
    with open(target, "wb") as out:
        out.write(b"\x1f\x8b\x08\x00\x00\x00\x00\x00\x02\xff" + first)
        for _ in range(size // chunk):
            out.write(block)
        out.write(compressor.flush())
        out.write(crc.to_bytes(4, "little") + ((len(header) + size) % (1 << 32)).to_bytes(4, "little"))


def gzip_bomb(base: Path, member: str = "chains/fake/summary.json", kind: bytes = tarfile.REGTYPE) -> Path:
    """A 2 GiB member of zeros in a 2 MB archive (the issue's: held whole in memory, 2.15 GB resident);
    kind=XHDTYPE makes it a 2 GiB PAX header instead, which tarfile itself would read whole."""
    info = tarfile.TarInfo(f"{PREFIX}/{member}")
    info.size, info.type = 2 << 30, kind
    target = base / "bomb" / ARCHIVE
    target.parent.mkdir(parents=True)
    _zeros_gzip(target, info.tobuf(format=tarfile.USTAR_FORMAT), info.size)
    return target


def many_members(base: Path, count: int | None = None) -> Path:
    """An archive of one more empty member than limits.MAX_MEMBERS (or `count`)."""
    count = limits.MAX_MEMBERS + 1 if count is None else count
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w", format=tarfile.USTAR_FORMAT) as tar:
        for i in range(count):
            tar.addfile(tarfile.TarInfo(f"{PREFIX}/chains/fake/m{i}.csv"), io.BytesIO(b""))
    target = base / "many" / ARCHIVE
    target.parent.mkdir(parents=True)
    target.write_bytes(gzip.compress(buffer.getvalue(), mtime=0))
    return target


def deep(depth: int) -> bytes:
    return b'{"numbers": {"x": {"value": ' + b"[" * depth + b"]" * depth + b"}}}"


def number(text: str) -> bytes:
    return b'{"numbers": {"x": {"value": ' + text.encode() + b', "unit": ""}}}'


HUGE = {  # name: (summary.json, what the line says)
    "1e999999": (number("1e999999"), "out of a float's range"),
    "100000-digit-int": (number("9" * 100_000), "an integer of 100000 digits"),
    "NaN": (number("NaN"), "NaN is not a JSON number"),
    "-Infinity": (number("-Infinity"), "-Infinity is not a JSON number"),
}


@dataclass(frozen=True)
class HostileFile:
    """One case: make(folder) writes its input and returns the command line after `python -m
    classical_dynamics`; `expect` is in the one line it must print."""

    id: str
    kind: str  # one of KINDS
    make: Callable[[Path], list[str]]
    expect: str


def _verify(given: Callable[[Path], Path]) -> Callable[[Path], list[str]]:
    return lambda base: ["verify", str(given(base)), "--root", str(checkout(base))]


def _diff(given: Callable[[Path], Path]) -> Callable[[Path], list[str]]:
    """diff of a good results folder and the given one."""
    return lambda base: ["diff", str(results_folder(base / "good")), str(given(base))]


def _folder(name: str) -> Callable[[Path], Path]:
    def make(base):
        (base / name).mkdir()
        return base / name

    return make


def all_cases() -> list[HostileFile]:
    cases = [
        HostileFile("verify-gzip-bomb", "gzip bomb", _verify(gzip_bomb), "over the limit of 256 MiB"),
        HostileFile("diff-gzip-bomb", "gzip bomb", _diff(gzip_bomb), "over the limit of 256 MiB"),
        HostileFile(
            "verify-pax-header-bomb",
            "gzip bomb",
            _verify(lambda base: gzip_bomb(base, "pax", tarfile.XHDTYPE)),
            "a tar header of",
        ),
        HostileFile(
            "verify-too-many-members", "too many members", _verify(many_members), "more than 20000 members"
        ),
        HostileFile(
            "verify-folder-not-results", "not results", _verify(_folder("empty")), "not a results folder"
        ),
        HostileFile(
            "verify-devnull", "not results", _verify(lambda base: Path("/dev/null")), "not a regular file"
        ),
        HostileFile(
            "verify-missing", "not results", _verify(lambda base: base / "missing.tar.gz"), "no such file"
        ),
        HostileFile(
            "diff-devnull", "not results", _diff(lambda base: Path("/dev/null")), "not a regular file"
        ),
        HostileFile("diff-missing", "not results", _diff(lambda base: base / "missing"), "no such file"),
        HostileFile(
            "verify-edited-folder",
            "not results",
            _verify(lambda base: _edited(results_folder(base))),
            "does not match its checksum",
        ),
    ]
    for depth in (100, 100_000):
        cases += [
            HostileFile(
                f"verify-archive-json-{depth}-deep",
                "deep JSON",
                _verify(lambda base, d=depth: archive(base, deep(d))),
                "nested deeper than 64",
            ),
            HostileFile(
                f"diff-json-{depth}-deep",
                "deep JSON",
                _diff(lambda base, d=depth: results_folder(base, deep(d))),
                "nested deeper than 64",
            ),
        ]
    for name, (text, line) in HUGE.items():
        cases += [
            HostileFile(
                f"verify-archive-{name}", "huge numbers", _verify(lambda base, t=text: archive(base, t)), line
            ),
            HostileFile(
                f"diff-{name}", "huge numbers", _diff(lambda base, t=text: results_folder(base, t)), line
            ),
            HostileFile(
                f"verify-folder-{name}",
                "huge numbers",
                _verify(lambda base, t=text: results_folder(base, t)),
                line,
            ),
        ]
    return cases


def _edited(results: Path) -> Path:
    summary = results / "chains/fake/summary.json"
    summary.write_text(summary.read_text().replace("2.64575131106459", "2.6457513110646"))
    return results


@dataclass
class Outcome:
    returncode: int
    stdout: str
    stderr: str
    seconds: float
    peak_mb: float  # the command's own peak resident memory (its rusage, not this process's)


def run(args: list[str], tmpdir: Path, env: dict | None = None) -> Outcome:
    """`python -m classical_dynamics ARGS` with TMPDIR=tmpdir, as a user runs it, timed and measured."""
    import os
    import subprocess
    import sys
    import tempfile
    import time

    root = Path(__file__).resolve().parents[1]
    env = {**os.environ, **(env or {}), "TMPDIR": str(tmpdir)}
    env["PYTHONPATH"] = str(root / "src") + os.pathsep + env.get("PYTHONPATH", "")
    start = time.perf_counter()
    with (
        tempfile.TemporaryFile("w+") as out,
        tempfile.TemporaryFile("w+") as err,
        tempfile.NamedTemporaryFile("r") as peak,
    ):
        # The command is started by a small interpreter, not by this process: a child forked from a process
        # reports that process's resident size at the fork as its own peak (Linux copies the high-water mark),
        # so from a 650 MB test worker any command would read 650 MB.
        child = subprocess.run(
            [sys.executable, "-c", MEASURE, peak.name, sys.executable, "-m", "classical_dynamics", *args],
            stdout=out,
            stderr=err,
            env=env,
        )
        seconds = time.perf_counter() - start
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read(), err.read()
        peak_kb = float(peak.read() or "nan")
    return Outcome(child.returncode, stdout, stderr, seconds, peak_kb / 1024)


# Run argv[2:], pass on its exit code, and write its own peak resident memory (kB) to argv[1].
MEASURE = (
    "import os, sys, subprocess\n"
    "child = subprocess.Popen(sys.argv[2:])\n"
    "_, status, usage = os.wait4(child.pid, 0)\n"
    "open(sys.argv[1], 'w').write(str(usage.ru_maxrss))\n"
    "sys.exit(os.waitstatus_to_exitcode(status))\n"
)


def digest(folder: Path) -> str:
    """Every file's name and bytes under folder: to see that a refusal touched nothing."""
    h = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file() and not p.is_symlink()):
        h.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


# --- a full disk (issue 35, item 6) -------------------------------------------------------------------------


def can_mount() -> bool:
    """Whether this process may mount a small tmpfs (as root, where the namespace allows it)."""
    import subprocess
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        try:
            done = subprocess.run(
                ["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", folder], capture_output=True
            )
        except OSError:  # no mount command
            return False
        if done.returncode != 0:
            return False
        subprocess.run(["umount", folder], check=True)
        return True


class small_disk:
    """A tmpfs of `size` mounted at `path` for the block (can_mount() first); fill() leaves it full."""

    def __init__(self, path: Path, size: str = "4m"):
        self.path, self.size = Path(path), size

    def __enter__(self):
        import subprocess

        self.path.mkdir(parents=True, exist_ok=True)
        subprocess.run(
            ["mount", "-t", "tmpfs", "-o", f"size={self.size}", "tmpfs", str(self.path)], check=True
        )
        return self

    def __exit__(self, *exc):
        import subprocess

        subprocess.run(["umount", "-l", str(self.path)], check=True)

    def fill(self, leave: int = 0) -> Path:
        """A file that takes all the room but `leave` pages of 4 KiB."""
        filler = self.path / "filler"
        with open(filler, "wb", buffering=0) as out:
            try:
                while True:
                    out.write(bytes(4096))
            except OSError as error:
                assert error.errno == 28
            out.truncate(max(0, out.tell() // 4096 - leave) * 4096)
        return filler
