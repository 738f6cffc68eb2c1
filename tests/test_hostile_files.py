"""verify, diff and dist bounded on any input (issue 35, item 4): each hostile file of tests/hostile_files.py
is refused in one line, exit 2, with nothing written and the command's memory small (a gzip bomb's 2 GiB
member was held whole: 2.15 GB resident). Time to refuse is a benchmark figure (benchmarks/bad_input.py)."""

import gzip
import io
import tarfile
import zlib

import numpy as np
import pytest

from classical_dynamics import limits
from classical_dynamics.io import ResultError
from classical_dynamics.report.dist import make_archive
from classical_dynamics.verify import VerifyError, unpack_archive

from . import hostile_files as hf

CASES = hf.all_cases()
MEMORY_MB = 400  # the interpreter with numpy is about 100 MB; a bomb held whole is 2000 MB and more


def test_the_cases_cover_every_kind():
    assert {c.kind for c in CASES} == set(hf.KINDS)


def test_the_checksum_of_zeros_is_zlibs(tmp_path):
    """The bombs' CRC, taken without reading their zeros, is what zlib reads, and a small bomb made the same
    way is a gzip file that Python's gzip (which checks the CRC and length) reads back whole."""
    rng = np.random.default_rng(1)
    for size in (0, 1, 2, 3, 255, 4096, 12345, (1 << 20) + 7, 3 << 20):
        start = int(rng.integers(0, 1 << 32))
        assert hf.crc32_zeros(start, size) == zlib.crc32(bytes(size), start), size
    hf._zeros_gzip(tmp_path / "small.gz", b"header", 2 << 20)
    assert gzip.decompress((tmp_path / "small.gz").read_bytes()) == b"header" + bytes(2 << 20)


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_a_hostile_file_is_refused_in_one_line(tmp_path, case):
    base, tmp = tmp_path / "base", tmp_path / "tmp"
    base.mkdir()
    tmp.mkdir()
    args = case.make(base)
    before = hf.digest(base)
    done = hf.run(args, tmp)
    assert done.returncode == 2 and done.stdout == "", done.stdout + done.stderr
    assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, done.stderr
    assert case.expect in done.stderr, done.stderr
    assert done.peak_mb < MEMORY_MB, done.peak_mb
    assert hf.digest(base) == before and list(tmp.iterdir()) == []  # nothing touched, nothing left


def test_verify_refuses_an_archive_over_the_total_limit_before_unpacking_any(tmp_path, monkeypatch):
    """Members each within the size limit, over the total: refused from the headers, before a byte is
    written (the headers are all read first)."""
    monkeypatch.setattr(limits, "MAX_ARCHIVE_BYTES", 3000)
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w") as tar:
        for i in range(3):
            info = tarfile.TarInfo(f"{hf.PREFIX}/chains/fake/m{i}.csv")
            info.size = 1500
            tar.addfile(info, io.BytesIO(bytes(1500)))
    archive = tmp_path / hf.ARCHIVE
    archive.write_bytes(gzip.compress(buffer.getvalue()))
    with pytest.raises(VerifyError, match="in all, over the limit") as error:
        unpack_archive(archive, tmp_path / "into")
    assert not (tmp_path / "into").exists() or not any((tmp_path / "into").rglob("*"))
    assert "\n" not in str(error.value)


def test_dist_refuses_a_file_verify_would_refuse(tmp_path, monkeypatch):
    results = hf.results_folder(tmp_path)
    monkeypatch.setattr(limits, "MAX_MEMBER_BYTES", 100)
    (results / "chains/fake/fake.csv").write_bytes(bytes(200))
    with pytest.raises(ResultError, match="fake.csv"):  # here its checksum; a folder whole but large below
        make_archive(results, tmp_path / "dist" / hf.ARCHIVE)
    (results / "report.html").write_bytes(bytes(200))
    (results / "chains/fake/fake.csv").write_bytes(b"x_m,y_m\n0,1\n")
    with pytest.raises(ResultError, match="report.html: 200 bytes, over the limit"):
        make_archive(results, tmp_path / "dist" / hf.ARCHIVE)
    assert not (tmp_path / "dist").exists() or list((tmp_path / "dist").iterdir()) == []


def test_a_synthetic_archive_and_folder_verify_up_to_the_rebuild(tmp_path):
    """The good inputs pass the checks: what refuses the hostile ones is no blanket refusal."""
    archive = hf.archive(tmp_path / "a")
    assert (unpack_archive(archive, tmp_path / "into") / "chains/fake/summary.json").is_file()
    done = hf.run(["diff", str(archive), str(tmp_path / "a/results")], tmp_path / "a")
    assert done.returncode == 0 and done.stdout.startswith("no numbers changed"), done.stdout + done.stderr
