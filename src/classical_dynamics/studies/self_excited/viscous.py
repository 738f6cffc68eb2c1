"""Lee §5: the symmetric body in a viscous medium under a constant torque fixed in the body.

Lee's quadrature solution (through his generalized sine and cosine integrals, or Fresnel's without
friction) against Euler's equations integrated, and against itself with the integrals at 30 digits; its
error bound; the limiting rotation of Theorem 3 and the bounds of Theorem 1 with friction; the circles of
Theorem 2 without. With `analysis.special_functions`, what si and ci cost by series, asymptotic expansion
and quadrature, and what the solution costs by quadrature formula against integration. Each computation
returns its values and takes no Results; _record_<name> beside it writes them, and run records them in order.
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

import numpy as np
import pandas as pd

from ...figure_style import legend_below
from ...formatting import format_number, shortest
from ...models.self_excited.effects import medium_torque
from ...models.viscous_medium import ViscousMedium, symmetric_axis, viscous_symmetric
from ...results import new_figures
from ...solvers import sine_cosine_integrals as sc
from ...solvers import workprecision as wp
from ...solvers.ode import Problem, solve
from ...solvers.timing import min_time
from . import section5
from .accuracy import publish


def _complex(w, sig=None) -> str:
    """0.3 + 0.4i (the source's digits, or sig figures), with a real minus."""
    text = (lambda v: shortest(v)) if sig is None else (lambda v: format_number(v, sig))
    sign = " − " if w.imag < 0 else " + "
    return f"{text(float(w.real))}{sign}{text(abs(float(w.imag)))}i"


SAMPLES = 401
REFERENCE_SAMPLES = 41
CLOSED_VS_ODE_BOUND = 1e-9  # hard case: Lee's formula against Euler's equations (rtol 1e-13)
LIMIT_BOUND = 1e-6  # hard case: the state at t_max against Theorem 3's rotation


def medium(data) -> ViscousMedium:
    A, C = symmetric_axis(data["body"]["moments"])
    m, nu, mu = medium_torque(data.get("effects"))
    return ViscousMedium.from_moments(A, C, nu, mu, m, data["viscous"]["omega0"])


def run(scene, results, quick):
    data = scene.data
    V = medium(data)
    t_max = float(data["viscous"]["t_max"])
    source = data["viscous"].get("source", "chosen to show the case")
    for name, value, note in (
        ("h", V.h, "(A − C)/A"),
        ("nu", V.nu, "μ1/A, equatorial drag"),
        ("mu", V.mu, "μ0/C, axial drag"),
        ("m1", V.m[0], "M1/A"),
        ("m2", V.m[1], "M2/A"),
        ("m3", V.m[2], "M3/C"),
    ):
        results.number(
            name,
            value,
            "1/time" if name in ("nu", "mu") else ("1" if name == "h" else "1/time²"),
            note=note + ("; " + source if name == "h" else ""),
        )
    results.number("case", V.case, "", note="Lee's case of §5.3")
    results.number("t_max", t_max, "time", note="the end of the run")
    if V.generalized:
        results.number("w_real", V.w.real, "1", note="w1 = 1 + (ν + i g1)/μ of (5.27)")
        results.number("w_imag", V.w.imag, "1")
        results.number("g", V.g, "1", note="(h/μ)(r0 − m3/μ)")

    sol = solution(V, t_max)
    _record_solution(results, sol, t_max)
    asymptotic = asymptotics(V, sol.ode)
    _record_asymptotics(results, asymptotic, t_max)
    analysis = data.get("analysis", {})
    panels, more = [], ""
    for name, (check, record, draw) in section5.PANELS.items():
        if analysis.get(name):
            values = check(V)
            record(results, values)
            extra, text = draw(values)
            panels, more = panels + extra, more + text
    for name, (check, record) in section5.ANALYSES.items():
        if analysis.get(name):
            record(results, check(V))
    fig = _figure(V, sol.t, sol.closed, sol.ode, asymptotic.points, panels)
    results.figure("solution", fig, _caption(V, t_max, more))
    if analysis.get("special_functions"):
        _record_special_function_costs(results, special_function_costs(quick))
        _record_solution_costs(results, solution_costs(V, quick))
        _record_large_order(results, large_order(V))


class Solution(NamedTuple):
    """Lee's quadrature solution against Euler's equations integrated and against itself at 30 digits."""

    t: np.ndarray
    ode: object  # the integration (t_eval, y_eval)
    closed: np.ndarray  # Lee's quadratures at t
    deviation: float  # largest |closed - ode|
    error: float  # largest distance of (p, q) from the formula with si, ci at 30 digits
    bound: float  # the formula's own largest bound
    error_over_bound: float  # largest error/(bound + 1e-13)


def solution(V, t_max) -> Solution:
    t = np.linspace(0.0, t_max, SAMPLES)
    ode = solve(
        Problem(viscous_symmetric, list(V.omega0), (0.0, t_max), V.parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=t,
    )
    closed, bound = V.closed_form(t)
    deviation = float(np.max(np.abs(closed - ode.y_eval)))
    every = (SAMPLES - 1) // (REFERENCE_SAMPLES - 1)
    exact, _ = V.closed_form(t[::every], integrals=sc.reference_value)
    error = np.hypot(*(closed[::every, :2] - exact[:, :2]).T)
    return Solution(
        t,
        ode,
        closed,
        deviation,
        float(error.max()),
        float(bound.max()),
        float(np.max(error / (bound[::every] + 1e-13))),
    )


def _record_solution(results, values: Solution, t_max):
    deviation = values.deviation
    results.number(
        "closed_vs_ode",
        deviation,
        "1/time",
        note="Lee's quadratures against Euler's equations (DOP853, rtol 1e-13), max over p, q, r and t",
    )
    results.hard_case(
        "closed_form_vs_euler",
        "Lee's quadrature solution against Euler's equations integrated, "
        f"$t \\le$ {shortest(t_max)} (largest $|\\Delta\\boldsymbol{{\\omega}}|$)",
        deviation,
        CLOSED_VS_ODE_BOUND,
    )
    results.number(
        "closed_form_error",
        values.error,
        "1/time",
        note="against the same formula with si, ci at 30 digits (mpmath), max over t",
    )
    results.number(
        "closed_form_bound",
        values.bound,
        "1/time",
        note="the formula's own bound, from those of the series and expansions, max over t",
    )
    results.hard_case(
        "closed_form_within_bound",
        "The quadrature solution's error (against $\\si$, $\\ci$ at 30 "
        "digits) over its own bound (10⁻¹³ added for round-off), largest over $t$",
        values.error_over_bound,
        1.0,
    )


class Limit(NamedTuple):
    """With friction: Theorem 3's uniform rotation and Theorem 1's bounds."""

    limit: np.ndarray  # (p, q, r)
    gap: float  # |omega(t_max) - limit|
    theorem_1_ratio: float  # the larger of max |p|, |q| and max |r| over their bounds, t > 0
    kind: str  # stable focus or node

    @property
    def points(self):
        return [self.limit]


class Circle(NamedTuple):
    """Without friction, m3 = 0: Theorem 2's circles."""

    center: np.ndarray
    radius_spread: float  # relative, along the circle
    period: float  # 2 pi/|h r0|
    period_measured: float  # from the angle swept about the center
    period_gap: float  # relative

    @property
    def points(self):
        return [self.center]


class Unbounded(NamedTuple):
    """Without friction, m3 != 0: r grows without bound, p and q stay bounded."""

    pq_max: float
    r_final: float

    @property
    def points(self):
        return []


def asymptotics(V, ode):
    """Theorem 1 and 3 with friction, Theorem 2 (circles) without, or the unbounded growth of r: Limit,
    Circle or Unbounded, each with the scene's singular points (points)."""
    y = ode.y_eval
    limit = V.limit()
    if limit is not None:
        gap = float(np.max(np.abs(y[-1] - limit)))
        pq_bound, r_bound = V.bounds()
        later = y[1:]  # Theorem 1 holds for t > 0: at t = 0, |r| = |r0| is its bound when m3 = 0
        ratio = max(
            float(np.max(np.abs(later[:, :2]))) / pq_bound, float(np.max(np.abs(later[:, 2]))) / r_bound
        )
        return Limit(limit, gap, ratio, "stable focus" if V.g1 != 0.0 else "stable node")
    center = V.circle_center()
    if center is not None:
        radius = np.hypot(y[:, 0] - center[0], y[:, 1] - center[1])
        period = 2 * np.pi / abs(V.h * V.omega0[2])
        angle = np.unwrap(np.arctan2(y[:, 1] - center[1], y[:, 0] - center[0]))
        measured = 2 * np.pi * (ode.t_eval[-1] - ode.t_eval[0]) / abs(angle[-1] - angle[0])
        return Circle(
            center, float(np.ptp(radius) / radius[0]), period, measured, abs(measured / period - 1.0)
        )
    return Unbounded(float(np.max(np.abs(y[:, :2]))), float(y[-1, 2]))


def _record_asymptotics(results, values, t_max):
    if isinstance(values, Limit):
        limit, gap, ratio = values.limit, values.gap, values.theorem_1_ratio
        for k, name in enumerate("pqr"):
            results.number(
                f"limit_{name}",
                float(limit[k]),
                "1/time",
                note="Theorem 3: (νm1 + g1m2, νm2 − g1m1)/(ν² + g1²), m3/μ",
            )
        results.number("limit_gap", gap, "1/time", note=f"|ω(t = {t_max:g}) − Theorem 3's rotation|")
        results.hard_case(
            "limiting_rotation",
            f"Euler's equations at $t$ = {shortest(t_max)} against Theorem 3's uniform rotation",
            gap,
            LIMIT_BOUND,
        )
        results.number(
            "theorem_1_ratio",
            ratio,
            "1",
            note="Theorem 1: the larger of max |p|, |q| over δ + (|m1| + "
            "|m2|)/ν and max |r| over |r0| + |m3|/μ, for 0 < t ≤ t_max",
        )
        results.hard_case(
            "theorem_1_bounds",
            "Theorem 1: the largest $|p|$, $|q|$ over its bound "
            "$\\delta + (|m_1| + |m_2|)/\\nu$, and $|r|$ over $|r_0| + |m_3|/\\mu$ (the larger ratio, "
            "$t > 0$)",
            ratio,
            1.0,
        )
        results.number(
            "singular_points",
            [{"p": float(limit[0]), "q": float(limit[1]), "r": float(limit[2]), "type": values.kind}],
            "1/time",
            note="the uniform rotation all motions tend to",
        )
    elif isinstance(values, Circle):
        center = values.center
        results.number("radius_spread", values.radius_spread, "1", note="relative, along the circle")
        results.hard_case(
            "circle_closed",
            "Without friction, $m_3 = 0$: $\\boldsymbol{\\omega}$ keeps its circle "
            "about Theorem 2's center (relative spread of the radius)",
            values.radius_spread,
            1e-10,
        )
        results.number(
            "period_tau",
            float(values.period),
            "time",
            note="2π/|h r0| (Theorem 2); §5 has no reduced time: τ = t",
        )
        results.number(
            "period_measured",
            float(values.period_measured),
            "time",
            note="from the angle swept about the center",
        )
        results.hard_case(
            "circle_period", "The circles' period against $2\\pi/|hr_0|$ (relative)", values.period_gap, 1e-9
        )
        results.number(
            "singular_points",
            [{"p": float(center[0]), "q": float(center[1]), "r": float(center[2]), "type": "center"}],
            "1/time",
            note="Theorem 2: a stable permanent rotation",
        )
    else:
        results.number(
            "singular_points",
            [],
            "1/time",
            note="none: without friction and with m3 ≠ 0, r grows without bound while p and q stay bounded",
        )
        results.number("pq_max", values.pq_max, "1/time", note="max |p|, |q| (bounded, Fresnel)")
        results.number("r_final", values.r_final, "1/time", note="r = r0 + m3 t")


def _figure(V, t, closed, ode, points, panels=()):
    fig, axes = new_figures(2 + len(panels), height=3.0)
    ax, bx = axes[:2]
    for draw, cx in zip(panels, axes[2:]):
        draw(cx)
    for k, (name, color) in enumerate(zip("pqr", ("#000000", "#E69F00", "#56B4E9"))):
        ax.plot(t, closed[:, k], color=color, lw=1.0, label=f"${name}$, Lee's quadratures")
        ax.plot(ode.t_eval[::10], ode.y_eval[::10, k], ".", color=color, ms=3)
    ax.plot([], [], "k.", ms=3, label="Euler's equations, integrated")
    ax.set_xlabel("$t$ (time units)")
    ax.set_ylabel("$p$, $q$, $r$ (rad per time unit)")
    fine, _ = V.closed_form(np.linspace(0.0, t[-1], 4 * SAMPLES - 3))  # the spiral drawn smooth
    bx.plot(fine[:, 0], fine[:, 1], color="#000000", lw=0.9)
    for extra in _extra_starts(V)[0]:
        y, _ = extra.closed_form(np.linspace(0.0, t[-1], 800))
        bx.plot(y[:, 0], y[:, 1], color="0.6", lw=0.6)
    for pt in points:
        bx.plot(pt[0], pt[1], "+", color="#D55E00", ms=9, mew=1.5)
    bx.set_xlabel("$p$ (rad per time unit)")
    bx.set_ylabel("$q$ (rad per time unit)")
    bx.set_aspect("equal", adjustable="datalim")
    legend_below(fig, *ax.get_legend_handles_labels(), ncol=4)
    return fig


def _extra_starts(V):
    """Figures 5.4 and 5.5: more circles about Theorem 2's center, or a start in the plane r = m3/mu (g = 0),
    whose spiral is elementary; and what the caption says of them."""
    if V.circle_center() is not None:
        return (
            [replace(V, omega0=(V.omega0[0] * f, V.omega0[1] * f, V.omega0[2])) for f in (0.4, 0.7, 1.4)],
            ", with Theorem 2's center (+) and, grey, the concentric circles of other starts (Lee's Figure "
            "5.4)",
        )
    if V.limit() is not None and V.m[2] != 0.0:
        return (
            [replace(V, omega0=(V.omega0[0], V.omega0[1], V.m[2] / V.mu))],
            ", with the limiting rotation (+) and, grey, a start in the plane $r = m_3/\\mu$ that spirals "
            "into it "
            "(Lee's Figure 5.5)",
        )
    return [], ""


def _triple(values) -> str:
    return "(" + ", ".join(shortest(float(v)) for v in values) + ")"


def _caption(V, t_max, more=""):
    what = {
        "I": "Case I: straight lines to $(m_1/\\nu, m_2/\\nu, 0)$",
        "II": "Case II: $m_3 = 0$, $r_0 \\ne 0$",
        "III": "Case III: $m_3 \\ne 0$",
        "III (g = 0)": "Case III with $r_0 = m_3/\\mu$, elementary",
        "IV": "Case IV: $h = 0$",
    }
    friction = (
        f"with friction $\\nu$ = {shortest(V.nu)}, $\\mu$ = {shortest(V.mu)}"
        if V.friction
        else "without friction"
    )
    return (
        f"Lee §5, {what[V.case]}; {friction}, $h$ = {shortest(V.h)}, $(m_1, m_2, m_3)$ = {_triple(V.m)}, "
        f"$\\boldsymbol{{\\omega}}_0$ = {_triple(V.omega0)}, $t \\le$ {shortest(t_max)}. Left: $p$, $q$, $r$ "
        "against $t$ from Lee's quadrature solution (lines) and from Euler's equations integrated (dots). "
        f"{'Second panel' if more else 'Right'}: "
        "the end of $\\boldsymbol{\\omega}$ projected on the equatorial plane, $(p, q)$ on equal axes"
        f"{_extra_starts(V)[1]}{more}."
    )


X_POINTS = (0.5, 2.0, 10.0, 30.0)
W_POINTS = (0.3 + 0.4j, 1.7 + 0.5j)


class SpecialFunctionCosts(NamedTuple):
    frame: pd.DataFrame  # si at 30 digits, each method's error and bound (table si_ci_values)
    error_over_bound: float  # largest: the series (10^-16 added to its bound) and the expansion
    bounds_exceeded: int  # rows where the series' or the expansion's error exceeds its bound
    timing: pd.DataFrame  # error and wall time by method and setting at x = 2 and 30 (table si_ci_costs)
    reaches: dict  # {(x, method): 1 if it reaches 1e-12, else 0}, mpmath left out


def special_function_costs(quick) -> SpecialFunctionCosts:
    """Table T-D of the digest: si, ci by series, expansion and quadrature against 30 digits, with bounds;
    and error against time for each method at x = 2 and x = 30."""
    rows = []
    for w in W_POINTS:
        for x in X_POINTS:
            ref_si, ref_ci = (complex(v) for v in sc.reference(x, w))
            row = {"w": _complex(w), "x": x, "si_real": ref_si.real, "si_imag": ref_si.imag}
            for name, f in (
                ("series", sc.series),
                ("asymptotic", sc.asymptotic),
                ("quadrature", sc.quadrature),
            ):
                v = f(x, w)
                row[f"{name}_error"] = max(abs(v.si - ref_si), abs(v.ci - ref_ci))
                row[f"{name}_bound"] = v.bound
            rows.append(row)
    frame = pd.DataFrame(rows)
    held = (frame.series_error <= frame.series_bound + 1e-16) & (
        frame.asymptotic_error <= frame.asymptotic_bound
    )
    ratio = np.maximum(
        frame.series_error / (frame.series_bound + 1e-16), frame.asymptotic_error / frame.asymptotic_bound
    )
    timing_rows = []
    w = W_POINTS[0]
    for x in (2.0, 30.0):
        ref_si, ref_ci = (complex(v) for v in sc.reference(x, w, dps=40))

        def err(v):
            return max(abs(complex(v.si) - ref_si), abs(complex(v.ci) - ref_ci))

        settings = [("series", n, lambda n=n: sc.series(x, w, terms=n)) for n in (2, 4, 6, 8, 12, 20, 30, 45)]
        settings += [
            ("asymptotic", n, lambda n=n: sc.asymptotic(x, w, terms=n)) for n in (1, 2, 4, 8, 16, 30)
        ]
        settings += [
            ("quadrature (scipy QAWO)", e, lambda e=e: sc.quadrature(x, w, epsabs=e))
            for e in (1e-4, 1e-8, 1e-12, 1e-15)
        ]
        settings += [
            (
                "mpmath incomplete gamma",
                d,
                lambda d=d: sc.Value(*map(complex, sc.reference(x, w, dps=d)), 0.0, 0),
            )
            for d in (15, 20, 30)
        ]
        for method, setting, run in settings[::2] if quick else settings:
            seconds, value, _ = min_time(run, repeats=5, budget_s=0.2)
            timing_rows.append(
                {
                    "x": x,
                    "method": method,
                    "kind": "setting",
                    "setting": setting,
                    "error": err(value),
                    "bound": value.bound,
                    "seconds": seconds,
                }
            )
    timing = pd.DataFrame(timing_rows)
    reaches = {}
    for x in (2.0, 30.0):
        part = timing[(timing.x == x) & (timing.method != "mpmath incomplete gamma")]
        for method, rows_ in part.groupby("method"):
            good = rows_[rows_.error <= 1e-12]
            reaches[x, method] = int(len(good) > 0)
    return SpecialFunctionCosts(frame, float(ratio.max()), int((~held).sum()), timing, reaches)


def _record_special_function_costs(results, values: SpecialFunctionCosts):
    frame, timing = values.frame, values.timing
    w = W_POINTS[0]  # the timings'
    results.table(
        "si_ci_values",
        frame,
        "Lee's generalized sine integral $\\si(x, w)$ at 30 digits (the incomplete "
        "gamma function of mpmath), and the error (the larger over $\\si$ and $\\ci$) and error bound of "
        "each way to compute it in double precision: the series, Lee (5.38) and (5.39), with the reduction, "
        "Lee (5.32) and (5.33), summed until the Lagrange bound, Lee (5.40) and (5.41), is below 10⁻¹⁶ of "
        "the sum, plus a round-off estimate; the asymptotic expansion, Lee (5.42)–(5.48), cut at its "
        "smallest remainder bound, Lee (5.45); and quadrature (SciPy's QAWO over $[x, 40]$, the expansion "
        "beyond, with its own error estimate).",
        headers={
            "w": "$w$",
            "x": "$x$",
            "si_real": "$\\Re\\,\\si(x, w)$",
            "si_imag": "$\\Im\\,\\si(x, w)$",
            "series_error": "series error",
            "series_bound": "series bound",
            "asymptotic_error": "expansion error",
            "asymptotic_bound": "expansion bound",
            "quadrature_error": "quadrature error",
            "quadrature_bound": "quadrature estimate",
        },
    )
    results.number(
        "si_ci_error_over_bound",
        values.error_over_bound,
        "1",
        note="largest error/bound over the table "
        "si_ci_values, the series (10⁻¹⁶ added to its bound for round-off) and the expansion",
    )
    results.hard_case(
        "si_ci_bounds_hold",
        "Values of $\\si$, $\\ci$ where the series' or the expansion's error exceeds its bound (count)",
        values.bounds_exceeded,
        0,
    )
    results.number(
        "si_ci_digest_check_x2",
        float(frame.series_error[(frame.x == 2.0)].iloc[0]),
        "1",
        note="series error at x = 2, w = 0.3 + 0.4i",
    )
    for method in ("series", "asymptotic"):
        results.number(
            f"si_ci_{method}_error_x30",
            float(frame[f"{method}_error"][frame.x == 30.0].iloc[0]),
            "1",
            note="at x = 30, w = 0.3 + 0.4i",
        )
    caption = (
        f"What $\\si$ and $\\ci$ cost: the error (against 40 digits, the larger over the two) of "
        f"$\\si(x, w)$ and $\\ci(x, w)$ for $w$ = {_complex(w)}, by method and setting (series and "
        "expansion: "
        "terms; quadrature: the absolute error requested; mpmath: digits), at $x = 2$ and $x = 30$."
    )
    headers = {
        "x": "$x$",
        "method": "method",
        "kind": "control",
        "setting": "terms, tolerance or digits",
        "error": "error",
        "bound": "error bound",
        "seconds": "wall time (s)",
    }
    results.table("si_ci_costs", timing.drop(columns=["seconds"]), caption, headers=headers)
    results.timing_table(
        "si_ci_costs",
        timing,
        caption + " With the wall time of each, the minimum over repeated runs.",
        headers=headers,
    )
    fig, axes = new_figures(2, height=3.0)
    axes[1].sharey(axes[0])
    drawn = timing.assign(error=np.minimum(timing.error, 1.0))  # the expansion diverges: cut at 1
    for ax, x in zip(axes, (2.0, 30.0)):
        wp.plot(
            drawn[drawn.x == x],
            ax,
            error="error",
            floor=1e-18,
            xlabel="error of $\\mathrm{si}$, $\\mathrm{ci}$",
        )
        ax.set_xlim(3.0, 1e-19)
        ax.set_title(f"$x = {x:g}$")
    axes[1].set_ylabel("")
    legend_below(fig, *axes[0].get_legend_handles_labels(), ncol=4)
    results.timing_figure(
        "si_ci_costs",
        fig,
        f"What $\\si$ and $\\ci$ cost: wall time against the error (against 40 "
        f"digits, the larger over the two) of $\\si(x, w)$ and $\\ci(x, w)$ for $w$ = {_complex(w)}, "
        "one line per method through its settings (series and expansion: terms; quadrature: the "
        "absolute error requested; mpmath: digits), at $x = 2$ (left) and $x = 30$ (right). Errors "
        "above 1 (the expansion diverges at $x = 2$) are drawn at 1, errors below 10⁻¹⁸ at 10⁻¹⁸. "
        "The series serves small $x$, the expansion large $x$.",
    )
    for (x, method), reached in values.reaches.items():
        key = method.split(" ")[0]
        results.number(
            f"si_ci_reaches_1e-12_x{x:g}_{key}",
            reached,
            "1",
            note=f"whether {method} reaches 1e-12 at x = {x:g}",
        )


class SolutionCosts(NamedTuple):
    t_end: float
    case: str  # Lee's case of the scene
    frame: pd.DataFrame  # error and wall time by method and setting (a work-precision frame)


def solution_costs(V, quick, t_end=4.0) -> SolutionCosts:
    """The state at t_end by Lee's formula (series with a given number of terms) against integration, each
    against the formula at 30 digits."""
    exact = V.closed_form([t_end], integrals=sc.reference_value)[0][0]
    rows = []

    def add(method, kind, setting, run, repeats):
        seconds, y, _ = min_time(run, repeats=repeats, budget_s=0.3)
        rows.append(
            {
                "method": method,
                "kind": kind,
                "setting": setting,
                "error": float(np.max(np.abs(np.asarray(y)[:2] - exact[:2]))),
                "seconds": seconds,
            }
        )

    for n in (2, 3, 4, 6, 8, 12):
        add(
            "Lee formula, series",
            "terms",
            n,
            lambda n=n: V.closed_form([t_end], integrals=lambda x, w: sc.series(x, w, terms=n))[0][0],
            5,
        )
    problem = Problem(viscous_symmetric, list(V.omega0), (0.0, t_end), V.parameters())
    for method in ("dop853", "dopri5", "scipy:DOP853", "scipy:RK45"):
        for rtol in (
            (1e-6, 1e-9, 1e-12) if quick or method.startswith("scipy") else (1e-6, 1e-8, 1e-10, 1e-12, 1e-13)
        ):
            add(
                method,
                "tolerance",
                rtol,
                lambda m=method, r=rtol: solve(problem, m, rtol=r, atol=r * 1e-2).y,
                1 if method.startswith("scipy") else 5,
            )
    return SolutionCosts(t_end, V.case, pd.DataFrame(rows))


def _record_solution_costs(results, values: SolutionCosts):
    t_end = values.t_end
    caption = (
        f"What the solution costs: $\\boldsymbol{{\\omega}}$ at $t$ = {shortest(t_end)} "
        f"(Case {values.case}) by "
        "Lee's quadrature formula, with $\\si$ and $\\ci$ from the series cut at a given number of terms, "
        "and "
        "by integrating Euler's equations at a given relative tolerance; the error of $(p, q)$ against the "
        "formula with $\\si$, $\\ci$ at 30 digits."
    )
    results.number("solution_t_end", t_end, "time", note="the time at which the costs are measured")
    publish(
        results,
        values.frame,
        "solution",
        "error",
        caption,
        f"error of $(p, q)$ at $t$ = {shortest(t_end)}",
        {"setting": "terms or rtol", "error": "error of $(p, q)$"},
    )


class LargeOrder(NamedTuple):
    nu: float
    mu: float
    times: tuple
    w: complex  # 1 + (nu + i g1)/mu
    factor: float  # |g|^(nu/mu)/mu, which multiplies si, ci
    error: float  # largest against 30 digits
    bound: float  # the formula's own largest bound
    error_over_bound: float  # largest error/(bound + 1e-13)


def large_order(V, nu=0.32, mu=0.05, times=(5.0, 20.0, 40.0)) -> LargeOrder:
    """Hard case (digest §7 item 9): with mu small against nu, w = 1 + (nu + i g1)/mu is large, si and ci are
    tiny and are multiplied by |g|^(nu/mu)/mu: the formula loses digits. Its bound must say so, and hold."""
    W = replace(V, nu=nu, mu=mu)
    y, bound = W.closed_form(times)
    exact, _ = W.closed_form(times, integrals=sc.reference_value)
    error = np.hypot(*(y[:, :2] - exact[:, :2]).T)
    return LargeOrder(
        nu,
        mu,
        times,
        W.w,
        abs(W.g) ** (nu / mu) / mu,
        float(error.max()),
        float(bound.max()),
        float(np.max(error / (bound + 1e-13))),
    )


def _record_large_order(results, values: LargeOrder):
    nu, mu, w = values.nu, values.mu, values.w
    results.number("large_order_w_real", w.real, "1", note=f"ν = {nu:g}, μ = {mu:g}")
    results.number("large_order_w_imag", w.imag, "1")
    results.number("large_order_factor", values.factor, "1", note="|g|^(ν/μ)/μ, which multiplies si, ci")
    results.number(
        "large_order_error", values.error, "1/time", note=f"against 30 digits, t in {list(values.times)}"
    )
    results.number("large_order_bound", values.bound, "1/time", note="the formula's own bound")
    results.hard_case(
        "large_order_bound_holds",
        f"Large order $w$ = {_complex(w, 3)}: the formula's error over its "
        "own bound (10⁻¹³ added for round-off), largest over $t$",
        values.error_over_bound,
        1.0,
    )
