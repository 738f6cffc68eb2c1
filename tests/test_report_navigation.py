"""Finding one's way through the report, trusting a number, citing it: in real Chromium and on the real PDF.

The HTML at a laptop's width (1280 px) and a phone's (390 px, touch); the PDF's pages, outline and metadata
through poppler. The numbering and citation helpers are tested directly.
"""

import json
import re
import subprocess
from html import unescape
from pathlib import Path

import pytest
import yaml

from classical_dynamics.report import assets
from classical_dynamics.report.citation import citation
from classical_dynamics.report.claims import ClaimFailure, ClaimResult, require
from classical_dynamics.report.navigation import add_navigation, number_sections
from classical_dynamics.studies import STUDIES

from .test_report_typesetting import CHROMIUM, FLAGS

ROOT = Path(__file__).resolve().parents[1]
CLAIMS = {study: assets.claims_file(study) for study in STUDIES}
PAGE_BUDGET = 60  # A4 pages, issue 16


# --- numbering and citation, directly ------------------------------------------------------------

PAGE = """<nav><!--contents--></nav>
<section id="abstract" class="front"><h2>Abstract</h2></section>
<section id="intro" class="chapter"><h2>Introduction</h2><h3 id="intro-a">First</h3><h3>Second <i>part</i></h3></section>
<section id="two" class="chapter"><h2>Two</h2><h3 id="two-a">Only</h3></section>
<section id="extra" class="appendix"><h2>Tables</h2><h3 id="extra-a">All</h3></section>"""  # noqa: E501


def test_sections_are_numbered_and_listed_two_levels_deep():
    page, outline = number_sections(PAGE)
    assert [(h.number, h.text) for h in outline] == [
        ("", "Abstract"),
        ("1", "Introduction"),
        ("2", "Two"),
        ("A", "Tables"),
    ]
    assert [(h.number, h.id) for h in outline[1].children] == [
        ("1.1", "intro-a"),
        ("1.2", "intro-second-part"),
    ]
    assert outline[3].children[0].number == "A.1"
    assert 'data-toc="1.2 Second part"' in page and 'href="#intro-second-part"' in page
    full = add_navigation(PAGE)
    contents = full[full.index("<nav>") : full.index("</nav>")]
    assert (
        contents.count("<li>") == 8 and '<a href="#two-a"><span class="secno">2.1</span> Only</a>' in contents
    )


def test_two_sections_with_one_id_are_refused():
    with pytest.raises(ValueError, match="intro-a"):
        number_sections(PAGE.replace('id="two-a"', 'id="intro-a"'))


def test_the_bibtex_entry_says_what_citation_cff_says():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    cite = citation(ROOT, "0123456789abcdef0123456789abcdef01234567", dirty=False, archive_sha256="ab" * 32)
    fields = dict(re.findall(r"^\s+(\w+) = \"(.*)\",?$", cite["bibtex"], re.M))
    assert fields["title"] == cff["title"]
    assert fields["version"] == f"{cff['version']}+g01234567"
    assert fields["author"] == " and ".join("{" + a["name"] + "}" for a in cff["authors"])
    assert "0123456789abcdef0123456789abcdef01234567" in fields["note"] and "ab" * 32 in fields["note"]
    assert cite["cff"] == (ROOT / "CITATION.cff").read_text().strip()
    assert (ROOT / "LICENSE").read_text().startswith(f"{cff['license']} License")


def _claim(passed, explanation=""):
    return ClaimResult(
        id="x",
        statement="s",
        study="precession",
        scene="a",
        number="n",
        computed=1.0,
        unit="",
        source={"value": 2.0},
        modern=None,
        check={"relative": 0.01},
        deviation=-1.0,
        relative_deviation=-0.5,
        passed=passed,
        must_hold=False,
        explanation=explanation,
    )


def test_a_claim_that_fails_must_say_why():
    with pytest.raises(ClaimFailure, match="precession/x"):
        require([_claim(False)])
    require([_claim(False, "a rigid Earth"), _claim(True)])


# --- the built report in Chromium ------------------------------------------------------------------

LANDS = """(id) => { const t = document.getElementById(id); if (!t) return null;
  const r = t.getBoundingClientRect(); return {top: r.top, visible: r.height > 0 && r.bottom > 0}; }"""


@pytest.fixture(scope="module")
def browser():
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        yield b
        b.close()


