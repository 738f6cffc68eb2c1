"""How to cite the report: one citation, read from CITATION.cff, shown as text, BibTeX and CFF.

CITATION.cff is the one source: the BibTeX entry is generated from it (through pybtex) with the
version made precise by the commit, so the two cannot drift apart.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import yaml
from pybtex.database import BibliographyData, Entry, Person

from ..provenance import git


def commit_date(root: Path) -> str:
    """ISO 8601 date of the commit the report is built from, a date that does not change on rebuild;
    "" outside a git checkout."""
    return git(root, "show", "-s", "--format=%cI", "HEAD") or ""


def version(root: Path, commit: str, dirty: bool) -> str:
    """The package version made exact by the commit (a PEP 440 local version: 0.1.0+gcc1ed64f)."""
    with open(Path(root) / "pyproject.toml", "rb") as handle:
        base = tomllib.load(handle)["project"]["version"]
    if not commit or commit == "unknown":
        return base
    return f"{base}+g{commit[:8]}" + (".dirty" if dirty else "")


def _person(author: dict) -> Person:
    if "name" in author:  # an entity: braces keep BibTeX from splitting it
        return Person("{" + author["name"] + "}")
    return Person(first=author.get("given-names", ""), last=author.get("family-names", ""))


def _author_text(author: dict) -> str:
    return author.get("name") or f"{author.get('family-names', '')}, {author.get('given-names', '')}".strip(
        ", "
    )


def citation(root: Path, commit: str, dirty: bool, archive_sha256: str | None = None, date: str = "") -> dict:
    """The citation of this build (dated `date`, ISO 8601): plain text, BibTeX and the CFF file it comes
    from."""
    root = Path(root)
    cff_text = (root / "CITATION.cff").read_text(encoding="utf-8")
    cff = yaml.safe_load(cff_text)
    exact = version(root, commit, dirty)
    year = (date or commit_date(root) or str(cff.get("date-released", "")))[:4]
    note = f"commit {commit}"
    if archive_sha256:
        note += f", results archive SHA-256 {archive_sha256}"
    fields = {"title": cff["title"], "version": exact, "year": year, "note": note}
    if cff.get("url") or cff.get("repository-code"):
        fields["url"] = cff.get("url") or cff["repository-code"]
    entry = Entry("software", fields=fields, persons={"author": [_person(a) for a in cff["authors"]]})
    key = "classical_dynamics_" + year
    authors = "; ".join(_author_text(a) for a in cff["authors"])
    return {
        "version": exact,
        "base_version": cff.get("version"),
        "year": year,
        "commit": commit,
        "title": cff["title"],
        "authors": authors,
        "keywords": cff.get("keywords", []),
        "text": f"{authors} ({year}). {cff['title']}. Version {exact}.",
        "bibtex": BibliographyData({key: entry}).to_string("bibtex").strip(),
        "cff": cff_text.strip(),
        "license": cff.get("license", ""),
    }
