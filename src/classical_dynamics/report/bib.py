"""A small reader for the project's own references.bib, and numbered citations in order of use."""

from __future__ import annotations

import re
from pathlib import Path

_ENTRY = re.compile(r"@(\w+)\s*\{\s*([^,\s]+)\s*,(.*?)\n\}", re.S)
_FIELD = re.compile(r"(\w+)\s*=\s*(\{(?:[^{}]|\{[^{}]*\})*\}|\"[^\"]*\"|\d+)\s*,?", re.S)


def read_bib(path: Path) -> dict[str, dict]:
    entries = {}
    for kind, key, body in _ENTRY.findall(Path(path).read_text(encoding="utf-8")):
        fields = {name.lower(): re.sub(r"\s+", " ", value.strip("{}\"").replace("{", "").replace("}", ""))
                  for name, value in _FIELD.findall(body)}
        entries[key] = {"kind": kind.lower(), "key": key, **fields}
    return entries


def format_entry(entry: dict) -> str:
    authors = entry.get("author", "").replace(" and others", " et al.").replace(" and ", ", ")
    parts = [authors, f"({entry.get('year', 'n.d.')})", f"<em>{entry.get('title', '')}</em>"]
    where = entry.get("journal") or entry.get("booktitle") or entry.get("publisher") or entry.get("school")
    if where:
        extra = ", ".join(x for x in (entry.get("volume"), entry.get("pages")) if x)
        parts.append(where + (f", {extra}" if extra else ""))
    if entry.get("note"):
        parts.append(entry["note"])
    if entry.get("doi"):
        parts.append(f"doi:{entry['doi']}")
    return ". ".join(p.rstrip(".") for p in parts if p) + "."


class Citations:
    def __init__(self, entries: dict):
        self.entries = entries
        self.order: list[str] = []

    def cite(self, key: str) -> int:
        if key not in self.entries:
            raise KeyError(f"citation {key!r} is not in report/references.bib")
        if key not in self.order:
            self.order.append(key)
        return self.order.index(key) + 1
