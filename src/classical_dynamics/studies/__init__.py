"""The studies (registered in registry.py). Each study module exposes EFFECTS, check(path, data), cost(data)
and run(scene, quick)."""

from __future__ import annotations

import dataclasses
import functools
import importlib
from pathlib import Path

from ..scenes import Scene, SceneError, load_scene
from ..scenes.cost import Budget, check_budget
from ..scenes.loader import project_yaml
from .registry import STUDIES

__all__ = ["STUDIES", "study_module", "load_schema", "validate"]


def study_module(study: str):
    if study not in STUDIES:
        raise KeyError(f"unknown study {study!r}; known: {', '.join(sorted(STUDIES))}")
    return importlib.import_module(STUDIES[study].module)


def load_schema(schema_path: Path | str) -> dict:
    path = Path(schema_path)
    return _schema(path.resolve(), path.stat().st_mtime_ns)


@functools.lru_cache(maxsize=16)
def _schema(path: Path, mtime_ns: int) -> dict:
    """A schema read once per process (validating every scene read it 94 times: 5 s), again if it changes."""
    return project_yaml(path)


def validate(study: str, scene_path: Path | str, budget: Budget | None = None) -> Scene:
    """Fully validate one scene file of a study (its schema, effects, physics, cost within the budget); raise
    SceneError. The scene returned carries its cost estimate, from which its job's limits follow."""
    module = study_module(study)  # also refuses an unknown study
    scene = load_scene(
        scene_path, study, load_schema(STUDIES[study].schema), module.EFFECTS.names(), module.check
    )
    try:
        works = module.cost(scene.data)
    except (ArithmeticError, ValueError, TypeError) as exc:  # sizes too large to even estimate
        raise SceneError(
            scene_path, "(values)", "sizes the machine can hold", f"{type(exc).__name__}: {exc}"
        ) from None
    estimate = check_budget(scene_path, scene.data, works, budget or Budget.from_file())
    return dataclasses.replace(scene, estimate=estimate)
