"""Unit tests of the report's pieces (report/build.py, claims.py, dist.py, pdf.py, assets.py) on tiny inputs
written in tmp_path: one scene written by the studies' own writer and read back, a two-row claims ledger, a
tampered results folder, a one-paragraph HTML page. No full report is built (render() and main() need every
study's results: the pipeline tests cover them)."""

import base64
import json
import re
import tarfile
from pathlib import Path

import pandas as pd
import pytest
from markupsafe import Markup
from matplotlib.figure import Figure

from classical_dynamics import io
from classical_dynamics.report import assets, build, claims, dist
from classical_dynamics.results import Results, new_figure

ROOT = Path(__file__).resolve().parents[1]


def write_scene(results_dir, rows=2, study="chains", scene="toy"):
    r = Results(study, scene, "A toy scene")
    r.number("period", 5.2254813, "s", note="4π/j₀₁")
    r.number("count", 7, "1")
    r.number("pair", [1.5, 2.5], "1")
    frame = pd.DataFrame({"k": range(1, rows + 1), "period": [5.2254813 / k for k in range(1, rows + 1)]})
    frame["name"] = ["node_regression"] * rows
    r.table("modes", frame, "The modes.", headers={"k": "$k$", "period": "period (s)", "name": "effect"})
    fig, ax = new_figure(3.0, 2.0)
    ax.plot([0.0, 1.0], [1.0, 0.5])
    r.figure("line", fig, "A line.")
    r.hard_case("bounded", "a bounded error", -3e-9, 1e-8)
    r.write(
        results_dir / study / scene,
        results_dir / study / "timings" / scene,
        {"study": study, "scene": scene, "commit": "abc", "wall_seconds": 0.25, "effects_simulated": ["g"]},
        {"wall_seconds": 0.25},
        {"scene.yaml": b"title: A toy scene\n"},
    )
    return results_dir / study / scene


@pytest.fixture(scope="module")
def results_dir(tmp_path_factory):
    return write_scene(tmp_path_factory.mktemp("report") / "results").parents[1]


@pytest.fixture(scope="module")
def built(results_dir):
    return build.Report(build.ResultsIndex(results_dir), ROOT, quick=True)  # reads the ledger: 0.8 s


@pytest.fixture
def report(built):
    """The module's Report as new: nothing numbered, shown or set aside yet."""
    from classical_dynamics.report.numbering import Numbering

    built.numbering, built._count, built.cited, built.long_tables = Numbering(), 0, {}, {}
    return built


def test_a_number_is_shown_rounded_with_its_unit_and_carries_its_full_value(report):
    shown = str(report.num("chains/toy", "period"))
    assert ">5.225</a>" in shown and 'data-value="5.2254813"' in shown and 'data-unit="s"' in shown
    assert 'href="#prov-chains-toy"' in shown and 'id="n1"' in shown
    again = str(report.num("chains/toy", "pair", i=1, unit=False, scale=2.0))
    assert ">5.000</a>" in again and 'data-key="pair[1]"' in again and 'id="n2"' in again
    assert report.cited[("chains", "toy")] == {"period": "n1", "pair[1]": "n2"}  # where each is first cited
    assert 'data-value="9.75"' in str(report.value("chains/toy", "derived", 9.75))
    with pytest.raises(KeyError, match="no number 'nope'"):
        report.index.entry("chains", "toy", "nope")
    with pytest.raises(KeyError, match="no results for chains/other"):
        report.index.summary("chains", "other")


def test_a_table_shows_the_csvs_rows_under_the_declared_headers(report):
    markup = str(report.table("chains/toy", "modes", "tab:modes"))
    assert markup.count("<tr>") == 3  # the header and the two rows written
    assert "Table 1." in markup and '<span class="unit">(s)</span>' in markup
    assert '<td class="n">1</td>' in markup and '<td class="n">2.613</td>' in markup  # 5.2254813/2, 4 figures
    assert "<td>node regression</td>" in markup  # an identifier reads as words
    kept = str(report.table("chains/toy", "modes", "tab:kept", columns=["k"], keep={"k": [2]}))
    assert kept.count("<tr>") == 2 and "Not shown here, in the CSV" in kept
    named = str(report.table("chains/toy", "modes", "tab:named", keep={"name": ["other"]}))
    assert named.count("<tr>") == 1  # no row holds that value
    assert str(report.ref("tab:kept")).endswith("Table&nbsp;2</a>")


