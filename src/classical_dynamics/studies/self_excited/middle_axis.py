"""Torque along the middle axis (Lee §3): the end of omega moves on a hyperbolic cylinder p^2/a - r^2/c =
const, and the motion reduces to one of four plane systems, by the signs of k1 -+ k2:
  sinh (|k1| > |k2|, |mu| below mu_c): one center, every motion periodic (3.12), series (4.13);
  cosh (|k2| > |k1|, above mu_c): a saddle and a center for m2 > 1, motions of the third kind (3.56), (4.14);
  exp  (k1 = k2: plane I, alpha1 = alpha2, or |mu| = mu_c): dq1/dtau = m3 - e^phi2 - nu q1^2 (3.58), (4.15);
  exp- (k1 = -k2: plane II, alpha1 = -alpha2): dq1/dtau = m3 - sgn(k1) e^-phi2 - nu q1^2 (3.59), (4.16);
  rare (k1 = k2 = 0: plane II at nu = nu_c): dq1/dtau = m - nu q1^2 (3.65), with tau = t; with m = 0 a line
    of rest points.
At nu = 1/2 (cosh form and plane II) the closed forms take their resonant terms phi2 e^{-phi2}
(se.middle_g_terms). Each portrait is checked against Euler's equations mapped into the plane, with its period
series; each fate Lee names (closed orbits, blow-up, escape at a linear rate, a finite limit) is checked where
the plane has it.
"""

from __future__ import annotations

import numpy as np

from ...figure_style import TEXT_WIDTH_IN
from ...formatting import format_number, shortest
from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from ...solvers.workprecision import legend_below
from ..results import new_figure
from . import accuracy, portrait
from .bounds import EXCURSION_PERIODS, INVARIANT_BOUND, OVERLAY_BOUND

AMPLITUDES = (0.4, 0.2, 0.1, 0.05)
# the cosh form's saddle loop is near: smaller amplitudes reach the η⁴ law
COSH_AMPLITUDES = (0.2, 0.1, 0.05, 0.025)


