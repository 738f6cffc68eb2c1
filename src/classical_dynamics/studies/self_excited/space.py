"""Lee §1.2: the motion of the body in space. Lee follows omega in the body only; the attitude follows from
the kinematic equations (1.2) by quadratures, and a periodic omega in the body need not make a periodic motion
in space.

Here the attitude is integrated twice, independently: as a unit quaternion beside Euler's equations, and as
Euler's angles (psi, theta, phi) from (1.2), z-x-z convention, the body-to-space matrix Rz(psi) Rx(theta)
Rz(phi) and
    p = psi' sin(theta) sin(phi) + theta' cos(phi),  q = psi' sin(theta) cos(phi) - theta' sin(phi),
    r = psi' cos(theta) + phi'.
The angular momentum in space must change by the integral of the torque turned into space (Gauss-Legendre on
the quaternion's samples); after one period of omega in the body the body has not come back.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from . import motions

RTOL, ATOL = 1e-13, 1e-15
PERIODS = 4  # periods of omega drawn and checked
START_ANGLES = (0.0, 1.2, 0.0)  # Euler's angles at t = 0: body z 1.2 rad from space Z, off the poles of (1.2)
GAUSS_NODES = 8


def _rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def angles_matrix(psi, theta, phi):
    return _rz(psi) @ _rx(theta) @ _rz(phi)


def quaternion_matrix(e):
    """Body-to-space matrix of the unit quaternion e = (e0, e1, e2, e3)."""
    e0, e1, e2, e3 = e / np.linalg.norm(e)
    return np.array(
        [
            [1 - 2 * (e2**2 + e3**2), 2 * (e1 * e2 - e0 * e3), 2 * (e1 * e3 + e0 * e2)],
            [2 * (e1 * e2 + e0 * e3), 1 - 2 * (e1**2 + e3**2), 2 * (e2 * e3 - e0 * e1)],
            [2 * (e1 * e3 - e0 * e2), 2 * (e2 * e3 + e0 * e1), 1 - 2 * (e1**2 + e2**2)],
        ]
    )


def matrix_quaternion(R):
    """The unit quaternion of a rotation matrix (Shepperd's choice of the largest diagonal term)."""
    t = np.trace(R)
    if t > 0:
        s = 2.0 * np.sqrt(1.0 + t)
        return np.array([0.25 * s, (R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s])
    i = int(np.argmax(np.diag(R)))
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * np.sqrt(1.0 + R[i, i] - R[j, j] - R[k, k])
    e = np.empty(4)
    e[0] = (R[k, j] - R[j, k]) / s
    e[1 + i] = 0.25 * s
    e[1 + j] = (R[j, i] + R[i, j]) / s
    e[1 + k] = (R[k, i] + R[i, k]) / s
    return e


def rotation_angle(R):
    """The angle of a rotation matrix, from |R - I|_F = 2 sqrt(2) sin(angle/2) (arccos of the trace would lose
    half the digits near 0)."""
    return float(2.0 * np.arcsin(min(1.0, np.linalg.norm(R - np.eye(3)) / (2.0 * np.sqrt(2.0)))))


class SpaceMotion(NamedTuple):
    """The body's attitude over PERIODS periods of omega in the body, integrated two ways."""

    omega_period: float  # T: omega returns in the body (time units)
    omega_return: float  # |omega(T) - omega(0)|/|omega(0)|
    angles_vs_quaternion: float  # largest rotation between the two attitudes (rad)
    theta_min: float
    theta_max: float
    momentum_vs_torque: float  # largest |L(t) - L(0) - int R M dt|/|L(t)| in space
    turn_after_period: float  # the body's rotation in space after one period of omega (rad)
    momentum_direction_turn: float  # the angle between L/|L| at 0 and after one period (rad)
    xs: np.ndarray  # the body's x-axis in space, for the sphere panel
    ls: np.ndarray  # L/|L| in space


def motion(L: se.LargestAxis, body: se.Body, w0: np.ndarray) -> SpaceMotion:
    """Attitude from w0 over PERIODS periods of omega in the body."""
    a, b, c = L.body.a, L.body.b, L.body.c
    params = np.array([a, b, c, L.m, L.mu, 2.0 * np.pi / np.sqrt(b * c)])  # phi1 advances 2 pi: omega returns
    first = solve(
        Problem(se.euler_largest_phase, np.r_[w0, 0.0], (0.0, 1e3), params),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        events=Events(motions.phase_reaches, 1, (1,), (True,)),
    )
    T = float(first.t)
    omega_return = float(np.linalg.norm(first.y[:3] - w0) / np.linalg.norm(w0))
    span = PERIODS * T
    x, wts = np.polynomial.legendre.leggauss(GAUSS_NODES)
    edges = np.linspace(0.0, span, 80 * PERIODS + 1)
    nodes = (0.5 * (edges[:-1, None] + edges[1:, None]) + 0.5 * np.diff(edges)[:, None] * x).ravel()
    t = np.unique(np.r_[edges, nodes, np.linspace(0.0, span, 801)])
    R0 = angles_matrix(*START_ANGLES)
    e0 = matrix_quaternion(R0)
    P = params[:5]
    quat = solve(
        Problem(se.euler_largest_attitude, np.r_[w0, e0], (0.0, span), P),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t,
    )
    ang = solve(
        Problem(se.euler_largest_angles, np.r_[w0, START_ANGLES], (0.0, span), P),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t,
    )
    Rq = np.array([quaternion_matrix(e) for e in quat.y_eval[:, 3:]])
    Ra = np.array([angles_matrix(*y) for y in ang.y_eval[:, 3:]])
    angle_gap = max(rotation_angle(A.T @ B) for A, B in zip(Rq, Ra))
    theta = ang.y_eval[:, 4]

    w = quat.y_eval[:, :3]
    moments = np.array([body.A, body.B, body.C])
    Ls = np.einsum("nij,nj->ni", Rq, w * moments)
    torque = np.zeros_like(w)
    torque[:, 0] = body.A * (L.m + L.mu * np.sum(w * w, axis=1))
    Ms = np.einsum("nij,nj->ni", Rq, torque)
    index = {v: i for i, v in enumerate(t)}
    gain = np.zeros(3)
    worst = 0.0
    for k in range(len(edges) - 1):
        chunk = nodes[k * GAUSS_NODES : (k + 1) * GAUSS_NODES]
        gain += 0.5 * (edges[k + 1] - edges[k]) * np.sum(wts[:, None] * Ms[[index[s] for s in chunk]], axis=0)
        change = Ls[index[edges[k + 1]]] - Ls[0]
        worst = max(worst, float(np.linalg.norm(change - gain) / np.linalg.norm(Ls[index[edges[k + 1]]])))
    after = next(i for i, s in enumerate(t) if s >= T - 1e-12)
    # one period exactly: integrate to T alone
    one = solve(
        Problem(se.euler_largest_attitude, np.r_[w0, e0], (0.0, T), P), "dop853", rtol=RTOL, atol=ATOL
    )
    turn = rotation_angle(quaternion_matrix(one.y[3:]) @ R0.T)
    L0, L1 = Ls[0] / np.linalg.norm(Ls[0]), Ls[after] / np.linalg.norm(Ls[after])
    xs = Rq[:, :, 0]
    ls = Ls / np.linalg.norm(Ls, axis=1)[:, None]
    keep = np.isin(t, np.linspace(0.0, span, 801))
    return SpaceMotion(
        omega_period=T,
        omega_return=omega_return,
        angles_vs_quaternion=angle_gap,
        theta_min=float(theta.min()),
        theta_max=float(theta.max()),
        momentum_vs_torque=worst,
        turn_after_period=turn,
        momentum_direction_turn=float(np.arccos(np.clip(L0 @ L1, -1, 1))),
        xs=xs[keep],
        ls=ls[keep],
    )


def record(results, values: SpaceMotion):
    """The numbers of the motion in space (the sphere's figure is drawn with the period series')."""
    results.number(
        "space_omega_period",
        values.omega_period,
        "time units",
        note="ω returns in the body: φ1 = √(bc)∫p dt advances 2π",
    )
    results.number("space_omega_return", values.omega_return, "1", note="|ω(T) − ω(0)|/|ω(0)|")
    results.number(
        "space_angles_vs_quaternion",
        values.angles_vs_quaternion,
        "rad",
        note="largest rotation between the attitude "
        "from Euler's angles (1.2) and from the quaternion, over four periods of ω",
    )
    results.number("space_theta_min", values.theta_min, "rad", note="θ stays off the poles of (1.2)")
    results.number("space_theta_max", values.theta_max, "rad")
    results.number(
        "space_momentum_vs_torque",
        values.momentum_vs_torque,
        "1",
        note="largest |L(t) − L(0) − ∫R M dt|/|L(t)| in space, "
        "the torque integrated by Gauss–Legendre on the quaternion's attitude",
    )
    results.number(
        "space_turn_after_period",
        values.turn_after_period,
        "rad",
        note="rotation of the body in space after one period of "
        "ω in the body (0 if the motion in space were periodic)",
    )
    results.number(
        "space_momentum_direction_turn",
        values.momentum_direction_turn,
        "rad",
        note="angle between L/|L| at 0 and after one period of ω (sample nearest)",
    )


def wander(ls):
    """L/|L| about its mean direction: the path in the tangent plane there (degrees, two columns) and its
    largest angle from that direction (degrees)."""
    centre = ls.mean(axis=0)
    centre /= np.linalg.norm(centre)
    e1 = np.cross(centre, [0.0, 0.0, 1.0] if abs(centre[2]) < 0.9 else [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(centre, e1)
    plane = np.degrees(np.c_[ls @ e1, ls @ e2])
    return plane, float(np.degrees(np.arccos(np.clip(ls @ centre, -1.0, 1.0))).max())


def draw_sphere(ax, xs, ls, inset=None):
    """The unit sphere (faint meridians), the body's x-axis and L/|L| in space, their starts marked; L/|L|
    magnified in `inset`, axes of their own beside the sphere (without one, an inset left of the sphere's
    axes, off the sphere)."""
    u = np.linspace(0.0, 2 * np.pi, 73)
    for lat in np.linspace(-60, 60, 5) * np.pi / 180:
        ax.plot(
            np.cos(lat) * np.cos(u),
            np.cos(lat) * np.sin(u),
            np.full_like(u, np.sin(lat)),
            color="0.85",
            lw=0.4,
        )
    for lon in np.linspace(0, np.pi, 7)[:-1]:
        ax.plot(np.cos(u) * np.cos(lon), np.cos(u) * np.sin(lon), np.sin(u), color="0.85", lw=0.4)
    ax.plot(*xs.T, color="#0072B2", lw=0.9, label="body $x$-axis in space")
    ax.plot(*ls.T, color="#009E73", lw=2.0, label="$\\mathbf{L}/|\\mathbf{L}|$ in space")
    ax.scatter(*xs[0], color="#0072B2", s=12, marker="o")
    ax.scatter(*ls[0], color="#009E73", s=12, marker="s")
    # L/|L| wanders less than a marker's width on the sphere: an inset draws it magnified, in degrees
    plane, _ = wander(ls)
    if inset is None:
        inset = ax.inset_axes([-0.5, 0.05, 0.36, 0.36])
    inset.plot(*plane.T, color="#009E73", lw=0.9)
    inset.plot(*plane[0], color="#009E73", marker="s", ms=3, ls="none")
    inset.set_aspect("equal", adjustable="box")
    inset.set_anchor("S")  # level with the sphere's lower half, where the frames' panel has no text
    inset.tick_params(labelsize=7.5, length=2, pad=1)
    inset.set_title("$\\mathbf{L}/|\\mathbf{L}|$ (°)", fontsize=7.5, pad=2)
    for k, name in enumerate("XYZ"):
        # X and Y long enough, and seen from a side, that their names stand off the sphere and its loops; Z's
        # name, above the sphere, stays inside the figure
        tip = np.zeros(3)
        tip[k] = 1.2 if name == "Z" else 1.6
        ax.plot(*np.c_[np.zeros(3), tip], color="0.4", lw=0.6)
        ax.text(*(1.08 * tip), f"${name}$", color="0.2", ha="center", va="center")
    ax.set_box_aspect((1, 1, 1), zoom=1.2)
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-1.0, 1.0)
    ax.set_axis_off()
    ax.view_init(elev=15, azim=-35)


def figure(xs, ls):
    """Lee's frames and angles (left), the motion in space on the unit sphere (right) and, in a column of its
    own between them, L/|L| magnified: beside the sphere, never on it."""
    from ...figure_style import TEXT_WIDTH_IN
    from ...results import bare_figure

    fig = bare_figure(figsize=(TEXT_WIDTH_IN, 2.6), layout="constrained")
    columns = fig.add_gridspec(1, 3, width_ratios=(1.0, 0.6, 1.0))
    draw_frames(fig.add_subplot(columns[0], projection="3d"))
    inset = fig.add_subplot(columns[1])
    draw_sphere(fig.add_subplot(columns[2], projection="3d"), xs, ls, inset=inset)
    return fig


# (psi, theta, phi), chosen to show each
FRAME_ANGLES = (np.radians(55.0), np.radians(40.0), np.radians(35.0))


def _arc(u, v, radius, n=30):
    """Points on the arc from unit vector u towards unit vector v (in their plane), at the given radius."""
    v_perp = v - (u @ v) * u
    v_perp /= np.linalg.norm(v_perp)
    angle = np.arccos(np.clip(u @ v, -1.0, 1.0))
    s = np.linspace(0.0, angle, n)[:, None]
    return radius * (np.cos(s) * u + np.sin(s) * v_perp)


def draw_frames(ax, angles=FRAME_ANGLES):
    """Lee's Figures 1.1 and 1.2: the space frame OXYZ, the body frame Oxyz = Rz(psi) Rx(theta) Rz(phi) OXYZ,
    the line of nodes ON (where the body's xy-plane cuts the XY-plane) and the three Euler angles of (1.2)."""
    psi, theta, phi = angles
    R = angles_matrix(psi, theta, phi)
    node = _rz(psi)[:, 0]  # the line of nodes: X turned by psi about Z
    space_axes, body_axes = np.eye(3), R.T  # rows: X, Y, Z and x, y, z in space
    for axis, name in zip(space_axes, "XYZ"):
        ax.plot(*np.c_[np.zeros(3), axis], color="0.45", lw=0.9)
        ax.text(*(1.12 * axis), f"${name}$", color="0.25", ha="center", va="center")
    for axis, name in zip(body_axes, "xyz"):
        ax.plot(*np.c_[np.zeros(3), axis], color="#0072B2", lw=1.4)
        ax.text(*(1.12 * axis), f"${name}$", color="#0072B2", ha="center", va="center")
    ax.plot(*np.c_[-0.9 * node, 0.9 * node], color="#D55E00", lw=0.8, ls="--")
    ax.text(*(1.0 * node), "$N$", color="#D55E00", ha="left", va="bottom")
    for u, v, r, name in (
        (space_axes[0], node, 0.45, "\\psi"),
        (space_axes[2], body_axes[2], 0.55, "\\theta"),
        (node, body_axes[0], 0.6, "\\varphi"),
    ):
        arc = _arc(u, v, r)
        ax.plot(*arc.T, color="#D55E00", lw=0.9)
        ax.text(*(1.15 * arc[len(arc) // 2]), f"${name}$", color="#D55E00", ha="center", va="center")
    ax.set_xlim(-0.8, 0.8)
    ax.set_ylim(-0.8, 0.8)
    ax.set_zlim(-0.25, 1.1)
    ax.set_box_aspect((1.6, 1.6, 1.35), zoom=1.25)  # equal scales on the three axes: true angles
    ax.set_axis_off()
    ax.view_init(elev=18, azim=-28)
