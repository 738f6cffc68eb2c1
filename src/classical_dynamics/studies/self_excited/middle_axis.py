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

from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

from ...figure_style import TEXT_WIDTH_IN
from ...models import self_excited as se
from ...results import new_figure
from ...solvers.ode import Events, Problem, solve
from . import accuracy, excursions, portrait, rare_case
from .bounds import INVARIANT_BOUND, OVERLAY_BOUND, PLANE_DEPARTURE

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
RUNAWAY_BOUND = 1e-8  # hard case: the unperturbed escape, dq1/dtau -> m3


def run(scene, results, quick):
    data = scene.data
    body = se.Body.from_moments(data["body"]["moments"])
    plane = data["plane"]
    m1, nu = se.plane_torque(data.get("effects"))
    nu = se.MiddleAxis.plane_nu(nu, body)
    alpha1, alpha2 = (float(x) for x in plane["alpha"])
    M = se.MiddleAxis.for_scene(body, m1, -nu, alpha1, alpha2)
    m1 = float(M.m1) if m1 is None else float(m1)
    lo, hi = data.get("portrait", {}).get("phi2_range", [-4.0, 4.0])
    q1_max = data.get("portrait", {}).get("p1_max", 3.0)
    reduced = reduction(M, m1)
    _record_reduction(results, M, plane, m1, nu, reduced)
    points = reduced.points

    fig, ax = new_figure(TEXT_WIDTH_IN, 3.6)
    drawing = portrait.Drawing("q1", (lo - 0.5, hi + 0.5, 2.0 * q1_max))
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    # a degenerate point has a separatrix too
    saddles = [pt["phi2"] for pt in points if pt["type"] != "center"]
    starts, others = _starts(M.form, centers, saddles, lo, hi)
    for y in portrait.trajectories(se.plane_middle, M.plane_parameters, starts + others, 30.0):
        drawing.curve("trajectory", y[:, 0], y[:, 1])
    if starts:
        _record_orbits_close(results, orbits_close(M, starts))
    _separatrix(drawing, M, saddles, centers, lo, hi)
    _fates(results, drawing, M, points, centers, saddles, others)
    overlay_starts = starts[:3] + others[:1] if starts else others[2:6]
    mapped = overlay(M, overlay_starts)
    for curve in mapped.curves:
        drawing.curve("euler", curve[:, 0], curve[:, 1])
    _record_overlay(results, M, mapped)
    drawing.points(points)
    drawing.window(lo, hi, q1_max)
    portrait.finish(ax, drawing, "$q_1$")
    results.figure(
        "portrait", fig, _caption(M, drawing, points, m1, nu, alpha1 == alpha2, len(overlay_starts))
    )
    drawing.save(
        results,
        "What the portrait draws, point by point: each element (trajectory, separatrix or the "
        "curve $c_1 = 0$, line of rest points, Euler's equations mapped into the plane, singular point by "
        "type, "
        "the window's corners) and its curve number, in $(\\varphi_2, q_1)$.",
    )
    if centers:
        _series(results, M, centers[0], nu)
    _middle_checks(results, M, overlay_starts, centers)
    if "excursion" in data:
        start = excursions.excursion_start(M, float(data["excursion"]["q0"]))
        excursions.record_excursion(results, excursions.excursion_orbit(M, start))
        accuracy.record_huge_excursion(results, accuracy.excursion_runs(M, start, quick), M, start[0][1])


class Reduction(NamedTuple):
    nu_c: float  # b/(2(a + c)): above it the cosh form
    points: list  # the singular points: {"phi2", "p1", "type"}


def reduction(M, m1) -> Reduction:
    """The critical drag and the plane's singular points (m1: the scene's, or the plane's if it has none)."""
    return Reduction(se.MiddleAxis.plane_nu("nu_c", M.body), _singular_points(m1, M.form, M.eps1))