def _open(browser, built_repo, width, touch=False):
    context = browser.new_context(viewport={"width": width, "height": 900}, has_touch=touch, is_mobile=touch)
    page = context.new_page()
    page.goto((built_repo / "results/report.html").as_uri(), wait_until="load")
    return page


@pytest.mark.slow
@pytest.mark.parametrize("width", [1280, 390])
def test_every_contents_link_lands_on_its_target(browser, built_repo, width):
    page = _open(browser, built_repo, width, touch=width < 1000)
    targets = page.eval_on_selector_all(
        "nav.toc a", "links => links.map(a => a.getAttribute('href').slice(1))"
    )
    assert len(targets) > 30  # chapters and their sections
    missed = []
    for target in targets:
        if width < 1000:
            page.click(".menu-toggle")  # on a phone the contents are a menu
        page.click(f"nav.toc a[href='#{target}']")
        page.wait_for_timeout(30)
        where = page.evaluate(LANDS, target)
        if where is None or not where["visible"] or abs(where["top"]) > 60:
            missed.append((target, where))
        if width < 1000:
            assert not page.is_visible("nav.toc"), "the menu closes when a section is chosen"
    assert missed == []
    assert page.evaluate("document.documentElement.scrollWidth") <= width  # no horizontal scroll
    page.context.close()


@pytest.mark.slow
def test_the_sidebar_stays_beside_the_text_on_a_laptop(browser, built_repo):
    page = _open(browser, built_repo, 1280)
    assert page.is_visible("nav.toc") and not page.is_visible(".menu-toggle")
    page.evaluate("window.scrollTo(0, document.body.scrollHeight / 2)")
    box = page.locator("nav.toc").bounding_box()
    assert box["y"] <= 1 and box["x"] < 400  # sticky, on the left, still in view
    page.context.close()


@pytest.mark.slow
def test_the_phone_menu_opens(browser, built_repo):
    page = _open(browser, built_repo, 390, touch=True)
    assert not page.is_visible("nav.toc")
    page.tap(".menu-toggle")
    assert page.is_visible("nav.toc a[href='#chains']")
    assert page.get_attribute(".menu-toggle", "aria-expanded") == "true"
    page.context.close()


def _provenance_of(page, link):
    scene, key = link.get_attribute("data-scene"), link.get_attribute("data-key")
    panel = page.locator("#provenance-panel")
    assert panel.is_visible()
    text = panel.inner_text()
    return scene, key, text


@pytest.mark.slow
@pytest.mark.parametrize("how", ["click", "tap", "keyboard"])
def test_a_number_opens_its_provenance(browser, built_repo, how):
    page = _open(browser, built_repo, 390 if how == "tap" else 1280, touch=how == "tap")
    link = page.locator("#chandler a.num").first
    link.scroll_into_view_if_needed()
    if how == "click":
        link.click()
    elif how == "tap":
        link.tap()
    else:
        link.focus()
        page.keyboard.press("Enter")
    scene, key, text = _provenance_of(page, link)
    study, name = scene.split("/")
    assert f"workflow/scenes/{study}/{name}.yaml" in text  # its scene
    assert f"results/{scene}/summary.json → numbers.{key}" in text  # its file and key
    assert f"snakemake -c all results/{scene}" in text  # the command that rebuilds it
    provenance = json.loads((built_repo / "results" / scene / "provenance.json").read_text())
    assert re.search(r"commit\s+" + re.escape(provenance["commit"]), text)
    assert re.search(r"scene SHA-256\s+" + provenance["scene_sha256"], text)
    assert float(link.get_attribute("data-value")) == pytest.approx(
        float(re.search(r"value\s+(\S+)", text)[1])
    )
    # the panel links to the appendix row, and that row names the number and links back
    row = page.locator(f"#prov-{study}-{name}")
    assert page.locator(f"#provenance-panel a[href='#prov-{study}-{name}']").count() == 1
    back = row.locator(f"tr.cited a:has-text('{key}')").first
    assert page.locator(back.get_attribute("href")).first.get_attribute("data-key") == key
    page.keyboard.press("Escape")
    assert not page.is_visible("#provenance-panel")
    page.context.close()