def test_a_long_table_goes_to_the_appendix_and_leaves_a_line(report, tmp_path, monkeypatch):
    write_scene(tmp_path / "results", rows=build.LONG_TABLE_ROWS + 1)
    monkeypatch.setattr(report, "index", build.ResultsIndex(tmp_path / "results"))  # undone after the test
    line = str(report.table("chains/toy", "modes", "tab:long", long=True))
    assert line.startswith('<p class="long-table">') and "in the appendix" in line
    assert len(report.long_tables["chains"]) == 1 and 'class="table long"' in report.long_tables["chains"][0]
    written = str(report.long_table("chains", "tab:long", "what it holds", caller=lambda: "<figure/>"))
    assert "what it holds" in written and report.long_tables["chains"][-1] == "<figure/>"


def test_a_figure_carries_its_svg_and_links_its_data_and_scene(report, results_dir):
    markup = str(report.fig("chains/toy", "line", "fig:line", extra="More."))
    uri = re.search(r'src="(data:image/svg\+xml;base64,[^"]+)"', markup).group(1)
    svg = (results_dir / "chains" / "toy" / "line.svg").read_bytes()
    assert base64.b64decode(uri.split(",", 1)[1]) == svg == base64.b64decode(build.svg_data_uri(svg)[26:])
    assert "Figure 1." in markup and "A line. More." in markup and 'href="chains/toy/line.csv"' in markup
    assert 'href="chains/toy/scene.yaml"' in markup  # the scene file travels with its results
    assert "snakemake -c all results/chains/toy" in markup


def test_stability_scenes_and_provenance_come_from_the_written_files(report):
    (case,) = report.stability("chains")
    assert case["margin"] == pytest.approx(0.3) and case["holds"] and case["scene"] == "toy"
    (row,) = report.scenes_table("chains")
    assert row == {"scene": "toy", "title": "A toy scene", "effects": "g", "seconds": 0.25}
    data = json.loads(str(report.provenance_json()))
    assert data["chains/toy"]["commit"] == "abc" and data["chains/toy"]["link"] == "chains/toy/scene.yaml"
    assert data["chains/toy"]["scene"] == "workflow/scenes/chains/toy.yaml"
    assert report.index.studies() == ["chains"] and report.index.scenes("chains") == ["toy"]
    assert report.rebuild("chains") == "snakemake -c all chains"


def test_equations_citations_and_the_shipped_claims_of_a_partial_build(report):
    eq = str(report.eq("eq:one", caller=lambda: "x^2 +\n  y^2"))
    assert 'id="eq:one"' in eq and 'alt="x^2 + y^2"' in eq and "(1)" in eq
    assert str(report.ref("eq:one")).endswith("Eq.&nbsp;(1)</a>")
    assert 'class="eqno"' not in str(report.eq(None, caller=lambda: "z"))
    key = next(iter(report.citations.entries))
    assert f'href="#bib-{key}"' in str(report.cite([key]))
    # the chains study's own claims, against a scene that has none of their numbers: each says so
    shown = report.claims("chains")
    assert shown and all(c.problem.startswith("no computed value") for c in shown)
    assert report.claim("chains", "no-such-claim") is None and report.all_claims() == shown


def test_text_helpers_type_units_identifiers_and_break_points():
    assert build.break_points("<code>a/b_c-d</code> x_y") == "<code>a/<wbr>b_<wbr>c-<wbr>d</code> x_y"
    assert build._cell_html("node_regression") == "node regression"
    assert build._header_html("period (s)").endswith('<span class="unit">(s)</span>')
    assert isinstance(build.unit_html("s"), Markup)


# ---- claims.py: a two-row ledger and every kind of check


def write_claims(tmp_path, rows):
    import yaml

    path = tmp_path / "claims.yaml"
    path.write_text(yaml.safe_dump([{"must_hold": False} | row for row in rows]))  # may fail unless it says
    return path


def claim(id, number, check, value=None, **extra):
    return {
        "id": id,
        "statement": f"{id} holds",
        "kind": "statement",
        "computed": {"scene": "toy", "number": number, **extra.pop("pick", {})},
        "check": check,
        "source": {} if value is None else {"value": value},
        **extra,
    }


