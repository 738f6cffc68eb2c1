"""The solver layer as a study: work-precision on classical test problems, long horizons, hard cases.

Scenes choose a `problem`: hnw_rigid_body or detest_b5 (work-precision sweeps against their
elliptic-function solutions), long_horizon (energy and Casimir error over up to 10^6 periods),
hard_cases (the separatrix, the intermediate axis, blow-up, numerical damping), heavy_top (the heavy
symmetric top in the body frame against its closed forms; its one effect is gravity), or inertia (moments of
inertia of the textbook bodies by quadrature).
"""

from __future__ import annotations

from pathlib import Path

from ...models.heavy_top import EFFECTS  # the test problems have no effects; the heavy top has gravity
from ...scenes import Scene, SceneError
from ...scenes.cost import check_step
from ...solvers.references import HNW_PERIOD
from .cost import SWEEP_SPAN, cost

__all__ = ["EFFECTS", "check", "cost", "run"]


def check(path: Path, data: dict) -> None:
    import math

    from .cost import DOP853_MAX_STEPS, LONG_DOP853_PER_TIME

    numerics = data.get("numerics", {})
    problem = data["problem"]
    effects = data.get("effects") or {}
    if problem != "heavy_top" and effects:
        raise SceneError(path, "effects", "no effects (a test problem has none)", sorted(effects))
    if problem == "heavy_top":
        if "gravity" not in effects:
            raise SceneError(path, "effects.gravity", "the heavy top's weight: gravity: {Mgh: ...}")
        if "top" not in data:
            raise SceneError(path, "top", "the top's moments A, C and its spin")
        top = data["top"]
        A, C, spin, Mgh = top["A"], top["C"], top["spin"], effects["gravity"]["Mgh"]
        if C > 2 * A:
            raise SceneError(path, "top.C", f"C <= A + B = 2A = {2 * A:g} (a real body)", C)
        # steady precession at the top's inclination and at 30, 60, 120 degrees (heavy_top._general_start and
        # steady) needs (C n)^2 >= 4 A Mgh cos(alpha); the disturbed precession (oscillation) runs at spin 6
        cos_alpha = max(math.cos(math.radians(top["inclination_deg"])), math.cos(math.radians(30.0)))
        if (C * spin) ** 2 < 4 * A * Mgh * cos_alpha:
            raise SceneError(
                path,
                "top.spin",
                f"a spin of at least sqrt(4 A Mgh cos alpha)/C = "
                f"{math.sqrt(4 * A * Mgh * cos_alpha) / C:.4g} (no steady precession below it, at the "
                "top's inclination or 30 degrees)",
                spin,
            )
        if (6.0 * C) ** 2 < 4 * A * Mgh * math.cos(math.radians(30.0)):
            raise SceneError(
                path,
                "top.C",
                f"C of at least sqrt(4 A Mgh cos 30)/6 = "
                f"{math.sqrt(4 * A * Mgh * math.cos(math.radians(30.0))) / 6:.4g} (the disturbed "
                "steady precession runs at spin 6)",
                C,
            )
    if problem in ("detest_b5", "heavy_top") and any(
        m.startswith("splitting") for m in numerics.get("methods", [])
    ):
        raise SceneError(
            path,
            "numerics.methods",
            "methods for a general ODE (splitting needs a free rigid body)",
            numerics["methods"],
        )
    for i, h in enumerate(numerics.get("steps", [])):
        check_step(path, f"numerics.steps.{i}", h, SWEEP_SPAN)
    if problem == "long_horizon":
        for key, what in (
            ("max_periods", "periods"),
            ("step", "the splitting's step"),
            ("rtol", "DOP853's rtol"),
        ):
            if key not in numerics:
                raise SceneError(path, f"numerics.{key}", f"a number ({what})")
        check_step(path, "numerics.step", numerics["step"], numerics["max_periods"] * HNW_PERIOD)
        # DOP853's steps (1 % from the measured law): past ode.solve's limit it stops and leaves NaN behind
        per_period = HNW_PERIOD * LONG_DOP853_PER_TIME * (1e-6 / numerics["rtol"]) ** (1 / 8)
        most = 0.9 * DOP853_MAX_STEPS / per_period
        if numerics["max_periods"] > most:
            raise SceneError(
                path,
                "numerics.max_periods",
                f"at most {most:.3g} periods at rtol "
                f"{numerics['rtol']:g} (DOP853 would stop at its {DOP853_MAX_STEPS:.0e} steps)",
                numerics["max_periods"],
            )
    if problem in ("hnw_rigid_body", "detest_b5"):
        for key in ("methods", "tolerances"):
            if key not in numerics:
                raise SceneError(path, f"numerics.{key}", "a list (the sweep)")
        if any(m.startswith("splitting") for m in numerics["methods"]) and "steps" not in numerics:
            raise SceneError(path, "numerics.steps", "step sizes for the splitting methods")


def run(scene: Scene, quick: bool = False):
    from ...results import Results
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
