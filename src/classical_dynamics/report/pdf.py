"""The PDF: WeasyPrint renders the same HTML with its print stylesheet (media print)."""

from __future__ import annotations

import contextlib
import gc
import os
import sys
import urllib.parse
from pathlib import Path

from .. import io


def _keep_whole_lines(split_first_line):
    """WeasyPrint 70's line splitter, without its one-word first lines.

    A text box that ends in a collapsible space (the text before an <em> or a link) and fits its line only
    without that space is measured with it: the splitter then takes the line for unbreakable and keeps just
    its first word, so a paragraph opens with "This" alone on a line. The space hangs in CSS (css-text-3,
    white-space processing), so the box fits; WeasyPrint's own inline layout already lets a trailing space
    overflow the line.
    """

    def split(text, style, context, max_width, *args, **kwargs):
        result = split_first_line(text, style, context, max_width, *args, **kwargs)
        stripped = text.rstrip(" ")
        if (
            result[2] is None
            or stripped == text
            or not stripped
            or max_width is None
            or style["white_space"] not in ("normal", "pre-line")
        ):
            return result
        if split_first_line(stripped, style, context, max_width, *args, **kwargs)[2] is not None:
            return result  # it does not fit even without the space: a real break
        return split_first_line(text, style, context, max_width + style["font_size"], *args, **kwargs)

    return split


def _relative(target: str, folder: Path) -> str:
    """A file:// link as a path relative to the report's folder; any other link as it is."""
    if not target.startswith("file://"):
        return target
    parts = urllib.parse.urlsplit(target)
    relative = Path(os.path.relpath(urllib.parse.unquote(parts.path), folder)).as_posix()
    return relative + (f"#{parts.fragment}" if parts.fragment else "")


@contextlib.contextmanager
def collector_paused():
    """Python's cyclic garbage collector off for the render. WeasyPrint's boxes, styles and layouts live until
    the PDF is written, millions of objects: the collector's full passes over them (19 for the report) took
    11 s of its 34 s of CPU to free 90 000 objects, 2 % of its 1 GB. The same bytes are written either way."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def html_to_pdf(html_path: Path, pdf_path: Path, fast_svg: bool = True) -> None:
    """Render the report; `fast_svg=False` draws figures with plain WeasyPrint (the old way) in a process
    that has not installed the patches (they are for the whole process: benchmarks/pdf_render.py runs each
    way in its own)."""
    with collector_paused():
        if fast_svg:
            from . import fast_svg as patches

            patches.install()
            try:
                _render(html_path, pdf_path)
            finally:
                patches.clear()
        else:
            _render(html_path, pdf_path)


def _render(html_path: Path, pdf_path: Path) -> None:
    import weasyprint
    from weasyprint.layout import inline

    if not getattr(inline.split_first_line, "keeps_whole_lines", False):
        inline.split_first_line = _keep_whole_lines(inline.split_first_line)
        inline.split_first_line.keeps_whole_lines = True
    document = weasyprint.HTML(filename=str(html_path), media_type="print").render(pdf_variant=None)
    # Links to the data beside the report stay relative, as in the HTML: WeasyPrint resolves them to file://
    # URLs of this machine, which would put its paths in the PDF and make the archive depend on where it was
    # built.
    folder = Path(html_path).resolve().parent
    for page in document.pages:
        page.links = [
            (kind, _relative(target, folder) if kind == "external" else target, rectangle, box)
            for kind, target, rectangle, box in page.links
        ]
    io.atomic_write_bytes(
        pdf_path, document.write_pdf(pdf_variant=None)
    )  # no temporary folder to leave behind


def main(argv=None) -> int:
    """The PDF job: a full disk is one line, and the last good PDF stays (written atomically)."""
    html, pdf = argv or sys.argv[1:]
    try:
        html_to_pdf(Path(html), Path(pdf))
    except OSError as error:
        if (line := io.no_space_line(error)) is None:
            raise
        print(f"report: {line}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
