"""File-level bad scenes, the same for every study: what a careless or hostile file system hands the
loader."""

from __future__ import annotations

import os
from pathlib import Path

from classical_dynamics.studies.registry import STUDIES

from . import ROOT, BadScene

# Nine levels of nine-fold aliases: 9^9 items once expanded (refused at the first alias).
BOMB = (
    "a: &a [x, x, x, x, x, x, x, x, x]\n"
    + "".join(f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]\n" for i in range(8))
).encode()


def _first_scene(study: str) -> Path:
    return sorted((ROOT / "workflow/scenes" / study).glob("*.yaml"))[0]


def _symlink_to(target):
    return lambda path: path.symlink_to(target)


def _symlink_to_scene(study):
    return lambda path: path.symlink_to(_first_scene(study))  # a good scene, but outside the folder's files


def _directory(path: Path) -> None:
    path.mkdir()


def _fifo(path: Path) -> None:
    os.mkfifo(path)  # reading it would block for ever


def _cases(study: str) -> list[BadScene]:
    good = _first_scene(study).read_bytes()
    base = _first_scene(study).name
    return [
        BadScene(f"{study}-symlink", study, "file", "(file)", make=_symlink_to_scene(study)),
        BadScene(f"{study}-dev-zero", study, "file", "(file)", make=_symlink_to("/dev/zero")),
        BadScene(f"{study}-fifo", study, "file", "(file)", make=_fifo),
        BadScene(f"{study}-directory", study, "file", "(file)", make=_directory),
        BadScene(f"{study}-2-mb", study, "file", "(file)", text=good + b"# padding\n" * 200_000),
        BadScene(
            f"{study}-50-mb", study, "file", "(file)", text=good + b"x: [" + b"1, " * 17_000_000 + b"1]\n"
        ),
        BadScene(f"{study}-latin-1", study, "file", "(file)", text=good + "# Poincaré\n".encode("latin-1")),
        BadScene(f"{study}-bad-name", study, "file", "(file name)", text=good, name="Bad-Name.yaml"),
        BadScene(f"{study}-reserved-name", study, "file", "(file name)", text=good, name="timings.yaml"),
        BadScene(f"{study}-step-name", study, "file", "(file name)", text=good, name="gallery.yaml"),
        BadScene(f"{study}-long-name", study, "file", "(file name)", text=good, name="a" * 240 + ".yaml"),
        BadScene(f"{study}-empty", study, "schema", "(top level)", text=b""),
        # what validates must build: a title the report's typesetter cannot set (it failed the render)
        BadScene(f"{study}-title-math", study, "schema", "title", base=base, set={"title": r"A $\nosuch x$"}),
        BadScene(f"{study}-list", study, "schema", "(top level)", text=b"- title: a list\n"),
        BadScene(f"{study}-alias-bomb", study, "yaml", "(YAML at line 2", text=BOMB),
        BadScene(
            f"{study}-nesting", study, "yaml", "(YAML at", text=b"title: " + b"[" * 20000 + b"]" * 20000
        ),
        BadScene(f"{study}-duplicate-key", study, "yaml", "(YAML at", text=good + b"title: again\n"),
        BadScene(
            f"{study}-python-tag",
            study,
            "yaml",
            "(YAML at",
            text=good + b"extra: !!python/object/apply:os.system ['true']\n",
        ),
        BadScene(f"{study}-broken", study, "yaml", "(YAML at", text=good + b"title: [unclosed\n"),
        BadScene(
            f"{study}-nan-title",
            study,
            "range",
            "title",
            base=base,
            set={"title": float("nan")},
            says="a string",
        ),
        BadScene(f"{study}-unknown-key", study, "schema", "colour", base=base, set={"colour": "red"}),
    ]


CASES = [case for study in STUDIES for case in _cases(study)]
