"""Malformed, oversized and hostile scenes (issue 19): every one is refused before anything runs, in one line
naming the file and the field, in well under 2 s, with results/ untouched.

Each study's module lists its own cases (CASES); generic.py holds the file-level ones (links, pipes, sizes,
aliases, encodings) for every study. tests/test_bad_input.py runs them all; benchmarks/bad_input.py tallies
them.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import yaml

ROOT = Path(__file__).resolve().parents[2]
DELETE = object()  # as a value in BadScene.set: remove that key
KINDS = ("schema", "range", "cost", "precision", "physics", "yaml", "file")


@dataclass(frozen=True)
class BadScene:
    """One bad scene. `field` is how the refusal must begin after the file name: "chain.n" matches
    "<file>: field 'chain.n'", "(YAML at" matches "<file>: field '(YAML at line 3 ...'"."""

    id: str
    study: str
    kind: str  # one of KINDS
    field: str
    base: str = ""  # a scene of workflow/scenes/<study>/ to start from
    set: dict = field(default_factory=dict)  # dotted field (list items by number) -> value, or DELETE
    text: bytes | None = None  # the file's bytes instead of base + set
    make: Callable[[Path], None] | None = None  # makes the file itself (links, pipes); overrides the rest
    name: str = "bad_scene.yaml"
    says: str = ""  # what the refusal must say was expected: the physical reason (every physics case)

    def write(self, folder: Path) -> Path:
        """The bad scene, written into folder; its path."""
        path = Path(folder) / self.name
        if self.make is not None:
            self.make(path)
        elif self.text is not None:
            path.write_bytes(self.text)
        else:
            path.write_text(yaml.safe_dump(self.data(), sort_keys=False), encoding="utf-8")
        return path

    def data(self) -> dict:
        data = copy.deepcopy(yaml.safe_load((ROOT / "workflow/scenes" / self.study / self.base).read_text()))
        for dotted, value in self.set.items():
            *parents, last = dotted.split(".")
            target = data
            for part in parents:
                target = target[int(part)] if isinstance(target, list) else target.setdefault(part, {})
            if isinstance(target, list):
                target[int(last)] = value
            elif value is DELETE:
                del target[last]
            else:
                target[last] = value
        return data


def case(study: str, id_: str, kind: str, field: str, base: str, says: str = "", **set_) -> BadScene:
    """A shipped scene of `study` with fields changed: a__b=v sets a.b, a__0=v the first item of a; `says`
    is what its refusal must give as expected."""
    return BadScene(
        f"{study}-{id_}",
        study,
        kind,
        field,
        base=base,
        set={key.replace("__", "."): value for key, value in set_.items()},
        says=says,
    )


def all_cases() -> list[BadScene]:
    from . import chains, chandler, generic, precession, self_excited, solvers

    cases = [
        case
        for module in (generic, precession, chandler, chains, self_excited, solvers)
        for case in module.CASES
    ]
    ids = [case.id for case in cases]
    assert len(ids) == len(set(ids)), "bad-scene ids must be unique"
    return cases
