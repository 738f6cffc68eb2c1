"""Study: the self-excited rigid body and its phase planes (Lee 1964).

A scene names a body (three principal moments, in any order), the axis of the body-fixed torque
(largest, middle or smallest), the cylinder of the reduced plane to draw (delta, or alpha for the middle
axis), and the effects its torque is made of, with their parameters: body_torque {m1} and
quadratic_torque {nu} (mu1 = -nu), the point of Lee's plane; an effect not listed is zero, and one listed
is not zero. The physical torque (M and mu0, per unit of the axis' moment) follows and is reported. This
build covers the torque along the largest or the smallest axis (Lee §2, §4.2) and along the middle axis
(§3, (4.13), (4.14)). A scene with a `viscous` block instead of a plane is Lee §5: a symmetric body in a
viscous medium under a constant body-fixed torque (effects body_torque {m} and drag {nu, mu}).
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


def check(path: Path, data: dict) -> None:
    """Physical consistency the schema cannot express. Raises SceneError (one line)."""
    from ...models.self_excited import Body, LargestAxis, limit_cycle_p1, plane_torque

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
            raise SceneError(path, field, "torque_axis and plane (a phase-plane scene), or viscous (Lee §5)")
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
    _check_listed_terms(path, effects, viscous=False)
    shape = "alpha" if axis == "middle" else "delta"
    if shape not in plane:
        raise SceneError(
            path,
            f"plane.{shape}",
            "the elliptic cylinder delta (torque along the largest or the smallest axis)"
            if shape == "delta"
            else "alpha: [alpha1, alpha2], the hyperbolic cylinder (middle axis)",
        )
    if axis == "middle":
        _check_middle(path, Body(A, B, C), data, effects)
        return
    m1, nu = plane_torque(effects)
    if isinstance(nu, str):
        raise SceneError(
            path, "effects.quadratic_torque.nu", "a number (nu_c is the middle axis' critical drag)", nu
        )
    numbers = Body(A, B, C).swapped() if axis == "smallest" else Body(A, B, C)
    L = LargestAxis.for_scene(numbers, m1, -nu, plane["delta"])
    _check_constant_torque(path, L.m, m1)
    m1 = L.m1 if m1 is None else m1
    on_F = nu > 0.0 and limit_cycle_p1([0.0], m1, nu) is not None
    if data.get("analysis", {}).get("motion_in_space") and (axis != "largest" or not on_F):
        raise SceneError(
            path,
            "analysis.motion_in_space",
            "torque_axis: largest and a plane with the limit cycle F (the attitude starts on it)",
            [axis, m1, nu],
        )
    if data.get("analysis", {}).get("motions") and (axis != "largest" or nu != 0.0):
        raise SceneError(
            path,
            "analysis.motions",
            "torque_axis: largest and no quadratic_torque (Lee §2.2-§2.4)",
            [axis, nu],
        )
    _check_range(path, data)


def _check_listed_terms(path, effects, viscous: bool):
    """Each listed effect has the parameters of the scene's kind and a term that is not zero: an effect whose
    term is zero is left out, so that the model is what the scene lists."""
    torque = effects.get("body_torque") or {}
    want, other = ("m", "m1") if viscous else ("m1", "m")
    if other in torque:
        kind = "a viscous-medium scene (Lee §5)" if viscous else "a phase-plane scene"
        raise SceneError(path, f"effects.body_torque.{other}", f"{want} in {kind}", torque[other])
    if viscous and "m" in torque and not any(torque["m"]):
        raise SceneError(
            path, "effects.body_torque.m", "a torque that is not zero (leave body_torque out)", 0.0
        )
    if not viscous and (effects.get("quadratic_torque") or {}).get("nu") == 0.0:
        raise SceneError(
            path, "effects.quadratic_torque.nu", "nu != 0 (leave quadratic_torque out for none)", 0.0
        )
    if viscous and "quadratic_torque" in effects:
        raise SceneError(
            path, "effects.quadratic_torque", "body_torque and drag only (Lee §5)", sorted(effects)
        )


def _check_constant_torque(path, m, m1):
    """The plane's m1 fixes the constant torque M on the scene's cylinder; body_torque is listed when M != 0
    (m1 = 0 may still need one: the quadratic torque's mean shifts the plane)."""
    if m1 is not None and m == 0.0:
        raise SceneError(
            path,
            "effects.body_torque.m1",
            "a plane that needs a constant torque (M = 0 here: leave it out)",
            m1,
        )


def _check_range(path, data):
    lo, hi = data.get("portrait", {}).get("phi2_range", [-3 * math.pi, 3 * math.pi])
    if not lo < hi:
        raise SceneError(path, "portrait.phi2_range", "[low, high] with low < high", [lo, hi])


def _check_middle(path, body, data, effects):
    from ...models.self_excited import MiddleAxis, plane_torque

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
    m1, nu = plane_torque(effects)
    M = MiddleAxis.for_scene(body, m1, -MiddleAxis.plane_nu(nu, body), alpha1, alpha2)
    _check_constant_torque(path, M.m, m1)
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
    from ...models.self_excited import medium_torque
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
    _check_listed_terms(path, effects, viscous=True)
    m, nu, mu = medium_torque(effects)
    if "drag" in effects and not (nu > 0.0 and mu > 0.0):
        raise SceneError(
            path,
            "effects.drag.mu" if nu > 0.0 else "effects.drag.nu",
            "both drags positive (the medium resists equatorial and axial turning alike)",
            [nu, mu],
        )
    A, C = symmetric_axis(moments)
    V = ViscousMedium.from_moments(A, C, nu, mu, m, v["omega0"])
    if V.generalized and float(nu / mu).is_integer():
        raise SceneError(
            path,
            "effects.drag.nu",
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
