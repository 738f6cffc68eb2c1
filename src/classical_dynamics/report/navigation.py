"""Section numbers, permalinks and the two-level contents, generated from the rendered headings.

The templates write plain headings: <section id=... class="chapter"> with an <h2>, and <h3 id=...> inside.
This pass numbers them (chapters 1, 2, ...; appendices A, B, ...; front matter and references unnumbered),
gives every heading an anchor and a permalink, and builds the contents from what is there, so a heading
added to a template appears in the sidebar, the printed contents and the PDF outline with the same number.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass, field

_TOKEN = re.compile(
    r'<section id="(?P<sid>[^"]+)" class="(?P<cls>[^"]*)">\s*<h2>(?P<h2>.*?)</h2>'
    r'|<h3(?: id="(?P<hid>[^"]+)")?>(?P<h3>.*?)</h3>',
    re.S,
)
_TAGS = re.compile(r"<[^>]+>")
CONTENTS_MARK = "<!--contents-->"


@dataclass
class Heading:
    id: str
    number: str
    html: str  # the heading's inner HTML, typeset
    children: list = field(default_factory=list)

    @property
    def text(self) -> str:
        return html.unescape(_TAGS.sub("", self.html)).strip()


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def _heading(tag: str, id_: str, number: str, inner: str, cls: str = "") -> str:
    label = f"{number} {Heading(id_, number, inner).text}".strip()
    secno = f'<span class="secno">{number}</span> ' if number else ""
    attrs = f' id="{id_}"' if tag == "h3" else ""
    return (
        f'<{tag}{attrs} data-toc="{html.escape(label, quote=True)}">{secno}{inner}'
        f'<a class="permalink" href="#{id_}" aria-label="Link to this section">#</a></{tag}>'
    )


def number_sections(page: str) -> tuple[str, list[Heading]]:
    """Number chapters and their sections in place; return the page and its outline."""
    outline: list[Heading] = []
    chapter = appendix = 0
    current: Heading | None = None
    seen: set[str] = set()

    def replace(match: re.Match) -> str:
        nonlocal chapter, appendix, current
        if match.group("sid"):
            sid, classes = match.group("sid"), match.group("cls").split()
            if "appendix" in classes:
                appendix += 1
                number = chr(ord("A") + appendix - 1)
            elif "chapter" in classes:
                chapter += 1
                number = str(chapter)
            else:
                number = ""
            current = Heading(sid, number, match.group("h2"))
            outline.append(current)
            return f'<section id="{sid}" class="{match.group("cls")}">' + _heading(
                "h2", sid, number, match.group("h2")
            )
        inner = match.group("h3")
        if current is None:
            raise ValueError(f"<h3> outside a section: {inner!r}")
        id_ = match.group("hid") or f"{current.id}-{_slug(_TAGS.sub('', inner))}"
        if id_ in seen:
            raise ValueError(f"two sections have the id {id_!r}")
        seen.add(id_)
        number = f"{current.number}.{len(current.children) + 1}" if current.number else ""
        current.children.append(Heading(id_, number, inner))
        return _heading("h3", id_, number, inner)

    return _TOKEN.sub(replace, page), outline


def contents_html(outline: list[Heading]) -> str:
    """The contents, two levels deep: chapters and their sections, each with its number."""

    def item(h: Heading, children: str = "") -> str:
        number = f'<span class="secno">{h.number}</span> ' if h.number else ""
        return f'<li><a href="#{h.id}">{number}{h.html}</a>{children}</li>'

    items = []
    for chapter in outline:
        sub = "".join(item(s) for s in chapter.children)
        items.append(item(chapter, f"<ol>{sub}</ol>" if sub else ""))
    return "<ol>" + "".join(items) + "</ol>"


def add_navigation(page: str) -> str:
    page, outline = number_sections(page)
    if CONTENTS_MARK not in page:
        raise ValueError("the report template has no contents mark " + CONTENTS_MARK)
    return page.replace(CONTENTS_MARK, contents_html(outline), 1)
