"""Torque along the largest axis (Lee §2, §4.2): the phase plane (phi2, p1), checked against Euler's
equations.

Every portrait draws trajectories of the plane system (2.10), the separatrices from their closed forms
((2.23), (2.13), the limit cycles (2.30)), the singular points typed by the linearization, and full
three-dimensional integrations of Euler's equations mapped into the plane by the inverse map, which
must lie on the plane's trajectories.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...figure_style import PAIR_WIDTH_IN, TEXT_WIDTH_IN
from ...formatting import format_number, shortest
from ...models import self_excited as se
from ...results import bare_figure, new_figure, subplots
from ...solvers.ode import Events, Problem, solve, solve_batch
from ...solvers.timing import min_time
from . import accuracy, portrait
from .bounds import INVARIANT_BOUND, OVERLAY_BOUND

OVERLAY_P1_MAX = 100.0  # beyond it the samples (every 0.05 in tau) could not follow the phase of (q, r)
CYLINDER_BOUND = 1e-10  # hard case: relative spread of q^2/b + r^2/c along Euler's equations
BLOW_UP_BOUND = portrait.BLOW_UP_BOUND
DEFAULT_AMPLITUDES = (0.4, 0.2, 0.1, 0.05)


def _plane(data):
    """(m1, nu, delta): the plane's point, from the scene's effects, and the cylinder it draws."""
    m1, nu = se.plane_torque(data.get("effects"))
    delta = float(data["plane"]["delta"])
    if m1 is None:  # no body_torque: m1 is where the quadratic torque alone puts the plane
        m1 = se.LargestAxis.for_scene(_numbers(data), None, -float(nu), delta).m1
    return float(m1), float(nu), delta


def _numbers(data):
    """The body's inertia numbers in the order of the reduction (swapped for the smallest axis)."""
    body = se.Body.from_moments(data["body"]["moments"])
    return body.swapped() if data["torque_axis"] == "smallest" else body


def run(scene, results, quick):
    data = scene.data
    body = se.Body.from_moments(data["body"]["moments"])
    m1, nu, delta = _plane(data)
    smallest = data["torque_axis"] == "smallest"
    L = se.LargestAxis.with_plane_parameters(body.swapped() if smallest else body, m1, -nu, delta)
    view = data.get("portrait", {})
    lo, hi = view.get("phi2_range", [-3 * np.pi, 3 * np.pi])
    p1_max = view.get("p1_max", 3.0)
    tau_max = view.get("tau_max", 12.0)

    cycles = se.limit_cycle_p1(np.array([0.0]), m1, nu) is not None
    _record_reduction(results, body, L, data, smallest, cycles)
    values = plane_portrait(L, body, smallest, m1, nu, delta, (lo, hi), p1_max, tau_max)
    _record_portrait(results, values, m1, nu, cycles, smallest)
    _analyses(results, data, L, body, values.points, cycles, quick)


class Portrait(NamedTuple):
    """Lee's plane (2.10) drawn and checked: what the portrait draws and how well it holds."""

    points: list  # the singular points, typed by the linearization
    wrong_types: int  # points whose type from the numerical Jacobian differs from the closed form's
    drawing: portrait.Drawing  # every element drawn, window included
    seconds: float  # what the plane's trajectories cost
    invariant_spread: float  # E or C1 along the plane's trajectories (largest relative spread)
    overlay_deviation: float  # Euler's equations mapped into the plane, against (2.10)
    cylinder_spread: float  # q^2/b + r^2/c along Euler's equations (relative)
    invariant_spread_euler: float  # E or C1 along Euler's equations mapped into the plane
    n_paths: int  # integrations of Euler's equations drawn
    body_view: pd.DataFrame | None  # the smallest axis: the motion in the body seen along z


def plane_portrait(L, body, smallest, m1, nu, delta, phi2_range, p1_max, tau_max) -> Portrait:
    """The singular points, the plane's trajectories, the separatrices and limit cycles from their closed
    forms, and Euler's equations mapped into the plane, in the window phi2_range x [-p1_max, p1_max]
    (widened to show F and F1)."""
    lo, hi = phi2_range
    points = se.singular_points(m1, -nu, lo, hi)
    wrong = _wrong_point_types(m1, nu, points)
    F = se.limit_cycle_p1(np.linspace(lo, hi, 801), m1, nu)
    view = p1_max if F is None else max(p1_max, 1.1 * float(np.max(np.abs(F))))  # F and F1 in the window
    drawing = portrait.Drawing("p1", (lo - 0.5, hi + 0.5, 2.0 * view))
    seconds, curves, _ = min_time(
        lambda: _trajectories(m1, nu, lo, hi, p1_max, tau_max, points), repeats=1, budget_s=0.1
    )
    spreads = _draw_trajectories(drawing, curves, m1, nu, lo, hi, p1_max)
    _draw_separatrices(drawing, m1, nu, lo, hi, p1_max, points)
    paths = []
    deviation, cyl, along_euler = _overlay(drawing, L, body, smallest, m1, nu, lo, hi, points, keep=paths)
    view_z = seen_along_z(paths, body, delta) if smallest else None
    drawing.points(points)
    drawing.window(lo, hi, view)
    return Portrait(points, wrong, drawing, seconds, spreads, deviation, cyl, along_euler, len(paths), view_z)


