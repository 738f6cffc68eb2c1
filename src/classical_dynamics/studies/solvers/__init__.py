"""The solver layer as a study: work-precision on classical test problems, long horizons, hard cases.

Scenes choose a `problem`: hnw_rigid_body or detest_b5 (work-precision sweeps against their
elliptic-function solutions), long_horizon (energy and Casimir error over up to 10^6 periods),
hard_cases (the separatrix, the intermediate axis, blow-up, numerical damping), heavy_top (the heavy
symmetric top in the body frame against its closed forms; its one effect is gravity), or inertia (moments of
inertia of the textbook bodies by quadrature).
"""

from __future__ import annotations

from pathlib import Path

from ...scenes import EffectRegistry, Scene, SceneError
from ...scenes.cost import check_step
from .cost import HNW_PERIOD, SWEEP_SPAN, cost
from . import top_model

TITLE = "The solver layer"
__all__ = ["TITLE", "EFFECTS", "check", "cost", "run"]
EFFECTS = EffectRegistry("solvers")           # the test problems have none; the heavy top has gravity
top_model.register(EFFECTS)


def check(path: Path, data: dict) -> None:
    numerics = data.get("numerics", {})
    problem = data["problem"]
    effects = data.get("effects") or {}
    if problem != "heavy_top" and effects:
        raise SceneError(path, "effects", "no effects (a test problem has none)", sorted(effects))
    if problem == "heavy_top":
        if "gravity" not in effects:
            raise SceneError(path, "effects.gravity", "the heavy top's weight: gravity: {Mgh: ...}", None,
                             has_got=False)
        if "top" not in data:
            raise SceneError(path, "top", "the top's moments A, C and its spin", None, has_got=False)
        top = data["top"]
        if top["C"] > 2 * top["A"]:
            raise SceneError(path, "top.C", f"C <= A + B = 2A = {2 * top['A']:g} (a real body)", top["C"])
    if problem == "detest_b5" and any(m.startswith("splitting") for m in numerics.get("methods", [])):
        raise SceneError(path, "numerics.methods", "methods for a general ODE (splitting needs a rigid body)",
                         numerics["methods"])
    for i, h in enumerate(numerics.get("steps", [])):
        check_step(path, f"numerics.steps.{i}", h, SWEEP_SPAN)
    if problem == "long_horizon" and "step" in numerics:
        check_step(path, "numerics.step", numerics["step"], numerics.get("max_periods", 1) * HNW_PERIOD)
    if problem in ("hnw_rigid_body", "detest_b5"):
        for key in ("methods", "tolerances"):
            if key not in numerics:
                raise SceneError(path, f"numerics.{key}", "a list (the sweep)", None, has_got=False)
        if any(m.startswith("splitting") for m in numerics["methods"]) and "steps" not in numerics:
            raise SceneError(path, "numerics.steps", "step sizes for the splitting methods", None, has_got=False)


def run(scene: Scene, quick: bool = False):
    from ..results import Results
    from . import hard_cases, heavy_top, inertia, long_horizon, sweeps

    results = Results("solvers", scene.name, scene.title)
    problem = scene.data["problem"]
    if problem in ("hnw_rigid_body", "detest_b5"):
        sweeps.run(scene, results, quick)
    elif problem == "heavy_top":
        heavy_top.run(scene, results, quick)
    elif problem == "inertia":
        inertia.run(scene, results, quick)
    elif problem == "long_horizon":
        long_horizon.run(scene, results, quick)
    else:
        hard_cases.run(scene, results, quick)
    return results
