"""The PDF's figures drawn with `report.fast_svg` are the figures WeasyPrint draws: the same page streams.

Each way renders in its own process (the patches are for the whole process). The figure is a matplotlib
figure saved as the pipeline saves one (text as glyph paths, markers, a translucent fill, clipping, math
text), inlined in the HTML as the report inlines it and also linked as a file.
"""

import base64
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

CHILD = """
import sys
from pathlib import Path
import weasyprint
from classical_dynamics.report import fast_svg
if sys.argv[2] == "new":
    fast_svg.install()
    import weasyprint.svg as svg
    assert getattr(svg, fast_svg._INSTALLED)
document = weasyprint.HTML(filename=sys.argv[1], media_type="print").render(pdf_variant=None)
Path(sys.argv[3]).write_bytes(document.write_pdf(pdf_variant=None, uncompressed_pdf=True))
"""


def figure_svg() -> bytes:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from classical_dynamics import figure_style, io

    figure_style.use()
    figure, (left, right) = plt.subplots(1, 2, figsize=(figure_style.FULL_WIDTH_IN, 2.2))
    t = np.linspace(0.0, 10.0, 400)
    left.plot(t, np.sin(t), label=r"$\sin\,\omega t$")
    left.plot(t[::25], np.cos(t[::25]), "o", label="samples 1e-3")
    left.fill_between(t, -0.5, 0.5, alpha=0.3)
    left.set_xlabel(r"time $t$ (days)")
    left.set_ylabel(r"$\theta - \theta_0$ (rad)")
    left.legend()
    right.loglog(t[1:], t[1:] ** -2.0, "--", label="slope $-2$")
    right.set_xlim(0.5, 20.0)  # the line runs past the axes: clipped
    right.set_title("Abcdefghijklmnopqrstuvwxyz 0123456789 ×10⁻³")
    data = io.svg_bytes(figure)
    plt.close(figure)
    return data


def render(way: str, html: Path, out: Path) -> bytes:
    subprocess.run(
        [sys.executable, "-c", CHILD, str(html), way, str(out)],
        check=True,
        env={**os.environ, "PYTHONPATH": str(ROOT / "src")},
        timeout=300,
    )
    return out.read_bytes()


@pytest.fixture(scope="module")
def pdfs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("fast_svg")
    svg = figure_svg()
    assert svg.count(b"<use ") > 100  # text as glyphs placed by <use>, what the patches are for
    (folder / "figure.svg").write_bytes(svg)
    inlined = "data:image/svg+xml;base64," + base64.b64encode(svg).decode()
    (folder / "page.html").write_text(
        "<!doctype html><html><body>"
        f'<p><img style="width: 170mm" src="{inlined}"></p>'
        '<p><img style="width: 80mm" src="figure.svg"></p>'
        f'<p><img style="width: 120mm" src="{inlined}"></p>'
        "</body></html>"
    )
    return {way: render(way, folder / "page.html", folder / f"{way}.pdf") for way in ("old", "new")}


def test_the_figures_are_drawn_with_the_same_operators(pdfs):
    old, new = pdfs["old"], pdfs["new"]
    assert old.count(b" c\n") > 1000  # the glyphs' curves are in the streams (uncompressed)
    assert old == new


def test_a_path_replayed_is_the_path_parsed():
    """A glyph drawn twice from the cache appends what parsing appends, and its vertices too."""
    code = """
import weasyprint.svg as svg
from classical_dynamics.report import fast_svg
from collections import deque

class Stream:
    def __init__(self): self.stream = []
    def move_to(self, x, y): self.stream.append(f"{x} {y} m".encode())
    def line_to(self, x, y): self.stream.append(f"{x} {y} l".encode())
    def curve_to(self, *p): self.stream.append((" ".join(map(str, p)) + " c").encode())
    def close(self): self.stream.append(b"h")

class Node:
    def __init__(self, attrib): self.attrib, self.vertices = attrib, deque()
    def get(self, key, default=None): return self.attrib.get(key, default)

class Image:
    inner_width = inner_height = inner_diagonal = 100.0
    def point(self, x, y, font_size): return float(x), float(y)

plain = svg.TAGS["path"]
calls = []
def counted(*args):
    calls.append(args)
    return plain(*args)
cached = fast_svg._memoized_path(counted)
image, d = Image(), "M 1 2 L 3 4 Q 5 6 7 8 C 1 2 3 4 5 6 z"
results = []
for attrib in ({"id": "glyph-a", "d": d}, {"id": "glyph-a", "d": d}, {"d": d}, {"d": d}):
    image.stream, node = Stream(), Node(attrib)
    cached(image, node, 12.0)
    results.append((image.stream.stream, list(node.vertices)))
image.stream, node = Stream(), Node({"id": "glyph-a", "d": d})
plain(image, node, 12.0)
assert all(result == (image.stream.stream, list(node.vertices)) for result in results), results
assert len(calls) == 3, calls  # the glyph parsed once, the paths without an id each time
fast_svg.clear()  # what a document remembered is forgotten once it is written
cached(image, Node({"id": "glyph-a", "d": d}), 12.0)
assert len(calls) == 4, calls
print("ok")
"""
    out = subprocess.run(
        [sys.executable, "-c", code],
        check=True,
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": str(ROOT / "src")},
    )
    assert out.stdout.strip() == "ok"


def test_the_patches_are_for_the_weasyprint_installed():
    """An upgraded WeasyPrint renders unpatched (correct, slower): compare it byte for byte, then bump."""
    import weasyprint

    from classical_dynamics.report import fast_svg

    assert fast_svg.CHECKED_ON == weasyprint.__version__, (
        "run tests/test_report_fast_svg.py and benchmarks/pdf_render.py on the new WeasyPrint, "
        "then set fast_svg.CHECKED_ON"
    )
