"""Torque along the middle axis (Lee §3): the end of omega moves on a hyperbolic cylinder p^2/a - r^2/c = const,
and the motion reduces to one of four plane systems, by the signs of k1 -+ k2:
  sinh (|k1| > |k2|, |mu| below mu_c): one center, every motion periodic (3.12), series (4.13);
  cosh (|k2| > |k1|, above mu_c): a saddle and a center for m2 > 1, motions of the third kind (3.56), (4.14);
  exp  (k1 = k2: plane I, alpha1 = alpha2, or |mu| = mu_c): dq1/dtau = m3 - e^phi2 - nu q1^2 (3.58), (4.15);
  exp- (k1 = -k2: plane II, alpha1 = -alpha2): dq1/dtau = m3 - sgn(k1) e^-phi2 - nu q1^2 (3.59), (4.16).
Each portrait is checked against Euler's equations mapped into the plane, with its period series.
"""

from __future__ import annotations

import numpy as np

from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from ..results import new_figure
from . import portrait
from .largest_axis import OVERLAY_BOUND

AMPLITUDES = (0.4, 0.2, 0.1, 0.05)


LABELS = {"sinh": "m1", "cosh": "m2", "exp": "m3", "exp-": "m3"}
EQUATIONS = {"sinh": "(3.12)", "cosh": "(3.56)", "exp": "(3.24)/(3.58)", "exp-": "(3.25)/(3.59)"}
SHAPES = {"sinh": "one center, every trajectory closed",
          "cosh": "a saddle whose loop holds the periodic motions, and outside it motions of the third kind that "
                  "leave every bound in finite time",
          "exp": "a center whose orbits inside the separatrix F close; outside F, ω runs to the −y axis and leaves "
                 "every bound in finite time",
          "exp-": "the plane of the other separating polhode"}