LABELS = {"sinh": "m1", "cosh": "m2", "exp": "m3", "exp-": "m3", "rare": "2√(ac) m0"}
SYMBOLS = {
    "sinh": "$m_1$",
    "cosh": "$m_2$",
    "exp": "$m_3$",
    "exp-": "$m_3$",
    "rare": "$m = 2\\sqrt{ac}\\,m_0$",
}
EQUATIONS = {
    "sinh": "Lee (3.12)",
    "cosh": "Lee (3.56)",
    "exp": "Lee (3.24), (3.58)",
    "exp-": "Lee (3.25), (3.59)",
    "rare": "Lee (3.65)",
}
SHAPES = {
    "sinh": "one center, every trajectory closed",
    "cosh": "a saddle whose loop holds the periodic motions, and outside it motions of the third kind that "
    "leave every bound in finite time",
    "exp": "a center whose orbits inside the separatrix $F$ close; outside $F$, $\\boldsymbol{\\omega}$ runs "
    "to the $-y$ axis and leaves every bound in finite time",
    "exp-": "the plane of the other separating polhode",
    "rare": "no singular point; above the line $q_1 = -\\sqrt{m/\\nu}$ the motion tends to "
    "$q_1 = \\sqrt{m/\\nu}$, the permanent rotation about $+y$, and below it $\\boldsymbol{\\omega}$ "
    "leaves every bound in finite time",
}
RARE_REST = (
    "a line of rest points $q_1 = 0$ (permanent rotations about axes of plane II); above it $q_1$ falls "
    "like $1/(\\nu\\tau)$ and $\\boldsymbol{\\omega} \\to 0$ along $+y$, below it $\\boldsymbol{\\omega}$ "
    "leaves every bound in finite time"
)
ESCAPE_EXPONENT_BOUND = 1e-3  # hard case: the rare case's escape, ln|q| against ln|(p, r)|, slope b/(a + c)
RUNAWAY_BOUND = 1e-8  # hard case: the unperturbed escape, dq1/dtau -> m3
PLANE_DEPARTURE = 1e-10  # the overlay in plane I or II stops where Euler's state has left the plane by this


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
    results.number(
        "m1", m1, "1", note=f"{name} of the plane: " + plane.get("source", "chosen to show the regime")
    )
    results.number("nu", nu, "1", note="mu1 = −nu")
    results.number(
        "nu_c",
        se.MiddleAxis.plane_nu("nu_c", body),
        "1",
        note="b/(2(a + c)): above it the cosh form (3.56) takes over",
    )
    results.number("cosh_form", int(form == "cosh"), "1", note="1: |k2| > |k1|, Lee (3.56); 0 otherwise")
    results.number(
        "form",
        form,
        "",
        note="Lee's reduction: sinh (3.12), cosh (3.56), exp (k1 = k2: plane I or "
        "|μ| = μ_c), exp- (k1 = −k2: plane II), rare (k1 = k2 = 0: plane II at ν_c)",
    )
    results.number("M_over_B", M.m, "1/time²", note=f"the constant torque per unit B that gives {name} here")
    results.number("mu0_over_B", M.mu, "1")
    results.number("hyperbola", alpha1**2 - alpha2**2, "1", note="p²/a − r²/c = α1² − α2²")
    points = _singular_points(m1, form, M.eps1)
    results.number(
        "singular_points", points, "1", note=f"q1 = 0 where {name} + ε f(φ2) = 0, typed by the linearization"
    )
    for kind in ("saddle", "center", "degenerate"):
        results.number(f"n_{kind}s", sum(pt["type"] == kind for pt in points), "1")

    fig, ax = new_figure(TEXT_WIDTH_IN, 3.6)
    drawing = portrait.Drawing("q1", (lo - 0.5, hi + 0.5, 2.0 * q1_max))
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    # a degenerate point has a separatrix too
    saddles = [pt["phi2"] for pt in points if pt["type"] != "center"]
    if centers and saddles:  # inside the saddle's loop: between the saddle and the center
        span = centers[0] - saddles[0]
        starts = [(centers[0] - f * span, 0.0) for f in (0.2, 0.5, 0.8)]
    elif centers:
        offsets = (0.3, 0.8, 1.4, 2.0, 2.6) if form == "sinh" else (-0.6, -0.3, 0.3)
        starts = [(centers[0] + s_, 0.0) for s_ in offsets]
    else:
        starts = []
    others = (
        [(lo + 0.3, v) for v in (-2.0, -1.0, 1.0, 2.0)]
        + [(0.5 * (lo + hi), 2.0), (0.5 * (lo + hi), -2.0), (hi - 0.5, 1.0), (hi - 0.5, -1.0)]
        if form != "sinh"
        else []
    )
    if saddles and not centers:
        others += [(saddles[0] + 0.5, 0.0), (saddles[0] + 1.0, 1.0), (saddles[0] - 0.2, 0.0)]
    for y in portrait.trajectories(se.plane_middle, M.plane_parameters, starts + others, 30.0):
        drawing.curve("trajectory", y[:, 0], y[:, 1])
    closed = 0
    for phi, q1 in starts:  # orbits about the center close; each turns back twice
        sol = solve(
            Problem(se.plane_middle, [phi, q1], (0.0, 200.0), M.plane_parameters()),
            "dop853",
            rtol=1e-12,
            atol=1e-14,
            events=Events(portrait.velocity_zero, 1, (-1,)),
            bound=portrait.BLOW_UP_BOUND,
        )
        closed += len(sol.event_t) >= 2
    if starts:
        results.hard_case(
            "orbits_about_the_center_closed",
            "Starts about the center whose orbit does not close "
            "(count; Lee: every motion is periodic for $|\\mu| < \\mu_\\mathrm{c}$, and inside the "
            "saddle's loop or $F$ otherwise)",
            len(starts) - closed,
            0,
        )
    _separatrix(drawing, M, saddles, centers, lo, hi)
    if M.mu1 < 0 and _turns_nowhere(M):
        _every_start_escapes(results, M, others)
    if form == "rare":
        _rare_escape(results, M)
        if M.m1 == 0.0:
            _rare_rest(drawing, results, M)
    else:
        escape = _escaping_start(M, centers, saddles)
        if escape is not None:
            _third_kind(results, M, escape)
    if M.mu1 == 0.0 and not points:
        _runaway(results, M)
    if M.mu1 < 0 and not points and M.m1 > 0 and not _turns_nowhere(M):
        _settles(results, M)
    overlay_starts = starts[:3] + others[:1] if starts else others[2:6]
    n_overlay = len(overlay_starts)
    deviation, hyp, invariant, share = _overlay(drawing, M, overlay_starts)
    results.number(
        "overlay_deviation", deviation, "1", note="Euler's equations in the plane against the plane, max"
    )
    results.number(
        "overlay_share",
        share,
        "1",
        note="share of the overlay's samples compared: those before the "
        f"motion leaves the window (|q1| < 100), every bound, or, in plane I or II, the plane itself (by "
        f"{PLANE_DEPARTURE:g}; the plane repels as φ2 runs away)",
    )
    results.hard_case(
        "overlay",
        "Full integrations of Euler's equations, mapped into the plane, on the plane's "
        "trajectories (largest deviation in $(\\varphi_2, q_1)$)",
        deviation,
        OVERLAY_BOUND,
    )
    integral = "C" if M.mu1 else "E"
    results.number(
        "invariant_spread",
        invariant,
        "1",
        note=f"{integral}: largest spread along one of Euler's "
        "integrations mapped into the plane, relative to the size of its terms",
    )
    resonant = ", resonant at $\\nu = \\tfrac12$" if _resonant(M) else ""
    results.hard_case(
        "plane_invariant",
        f"The plane's first integral (${integral}$, Lee's closed form"
        f"{resonant}) along Euler's equations mapped "
        "into the plane (largest relative spread)",
        invariant,
        INVARIANT_BOUND,
    )
    results.number(
        "cylinder_spread",
        hyp,
        "1",
        note="relative spread of p²/a − r²/c along Euler's equations "
        "(against p²/a + r²/c at the start in the planes, where it is 0)",
    )
    results.hard_case(
        "hyperbolic_cylinder",
        "The end of $\\boldsymbol{\\omega}$ stays on its hyperbolic cylinder "
        "(relative spread of $p^2/a - r^2/c$, against $p^2/a + r^2/c$ at the start in the planes, where "
        "it is 0)",
        hyp,
        1e-10,
    )
    drawing.points(points)
    drawing.window(lo, hi, q1_max)
    portrait.finish(ax, drawing, "$q_1$")
    regime = f"{SYMBOLS[form] if form != 'rare' else '$m$'} = {portrait.param_text(m1)}"
    regime += f", $\\nu$ = {portrait.param_text(nu)}" if nu else ", unperturbed ($\\nu = 0$)"
    drawn = drawing.elements()
    black = (
        "; black: the separatrix from the closed form"
        if "separatrix" in drawn
        else "; black: the curve $C = 0$ of the closed form"
        if "curve_C0" in drawn
        else ""
    )
    if "rest_line" in drawn:
        black += "; the line of rest points in colour"
    marked = "; markers: the singular points, by type" if points else ""
    where = {
        "exp": "plane I ($\\alpha_1 = \\alpha_2$)" if alpha1 == alpha2 else "$|\\mu| = \\mu_\\mathrm{c}$",
        "exp-": "plane II ($\\alpha_1 = -\\alpha_2$)",
        "rare": "plane II at $\\nu = \\nu_\\mathrm{c}$, Lee's rare case ($k_1 = k_2 = 0$; "
        "here $\\tau = t$ and $\\varphi_2 = 2\\sqrt{ac}\\,\\varphi$)",
    }
    results.figure(
        "portrait",
        fig,
        f"Phase plane of {EQUATIONS[form]} for the torque along the middle axis $y$"
        f"{', ' + where[form] if form in where else ''}; {regime}: {_shape(M, points)}. Grey: trajectories "
        f"of the plane{black}{marked}; dots: {portrait.COUNTS[n_overlay]} integrations of Euler's "
        "equations in three dimensions, mapped into the plane, which lie on the plane's trajectories.",
    )
    drawing.save(
        results,
        "What the portrait draws, point by point: each element (trajectory, separatrix or the "
        "curve $C = 0$, line of rest points, Euler's equations mapped into the plane, singular point by "
        "type, "
        "the window's corners) and its curve number, in $(\\varphi_2, q_1)$.",
    )
    if centers:
        _series(results, M, centers[0], nu)
    _middle_checks(results, M, overlay_starts, centers)
    if "excursion" in data:
        start = excursion_start(M, float(data["excursion"]["q0"]))
        _excursion(results, M, start)
        accuracy.huge_excursion(results, M, start, quick)