@pytest.mark.slow
def test_a_tap_shows_a_figure_at_its_print_size_on_a_phone(browser, built_repo):
    """Fitted to 390 px a full-width figure's text falls to about 5 px; a tap shows it at its intrinsic
    (print) width, its text as on paper, scrolling inside its own box while the page stays 390 px wide."""
    page = _open(browser, built_repo, 390, touch=True)
    link = page.locator("figure.figure a.full-size").first
    link.scroll_into_view_if_needed()
    fitted = link.locator("img").bounding_box()["width"]
    natural = link.locator("img").evaluate("img => img.naturalWidth")
    assert fitted < 390 < natural  # a full-width figure is wider than a phone at print size
    link.tap()
    assert link.get_attribute("aria-expanded") == "true"
    assert link.locator("img").bounding_box()["width"] == pytest.approx(natural, abs=1)
    assert page.evaluate("document.documentElement.scrollWidth") <= 390  # the figure scrolls, not the page
    link.tap()
    assert link.locator("img").bounding_box()["width"] == pytest.approx(fitted, abs=1)
    page.context.close()


@pytest.mark.slow
def test_every_figure_links_its_svg_data_and_scene(built_repo):
    page = (built_repo / "results/report.html").read_text()
    figures = re.findall(r'<figure id="fig:[^"]+" class="figure">.*?</figure>', page, re.S)
    assert len(figures) > 20
    for figure in figures:
        links = re.findall(r'<a href="([^"#]+)"', figure)
        kinds = {Path(link).suffix for link in links}
        scene = re.sub(r"<[^>]+>", "", re.search(r"scene <a[^>]*><code>(.*?)</code>", figure)[1])
        source = json.loads((built_repo / "results" / scene / "provenance.json").read_text())["scene_file"]
        # the scene's link is the copy of its file that travels with its results (the same bytes); a step
        # drawn from other scenes (the gallery) has no scene file and links its provenance
        assert {".svg", ".csv"} <= kinds, figure[-400:]
        if (built_repo / source).suffix == ".yaml":
            assert f"{scene}/scene.yaml" in links, figure[-400:]
            assert (built_repo / "results" / scene / "scene.yaml").read_bytes() == (
                built_repo / source
            ).read_bytes()
        else:
            assert f"{scene}/provenance.json" in links, figure[-400:]
        for link in links:
            assert (built_repo / "results" / link).resolve().is_file(), link


# --- the PDF -------------------------------------------------------------------------------------


@pytest.mark.slow
def test_the_pdf_keeps_its_page_budget_outline_and_metadata(built_repo):
    pdf = built_repo / "results/report.pdf"
    info = subprocess.run(
        ["pdfinfo", "-isodates", str(pdf)], capture_output=True, text=True, check=True
    ).stdout
    fields = dict(line.split(":", 1) for line in info.splitlines() if ":" in line)
    fields = {k.strip(): v.strip() for k, v in fields.items()}

    # the main text (title page to the last chapter) within the budget; appendices and back matter outside it
    def text(page):
        return subprocess.run(
            ["pdftotext", "-f", str(page), "-l", str(page), str(pdf), "-"], capture_output=True, text=True
        ).stdout

    # the first page headed by the first appendix, as heading or running head: a line of its own (the contents
    # and the pointers to its tables name it inside longer lines)
    appendix = next(
        page
        for page in range(1, int(fields["Pages"]) + 1)
        if "A Long tables in full" in text(page).splitlines()
    )
    assert 40 < appendix - 1 <= PAGE_BUDGET
    cff = yaml.safe_load((built_repo / "CITATION.cff").read_text())
    assert fields["Title"] == cff["title"]
    assert fields["Author"] == cff["authors"][0]["name"]
    assert "Chandler wobble" in fields["Subject"] and "precession of the equinoxes" in fields["Keywords"]
    # The date is the commit's (a rebuild keeps it); the test's copy is no git checkout, so it is the newest
    # result's.
    newest = max(
        json.loads(p.read_text())["finished"] for p in (built_repo / "results").glob("*/*/provenance.json")
    )
    assert fields["CreationDate"][:10] == newest[:10]
    assert (
        f'<meta name="dcterms.created" content="{newest}">'
        in (built_repo / "results/report.html").read_text()
    )
    # The outline: every numbered chapter and section of the contents, in order.
    xml = subprocess.run(
        ["pdftohtml", "-xml", "-i", "-stdout", "-q", str(pdf)], capture_output=True, text=True, check=True
    ).stdout
    outline = [unescape(o).strip() for o in re.findall(r"<item[^>]*>([^<]+)</item>", xml)]
    html_page = (built_repo / "results/report.html").read_text()
    headings = [unescape(h) for h in re.findall(r'<h[23](?: id="[^"]+")? data-toc="([^"]+)"', html_page)]
    assert len(headings) > 30 and headings == [o for o in outline if o != "Contents"]


