"""The report's bibliography: report/references.bib read with pybtex, each entry typeset as
an HTML fragment, and numbered citations in order of first use.

pybtex parses the file (entries, @string macros, names split into first/von/last/jr parts). Field values keep
their TeX markup; they are decoded with latexcodec's ``ulatex`` codec (accents, ``--``/``---`` dashes,
````...''`` quotes, ``\\&``, ``~``, math-mode Greek) and the braces, text-style commands and inline math that
the codec leaves are turned into pybtex rich text, which pybtex's html backend renders with proper escaping.
pybtex's own 'unsrt' style is not used: it lower-cases titles and puts the year last; the layout here is "A.
B. Name, C. Other and D. Third (year). Title. *Journal* volume(number), pages. doi:…".

Anything the typesetter cannot turn into plain text (an unknown TeX command, an unbalanced brace) is a
ValueError naming the entry and field, so raw TeX can never reach the printed report.
"""

from __future__ import annotations

import codecs
import html
import re
from collections.abc import Iterator, Mapping
from pathlib import Path
from urllib.parse import quote

import latexcodec  # noqa: F401  (registers the "ulatex" codec)
from pybtex.database import Entry, Person, parse_file
from pybtex.plugin import find_plugin
from pybtex.richtext import HRef, Tag, Text

_HTML = find_plugin("pybtex.backends", "html")()
_TEXT = find_plugin("pybtex.backends", "text")()  # render_as("text") looks it up again on each call: 26 ms

# Types whose title is a stand-alone work (set in italics); others (articles, chapters, talks) are parts.
_ITALIC_TITLE = {
    "book",
    "inbook",
    "booklet",
    "manual",
    "phdthesis",
    "mastersthesis",
    "techreport",
    "proceedings",
}
_THESIS = {"phdthesis": "PhD thesis", "mastersthesis": "Master\N{RIGHT SINGLE QUOTATION MARK}s thesis"}
# Text-mode commands that take one argument and set it in a style (None: argument printed as it is).
_STYLE = {
    "emph": "em",
    "textit": "em",
    "textsl": "em",
    "mathit": "em",
    "textbf": "strong",
    "mathbf": "strong",
    "textsuperscript": "sup",
    "textsubscript": "sub",
    "textrm": None,
    "textup": None,
    "textnormal": None,
    "textsc": None,
    "texttt": None,
    "textsf": None,
    "mbox": None,
    "text": None,
    "mathrm": None,
}
# Control symbols the codec leaves alone: \{ \} \$ and friends print the character; spacing commands.
_SYMBOL = {
    "{": "{",
    "}": "}",
    "$": "$",
    "%": "%",
    "&": "&",
    "#": "#",
    "_": "_",
    " ": " ",
    "\n": " ",
    ",": "\N{THIN SPACE}",
    ";": "\N{THIN SPACE}",
    ":": "\N{THIN SPACE}",
    "/": "",
    "-": "",
    "\\": " ",
}
_DOTLESS = re.compile(r"(\\[`'^\"~=.uvHcd])\s*\{\\([ij])\}")  # \'{\i} -> \'\i, which the codec decodes to í


class Reference(Mapping):
    """One entry of references.bib: a read-only mapping of its raw (TeX) fields by case-insensitive name, the
    person fields (author, editor) included as BibTeX writes them, plus `.key`, `.type` and the pybtex
    `.entry`."""

    def __init__(self, key: str, entry: Entry):
        self.key = key
        self.entry = entry
        self.type = entry.type.lower()

    def __getitem__(self, name: str) -> str:
        if name in self.entry.fields:
            return self.entry.fields[name]
        if name in self.entry.persons:
            return " and ".join(str(p) for p in self.entry.persons[name])
        raise KeyError(name)

    def __iter__(self) -> Iterator[str]:
        yield from self.entry.fields
        yield from self.entry.persons

    def __len__(self) -> int:
        return len(self.entry.fields) + len(self.entry.persons)

    def __repr__(self) -> str:
        return f"Reference({self.key!r}, @{self.type})"


def read_bib(path: Path) -> dict[str, Reference]:
    """Every entry of a BibTeX file by key, in file order (pybtex raises on a duplicate key or a syntax
    error)."""
    data = parse_file(str(path), bib_format="bibtex")
    return {key: Reference(key, entry) for key, entry in data.entries.items()}


# --- TeX field value -> rich text ---------------------------------------------------------------------------