def _record_portrait(results, values: Portrait, m1, nu, cycles, smallest):
    """The singular points, the plane's checks, the figure (beside it, for the smallest axis, the body seen
    along z) and its table, and what the trajectories cost."""
    points = values.points
    results.number("singular_points", points, "1", note="p1 = 0, sin φ2 = −m1, typed by the linearization")
    for kind in ("saddle", "center", "degenerate"):
        results.number(f"n_{kind}s", sum(pt["type"] == kind for pt in points), "1")
    results.hard_case(
        "singular_point_types",
        "Singular points whose type from the numerical Jacobian differs from the closed form's (count)",
        values.wrong_types,
        0,
    )
    results.number(
        "invariant_spread",
        values.invariant_spread,
        "1",
        note=("E" if nu == 0 else "C1") + ": largest spread along "
        "one trajectory, relative to the size of its terms",
    )
    integral = "$E$" if nu == 0 else "$C_1$"
    results.hard_case(
        "plane_invariant",
        f"The plane's first integral {integral} along its trajectories (largest relative spread)",
        values.invariant_spread,
        INVARIANT_BOUND,
    )
    fig, ax, cx = _portrait_axes(smallest)
    if smallest:
        draw_seen_along_z(cx, values.body_view)
        cx.set_title("seen along $z$")
        results.table(
            "body_view",
            values.body_view,
            "The motion in the body seen along the torque axis $z$: the ellipse "
            "$p^2/a + q^2/b = \\delta^2$ and the integrations of Euler's equations on it.",
            headers=BODY_VIEW_HEADERS,
        )
    _overlay_checks(
        results, values.overlay_deviation, values.cylinder_spread, values.invariant_spread_euler, integral
    )
    portrait.finish(ax, values.drawing, "$p_1$", angle=True)
    caption = _caption(m1, nu, points, cycles, values.n_paths, smallest)
    results.figure("portrait", fig, caption)
    values.drawing.save(
        results,
        "What the portrait draws, point by point: each element (trajectory, separatrix, limit "
        "cycle, Euler's equations mapped into the plane, singular point by type, the window's corners) and "
        "its curve number, in $(\\varphi_2, p_1)$.",
    )
    results.timing_table(
        "cost",
        pd.DataFrame([{"what": "plane trajectories of the portrait", "seconds": values.seconds}]),
        "What the portrait's plane trajectories cost to integrate.",
        headers={"what": "computation", "seconds": "wall time (s)"},
    )


def _record_reduction(results, body, L, data, smallest, cycles):
    """The body, the plane's parameters and the physical torque that gives them; whether F and F1 exist."""
    m1, nu, delta = _plane(data)
    plane = data["plane"]
    for name, value in (
        ("A", body.A),
        ("B", body.B),
        ("C", body.C),
        ("a", body.a),
        ("b", body.b),
        ("c", body.c),
    ):
        results.number(
            f"body_{name}", value, "1", note="moments sorted A > B > C; a, b, c Lee's inertia numbers"
        )
    results.number("m1", m1, "1", note=plane.get("source", "chosen to show the regime"))
    results.number("nu", nu, "1", note="mu1 = −nu")
    results.number("delta", delta, "1", note="the elliptic cylinder q²/b + r²/c = δ²")
    moment = "C" if smallest else "A"
    results.number(
        "M_over_moment",
        L.m,
        "1/time²",
        note=f"the constant torque per unit {moment} (the torque axis' "
        "moment) that gives m1 on this cylinder",
    )
    results.number("mu0_over_moment", L.mu, "1", note=f"the coefficient of |ω|² per unit {moment}")
    results.number("tau_per_t", L.time_scale, "1/time", note="τ = √(2d) t")
    if 0.0 < m1 < 1.0:
        results.number(
            "nu_star", se.nu_star(m1), "1", note="limit cycles F, F1 exist for nu below this (Lee §2.5)"
        )
    results.number("limit_cycles", int(cycles), "1", note="1 if F and F1 exist (m1/ν > 2/√(1 + 4ν²))")


def _portrait_axes(smallest):
    """(figure, plane axes, body-view axes or None): for the smallest axis the plane, and beside it the motion
    in the body seen along the torque axis z."""
    if not smallest:
        fig, ax = new_figure(TEXT_WIDTH_IN, 3.9)
        return fig, ax, None
    fig, (ax, cx) = subplots(
        1, 2, figsize=(TEXT_WIDTH_IN, 3.9), layout="constrained", width_ratios=[2.6, 1.0]
    )
    for a in (ax, cx):
        a.grid(True, which="both", alpha=0.25, linewidth=0.6)
    return fig, ax, cx


def _caption(m1, nu, points, cycles, n_paths, smallest):
    """The portrait's caption: the plane, the regime, and what each ink draws."""
    regime = f"$m_1$ = {portrait.param_text(m1)}" + (
        f", $\\nu$ = {portrait.param_text(nu)}" if nu else ", unperturbed ($\\nu = 0$)"
    )
    shown = ["trajectories of the plane (grey)"]
    if any(pt["type"] != "center" for pt in points):
        shown.append("the separatrices from the closed forms (black)")
    if cycles:
        shown.append("the limit cycles $F$ (stable, solid) and $F_1$ (unstable, dashed)")
    if points:
        shown.append("the singular points by type")
    shown.append(
        f"{portrait.COUNTS[n_paths]} integrations of Euler's equations in three dimensions, mapped "
        "into the plane (dots)"
    )
    axis_text = "smallest axis $z$ ($p$ and $r$, $a$ and $c$ exchanged)" if smallest else "largest axis $x$"
    caption = (
        f"Phase plane of Lee (2.10) for the torque along the {axis_text}, {regime}: "
        + ", ".join(shown[:-1])
        + ", and "
        + shown[-1]
        + ". The dots lie on the plane's trajectories."
    )
    if smallest:
        caption += (
            " Right: the same integrations in the body, seen along the torque axis $z$: the end of "
            "$\\boldsymbol{\\omega}$ runs on the ellipse $p^2/a + q^2/b = \\delta^2$ about $z$ (black), "
            "where for the torque along the largest axis it runs about $x$; the plane is the same."
        )
    return caption