def _shape(M, points):
    """What the portrait shows, in words."""
    w = "$\\boldsymbol{\\omega}$"
    if M.form == "cosh" and not any(pt["type"] == "center" for pt in points):
        return (
            "a degenerate point where saddle and center have merged: motions of the second kind into it, and "
            "of the third kind, leaving every bound in finite time"
            if points
            else "no singular point: every motion is of the third kind and leaves every bound in finite time"
        )
    if M.form in ("exp", "exp-") and not points:
        if M.mu1 == 0.0:
            return (
                f"no singular point: {w} runs to the $y$ axis, with finite modulus (the force-free "
                "separatrix "
                "motion)"
                if M.m1 == 0.0
                else f"no singular point: {w} runs to the $y$ axis, $|q_1|$ growing like $|m_3|\\tau$"
            )
        if _turns_nowhere(M):
            return f"no singular point: {w} runs to the $-y$ axis and leaves every bound in finite time"
        return (
            "no singular point: $q_1$ tends to $\\sqrt{m_3/\\nu}$, the permanent rotation about the $+y$ axis"
        )
    if M.form == "rare" and M.m1 <= 0:
        return (
            RARE_REST
            if M.m1 == 0
            else f"no singular point: from every start {w} leaves every bound in finite "
            "time, towards an axis of plane II perpendicular to $y$"
        )
    if M.form in ("exp", "exp-") and M.mu1 == 0.0:
        return (
            "a center, every orbit closed (the energy of Lee (3.47) is conserved)"
            if M.form == "exp"
            else "a center, every orbit closed (the energy of Lee (3.48) is conserved)"
        )
    if M.form == "exp-":
        kinds = {pt["type"] for pt in points}
        if kinds == {"center"}:
            return "a center, every orbit about it closed"
        if kinds == {"saddle"}:
            return (
                f"one saddle, whose separatrices divide the plane into four regions: in two {w} runs to the "
                "$-y$ axis and leaves every bound in finite time, in the other two it tends to the $+y$ axis"
            )
    return SHAPES[M.form]


def _resonant(M):
    """nu = 1/2 in the cosh form or plane II: Lee's closed forms take the resonant terms phi2 e^{-phi2}."""
    return M.form in ("cosh", "exp-") and se.resonant(M.mu1, -1.0)


def _turns_nowhere(M):
    """sup over phi2 of m + eps f(phi2) <= 0: with the drag, q1 then falls for ever and every motion escapes
    (in the rare case with m = 0, q1 > 0 falls for ever towards the line of rest points q1 = 0 but never
    crosses it)."""
    top = {
        "sinh": np.inf,
        "cosh": M.m1 + M.eps1 if M.eps1 < 0 else np.inf,
        "exp": M.m1 if M.eps1 < 0 else np.inf,
        "exp-": M.m1 if M.eps1 < 0 else np.inf,
        "rare": M.m1 if M.m1 != 0.0 else np.inf,
    }[M.form]
    return top <= 0.0


def _every_start_escapes(results, M, starts):
    stayed = 0
    for start in starts:
        sol = solve(
            Problem(se.plane_middle, list(start), (0.0, 400.0), M.plane_parameters()),
            "dop853",
            rtol=1e-12,
            atol=1e-14,
            bound=portrait.BLOW_UP_BOUND,
        )
        stayed += sol.status != "blow-up"
    results.hard_case(
        "every_start_escapes",
        "Starts of the portrait that do not leave every bound in finite time "
        "(count; Lee: $m + \\varepsilon f(\\varphi_2) < 0$ everywhere, so none can turn back)",
        stayed,
        0,
    )


def _derivatives(m, form, eps, phi):
    """F = m + eps f(phi2) and its first three derivatives at phi."""
    if form == "sinh":
        f = (np.sinh(phi), np.cosh(phi), np.sinh(phi), np.cosh(phi))
    elif form == "cosh":
        f = (np.cosh(phi), np.sinh(phi), np.cosh(phi), np.sinh(phi))
    elif form == "exp":
        f = (np.exp(phi),) * 4
    elif form == "exp-":
        e = np.exp(-phi)
        f = (e, -e, e, -e)
    else:
        f = (0.0,) * 4
    return (m + eps * f[0], eps * f[1], eps * f[2], eps * f[3])


