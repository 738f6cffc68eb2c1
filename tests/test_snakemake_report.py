"""Snakemake's own report, `snakemake --report results/snakemake-report.zip` (report/snakemake_report.py):
every figure the report shows is in it, with its caption, under its chapter and scene."""

import html
import json
import re
import time
import zipfile

import pytest

from classical_dynamics.inline_math import _INLINE
from classical_dynamics.report.snakemake_report import REPORT, chapter, rst
from classical_dynamics.studies import STUDIES

from .conftest import snakemake


def embedded(page: str, name: str) -> dict:
    """One of the JSON objects Snakemake's report page carries (`var categories = {...};`)."""
    return json.loads(re.search(rf"var {name} = (\{{.*?\}});\n", page).group(1))


def words(markup: str) -> str:
    return " ".join(html.unescape(re.sub(r"<[^>]+>", " ", markup)).split())


def test_the_caption_rst_is_plain_text_and_math_roles():
    assert rst(r"The gravest $\omega_1$ of $n$th, $(n + \tfrac12)a$, a_b *c*") == (
        r"The gravest :math:`\omega_1` of :math:`n`\ th, :math:`(n + \tfrac{1}{2})a`, a\_b \*c\*"
    )
    assert rst(r"1. $\si(x)$ costs \$2") == r"\1. :math:`\operatorname{si}(x)` costs $2"


@pytest.mark.slow
@pytest.mark.pipeline
def test_the_snakemake_report_lists_every_figure_of_the_report_with_its_caption(built_repo, tmp_path):
    started = time.monotonic()
    snakemake(built_repo, "--report", str(tmp_path / "r.zip"), "--config", "quick=1")
    took = time.monotonic() - started
    archive = zipfile.ZipFile(tmp_path / "r.zip")
    page = archive.read("r/report.html").decode()
    categories, results = embedded(page, "categories"), embedded(page, "results")

    # One category per study, titled and numbered as the report's chapters, and the report itself
    report = (built_repo / "results/report.html").read_text()
    titles = {
        study: html.unescape(
            re.search(rf'<section id="{study}" class="chapter">\s*<h2 data-toc="([^"]+)"', report)[1]
        )
        for study in STUDIES
    }
    assert titles == {study: chapter(study) for study in STUDIES}
    assert set(categories) == set(titles.values()) | {REPORT}
    assert sorted(categories[REPORT]["report"]) == ["results/report.html", "results/report.pdf"]

    # Every SVG the report shows (each figure links its own at full size), there with its caption
    shown = re.findall(r'<a class="full-size" href="([^"]+\.svg)"', report)
    assert {path.split("/")[0] for path in shown} == set(STUDIES) | {"measured"}, shown
    members = set(archive.namelist())
    for path in shown:
        key = f"results/{path}"
        assert key in results, key
        assert f"r/{results[key]['data_uri']}" in members
        entry, caption = results[key], words(results[key]["caption"])
        if path.startswith("measured/"):
            assert key in categories[REPORT]["measured"] and "benchmarks/" in caption
            continue
        study, *timing, scene, name = path.split("/")
        assert key in categories[chapter(study)][scene], key
        summary = json.loads((built_repo / "results" / study / scene / "summary.json").read_text())
        figures = summary["timings"]["figures"] if timing else summary["figures"]
        written = next(meta["caption"] for meta in figures.values() if meta["file"] == name)
        # the caption's text, math apart (typeset by docutils), word for word
        for text in _INLINE.split(written)[::2]:
            assert " ".join(text.replace("\\$", "$").split()) in caption, (key, text, caption)
        assert "formula" in entry["caption"] or "$" not in written  # its math typeset, none left as typed
        assert ":math:" not in caption and "System Message" not in caption

    # and every table of every scene, with its caption, beside its figures
    for summary_file in (built_repo / "results").glob("*/*/summary.json"):
        summary, (study, scene) = json.loads(summary_file.read_text()), summary_file.parent.parts[-2:]
        for meta in summary["tables"].values():
            key = f"results/{study}/{scene}/{meta['file']}"
            assert key in categories[chapter(study)][scene] and results[key]["caption"], key

    # The flags change no job: after the report, nothing to do
    dry = snakemake(built_repo, "-n", "--config", "quick=1")
    assert "Nothing to be done" in dry.stdout + dry.stderr
    print(f"snakemake --report: {took:.1f} s, {len(results)} files")
