"""The bibliography: every entry of report/references.bib typeset by pybtex + latexcodec, with no TeX left."""

import html
import re
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from classical_dynamics.report import assets  # noqa: E402
from classical_dynamics.report.bib import Citations, format_entry, read_bib  # noqa: E402

BIB = assets.BIBLIOGRAPHY
ENTRIES = read_bib(BIB)


class _Text(HTMLParser):
    """The text a reader sees (tags dropped, entities decoded), and the tags used."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.text, self.tags, self.links = [], [], []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        if tag == "a":
            self.links.append(dict(attrs)["href"])

    def handle_data(self, data):
        self.text.append(data)


def _read(fragment: str) -> _Text:
    parser = _Text()
    parser.feed(fragment)
    parser.close()
    parser.text = "".join(parser.text)
    return parser


def _mentions(entry, pattern: str) -> bool:
    return any(re.search(pattern, entry.get(name, "")) for name in entry)


def _write_bib(tmp_path, text: str) -> dict:
    path = tmp_path / "t.bib"
    path.write_text(text, encoding="utf-8")
    return read_bib(path)


def test_the_file_has_entries():
    assert len(ENTRIES) >= 20 and all(e.key == k for k, e in ENTRIES.items())


@pytest.mark.parametrize("key", sorted(ENTRIES))
def test_every_entry_renders_without_tex(key):
    fragment = format_entry(ENTRIES[key])
    seen = _read(fragment)
    for raw in ("\\", "{", "}", "``", "''", "$"):
        assert raw not in seen.text, f"{key}: {raw!r} left in {seen.text!r}"
    assert set(seen.tags) <= {"em", "strong", "a", "sup", "sub"}, seen.tags
    assert seen.text.endswith("."), seen.text
    assert "  " not in seen.text and ".." not in seen.text
    if ENTRIES[key].get("title"):  # the title's words are all there
        words = re.findall(r"[A-Za-z]{4,}", ENTRIES[key]["title"])
        assert all(w in seen.text for w in words), (words, seen.text)


def test_accented_names_print_as_letters():
    poincare = [k for k, e in ENTRIES.items() if _mentions(e, "Poincar")]
    norsett = [k for k, e in ENTRIES.items() if _mentions(e, r"N.{0,5}rsett")]
    assert poincare and norsett
    for key in poincare:
        assert "Poincaré" in _read(format_entry(ENTRIES[key])).text
    for key in norsett:
        assert "Nørsett" in _read(format_entry(ENTRIES[key])).text


def test_tex_quotes_and_protected_capitals():
    (key,) = [k for k, e in ENTRIES.items() if "REN" in e.get("title", "")]
    text = _read(format_entry(ENTRIES[key])).text
    assert "“REN-2000”" in text and " III. " in text


def test_a_doi_becomes_a_link():
    with_doi = {k: e for k, e in ENTRIES.items() if e.get("doi")}
    assert len(with_doi) >= 10
    for key, entry in with_doi.items():
        fragment = format_entry(entry)
        doi = entry["doi"]
        assert f'href="https://doi.org/{doi}"' in fragment, fragment
        assert _read(fragment).text.rstrip(".").endswith(f"doi:{doi}")


def test_citations_are_numbered_in_order_of_first_use():
    first, second, third = sorted(ENTRIES)[:3]
    citations = Citations(ENTRIES)
    assert citations.cite(second) == 1
    assert citations.cite(first) == 2
    assert citations.cite(second) == 1
    assert citations.cite(third) == 3
    assert citations.order == [second, first, third]
    with pytest.raises(KeyError, match="citation 'no_such_key' is not in the report's references.bib"):
        citations.cite("no_such_key")
    assert citations.order == [second, first, third]


def test_layout_of_an_article_and_a_book(tmp_path):
    entries = _write_bib(
        tmp_path,
        r"""
@article{a, author = {Name, Albert B. and Other, C. and Third, D.}, title = {Waves---and {Fourier} \& co.},
  journal = {J. Things}, volume = {7}, number = {2}, pages = {10-20}, year = {2001}, doi = {10.1/x<y>}}
@book{b, author = {van der Berg, J. and Smith, Jr., A. and others}, title = {A Book}, publisher = {Pub},
  address = {Town}, year = {1999}, url = {https://example.org/a\_b?c=1&d=2}}
""",
    )
    article = format_entry(entries["a"])
    assert _read(article).text == (
        "A. B. Name, C. Other and D. Third (2001). Waves—and Fourier & co. "
        "J. Things 7(2), 10–20. doi:10.1/x<y>."
    )
    assert "<em>J. Things</em>" in article and "<em>Waves" not in article
    assert "&amp; co." in article and "x&lt;y&gt;" in article and "<y>" not in article
    assert _read(article).links == ["https://doi.org/10.1/x%3Cy%3E"]

    book = format_entry(entries["b"])
    assert _read(book).text.startswith("J. van der Berg, A. Smith Jr. et al. (1999). A Book. Pub, Town.")
    assert "<em>A Book</em>" in book
    assert _read(book).links == ["https://example.org/a_b?c=1&d=2"]
    assert 'href="https://example.org/a_b?c=1&amp;d=2"' in book


def test_unknown_tex_is_an_error_not_output(tmp_path):
    entries = _write_bib(tmp_path, r"@misc{m, title = {A \foo{bar} title}, year = {2000}}")
    with pytest.raises(ValueError, match=r"m\.title.*\\foo"):
        format_entry(entries["m"])


def test_html_in_fields_is_escaped(tmp_path):
    entries = _write_bib(tmp_path, r'@misc{m, title = {<script>alert("x")</script>}, note = {a < b}}')
    fragment = format_entry(entries["m"])
    assert "<script>" not in fragment and "&lt;script&gt;" in fragment
    assert html.unescape(fragment).startswith('<script>alert("x")</script> (n.d.).')


@pytest.mark.parametrize(
    "tex,html_out",
    [
        (r"The {Bessel} functions", "The Bessel functions"),
        (r"$J_0$ and $x^{2}$", "<em>J</em><sub>0</sub> and <em>x</em><sup>2</sup>"),
        (r"\emph{Der Kreisel} and \textbf{bold}", "<em>Der Kreisel</em> and <strong>bold</strong>"),
        (r"``quoted'' and $f'$", "\u201cquoted\u201d and <em>f</em>\u2032"),
        (r"$\alpha$ \& 50\%", "\u03b1 &amp; 50%"),
        (r"\url{https://example.org/a_b}", '<a href="https://example.org/a_b">https://example.org/a_b</a>'),
    ],
)
def test_a_field_is_typeset_from_its_tex(tex, html_out):
    """The TeX a field may hold, read by hand here into what a reader should see."""
    from classical_dynamics.report.bib import _rich

    assert _rich(tex, "t").render_as("html") == html_out


@pytest.mark.parametrize(
    "tex,what",
    [
        ("a } b", "an unmatched '}'"),
        ("{a", "an unclosed '{'"),
        ("$x", "an unclosed '$'"),
        ("a \\", "can't decode"),  # latexcodec refuses it before the reader sees it
        ("\\emph", "a command without its argument"),
        ("\\frobnicate{x}", "the command \\frobnicate"),
    ],
)
def test_tex_the_reader_does_not_know_is_refused_naming_it(tex, what):
    from classical_dynamics.report.bib import _rich

    with pytest.raises(ValueError, match=re.escape(what)):
        _rich(tex, "entry x, field title")
