"""Figures, tables and equations numbered in order of appearance, with cross-references.

The template is rendered twice with one Numbering: the first pass assigns numbers, the second
resolves references made before their target. The HTML (and so the PDF) carries the numbers.
"""

from __future__ import annotations

NAMES = {"fig": "Figure", "tab": "Table", "eq": "Equation"}


class Numbering:
    def __init__(self):
        self.numbers: dict[str, int] = {}
        self.counts = {kind: 0 for kind in NAMES}
        self.missing: set[str] = set()

    def start_pass(self):
        self.counts = {kind: 0 for kind in NAMES}
        self.missing = set()

    def label(self, label: str) -> int:
        kind = label.split(":", 1)[0]
        if kind not in NAMES:
            raise ValueError(f"label {label!r} must start with one of {', '.join(NAMES)}:")
        self.counts[kind] += 1
        number = self.counts[kind]
        if self.numbers.get(label, number) != number:
            raise ValueError(f"label {label!r} numbered differently between passes")
        self.numbers[label] = number
        return number

    def ref(self, label: str) -> str:
        if label not in self.numbers:
            self.missing.add(label)
            return "?"
        return str(self.numbers[label])