NUMBERS = {"period": 5.2, "pair": [-3.0, 2.0], "flag": True, "count": 7}


def lookup(study, scene, number):
    return {"value": NUMBERS[number], "unit": "s"}


@pytest.mark.parametrize(
    "row,passed",
    [
        (claim("rel", "period", {"relative": 0.01}, 5.21), True),  # |5.2/5.21 - 1| = 0.0019
        (claim("rel_off", "period", {"relative": 0.001}, 5.21), False),
        (claim("abs", "period", {"absolute": 0.05}, 5.25), True),
        (claim("most", "count", {"at_most": 7}), True),
        (claim("least", "count", {"at_least": 8}), False),
        (claim("factor", "period", {"factor": 2}, 10.0), True),  # 5.2/10 = 0.52 >= 1/2
        (claim("factor_off", "period", {"factor": 1.5}, 10.0), False),
        (claim("equals", "flag", {"equals": True}), True),
        (claim("index", "pair", {"absolute": 1e-12}, 2.0, pick={"index": 1}), True),
        (claim("max_abs", "pair", {"at_least": 3.0}, pick={"reduce": "max_abs"}), True),
    ],
)
def test_each_check_kind_decides_as_its_arithmetic_says(tmp_path, row, passed):
    (result,) = claims.evaluate("chains", write_claims(tmp_path, [row]), lookup)
    assert result.passed is passed and result.unit == "s" and result.anchor == f"claim-chains-{row['id']}"
    if "relative" in row["check"]:
        assert result.relative_deviation == pytest.approx(5.2 / 5.21 - 1)


def test_a_two_row_ledger_is_counted_by_kind_and_an_unexplained_failure_stops_the_report(tmp_path):
    rows = [
        claim("holds", "period", {"relative": 0.01}, 5.21),
        claim("fails", "period", {"relative": 1e-6}, 5.21, kind="limit", omits="drag, 1 %"),
    ]
    results = claims.evaluate("chains", write_claims(tmp_path, rows), lookup)
    assert claims.count_by_kind(results) == (
        "1 check of a source's statement or formula, 1 limit of the model"
    )
    with pytest.raises(claims.ClaimFailure, match="chains/fails"):
        claims.require(results)
    results[1].explanation = "the model leaves drag out"
    claims.require(results)  # explained, not must-hold: reported, not fatal
    with pytest.raises(ValueError, match="unknown check"):
        claims.evaluate("chains", write_claims(tmp_path, [claim("odd", "period", {"near": 1})]), lookup)
    assert claims.compares({"factor": 2}) and not claims.compares({"at_most": 1})


# ---- dist.py: the archive refuses a tampered folder; its manifest checks every member


def test_the_results_archive_lists_every_member_with_its_sha256_and_refuses_a_tampered_folder(tmp_path):
    import hashlib

    results = tmp_path / "results"
    folder = write_scene(results)
    (results / ".toy.staging").mkdir()  # a folder being written: never archived
    (results / ".toy.staging" / "summary.json").write_text("{}")
    names = {p.relative_to(results).as_posix() for p in dist.archive_members(results, with_report=False)}
    assert "chains/toy/summary.json" in names and not any(".toy" in n for n in names)
    archive = tmp_path / "out" / "x-results.tar.gz"
    dist.make_archive(results, archive, with_report=False)
    # the sum beside the archive is sha256 of its bytes; the manifest inside, of each member's bytes
    line = (archive.parent / "x-results.SHA256SUMS").read_text()
    assert line == f"{hashlib.sha256(archive.read_bytes()).hexdigest()}  x-results.tar.gz\n"
    with tarfile.open(archive) as tar:
        manifest = tar.extractfile("x-results/SHA256SUMS").read().decode().splitlines()
        for entry in manifest:
            digest, rel = entry.split("  ")
            assert hashlib.sha256(tar.extractfile(f"x-results/{rel}").read()).hexdigest() == digest
    assert any(e.endswith("  chains/toy/modes.csv") for e in manifest)
    assert dist.results_archive_name(results, ROOT).name.endswith("-results.tar.gz")
    (folder / "modes.csv").write_text("k,period\n1,6.0\n")  # tampered after its provenance was written
    with pytest.raises(io.ResultError, match="modes.csv"):
        dist.make_archive(results, tmp_path / "out" / "y.tar.gz", with_report=False)