def _analyses(results, data, L, body, points, cycles, quick):
    """What a scene asks beyond the portrait (its `analysis`), and what the plane's regime calls for: the
    motion in space, the period series about the center, the separatrix's sides, the degenerate approach,
    blow-up and the limit cycle's period, the motions of §2.5, accuracy and cost, the bifurcations; each
    computed, then recorded."""
    smallest = data["torque_axis"] == "smallest"
    m1, nu, delta = _plane(data)
    centers = [pt for pt in points if pt["type"] == "center"]
    sphere = None
    if data.get("analysis", {}).get("motion_in_space"):  # Lee §1.2, started on F
        from . import space

        sigma3 = np.arctan(-1.0 / (2.0 * nu))
        on_F = float(se.limit_cycle_p1(np.array([-sigma3]), m1, nu)[0])
        sphere = space.motion(L, body, L.from_plane(-sigma3, on_F))
        space.record(results, sphere)
    if centers:
        amplitudes = data.get("analysis", {}).get("series_amplitudes", DEFAULT_AMPLITUDES)
        _record_series(results, series(m1, nu, centers[0]["phi2"], amplitudes), sphere)
        if nu == 0.0 or nu < (1.0 - 1e-9) * se.nu_star(m1):  # where the saddle's own loop encloses the center
            _record_separatrix_sides(results, separatrix_sides(m1, nu))
    if nu == 0.0 and abs(abs(m1) - 1.0) < 1e-12:
        _record_degenerate_approach(results, degenerate_approach(m1))
    if cycles:
        _record_blow_up(results, blow_up(m1, nu))
        _record_limit_cycle_period(results, limit_cycle_period(m1, nu))
        if centers and nu > 0:
            _record_cylinder(results, cylinder(m1, nu, points))
    if data.get("analysis", {}).get("motions"):
        from . import motions

        motions.run(results, L, m1, points)
    if data.get("analysis", {}).get("accuracy_cost"):
        if nu == 0.0 and centers:
            accuracy.record_separatrix(results, accuracy.separatrix(m1, quick))
        if cycles:
            accuracy.record_limit_cycle(results, accuracy.limit_cycle(m1, nu, quick), m1, nu)
    if data.get("analysis", {}).get("bifurcation"):
        _record_singular_point_bifurcation(results, singular_point_bifurcation())
        _record_limit_cycle_bifurcation(results, limit_cycle_bifurcation(), m1, nu)
    if not smallest:
        from . import largest_cycles  # Lee §2.5 (Figure 2.12, the motions on and off F) and §2.6

        largest_cycles.run(results, data, body, m1, nu, delta)


def _overlay_checks(results, deviation, cyl, along_euler, integral):
    """Euler's equations mapped into the plane: on the plane's trajectories, keeping its first integral
    (`integral`, E or C1 as the caption writes it), and on their elliptic cylinder."""
    nu_zero = integral == "$E$"
    results.number(
        "overlay_deviation", deviation, "1", note="Euler's equations in the plane against (2.10), max"
    )
    results.number("cylinder_spread", cyl, "1", note="relative spread of q²/b + r²/c along Euler's equations")
    results.hard_case(
        "overlay",
        "Full integrations of Euler's equations, mapped into the plane, on the plane's "
        "trajectories (largest deviation in $(\\varphi_2, p_1)$)",
        deviation,
        OVERLAY_BOUND,
    )
    results.number(
        "invariant_spread_euler",
        along_euler,
        "1",
        note=("E" if nu_zero else "C1") + ": largest "
        "spread along one of Euler's integrations mapped into the plane, relative to the size of its terms",
    )
    results.hard_case(
        "plane_invariant_euler",
        f"The plane's first integral {integral} along Euler's equations "
        "mapped into the plane (largest relative spread)",
        along_euler,
        INVARIANT_BOUND,
    )
    results.hard_case(
        "elliptic_cylinder",
        "The end of $\\boldsymbol{\\omega}$ stays on its elliptic cylinder "
        "(relative spread of $q^2/b + r^2/c$)",
        cyl,
        CYLINDER_BOUND,
    )


def _wrong_point_types(m1, nu, points) -> int:
    """The points whose type from the numerical Jacobian of (2.10) differs from the closed-form type."""
    wrong = 0
    for pt in points:
        h = 1e-6
        J = np.empty((2, 2))
        out_p, out_m = np.empty(2), np.empty(2)
        base = np.array([pt["phi2"], 0.0])
        for k in range(2):
            e = np.zeros(2)
            e[k] = h
            se.plane_largest(0.0, base + e, np.array([m1, -nu, 1.0]), out_p)
            se.plane_largest(0.0, base - e, np.array([m1, -nu, 1.0]), out_m)
            J[:, k] = (out_p - out_m) / (2 * h)
        lam = np.linalg.eigvals(J)
        kind = (
            "degenerate"
            if np.max(np.abs(lam)) < 1e-4
            else ("saddle" if np.max(lam.real) > 1e-8 else "center")
        )
        wrong += kind != pt["type"]
    return wrong


def _starts(m1, nu, lo, hi, p1_max, points):
    starts = [(lo + 0.05, v) for v in np.linspace(-0.8 * p1_max, 0.8 * p1_max, 7)]
    starts += [(x, 0.0) for x in np.linspace(lo, hi, 7)[1:-1]]
    for pt in points:
        if pt["type"] == "center":
            starts += [(pt["phi2"] + s, 0.0) for s in (0.4, 0.9, 1.5)]
    return starts


def _trajectories(m1, nu, lo, hi, p1_max, tau_max, points):
    return portrait.trajectories(
        se.plane_largest,
        lambda direction: [m1, -nu, direction],
        _starts(m1, nu, lo, hi, p1_max, points),
        tau_max,
    )


def _draw_trajectories(drawing, curves, m1, nu, lo, hi, p1_max):
    """Record the plane's trajectories; return the largest spread of the first integral along one of them."""
    worst = 0.0
    for y in curves:
        drawing.curve("trajectory", y[:, 0], y[:, 1])
        inside = (np.abs(y[:, 1]) < 10 * p1_max) & (np.abs(y[:, 0]) < 10 * max(abs(lo), abs(hi)))
        y = y[inside]
        if len(y) < 2:
            continue
        worst = max(worst, se.invariant_spread(y, m1, -nu))
    return worst


def _draw_separatrices(drawing, m1, nu, lo, hi, p1_max, points):
    phi = np.linspace(lo, hi, 4001)
    for pt in points:
        if pt["type"] == "center":
            continue
        sq = se.separatrix_p1_squared(phi, m1, -nu, pt["phi2"])
        ok = sq >= 0
        for sign in (1, -1):
            drawing.curve("separatrix", phi, np.where(ok, sign * np.sqrt(np.where(ok, sq, 0.0)), np.nan))
    F = se.limit_cycle_p1(phi, m1, nu)
    if F is not None:
        drawing.curve("limit_cycle_F", phi, F)
        drawing.curve("limit_cycle_F1", phi, -F)


BODY_VIEW_HEADERS = {
    "element": "what is drawn",
    "curve": "curve",
    "p": "$p$ (rad per time unit)",
    "q": "$q$ (rad per time unit)",
}