def run(scene, results, quick):
    data = scene.data
    body = se.Body.from_moments(data["body"]["moments"])
    plane = data["plane"]
    m1, nu = float(plane["m1"]), se.MiddleAxis.plane_nu(plane["nu"], body)
    alpha1, alpha2 = (float(x) for x in plane["alpha"])
    M = se.MiddleAxis.with_plane_parameters(body, m1, -nu, alpha1, alpha2)
    lo, hi = data.get("portrait", {}).get("phi2_range", [-4.0, 4.0])
    q1_max = data.get("portrait", {}).get("p1_max", 3.0)
    form = M.form
    name = LABELS[form]
    results.number("m1", m1, "1", note=f"{name} of the plane: " + plane.get("source", "chosen to show the regime"))
    results.number("nu", nu, "1", note="mu1 = −nu")
    results.number("nu_c", se.MiddleAxis.plane_nu("nu_c", body), "1",
                   note="b/(2(a + c)): above it the cosh form (3.56) takes over")
    results.number("cosh_form", int(form == "cosh"), "1", note="1: |k2| > |k1|, Lee (3.56); 0 otherwise")
    results.number("form", form, "", note="Lee's reduction: sinh (3.12), cosh (3.56), exp (k1 = k2: plane I or "
                   "|μ| = μ_c), exp- (k1 = −k2: plane II)")
    results.number("M_over_B", M.m, "1/time²", note=f"the constant torque per unit B that gives {name} here")
    results.number("mu0_over_B", M.mu, "1")
    results.number("hyperbola", alpha1**2 - alpha2**2, "1", note="p²/a − r²/c = α1² − α2²")
    points = _singular_points(m1, form, M.eps1)
    results.number("singular_points", points, "1", note=f"q1 = 0 where {name} + ε f(φ2) = 0, typed by the "
                   "linearization")
    for kind in ("saddle", "center", "degenerate"):
        results.number(f"n_{kind}s", sum(pt["type"] == kind for pt in points), "1")

    fig, ax = new_figure(6.4, 4.2)
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    saddles = [pt["phi2"] for pt in points if pt["type"] == "saddle"]
    if centers and saddles:                         # inside the saddle's loop: between the saddle and the center
        span = centers[0] - saddles[0]
        starts = [(centers[0] - f * span, 0.0) for f in (0.2, 0.5, 0.8)]
    elif centers:
        offsets = (0.3, 0.8, 1.4, 2.0, 2.6) if form == "sinh" else (-0.6, -0.3, 0.3)
        starts = [(centers[0] + s_, 0.0) for s_ in offsets]
    else:
        starts = []
    others = ([(lo + 0.3, v) for v in (-2.0, -1.0, 1.0, 2.0)] + [(0.5 * (lo + hi), 2.0), (0.5 * (lo + hi), -2.0),
                                                                  (hi - 0.5, 1.0), (hi - 0.5, -1.0)]
              if form != "sinh" else [])
    if saddles and not centers:
        others += [(saddles[0] + 0.5, 0.0), (saddles[0] + 1.0, 1.0), (saddles[0] - 0.2, 0.0)]
    for y in portrait.trajectories(se.plane_middle, M.plane_parameters, starts + others, 30.0):
        ax.plot(y[:, 0], y[:, 1], color="0.55", lw=0.6)
    closed = 0
    for phi, q1 in starts:                          # orbits about the center close; each turns back twice
        sol = solve(Problem(se.plane_middle, [phi, q1], (0.0, 200.0), M.plane_parameters()), "dop853", rtol=1e-12,
                    atol=1e-14, events=Events(portrait.velocity_zero, 1, (-1,)), bound=portrait.BLOW_UP_BOUND)
        closed += len(sol.event_t) >= 2
    if starts:
        results.hard_case("orbits_about_the_center_closed", "Starts about the center whose orbit does not close "
                          "(count; Lee: every motion periodic for |μ| < μ_c; inside the saddle's loop or F otherwise)",
                          len(starts) - closed, 0)
    _separatrix(ax, M, saddles, lo, hi)
    escape = _escaping_start(M, centers, saddles, hi)
    if escape is not None:
        _third_kind(results, M, escape)
    deviation, hyp = _overlay(ax, M, (starts[:3] + others[:1]) or others[-3:-1])
    results.number("overlay_deviation", deviation, "1", note="Euler's equations in the plane against the plane, max")
    results.hard_case("overlay", "Full integrations of Euler's equations, mapped into the plane, on the plane's "
                      "trajectories (max deviation in (φ2, q1))", deviation, OVERLAY_BOUND)
    results.hard_case("hyperbolic_cylinder", "The end of ω stays on its hyperbolic cylinder (relative spread of "
                      "p²/a − r²/c, against p²/a + r²/c at the start in the planes, where it is 0)", hyp, 1e-10)
    portrait.finish(ax, points, (lo, hi), q1_max, "q1")
    regime = f"{name} = {m1:g}" + (f", ν = {nu:.6g}" if nu else ", unperturbed")
    where = {"exp": "plane I (α1 = α2)" if alpha1 == alpha2 else "|μ| = μ_c", "exp-": "plane II (α1 = −α2)"}
    results.figure("portrait", fig, f"Phase plane of Lee's {EQUATIONS[form]} for the torque along the middle axis"
                   f"{', ' + where[form] if form in where else ''}, {regime}: {SHAPES[form]} (grey), and Euler's "
                   "equations mapped into the plane (dots).")
    if centers:
        _series(results, M, centers[0], nu)


def _derivatives(m, form, eps, phi):
    """F = m + eps f(phi2) and its first three derivatives at phi."""
    if form == "sinh":
        f = (np.sinh(phi), np.cosh(phi), np.sinh(phi), np.cosh(phi))
    elif form == "cosh":
        f = (np.cosh(phi), np.sinh(phi), np.cosh(phi), np.sinh(phi))
    elif form == "exp":
        f = (np.exp(phi),) * 4
    else:
        e = np.exp(-phi)
        f = (e, -e, e, -e)
    return (m + eps * f[0], eps * f[1], eps * f[2], eps * f[3])


def _singular_points(m, form, eps):
    """q1 = 0 and m + eps f(phi2) = 0; center where F' < 0, saddle where F' > 0, degenerate where F' = 0."""
    target = -m / eps
    if form == "sinh":
        phis = [float(np.arcsinh(target))]
    elif form == "cosh":
        phis = [] if target < 1.0 else sorted({-float(np.arccosh(target)), float(np.arccosh(target))})
    elif form == "exp":
        phis = [float(np.log(target))] if target > 0 else []
    else:
        phis = [-float(np.log(target))] if target > 0 else []
    out = []
    for phi in phis:
        slope = _derivatives(m, form, eps, phi)[1]
        kind = "degenerate" if abs(slope) < 1e-12 else ("center" if slope < 0 else "saddle")
        out.append({"phi2": phi, "p1": 0.0, "type": kind})
    return out


