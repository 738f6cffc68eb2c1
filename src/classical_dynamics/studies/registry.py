"""The studies of the report, in the order of its chapters, as registry.yaml beside this file lists them: one
line a study.

A study is its package, classical_dynamics/studies/<name>/, which holds its code (EFFECTS, check, cost, run),
schema.yaml (what its scenes may say), chapter.html.j2 (its chapter) and claims.yaml (the numbers its chapter
checks against the sources), and its scenes, workflow/scenes/<name>/. The pipeline's rules and targets, the
report's chapters and their titles all follow from STUDIES. (The list is data, so that adding a study or
retitling a chapter reruns no scene: a scene's code digest covers the modules its job imports.)
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib.resources import files
from pathlib import Path

from ..scenes.loader import project_yaml

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

    def effect_names(self) -> list[str]:
        """The effects its scenes may list, in the schema's order (the tests hold schema and registry
        equal)."""
        schema = project_yaml(self.schema)
        return list(schema["properties"].get("effects", {}).get("properties", {}))


LIST = HERE / "registry.yaml"
STUDIES = {name: Study(name, title) for name, title in project_yaml(LIST).items()}


def resource_files() -> list[Path]:
    """Every file the studies ship beside their code (the list, schemas, chapters, claims): what the report
    reads."""
    return [LIST] + sorted(
        path
        for study in STUDIES
        for path in (HERE / study).iterdir()
        if path.is_file() and path.suffix != ".py"
    )
