"""The report as a reader meets it: the HTML in headless Chromium, the PDF rendered to page images."""

import json
import re
import subprocess

import numpy as np
import pytest
from PIL import Image

from .test_report_typesetting import CHROMIUM, FLAGS

pytestmark = [pytest.mark.slow, pytest.mark.pipeline]


def test_html_in_a_real_browser(built_repo, tmp_path):
    from playwright.sync_api import sync_playwright

    html = built_repo / "results/report.html"
    errors, failed, requests = [], [], []
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        page = browser.new_page(viewport={"width": 1200, "height": 1000})
        page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.on("requestfailed", lambda r: failed.append(r.url))
        page.on("request", lambda r: requests.append(r.url))
        page.goto(html.as_uri(), wait_until="load")
        images = page.evaluate("Array.from(document.images).map(i => [i.complete, i.naturalWidth, i.alt])")
        figures = page.evaluate("document.querySelectorAll('figure.figure img').length")
        numbers = page.evaluate("""Array.from(document.querySelectorAll('a.num')).map(a => {
            const p = JSON.parse(document.getElementById('provenance-data').textContent)[a.dataset.scene];
            return p ? [p.commit, p.input, a.dataset.key, a.dataset.value] : null; })""")
        page.screenshot(path=str(tmp_path / "top.png"))
        page.locator("#chains-results").scroll_into_view_if_needed()
        page.screenshot(path=str(tmp_path / "results.png"))
        browser.close()
    assert errors == [] and failed == []
    assert [u for u in requests if not u.startswith(("file:", "data:"))] == []  # works offline
    assert figures >= 10 and all(complete and width > 0 for complete, width, _ in images)
    # every number knows its scene's commit and input hash, its key and its full value
    assert len(numbers) > 50 and all(n and n[0] and len(n[1]) == 64 and n[2] and n[3] for n in numbers)
    for shot in ("top.png", "results.png"):
        pixels = np.asarray(Image.open(tmp_path / shot).convert("L"), dtype=float)
        assert pixels.std() > 10  # not blank


def test_html_has_resolved_numbering(built_repo):
    text = (built_repo / "results/report.html").read_text()
    assert "&nbsp;?</a>" not in text
    labels = re.findall(r'<span class="label">Figure (\d+)\.</span>', text)
    assert labels == [str(i) for i in range(1, len(labels) + 1)] and len(labels) >= 10
    eqs = re.findall(r'<span class="eqno">\((\d+)\)</span>', text)
    assert eqs == [str(i) for i in range(1, len(eqs) + 1)]


def test_the_appendix_shows_the_measured_scaling_with_its_origin(built_repo):
    """The cost-against-scenes figure and its slopes come from the benchmark's saved file, named with its
    commit."""
    import json

    from classical_dynamics.formatting import format_number

    data = json.loads((built_repo / "benchmarks/results/pipeline_scaling.json").read_text())
    text = (built_repo / "results/report.html").read_text()
    section = text[
        text.index("How the cost grows with the number of scenes") : text.index('id="provenance-scenes"')
    ]
    assert 'id="fig:pipeline-scaling"' in section and data["commit"][:10] in section
    links = re.findall(r'<a href="([^"#]+)"', section)
    assert {
        "measured/pipeline_scaling.svg",
        "measured/pipeline_scaling.json",
        "measured/pipeline_scaling.py",
    } <= set(links)
    for link in links:
        assert (built_repo / "results" / link).resolve().is_file(), link
    for key in ("build_s_per_scene", "report_html_s_per_scene", "report_pdf_s_per_scene"):
        assert format_number(data["slopes"][key], 2) in section, key
    assert format_number(data["slopes"]["dry_run_s_per_1000_scenes"], 2) in section


def test_pdf_pages(built_repo, tmp_path):
    pdf = built_repo / "results/report.pdf"
    subprocess.run(["pdftoppm", "-png", "-r", "72", str(pdf), str(tmp_path / "page")], check=True)
    pages = sorted(tmp_path.glob("page-*.png"))
    assert len(pages) >= 10

    def body(page):  # the page less its running header and page number (grey: ink of their own)
        image = np.asarray(Image.open(page).convert("L"))
        return image[int(0.06 * len(image)) : int(0.94 * len(image))]

    inked = [body(p).min() < 100 for p in pages]  # no page is empty but for header and number
    assert all(inked), [p.name for p, ink in zip(pages, inked) if not ink]
    text = subprocess.run(
        ["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True, check=True
    ).stdout
    html = (built_repo / "results/report.html").read_text()
    for number in re.findall(r'<span class="label">Figure (\d+)\.</span>', html):
        assert f"Figure {number}." in text  # every figure, same number
    assert "Contents" in text and "References" in text and "Vibrations of chains" in text
    assert "The Chandler wobble" in text and "observed polar motion" in text
    assert "Precession of the equinoxes" in text and "The spin-resolved Earth" in text
    assert "The self-excited rigid body" in text and "Periodic motions as series" in text
    # page numbers: the contents page names the page of the chains chapter
    assert re.search(r"Vibrations of chains\s*\.*\s*\d+", text)
    # figures are drawn: a figure page has much more ink than a text page
    heavy = [np.mean(np.asarray(Image.open(p).convert("L")) < 200) for p in pages]
    assert max(heavy) > 0.04


@pytest.mark.slow
def test_each_studys_effects_table_is_its_registry(built_repo):
    """The appendix's table of a study's effects is generated from its registry (through each scene's
    provenance): every effect a built scene lists, with the registry's kind."""
    import importlib

    page = (built_repo / "results/report.html").read_text(encoding="utf-8")
    checked = 0
    for provenance_file in sorted((built_repo / "results").glob("*/*/provenance.json")):
        record = json.loads(provenance_file.read_text())
        if "effects_simulated" not in record or not record["effects_simulated"]:
            continue
        study = record["study"]
        registry = importlib.import_module(f"classical_dynamics.studies.{study}").EFFECTS
        label = f"tab:{study}-effect-registry"
        table = re.search(rf'<figure class="table" id="{label}">(.*?)</figure>', page, re.S)
        assert table, study
        cells = re.findall(r"<tr><td><code>(.*?)</code></td><td>(\w+)</td>", table[1])
        # a long name carries break points (<wbr>, soft hyphens) for narrow columns
        rows = {re.sub(r"<[^>]+>|\u00ad|\u200b", "", name): kind for name, kind in cells}
        for name in record["effects_simulated"]:
            assert rows.get(name) == registry[name].kind, (study, name)
            checked += 1
    assert checked > 20
