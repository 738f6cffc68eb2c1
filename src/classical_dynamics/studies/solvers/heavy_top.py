"""The heavy symmetric top (scene heavy_top): the body-frame integration against its closed forms.

Every reference is a closed form of the integrals J3, Jz, E (models/heavy_top.py, Nutation: the roots of the
cubic in cos theta, Jacobi's sn^2 for cos theta(t), the apsidal angle by quadrature), the quadratic of steady
precession (Lamb Art. 54 (8)), Lamb's small-oscillation frequency (Art. 57 (13)) and the roots of the sleeping
top (Art. 79), never the integrator. Runs are DOP853 at the scene's relative tolerance; apses are events
theta' = 0.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...figure_style import PAIR_WIDTH_IN
from ...models import heavy_top as tm
from ...models import rigid_body
from ...provenance import software_stamp
from ...results import new_figure
from ...solvers.ode import Events, Problem, solve
from ...solvers.timing import min_time


def _run(top, y0, T, rtol, t_eval=None, events=True, record=False):
    return solve(
        Problem(top.rhs, y0, (0.0, T), top.params),
        "dop853",
        rtol=rtol,
        atol=rtol * 1e-3,
        t_eval=t_eval,
        events=Events(tm.apse, tm.APSE_EVENTS_N) if events else None,
        record_steps=record,
    )


def _apses(sol):
    keep = sol.event_t > 1e-9  # the start itself may sit at an apse
    return sol.event_t[keep], sol.event_y[keep]


def _half_period(times):
    """Least-squares spacing of successive apse times (half a nutation period)."""
    return float(np.polyfit(np.arange(times.size), times, 1)[0])


def run(scene, results, quick):
    body = scene.data["top"]
    numerics = scene.data.get("numerics", {})
    couple = tm.EFFECTS.assemble(scene.data.get("effects") or {}, None)  # the model is the listed effects
    top = tm.Top(float(body["A"]), float(body["C"]), couple["gravity"])  # check() requires it
    rtol = float(numerics.get("rtol", 1e-12))
    nutations = int(body.get("nutations", 200)) // (10 if quick else 1)
    n, alpha = float(body["spin"]), np.radians(body["inclination_deg"])
    results.number("A", top.A, "1")
    results.number("C", top.C, "1")
    results.number("Mgh", top.Mgh, "1")
    _record_general(results, general(top, n, alpha, nutations, rtol))
    _record_steady(results, steady(top, n, rtol))
    _record_roots_limits(results, roots_limits(top))
    _record_gyroscope(results, gyroscope(top, rtol))
    _record_oscillation(results, oscillation(top, rtol))
    _record_sleeping(results, sleeping(top, rtol, quick))
    _record_descent(results, descent(top, rtol))
    _record_reciprocal(results, reciprocal(top, n, alpha))
    _record_work_precision(results, work_precision(top, n, alpha, numerics, quick))


class Reciprocal(NamedTuple):
    tau: float
    d_theta: float  # per unit impulsive couple about the vertical
    d_psi_reversed: float  # azimuth change in the reversed motion per unit couple in the plane of theta
    relative_difference: float
    unreversed_relative_difference: float  # the same couple on the forward motion: no reciprocity
    energy_check: float  # the Euler-angle run's relative energy change


def reciprocal(top, n, alpha, tau=3.0, impulse=1e-6) -> Reciprocal:
    """Lamb's reciprocal theorem (Art. 107, Ex. 3): an impulsive couple about the vertical (p_phi += J)
    changes the inclination after tau by d theta; in the reversed motion (every velocity, the spin too,
    reversed) an equal couple in the plane of theta (p_theta += J) changes the azimuth after tau by d phi = d
    theta. Canonical equations in Euler angles (theta, azimuth phi, spin angle psi), scipy's DOP853, central
    differences of two runs each: independent of the body-frame model and of the compiled integrators."""
    params = np.array([top.A, top.C, top.Mgh])
    A, C, Mgh = top.A, top.C, top.Mgh

    def flow(z):
        return solve(
            Problem(rigid_body.heavy_top_euler_angles, z, (0.0, tau), params),
            "scipy:DOP853",
            rtol=1e-13,
            atol=1e-15,
        ).y

    p_ps = C * n
    z0 = np.array([alpha, 0.0, 0.0, A * 0.3, A * np.sin(alpha) ** 2 * 0.5 + p_ps * np.cos(alpha), p_ps])
    kick_azimuth, kick_plane = np.eye(6)[4] * impulse, np.eye(6)[3] * impulse
    d_theta = (flow(z0 + kick_azimuth)[0] - flow(z0 - kick_azimuth)[0]) / 2
    end = flow(z0)
    reversed_start = np.concatenate([end[:3], -end[3:]])
    d_phi = (flow(reversed_start + kick_plane)[1] - flow(reversed_start - kick_plane)[1]) / 2
    d_phi_forward = (flow(z0 + kick_plane)[1] - flow(z0 - kick_plane)[1]) / 2
    energy = lambda z: (
        z[3] ** 2 / (2 * A)
        + (z[4] - z[5] * np.cos(z[0])) ** 2 / (2 * A * np.sin(z[0]) ** 2)
        + z[5] ** 2 / (2 * C)
        + Mgh * np.cos(z[0])
    )
    return Reciprocal(
        tau,
        float(d_theta / impulse),
        float(d_phi / impulse),
        float(abs(d_phi - d_theta) / abs(d_theta)),
        float(abs(d_phi_forward - d_theta) / abs(d_theta)),
        float(abs(energy(end) / energy(z0) - 1)),
    )


def _record_reciprocal(results, values: Reciprocal):
    results.number(
        "reciprocal_d_theta",
        values.d_theta,
        "1/(A n)",
        note=f"$\\delta\\theta$ after $\\tau$ = {values.tau:g} per unit impulsive couple about the vertical",
    )
    results.number(
        "reciprocal_d_psi_reversed",
        values.d_psi_reversed,
        "1/(A n)",
        note="$\\delta\\psi$ (azimuth) after the same time in the reversed motion per unit couple in "
        "the plane of $\\theta$",
    )
    results.number(
        "reciprocal_relative_difference",
        values.relative_difference,
        "1",
        note="central differences, impulse $10^{-6}$, DOP853 at rtol $10^{-13}$",
    )
    results.number(
        "reciprocal_unreversed_relative_difference",
        values.unreversed_relative_difference,
        "1",
        note="the same couple in the plane of $\\theta$ on the forward motion instead: no reciprocity",
    )
    results.number(
        "reciprocal_energy_check",
        values.energy_check,
        "1",
        note="the Euler-angle run's energy change (relative)",
    )


def _general_start(top, n, alpha):
    slow, _ = tm.steady_roots(top.A, top.C * n, top.Mgh, alpha)
    return top.state(alpha, 0.0, 0.3 * slow, n)


class General(NamedTuple):
    nutations: int
    rtol: float
    drift: list  # relative drift of J3, Jz, E over the run, at every step
    rate_error: float  # phi', psi' against their closed forms at theta(t), relative
    theta_min: float  # rad, root u2 of the cubic
    theta_max: float  # rad, root u1
    turning_points_error: float  # the apses' inclinations against the roots, relative
    period: float  # 2K(m)/lambda
    period_error: float  # from the apse times, relative
    apsidal_angle: float  # rad, quadrature between the roots
    apsidal_error: float  # rad, largest over the half nutations
    half_nutations: int
    apses: int
    u1: float  # the roots of the cubic in cos theta (the figure's circles)
    u2: float
    apex: np.ndarray  # (k_x, k_y, k_z) of the figure axis over one turn in azimuth
    pole_span: float  # time of the pole-particle comparison (Lamb Art. 55)
    pole_particle_max_angle: float  # rad
    darboux_axis_max_angle: float  # rad, Lamb Ex. XI.9
    darboux_spin_residual: float  # rad


def general(top, n, alpha, nutations, rtol) -> General:
    """A nutating top, theta' = 0 at the start and phi' at 0.3 of the slow steady rate."""
    y0 = _general_start(top, n, alpha)
    J3, Jz, E = (float(v[0]) for v in top.integrals(y0))
    nut = tm.Nutation.from_integrals(top.A, top.C, top.Mgh, J3, Jz, E)
    T = nutations * nut.period
    sol = _run(top, y0, T, rtol, record=True)
    # the integrals over the whole run, at every step
    drift = [float(np.max(np.abs(v - v[0])) / abs(v[0])) for v in top.integrals(sol.y_steps)]
    # the rates read from the body rates and the vertical, against the closed forms at theta(t)
    phi_dot, psi_dot = tm.rates(top, sol.y_steps)
    u = sol.y_steps[:, 5]
    phi_closed = (Jz - J3 * u) / (top.A * (1 - u * u))
    psi_closed = J3 / top.C - phi_closed * u
    rate_error = max(
        np.max(np.abs(phi_dot - phi_closed)) / np.max(np.abs(phi_closed)),
        np.max(np.abs(psi_dot - psi_closed)) / np.max(np.abs(psi_closed)),
    )
    # the apses: inclinations, times and azimuth advance, against the roots, K(m) and the quadrature
    t_apse, y_apse = _apses(sol)
    theta, phi, _ = tm.angles(np.vstack([y0, y_apse]))
    theta, phi = theta[1:], phi[1:] - phi[0]
    roots = np.arccos([nut.u2, nut.u1])  # smallest and largest inclination
    lower = theta > 0.5 * (roots[0] + roots[1])
    theta_error = max(
        np.max(np.abs(theta[~lower] / roots[0] - 1)), np.max(np.abs(theta[lower] / roots[1] - 1))
    )
    period_error = abs(2 * _half_period(t_apse) / nut.period - 1)
    advance = np.diff(np.concatenate([[0.0], phi]))
    apsidal = nut.apsidal_angle()
    apsidal_error = float(np.max(np.abs(advance - apsidal)))
    # the figure's path of the apex over a first few nutations, one turn in azimuth
    t_fig = np.linspace(0.0, min(T, np.pi / apsidal * nut.period), 1601)
    k = tm.axis_in_space(_run(top, y0, t_fig[-1], rtol, t_eval=t_fig, events=False).y_eval)
    # Lamb Art. 55: the pole as a particle of mass A with the deviating force Cn v, against the full top
    t_cmp = np.linspace(0.0, min(T, 50 * nut.period), 2001)
    full = tm.axis_in_space(_run(top, y0, t_cmp[-1], rtol, t_eval=t_cmp, events=False).y_eval)
    w_space = tm.rotation(0.0, alpha, 0.0) @ y0[:3]
    k0 = full[0]
    particle = solve(
        Problem(
            tm.pole_particle,
            np.concatenate([k0, np.cross(w_space, k0)]),
            (0.0, t_cmp[-1]),
            np.array([top.A, J3, top.Mgh]),
        ),
        "dop853",
        rtol=rtol,
        atol=rtol * 1e-3,
        t_eval=t_cmp,
    )
    kp = particle.y_eval[:, :3]
    angle = np.arctan2(np.linalg.norm(np.cross(full, kp), axis=1), np.sum(full * kp, axis=1))
    # Darboux (Lamb Ex. XI.9): (A, A, C, n) and (A, A, A, Cn/A) keep step; spin angles differ by (C - A) n t/A
    sphere = tm.Top(top.A, top.A, top.Mgh)
    y0s = y0.copy()
    y0s[2] = top.C * n / top.A
    a_run = _run(top, y0, t_cmp[-1], rtol, t_eval=t_cmp, events=False).y_eval
    b_run = _run(sphere, y0s, t_cmp[-1], rtol, t_eval=t_cmp, events=False).y_eval
    ka, kb = tm.axis_in_space(a_run), tm.axis_in_space(b_run)
    axis_angle = np.arctan2(np.linalg.norm(np.cross(ka, kb), axis=1), np.sum(ka * kb, axis=1))
    psi_a, psi_b = tm.angles(a_run)[2], tm.angles(b_run)[2]
    spin_residual = np.abs(psi_b - psi_a - (top.C - top.A) * n * t_cmp / top.A)
    return General(
        nutations,
        rtol,
        drift,
        float(rate_error),
        float(roots[0]),
        float(roots[1]),
        float(theta_error),
        float(nut.period),
        float(period_error),
        float(apsidal),
        apsidal_error,
        int(advance.size),
        int(t_apse.size),
        nut.u1,
        nut.u2,
        k,
        float(t_cmp[-1]),
        float(np.max(angle)),
        float(np.max(axis_angle)),
        float(np.max(spin_residual)),
    )


def _record_general(results, values: General):
    nutations, drift = values.nutations, values.drift
    results.number("nutations", nutations, "1")
    results.number("integrals_J3_drift", drift[0], "1")
    results.number("integrals_Jz_drift", drift[1], "1")
    results.number("integrals_E_drift", drift[2], "1")
    results.number(
        "integrals_max_drift", max(drift), "1", note=f"{nutations} nutations, rtol {values.rtol:g}"
    )
    results.hard_case(
        "top_integrals",
        f"The heavy top over {nutations} nutations (DOP853, relative tolerance "
        "$10^{-12}$): the largest relative drift of $J_3$, $J_z$ and $E$",
        max(drift),
        1e-10,
    )
    results.number(
        "rates_max_relative_difference",
        values.rate_error,
        "1",
        note="phi' and psi' from (omega, gamma) against (Jz - J3 cos)/(A sin^2), J3/C - phi' cos",
    )
    theta_error, period_error = values.turning_points_error, values.period_error
    results.number("theta_min_deg", float(np.degrees(values.theta_min)), "°", note="root u2 of the cubic")
    results.number("theta_max_deg", float(np.degrees(values.theta_max)), "°", note="root u1 of the cubic")
    results.number("turning_points_max_relative_difference", theta_error, "1")
    results.number("nutation_period", values.period, "time units", note="2K(m)/lambda")
    results.number("nutation_period_relative_difference", period_error, "1")
    results.number(
        "turning_points_and_period_max_relative_difference", float(max(theta_error, period_error)), "1"
    )
    results.number("apsidal_angle", values.apsidal_angle, "rad", note="quadrature between the roots")
    results.number(
        "apsidal_angle_max_difference",
        values.apsidal_error,
        "rad",
        note=f"{values.half_nutations} half nutations",
    )
    results.number("apses", values.apses, "1")
    _apex_figure(results, values.apex, values.u1, values.u2)
    results.number(
        "pole_particle_max_angle",
        values.pole_particle_max_angle,
        "rad",
        note=f"{values.pole_span / values.period:.0f} nutations",
    )
    axis_angle, spin_residual = values.darboux_axis_max_angle, values.darboux_spin_residual
    results.number("darboux_axis_max_angle", axis_angle, "rad")
    results.number("darboux_spin_residual", spin_residual, "rad")
    results.number("darboux_max", float(max(axis_angle, spin_residual)), "rad")


def _apex_figure(results, k, u1, u2):
    """The path of the apex seen from above, between the circles of the two roots."""
    fig, ax = new_figure(width=PAIR_WIDTH_IN, height=2.7)  # printed beside its table
    ring = np.linspace(0, 2 * np.pi, 361)
    for u, style, label in ((u2, "--", "$\\theta_1$"), (u1, ":", "$\\theta_2$")):
        r = np.sqrt(1 - u * u)
        ax.plot(r * np.cos(ring), r * np.sin(ring), style, color="0.45", lw=0.8, label=f"circle at {label}")
    ax.plot(k[:, 0], k[:, 1], color="#0072B2", lw=0.9, label="apex (DOP853)")
    ax.set_aspect("equal")
    ax.set_xlabel("$k_x$")
    ax.set_ylabel("$k_y$")
    ax.legend(loc="center", frameon=False)
    results.figure(
        "apex_path",
        fig,
        "The apex of the heavy top seen from above: the horizontal components "
        "$(k_x, k_y)$ of the unit figure axis over one turn in azimuth, integrated in the body "
        "frame, between the circles at the inclinations $\\theta_1$, $\\theta_2$ where "
        "$E = U_\\mathrm{eff}(\\theta)$ (roots of the cubic in $\\cos\\theta$). The path touches the two "
        "circles alternately, advancing by the same azimuth from apse to apse (Lamb 1920, Art. 57).",
    )


class Steady(NamedTuple):
    frame: pd.DataFrame  # per inclination and root: the largest |theta - alpha|, the rate's difference
    conical_rate: float  # the conical pendulum at 120 degrees: sqrt(-Mgh/(A cos alpha))
    conical_theta_deviation: float  # rad
    threshold_spin_60deg: float  # J3^2 = 4 A Mgh cos alpha, as a spin
    roots_exist_just_below: bool  # at 0.999 of the threshold
    conical_roots_exist_above_support: bool  # J3 = 0 at 60 degrees


def steady(top, n, rtol) -> Steady:
    """Steady precession at either root (Lamb Art. 54 (8)), the horizontal gyroscope and the conical
    pendulum."""
    J3 = top.C * n
    rows = []
    for alpha_deg in (30.0, 60.0, 120.0):
        alpha = np.radians(alpha_deg)
        for which, rate in zip(("slow", "fast"), tm.steady_roots(top.A, J3, top.Mgh, alpha)):
            T = 10 * 2 * np.pi / abs(rate)  # ten turns of the precession
            sol = _run(top, top.state(alpha, 0.0, rate, n), T, rtol, record=True, events=False)
            theta, phi, _ = tm.angles(sol.y_steps)
            rows.append(
                {
                    "alpha_deg": alpha_deg,
                    "root": which,
                    "rate": rate,
                    "theta_deviation": float(np.max(np.abs(theta - alpha))),
                    "rate_relative_difference": float(abs(phi[-1] / T / rate - 1)),
                }
            )
    # the conical pendulum: no spin, hanging below the support at 120 degrees
    alpha = np.radians(120.0)
    rate = np.sqrt(-top.Mgh / (top.A * np.cos(alpha)))
    T = 10 * 2 * np.pi / rate
    sol = _run(top, top.state(alpha, 0.0, rate, 0.0), T, rtol, record=True, events=False)
    theta, phi, _ = tm.angles(sol.y_steps)
    conical = float(np.max(np.abs(theta - alpha)))
    # below the threshold J3^2 = 4 A Mgh cos alpha no steady state exists: the discriminant
    alpha = np.radians(60.0)
    spin_threshold = np.sqrt(4 * top.A * top.Mgh * np.cos(alpha)) / top.C
    return Steady(
        pd.DataFrame(rows),
        float(rate),
        conical,
        float(spin_threshold),
        tm.steady_roots(top.A, 0.999 * top.C * spin_threshold, top.Mgh, alpha) is not None,
        tm.steady_roots(top.A, 0.0, top.Mgh, np.radians(60.0)) is not None,
    )


def _record_steady(results, values: Steady):
    frame = values.frame
    results.table(
        "steady_precession",
        frame,
        "Steady precession of the heavy top started at either root of "
        "$A\\omega^2\\cos\\alpha - Cn\\omega + Mgh = 0$, ten turns: the largest departure of $\\theta$ from "
        "$\\alpha$ and the relative difference of the measured mean rate from the root.",
        headers={
            "alpha_deg": "$\\alpha$ (°)",
            "root": "root",
            "rate": "$\\dot\\varphi$ (per time unit)",
            "theta_deviation": "largest $|\\theta - \\alpha|$ (rad)",
            "rate_relative_difference": "rate, relative difference",
        },
    )
    results.number(
        "steady_theta_max_deviation",
        float(frame.theta_deviation.max()),
        "rad",
        note="both roots at 30, 60, 120 degrees",
    )
    results.number("steady_rate_max_relative_difference", float(frame.rate_relative_difference.max()), "1")
    results.number("conical_pendulum_rate", values.conical_rate, "1/time", note="sqrt(-Mgh/(A cos 120 deg))")
    results.number("conical_pendulum_theta_deviation", values.conical_theta_deviation, "rad")
    results.number("steady_threshold_spin_60deg", values.threshold_spin_60deg, "1/time")
    results.number("steady_roots_exist_just_below", values.roots_exist_just_below, "bool")
    results.number(
        "conical_roots_exist_above_support",
        values.conical_roots_exist_above_support,
        "bool",
        note="J3 = 0, cos theta > 0: no real root",
    )


class RootsLimits(NamedTuple):
    slow_slope: float  # log |slow/(Mgh/J3) - 1| against log J3
    fast_slope: float  # log |fast/(J3/(A cos alpha)) - 1| against log J3
    slow_difference_at_10: float  # J3^2/(4 A Mgh cos alpha) = 10
    fast_difference_at_10: float
    fast_free_difference: float  # Mgh = 0


def roots_limits(top) -> RootsLimits:
    """The slow and fast roots against Mgh/J3 and J3/(A cos alpha) as the spin grows (Lamb Art. 55)."""
    alpha = np.radians(60.0)
    ratio = np.geomspace(10.0, 1e4, 7)  # J3^2 / (4 A Mgh cos alpha)
    J3 = np.sqrt(4 * top.A * top.Mgh * np.cos(alpha) * ratio)
    slow = np.array([tm.steady_roots(top.A, j, top.Mgh, alpha)[0] for j in J3])
    fast = np.array([tm.steady_roots(top.A, j, top.Mgh, alpha)[1] for j in J3])
    d_slow = np.abs(slow / (top.Mgh / J3) - 1)
    d_fast = np.abs(fast / (J3 / (top.A * np.cos(alpha))) - 1)
    free = tm.steady_roots(top.A, 1.0, 0.0, alpha)[1]
    return RootsLimits(
        float(np.polyfit(np.log(J3), np.log(d_slow), 1)[0]),
        float(np.polyfit(np.log(J3), np.log(d_fast), 1)[0]),
        float(d_slow[0]),
        float(d_fast[0]),
        float(abs(free / (1.0 / (top.A * np.cos(alpha))) - 1)),
    )


def _record_roots_limits(results, values: RootsLimits):
    results.number(
        "slow_root_slope",
        values.slow_slope,
        "1",
        note="log |slow/(Mgh/J3) - 1| against log J3, J3^2/(4 A Mgh cos a) from 10 to 10^4",
    )
    results.number("fast_root_slope", values.fast_slope, "1")
    results.number("slow_root_difference_at_10", values.slow_difference_at_10, "1")
    results.number("fast_root_difference_at_10", values.fast_difference_at_10, "1")
    results.number("fast_root_free_difference", values.fast_free_difference, "1", note="Mgh = 0")


class Gyroscope(NamedTuple):
    J3: float  # J3^2/(A Mgh) = 100
    rate_measured: float  # mean precession rate over five turns
    rate_relative_difference: float  # against Mgh/J3
    theta_deviation: float  # rad, from the horizontal
    nutation_frequency: float  # measured from the apses of a disturbed run
    nutation_vs_J3_over_A: float  # relative
    nutation_vs_sigma: float  # relative, Lamb Art. 57 (13)


def gyroscope(top, rtol) -> Gyroscope:
    """The horizontal gyroscope, J3^2/(A Mgh) = 100: steady at Mgh/J3, and its nutation when disturbed."""
    J3 = 10.0 * np.sqrt(top.A * top.Mgh)
    n = J3 / top.C
    rate = top.Mgh / J3
    T = 5 * 2 * np.pi / rate
    sol = _run(top, top.state(np.pi / 2, 0.0, rate, n), T, rtol, events=False, record=True)
    theta, phi, _ = tm.angles(sol.y_steps)
    sigma = tm.nutation_frequency(top.A, J3, np.pi / 2, rate)
    eps = 1e-4
    sol_disturbed = _run(top, top.state(np.pi / 2, eps * sigma, rate, n), 40 * 2 * np.pi / sigma, rtol)
    measured = np.pi / _half_period(_apses(sol_disturbed)[0])
    return Gyroscope(
        float(J3),
        float(phi[-1] / T),
        float(abs(phi[-1] / T / rate - 1)),
        float(np.max(np.abs(theta - np.pi / 2))),
        float(measured),
        float(measured / (J3 / top.A) - 1),
        float(measured / sigma - 1),
    )


def _record_gyroscope(results, values: Gyroscope):
    results.number("gyroscope_J3", values.J3, "1")
    results.number("gyroscope_rate_measured", values.rate_measured, "1/time", note="mean over five turns")
    results.number(
        "gyroscope_rate_relative_difference",
        values.rate_relative_difference,
        "1",
        note="measured mean rate over five turns against Mgh/J3",
    )
    results.number("gyroscope_theta_deviation", values.theta_deviation, "rad")
    results.number("gyroscope_nutation_frequency", values.nutation_frequency, "1/time")
    results.number(
        "gyroscope_nutation_vs_J3_over_A", values.nutation_vs_J3_over_A, "1", note="J3^2/(A Mgh) = 100"
    )
    results.number("gyroscope_nutation_vs_sigma", values.nutation_vs_sigma, "1")


def oscillation(top, rtol) -> pd.DataFrame:
    """Lamb Art. 57 (13): a steady precession disturbed by theta' = 1e-4 sigma nutates at sigma. One row per
    inclination and root: sigma, the frequency measured from the apses and their relative difference."""
    n = 6.0
    J3 = top.C * n
    rows = []
    for alpha_deg in (30.0, 60.0, 120.0):
        alpha = np.radians(alpha_deg)
        for which, rate in zip(("slow", "fast"), tm.steady_roots(top.A, J3, top.Mgh, alpha)):
            sigma = tm.nutation_frequency(top.A, J3, alpha, rate)
            sol = _run(top, top.state(alpha, 1e-4 * sigma, rate, n), 40 * 2 * np.pi / sigma, rtol)
            measured = np.pi / _half_period(_apses(sol)[0])
            rows.append(
                {
                    "alpha_deg": alpha_deg,
                    "root": which,
                    "sigma": sigma,
                    "measured": measured,
                    "relative_difference": measured / sigma - 1,
                }
            )
    return pd.DataFrame(rows)


def _record_oscillation(results, frame: pd.DataFrame):
    results.table(
        "nutation_frequency",
        frame,
        "Nutation of a disturbed steady precession ($\\dot\\theta_0 = "
        "10^{-4}\\sigma$): the frequency measured from 80 apses against Lamb's $\\sigma$, Art. 57 (13).",
        headers={
            "alpha_deg": "$\\alpha$ (°)",
            "root": "root",
            "sigma": "$\\sigma$ (per time unit)",
            "measured": "measured (per time unit)",
            "relative_difference": "relative difference",
        },
    )
    results.number(
        "nutation_sigma_max_relative_difference", float(frame.relative_difference.abs().max()), "1"
    )


class Sleeping(NamedTuple):
    theta0: float  # rad, the start's tilt from the vertical, at rest
    spin_periods: int
    above_largest_tilt: float  # rad, nu^2/4AMgh = 1.01
    above_linear_bound: float  # rad, theta0 nu / sqrt(nu^2 - 4AMgh)
    below_largest_tilt: float  # rad, nu^2/4AMgh = 0.99
    below_root: float  # rad, the outer root of the cubic in cos theta there
    upright_sigma_exact: np.ndarray  # [nu -+ sqrt(nu^2 - 4AMgh)]/2A at nu^2/4AMgh = 4
    upright_sigma_fitted: np.ndarray  # the two frequencies fitted to a small-tilt run
    upright_ellipse_period_closed_form: float  # 4 pi A/sqrt(nu^2 - 4AMgh)


def sleeping(top, rtol, quick) -> Sleeping:
    """The sleeping top (Lamb Art. 79): nu = Cn against 4 A Mgh, started 1e-4 rad from the vertical at
    rest."""
    theta0 = 1e-4
    spin_periods = 100 if quick else 1000
    out = {}
    for s in (1.01, 0.99):
        nu = np.sqrt(4 * top.A * top.Mgh * s)
        n = nu / top.C
        T = spin_periods * 2 * np.pi / n
        t = np.linspace(0, T, 20001)
        sol = _run(top, top.state(theta0, 0.0, 0.0, n), T, rtol, t_eval=t)
        tilt = tm.angles(sol.y_eval)[0]
        apse_tilt = tm.angles(_apses(sol)[1])[0] if _apses(sol)[0].size else tilt
        out[s] = (nu, max(np.max(tilt), np.max(apse_tilt)))
    # below the threshold the tilt is bounded all the same, by the outer root of the cubic in cos theta (the
    # roots crowd within 10^-8 of 1 above the threshold, where the linear bound serves instead)
    J3, Jz, E = (float(v[0]) for v in top.integrals(top.state(theta0, 0.0, 0.0, out[0.99][0] / top.C)))
    below_root = float(np.arccos(tm.Nutation.from_integrals(top.A, top.C, top.Mgh, J3, Jz, E).u1))
    nu, largest = out[1.01]
    bound = theta0 * nu / np.sqrt(nu * nu - 4 * top.A * top.Mgh)
    # Art. 58 / 79: the two circular frequencies of a small-tilt run, nu^2/4AMgh = 4
    nu = np.sqrt(16 * top.A * top.Mgh)
    n = nu / top.C
    root = np.sqrt(nu * nu - 4 * top.A * top.Mgh)
    exact = np.array([(nu - root) / (2 * top.A), (nu + root) / (2 * top.A)])
    dt = 0.05
    t = np.arange(0, 4000) * dt
    y = _run(
        top, top.state(theta0, 0.3 * theta0 * exact[0], 0.0, n), t[-1], rtol, t_eval=t, events=False
    ).y_eval
    k = tm.axis_in_space(y)
    z = k[:, 0] + 1j * k[:, 1]
    # two exponentials: z[j + 2] = c1 z[j + 1] + c0 z[j] by least squares, roots exp(i sigma dt)
    M = np.stack([z[1:-1], z[:-2]], axis=1)
    c = np.linalg.lstsq(M, z[2:], rcond=None)[0]
    fitted = np.sort(np.abs(np.angle(np.roots([1.0, -c[0], -c[1]])) / dt))
    return Sleeping(
        theta0,
        spin_periods,
        largest,
        bound,
        out[0.99][1],
        below_root,
        exact,
        fitted,
        4 * np.pi * top.A / root,
    )


def _record_sleeping(results, values: Sleeping):
    theta0, spin_periods = values.theta0, values.spin_periods
    largest, bound, below = values.above_largest_tilt, values.above_linear_bound, values.below_largest_tilt
    results.number("sleeping_above_largest_tilt", float(largest), "rad", note="nu^2/4AMgh = 1.01")
    results.number("sleeping_above_linear_bound", float(bound), "rad", note="theta0 nu / sqrt(nu^2 - 4AMgh)")
    results.number("sleeping_above_ratio_to_bound", float(largest / bound), "1")
    results.number("sleeping_above_ratio_to_start", float(largest / theta0), "1")
    results.number("sleeping_below_largest_tilt_deg", float(np.degrees(below)), "°", note="nu^2/4AMgh = 0.99")
    results.number(
        "sleeping_below_root_deg",
        float(np.degrees(values.below_root)),
        "°",
        note="the outer root of the cubic in cos theta",
    )
    results.number("sleeping_spin_periods", spin_periods, "1")
    results.number("sleeping_start_tilt", theta0, "rad")
    results.number("sleeping_ratio_above", 1.01, "1", note="nu^2/4AMgh")
    results.number("sleeping_ratio_below", 0.99, "1", note="nu^2/4AMgh")
    results.hard_case(
        "sleeping_top_above",
        "The sleeping top at $\\nu^2/4AMgh = 1.01$, started $10^{-4}$ rad "
        f"from the vertical, over {spin_periods} spin periods: largest tilt against the linear bound "
        "$\\theta_0\\nu/\\sqrt{\\nu^2 - 4AMgh}$ (relative difference)",
        largest / bound - 1,
        1e-3,
    )
    results.hard_case(
        "sleeping_top_below",
        "The sleeping top at $\\nu^2/4AMgh = 0.99$, started $10^{-4}$ rad from the vertical: 10° over the "
        "largest tilt (the top falls away from the vertical)",
        np.radians(10.0) / below,
        1.0,
    )
    exact, fitted = values.upright_sigma_exact, values.upright_sigma_fitted
    results.number("upright_sigma_exact", exact.tolist(), "1/time", note="[nu -+ sqrt(nu^2 - 4AMgh)]/2A")
    results.number("upright_sigma_fitted", fitted.tolist(), "1/time")
    results.number("upright_sigma_max_relative_difference", float(np.max(np.abs(fitted / exact - 1))), "1")
    results.number(
        "upright_revolving_rate", float(fitted.mean()), "1/time", note="(sigma1 + sigma2)/2 = nu/2A"
    )
    results.number(
        "upright_ellipse_period",
        float(4 * np.pi / (fitted[1] - fitted[0])),
        "time units",
        note="4 pi/(sigma2 - sigma1) = 4 pi A/sqrt(nu^2 - 4AMgh)",
    )
    results.number(
        "upright_ellipse_period_closed_form", float(values.upright_ellipse_period_closed_form), "time units"
    )


class Descent(NamedTuple):
    frame: pd.DataFrame  # per A Mgh/C^2 n^2: the descent measured, Lamb's, the root's, their difference
    slope: float  # log |descent/Lamb - 1| against log n


def descent(top, rtol) -> Descent:
    """Lamb Ex. XI.8: released at rest at alpha, the axis descends through about 2 A Mgh sin alpha / C^2
    n^2."""
    alpha = np.radians(60.0)
    small = np.geomspace(1e-2, 1e-4, 5)  # A Mgh / C^2 n^2
    rows = []
    for s in small:
        n = np.sqrt(top.A * top.Mgh / s) / top.C
        y0 = top.state(alpha, 0.0, 0.0, n)
        J3, Jz, E = (float(v[0]) for v in top.integrals(y0))
        nut = tm.Nutation.from_integrals(top.A, top.C, top.Mgh, J3, Jz, E)
        sol = _run(top, y0, 10 * nut.period, rtol)
        theta = tm.angles(_apses(sol)[1])[0]
        drop = float(np.max(theta) - alpha)  # not `descent`, the function's own name
        lamb = 2 * s * np.sin(alpha)
        rows.append(
            {
                "AMgh_over_C2n2": s,
                "descent": drop,
                "lamb": lamb,
                "exact": float(np.arccos(nut.u1) - alpha),
                "relative_difference": drop / lamb - 1,
            }
        )
    frame = pd.DataFrame(rows)
    slope = np.polyfit(
        np.log(np.sqrt(1 / frame.AMgh_over_C2n2)), np.log(np.abs(frame.relative_difference)), 1
    )[0]
    return Descent(frame, float(slope))


def _record_descent(results, values: Descent):
    frame = values.frame
    results.number("descent_slope", values.slope, "1", note="log |descent/Lamb - 1| against log n")
    results.number("descent_relative_difference_fastest", float(frame.relative_difference.iloc[-1]), "1")
    results.number(
        "descent_vs_root_max_relative", float(np.max(np.abs(frame.descent / frame.exact - 1))), "1"
    )


def work_precision(top, n, alpha, numerics, quick) -> pd.DataFrame:
    """DOP853 and DOPRI5 against scipy's over 20 nutations: error in cos theta against Jacobi's sn^2. One row
    per method and relative tolerance: the error, steps, evaluations, drift of Jz and E, and the wall time."""
    y0 = _general_start(top, n, alpha)
    J3, Jz, E = (float(v[0]) for v in top.integrals(y0))
    nut = tm.Nutation.from_integrals(top.A, top.C, top.Mgh, J3, Jz, E)
    T = 20 * nut.period
    t = np.linspace(0, T, 100)
    exact = nut.cos_theta(t, y0[5])
    problem = Problem(top.rhs, y0, (0.0, T), top.params)
    rows = []
    for method in numerics.get("methods", ["dop853", "scipy:DOP853", "scipy:RK45"]):
        for rtol in numerics.get("tolerances", [1e-6, 1e-9, 1e-12]):
            if quick and rtol < 1e-9:
                continue
            seconds, _, runs = min_time(
                lambda: solve(problem, method, rtol=rtol, atol=rtol * 1e-3),
                repeats=2 if quick else int(numerics.get("repeats", 5)),
                budget_s=1.0,
            )
            sol = solve(problem, method, rtol=rtol, atol=rtol * 1e-3, t_eval=t)
            steps = solve(problem, method, rtol=rtol, atol=rtol * 1e-3, record_steps=True)
            # np.max over all: a NaN comes through (max() drops one that is not first)
            drift = float(
                np.max([np.max(np.abs(v - v[0])) / abs(v[0]) for v in top.integrals(steps.y_steps)[1:]])
            )
            rows.append(
                {
                    "method": method,
                    "rtol": rtol,
                    "error": float(np.max(np.abs(sol.y_eval[:, 5] - exact))),
                    "steps": int(steps.n_steps),
                    "evaluations": int(steps.nfev),
                    "drift": drift,
                    "seconds": seconds,
                    "runs": runs,
                }
            )
    return pd.DataFrame(rows)


def _record_work_precision(results, frame: pd.DataFrame):
    headers = {
        "method": "method",
        "rtol": "rtol",
        "error": "error in $\\cos\\theta$",
        "steps": "steps",
        "evaluations": "evaluations",
        "drift": "drift of $J_z$, $E$",
        "seconds": "wall time (s)",
        "runs": "runs timed",
    }
    results.timing_table(
        "top_work_precision",
        frame,
        "The heavy top over 20 nutations, by method and relative tolerance: the largest error of "
        "$\\cos\\theta$ on 100 points against Jacobi's $\\mathrm{sn}^2$, the steps taken and the wall "
        f"time (minimum over repeated runs). {software_stamp()}.",
        headers=headers,
    )
    accuracy = frame.drop(columns=["seconds", "runs"])
    results.table(
        "top_accuracy",
        accuracy,
        "The heavy top over 20 nutations: the largest error of $\\cos\\theta$ "
        "on 100 points against Jacobi's $\\mathrm{sn}^2$, by method and relative tolerance.",
        headers=headers,
    )
    for method in ("dop853", "scipy:DOP853", "scipy:RK45"):
        part = frame[frame.method == method]
        if len(part):
            tight = part[part.rtol == part.rtol.min()].iloc[0]
            key = method.replace(":", "_").lower()
            results.number(
                f"top_{key}_error_at_tightest", float(tight.error), "1", note=f"rtol {tight.rtol:g}"
            )
            results.number(f"top_{key}_steps_at_tightest", int(tight.steps), "steps")