def _record_reduction(results, M, plane, m1, nu, values: Reduction):
    """The plane's parameters, the physical torque that gives them, and its singular points."""
    form, name = M.form, LABELS[M.form]
    results.number(
        "m1", m1, "1", note=f"{name} of the plane: " + plane.get("source", "chosen to show the regime")
    )
    results.number("nu", nu, "1", note="mu1 = −nu")
    results.number("nu_c", values.nu_c, "1", note="b/(2(a + c)): above it the cosh form (3.56) takes over")
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
    results.number("hyperbola", M.alpha1**2 - M.alpha2**2, "1", note="p²/a − r²/c = α1² − α2²")
    points = values.points
    results.number(
        "singular_points", points, "1", note=f"q1 = 0 where {name} + ε f(φ2) = 0, typed by the linearization"
    )
    for kind in ("saddle", "center", "degenerate"):
        results.number(f"n_{kind}s", sum(pt["type"] == kind for pt in points), "1")


def _starts(form, centers, saddles, lo, hi):
    """The portrait's starts: (about the center, elsewhere in the window)."""
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
    return starts, others


def orbits_close(M, starts) -> int:
    """Orbits about the center close: each turns back twice. Returns how many of the starts' orbits do not."""
    closed = 0
    for phi, q1 in starts:
        sol = solve(
            Problem(se.plane_middle, [phi, q1], (0.0, 200.0), M.plane_parameters()),
            "dop853",
            rtol=1e-12,
            atol=1e-14,
            events=Events(portrait.velocity_zero, 1, (-1,)),
            bound=portrait.BLOW_UP_BOUND,
        )
        closed += len(sol.event_t) >= 2
    return len(starts) - closed


def _record_orbits_close(results, not_closed: int):
    results.hard_case(
        "orbits_about_the_center_closed",
        "Starts about the center whose orbit does not close "
        "(count; Lee: every motion is periodic for $|\\mu| < \\mu_\\mathrm{c}$, and inside the "
        "saddle's loop or $F$ otherwise)",
        not_closed,
        0,
    )


def _fates(results, drawing, M, points, centers, saddles, others):
    """Each fate Lee names where this plane has it: every start escapes, the rare case's blow-up and rest
    line, motions of the third kind, the unperturbed runaway, settling to a finite limit. Picks the checks
    and records them."""
    if M.mu1 < 0 and _turns_nowhere(M):
        _record_every_start_escapes(results, every_start_escapes(M, others))
    if M.form == "rare":
        rare_case.record_escape(results, rare_case.escape_motion(M))
        if M.m1 == 0.0:
            rare_case.record_rest_line(drawing, results, rare_case.rest_line_motion(M))
    else:
        escape = _escaping_start(M, centers, saddles)
        if escape is not None:
            _record_third_kind(results, third_kind(M, escape))
    if M.mu1 == 0.0 and not points:
        _record_runaway(results, M, runaway(M))
    if M.mu1 < 0 and not points and M.m1 > 0 and not _turns_nowhere(M):
        _record_settles(results, settles(M))


def _record_overlay(results, M, values: Overlay):
    """Euler's equations mapped into the plane: on the plane's trajectories, keeping its first integral, and
    on their hyperbolic cylinder."""
    deviation, hyp, invariant, share = (
        values.deviation,
        values.cylinder_spread,
        values.invariant,
        values.share,
    )
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


