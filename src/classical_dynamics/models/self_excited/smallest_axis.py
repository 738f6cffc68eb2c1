"""Torque along the smallest axis (Lee §2): the largest axis' reduction with p <-> r and a <-> c
(Body.swapped; LargestAxis on the swapped numbers)."""

from __future__ import annotations

from ...solvers.runge_kutta import rhs_function


@rhs_function
def euler_smallest(t, w, p, out):
    """Lee (2.1) with the torque along z: p' = a q r, q' = -b r p, r' = c p q + m + mu |w|^2; p = (a, b, c, m,
    mu)."""
    out[0] = p[0] * w[1] * w[2]
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1] + p[3]
    if p[4] != 0.0:
        out[2] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