def seen_along_z(paths, body, delta):
    """The torque along z: the ellipse p^2/a + q^2/b = delta^2 and Euler's integrations (p, q) on it, as a
    table."""
    theta = np.linspace(0.0, 2 * np.pi, 361)
    parts = [
        pd.DataFrame(
            {
                "element": "ellipse",
                "curve": 0,
                "p": delta * np.sqrt(body.a) * np.cos(theta),
                "q": delta * np.sqrt(body.b) * np.sin(theta),
            }
        )
    ]
    parts += [
        pd.DataFrame({"element": "euler", "curve": k + 1, "p": w[::4, 0], "q": w[::4, 1]})
        for k, w in enumerate(paths)
    ]
    frame = pd.concat(parts, ignore_index=True)
    return frame.round({"p": portrait.DIGITS, "q": portrait.DIGITS})


def draw_seen_along_z(ax, frame, small=False):
    ring = frame[frame.element == "ellipse"]
    ax.plot(ring.p, ring.q, "k-", lw=0.8 if small else 1.0)
    dots = frame[frame.element == "euler"]
    for _, path in dots.groupby("curve"):
        ax.plot(path.p, path.q, ".", color=portrait.EULER_COLOUR, ms=2.2 if small else 3)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("$p$ (rad per time unit)")
    ax.set_ylabel("$q$ (rad per time unit)")


def _overlay(drawing, L, body, smallest, m1, nu, lo, hi, points, keep=None):
    """Three starts integrated in (p, q, r) and in the plane: their largest disagreement after mapping, and
    along Euler's integrations the spreads of q^2/b + r^2/c and of the plane's first integral. For the
    smallest axis the physical equations are integrated and their state read as (r, q, p). keep: a list that
    receives each integration's physical states (p, q, r)."""
    order = [2, 1, 0] if smallest else [0, 1, 2]
    rhs = se.euler_smallest if smallest else se.euler_largest
    physical = np.array([body.a, body.b, body.c, L.m, L.mu])
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    starts = [(centers[0] + 0.7, 0.0)] if centers else []
    starts += [(0.5 * (lo + hi), 1.2), (lo + 0.3 * (hi - lo), -0.6)]
    worst, cyl_worst, inv_worst = 0.0, 0.0, 0.0
    tau_span = 6.0
    for phi, p1 in starts:
        tau = np.linspace(0.0, tau_span, 121)
        w0 = L.from_plane(phi, p1)[order]
        full = solve(
            Problem(rhs, w0, (0.0, tau_span / L.time_scale), physical),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau / L.time_scale,
            bound=BLOW_UP_BOUND,
        )
        flat = solve(
            Problem(se.plane_largest, [phi, p1], (0.0, tau_span), [m1, -nu, 1.0]),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau,
            bound=BLOW_UP_BOUND,
        )
        good = np.all(np.isfinite(full.y_eval), axis=1) & np.all(np.isfinite(flat.y_eval), axis=1)
        good &= np.cumprod(np.abs(np.nan_to_num(flat.y_eval[:, 1], nan=np.inf)) < OVERLAY_P1_MAX).astype(bool)
        reduced = full.y_eval[good][:, order]
        if keep is not None:
            keep.append(full.y_eval[good])
        mapped = L.to_plane(reduced, phi2_start=phi)
        scale = np.maximum(1.0, np.abs(flat.y_eval[good]))
        worst = max(worst, float(np.max(np.abs(mapped - flat.y_eval[good]) / scale)))
        cyl = se.cylinder(L.body, reduced)
        cyl_worst = max(cyl_worst, float(np.ptp(cyl) / cyl[0]))
        inv_worst = max(inv_worst, se.invariant_spread(mapped, m1, -nu))
        drawing.curve("euler", mapped[::4, 0], mapped[::4, 1])
    return worst, cyl_worst, inv_worst


def _period(m1, nu, phi_c, eta):
    return portrait.period(se.plane_largest, [m1, -nu, 1.0], [phi_c + eta, 0.0], span=60.0)


class Series(NamedTuple):
    """Lee §4.2: the period series about the center against the integrated period."""

    check: portrait.SeriesCheck
    period_linear: float  # 2 pi (1 - m1^2)^(-1/4)


def series(m1, nu, phi_c, amplitudes) -> Series:
    """Lee §4.2: the series period against the measured one; the error must shrink like eta^4."""
    check = portrait.series_periods(
        lambda eta: _period(m1, nu, phi_c, eta), lambda eta: se.series_period(m1, nu, eta), amplitudes
    )
    return Series(check, 2 * np.pi / (1 - m1**2) ** 0.25)


def _record_series(results, values: Series, sphere=None):
    """The series' table, numbers and figure; with sphere (space.motion), the motion in space."""
    portrait.record_series_check(
        results,
        values.check,
        "Lee §4.2: the period (in $\\tau$) of the oscillation about the center $\\varphi_{2\\mathrm{c}}$ "
        "started at "
        "$\\varphi_{2\\mathrm{c}} + \\eta$, integrated from the plane system and from the series "
        "$2\\pi(1 - m_1^2)^{-1/4}(1 + h_2\\eta^2 + h_3\\eta^3)$, and their relative difference.",
    )
    results.number("period_tau_linear", values.period_linear, "τ", note="2π(1 − m1²)^(−1/4)")
    slope = values.check.slope
    fig, ax = new_figure(PAIR_WIDTH_IN, 2.9)  # printed beside its table
    portrait.series_figure(ax, values.check.frame, slope, ncol=1)
    results.figure(
        "series",
        fig,
        (
            "The relative error of Lee's period series (§4.2) against the integrated period, by amplitude "
            "$\\eta$ (log-log), with the dashed reference slope $\\eta^4$, the first power the series leaves "
            "out: "
            f"the fitted slope is {format_number(slope, 3)}."
        ),
    )
    if sphere is not None:  # Lee §1.2: the frames and angles of (1.2), and this body's motion in space
        from . import space

        results.figure(
            "space",
            space.figure(sphere.xs, sphere.ls),
            (
                "Left: the frames and angles of Lee's Figures 1.1 and 1.2: space axes $X$, $Y$, $Z$ (grey), "
                "body axes "
                "$x$, $y$, $z$ along the moments $A$, $B$, $C$ (blue), the line of nodes $N$ and Euler's "
                "angles "
                "$\\psi$, $\\theta$, $\\varphi$ of (1.2) (z-x-z: the body turned by "
                "$R_z(\\psi)R_x(\\theta)R_z(\\varphi)$; "
                + ", ".join(f"{np.degrees(a):.0f}°" for a in space.FRAME_ANGLES)
                + " here, chosen to show each). Right: the motion in "
                "space (Lee §1.2) over four periods of $\\boldsymbol{\\omega}$ on the limit cycle $F$, the "
                "attitude "
                "integrated as a quaternion: the body's $x$-axis (blue) and $\\mathbf{L}/|\\mathbf{L}|$ "
                "(green; starts marked) on the unit sphere; $\\mathbf{L}/|\\mathbf{L}|$ stays within "
                f"{format_number(space.wander(sphere.ls)[1], 2)}° of its mean direction, drawn magnified in "
                "the small middle panel (degrees in the plane tangent there). $\\boldsymbol{\\omega}$ is "
                "periodic in the "
                "body, the motion in space is not."
            ),
        )


