"""The studies of the report, in the order of its chapters: the one place a study is registered.

A study is its package, classical_dynamics/studies/<name>/, which holds its code (EFFECTS, check, cost, run),
schema.yaml (what its scenes may say), chapter.html.j2 (its chapter) and claims.yaml (the numbers its chapter
checks against the sources), and its scenes, workflow/scenes/<name>/. The pipeline's rules and targets, the
report's chapters and their titles all follow from STUDIES. (Apart from the study modules, so that retitling a
chapter reruns no scene: the scenes' code digest covers studies/__init__.py, not this file.)
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib.resources import files
from pathlib import Path

# The studies' folder (found without importing a study's code, which takes up to a second; the package is
# installed as files, so this is a real path)
HERE = Path(str(files(__package__)))


@dataclass(frozen=True)
class Study:
    name: str  # the package's and the scenes folder's name; also the Snakemake target
    title: str  # its chapter's title

    @property
    def module(self) -> str:
        return f"{__package__}.{self.name}"

    def file(self, name: str) -> Path:
        """One of the files shipped in the study's package: schema.yaml, chapter.html.j2, claims.yaml."""
        return HERE / self.name / name

    @property
    def schema(self) -> Path:
        return self.file("schema.yaml")


STUDIES = {
    study.name: study
    for study in (
        Study("precession", "Precession of the equinoxes"),
        Study("chandler", "The Chandler wobble"),
        Study("chains", "Vibrations of chains"),
        Study("self_excited", "The self-excited rigid body"),
        Study("solvers", "The solver layer: what accuracy costs"),
    )
}


def resource_files() -> list[Path]:
    """Every file the studies ship beside their code (schemas, chapters, claims): what the report reads."""
    return sorted(
        path
        for study in STUDIES
        for path in (HERE / study).iterdir()
        if path.is_file() and path.suffix != ".py"
    )