def _singular_points(m, form, eps):
    """q1 = 0 and m + eps f(phi2) = 0; center where F' < 0, saddle where F' > 0, degenerate where F' = 0."""
    target = -m / eps if eps else np.inf
    if form == "sinh":
        phis = [float(np.arcsinh(target))]
    elif form == "cosh":
        phis = [] if target < 1.0 else sorted({-float(np.arccosh(target)), float(np.arccosh(target))})
    elif form == "exp":
        phis = [float(np.log(target))] if target > 0 else []
    elif form == "exp-":
        phis = [0.0 - float(np.log(target))] if target > 0 else []  # 0.0 - : no -0.0 at m3 = 1
    else:  # the rare case: none, or with m = 0 a whole line (_rare_rest)
        phis = []
    out = []
    for phi in phis:
        slope = _derivatives(m, form, eps, phi)[1]
        kind = "degenerate" if abs(slope) < 1e-12 else ("center" if slope < 0 else "saddle")
        out.append({"phi2": phi, "p1": 0.0, "type": kind})
    return out


def _separatrix(drawing, M, saddles, centers, lo, hi):
    """Through the saddle or degenerate point; without one, Lee's F (C = 0) about the center of the
    exponential form, or the lines q1 = +-sqrt(m/nu) of the rare case."""
    bounding = M.form == "exp" and centers or M.form == "rare" and M.m1 > 0
    if M.mu1 == 0.0 or not (saddles or bounding):
        return
    C = (
        -se.middle_g(saddles[0], M.m1, M.mu1, M.eps1, M.form) * np.exp(-2 * M.mu1 * saddles[0])
        if saddles
        else 0.0
    )
    phi = np.linspace(lo, hi, 3001)
    sq = C * np.exp(2 * M.mu1 * phi) + se.middle_g(phi, M.m1, M.mu1, M.eps1, M.form)
    for sign in (1, -1):
        drawing.curve(
            "separatrix" if saddles else "curve_C0",
            phi,
            np.where(sq >= 0, sign * np.sqrt(np.maximum(sq, 0.0)), np.nan),
        )


def _escaping_start(M, centers, saddles):
    """A start that must leave every bound: just left of the saddle or degenerate point (with mu1 <= 0 these
    occur only in the cosh form and in plane II, and beyond them to the left the motion runs away), right of
    F's turning point, or anywhere when nothing can turn the motion back."""
    if M.mu1 >= 0:
        return None
    if saddles:
        return [saddles[0] - 0.3, 0.0]
    if M.form == "exp" and centers:
        turn = np.log(M.m1 * (1 - 2 * M.mu1) / (-2 * M.mu1))  # C = 0 at q1 = 0
        return [turn + 0.3, 0.0]
    return [0.0, 0.0] if _turns_nowhere(M) else None


