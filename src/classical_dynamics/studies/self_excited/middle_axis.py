"""Torque along the middle axis (Lee §3), the case |k1| > |k2| (|mu| below mu_c): a single center.

The end of omega moves on a hyperbolic cylinder p^2/a - r^2/c = const; the plane (3.12) with eps1 = -1
has one singular point, a center at phi2 = arcsinh(m1), and Lee shows every trajectory closes: every
motion is periodic, unperturbed or with nu below nu_c = b/(2(a + c)). The portrait checks it, with
Euler's equations overlaid, and the period series (4.13).
"""

from __future__ import annotations

import numpy as np

from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from ..results import new_figure
from . import portrait
from .largest_axis import OVERLAY_BOUND

AMPLITUDES = (0.4, 0.2, 0.1, 0.05)


def run(scene, results, quick):
    data = scene.data
    body = se.Body.from_moments(data["body"]["moments"])
    plane = data["plane"]
    m1, nu = float(plane["m1"]), float(plane["nu"])
    alpha1, alpha2 = (float(x) for x in plane["alpha"])
    M = se.MiddleAxis.with_plane_parameters(body, m1, -nu, alpha1, alpha2)
    lo, hi = data.get("portrait", {}).get("phi2_range", [-4.0, 4.0])
    q1_max = data.get("portrait", {}).get("p1_max", 3.0)
    eps1 = M.eps1
    results.number("m1", m1, "1", note=plane.get("source", "chosen to show the regime"))
    results.number("nu", nu, "1", note="mu1 = −nu")
    results.number("nu_c", se.MiddleAxis.mu_c(body) / (2 * np.sqrt(body.a * body.c)), "1",
                   note="b/(2(a + c)): above it the cosh form of (3.56) takes over")
    results.number("M_over_B", M.m, "1/time²", note="the constant torque per unit B that gives m1 here")
    results.number("mu0_over_B", M.mu, "1")
    results.number("hyperbola", alpha1**2 - alpha2**2, "1", note="p²/a − r²/c = α1² − α2²")
    center = float(np.arcsinh(m1))
    points = [{"phi2": center, "p1": 0.0, "type": "center"}]
    results.number("singular_points", points, "1", note="q1 = 0, sinh φ2 = m1: one center")
    results.number("n_centers", 1, "1")

    fig, ax = new_figure(6.4, 4.2)
    starts = [(center + s_, 0.0) for s_ in (0.3, 0.8, 1.4, 2.0, 2.6)]
    curves = portrait.trajectories(se.plane_middle, lambda d: [m1, -nu, eps1, d], starts, 30.0)
    closed = 0
    for y in curves:
        ax.plot(y[:, 0], y[:, 1], color="0.55", lw=0.6)
    for phi, q1 in starts:                          # Lee: every trajectory closes; each must turn back twice
        sol = solve(Problem(se.plane_middle, [phi, q1], (0.0, 200.0), [m1, -nu, eps1, 1.0]), "dop853", rtol=1e-12,
                    atol=1e-14, events=Events(portrait.velocity_zero, 1, (-1,)), bound=portrait.BLOW_UP_BOUND)
        closed += len(sol.event_t) >= 2
    results.hard_case("all_orbits_closed", "Starts around the center whose orbit does not close (count; Lee: every "
                      "motion is periodic for |μ| < μ_c)", len(starts) - closed, 0)
    deviation, hyp = _overlay(ax, M, m1, nu, starts[1:4])
    results.number("overlay_deviation", deviation, "1", note="Euler's equations in the plane against (3.12), max")
    results.hard_case("overlay", "Full integrations of Euler's equations, mapped into the plane, on the plane's "
                      "trajectories (max deviation in (φ2, q1))", deviation, OVERLAY_BOUND)
    results.hard_case("hyperbolic_cylinder", "The end of ω stays on its hyperbolic cylinder (relative spread of "
                      "p²/a − r²/c)", hyp, 1e-10)
    portrait.finish(ax, points, (lo, hi), q1_max, "q1")
    regime = f"m1 = {m1:g}" + (f", ν = {nu:g}" if nu else ", unperturbed")
    results.figure("portrait", fig, f"Phase plane of Lee's (3.12) for the torque along the middle axis, {regime}: "
                   "one center, every trajectory closed (grey), and Euler's equations mapped into the plane (dots).")
    _series(results, m1, nu, eps1, center)


def _overlay(ax, M, m1, nu, starts):
    worst, hyp_worst = 0.0, 0.0
    for k, (phi, q1) in enumerate(starts):
        tau = np.linspace(0.0, 12.0, 241)
        full = solve(Problem(se.euler_middle, M.from_plane(phi, q1), (0.0, tau[-1] / M.time_scale),
                             M.euler_parameters()), "dop853", rtol=1e-13, atol=1e-15, t_eval=tau / M.time_scale)
        flat = solve(Problem(se.plane_middle, [phi, q1], (0.0, tau[-1]), [m1, -nu, M.eps1, 1.0]), "dop853",
                     rtol=1e-13, atol=1e-15, t_eval=tau)
        mapped = M.to_plane(full.y_eval)
        worst = max(worst, float(np.max(np.abs(mapped - flat.y_eval) / np.maximum(1.0, np.abs(flat.y_eval)))))
        h = se.hyperbola(M.body, full.y_eval)
        hyp_worst = max(hyp_worst, float(np.ptp(h) / abs(h[0])))
        ax.plot(mapped[::5, 0], mapped[::5, 1], ".", color="C2", ms=3,
                label="Euler's equations, mapped" if k == 0 else None)
    return worst, hyp_worst


def _series(results, m1, nu, eps1, center):
    portrait.series_check(
        results, lambda eta: portrait.period(se.plane_middle, [m1, -nu, eps1, 1.0], [center + eta, 0.0]),
        lambda eta: se.middle_series_period(m1, nu, eta), AMPLITUDES,
        "Lee (4.13): the period (in τ) about the center started at φ2c + η, measured and from the series "
        "2π(1 + m1²)^(−1/4)(1 + h2η² + h3η³).")