DEGENERATE_TAUS = (40.0, 100.0)  # where the approach to the degenerate point is measured
DEGENERATE_BOUND = 1e-4  # hard case: relative error of the algebraic rate


class DegenerateApproach(NamedTuple):
    """|m1| = 1: the algebraic approach to the degenerate point along the separatrix."""

    coefficient: float  # C in |phi2 - phi2d| ~ C/(tau + c)^2: 12 expected
    distance_tau100: float  # |phi2 - phi2d| at tau = 100
    rate_error: float  # the rate of |phi2 - phi2d|^(-1/2) against 1/sqrt(12), relative


def degenerate_approach(m1) -> DegenerateApproach:
    """|m1| = 1 without drag: the separatrix (2.23) through the degenerate point phi2d (sin phi2d = -m1) is
    p1^2 = 2(x - sin x) ~ x^3/3 in x = |phi2 - phi2d|, so the motion along it reaches the point only
    algebraically, x = 12/(tau + c)^2, where a saddle is approached exponentially. Started on the branch at x
    = 0.5 and integrated, x^(-1/2) must grow linearly in tau at the rate 1/sqrt(12) (the energy error of the
    integration, 1e-13 or so, would stop the motion near x = (6e-13)^(1/3) only at tau of several hundred)."""
    side = np.sign(m1)  # m1 = 1: from the right, m1 = -1: from the left
    phi_d = float(np.arcsin(-m1))
    phi0 = phi_d + 0.5 * side
    gap = (-m1 * phi_d + np.cos(phi_d)) - (-m1 * phi0 + np.cos(phi0))  # E at the point − V(phi0)
    p0 = -side * np.sqrt(2.0 * gap)
    taus = np.array(DEGENERATE_TAUS)
    sol = solve(
        Problem(se.plane_largest, [phi0, p0], (0.0, taus[-1]), [m1, 0.0, 1.0]),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=taus,
    )
    x = np.abs(sol.y_eval[:, 0] - phi_d)
    rate = float(np.diff(x**-0.5)[0] / np.diff(taus)[0])
    return DegenerateApproach(1.0 / rate**2, float(x[-1]), rate * np.sqrt(12.0) - 1.0)


def _record_degenerate_approach(results, values: DegenerateApproach):
    results.number(
        "degenerate_approach_coefficient",
        values.coefficient,
        "1",
        note="C in |φ2 − φ2d| ≈ C/(τ + c)² along "
        "the separatrix into the degenerate point, from |φ2 − φ2d|^(−1/2) at τ = 40 and 100; 12 expected",
    )
    results.number(
        "degenerate_distance_tau100",
        values.distance_tau100,
        "1",
        note="|φ2 − φ2d| at τ = 100 from 0.5 at τ = 0",
    )
    results.hard_case(
        "degenerate_approach",
        "$|m_1| = 1$: along the separatrix the motion reaches the degenerate "
        "point algebraically, $|\\varphi_2 - \\varphi_{2\\mathrm{d}}| \\approx 12/\\tau^2$, not "
        "exponentially as into a saddle (relative error of the rate of "
        "$|\\varphi_2 - \\varphi_{2\\mathrm{d}}|^{-1/2}$ against $1/\\sqrt{12}$, $\\tau$ from 40 to 100)",
        values.rate_error,
        DEGENERATE_BOUND,
    )


class BlowUp(NamedTuple):
    """A start below F1 on the plane."""

    start: float  # p1 at phi2 = 0
    blew_up: bool  # |y| passed BLOW_UP_BOUND in finite time
    time: float  # when (tau)


def blow_up(m1, nu) -> BlowUp:
    """Below F1 the spin runs to the negative x-axis in finite time: p1' ~ -nu p1^2."""
    F1_at_0 = -se.limit_cycle_p1(np.array([0.0]), m1, nu)[0]
    start = F1_at_0 - 0.5
    sol = solve(
        Problem(se.plane_largest, [0.0, start], (0.0, 100.0), [m1, -nu, 1.0]),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=BLOW_UP_BOUND,
    )
    return BlowUp(start, sol.status == "blow-up", sol.t)


def _record_blow_up(results, values: BlowUp):
    if values.blew_up:
        results.number(
            "blow_up_time",
            values.time,
            "τ",
            note=f"from φ2 = 0, p1 = {values.start:.4g} (below F1): |y| passes "
            f"{BLOW_UP_BOUND:g}, within 1/(ν·{BLOW_UP_BOUND:g}) of the singularity",
        )
    results.hard_case(
        "below_F1_blows_up",
        "A start below $F_1$ leaves every bound in finite time (1 if it does not)",
        0.0 if values.blew_up else 1.0,
        0.0,
    )


SEPARATRIX_OFFSETS = (1e-2, 1e-4, 1e-6, 1e-8, 1e-10)


class SeparatrixSides(NamedTuple):
    """Starts either side of the saddle's loop: their fates and the period's growth inside."""

    frame: pd.DataFrame  # by offset: the period inside, whether the start outside turns back
    wrong: int  # starts that end on the wrong side
    slope: float  # d(period)/d ln(1/eps) inside, fitted
    slope_expected: float  # n/lambda
    slope_error: float  # the fitted slope against n/lambda, relative


