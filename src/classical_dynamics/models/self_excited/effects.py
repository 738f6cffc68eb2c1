"""The effects a self-excited scene may list, each with its parameters: the torque along a principal axis, its
|omega|^2 part, a viscous medium (Lee 1964). A scene's effects are all its torque is made of: an effect not
listed contributes nothing, and the plane's and the medium's parameters are read from here alone."""

from __future__ import annotations

from ...scenes import EffectRegistry

EFFECTS = EffectRegistry("self_excited")


@EFFECTS.register("body_torque", "torque", "a constant torque $M$ along a principal axis, fixed in the body")
def _body_torque(params, context):
    # m1: Lee's reduced torque in a phase-plane scene (the axis is the scene's torque_axis);
    # m: (M1/A, M2/A, M3/C), the torque per unit moment in a viscous-medium scene (Lee §5)
    return params["m1"] if "m1" in params else tuple(params["m"])


@EFFECTS.register(
    "quadratic_torque",
    "torque",
    "the torque's part $\\mu_0|\\boldsymbol\\omega|^2$ along the same axis (Lee's "
    "perturbation: a negative $\\mu_0$ is a drag-like self-regulation)",
)
def _quadratic_torque(params, context):
    return params["nu"]  # the plane's nu, mu1 = -nu; or "nu_c", the middle axis' critical value


@EFFECTS.register(
    "drag",
    "medium",
    "a viscous medium's resisting torque, $-\\mu_1(p, q)$ equatorial and $-\\mu_0 r$ axial "
    "(Lee §5; both or neither)",
)
def _drag(params, context):
    return params["nu"], params["mu"]  # mu1/A and mu0/C


def plane_torque(effects: dict | None) -> tuple[float | None, float | str]:
    """(m1, nu) of Lee's reduced plane, from the listed effects alone: nu = 0 without quadratic_torque, and
    m1 = None without body_torque (no constant torque, M = 0: then m1 follows from nu and the cylinder,
    LargestAxis.for_scene and MiddleAxis.for_scene)."""
    parts = EFFECTS.assemble(effects or {}, None)
    return parts.get("body_torque"), parts.get("quadratic_torque", 0.0)


def medium_torque(effects: dict | None) -> tuple[tuple[float, float, float], float, float]:
    """(m, nu, mu) of Lee §5's medium: the torque per unit moment and the drags, from the listed effects."""
    parts = EFFECTS.assemble(effects or {}, None)
    return parts.get("body_torque", (0.0, 0.0, 0.0)), *parts.get("drag", (0.0, 0.0))