class _TeX:
    """A small reader for what the ulatex codec leaves: brace groups, text-style commands, control symbols and
    $...$ math. Produces pybtex rich Text; raises ValueError on anything it does not know."""

    def __init__(self, decoded: str, where: str):
        self.s, self.i, self.where = decoded, 0, where

    def fail(self, what: str) -> ValueError:
        return ValueError(f"{self.where}: cannot typeset {what} in {self.s!r}")

    def parse(self) -> Text:
        text = self.run(closing=None)
        if self.i < len(self.s):
            raise self.fail("an unmatched '}'")
        return text

    def run(self, closing: str | None, math: bool = False) -> Text:
        parts: list = []
        s = self.s
        while self.i < len(s):
            c = s[self.i]
            if c == closing:
                self.i += 1
                return Text(*parts)
            if c == "}":
                break  # unmatched: reported by the caller
            self.i += 1
            if c == "{":
                parts.append(self.run("}", math))
            elif c == "\\":
                parts.append(self.command(math))
            elif c == "$" and not math:
                parts.append(self.run("$", math=True))
            elif math and c in "^_":
                parts.append(Tag("sup" if c == "^" else "sub", self.argument(math)))
            elif math and c == " ":
                continue
            elif math and c.isalpha():
                parts.append(Tag("em", c))
            elif c == "`":
                parts.append("\N{LEFT SINGLE QUOTATION MARK}")
            elif c == "'":
                parts.append("\N{PRIME}" if math else "\N{RIGHT SINGLE QUOTATION MARK}")
            else:
                parts.append(c)
        if closing is not None:
            raise self.fail("an unclosed '{'" if closing == "}" else "an unclosed '$'")
        return Text(*parts)

    def argument(self, math: bool) -> Text:
        """A command's argument: a {group} or a single character."""
        while self.i < len(self.s) and self.s[self.i] == " ":
            self.i += 1
        if self.i >= len(self.s):
            raise self.fail("a command without its argument")
        c = self.s[self.i]
        self.i += 1
        if c == "{":
            return self.run("}", math)
        if c == "\\":
            return Text(self.command(math))
        return Text(c)

    def command(self, math: bool):
        s = self.s
        if self.i >= len(s):
            raise self.fail("a trailing backslash")
        name = re.match(r"[A-Za-z]+|.", s[self.i :], re.S).group(0)
        self.i += len(name)
        if name in _SYMBOL:
            return _SYMBOL[name]
        if name in _STYLE:
            arg = self.argument(math)
            return Tag(_STYLE[name], arg) if _STYLE[name] else arg
        if name == "url":
            url = self.argument(math).render(_TEXT)
            return HRef(html.escape(url, quote=True), url)
        # A symbol the codec knows only in math mode (Greek letters, \infty, \pm ...).
        symbol = codecs.decode(f"${chr(92)}{name}$", "ulatex").strip()
        if "\\" in symbol or "$" in symbol:
            raise self.fail(f"the command \\{name}")
        while name.isalpha() and self.i < len(s) and s[self.i] == " ":
            self.i += 1  # the space that ends a control word
        return symbol


def _rich(value: str, where: str) -> Text:
    """A BibTeX field value (TeX) as pybtex rich text with nothing of TeX left."""
    value = re.sub(r"[ \t\r\n]+", " ", _DOTLESS.sub(r"\1\\\2", value)).strip()
    return _TeX(codecs.decode(value, "ulatex"), where).parse()


def _plain(value: str, where: str) -> str:
    return _rich(value, where).render(_TEXT)


# --- names --------------------------------------------------------------------------------------------------


def _initials(name: str) -> str:
    """'Horace' -> 'H.', 'Jean-Yves' -> 'J.-Y.'; names already given as initials ('J.', 'J.-Y.') are kept."""
    out = []
    for part in name.split("-"):
        if not part or part.endswith(".") or len(part) == 1:
            out.append(part + ("." if len(part) == 1 and part.isalpha() else ""))
        else:
            out.append(part[0] + ".")
    return "-".join(out)


def _person(person: Person, where: str) -> str:
    given = [_initials(_plain(n, where)) for n in person.first_names + person.middle_names]
    rest = [_plain(n, where) for n in person.prelast_names + person.last_names + person.lineage_names]
    return " ".join(given + rest)


def _names(people: list[Person], where: str) -> str:
    """'A. B. Name', 'A. B. Name and C. Other', 'A. B. Name, C. Other and D. Third'; a final 'others' -> 'et
    al.'"""
    others = bool(people) and str(people[-1]).strip().lower() == "others"
    names = [_person(p, where) for p in (people[:-1] if others else people)]
    if others:
        return ", ".join(names) + " et al."
    if len(names) <= 1:
        return "".join(names)
    return ", ".join(names[:-1]) + " and " + names[-1]


