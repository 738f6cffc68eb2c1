"""Study: the self-excited rigid body and its phase planes (Lee 1964).

A scene names a body (three principal moments, in any order), the axis of the body-fixed torque
(largest, middle or smallest) and the point of the reduced plane to draw: m1, the drag nu (mu1 = -nu)
and the cylinder delta; the physical torque (M and mu0, per unit of the axis' moment) follows and is
reported. The effects it lists must be those the plane needs: body_torque when M != 0, quadratic_torque
when nu != 0. This build covers the torque along the largest or the smallest axis (Lee §2, §4.2) and
along the middle axis (§3, (4.13), (4.14)). A scene with a `viscous` block instead of a plane is Lee §5:
a symmetric body in a viscous medium under a constant body-fixed torque (effects body_torque and drag).
"""

from __future__ import annotations

import math
from pathlib import Path

from ...scenes import Scene, SceneError
from .cost import cost

__all__ = ["EFFECTS", "check", "cost", "run"]


def __getattr__(name):
    # The model's registry (it compiles with numba) only when asked for: every parse of the Snakefile imports
    # .gallery, and numba's import and cached compiles cost 1.5 s.
    if name == "EFFECTS":
        from ...models.self_excited import EFFECTS

        return EFFECTS
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _numbers(data, prefix=""):
    """Every number in the scene, with its field path (a YAML .nan or .inf passes the schema)."""
    if isinstance(data, dict):
        for k, v in data.items():
            yield from _numbers(v, f"{prefix}{k}.")
    elif isinstance(data, list):
        for i, v in enumerate(data):
            yield from _numbers(v, f"{prefix[:-1]}[{i}].")
    elif isinstance(data, (int, float)) and not isinstance(data, bool):
        yield prefix[:-1], data


def check(path: Path, data: dict) -> None:
    """Physical consistency the schema cannot express. Raises SceneError (one line)."""
    from ...models.self_excited import Body, LargestAxis, limit_cycle_p1

    for field, value in _numbers(data):
        if not math.isfinite(value):
            raise SceneError(path, field, "a finite number", value)
    moments = data["body"]["moments"]
    A, B, C = sorted(moments, reverse=True)
    if not A < B + C:
        raise SceneError(
            path,
            "body.moments",
            "moments a body can have: each less than the sum of the other two (A < B + C)",
            moments,
        )
    if "viscous" in data:
        _check_viscous(path, data)
        return
    if "excursion" in data and data.get("torque_axis") != "middle":
        raise SceneError(
            path,
            "excursion",
            "torque_axis: middle (the huge excursions are Lee §3's)",
            data.get("torque_axis"),
        )
    for field in ("torque_axis", "plane"):
        if field not in data:
            raise SceneError(
                path, field, "torque_axis and plane (a phase-plane scene), or viscous (Lee §5)", None
            )
    axis = data["torque_axis"]
    if not A > B > C:
        raise SceneError(
            path,
            "body.moments",
            "three different moments (the reduction to the plane needs A > B > C)",
            moments,
        )
    plane = data["plane"]
    effects = data.get("effects") or {}
    shape = "alpha" if axis == "middle" else "delta"
    if shape not in plane:
        raise SceneError(
            path,
            f"plane.{shape}",
            "the elliptic cylinder delta (torque along the largest or the smallest axis)"
            if shape == "delta"
            else "alpha: [alpha1, alpha2], the hyperbolic cylinder (middle axis)",
            None,
        )
    if axis == "middle":
        _check_middle(path, Body(A, B, C), data, effects)
        return
    if isinstance(plane["nu"], str):
        raise SceneError(path, "plane.nu", "a number (nu_c is the middle axis' critical drag)", plane["nu"])
    if plane["nu"] != 0.0 and "quadratic_torque" not in effects:
        raise SceneError(
            path,
            "effects",
            "quadratic_torque listed (nu != 0 is the mu0 |omega|^2 part of the torque)",
            sorted(effects),
        )
    if plane["nu"] == 0.0 and "quadratic_torque" in effects:
        raise SceneError(
            path, "effects.quadratic_torque", "nu != 0 in plane (an unused effect is not listed)", plane["nu"]
        )
    numbers = Body(A, B, C).swapped() if axis == "smallest" else Body(A, B, C)
    L = LargestAxis.with_plane_parameters(numbers, plane["m1"], -plane["nu"], plane["delta"])
    if abs(L.m) > 0.0 and "body_torque" not in effects:
        raise SceneError(
            path,
            "effects",
            f"body_torque listed (this plane needs a torque of {L.m:.4g} per unit moment)",
            sorted(effects),
        )
    if L.m == 0.0 and "body_torque" in effects:
        raise SceneError(path, "effects.body_torque", "a plane that needs a constant torque (none here)", 0.0)
    on_F = plane["nu"] > 0.0 and limit_cycle_p1([0.0], plane["m1"], plane["nu"]) is not None
    if data.get("analysis", {}).get("motion_in_space") and (axis != "largest" or not on_F):
        raise SceneError(
            path,
            "analysis.motion_in_space",
            "torque_axis: largest and a plane with the limit cycle F (the attitude starts on it)",
            [axis, plane["m1"], plane["nu"]],
        )
    if data.get("analysis", {}).get("motions") and (axis != "largest" or plane["nu"] != 0.0):
        raise SceneError(
            path, "analysis.motions", "torque_axis: largest and nu = 0 (Lee §2.2-§2.4)", [axis, plane["nu"]]
        )
    _check_range(path, data)