def separatrix_sides(m1, nu) -> SeparatrixSides:
    """Starts a relative 1e-2 ... 1e-10 inside and outside the saddle's loop, on the vertical through its
    center and heading for the saddle: inside, p1 must change sign (a closed orbit) with a period growing
    like n ln(1/eps)/lambda, lambda = (1 - m1^2)^(1/4) the saddle's rate and n the saddles passed in a
    period (1 on a homoclinic loop; 2 for m1 = 0, where the separatrix joins two saddles); outside, p1
    must never change sign (the motion runs past the saddle)."""
    phi_s = -np.arcsin(m1)
    side = -1.0 if m1 >= 0 else 1.0  # the loop lies left of its saddle for m1 > 0
    phi_c = phi_s + side * (np.pi - 2.0 * abs(np.arcsin(m1)))
    p_sep = -side * float(np.sqrt(se.separatrix_p1_squared(np.array([phi_c]), m1, -nu, phi_s))[0])
    passages = 2 if m1 == 0.0 else 1
    rows, wrong = [], 0
    for eps in SEPARATRIX_OFFSETS:
        fates = {}
        for name, factor in (("inside", 1.0 - eps), ("outside", 1.0 + eps)):
            sol = solve(
                Problem(se.plane_largest, [phi_c, p_sep * factor], (0.0, 200.0), [m1, -nu, 1.0]),
                "dop853",
                rtol=1e-13,
                atol=1e-15,
                events=Events(portrait.velocity_zero, 1, (-1,)),
                bound=BLOW_UP_BOUND,
            )
            fates[name] = sol.event_t
        wrong += (len(fates["inside"]) < 2) + (len(fates["outside"]) > 0)
        period = float(fates["inside"][1] - fates["inside"][0]) if len(fates["inside"]) >= 2 else np.nan
        rows.append({"offset": eps, "period_inside": period, "outside_turns_back": len(fates["outside"]) > 0})
    frame = pd.DataFrame(rows)
    slope = float(np.polyfit(np.log(1.0 / frame.offset), frame.period_inside, 1)[0])
    rate = (1.0 - m1**2) ** 0.25 / passages
    return SeparatrixSides(frame, wrong, slope, 1.0 / rate, slope * rate - 1.0)


def _record_separatrix_sides(results, values: SeparatrixSides):
    results.table(
        "separatrix",
        values.frame,
        "Starts a relative offset $\\varepsilon$ inside and outside the separatrix "
        "loop, heading for the saddle: the period inside (in $\\tau$), which grows like "
        "$\\ln(1/\\varepsilon)$, and whether the start outside ever turns back (it must not).",
        headers={
            "offset": "offset $\\varepsilon$",
            "period_inside": "period inside ($\\tau$)",
            "outside_turns_back": "outside turns back",
        },
    )
    results.number("separatrix_period_slope", values.slope, "τ", note="d(period)/d ln(1/ε) inside the loop")
    results.number(
        "separatrix_slope_expected",
        values.slope_expected,
        "τ",
        note="n/λ, λ = (1 − m1²)^(1/4), n saddles passed",
    )
    results.hard_case(
        "separatrix_sides",
        "Starts a relative 10⁻² to 10⁻¹⁰ either side of the separatrix that end on the wrong side (count)",
        values.wrong,
        0,
    )
    results.hard_case(
        "separatrix_period_growth",
        "Near the separatrix the period grows like "
        "$n\\ln(1/\\varepsilon)/\\lambda$, $\\lambda = (1 - m_1^2)^{1/4}$ the saddle's rate and $n$ the "
        "saddles passed in a period (relative error of the slope)",
        values.slope_error,
        0.01,
    )


class LimitCyclePeriod(NamedTuple):
    """The period of p1 on F (in tau), integrated and from Jacobi's form."""

    period: float  # integrated, phi2 as the clock over one turn
    jacobi: float  # 4K(k)/sqrt(alpha + beta)
    relative: float  # period/jacobi - 1
    closure: float  # p1 after the turn minus its start


def limit_cycle_period(m1, nu) -> LimitCyclePeriod:
    """The period of p1 on F, integrated with phi2 as the clock over one turn, against Jacobi's form."""
    sigma3 = np.arctan(-1.0 / (2.0 * nu))
    start = float(se.limit_cycle_p1(np.array([-sigma3]), m1, nu)[0])
    sol = solve(
        Problem(se.plane_by_phase, [0.0, start], (-sigma3, -sigma3 + 2 * np.pi), [m1, -nu]),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
    )
    closed = se.limit_cycle_period(m1, nu)
    period = float(sol.y[0])
    return LimitCyclePeriod(period, closed, period / closed - 1.0, float(sol.y[1]) - start)


def _record_limit_cycle_period(results, values: LimitCyclePeriod):
    results.number("period_tau_F", values.period, "τ", note="p1 on F, one turn of φ2 (2π), integrated")
    results.number("period_tau_F_jacobi", values.jacobi, "τ", note="4K(k)/√(α + β), Jacobi's form")
    results.number(
        "period_tau_F_minus_jacobi_relative",
        values.relative,
        "1",
        note="the integrated period against the rebuilt Jacobi form (Lee's (2.31)-(2.32) are lost)",
    )
    results.number("omega_period_tau_F", 2 * values.period, "τ", note="ω returns after two turns of φ2 (4π)")
    results.hard_case(
        "limit_cycle_period",
        "The period on $F$, integrated, against Jacobi's closed form "
        "$4K(k)/\\sqrt{\\alpha + \\beta}$ (relative)",
        values.relative,
        1e-9,
    )
    results.hard_case(
        "limit_cycle_closes",
        "$p_1$ on $F$ returns to its start after one turn of $\\varphi_2$ (absolute)",
        values.closure,
        1e-9,
    )


class SingularPointBifurcation(NamedTuple):
    """The roots of m1 + sin(phi2) found numerically over a grid of m1."""

    found: list  # (m1, phi2, type) of each root
    wrong: int  # roots the closed form misses, misplaces or mistypes