def _caption(M, drawing, points, m1, nu, plane_one, n_overlay):
    """The portrait's caption: the equation and plane, the regime, what its shape is, what each ink draws."""
    form = M.form
    regime = f"{SYMBOLS[form] if form != 'rare' else '$m$'} = {portrait.param_text(m1)}"
    regime += f", $\\nu$ = {portrait.param_text(nu)}" if nu else ", unperturbed ($\\nu = 0$)"
    drawn = drawing.elements()
    black = (
        "; black: the separatrix from the closed form"
        if "separatrix" in drawn
        else "; black: the curve $c_1 = 0$ of the closed form"
        if "curve_C0" in drawn
        else ""
    )
    if "rest_line" in drawn:
        black += "; the line of rest points in colour"
    marked = "; markers: the singular points, by type" if points else ""
    where = {
        "exp": "plane I ($\\alpha_1 = \\alpha_2$)" if plane_one else "$|\\mu| = \\mu_\\mathrm{c}$",
        "exp-": "plane II ($\\alpha_1 = -\\alpha_2$)",
        "rare": "plane II at $\\nu = \\nu_\\mathrm{c}$, Lee's rare case ($k_1 = k_2 = 0$; "
        "here $\\tau = t$ and $\\varphi_2 = 2\\sqrt{ac}\\,\\varphi$)",
    }
    return (
        f"Phase plane of {EQUATIONS[form]} for the torque along the middle axis $y$"
        f"{', ' + where[form] if form in where else ''}; {regime}: {_shape(M, points)}. Grey: trajectories "
        f"of the plane{black}{marked}; dots: {portrait.COUNTS[n_overlay]} integrations of Euler's "
        "equations in three dimensions, mapped into the plane, which lie on the plane's trajectories."
    )


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
            rare_case.RARE_REST
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


def every_start_escapes(M, starts) -> int:
    """How many of the starts do not leave every bound in finite time."""
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
    return stayed


def _record_every_start_escapes(results, stayed: int):
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
    """Through the saddle or degenerate point; without one, Lee's F (c1 = 0 of (3.60)) about the center of the
    exponential form, or the lines q1 = +-sqrt(m/nu) of the rare case."""
    bounding = M.form == "exp" and centers or M.form == "rare" and M.m1 > 0
    if M.mu1 == 0.0 or not (saddles or bounding):
        return
    C = (
        -se.middle_g(saddles[0], M.m1, M.mu1, M.eps1, M.form) * np.exp(-2 * M.mu1 * saddles[0])
        if saddles
        else 0.0
    )

    def square(x):
        return C * np.exp(2 * M.mu1 * x) + se.middle_g(x, M.m1, M.mu1, M.eps1, M.form)

    phi = np.linspace(lo, hi, 3001)
    sq = square(phi)
    # where q1^2 changes sign the curve turns at q1 = 0: that point is added, so the two halves meet there
    # rather than a grid step short of the axis
    turns = np.nonzero(np.sign(sq[:-1]) * np.sign(sq[1:]) < 0)[0]
    roots = [brentq(square, phi[i], phi[i + 1], xtol=1e-14) for i in turns]
    phi = np.r_[phi, roots]
    sq = np.r_[sq, np.zeros(len(roots))]
    order = np.argsort(phi, kind="stable")
    phi, sq = phi[order], sq[order]
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
        turn = np.log(M.m1 * (1 - 2 * M.mu1) / (-2 * M.mu1))  # c1 = 0 (Lee (3.60)) at q1 = 0
        return [turn + 0.3, 0.0]
    return [0.0, 0.0] if _turns_nowhere(M) else None


class ThirdKind(NamedTuple):
    blows_up: bool  # the start leaves every bound in finite time
    t: float  # where the integration stopped (the blow-up time if it blows up)


