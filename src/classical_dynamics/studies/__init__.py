"""The four studies. Each module exposes TITLE, EFFECTS, check(path, data) and run(scene, quick)."""

from __future__ import annotations

import importlib
from pathlib import Path

import yaml

from ..scenes import Scene, load_scene

STUDIES = {
    "precession": "classical_dynamics.studies.precession",
    "chandler": "classical_dynamics.studies.chandler",
    "chains": "classical_dynamics.studies.chains",
    "self_excited": "classical_dynamics.studies.self_excited",
    "solvers": "classical_dynamics.studies.solvers",
}


def study_module(study: str):
    if study not in STUDIES:
        raise KeyError(f"unknown study {study!r}; known: {', '.join(sorted(STUDIES))}")
    return importlib.import_module(STUDIES[study])


def load_schema(schema_path: Path | str) -> dict:
    return yaml.safe_load(Path(schema_path).read_text(encoding="utf-8"))


def validate(study: str, scene_path: Path | str, schema_path: Path | str) -> Scene:
    """Fully validate one scene file of a study (schema, effects, physics); raise SceneError."""
    module = study_module(study)
    return load_scene(scene_path, study, load_schema(schema_path), module.EFFECTS.names(), module.check)
