"""Scenes: loading, validation, and the effect registry a model is assembled from."""

from .effects import EffectRegistry
from .loader import Scene, SceneError, load_scene

__all__ = ["EffectRegistry", "Scene", "SceneError", "load_scene"]