def _check_range(path, data):
    lo, hi = data.get("portrait", {}).get("phi2_range", [-3 * math.pi, 3 * math.pi])
    if not lo < hi:
        raise SceneError(path, "portrait.phi2_range", "[low, high] with low < high", [lo, hi])


def _check_middle(path, body, data, effects):
    from ...models.self_excited import MiddleAxis

    plane = data["plane"]
    alpha1, alpha2 = plane["alpha"]
    if alpha1 == alpha2 == 0.0:
        raise SceneError(path, "plane.alpha", "a hyperbolic cylinder, not both alpha zero", plane["alpha"])
    if abs(alpha1) == abs(alpha2) and not alpha1 > 0:
        raise SceneError(
            path,
            "plane.alpha",
            "alpha1 > 0 in the planes of the separating polhodes (orient the axes so; the map takes a log)",
            plane["alpha"],
        )
    if abs(alpha1) != abs(alpha2) and not alpha1 + alpha2 > 0:
        raise SceneError(
            path,
            "plane.alpha",
            "alpha1 + alpha2 > 0 (orient the axes so; the map takes its log)",
            plane["alpha"],
        )
    nu = MiddleAxis.plane_nu(plane["nu"], body)
    M = MiddleAxis.with_plane_parameters(body, plane["m1"], -nu, alpha1, alpha2)
    if (nu != 0.0) != ("quadratic_torque" in effects):
        raise SceneError(path, "effects", "quadratic_torque listed exactly when nu != 0", sorted(effects))
    if (M.m != 0.0) != ("body_torque" in effects):
        raise SceneError(
            path,
            "effects",
            f"body_torque listed exactly when the plane needs a torque (here M/B = {M.m:.4g})",
            sorted(effects),
        )
    if "excursion" in data:
        if M.form != "sinh":
            raise SceneError(
                path,
                "excursion",
                "a plane below the critical drag and off the planes of the "
                "separating polhodes (Lee's (3.52): every orbit closed)",
                M.form,
            )
        if data["excursion"]["q0"] == 0.0:
            raise SceneError(path, "excursion.q0", "a spin q0 != 0 (q0 = 0 starts at a turning point)", 0.0)


def _check_viscous(path, data):
    from ...models.viscous_medium import ViscousMedium, symmetric_axis

    for field in ("torque_axis", "plane"):
        if field in data:
            raise SceneError(
                path, field, "no phase plane in a viscous-medium scene (Lee §5 has none)", data[field]
            )
    moments = data["body"]["moments"]
    if symmetric_axis(moments) is None:
        raise SceneError(path, "body.moments", "a symmetric body, two moments equal (Lee §5: A = B)", moments)
    v, effects = data["viscous"], data.get("effects") or {}
    nu, mu = v.get("nu", 0.0), v.get("mu", 0.0)
    if (nu > 0.0) != (mu > 0.0):
        raise SceneError(
            path,
            "viscous.mu" if nu > 0.0 else "viscous.nu",
            "both drags positive or both zero (the medium resists equatorial and axial turning alike)",
            [nu, mu],
        )
    if (nu > 0.0) != ("drag" in effects):
        raise SceneError(path, "effects", "drag listed exactly when nu and mu are positive", sorted(effects))
    if any(v["torque"]) != ("body_torque" in effects):
        raise SceneError(
            path, "effects", "body_torque listed exactly when the torque is not zero", sorted(effects)
        )
    if "quadratic_torque" in effects:
        raise SceneError(path, "effects.quadratic_torque", "body_torque and drag only (Lee §5)", None)
    A, C = symmetric_axis(moments)
    V = ViscousMedium.from_moments(A, C, nu, mu, v["torque"], v["omega0"])
    if V.generalized and float(nu / mu).is_integer():
        raise SceneError(
            path,
            "viscous.nu",
            "nu/mu not an integer (Lee's reduction (5.32)/(5.33) needs 0 < Re w' < 1)",
            nu / mu,
        )


def run(scene: Scene, quick: bool = False):
    from ...results import Results  # imported here so that validation stays light
    from . import largest_axis, middle_axis, viscous

    results = Results("self_excited", scene.name, scene.title)
    if "viscous" in scene.data:
        module = viscous
    else:
        module = middle_axis if scene.data["torque_axis"] == "middle" else largest_axis
    module.run(scene, results, quick)
    return results