def third_kind(M, start) -> ThirdKind:
    """A start outside the bounded region, integrated until it leaves every bound (or tau = 200)."""
    sol = solve(
        Problem(se.plane_middle, start, (0.0, 200.0), M.plane_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=portrait.BLOW_UP_BOUND,
    )
    return ThirdKind(sol.status == "blow-up", sol.t)


def _record_third_kind(results, values: ThirdKind):
    if values.blows_up:
        results.number(
            "blow_up_time",
            values.t,
            "τ",
            note="a start just outside the bounded region: ω leaves every "
            f"bound (|y| passes {portrait.BLOW_UP_BOUND:g})",
        )
    results.hard_case(
        "third_kind_blows_up",
        "A start outside the bounded region leaves every bound in finite time (1 if it does not)",
        0.0 if values.blows_up else 1.0,
        0.0,
    )


class Overlay(NamedTuple):
    """Euler's equations from the overlay's starts mapped into the plane, against the plane's solution."""

    deviation: float  # largest, relative to max(1, |plane's value|)
    cylinder_spread: float  # of p^2/a - r^2/c, relative
    invariant: float  # the plane's first integral's largest relative spread
    share: float  # of the samples compared
    curves: list  # each run mapped into the plane, every 5th compared sample: (phi2, q1) rows


def overlay(M, starts) -> Overlay:
    """Euler's equations from each start mapped into the plane against the plane's solution: the worst
    deviation, the spreads of the hyperbola and of the plane's first integral along Euler's rows, the share
    of samples compared, and the mapped runs to draw."""
    worst, hyp_worst, inv_worst, compared = 0.0, 0.0, 0.0, 0
    curves = []
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
        curves.append(mapped[::5])
    return Overlay(worst, hyp_worst, inv_worst, compared / (len(starts) * tau.size), curves)


def lyapunov_coefficients(M, center):
    """k^2, beta2, beta3 of the Lyapunov system about the center: minus the first, the second and the third
    derivative of F = m + eps f(phi2) there."""
    F = _derivatives(M.m1, M.form, M.eps1, center)
    return -F[1], F[2], F[3]


def _series(results, M, center, nu):
    """Lee §4: the Lyapunov system about the center, (4.13), (4.14), (4.15), (4.16). Records the series
    (portrait.series_periods measures the periods)."""
    k_sq, beta2, beta3 = lyapunov_coefficients(M, center)
    which = {"sinh": "(4.13)", "cosh": "(4.14)", "exp": "(4.15)", "exp-": "(4.16)"}[M.form]
    from . import middle_checks

    middle_checks.record_theta_series(results, middle_checks.theta_series(M, center, k_sq, beta2, beta3))
    values = portrait.series_periods(
        lambda eta: portrait.period(se.plane_middle, M.plane_parameters(), [center + eta, 0.0]),
        lambda eta: se.lyapunov_period(k_sq, beta2, beta3, -nu, eta),
        COSH_AMPLITUDES if M.form == "cosh" else AMPLITUDES,
    )
    portrait.record_series_check(
        results,
        values,
        f"Lee {which}: the period (in $\\tau$) of the oscillation about the center "
        f"$\\varphi_{{2\\mathrm{{c}}}}$ "
        "started at $\\varphi_{2\\mathrm{c}} + \\eta$, integrated from the plane system and from the series "
        "$(2\\pi/k)(1 + h_2\\eta^2 + h_3\\eta^3)$, and their relative difference.",
    )


def _middle_checks(results, M, starts, centers):
    """Lee (3.3)/(3.8), the planes (3.38)-(3.41), the center as a permanent rotation, the unstable middle axis
    and plane I's escape for large q0 (see middle_checks): picks those this plane has and records them."""
    from . import middle_checks as mc

    w0 = M.from_plane(*starts[0])
    mc.record_general_solution(results, mc.general_solution(M, w0, 12.0 / M.time_scale))
    if M.form in ("exp", "exp-") and abs(M.alpha1) == abs(M.alpha2):
        mc.record_plane_departure(results, mc.plane_departure(M, w0, 12.0 / M.time_scale))
    if centers:
        mc.record_center_at_rest(results, mc.center_at_rest(M, centers[0]))
    if M.form == "sinh" and M.mu1 == 0.0:
        mc.record_middle_axis_unstable(results, mc.middle_axis_unstable(M))
    if M.form == "exp" and M.alpha1 == M.alpha2 and M.mu1 < 0 and centers:
        mc.record_large_q0(results, mc.large_q0(M))


class Runaway(NamedTuple):
    """Unperturbed, no singular point: from phi2 = 0, q1 = 0."""

    rate: float  # dq1/dtau between tau = 40 and 60
    rate_gap: float  # |rate - m3|
    limit_q1: float | None  # with m3 = 0: q1 at tau = 60 (None otherwise)
    limit: float | None  # with m3 = 0: the closed form's limit -+sqrt(2E)
    limit_gap: float | None  # |q1 - limit| at tau = 60
    q_over_start: float | None  # the limiting |q| against |omega0|


def runaway(M) -> Runaway:
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
    if M.m1 != 0.0:
        return Runaway(rate, abs(rate - M.m1), None, None, None, None)
    E = float(se.middle_energy(start, 0.0, M.eps1, M.form)[0])
    limit = float(np.sign(sol.y_eval[-1, 1])) * np.sqrt(2 * E)
    q1 = float(sol.y_eval[-1, 1])
    return Runaway(
        rate,
        abs(rate - M.m1),
        q1,
        limit,
        abs(q1 - limit),
        abs(M.from_plane(0.0, limit)[1]) / np.linalg.norm(M.from_plane(0.0, 0.0)),
    )


def _record_runaway(results, M, values: Runaway):
    results.number(
        "runaway_rate", values.rate, "1/τ", note="dq1/dτ between τ = 40 and 60, from φ2 = 0, q1 = 0"
    )
    results.hard_case(
        "runaway_rate",
        f"Unperturbed, no singular point: $q_1$ changes at the rate {SYMBOLS[M.form]} "
        "($|dq_1/d\\tau - m_3|$ late in the motion)",
        values.rate_gap,
        RUNAWAY_BOUND,
    )
    if values.limit_q1 is not None:
        results.number("limit_q1", values.limit_q1, "1", note="q1 at τ = 60")
        results.number(
            "limit_q1_closed_form", values.limit, "1", note="±√(2E): all of the energy in q1 once e^{±φ2} → 0"
        )
        results.number(
            "limit_q_over_start",
            values.q_over_start,
            "1",
            note="the limiting |q| against |ω0|: ω tends to the y axis with finite modulus",
        )
        results.hard_case(
            "force_free_limit",
            "No torque in a plane of the separating polhodes: $q_1$ tends to the "
            "finite limit $\\pm\\sqrt{2E}$ ($|q_1 - \\text{limit}|$ at $\\tau = 60$)",
            values.limit_gap,
            RUNAWAY_BOUND,
        )


class Settles(NamedTuple):
    """With the drag, no singular point: from phi2 = 0, q1 = 0."""

    q1: float  # at tau = 80
    limit: float  # sqrt(m/nu)
    gap: float  # |q1 - limit| (inf if the run did not reach tau = 80)
    departure_rate: float  # d ln(departure from plane II)/d phi2 along Euler's equations
    departure_rate_gap: float  # |departure_rate - 1|


def settles(M) -> Settles:
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
    gap = abs(float(sol.y[1]) - limit) if sol.status == "success" else np.inf
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
    return Settles(float(sol.y[1]), float(limit), gap, slope, abs(slope - 1.0))


def _record_settles(results, values: Settles):
    results.number("limit_q1", values.q1, "1", note="q1 at τ = 80 from φ2 = 0, q1 = 0")
    results.number(
        "limit_q1_closed_form", values.limit, "1", note="√(m/ν): the rotation about +y, q = √(m/|μ|)"
    )
    results.hard_case(
        "settles_on_the_axis",
        "The drag stops the growth: $q_1$ tends to $\\sqrt{m/\\nu}$ "
        "($|q_1 - \\sqrt{m/\\nu}|$ at $\\tau = 80$)",
        values.gap,
        RUNAWAY_BOUND,
    )
    results.number(
        "plane_departure_rate",
        values.departure_rate,
        "1",
        note="d ln(departure)/dφ2 along Euler's equations (departure "
        "from 1e-11 to 1e-4): the plane repels like e^{φ2}",
    )
    results.hard_case(
        "plane_repels",
        "Plane II repels as $\\boldsymbol{\\omega}$ runs to $+y$: the departure $D$ "
        "of Euler's solution from the plane grows like $e^{\\varphi_2}$ "
        "($|d\\ln D/d\\varphi_2 - 1|$)",
        values.departure_rate_gap,
        0.01,
    )