def _outline_starts(pdf) -> set[int]:
    """Pages on which a top-level entry of the PDF outline (a chapter, appendix or front section) starts."""
    xml = subprocess.run(
        ["pdftohtml", "-xml", "-i", "-stdout", "-q", str(pdf)], capture_output=True, text=True, check=True
    ).stdout
    starts, depth = set(), 0
    for tag, page in re.findall(r'<(/?outline|item)(?: page="(\d+)")?', xml):
        depth += {"outline": 1, "/outline": -1}.get(tag, 0)
        if tag == "item" and depth == 1:
            starts.add(int(page))
    return starts


@pytest.mark.slow
def test_no_page_is_more_than_40_percent_blank_but_a_sections_last(built_repo, tmp_path):
    """Ink must reach at least 60 % down the text block, except on the last page of a chapter or section."""
    import numpy as np
    from PIL import Image

    pdf = built_repo / "results/report.pdf"
    subprocess.run(["pdftoppm", "-r", "30", "-gray", str(pdf), str(tmp_path / "p")], check=True)
    pages = sorted(tmp_path.glob("p-*.pgm"))
    starts = _outline_starts(pdf)
    mostly_blank = []
    for number, page in enumerate(pages, start=1):
        if number + 1 in starts or number == len(pages):
            continue  # a chapter's last page may end where it ends
        ink = np.asarray(Image.open(page)) < 200
        mm = ink.shape[0] / 297
        block = ink[int(22 * mm) : int((297 - 18) * mm)]  # below the running head, above the folio
        rows = np.flatnonzero(block.any(axis=1))
        used = (rows.max() + 1) / len(block) if len(rows) else 0.0
        if used < 0.6:
            mostly_blank.append((number, round(1 - used, 2)))
    assert mostly_blank == []


# --- the source ledger ---------------------------------------------------------------------------


def _ledger(tmp_path, entry):
    folder = tmp_path / "ledger"
    folder.mkdir(exist_ok=True)
    (folder / "notes.yaml").write_text(
        yaml.safe_dump({"source": {"key": "lecture_notes", "title": "Notes"}, "statements": [entry]})
    )
    return folder


@pytest.mark.parametrize(
    "entry,message",
    [
        ({"id": "a", "where": "p. 1", "states": "ω² = k/m"}, "maps to nothing"),
        ({"id": "a", "claim": "chains/no_such_claim"}, "no_such_claim"),
        ({"id": "a", "claim": "chains/lamb_node", "out_of_scope": "historical"}, "exactly one"),
    ],
)
def test_a_ledger_statement_must_map_to_one_thing_that_exists(tmp_path, entry, message):
    from classical_dynamics.report.ledger import LedgerError, read_ledger

    with pytest.raises(LedgerError, match=message):
        read_ledger(_ledger(tmp_path, entry), CLAIMS)


def test_the_ledgers_map_every_statement(tmp_path):
    from classical_dynamics.report.ledger import read_ledger

    sources = read_ledger(assets.LEDGER, CLAIMS)
    for source in sources:
        assert source.statements, source.key
        assert all(s.kind != "out_of_scope" or len(s.target) > 20 for s in source.statements)  # a real reason


@pytest.mark.slow
def test_every_link_of_the_report_resolves_inside_the_results_folder(built_repo):
    """The shipped folder is self-contained: every link of results/report.html that is not an anchor in the
    page leads to a file inside results/ (scene files and measured data are copied in beside the results)."""
    import html as html_lib
    import re
    from urllib.parse import unquote, urlsplit

    results = (built_repo / "results").resolve()
    page = (results / "report.html").read_text(encoding="utf-8")
    outside, missing = [], []
    for href in sorted(set(re.findall(r'href="([^"#][^"]*)"', page))):
        parts = urlsplit(html_lib.unescape(href))
        if parts.scheme in ("http", "https", "mailto"):
            continue
        target = (results / unquote(parts.path)).resolve()
        if not target.is_relative_to(results):
            outside.append(href)
        elif not target.exists():
            missing.append(href)
    assert outside == [] and missing == []