def singular_point_bifurcation() -> SingularPointBifurcation:
    """Where the permanent rotations appear, merge and vanish as m1 crosses +-1: roots of m1 + sin(phi2) found
    numerically (sign changes and bisection, types from the numerical Jacobian) against the closed form."""
    from scipy.optimize import brentq

    m1_grid = np.linspace(-1.5, 1.5, 60)  # an even count: +-1 and 0 are not on it
    phi = np.linspace(-np.pi, np.pi, 2001)
    found, wrong = [], 0
    for m1 in m1_grid:
        f = m1 + np.sin(phi)
        roots = [
            brentq(lambda x: m1 + np.sin(x), phi[i], phi[i + 1], xtol=1e-14)
            for i in np.nonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)[0]
        ]
        closed = se.singular_points(m1, 0.0, -np.pi, np.pi)
        wrong += len(roots) != len(closed)
        for x in roots:
            kind = "saddle" if np.cos(x) > 0 else "center"  # eigenvalues +-sqrt(cos phi2)
            match = [pt for pt in closed if abs(pt["phi2"] - x) < 1e-10 and pt["type"] == kind]
            wrong += len(match) != 1
            found.append((m1, x, kind))
    return SingularPointBifurcation(found, wrong)


def _record_singular_point_bifurcation(results, values: SingularPointBifurcation):
    """The hard case, and the figure: the closed form's curves and the roots found."""
    results.hard_case(
        "singular_point_bifurcation",
        "Singular points found numerically for $m_1$ in [−1.5, 1.5] "
        "that the closed form misses, misplaces or mistypes (count)",
        values.wrong,
        0,
    )
    fig, ax = new_figure(height=2.8)
    m = np.linspace(-1.0, 1.0, 401)
    ax.plot(m, -np.arcsin(m), "k-", lw=1.2, label="saddles, closed form")
    centre = np.pi + np.arcsin(m)
    centre = np.where(centre > np.pi, centre - 2 * np.pi, centre)
    centre[np.r_[False, np.abs(np.diff(centre)) > np.pi]] = np.nan  # the jump from π to −π is no curve
    ax.plot(m, centre, "k--", lw=1.2, label="centers, closed form")
    for kind, marker in (("saddle", "x"), ("center", "o")):
        pts = np.array([(a, b) for a, b, k in values.found if k == kind])
        ax.plot(
            pts[:, 0],
            pts[:, 1],
            marker,
            ms=3.5,
            color="#0072B2",
            mfc="none",
            label=f"{kind}s, found numerically",
        )
    ax.axvline(-1, color="0.6", lw=0.6)
    ax.axvline(1, color="0.6", lw=0.6)
    portrait.pi_ticks(ax.yaxis, -np.pi, np.pi)
    ax.set_ylim(-1.1 * np.pi, 1.1 * np.pi)
    ax.set_xlabel("$m_1$")
    ax.set_ylabel("$\\varphi_2$ of the singular point (rad)")
    fig.legend(loc="outside right upper")
    results.figure(
        "bifurcation_m1",
        fig,
        "The singular points of Lee (2.10) against $m_1$, $\\varphi_2$ taken in "
        "$(-\\pi, \\pi]$: lines from the closed form $\\sin\\varphi_2 = -m_1$, markers from numerical "
        "root finding with the type read from the Jacobian. Each saddle–center pair merges into a "
        "degenerate point at $m_1 = \\pm 1$ and vanishes beyond.",
    )


class LimitCycleGrid(NamedTuple):
    """The fate of a start above F over a grid of (m1, nu)."""

    m1: np.ndarray  # the grid (m1 along the first index)
    nu: np.ndarray
    bounded: np.ndarray  # the start stayed bounded (it tends to F)
    wrong: int  # cells off nu* by more than 2 % whose fate disagrees with it


def limit_cycle_bifurcation() -> LimitCycleGrid:
    """Where F exists in the (m1, nu) plane: a start high above (phi2 = 0, p1 = 4) stays bounded exactly when
    it has F to converge to; otherwise it runs to the negative x-axis in finite time. One batch call."""
    m1s, nus = np.linspace(0.05, 1.95, 39), np.linspace(0.025, 1.0, 40)
    M, N = np.meshgrid(m1s, nus, indexing="ij")
    P = np.column_stack([M.ravel(), -N.ravel(), np.ones(M.size)])
    status, _, _, _ = solve_batch(
        se.plane_largest, np.tile([0.0, 4.0], (M.size, 1)), (0.0, 300.0), P, rtol=1e-9, atol=1e-11, bound=1e6
    )
    bounded = np.array([s_ == "success" for s_ in status]).reshape(M.shape)
    exists = np.array(
        [se.limit_cycle_p1(np.zeros(1), a, b) is not None for a, b in zip(M.ravel(), N.ravel())]
    )
    exists = exists.reshape(M.shape)
    star = np.full(M.shape, np.inf)
    below = M < 1.0
    star[below] = M[below] / (2.0 * np.sqrt(1.0 - M[below] ** 2))
    clear = np.abs(N / star - 1.0) > 0.02  # cells on the boundary itself are undecided
    return LimitCycleGrid(M, N, bounded, int(np.sum((bounded != exists) & clear)))


