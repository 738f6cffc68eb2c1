"""The effect registry: named physical components a scene switches on.

A model is assembled from the effects a scene lists, and from those alone: an effect
that is not listed is never called (not multiplied by zero). Each study owns one registry;
parameter schemas live in the study's scene schema (classical_dynamics/studies/<study>/schema.yaml).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class Effect:
    name: str
    kind: str  # torque, force, tension, deformation, dissipation, excitation, ...
    summary: str  # one line for the report
    build: Callable  # build(params, context) -> the component the model calls


class EffectRegistry:
    def __init__(self, study: str):
        self.study = study
        self._effects: dict[str, Effect] = {}

    def register(self, name: str, kind: str, summary: str):
        def decorator(build: Callable) -> Callable:
            if name in self._effects:
                raise ValueError(f"effect {name!r} registered twice in {self.study}")
            self._effects[name] = Effect(name, kind, summary, build)
            return build

        return decorator

    def names(self) -> list[str]:
        return sorted(self._effects)

    def __getitem__(self, name: str) -> Effect:
        return self._effects[name]

    def assemble(self, effects: dict, context) -> dict[str, object]:
        """Build the listed effects only, in the scene's order: {name: component}."""
        return {name: self._effects[name].build(params or {}, context) for name, params in effects.items()}
