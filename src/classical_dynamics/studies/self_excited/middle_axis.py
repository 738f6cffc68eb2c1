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
    cosh = M.cosh_form
    name = "m2" if cosh else "m1"
    results.number("m1", m1, "1", note=f"{name} of the plane: " + plane.get("source", "chosen to show the regime"))
    results.number("nu", nu, "1", note="mu1 = −nu")
    results.number("nu_c", se.MiddleAxis.mu_c(body) / (2 * np.sqrt(body.a * body.c)), "1",
                   note="b/(2(a + c)): above it the cosh form (3.56) takes over")
    results.number("cosh_form", int(cosh), "1", note="1: |k2| > |k1|, Lee (3.56); 0: |k1| > |k2|, (3.12)")
    results.number("M_over_B", M.m, "1/time²", note=f"the constant torque per unit B that gives {name} here")
    results.number("mu0_over_B", M.mu, "1")
    results.number("hyperbola", alpha1**2 - alpha2**2, "1", note="p²/a − r²/c = α1² − α2²")
    points = _singular_points(m1, cosh)
    results.number("singular_points", points, "1", note=f"q1 = 0, {'cosh' if cosh else 'sinh'} φ2 = {name}")
    for kind in ("saddle", "center", "degenerate"):
        results.number(f"n_{kind}s", sum(pt["type"] == kind for pt in points), "1")

    fig, ax = new_figure(6.4, 4.2)
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    if cosh:                                        # inside the saddle's loop: between the saddle and the center
        span = centers[0] - points[0]["phi2"]
        starts = [(centers[0] - f * span, 0.0) for f in (0.2, 0.5, 0.8)]
    else:
        starts = [(centers[0] + s_, 0.0) for s_ in (0.3, 0.8, 1.4, 2.0, 2.6)]
    others = [(lo + 0.3, v) for v in (-2.0, -1.0, 1.0, 2.0)] + [(0.5 * (lo + hi), 2.0)] if cosh else []
    for y in portrait.trajectories(se.plane_middle, M.plane_parameters, starts + others, 30.0):
        ax.plot(y[:, 0], y[:, 1], color="0.55", lw=0.6)
    closed = 0
    for phi, q1 in starts:                          # orbits about the center close; each turns back twice
        sol = solve(Problem(se.plane_middle, [phi, q1], (0.0, 200.0), M.plane_parameters()), "dop853", rtol=1e-12,
                    atol=1e-14, events=Events(portrait.velocity_zero, 1, (-1,)), bound=portrait.BLOW_UP_BOUND)
        closed += len(sol.event_t) >= 2
    results.hard_case("orbits_about_the_center_closed", "Starts about the center whose orbit does not close (count; "
                      "Lee: every motion periodic for |μ| < μ_c; inside the saddle's loop above it)",
                      len(starts) - closed, 0)
    if cosh:
        _third_kind(results, ax, M, points, lo, hi)
    deviation, hyp = _overlay(ax, M, starts[:3] + others[:1])
    results.number("overlay_deviation", deviation, "1", note="Euler's equations in the plane against the plane, max")
    results.hard_case("overlay", "Full integrations of Euler's equations, mapped into the plane, on the plane's "
                      "trajectories (max deviation in (φ2, q1))", deviation, OVERLAY_BOUND)
    results.hard_case("hyperbolic_cylinder", "The end of ω stays on its hyperbolic cylinder (relative spread of "
                      "p²/a − r²/c)", hyp, 1e-10)
    portrait.finish(ax, points, (lo, hi), q1_max, "q1")
    regime = f"{name} = {m1:g}" + (f", ν = {nu:g}" if nu else ", unperturbed")
    shape = ("a saddle whose loop holds the periodic motions, and outside it motions of the third kind that leave "
             "every bound in finite time" if cosh else "one center, every trajectory closed")
    results.figure("portrait", fig, f"Phase plane of Lee's {'(3.56)' if cosh else '(3.12)'} for the torque along the "
                   f"middle axis, {regime}: {shape} (grey), and Euler's equations mapped into the plane (dots).")
    _series(results, m1, nu, M.eps1, centers[0], cosh)