def _record_limit_cycle_bifurcation(results, values: LimitCycleGrid, m1_scene, nu_scene):
    """The grid's count and hard case, and the figure with the scene's plane marked."""
    M, N, bounded = values.m1, values.nu, values.bounded
    results.number("limit_cycle_grid_cells", int(M.size), "1")
    results.hard_case(
        "limit_cycle_bifurcation",
        "Cells of the $(m_1, \\nu)$ grid where the integrated fate "
        "disagrees with $\\nu^* = m_1/(2\\sqrt{1 - m_1^2})$ (count, cells within 2 % of the curve "
        "excluded)",
        values.wrong,
        0,
    )
    fig, ax = new_figure(height=2.8)
    ax.plot(M[bounded], N[bounded], "s", ms=2.5, color="#56B4E9", label="bounded: tends to $F$")
    ax.plot(M[~bounded], N[~bounded], "s", ms=2.5, color="0.78", label="runs to $-x$ in finite time")
    m = np.linspace(0.01, 0.999, 400)
    ax.plot(m, m / (2 * np.sqrt(1 - m**2)), "k-", lw=1.2, label="$\\nu^* = m_1/(2\\sqrt{1 - m_1^2})$")
    ax.plot(
        [m1_scene],
        [nu_scene],
        "*",
        color="#D55E00",
        mec="k",
        mew=0.5,
        ms=10,
        label=f"the portrait's plane\n($m_1$ = {shortest(m1_scene)}, $\\nu$ = {shortest(nu_scene)})",
    )
    ax.set_xlim(0, 2)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("$m_1$")
    ax.set_ylabel("$\\nu$")
    ax.grid(False)
    fig.legend(loc="outside right upper")
    results.figure(
        "bifurcation_nu",
        fig,
        "Where the limit cycles exist in the $(m_1, \\nu)$ plane: each cell is "
        "the fate of a start above $F$ ($\\varphi_2 = 0$, $p_1 = 4$) integrated to $\\tau = 300$, "
        f"{format_number(int(M.size))} integrations in one batch call, and the curve $\\nu^*$ from the "
        "closed form. The fates change exactly at $\\nu^*$; for $m_1 \\ge 1$ the cycles exist at every "
        "$\\nu$.",
    )


class Cylinder(NamedTuple):
    """Lee's Figure 2.13: the plane rolled onto the cylinder (cos phi2, sin phi2, p1)."""

    m1: float
    nu: float
    theta: np.ndarray  # phi2 over one turn
    F: np.ndarray  # p1 on F there (F1 is -F)
    paths: dict  # label: the integrated (phi2, p1) of each start, where finite and |p1| < 4
    saddle: float  # phi2 of one saddle and of one center: the cylinder merges each kind into one
    center: float


CYLINDER_COLOURS = {  # the starts' ink
    "closed orbit about $C$": "k",
    "above $F_1$: winds onto $F$": "#0072B2",
    "below $F_1$: runs away": "0.55",
}


def cylinder(m1, nu, points) -> Cylinder:
    """Lee's Figure 2.13: phi2 taken mod 2 pi, the plane rolled onto a cylinder (cos phi2, sin phi2, p1). The
    saddles merge into one S and the centers into one C; F and F1 close on themselves; a closed orbit about C,
    a start above F1 winding onto F, and one below F1 running away to p1 -> -infinity."""
    theta = np.linspace(0.0, 2 * np.pi, 721)
    F = se.limit_cycle_p1(theta, m1, nu)
    center = next(pt["phi2"] for pt in points if pt["type"] == "center")
    F1_at_0 = -float(se.limit_cycle_p1(np.zeros(1), m1, nu)[0])
    starts = {
        "closed orbit about $C$": ([center + 0.7, 0.0], 30.0),
        "above $F_1$: winds onto $F$": ([0.0, F1_at_0 + 0.05], 60.0),
        "below $F_1$: runs away": ([0.0, F1_at_0 - 0.05], 20.0),
    }
    paths = {}
    for label, (start, span) in starts.items():
        tau = np.linspace(0.0, span, 3000)
        sol = solve(
            Problem(se.plane_largest, start, (0.0, span), [m1, -nu, 1.0]),
            "dop853",
            rtol=1e-10,
            atol=1e-12,
            t_eval=tau,
            bound=BLOW_UP_BOUND,
        )
        paths[label] = sol.y_eval[np.all(np.isfinite(sol.y_eval), axis=1) & (np.abs(sol.y_eval[:, 1]) < 4.0)]
    saddle = next(pt["phi2"] for pt in points if pt["type"] == "saddle")
    return Cylinder(m1, nu, theta, F, paths, saddle, center)


def _record_cylinder(results, values: Cylinder):
    """The figure of Lee's Figure 2.13."""
    m1, nu, theta, F = values.m1, values.nu, values.theta, values.F
    fig = bare_figure(figsize=(5.8, 3.2), layout="constrained")  # at most 40 % of a page
    ax = fig.add_subplot(projection="3d")
    ax.plot(np.cos(theta), np.sin(theta), F, color=portrait.LIMIT_CYCLE_COLOUR, lw=1.6, label="$F$ (stable)")
    ax.plot(
        np.cos(theta),
        np.sin(theta),
        -F,
        color=portrait.LIMIT_CYCLE_COLOUR,
        lw=1.6,
        ls="--",
        label="$F_1$ (unstable)",
    )
    for label, y in values.paths.items():
        ax.plot(np.cos(y[:, 0]), np.sin(y[:, 0]), y[:, 1], color=CYLINDER_COLOURS[label], lw=0.7, label=label)
    for phi, marker, label in ((values.saddle, "x", "$S$ (saddle)"), (values.center, "o", "$C$ (center)")):
        ax.scatter([np.cos(phi)], [np.sin(phi)], [0.0], color="k", marker=marker, s=24, label=label)
    ax.set_xticks([-1.0, 0.0, 1.0])
    ax.set_yticks([-1.0, 0.0, 1.0])
    ax.set_zticks([-4.0, -2.0, 0.0, 2.0, 4.0])
    ax.set_xlabel("$\\cos\\varphi_2$", labelpad=-4)
    ax.set_ylabel("$\\sin\\varphi_2$", labelpad=-4)
    ax.set_zlabel("$p_1$", labelpad=-2)
    ax.tick_params(pad=0)
    ax.set_zlim(-4.0, 4.0)
    ax.set_box_aspect((1.0, 1.0, 1.1))
    ax.view_init(elev=18, azim=-60)
    fig.legend(loc="outside right upper")
    results.figure(
        "cylinder",
        fig,
        f"The plane of Lee (2.10) for $m_1$ = {shortest(m1)}, $\\nu$ = {shortest(nu)} "
        "rolled onto the cylinder $(\\cos\\varphi_2, \\sin\\varphi_2, p_1)$, $\\varphi_2$ taken modulo "
        "$2\\pi$, as in Lee's Figure 2.13. The saddles become one saddle $S$ and the centers one center "
        "$C$; $F$ (stable) and $F_1$ (unstable) close on themselves; a start just above $F_1$ winds onto "
        "$F$, one just below it runs away to $p_1 \\to -\\infty$.",
    )