def test_the_streamed_gzip_is_byte_for_byte_gzip_compress():
    import gzip
    import io as stdio

    data = b"classical dynamics " * 5000
    out = stdio.BytesIO()
    packed = dist._Gzip(out, level=6)
    for i in range(0, len(data), 4096):
        packed.write(data[i : i + 4096])
    packed.close()
    assert packed.tell() == len(data)
    assert out.getvalue() == gzip.compress(data, 6, mtime=0)


# ---- pdf.py and assets.py


def test_a_tiny_page_becomes_a_pdf_with_its_links_kept_relative(tmp_path):
    pytest.importorskip("weasyprint")
    from classical_dynamics.report import pdf

    page = tmp_path / "report.html"
    page.write_text('<html><body><p>One paragraph. <a href="chains/toy/modes.csv">data</a></p></body></html>')
    assert pdf.main([str(page), str(tmp_path / "report.pdf")]) == 0
    assert (tmp_path / "report.pdf").read_bytes().startswith(b"%PDF")
    assert pdf._relative(f"file://{tmp_path}/chains/x.csv#row", tmp_path) == "chains/x.csv#row"
    # the same page rendered in another folder: the same bytes (no path of this machine, no render-time stamp)
    other = tmp_path / "elsewhere" / "deeper"
    other.mkdir(parents=True)
    (other / "report.html").write_bytes(page.read_bytes())
    assert pdf.main([str(other / "report.html"), str(other / "report.pdf")]) == 0
    assert (other / "report.pdf").read_bytes() == (tmp_path / "report.pdf").read_bytes()
    assert pdf._relative("https://example.org/a", tmp_path) == "https://example.org/a"


def test_the_render_runs_with_the_collector_paused_and_writes_the_same_bytes(tmp_path, monkeypatch):
    """The PDF renders with Python's cyclic collector off (a third of its CPU went to full passes over
    WeasyPrint's objects), restored afterwards, also after a failure; with the collector on throughout, the
    same bytes."""
    import gc

    pytest.importorskip("weasyprint")
    from classical_dynamics.report import pdf

    page = tmp_path / "report.html"
    page.write_text("<html><body><h2>One</h2><p>A paragraph, <i>x</i><sub>1</sub>.</p></body></html>")
    seen = []
    render = pdf._render
    monkeypatch.setattr(pdf, "_render", lambda *args: seen.append(gc.isenabled()) or render(*args))
    assert gc.isenabled()
    pdf.html_to_pdf(page, tmp_path / "paused.pdf")
    assert seen == [False] and gc.isenabled()
    render(page, tmp_path / "collected.pdf")
    assert (tmp_path / "paused.pdf").read_bytes() == (tmp_path / "collected.pdf").read_bytes()
    with pytest.raises(OSError):
        pdf.html_to_pdf(tmp_path / "missing.html", tmp_path / "never.pdf")
    assert gc.isenabled()


def test_the_assets_name_every_studys_template_and_claims_file():
    from classical_dynamics.studies import STUDIES

    for study in STUDIES:
        assert assets.claims_file(study).name == "claims.yaml"
        template = assets.chapter_template(study)
        assert any((Path(folder) / template).is_file() for folder in assets.template_folders())
    files = assets.asset_files()
    assert assets.BIBLIOGRAPHY in files and all(p.is_file() for p in files)


# ---- snakemake_report.py: the captions of Snakemake's own report, from the written summary