def _separatrix(ax, M, saddles, lo, hi):
    """Through the saddle; in the exponential form without a saddle, Lee's F (C = 0)."""
    if M.mu1 == 0.0 or (not saddles and M.form != "exp"):
        return
    C = -se.middle_g(saddles[0], M.m1, M.mu1, M.eps1, M.form) * np.exp(-2 * M.mu1 * saddles[0]) if saddles else 0.0
    phi = np.linspace(lo, hi, 3001)
    sq = C * np.exp(2 * M.mu1 * phi) + se.middle_g(phi, M.m1, M.mu1, M.eps1, M.form)
    for sign in (1, -1):
        ax.plot(phi, np.where(sq >= 0, sign * np.sqrt(np.maximum(sq, 0.0)), np.nan), "k-", lw=1.1,
                label=("separatrix (closed form)" if saddles else "F, C = 0 (closed form)") if sign == 1 else None)


def _escaping_start(M, centers, saddles, hi):
    """A start that must leave every bound: just left of the saddle (with mu1 <= 0 a saddle occurs only in the
    cosh form and in plane II, and beyond it to the left the motion runs away), or right of F's turning point."""
    if saddles:
        return [saddles[0] - 0.3, 0.0]
    if M.form == "exp" and M.mu1 < 0 and centers:
        turn = np.log(M.m1 * (1 - 2 * M.mu1) / (-2 * M.mu1))      # C = 0 at q1 = 0
        return [turn + 0.3, 0.0]
    return None


def _third_kind(results, M, start):
    sol = solve(Problem(se.plane_middle, start, (0.0, 200.0), M.plane_parameters()), "dop853",
                rtol=1e-12, atol=1e-14, bound=portrait.BLOW_UP_BOUND)
    if sol.status == "blow-up":
        results.number("blow_up_time", sol.t, "τ", note="a start just outside the bounded region: ω leaves every "
                       f"bound (|y| passes {portrait.BLOW_UP_BOUND:g})")
    results.hard_case("third_kind_blows_up", "A start outside the bounded region leaves every bound in finite time "
                      "(1 if it does not)", 0.0 if sol.status == "blow-up" else 1.0, 0.0)


def _overlay(ax, M, starts):
    worst, hyp_worst = 0.0, 0.0
    for k, (phi, q1) in enumerate(starts):
        tau = np.linspace(0.0, 12.0, 241)
        full = solve(Problem(se.euler_middle, M.from_plane(phi, q1), (0.0, tau[-1] / M.time_scale),
                             M.euler_parameters()), "dop853", rtol=1e-13, atol=1e-15, t_eval=tau / M.time_scale,
                     bound=portrait.BLOW_UP_BOUND)           # a start that runs away stops there, as in the plane
        flat = solve(Problem(se.plane_middle, [phi, q1], (0.0, tau[-1]), M.plane_parameters()), "dop853",
                     rtol=1e-13, atol=1e-15, t_eval=tau, bound=portrait.BLOW_UP_BOUND)
        good = np.all(np.isfinite(full.y_eval), axis=1) & np.all(np.isfinite(flat.y_eval), axis=1)
        good &= np.cumprod(np.abs(np.nan_to_num(flat.y_eval[:, 1], nan=np.inf)) < 100.0).astype(bool)
        mapped = M.to_plane(full.y_eval[good])
        worst = max(worst, float(np.max(np.abs(mapped - flat.y_eval[good]) / np.maximum(1.0, np.abs(flat.y_eval[good])))))
        h = se.hyperbola(M.body, full.y_eval[good])
        w0 = full.y_eval[0]
        hyp_worst = max(hyp_worst, float(np.ptp(h) / max(abs(h[0]), w0[0]**2 / M.body.a + w0[2]**2 / M.body.c)))
        ax.plot(mapped[::5, 0], mapped[::5, 1], ".", color="C2", ms=3,
                label="Euler's equations, mapped" if k == 0 else None)
    return worst, hyp_worst


def _series(results, M, center, nu):
    """Lee §4: the Lyapunov system about the center, (4.13), (4.14), (4.15), (4.16)."""
    F = _derivatives(M.m1, M.form, M.eps1, center)
    k_sq, beta2, beta3 = -F[1], F[2], F[3]
    which = {"sinh": "(4.13)", "cosh": "(4.14)", "exp": "(4.15)", "exp-": "(4.16)"}[M.form]
    portrait.series_check(
        results, lambda eta: portrait.period(se.plane_middle, M.plane_parameters(), [center + eta, 0.0]),
        lambda eta: se.lyapunov_period(k_sq, beta2, beta3, -nu, eta), AMPLITUDES,
        f"Lee {which}: the period (in τ) about the center started at φ2c + η, measured and from the series "
        "(2π/k)(1 + h2η² + h3η³).")
