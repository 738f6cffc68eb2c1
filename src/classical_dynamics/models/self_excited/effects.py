"""The effects a self-excited scene may list: the torque along a principal axis, its |omega|^2 part, a viscous
medium (Lee 1964)."""

from __future__ import annotations

from ...scenes import EffectRegistry

EFFECTS = EffectRegistry("self_excited")


@EFFECTS.register("body_torque", "torque", "a constant torque $M$ along a principal axis, fixed in the body")
def _body_torque(params, context):
    return params


@EFFECTS.register(
    "quadratic_torque",
    "torque",
    "the torque's part $\\mu_0|\\boldsymbol\\omega|^2$ along the same axis (Lee's "
    "perturbation: a negative $\\mu_0$ is a drag-like self-regulation)",
)
def _quadratic_torque(params, context):
    return params


@EFFECTS.register(
    "drag",
    "medium",
    "a viscous medium's resisting torque, $-\\mu_1(p, q)$ equatorial and $-\\mu_0 r$ axial "
    "(Lee §5; both or neither)",
)
def _drag(params, context):
    return params
