"""The PDF of one report.html, the old way and the new way side by side in one run (printed, not asserted).

Old: WeasyPrint draws the figures as it is. New: `classical_dynamics.report.fast_svg` computes each glyph's
path and each URL once (`html_to_pdf(..., fast_svg=True)`, what the pipeline runs). Each way runs in its own
fresh process, alternating old/new `--repeats` times; the minimum CPU time of each is compared, with the
time spent in layout (render) and in drawing and writing (write_pdf) apart. Then the two PDFs are compared:
byte for byte, then page by page as images at 100 dpi (pdftoppm), the number of pages that differ and the
largest difference of one pixel's channel. Goal (issue 37): 3.5 x.

    python benchmarks/pdf_render.py [--html results/report.html] [--repeats 1] [--keep DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
from classical_dynamics.provenance import software_stamp  # noqa: E402

GOAL = 3.5

CHILD = """
import json, sys, time
import weasyprint.document as document
from pathlib import Path
from classical_dynamics.report import pdf

phases = {}
write_pdf = document.Document.write_pdf
def timed(self, *args, **kwargs):
    start = time.process_time()
    try:
        return write_pdf(self, *args, **kwargs)
    finally:
        phases["write_pdf"] = time.process_time() - start
document.Document.write_pdf = timed
wall, cpu = time.perf_counter(), time.process_time()
pdf.html_to_pdf(Path(sys.argv[1]), Path(sys.argv[2]), fast_svg=sys.argv[3] == "new")
cpu = time.process_time() - cpu
print(json.dumps({"wall": time.perf_counter() - wall, "cpu": cpu, "write_pdf": phases["write_pdf"],
                  "render": cpu - phases["write_pdf"]}))
"""


def run(way: str, html: Path, pdf: Path) -> dict:
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    out = subprocess.run(
        [sys.executable, "-c", CHILD, str(html), str(pdf), way],
        check=True,
        capture_output=True,
        text=True,
        env=env,
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def pages(pdf: Path, folder: Path) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    subprocess.run(["pdftoppm", "-r", "100", "-png", str(pdf), str(folder / "p")], check=True)
    return sorted(folder.glob("p-*.png"))


def compare_pages(old: list[Path], new: list[Path]) -> tuple[list[int], int]:
    from PIL import Image, ImageChops

    differing, largest = [], 0
    for number, (a, b) in enumerate(zip(old, new, strict=True), start=1):
        with Image.open(a) as image_a, Image.open(b) as image_b:
            if image_a.size != image_b.size:
                differing.append(number)
                largest = 255
                continue
            extrema = ImageChops.difference(image_a.convert("RGB"), image_b.convert("RGB")).getextrema()
            worst = max(high for _, high in extrema)
            if worst:
                differing.append(number)
                largest = max(largest, worst)
    return differing, largest


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--html", type=Path, default=ROOT / "results/report.html")
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--keep", type=Path, help="keep the PDFs and page images here")
    args = parser.parse_args()
    html = args.html.resolve()
    if not html.is_file():
        print(f"{html}: no report to render (snakemake -c all report first)")
        return 1
    print(f"# {software_stamp()}")
    print(f"# {html} ({html.stat().st_size / 1e6:.1f} MB)\n")
    with tempfile.TemporaryDirectory() as scratch:
        folder = args.keep or Path(scratch)
        folder.mkdir(parents=True, exist_ok=True)
        # the PDF beside the HTML, as in the pipeline: its data links are made relative to that folder
        pdfs = {way: html.parent / f".pdf_render_{way}.pdf" for way in ("old", "new")}
        times = {"old": [], "new": []}
        try:
            for _ in range(args.repeats):
                for way in ("old", "new"):
                    times[way].append(run(way, html, pdfs[way]))
                    print(f"{way}: " + "  ".join(f"{k} {v:6.2f} s" for k, v in times[way][-1].items()))
            best = {way: min(runs, key=lambda r: r["cpu"]) for way, runs in times.items()}
            print()
            for key in ("cpu", "render", "write_pdf"):
                ratio = best["old"][key] / best["new"][key]
                old, new = best["old"][key], best["new"][key]
                print(f"{key:>9}: old {old:6.2f} s  new {new:6.2f} s  ratio {ratio:4.2f} x")
            reached = best["old"]["cpu"] / best["new"]["cpu"]
            print(f"     goal: {GOAL} x on the whole PDF (cpu); reached {reached:.2f} x")
            old_bytes, new_bytes = (pdfs[way].read_bytes() for way in ("old", "new"))
            print(
                f"\nPDFs byte for byte: {'identical' if old_bytes == new_bytes else 'different'}"
                f" ({len(old_bytes)} and {len(new_bytes)} bytes)"
            )
            old_pages, new_pages = pages(pdfs["old"], folder / "old"), pages(pdfs["new"], folder / "new")
            if len(old_pages) != len(new_pages):
                print(f"page count differs: old {len(old_pages)}, new {len(new_pages)}")
                return 1
            differing, largest = compare_pages(old_pages, new_pages)
            print(
                f"page images at 100 dpi: {len(old_pages)} pages, {len(differing)} differ"
                + (f" (pages {differing}, largest channel difference {largest}/255)" if differing else "")
            )
            if args.keep:
                for way, pdf in pdfs.items():
                    pdf.replace(folder / f"{way}.pdf")
        finally:
            for pdf in pdfs.values():
                pdf.unlink(missing_ok=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