def _singular_points(m, cosh):
    if not cosh:
        return [{"phi2": float(np.arcsinh(m)), "p1": 0.0, "type": "center"}]
    if m < 1.0:
        return []
    x = float(np.arccosh(m))                       # d(q1')/dphi2 = -sinh(phi2): a saddle left, a center right
    return [{"phi2": -x, "p1": 0.0, "type": "saddle"}, {"phi2": x, "p1": 0.0, "type": "center"}]


def _third_kind(results, ax, M, points, lo, hi):
    """Above mu_c: the separatrix through the saddle from (3.19), and a start outside it that blows up."""
    saddle = [pt["phi2"] for pt in points if pt["type"] == "saddle"][0]
    m2, mu1, eps = M.m1, M.mu1, M.eps1
    g = lambda x: -m2 / mu1 + 2 * eps * (np.sinh(x) + 2 * mu1 * np.cosh(x)) / (1 - 4 * mu1**2)   # noqa: E731
    C = -g(saddle) * np.exp(-2 * mu1 * saddle)
    phi = np.linspace(lo, hi, 3001)
    sq = C * np.exp(2 * mu1 * phi) + g(phi)
    for sign in (1, -1):
        ax.plot(phi, np.where(sq >= 0, sign * np.sqrt(np.maximum(sq, 0.0)), np.nan), "k-", lw=1.1,
                label="separatrix (closed form)" if sign == 1 else None)
    sol = solve(Problem(se.plane_middle, [saddle - 0.3, 0.0], (0.0, 200.0), M.plane_parameters()), "dop853",
                rtol=1e-12, atol=1e-14, bound=portrait.BLOW_UP_BOUND)
    if sol.status == "blow-up":
        results.number("blow_up_time", sol.t, "τ", note="a start just left of the saddle: a motion of the third kind "
                       f"(|y| passes {portrait.BLOW_UP_BOUND:g})")
    results.hard_case("third_kind_blows_up", "A start outside the saddle's loop leaves every bound in finite time "
                      "(1 if it does not)", 0.0 if sol.status == "blow-up" else 1.0, 0.0)


def _overlay(ax, M, starts):
    worst, hyp_worst = 0.0, 0.0
    for k, (phi, q1) in enumerate(starts):
        tau = np.linspace(0.0, 12.0, 241)
        full = solve(Problem(se.euler_middle, M.from_plane(phi, q1), (0.0, tau[-1] / M.time_scale),
                             M.euler_parameters()), "dop853", rtol=1e-13, atol=1e-15, t_eval=tau / M.time_scale)
        flat = solve(Problem(se.plane_middle, [phi, q1], (0.0, tau[-1]), M.plane_parameters()), "dop853",
                     rtol=1e-13, atol=1e-15, t_eval=tau)
        good = np.all(np.isfinite(full.y_eval), axis=1) & np.all(np.isfinite(flat.y_eval), axis=1)
        good &= np.cumprod(np.abs(np.nan_to_num(flat.y_eval[:, 1], nan=np.inf)) < 100.0).astype(bool)
        mapped = M.to_plane(full.y_eval[good])
        worst = max(worst, float(np.max(np.abs(mapped - flat.y_eval[good]) / np.maximum(1.0, np.abs(flat.y_eval[good])))))
        h = se.hyperbola(M.body, full.y_eval[good])
        hyp_worst = max(hyp_worst, float(np.ptp(h) / abs(h[0])))
        ax.plot(mapped[::5, 0], mapped[::5, 1], ".", color="C2", ms=3,
                label="Euler's equations, mapped" if k == 0 else None)
    return worst, hyp_worst


def _series(results, m, nu, eps1, center, cosh):
    portrait.series_check(
        results, lambda eta: portrait.period(se.plane_middle, [m, -nu, eps1, 1.0, float(cosh)], [center + eta, 0.0]),
        lambda eta: se.middle_series_period(m, nu, eta, cosh), AMPLITUDES,
        ("Lee (4.14): the period (in τ) about the center started at φ2c + η, measured and from the series "
         "2π(m2² − 1)^(−1/4)(1 + h2η² + h3η³)." if cosh else
         "Lee (4.13): the period (in τ) about the center started at φ2c + η, measured and from the series "
         "2π(1 + m1²)^(−1/4)(1 + h2η² + h3η³)."))