def _unescape(value: str) -> str:
    """A DOI or URL field as it is meant: verbatim but for TeX-escaped \\_ \\% \\& \\# \\~ and surrounding
    braces."""
    value = re.sub(r"\\([_%&#~$])", r"\1", value.strip())
    return value[1:-1] if value.startswith("{") and value.endswith("}") else value


# --- one entry ----------------------------------------------------------------------------------------------


def _join(*pieces, sep: str = ", ") -> Text:
    return Text(sep).join([p for p in pieces if p])


def format_entry(entry: Reference | Entry) -> str:
    """One bibliography entry as an HTML fragment (escaped; safe to insert as Markup)."""
    if not isinstance(entry, Reference):
        entry = Reference(getattr(entry, "key", None) or "?", entry)
    kind, fields, persons = entry.type, entry.entry.fields, entry.entry.persons

    def field(name: str) -> Text | None:
        return _rich(fields[name], f"{entry.key}.{name}") if fields.get(name, "").strip() else None

    def names(role: str) -> str:
        return _names(persons.get(role, []), f"{entry.key}.{role}")

    def pages(prefix: bool) -> Text | None:
        p = field("pages")
        if p is None:
            return None
        text = re.sub(r"\s*[-\N{EN DASH}\N{HYPHEN}]+\s*", "\N{EN DASH}", p.render(_TEXT))
        return Text(("pp. " if "\N{EN DASH}" in text else "p. ") if prefix else "", text)

    title = field("title")
    if title is not None and kind in _ITALIC_TITLE:
        title = Tag("em", title)
    year = field("year") or Text("n.d.")

    blocks: list[Text] = []
    if persons.get("author"):
        who = names("author")
    elif persons.get("editor") and kind not in ("incollection", "inproceedings"):
        who = names("editor") + (" (eds.)" if len(persons["editor"]) > 1 else " (ed.)")
    else:
        who = ""
    if who:
        blocks += [Text(who, " (", year, ")"), title]
    else:  # no one to name: the title leads
        blocks.append(Text(title or Text(entry.key), " (", year, ")"))

    series = _join(field("series"), field("volume") if kind != "article" else None, sep=" ")
    publisher = _join(field("publisher"), field("address"))
    if kind == "article":
        volume = _join(field("volume"), Text("(", field("number"), ")") if field("number") else None, sep="")
        journal = Tag("em", field("journal")) if field("journal") else None
        blocks.append(_join(_join(journal, volume, sep=" "), pages(prefix=False)))
    elif kind in ("incollection", "inproceedings"):
        editors = names("editor")
        if editors:
            editors += " (eds.)" if len(persons["editor"]) > 1 else " (ed.)"
        booktitle = Tag("em", field("booktitle")) if field("booktitle") else None
        inside = _join(editors, booktitle, series, pages(prefix=True))
        blocks += [Text("In ", inside) if inside else None, publisher]
    elif kind in _THESIS:
        blocks.append(_join(field("type") or Text(_THESIS[kind]), field("school"), field("address")))
    elif kind == "techreport":
        report = _join(field("type") or Text("Technical report"), field("number"), sep=" ")
        blocks += [report, _join(field("institution"), field("address"))]
    else:  # book, inbook, booklet, manual, proceedings, misc, unpublished, ...
        edition = Text(field("edition"), " edition") if field("edition") else None
        chapter = Text("chapter ", field("chapter")) if field("chapter") else None
        blocks += [
            _join(edition, series, chapter, pages(prefix=True)),
            field("howpublished"),
            _join(publisher, field("organization"), field("institution"), field("school")),
        ]
    blocks.append(field("note"))

    doi = _unescape(fields.get("doi", ""))
    if doi:
        doi = re.sub(r"^(https?://(dx\.)?doi\.org/|doi:)", "", doi, flags=re.I)
        url = "https://doi.org/" + quote(doi, safe="/:;()[]._-+*'!~,=@&")
        blocks.append(HRef(html.escape(url, quote=True), f"doi:{doi}"))
    url = _unescape(fields.get("url", ""))
    if url:
        blocks.append(HRef(html.escape(url, quote=True), url))

    # Text(b): the closing period goes after an <em> or <a>, not inside it.
    return " ".join(Text(b).add_period().render(_HTML) for b in blocks if b)


class Citations:
    """Numbered citations: a key's number is its place in the order of first citation."""

    def __init__(self, entries: dict):
        self.entries = entries
        self.order: list[str] = []

    def cite(self, key: str) -> int:
        if key not in self.entries:
            raise KeyError(f"citation {key!r} is not in the report's references.bib")
        if key not in self.order:
            self.order.append(key)
        return self.order.index(key) + 1
