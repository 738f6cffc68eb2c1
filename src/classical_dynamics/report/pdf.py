"""The PDF: WeasyPrint renders the same HTML with its print stylesheet (media print)."""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

from .. import io


def html_to_pdf(html_path: Path, pdf_path: Path) -> None:
    import weasyprint

    document = weasyprint.HTML(filename=str(html_path), media_type="print")
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(tmp) / "report.pdf"
        document.write_pdf(str(target), pdf_variant=None)
        io.atomic_write_bytes(pdf_path, target.read_bytes())


if __name__ == "__main__":
    html_to_pdf(Path(sys.argv[1]), Path(sys.argv[2]))
