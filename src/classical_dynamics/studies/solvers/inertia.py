"""Moments of inertia by quadrature (scene inertia): the textbook bodies against their closed forms.

I_ij = integral of rho (r^2 delta_ij - x_i x_j) dV over the body, by product rules: Gauss-Legendre in radii
and lengths, the trapezoidal rule in angles (exact for the trigonometric polynomials that appear). The mass
comes from the same rule, so every moment is in units of M (length)^2. The references are the closed forms the
sources print (rod, disc, rectangle, sphere, cylinder, torus) and the two theorems, never a second quadrature.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd


def _gauss(a, b, n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def _angles(n):
    return 2 * np.pi * np.arange(n) / n, np.full(n, 2 * np.pi / n)


def _grid(*rules):
    """The product of 1-d rules: nodes (N, d) and weights (N,)."""
    nodes = np.meshgrid(*[r[0] for r in rules], indexing="ij")
    weights = np.meshgrid(*[r[1] for r in rules], indexing="ij")
    return np.stack([x.ravel() for x in nodes], axis=1), np.prod([w.ravel() for w in weights], axis=0)


def tensor(points, weights):
    """(mass, inertia tensor about the origin) of weighted points."""
    r2 = np.sum(points * points, axis=1)
    I = np.eye(3) * np.sum(weights * r2) - np.einsum("n,ni,nj->ij", weights, points, points)
    return float(np.sum(weights)), I


def rod(L, n, shift=0.0):
    x, w = _gauss(-L / 2 + shift, L / 2 + shift, n)
    return np.stack([x, 0 * x, 0 * x], axis=1), w


def disc(a, n, centre=(0.0, 0.0)):
    (q, w) = _grid(_gauss(0, a, n), _angles(2 * n))
    r, th = q[:, 0], q[:, 1]
    return np.stack([r * np.cos(th) - centre[0], r * np.sin(th) - centre[1], 0 * r], axis=1), w * r


def rectangle(sx, sy, n):
    q, w = _grid(_gauss(-sx / 2, sx / 2, n), _gauss(-sy / 2, sy / 2, n))
    return np.stack([q[:, 0], q[:, 1], 0 * q[:, 0]], axis=1), w


def sphere(a, n):
    q, w = _grid(_gauss(0, a, n), _gauss(-1, 1, n), _angles(2 * n))
    r, mu, ph = q.T
    s = np.sqrt(1 - mu * mu)
    return np.stack([r * s * np.cos(ph), r * s * np.sin(ph), r * mu], axis=1), w * r * r


def cylinder(a, length, n):
    q, w = _grid(_gauss(0, a, n), _angles(2 * n), _gauss(-length / 2, length / 2, n))
    r, th, z = q.T
    return np.stack([r * np.cos(th), r * np.sin(th), z], axis=1), w * r


def torus_circular(a, b, n):
    """Circular section of radius b, its centre a from the axis z."""
    q, w = _grid(_gauss(0, b, n), _angles(2 * n), _angles(2 * n))
    rho, psi, ph = q.T
    R = a + rho * np.cos(psi)
    return np.stack([R * np.cos(ph), R * np.sin(ph), rho * np.sin(psi)], axis=1), w * rho * R


def torus_square(a, c, n):
    """Square section of side 2c, its centre a from the axis z."""
    q, w = _grid(_gauss(-c, c, n), _gauss(-c, c, n), _angles(2 * n))
    s, z, ph = q.T
    R = a + s
    return np.stack([R * np.cos(ph), R * np.sin(ph), z], axis=1), w * R


class Moments(NamedTuple):
    nodes: int  # Gauss-Legendre nodes a radius or length (twice as many trapezoidal an angle)
    moments: list  # (number name, quadrature, closed form) per body and axis, in units of M (length)^2
    frame: pd.DataFrame  # the same as the table: body, closed form's text, both values, relative difference
    worst: float  # largest relative difference
    cylinder_worst: float
    torus_worst: float
    perpendicular_axes: float  # I1 + I2 = I3 of the disc and the rectangle, relative residual
    parallel_axes: float  # the rod about its end and the disc about its rim
    parallel_axis_general: float  # the cylinder about a tilted, shifted axis
    dumbbell_tensor: float  # largest difference from the lecture notes' printed tensor (m a^2)
    dumbbell_J_angle_deg: float  # between J and omega
    dumbbell_couple_z: float  # (m a^2 omega^2)


def moments(n) -> Moments:
    """The textbook bodies' moments by quadrature at n nodes, the two theorems and the notes' dumbbell."""
    rows, numbers = [], []

    def moment(body, name, axis, value, closed, text):
        M, I = tensor(*body)
        axis = np.asarray(axis, float) / np.linalg.norm(axis)
        computed = float(axis @ I @ axis) / M
        rows.append(
            {
                "body": name,
                "moment": text,
                "quadrature": computed,
                "closed_form": closed,
                "relative_difference": computed / closed - 1,
            }
        )
        numbers.append((value, computed, closed))
        return M, I

    L, a, length = 1.0, 1.0, 2.0
    moment(rod(L, n), "rod, length $l$", (0, 1, 0), "rod_centre", 1 / 12, "$Ml^2/12$")
    moment(rod(L, n, shift=L / 2), "rod, about its end", (0, 1, 0), "rod_end", 1 / 3, "$Ml^2/3$")
    Md, Id = moment(disc(a, n), "disc, radius $a$", (0, 0, 1), "disc_axial", 0.5, "$Ma^2/2$")
    moment(disc(a, n), "disc, about a diameter", (1, 0, 0), "disc_diameter", 0.25, "$Ma^2/4$")
    moment(
        disc(a, n, centre=(a, 0.0)), "disc, about a point of its rim", (0, 0, 1), "disc_rim", 1.5, "$3Ma^2/2$"
    )
    Mr, Ir = moment(
        rectangle(2.0, 1.0, n),
        "rectangle $2 \\times 1$",
        (0, 0, 1),
        "rectangle_axial",
        5 / 12,
        "$M(4 + 1)/12$",
    )
    moment(sphere(a, n), "solid sphere, radius $a$", (0, 0, 1), "sphere", 0.4, "$2Ma^2/5$")
    moment(sphere(a, n), "solid sphere, about $x$", (1, 0, 0), "sphere_x", 0.4, "$2Ma^2/5$")
    Mc, Ic = moment(
        cylinder(a, length, n),
        "cylinder, $l = 2a$",
        (1, 0, 0),
        "cylinder_transverse",
        7 / 12,
        "$M(a^2/4 + l^2/12)$",
    )
    moment(cylinder(a, length, n), "cylinder, its axis", (0, 0, 1), "cylinder_axial", 0.5, "$Ma^2/2$")
    moment(
        torus_circular(3.0, 1.0, n),
        "torus, circular section",
        (0, 0, 1),
        "torus_circular",
        9 + 0.75,
        "$M(d^2 + 3b^2/4)$",
    )
    moment(
        torus_square(3.0, 1.0, n),
        "torus, square section",
        (0, 0, 1),
        "torus_square",
        9 + 1.0,
        "$M(d^2 + c^2)$",
    )
    frame = pd.DataFrame(rows)
    worst = float(frame.relative_difference.abs().max())

    def worst_of(*names):
        part = frame[frame.moment.isin(names) | frame.body.isin(names)]
        return float(part.relative_difference.abs().max())

    # perpendicular axes: a lamina has I1 + I2 = I3 (disc and rectangle)
    perpendicular = max(
        abs(Id[0, 0] + Id[1, 1] - Id[2, 2]) / Id[2, 2], abs(Ir[0, 0] + Ir[1, 1] - Ir[2, 2]) / Ir[2, 2]
    )
    # parallel axes: the rod about its end and the disc about its rim, and a tilted, shifted axis of the
    # cylinder
    end = abs(frame.quadrature[1] / (frame.quadrature[0] + 0.25) - 1)
    rim = abs(frame.quadrature[4] / (frame.quadrature[2] + 1.0) - 1)
    points, weights = cylinder(a, length, n)
    nhat = np.array([np.sin(0.5), 0.0, np.cos(0.5)])
    R = np.array([0.3, -0.7, 0.5])
    direct = float(np.sum(weights * np.sum(np.cross(points - R, nhat) ** 2, axis=1)))
    theorem = float(nhat @ Ic @ nhat + Mc * np.sum(np.cross(R, nhat) ** 2))
    # the dumbbell of the lecture notes: masses m at +-(a/sqrt2, -a/sqrt2, 0), omega along e_y
    s = 1 / np.sqrt(2)
    _, Ib = tensor(np.array([[s, -s, 0.0], [-s, s, 0.0]]), np.array([1.0, 1.0]))
    printed = np.array([[1.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 2.0]])
    omega = np.array([0.0, 1.0, 0.0])
    J = Ib @ omega
    return Moments(
        n,
        numbers,
        frame,
        worst,
        worst_of("cylinder, $l = 2a$", "cylinder, its axis"),
        worst_of("torus, circular section", "torus, square section"),
        float(perpendicular),
        float(max(end, rim)),
        abs(direct / theorem - 1),
        float(np.max(np.abs(Ib - printed))),
        float(np.degrees(np.arctan2(np.linalg.norm(np.cross(J, omega)), J @ omega))),
        float(np.cross(omega, J)[2]),
    )


def run(scene, results, quick):
    _record_moments(results, moments(int(scene.data.get("numerics", {}).get("nodes", 24))))


def _record_moments(results, values: Moments):
    n = values.nodes
    for name, computed, closed in values.moments:
        results.number(name, computed, "1", note=f"in units of M (length)^2; closed form {closed:.15g}")
    results.table(
        "moments",
        values.frame,
        f"Moments of inertia by quadrature ({n} Gauss–Legendre nodes a radius or "
        f"length, {2 * n} trapezoidal nodes an angle) against the closed forms, in units of $M$ times "
        "the length squared ($l = 1$, $a = 1$; the tori: section radius $b = 1$ or half-side $c = 1$, its "
        "centre $d = 3$ from the axis).",
        headers={
            "body": "body",
            "moment": "closed form",
            "quadrature": "quadrature",
            "closed_form": "closed form, value",
            "relative_difference": "relative difference",
        },
    )
    results.number("moments_max_relative_difference", values.worst, "1")
    results.number("cylinder_max_relative_difference", values.cylinder_worst, "1")
    results.number("torus_max_relative_difference", values.torus_worst, "1")
    results.number("perpendicular_axes_residual", values.perpendicular_axes, "1", note="disc and rectangle")
    results.number(
        "parallel_axes_residual", values.parallel_axes, "1", note="rod about its end, disc about its rim"
    )
    results.number(
        "parallel_axis_general_residual",
        values.parallel_axis_general,
        "1",
        note="cylinder about a tilted axis through (0.3, -0.7, 0.5)",
    )
    results.number("dumbbell_tensor_residual", values.dumbbell_tensor, "1", note="in m a^2")
    results.number("dumbbell_J_angle_deg", values.dumbbell_J_angle_deg, "°")
    results.number("dumbbell_couple_z", values.dumbbell_couple_z, "1", note="in m a^2 omega^2")