def test_snakemakes_report_captions_each_file_as_the_summary_does(results_dir, tmp_path, monkeypatch):
    from types import SimpleNamespace

    from classical_dynamics.report import snakemake_report as sr
    from classical_dynamics.studies import STUDIES

    summary = json.loads((results_dir / "chains" / "toy" / "summary.json").read_text())
    assert sr.caption(summary, "line.svg") == "A line."
    assert sr.caption(summary, "modes.csv") == "The modes."
    assert sr.caption(summary, "line.csv") == "The data of line.svg: A line."
    assert sr.caption(summary, "hard_cases.csv").startswith("The scene's hard cases")
    assert sr.caption(summary, "run.csv", timing=True).startswith("What the job cost")
    assert sr.caption(summary, "other.csv") == "A file of chains/toy."
    # the chapter as the report numbers it: the introduction is 1, the studies follow in order
    assert sr.chapter("chains") == f"{list(STUDIES).index('chains') + 2} {STUDIES['chains'].title}"
    # as Snakemake asks: folders relative to the working directory, the caption written under it
    monkeypatch.chdir(tmp_path)
    import shutil

    shutil.copytree(results_dir, tmp_path / "results")
    output = SimpleNamespace(results="results/chains/toy", timings="results/chains/timings/toy")
    assert sr.category("results")(SimpleNamespace(file="line.svg", study="chains"), output) == sr.chapter(
        "chains"
    )
    assert (sr.CAPTIONS / "results/chains/toy/line.svg.rst").read_text() == "A line.\n"
    sr.category("timings", "chains")(SimpleNamespace(file="run.csv"), output)
    timing = (sr.CAPTIONS / "results/chains/timings/toy/run.csv.rst").read_text()
    assert (
        timing == "What the job cost\\: its wall and CPU time and peak memory, beside what was estimated.\n"
    )
    # RST: markup characters escaped, math as a role, a paragraph that would open a list escaped
    assert sr.rst("a *b* $x_1$th") == r"a \*b\* :math:`x_1`\ th"
    assert sr.rst("1. first") == r"\1. first"
    assert sr.rst(r"$\tfrac12 \sin x$") == r":math:`\tfrac{1}{2} \operatorname{sin} x`"


def test_the_context_of_a_partial_build_sums_its_times_and_pins_the_results_archive(report, results_dir):
    import hashlib

    context = report.context()
    assert context["studies"] == ["chains"] and context["build_times"] == {"chains": 0.25}
    assert context["results_commit"] == "abc" and context["quick"] is True
    assert set(context["css"]) == {"report", "screen", "print"} and context["script"]
    archive = dist.results_archive_name(results_dir, ROOT)
    archive.parent.mkdir(parents=True, exist_ok=True)
    try:
        archive.write_bytes(b"a stand-in archive")
        pinned = report.context()["results_archive"]
        assert pinned == {"name": archive.name, "sha256": hashlib.sha256(b"a stand-in archive").hexdigest()}
    finally:
        archive.unlink()
    assert report._benchmark("no_such_benchmark") is None


def test_a_result_with_an_unregistered_unit_or_a_bare_column_stops_where_it_is_written():
    """A unit the registry does not know, or a table whose headers leave a column out, would reach the
    reader as code ('XX1XX', 'step_hours'): the run stops at the record that wrote it, not in the report."""
    from classical_dynamics.units import UnknownUnit

    r = Results("chains", "toy", "A toy scene")
    with pytest.raises(ValueError, match="a name and a value"):
        r.number(None, 1.0, "m")
    with pytest.raises(ValueError, match="a name and a value"):
        r.number("length", None, "m")
    with pytest.raises(UnknownUnit, match="furlongs"):
        r.number("length", 1.0, "furlongs")
    with pytest.raises(ValueError, match="needs its unit"):  # lost, it would read as a pure number
        r.number("omega_squared_over_k_per_m", 3.0, None)
    with pytest.raises(UnknownUnit, match="fortnights"):
        r.hard_case("late", "a late case", 1.0, 2.0, unit="fortnights")
    frame = pd.DataFrame({"k": [1, 2], "step_hours": [0.5, 0.25]})
    with pytest.raises(ValueError, match="step_hours"):
        r.table("steps", frame, "Steps.", headers={"k": "$k$", "STEP_HOURS": "step (h)"})
    with pytest.raises(ValueError, match="step_hours"):
        r.timing_table("steps", frame, "Steps.", headers={"k": "$k$"})
    r.table("steps", frame, "Steps.", headers={"k": "$k$", "step_hours": "step (h)", "rtol": "rtol"})
    with pytest.raises(ValueError, match="no header for its columns"):  # a code name never reaches a reader
        r.table("bare", frame, "Steps, headed by their names.")
    headed = {"k": "$k$", "step_hours": "step (h)"}
    for name, description in ((None, "a case"), ("case", ""), ("case", None)):  # a hard case says what it is
        with pytest.raises(ValueError, match="a name and a description"):
            r.hard_case(name, description, 1.0, 2.0)
    # a caption or a figure lost stops the record too: the report shows nothing without its caption
    for caption in (None, "", "  "):
        with pytest.raises(ValueError, match="needs a caption"):
            r.table("uncaptioned", frame, caption, headers=headed)
        with pytest.raises(ValueError, match="needs a caption"):
            r.timing_figure("uncaptioned", Figure(), caption)
    with pytest.raises(ValueError, match="needs a matplotlib figure, not NoneType"):
        r.figure("lost", None, "A figure.")
    with pytest.raises(ValueError, match="needs a caption"):
        r.timing_table("uncaptioned", frame, None, headers=headed)
    assert not {"uncaptioned", "lost"} & {*r.tables, *r.figures, *r.timing_tables, *r.timing_figures}
    r.number("length", 1.0, "m")
    assert set(r.tables) == {"steps"} and r.numbers["length"]["unit"] == "m"