def _third_kind(results, M, start):
    sol = solve(
        Problem(se.plane_middle, start, (0.0, 200.0), M.plane_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=portrait.BLOW_UP_BOUND,
    )
    if sol.status == "blow-up":
        results.number(
            "blow_up_time",
            sol.t,
            "τ",
            note="a start just outside the bounded region: ω leaves every "
            f"bound (|y| passes {portrait.BLOW_UP_BOUND:g})",
        )
    results.hard_case(
        "third_kind_blows_up",
        "A start outside the bounded region leaves every bound in finite time (1 if it does not)",
        0.0 if sol.status == "blow-up" else 1.0,
        0.0,
    )


def _overlay(drawing, M, starts):
    """Euler's equations from each start mapped into the plane against the plane's solution; returns the worst
    deviation, the spreads of the hyperbola and of the plane's first integral along Euler's rows, and the
    share of samples compared."""
    worst, hyp_worst, inv_worst, compared = 0.0, 0.0, 0.0, 0
    for phi, q1 in starts:
        tau = np.linspace(0.0, 12.0, 241)
        # a start that runs away stops there, as in the plane
        full = solve(
            Problem(
                se.euler_middle, M.from_plane(phi, q1), (0.0, tau[-1] / M.time_scale), M.euler_parameters()
            ),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau / M.time_scale,
            bound=portrait.BLOW_UP_BOUND,
        )
        flat = solve(
            Problem(se.plane_middle, [phi, q1], (0.0, tau[-1]), M.plane_parameters()),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau,
            bound=portrait.BLOW_UP_BOUND,
        )
        good = np.all(np.isfinite(full.y_eval), axis=1) & np.all(np.isfinite(flat.y_eval), axis=1)
        good &= np.cumprod(np.abs(np.nan_to_num(flat.y_eval[:, 1], nan=np.inf)) < 100.0).astype(bool)
        # in plane I or II, only while Euler's state is still in the plane to PLANE_DEPARTURE (see
        # plane_departure)
        good &= np.cumprod(
            np.nan_to_num(M.plane_departure(full.y_eval), nan=np.inf) < PLANE_DEPARTURE
        ).astype(bool)
        mapped = M.to_plane(full.y_eval[good])
        compared += int(good.sum())
        worst = max(
            worst,
            float(np.max(np.abs(mapped - flat.y_eval[good]) / np.maximum(1.0, np.abs(flat.y_eval[good])))),
        )
        h = se.hyperbola(M.body, full.y_eval[good])
        w0 = full.y_eval[0]
        hyp_worst = max(
            hyp_worst, float(np.ptp(h) / max(abs(h[0]), w0[0] ** 2 / M.body.a + w0[2] ** 2 / M.body.c))
        )
        inv_worst = max(inv_worst, se.middle_invariant_spread(mapped, M.m1, M.mu1, M.eps1, M.form))
        drawing.curve("euler", mapped[::5, 0], mapped[::5, 1])
    return worst, hyp_worst, inv_worst, compared / (len(starts) * tau.size)


def _series(results, M, center, nu):
    """Lee §4: the Lyapunov system about the center, (4.13), (4.14), (4.15), (4.16)."""
    F = _derivatives(M.m1, M.form, M.eps1, center)
    k_sq, beta2, beta3 = -F[1], F[2], F[3]
    which = {"sinh": "(4.13)", "cosh": "(4.14)", "exp": "(4.15)", "exp-": "(4.16)"}[M.form]
    from . import middle_checks

    middle_checks.theta_series(results, M, center, k_sq, beta2, beta3)
    portrait.series_check(
        results,
        lambda eta: portrait.period(se.plane_middle, M.plane_parameters(), [center + eta, 0.0]),
        lambda eta: se.lyapunov_period(k_sq, beta2, beta3, -nu, eta),
        COSH_AMPLITUDES if M.form == "cosh" else AMPLITUDES,
        f"Lee {which}: the period (in $\\tau$) of the oscillation about the center "
        f"$\\varphi_{{2\\mathrm{{c}}}}$ "
        "started at $\\varphi_{2\\mathrm{c}} + \\eta$, integrated from the plane system and from the series "
        "$(2\\pi/k)(1 + h_2\\eta^2 + h_3\\eta^3)$, and their relative difference.",
    )


def _middle_checks(results, M, starts, centers):
    """Lee (3.3)/(3.8), the planes (3.38)-(3.41), the center as a permanent rotation, the unstable middle axis
    and plane I's escape for large q0 (see middle_checks)."""
    from . import middle_checks

    w0 = M.from_plane(*starts[0])
    middle_checks.general_solution(results, M, w0, 12.0 / M.time_scale)
    if M.form in ("exp", "exp-") and abs(M.alpha1) == abs(M.alpha2):
        middle_checks.plane_departure(results, M, w0, 12.0 / M.time_scale)
    if centers:
        middle_checks.center_at_rest(results, M, centers[0])
    if M.form == "sinh" and M.mu1 == 0.0:
        middle_checks.middle_axis_unstable(results, M)
    if M.form == "exp" and M.alpha1 == M.alpha2 and M.mu1 < 0 and centers:
        middle_checks.large_q0(results, M)


def _rare_escape(results, M):
    """Lee (3.65)-(3.66): below the line q1 = -sqrt(m/nu) (m > 0), below q1 = 0 (m = 0) or from anywhere (m <
    0) the Riccati equation dq1/dtau = m - nu q1^2 blows up at a time known in closed form; Euler's equations
    then run to an axis of plane II perpendicular to y, because p and r grow like e^{sqrt(ac)|phi|}, faster
    than q: ln|q| against ln|(p, r)| has slope |mu|/sqrt(ac) = b/(a + c)."""
    m, nu, bound = M.m1, -M.mu1, portrait.BLOW_UP_BOUND
    q0 = -1.5 * np.sqrt(m / nu) if m > 0 else -1.0
    flat = solve(
        Problem(se.plane_middle, [0.0, q0], (0.0, 100.0), M.plane_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=bound,
    )
    closed = _riccati_time(m, nu, q0, -bound)
    results.number("blow_up_time", flat.t, "τ", note=f"from φ2 = 0, q1 = {q0:.4g}: q1 passes −{bound:g}")
    results.number(
        "blow_up_time_closed_form",
        closed,
        "τ",
        note="dq1/dτ = m − νq1² integrated in closed form between the start and the bound",
    )
    results.hard_case(
        "rare_blow_up_time",
        "The blow-up time of the rare case against its closed form (relative)",
        abs(flat.t / closed - 1.0) if flat.status == "blow-up" else np.inf,
        1e-9,
    )
    full = solve(
        Problem(se.euler_middle, M.from_plane(0.0, q0), (0.0, 100.0), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        bound=1e12,
        record_steps=True,
    )
    w = full.y_steps
    pr, q = np.hypot(w[:, 0], w[:, 2]), np.abs(w[:, 1])
    late = (pr > 1e4) & (pr < 1e11)
    slope = float(np.polyfit(np.log(pr[late]), np.log(q[late]), 1)[0])
    expected = M.body.b / (M.body.a + M.body.c)
    results.number(
        "escape_exponent",
        slope,
        "1",
        note="slope of ln|q| against ln|(p, r)| as ω leaves every bound "
        "(Euler's equations, |(p, r)| from 1e4 to 1e11)",
    )
    results.number(
        "escape_exponent_expected",
        expected,
        "1",
        note="b/(a + c) = |μ|/√(ac) at |μ| = μ_c: below 1, so "
        "ω turns towards plane II's axis perpendicular to y",
    )
    results.number(
        "escape_q_share", float(q[-1] / np.linalg.norm(w[-1])), "1", note="|q|/|ω| when |ω| passes 1e12"
    )
    results.hard_case(
        "rare_escape_direction",
        "Lee: below the line $\\boldsymbol{\\omega}$ runs to an axis of plane "
        "II perpendicular to $y$: $|s - b/(a + c)|$ for the slope $s$ of $\\ln|q|$ against "
        "$\\ln|(p, r)|$",
        abs(slope - expected),
        ESCAPE_EXPONENT_BOUND,
    )


def _riccati_time(m, nu, q_from, q_to):
    """The time dq/dtau = m - nu q^2 takes from q_from to q_to, both below every rest point: with s^2 = |m|/nu
    the difference between the ends of -ln((q - s)/(q + s))/(2 s nu) (m > 0), 1/(nu q) (m = 0) or
    -arctan(q/s)/(s nu) (m < 0)."""
    s = np.sqrt(abs(m) / nu)
    if m > 0:
        F = lambda q: -np.log((q - s) / (q + s)) / (2 * s * nu)
    elif m == 0:
        F = lambda q: 1.0 / (nu * q)
    else:
        F = lambda q: -np.arctan(q / s) / (s * nu)
    return float(F(q_to) - F(q_from))


def _rare_rest(drawing, results, M):
    """Lee's Figure 3.18(b), the rare case without torque (m0 = 0): dq1/dtau = -nu q1^2, so every point of q1
    = 0 is at rest (a permanent rotation about an axis of plane II: -b r p + mu |omega|^2 = 0 there at |mu| =
    mu_c). Above the line q1 = q10/(1 + nu q10 tau) falls to 0 while phi2 runs to +infinity, so p and r decay
    like e^{-phi2/2} = (1 + nu q10 tau)^{-1/(2 nu)}, faster than q: omega -> 0 along +y. Along Euler's
    equations ln|q| against ln|(p, r)| has slope 2 nu_c = b/(a + c) exactly."""
    drawing.curve("rest_line", drawing.reach[:2], [0.0, 0.0])
    drift = 0.0
    for phi in (-2.0, 0.0, 2.0):
        w0 = M.from_plane(phi, 0.0)
        rest = solve(
            Problem(se.euler_middle, w0, (0.0, 100.0), M.euler_parameters()),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            record_steps=True,
        )
        drift = max(drift, float(np.max(np.linalg.norm(rest.y_steps - w0, axis=1)) / np.linalg.norm(w0)))
    results.number(
        "rest_line_drift",
        drift,
        "1",
        note="largest |ω(t) − ω0|/|ω0| over t ≤ 100 from three points of "
        "q1 = 0 (φ2 = −2, 0, 2), Euler's equations",
    )
    results.hard_case(
        "rest_line_at_rest",
        "Every point of $q_1 = 0$ is a permanent rotation (Euler's equations "
        "from three of them: largest relative drift over $t \\le 100$)",
        drift,
        1e-12,
    )
    q10, nu = 1.0, -M.mu1
    tau = np.linspace(0.0, 200.0, 401)
    # tau = t in the rare case
    full = solve(
        Problem(se.euler_middle, M.from_plane(0.0, q10), (0.0, tau[-1]), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=tau,
    )
    inside = np.cumprod(M.plane_departure(full.y_eval) < PLANE_DEPARTURE).astype(bool)
    w, t = full.y_eval[inside], tau[inside]
    decay = float(np.max(np.abs(M.to_plane(w)[:, 1] / (q10 / (1.0 + nu * q10 * t)) - 1.0)))
    slope = float(np.polyfit(np.log(np.hypot(w[:, 0], w[:, 2])), np.log(np.abs(w[:, 1])), 1)[0])
    results.number(
        "rest_decay_error",
        decay,
        "1",
        note=f"Euler's q1 against q10/(1 + νq10τ) from φ2 = 0, q10 = "
        f"{q10:g}, while the state is in plane II (to τ = {t[-1]:g}; largest relative error)",
    )
    results.number(
        "rest_decay_exponent",
        slope,
        "1",
        note="slope of ln|q| against ln|(p, r)| along that motion: "
        "below 1, so q outlasts p and r and ω → 0 along +y",
    )
    results.hard_case(
        "rare_rest_decay",
        "Without torque, above the line of rest points $q_1$ falls like "
        "$q_{10}/(1 + \\nu q_{10}\\tau)$ (Euler's equations against the closed form, largest relative "
        "error)",
        decay,
        1e-9,
    )
    results.hard_case(
        "rare_rest_direction",
        "Lee: $\\boldsymbol{\\omega} \\to 0$ along $+y$: $|s - b/(a + c)|$ for "
        "the slope $s$ of $\\ln|q|$ against $\\ln|(p, r)|$",
        abs(slope - M.body.b / (M.body.a + M.body.c)),
        ESCAPE_EXPONENT_BOUND,
    )


def _runaway(results, M):
    """Unperturbed, no singular point (Lee's Figures 3.4 (d), (e), 3.5 (e)): the exponential term dies away
    and q1 changes at the constant rate m3; with m3 = 0 (no torque: the force-free separatrix motion) it tends
    to the finite limit -+sqrt(2E)."""
    start = np.array([0.0, 0.0])
    tau = np.array([40.0, 60.0])
    sol = solve(
        Problem(se.plane_middle, start, (0.0, tau[-1]), M.plane_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        t_eval=tau,
        bound=portrait.BLOW_UP_BOUND,
    )
    rate = float(np.diff(sol.y_eval[:, 1])[0] / np.diff(tau)[0])
    results.number("runaway_rate", rate, "1/τ", note="dq1/dτ between τ = 40 and 60, from φ2 = 0, q1 = 0")
    results.hard_case(
        "runaway_rate",
        f"Unperturbed, no singular point: $q_1$ changes at the rate {SYMBOLS[M.form]} "
        "($|dq_1/d\\tau - m_3|$ late in the motion)",
        abs(rate - M.m1),
        RUNAWAY_BOUND,
    )
    if M.m1 == 0.0:
        E = float(se.middle_energy(start, 0.0, M.eps1, M.form)[0])
        limit = float(np.sign(sol.y_eval[-1, 1])) * np.sqrt(2 * E)
        results.number("limit_q1", float(sol.y_eval[-1, 1]), "1", note="q1 at τ = 60")
        results.number(
            "limit_q1_closed_form", limit, "1", note="±√(2E): all of the energy in q1 once e^{±φ2} → 0"
        )
        results.number(
            "limit_q_over_start",
            abs(M.from_plane(0.0, limit)[1]) / np.linalg.norm(M.from_plane(0.0, 0.0)),
            "1",
            note="the limiting |q| against |ω0|: ω tends to the y axis with finite modulus",
        )
        results.hard_case(
            "force_free_limit",
            "No torque in a plane of the separating polhodes: $q_1$ tends to the "
            "finite limit $\\pm\\sqrt{2E}$ ($|q_1 - \\text{limit}|$ at $\\tau = 60$)",
            abs(float(sol.y_eval[-1, 1]) - limit),
            RUNAWAY_BOUND,
        )


def turning_points(M, y0):
    """The orbit's turning points (q1 = 0) from the closed form: the roots of C e^{2 mu1 phi2} + g(phi2) on
    either side of the start, which lies inside the orbit's range of phi2."""
    from scipy.optimize import brentq

    C = float(se.middle_invariant(y0, M.m1, M.mu1, M.eps1, M.form)[0])

    def h(phi):
        if M.mu1 == 0.0:
            return 2.0 * (C - se.middle_potential(phi, M.m1, M.eps1, M.form))
        return C * np.exp(2 * M.mu1 * phi) + se.middle_g(phi, M.m1, M.mu1, M.eps1, M.form)

    roots = []
    for side in (-1.0, 1.0):
        step = 0.25
        while h(y0[0] + side * step) > 0:
            step *= 2.0
        roots.append(brentq(h, y0[0] + side * step / 2, y0[0] + side * step, xtol=1e-15, rtol=1e-15))
    return roots, h


def closed_form_period(M, y0):
    """The tau-period 2 int dphi2/|q1| between the turning points, q1^2 from the closed form, by quadrature
    with phi2 = mid + half sin(theta), which removes the inverse square roots at the ends."""
    from scipy.integrate import quad

    (left, right), h = turning_points(M, y0)
    mid, half = 0.5 * (left + right), 0.5 * (right - left)
    value, _ = quad(
        lambda th: half * np.cos(th) / np.sqrt(max(h(mid + half * np.sin(th)), 1e-300)),
        -np.pi / 2,
        np.pi / 2,
        epsabs=0.0,
        epsrel=1e-13,
        limit=200,
    )
    return 2.0 * value, (left, right)


def excursion_start(M, q0):
    """phi = 0 on the cylinder (p, r) = (alpha1 sqrt a, alpha2 sqrt c), spin q0 about the torque axis: the
    start w0, the period T in t, the turning points (phi2) of the closed form and |omega| at each of them."""
    w0 = np.array([M.alpha1 * np.sqrt(M.body.a), q0, M.alpha2 * np.sqrt(M.body.c)])
    T_tau, turns = closed_form_period(M, M.to_plane(w0)[0])
    sizes = np.array([np.linalg.norm(M.from_plane(phi, 0.0)) for phi in turns])
    return w0, T_tau / M.time_scale, turns, sizes


def _excursion(results, M, start):
    """The huge excursions just below mu_c (digest §7.5): from phi = 0 on the cylinder with a large spin q0
    about the torque axis, the orbit closes, but p and r swing out like cosh(sqrt(ac) phi) on the way. The
    turning points and the period come from the closed form; Euler's equations must reach the same points,
    close after every period and stay on their cylinder. Rounding errors in omega are relative to the largest
    |omega| the orbit reaches, so the errors are measured against it."""
    w0, T, (left, right), predicted = start
    q0, scale = w0[1], float(predicted.max())  # the largest |omega|, at the far turning point
    full = solve(
        Problem(se.euler_middle, w0, (0.0, EXCURSION_PERIODS * T), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        events=Events(portrait.velocity_zero, 1),
        record_steps=True,
    )
    w = full.y_steps
    sizes = np.linalg.norm(w, axis=1)
    reached = np.linalg.norm(full.event_y, axis=1)
    turning = float(np.max(np.min(np.abs(reached[:, None] - predicted[None, :]), axis=1)) / scale)
    closure = float(np.linalg.norm(full.y - w0) / scale)
    hyp = se.hyperbola(M.body, w)
    hyp_spread = float(np.ptp(hyp) / np.max(w[:, 0] ** 2 / M.body.a + w[:, 2] ** 2 / M.body.c))
    c1 = se.middle_invariant(M.to_plane(w), M.m1, M.mu1, M.eps1, M.form)
    fig, ax = new_figure(height=2.6)
    first = full.t_steps <= 2 * T
    ax.semilogy(
        full.t_steps[first],
        sizes[first],
        ".-",
        color=portrait.EULER_COLOUR,
        ms=2,
        lw=0.6,
        label="$|\\omega|$ along Euler's equations (at the steps)",
    )
    for k, value in enumerate(predicted):
        ax.axhline(
            value,
            color="k",
            ls="--",
            lw=0.8,
            label="$|\\omega|$ at the turning points, closed form" if k == 0 else None,
        )
    ax.set_xlabel("$t$ (time units)")
    ax.set_ylabel("$|\\omega|$ (rad per time unit)")
    legend_below(fig, *ax.get_legend_handles_labels(), ncol=2)
    nu_c = se.MiddleAxis.plane_nu("nu_c", M.body)
    results.figure(
        "excursion",
        fig,
        "A huge excursion below the critical drag "
        f"($\\nu$ = {portrait.param_text(-M.mu1)}, "
        f"$\\nu_\\mathrm{{c}}$ = {format_number(nu_c, 3)}): $|\\boldsymbol{{\\omega}}|$ against $t$ "
        f"(log scale) from a spin $q_0$ = {shortest(q0)} about the torque axis, over the first two of the "
        f"{EXCURSION_PERIODS} periods integrated. $|\\boldsymbol{{\\omega}}|$ swings out by a factor "
        f"{format_number(float(sizes.max() / sizes[0]), 3)} and back, and turns where the closed form "
        "says (dashed).",
    )
    results.number("excursion_q0", q0, "1/time", note="the start: φ = 0 on the cylinder, q = q0")
    results.number("excursion_max_omega", float(sizes.max()), "1/time", note="max |ω| over the orbit (Euler)")
    results.number(
        "excursion_max_omega_closed_form",
        scale,
        "1/time",
        note="|ω| at the far turning point of the closed form",
    )
    results.number("excursion_growth", float(sizes.max() / sizes[0]), "1", note="max |ω| against |ω0|")
    results.number(
        "excursion_period",
        T,
        "time",
        note="2∫dφ2/|q1| between the turning points of the closed form, by quadrature, in t",
    )
    results.number(
        "excursion_phi2_left", float(left), "1", note="the left turning point of the closed form (q1 = 0)"
    )
    results.number(
        "excursion_phi2_right", float(right), "1", note="the right turning point of the closed form"
    )
    results.number(
        "excursion_closure",
        closure,
        "1",
        note=f"|ω − ω0| after {EXCURSION_PERIODS} periods, relative to the largest |ω|",
    )
    results.number(
        "excursion_c1_spread",
        float(np.ptp(c1) / np.max(np.abs(c1))),
        "1",
        note="relative spread of C1 "
        "from Euler's state: q is known to rounding relative to the largest |ω|, and near its turning "
        "points q1 is small",
    )
    results.hard_case(
        "excursion_turning_points",
        "Huge excursions below $\\mu_\\mathrm{c}$: "
        "$|\\boldsymbol{\\omega}|$ where Euler's equations turn ($q = 0$) against the closed "
        "form's turning points (worst, relative to the largest $|\\boldsymbol{\\omega}|$)",
        turning,
        1e-10,
    )
    results.hard_case(
        "excursion_closes",
        f"Huge excursions below $\\mu_\\mathrm{{c}}$: $\\boldsymbol{{\\omega}}$ "
        f"back at its start after {EXCURSION_PERIODS} periods of the closed form (relative to the "
        "largest $|\\boldsymbol{\\omega}|$)",
        closure,
        1e-8,
    )
    results.hard_case(
        "excursion_cylinder",
        "Huge excursions below $\\mu_\\mathrm{c}$: spread of $p^2/a - r^2/c$ "
        "along Euler's equations, relative to the largest $p^2/a + r^2/c$",
        hyp_spread,
        1e-12,
    )


def _settles(results, M):
    """With the drag and nothing to stop it but the drag (Lee's Figure 3.15; the rare case above its line):
    from phi2 = 0, q1 = 0 the motion runs off along the axis and q1 tends to sqrt(m/nu), the permanent
    rotation about +y (p and r -> 0)."""
    sol = solve(
        Problem(se.plane_middle, [0.0, 0.0], (0.0, 80.0), M.plane_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=portrait.BLOW_UP_BOUND,
    )
    limit = np.sqrt(M.m1 / -M.mu1)
    results.number("limit_q1", float(sol.y[1]), "1", note="q1 at τ = 80 from φ2 = 0, q1 = 0")
    results.number(
        "limit_q1_closed_form", float(limit), "1", note="√(m/ν): the rotation about +y, q = √(m/|μ|)"
    )
    results.hard_case(
        "settles_on_the_axis",
        "The drag stops the growth: $q_1$ tends to $\\sqrt{m/\\nu}$ "
        "($|q_1 - \\sqrt{m/\\nu}|$ at $\\tau = 80$)",
        abs(float(sol.y[1]) - limit) if sol.status == "success" else np.inf,
        RUNAWAY_BOUND,
    )
    # Euler's equations: the rotation about +y is a saddle, and plane II its stable manifold. A rounding error
    # off the plane grows like e^{phi2} against the in-plane part, so Euler's solution leaves the plane.
    full = solve(
        Problem(se.euler_middle, M.from_plane(0.0, 0.0), (0.0, 80.0 / M.time_scale), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        record_steps=True,
        bound=portrait.BLOW_UP_BOUND,
    )
    departure = M.plane_departure(full.y_steps)
    grown = np.cumprod(departure < 1e-4).astype(bool) & (departure > 1e-11)  # before it has left the plane
    slope = float(np.polyfit(M.to_plane(full.y_steps[grown])[:, 0], np.log(departure[grown]), 1)[0])
    results.number(
        "plane_departure_rate",
        slope,
        "1",
        note="d ln(departure)/dφ2 along Euler's equations (departure "
        "from 1e-11 to 1e-4): the plane repels like e^{φ2}",
    )
    results.hard_case(
        "plane_repels",
        "Plane II repels as $\\boldsymbol{\\omega}$ runs to $+y$: the departure $D$ "
        "of Euler's solution from the plane grows like $e^{\\varphi_2}$ "
        "($|d\\ln D/d\\varphi_2 - 1|$)",
        abs(slope - 1.0),
        0.01,
    )
