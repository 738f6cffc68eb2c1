"""A full disk during a scene's write, the report's render, dist and verify's unpacking (issue 35, item 6):
one line naming the file and 'no space left on device', a non-zero exit, no temporary file, the previous
result kept whole, and the next run, with room again, recovers. On a small tmpfs the test mounts when it may
(root here); an injected ENOSPC (os.write, which every atomic write goes through) where it may not, and always
for the report's HTML and PDF, whose real render needs a whole build."""

import errno
import os
import sys

import pytest

from classical_dynamics import io
from classical_dynamics.cli import main as cli
from classical_dynamics.report import build, pdf

from . import hostile_files as hf
from .conftest import ROOT

SCENE = ROOT / "workflow/scenes/chains/two_masses_three_springs.yaml"
mountable = pytest.mark.skipif(not hf.can_mount(), reason="may not mount a tmpfs here (not root)")


def one_line_no_space(done, where):
    assert done.returncode != 0 and done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, (
        done.stderr
    )
    assert "no space left on device" in done.stderr and str(where) in done.stderr, done.stderr


def hidden(folder):
    return [p for p in folder.rglob(".*")]


@mountable
def test_a_scene_on_a_full_disk_keeps_its_last_results_and_recovers(tmp_path):
    with hf.small_disk(tmp_path / "disk") as disk:
        out, timings = disk.path / "results/chains/s", disk.path / "results/chains/timings/s"
        run = ["run", "chains", str(SCENE), str(out), str(timings), "--quick"]
        assert cli(run) == 0  # in this process: the refusal below is the run that needs its own
        before = hf.digest(out)
        filler = disk.fill()
        done = hf.run(run, tmp_path)
        one_line_no_space(done, out)
        assert hf.digest(out) == before and io.check_result_folder(out)  # the last whole results, untouched
        assert hidden(disk.path / "results") == []  # no staging folder left
        filler.unlink()
        assert cli(run) == 0 and io.check_result_folder(out)


@mountable
def test_dist_onto_a_full_disk_keeps_the_last_archive(tmp_path):
    results = hf.results_folder(tmp_path)
    with hf.small_disk(tmp_path / "disk") as disk:
        archive = disk.path / "dist" / hf.ARCHIVE
        assert hf.run(["dist", str(results), str(archive)], tmp_path).returncode == 0
        before = archive.read_bytes()
        (results / "report.html").write_bytes(os.urandom(8 << 20))  # incompressible: more than the room left
        done = hf.run(["dist", str(results), str(archive)], tmp_path)
        one_line_no_space(done, archive)
        assert archive.read_bytes() == before and hidden(disk.path) == []


@mountable
def test_verify_unpacking_onto_a_full_disk_says_so(tmp_path):
    archive = hf.archive(tmp_path)
    with hf.small_disk(tmp_path / "disk", "1m") as disk:
        disk.fill(leave=1)  # room for Python's probe of TMPDIR (full, it quietly takes /tmp), not the archive
        done = hf.run(["verify", str(archive), "--root", str(hf.checkout(tmp_path))], disk.path)
        one_line_no_space(done, disk.path)
        assert sorted(p.name for p in disk.path.iterdir()) == ["filler"]


@pytest.fixture()
def full(monkeypatch):
    """Writes to files under the folder returned fail with ENOSPC, after the first has written half its bytes:
    the injected fault where a test may not mount."""
    real = os.write
    started = set()

    def write(fd, data):
        try:
            target = os.readlink(f"/proc/self/fd/{fd}")
        except OSError:
            target = ""
        if not target.startswith(str(folder)):
            return real(fd, data)
        if fd not in started and len(data) > 1:
            started.add(fd)
            return real(fd, bytes(data)[: len(data) // 2])
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    folder = None

    def on(path):
        nonlocal folder
        folder = path
        monkeypatch.setattr(os, "write", write)
        return path

    return on


def test_an_atomic_write_on_a_full_disk_leaves_the_old_file(tmp_path, full):
    target = tmp_path / "disk/summary.json"
    io.atomic_write_bytes(target, b"old\n")
    full(tmp_path / "disk")
    with pytest.raises(OSError) as error:
        io.atomic_write_bytes(target, b"new" * 1000)
    assert io.no_space_line(error.value).startswith(f"{target}: no space left on device")
    assert target.read_bytes() == b"old\n" and hidden(tmp_path / "disk") == []


def test_a_scene_written_onto_an_injected_full_disk(tmp_path, full, capsys):
    from classical_dynamics.cli import main

    out, timings = tmp_path / "disk/chains/s", tmp_path / "disk/chains/timings/s"
    run = ["run", "chains", str(SCENE), str(out), str(timings), "--quick"]
    assert main(run) == 0
    before = hf.digest(out)
    full(tmp_path / "disk")
    capsys.readouterr()
    assert main(run) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no space left on device" in err and str(out) in err, err
    assert hf.digest(out) == before and hidden(tmp_path / "disk") == []


def keeps_the_last(render, target, full, capsys):
    """render() writes target whole; on a disk then full it exits 2 with one line and leaves target as it was,
    with no temporary file beside it."""
    assert render() == 0
    before = target.read_bytes()
    full(target.parent)
    assert render() == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{target}: no space left on device" in err, err
    assert target.read_bytes() == before and hidden(target.parent) == []


def test_the_report_rendered_onto_a_full_disk_keeps_the_last_report(tmp_path, full, monkeypatch, capsys):
    class Rendered:
        def __init__(self, *args):
            pass

        def render(self):
            return "<html>" + "new " * 10_000 + "</html>"

    monkeypatch.setattr(build, "Report", Rendered)
    monkeypatch.setattr(build, "ResultsIndex", lambda results: None)
    html = tmp_path / "disk/report.html"
    keeps_the_last(lambda: build.main([str(tmp_path), str(html)]), html, full, capsys)


def test_the_pdf_written_onto_a_full_disk_keeps_the_last_pdf(tmp_path, full, monkeypatch, capsys):
    weasyprint = pytest.importorskip("weasyprint")

    class Document:
        pages = []

        def write_pdf(self, **_):
            return b"%PDF-1.7\n" + bytes(100_000)

    class HTML:
        def __init__(self, **_):
            pass

        def render(self, **_):
            return Document()

    monkeypatch.setattr(weasyprint, "HTML", HTML)
    html, target = tmp_path / "report.html", tmp_path / "disk/report.pdf"
    html.write_text("<html></html>")
    keeps_the_last(lambda: pdf.main([str(html), str(target)]), target, full, capsys)
    assert sys.modules["weasyprint"] is weasyprint