def test_every_unit_of_the_registry_typesets_with_any_value():
    """A unit is typeset wherever a number carries it: one whose math does not parse (rad s$^{-1}$: a
    superscript with nothing before it) would stop the HTML build, which no other fast test renders."""
    from classical_dynamics.report.build import unit_html
    from classical_dynamics.units import REGISTRY

    for key in REGISTRY:
        for value in (None, 1, 2.5):
            html = str(unit_html(key, value))
            assert "$" not in html and html.strip(), (key, html)


def test_a_wide_display_stacks_its_side_by_side_formulas_for_a_phone():
    """Only a top-level \\qquad separates formulas: one inside braces or a nested environment stays."""
    from classical_dynamics.report.math import stacked

    assert (
        stacked(r"a = 1,\qquad b = \frac{1}{2}") == r"\begin{gathered}a = 1, \\ b = \frac{1}{2}\end{gathered}"
    )
    assert (
        stacked(r"\begin{gathered}a,\qquad b,\\ c\end{gathered}")
        == r"\begin{gathered}a, \\ b,\\ c\end{gathered}"
    )
    assert stacked(r"\frac{a\qquad b}{c}") is None
    assert stacked(r"\begin{cases}a\qquad b\end{cases}") is None
    assert stacked(r"a + b") is None


def test_a_kept_equation_is_read_back_and_is_the_equation_set_afresh(tmp_path):
    """The report job keeps each display's SVG (ziamath takes a second for the thirty): what it reads back is
    what ziamath sets, under a folder named by the typesetting packages' releases, and it is read, not set
    again (a kept file altered by hand is what comes back: the folder is trusted, named by the code)."""
    from classical_dynamics.report import math as report_math

    latex = r"\omega_c = \frac{C - A}{A}\,r"
    try:
        report_math.keep_in(None)
        fresh = report_math.latex_image(latex)
        report_math.keep_in(tmp_path)
        assert report_math.latex_image(latex) == fresh  # set, and kept
        (kept,) = tmp_path.glob("*/*.svg")
        assert kept.parent.name.startswith("ziamath") and "latex2mathml" in kept.parent.name
        report_math.keep_in(tmp_path)  # a new process: nothing remembered but the folder
        assert report_math.latex_image(latex) == fresh
        kept.write_text(kept.read_text().replace("<svg", '<svg data-read="back"', 1))
        report_math.keep_in(tmp_path)
        assert "data-read" in base64.b64decode(report_math.latex_image(latex)[0].split(",")[1]).decode()
    finally:
        report_math.keep_in(None)


def test_templates_compiled_once_are_read_back_and_other_codes_folders_go(results_dir, tmp_path, monkeypatch):
    """The report job's cache folder is named by its code digest: the templates it compiled are read back by
    the next run (none compiled again), and the folders kept for other code are removed."""
    import jinja2

    cache = tmp_path / "digest-now"
    (tmp_path / "digest-before" / "jinja").mkdir(parents=True)
    build.forget_others(cache)
    assert not (tmp_path / "digest-before").exists()
    compiled = []
    original = jinja2.Environment.compile
    monkeypatch.setattr(
        jinja2.Environment, "compile", lambda self, *a, **k: compiled.append(a) or original(self, *a, **k)
    )
    first = build.Report(build.ResultsIndex(results_dir), ROOT, quick=True, cache=cache)
    code = first.env.get_template("report.html.j2").root_render_func.__code__.co_code
    assert compiled and list(cache.glob("jinja*/*.cache"))
    compiled.clear()
    again = build.Report(build.ResultsIndex(results_dir), ROOT, quick=True, cache=cache)
    assert again.env.get_template("report.html.j2").root_render_func.__code__.co_code == code
    assert not compiled
