"""Lee §2.5-§2.6 for the torque along the largest axis: what the limit cycles mean for the body.

- Figure 2.12: the separatrices T1 (leaving the saddle S1) and T2 (entering the next saddle S2), integrated
  from the saddles' eigenvectors, their crossings f1, f2 of the vertical through the center C and g1, g2
  further on; f1 - f2 changes sign where nu crosses nu* (found by bisection on the integrated crossings).
- On F, omega returns to its start after one turn of (q, r) (two turns of phi2), (q, r) reversed after one.
- The permanent rotations p = +-sqrt(m/|mu|) about x: the + one stable, the - one leaving at 2 sqrt(m|mu|); F
  shrinks onto the + one as delta -> 0 (mean of p on F).
- Below F1 omega runs to the negative x-axis with |omega| -> infinity; just above F1 it tends to F.
- Lee §2.6: other torques that reduce to the same planes, integrated in three dimensions and mapped.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from ...solvers.runge_kutta import rhs_function
from . import portrait

SADDLE_OFFSET = 1e-7  # the start of T1, T2 off the saddle along the eigenvector (error ~ offset^2)
CROSSING_BOUND = 1e-8  # hard case: the integrated crossings against the closed form (2.13)
NAMES = {1: "$f_1$", 2: "$f_2$", 3: "$g_1$", 4: "$g_2$"}  # curve numbers of the crossings in zoom.csv


@rhs_function
def _crossings(t, y, p, out):
    """Events on (phi2, p1): phi2 through p[3] (the center's vertical), through p[4] (the far saddle's), p1 =
    0."""
    out[0] = y[0] - p[3]
    out[1] = y[0] - p[4]
    out[2] = y[1]


def _separatrix(m1, nu, which, samples=400):
    """T1 (which = 1: out of S1 forward in tau) or T2 (which = 2: into S2, backward in tau) of the plane
    (2.10), S1 at asin(-m1), C at pi - asin(-m1), S2 = S1 + 2 pi. Returns (f: height at C's vertical, end:
    (phi2, p1) where the curve stops: the far saddle's vertical or the phi2-axis, which: 'vertical' or 'axis',
    the curve)."""
    s1 = float(np.arcsin(-m1))
    c, s2 = np.pi - s1, s1 + 2 * np.pi
    lam = float(np.sqrt(np.cos(s1)))  # the saddles' rate (the p1^2 term is second order)
    eps = SADDLE_OFFSET
    if which == 1:
        start, direction, far = [s1 + eps, lam * eps], 1.0, s2
        dirs = (1, 1, -1)
    else:
        start, direction, far = [s2 - eps, lam * eps], -1.0, s1
        dirs = (-1, -1, -1)
    params = [m1, -nu, direction, c, far]
    sol = solve(
        Problem(se.plane_largest, start, (0.0, 200.0), params),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        events=Events(_crossings, 3, dirs, (False, True, True)),
        bound=portrait.BLOW_UP_BOUND,
    )
    at_c = sol.event_y[sol.event_index == 0]
    f = float(at_c[0, 1]) if len(at_c) else np.nan
    ends = sol.event_index[sol.event_index > 0]
    kind = "vertical" if len(ends) and ends[-1] == 1 else ("axis" if len(ends) else "none")
    end = sol.y.copy()
    curve = solve(
        Problem(se.plane_largest, start, (0.0, sol.t), params),
        "dop853",
        rtol=1e-10,
        atol=1e-12,
        t_eval=np.linspace(0.0, sol.t, samples),
    ).y_eval
    return f, end, kind, curve


def crossings(m1, nu):
    """f1, f2 and the ends g1, g2 of T1, T2 with their kinds."""
    f1, e1, k1, t1 = _separatrix(m1, nu, 1)
    f2, e2, k2, t2 = _separatrix(m1, nu, 2)
    return {"f1": f1, "f2": f2, "g1": e1, "g1_kind": k1, "g2": e2, "g2_kind": k2, "T1": t1, "T2": t2}


def nu_where_f1_meets_f2(m1, lo=0.02, hi=1.0):
    """nu at which f1 - f2 (integrated) changes sign, by bisection (brentq)."""
    from scipy.optimize import brentq

    gap = lambda nu: (lambda x: x["f1"] - x["f2"])(crossings(m1, nu))
    return brentq(gap, lo, hi, xtol=1e-13, rtol=1e-14)


class Figure212(NamedTuple):
    """Lee's Figure 2.12 for one plane: the crossings (see `crossings`) and their distance from (2.13)."""

    crossings: dict
    deviation: float  # the integrated f1, f2 against the closed form (2.13), the larger difference


def figure_2_12(m1, nu) -> Figure212:
    """The numbers of Lee's Figure 2.12 for this plane."""
    x = crossings(m1, nu)
    s1 = float(np.arcsin(-m1))
    c = np.pi - s1
    closed = [
        float(np.sqrt(se.separatrix_p1_squared(np.array([c]), m1, -nu, s))[0]) for s in (s1, s1 + 2 * np.pi)
    ]
    return Figure212(x, max(abs(x["f1"] - closed[0]), abs(x["f2"] - closed[1])))


def _record_figure_2_12(results, values: Figure212, zoom=None):
    """zoom: the table of the grid's panel (zoom_table), recorded after the numbers."""
    x = values.crossings
    results.number(
        "f1_height",
        x["f1"],
        "1",
        note="p1 where T1 (out of S1) crosses the vertical through C, "
        "integrated from the saddle's eigenvector",
    )
    results.number("f2_height", x["f2"], "1", note="p1 where T2 (into S2) crosses the vertical through C")
    results.number(
        "f1_minus_f2", x["f1"] - x["f2"], "1", note="positive below nu*, negative above (Lee §2.5)"
    )
    results.number(
        "g1_kind_vertical",
        int(x["g1_kind"] == "vertical"),
        "1",
        note="1 if T1 reaches the vertical through S2 (at g1), 0 if it falls to the phi2-axis first",
    )
    results.number(
        "g1_phi2", float(x["g1"][0]), "rad", note="where T1 ends: the vertical through S2 or the axis"
    )
    results.number(
        "g1_p1", float(x["g1"][1]), "1", note="p1 at the end of T1 (its height at g1 on S2's vertical)"
    )
    results.number(
        "g2_kind_axis",
        int(x["g2_kind"] == "axis"),
        "1",
        note="1 if T2 (backward) falls to the phi2-axis (at g2) before the vertical through S1",
    )
    results.number("g2_phi2", float(x["g2"][0]), "rad", note="where T2, traced back, ends")
    results.number(
        "crossing_closed_deviation", values.deviation, "1", note="integrated f1, f2 against (2.13)"
    )
    results.hard_case(
        "separatrix_crossings",
        "The heights $f_1$, $f_2$ of Lee's Figure 2.12, integrated from the "
        "saddles, against the closed form (2.13) (largest difference)",
        values.deviation,
        CROSSING_BOUND,
    )
    if zoom is not None:
        results.table(
            "zoom",
            zoom,
            "Lee's Figure 2.12, one period of the plane: the separatrices $T_1$ (out of $S_1$) "
            "and $T_2$ (into "
            "$S_2$) integrated from the saddles, $F$ and $F_1$, the singular points, and the crossings "
            "(curve 1 to 4: $f_1$, $f_2$, $g_1$, $g_2$).",
            headers=portrait.TABLE_HEADERS,
        )


def zoom_table(m1, nu, x) -> pd.DataFrame:
    """One period [S1 - 0.3, S2 + 0.3] in the portrait table's format, for the grid's panel (Lee's Figure
    2.12); x: the plane's crossings."""
    s1 = float(np.arcsin(-m1))
    lo, hi = s1 - 0.3, s1 + 2 * np.pi + 0.3
    drawing = portrait.Drawing("p1", (lo, hi, 8.0))
    drawing.curve("separatrix_T", x["T1"][:, 0], x["T1"][:, 1])
    drawing.curve("separatrix_T", x["T2"][:, 0], x["T2"][:, 1])
    phi = np.linspace(lo, hi, 400)
    F = se.limit_cycle_p1(phi, m1, nu)
    if F is not None:
        drawing.curve("limit_cycle_F", phi, F)
        drawing.curve("limit_cycle_F1", phi, -F)
    drawing.points(se.singular_points(m1, -nu, lo, hi))
    c = np.pi - s1
    rows = [(1, c, x["f1"]), (2, c, x["f2"]), (3, *x["g1"]), (4, *x["g2"])]
    drawing.parts.append(
        pd.DataFrame(
            {
                "element": "crossing",
                "curve": [r[0] for r in rows],
                "phi2": [r[1] for r in rows],
                "p1": [r[2] for r in rows],
            }
        )
    )
    top = 1.25 * max(x["f1"], x["f2"], float(np.max(F)) if F is not None else 0.0)
    drawing.window(lo, hi, top)
    return drawing.frame().round({"phi2": portrait.DIGITS, "p1": portrait.DIGITS})


def _record_nu_star_bisection(results, nu):
    results.number("nu_star_bisection", nu, "1", note="nu where the integrated f1 - f2 changes sign (brentq)")


# --- omega on F, the permanent rotations, the reversal ------------------------------------------------------
@rhs_function
def _r_up(t, w, p, out):
    out[0] = w[2]


class PeriodicMotion(NamedTuple):
    """Euler's equations on F: omega's period and how far omega is from its start (relative to |omega0|)."""

    period_tau: float  # the first upward crossing of r through zero, in tau
    return_error: float  # |omega(T) - omega0|
    half_reversed_error: float  # |omega(T/2) - (p0, -q0, -r0)|
    half_distance: float  # |omega(T/2) - omega0|


def periodic_motion(body, m1, nu, delta) -> PeriodicMotion:
    """Euler's equations started on F where r = 0, q > 0 (phi1 = 0, phi2 = sigma1): the first upward crossing
    of r through zero is omega's period; at it omega is back, and at the period of p (half of it) (q, r) is
    reversed."""
    L = se.LargestAxis.with_plane_parameters(body, m1, -nu, delta)
    phi2 = L.sigma1
    w0 = L.from_plane(phi2, float(se.limit_cycle_p1(np.array([phi2]), m1, nu)[0]))
    T = 2.0 * se.limit_cycle_period(m1, nu) / L.time_scale  # Jacobi's form, twice: omega's period
    sol = solve(
        Problem(se.euler_largest, w0, (0.0, 1.5 * T), L.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=np.array([0.5 * T, T]),
        events=Events(_r_up, 1, (1,)),
    )
    size = float(np.linalg.norm(w0))
    reversed_ = w0 * np.array([1.0, -1.0, -1.0])
    return PeriodicMotion(
        period_tau=float(sol.event_t[0]) * L.time_scale,
        return_error=float(np.linalg.norm(sol.y_eval[1] - w0)) / size,
        half_reversed_error=float(np.linalg.norm(sol.y_eval[0] - reversed_)) / size,
        half_distance=float(np.linalg.norm(sol.y_eval[0] - w0)) / size,
    )


def _record_periodic_motion(results, values: PeriodicMotion):
    results.number(
        "omega_period_tau_F_measured",
        values.period_tau,
        "τ",
        note="the first return of r through zero upward "
        "(φ1 one full turn) along Euler's equations, started on F",
    )
    results.number(
        "omega_return_error",
        values.return_error,
        "1",
        note="|ω(T) − ω0|/|ω0| at T = twice Jacobi's period of p1",
    )
    results.number(
        "omega_half_reversed_error",
        values.half_reversed_error,
        "1",
        note="|ω(T/2) − (p0, −q0, −r0)|/|ω0|: after one period of p, (q, r) is reversed",
    )
    results.number(
        "omega_half_distance",
        values.half_distance,
        "1",
        note="|ω(T/2) − ω0|/|ω0|: not back after the period of p",
    )


class PermanentRotations(NamedTuple):
    """The permanent rotations p = +-P about x (rates per time unit) and F shrinking onto the + one."""

    P: float  # sqrt(m/|mu|)
    drift: float  # largest change of omega started on either
    plus_kicked: float  # largest distance from (P, 0, 0) after a kick of 1e-6
    minus_rate: float  # growth rate of |p + P| off the - one, fitted
    minus_rate_expected: float  # 2 sqrt(m|mu|)
    limit: pd.DataFrame  # by delta: m1, the time mean of p on F, its ratio to P


def permanent_rotations(body, m1, nu, delta) -> PermanentRotations:
    """p = +-sqrt(m/|mu|) (q = r = 0) are rest points of Euler's equations with mu < 0."""
    L = se.LargestAxis.with_plane_parameters(body, m1, -nu, delta)
    m, mu = L.m, L.mu
    P = np.sqrt(m / abs(mu))
    par = L.euler_parameters()
    t_end = 100.0
    drift = 0.0
    for sign, span in ((1.0, t_end), (-1.0, 20.0)):  # the − one amplifies rounding by e^{2√(m|μ|) t}: t ≤ 20
        w0 = np.array([sign * P, 0.0, 0.0])
        sol = solve(Problem(se.euler_largest, w0, (0.0, span), par), "dop853", rtol=1e-13, atol=1e-15)
        drift = max(drift, float(np.max(np.abs(sol.y - w0))))
    kick = 1e-6
    t = np.linspace(0.0, t_end, 2001)
    sol = solve(
        Problem(se.euler_largest, np.array([P + kick, kick, kick]), (0.0, t_end), par),
        "dop853",
        rtol=1e-13,
        atol=1e-18,
        t_eval=t,
    )
    plus_kicked = float(np.max(np.linalg.norm(sol.y_eval - [P, 0, 0], axis=1)))
    small = 1e-9  # kicked in p only: p − P grows like e^{2√(m|μ|) t} while small
    sol = solve(
        Problem(se.euler_largest, np.array([-P - small, 0.0, 0.0]), (0.0, t_end), par),
        "dop853",
        rtol=1e-13,
        atol=1e-20,
        t_eval=t,
        bound=portrait.BLOW_UP_BOUND,
    )
    gap = np.abs(sol.y_eval[:, 0] + P)
    use = np.isfinite(gap) & (gap > 2 * small) & (gap < 1e-6)
    rate = float(np.polyfit(t[use], np.log(gap[use]), 1)[0])
    rows = []
    for d in (1.0, 0.3, 0.1):
        Ld = se.LargestAxis(L.body, m, mu, d)
        m1d, nud = Ld.m1, -Ld.mu1
        T = 2.0 * se.limit_cycle_period(m1d, nud) / Ld.time_scale
        w0 = Ld.from_plane(0.0, float(se.limit_cycle_p1(np.zeros(1), m1d, nud)[0]))
        ts = np.linspace(0.0, T, 4001)
        sol = solve(Problem(se.euler_largest, w0, (0.0, T), par), "dop853", rtol=1e-12, atol=1e-14, t_eval=ts)
        mean = float(np.trapezoid(sol.y_eval[:, 0], ts) / T)
        rows.append({"delta": d, "m1": m1d, "mean_p": mean, "ratio": mean / P})
    return PermanentRotations(P, drift, plus_kicked, rate, 2.0 * np.sqrt(m * abs(mu)), pd.DataFrame(rows))


def _record_permanent_rotations(results, values: PermanentRotations):
    results.number(
        "x_rotation_p", values.P, "1/time", note="√(m/|μ|): the permanent rotations about x at ±this"
    )
    results.number(
        "x_rotation_drift",
        values.drift,
        "1/time",
        note="largest change of ω started at (±√(m/|μ|), 0, 0): + over t ≤ 100, − over t ≤ 20",
    )
    results.number(
        "x_rotation_plus_kicked",
        values.plus_kicked,
        "1/time",
        note="largest distance from (√(m/|μ|), 0, 0), t ≤ 100, after a kick of 10⁻⁶ in p, q, r",
    )
    results.number(
        "x_rotation_minus_rate",
        values.minus_rate,
        "1/time",
        note="growth rate of |p + √(m/|μ|)| from 2·10⁻⁹ to 10⁻⁶ (fitted), started 10⁻⁹ off the − rotation",
    )
    results.number("x_rotation_minus_rate_expected", values.minus_rate_expected, "1/time", note="2√(m|μ|)")
    for d, mean in zip(values.limit.delta, values.limit.mean_p):
        results.number(
            f"mean_p_F_delta_{d:g}".replace(".", "_"),
            float(mean),
            "1/time",
            note=f"time mean of p over one period of ω on F, δ = {d:g} (m, μ fixed), Euler's equations",
        )
    results.table(
        "x_rotation_limit",
        values.limit,
        "As $\\delta \\to 0$ (the torque fixed) $F$ shrinks onto "
        "the permanent rotation $p = \\sqrt{m/|\\mu|}$: the time mean of $p$ over one period of "
        "$\\boldsymbol{\\omega}$ on $F$, from Euler's equations.",
        headers={
            "delta": "$\\delta$",
            "m1": "$m_1$",
            "mean_p": "mean of $p$ (rad per time unit)",
            "ratio": "mean of $p$ / $\\sqrt{m/|\\mu|}$",
        },
    )


class Reversal(NamedTuple):
    """Below F1 in Euler's equations, above F1 in the plane."""

    escaped: bool  # |omega| passed the bound in finite time
    direction: float  # p/|omega| where it did
    escape_tau: float
    above_distance: float  # |p1 - F(phi2)| at tau = 60 from just above F1


def reversal(body, m1, nu, delta) -> Reversal:
    """A start 0.5 below F1 (phi2 = 0) in Euler's equations: |omega| -> infinity along the negative x-axis. A
    start 0.05 above F1 in the plane: on F at tau = 60."""
    F0 = float(se.limit_cycle_p1(np.zeros(1), m1, nu)[0])
    L = se.LargestAxis.with_plane_parameters(body, m1, -nu, delta)
    w0 = L.from_plane(0.0, -F0 - 0.5)
    sol = solve(
        Problem(se.euler_largest, w0, (0.0, 100.0 / L.time_scale), L.euler_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=portrait.BLOW_UP_BOUND,
    )
    escaped = sol.status == "blow-up"
    direction = float(sol.y[0] / np.linalg.norm(sol.y))
    escape_tau = float(sol.t) * L.time_scale
    sol = solve(
        Problem(se.plane_largest, [0.0, -F0 + 0.05], (0.0, 60.0), [m1, -nu, 1.0]),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
    )
    on_F = float(se.limit_cycle_p1(np.array([sol.y[0]]), m1, nu)[0])
    return Reversal(escaped, direction, escape_tau, abs(float(sol.y[1]) - on_F))


def _record_reversal(results, values: Reversal):
    results.number(
        "below_F1_escapes",
        int(values.escaped),
        "1",
        note="1 if Euler's equations from 0.5 below F1 leave every bound (|ω| > 10⁸) in finite time",
    )
    results.number(
        "below_F1_direction",
        values.direction,
        "1",
        note="p/|ω| where it left the bound: −1 is the negative x-axis",
    )
    results.number("below_F1_escape_tau", values.escape_tau, "τ", note="when |ω| passed 10⁸ (τ)")
    results.number(
        "above_F1_distance_tau60",
        values.above_distance,
        "1",
        note="|p1 − F(φ2)| at τ = 60 from 0.05 above F1 at φ2 = 0",
    )


def c1_zero_start(m1, nu) -> float:
    """Lee (2.29): from phi2 = -sigma3, p1 = sqrt(m1/nu) C1 = 0, and p1 returns after one turn of phi2:
    p1 after the turn minus the start."""
    sigma3 = float(np.arctan(-1.0 / (2.0 * nu)))
    start = float(np.sqrt(m1 / nu))
    sol = solve(
        Problem(se.plane_by_phase, [0.0, start], (-sigma3, -sigma3 + 2 * np.pi), [m1, -nu]),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
    )
    return float(sol.y[1]) - start


def _record_c1_zero_start(results, closure):
    results.number(
        "c1_zero_start_closure",
        closure,
        "1",
        note="p1 after one turn of φ2 minus its "
        "start √(m1/ν) at φ2 = −σ3 (C1 = 0), integrated with φ2 as the clock",
    )


class AxisStable(NamedTuple):
    """Lee (2.37)-(2.38): delta where m1 passes 1, and omega started near +x."""

    delta_m1_one: float
    start_angle: float  # the start's angle from +x (rad)
    angle_ratio: float  # the largest angle from +x over t <= 200, over the start's


def axis_stable(body, m1, nu, delta) -> AxisStable:
    """Lee (2.37)-(2.38): the torque fixed, m1(delta) grows without bound as delta -> 0; it passes 1 at
    delta_1. From a start a small angle off +x (delta = 0.01), omega stays near +x."""
    from scipy.optimize import brentq

    L = se.LargestAxis.with_plane_parameters(body, m1, -nu, delta)
    m, mu = L.m, L.mu
    d1 = brentq(lambda d: se.LargestAxis(L.body, m, mu, d).m1 - 1.0, 1e-3, 1e3, xtol=1e-15, rtol=1e-15)
    P = np.sqrt(m / abs(mu))
    d = 0.01
    w0 = np.array([P, d * np.sqrt(body.b), 0.0])
    angle0 = float(np.arctan2(np.hypot(w0[1], w0[2]), w0[0]))
    t = np.linspace(0.0, 200.0, 20001)
    sol = solve(
        Problem(se.euler_largest, w0, (0.0, 200.0), L.euler_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        t_eval=t,
    )
    y = sol.y_eval
    angle = np.arctan2(np.hypot(y[:, 1], y[:, 2]), y[:, 0])
    return AxisStable(d1, angle0, float(np.max(angle)) / angle0)


def _record_axis_stable(results, values: AxisStable):
    results.number(
        "delta_m1_one",
        values.delta_m1_one,
        "1",
        note="δ where m1(δ) of (2.9) = 1 for this scene's torque (brentq); m1 > 1 below",
    )
    results.number(
        "axis_start_angle",
        values.start_angle,
        "rad",
        note="the start's angle from +x: p = √(m/|μ|), δ = 0.01",
    )
    results.number(
        "axis_angle_ratio",
        values.angle_ratio,
        "1",
        note="largest angle from +x over t ≤ 200 over the start's",
    )


# --- Lee §2.6: other torques that reduce to the same planes -------------------------------------------------
def _overlay(rhs, physical, L, plane, starts, span=6.0):
    """Euler's equations (rhs, physical parameters) from the plane's starts mapped by L, against the plane
    (m1, mu1); returns the largest deviation in (phi2, p1) and the largest spread of the plane's integral
    along the mapped integrations."""
    worst, spread = 0.0, 0.0
    tau = np.linspace(0.0, span, 121)
    for phi, p1 in starts:
        full = solve(
            Problem(rhs, L.from_plane(phi, p1), (0.0, span / L.time_scale), physical),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau / L.time_scale,
            bound=portrait.BLOW_UP_BOUND,
        )
        flat = solve(
            Problem(se.plane_largest, [phi, p1], (0.0, span), [*plane, 1.0]),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau,
            bound=portrait.BLOW_UP_BOUND,
        )
        mapped = L.to_plane(full.y_eval, phi2_start=phi)
        worst = max(worst, float(np.max(np.abs(mapped - flat.y_eval))))
        spread = max(spread, se.invariant_spread(mapped, *plane))
    return worst, spread


OTHER_STARTS = ((2.0, 0.0), (0.0, 1.2), (-3.0, -0.6), (0.0, 3.0))


class TorqueYZ(NamedTuple):
    """Lee §2.6: M + mu0 (q^2 + r^2) along x against the conservative plane."""

    mu0: float  # mu0/A
    m1: float  # m1 of (2.9) for that torque
    overlay: float  # Euler's equations mapped, against (2.10) with mu1 = 0 (largest deviation)
    energy_spread: float  # E along them, relative


def torque_yz(body, m1, delta, mu_per_moment=-0.3) -> TorqueYZ:
    """Torque M + mu0 (q^2 + r^2) along x: the conservative plane (mu1 = 0) with m1 of (2.9)."""
    b, c = body.b, body.c
    R = np.sqrt(body.a**2 * b * c + mu_per_moment**2 * (b - c) ** 2)
    m = 0.5 * (m1 * delta**2 * R - mu_per_moment * delta**2 * (b + c))
    L = se.LargestAxis(body, m, mu_per_moment, delta)
    deviation, spread = _overlay(se.euler_largest_yz, L.euler_parameters(), L, (L.m1, 0.0), OTHER_STARTS)
    return TorqueYZ(mu_per_moment, L.m1, deviation, spread)


def _record_torque_yz(results, values: TorqueYZ):
    results.number("yz_torque_mu0", values.mu0, "1", note="μ0/A of the torque M + μ0(q² + r²) along x")
    results.number("yz_torque_m1", values.m1, "1", note="m1 of (2.9) for that torque: the scene's plane")
    results.number(
        "yz_torque_overlay",
        values.overlay,
        "1",
        note="Euler's equations with M + μ0(q² + r²), mapped, "
        "against (2.10) with μ1 = 0 (largest deviation in (φ2, p1))",
    )
    results.number("yz_torque_energy_spread", values.energy_spread, "1", note="E along them, relative spread")


class TorqueGrammel(NamedTuple):
    """Lee §2.6: Grammel's torque M - mu0 p^2 along x against the plane (2.25)."""

    mu0: float  # mu0/A giving this nu
    overlay: float  # Euler's equations mapped with sigma1 = 0, against (2.25) (largest deviation)
    c1_spread: float  # C1 along them, relative
    to_F: float  # |p1 - F| at tau = 60 from 1 above F


def torque_grammel(body, m1, nu, delta) -> TorqueGrammel:
    """Grammel's torque M - mu0 p^2 along x (mu0 > 0): the plane (2.25) with sigma1 = 0."""
    bc = np.sqrt(body.b * body.c)
    mu = 2.0 * bc * nu
    m = 0.5 * m1 * delta**2 * body.a * bc
    L = se.LargestAxis(body, m, 0.0, delta)  # sigma1 = 0, R = a sqrt(bc): the map Grammel's torque needs
    deviation, spread = _overlay(
        se.euler_grammel, np.array([body.a, body.b, body.c, m, mu]), L, (m1, -nu), OTHER_STARTS
    )
    F0 = float(se.limit_cycle_p1(np.zeros(1), m1, nu)[0])
    w0 = L.from_plane(0.0, F0 + 1.0)
    T = 60.0 / L.time_scale
    sol = solve(
        Problem(se.euler_grammel, w0, (0.0, T), np.array([body.a, body.b, body.c, m, mu])),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
    )
    end = L.to_plane(sol.y)[0]
    gap = abs(end[1] - float(se.limit_cycle_p1(np.array([end[0]]), m1, nu)[0]))
    return TorqueGrammel(mu, deviation, spread, gap)


def _record_torque_grammel(results, values: TorqueGrammel):
    results.number("grammel_mu0", values.mu0, "1", note="μ0/A of Grammel's torque M − μ0p² giving this ν")
    results.number(
        "grammel_overlay",
        values.overlay,
        "1",
        note="Euler's equations with Grammel's torque, mapped with "
        "σ1 = 0, against (2.25) (largest deviation in (φ2, p1))",
    )
    results.number("grammel_c1_spread", values.c1_spread, "1", note="C1 along them, relative spread")
    results.number(
        "grammel_to_F", values.to_F, "1", note="|p1 − F| at τ = 60 from 1 above F, Grammel's torque"
    )


def run(results, data, body, m1, nu, delta):
    """The scene's analyses of this module (none unless listed): each computed, then recorded."""
    analysis = data.get("analysis", {})
    if analysis.get("separatrix_crossings"):
        values = figure_2_12(m1, nu)
        zoom = zoom_table(m1, nu, values.crossings) if analysis.get("limit_cycle_motion") else None
        _record_figure_2_12(results, values, zoom)
    if analysis.get("limit_cycle_motion"):
        _record_nu_star_bisection(results, nu_where_f1_meets_f2(m1))
        _record_periodic_motion(results, periodic_motion(body, m1, nu, delta))
        _record_permanent_rotations(results, permanent_rotations(body, m1, nu, delta))
        _record_reversal(results, reversal(body, m1, nu, delta))
        _record_c1_zero_start(results, c1_zero_start(m1, nu))
    if analysis.get("axis_stability"):
        _record_axis_stable(results, axis_stable(body, m1, nu, delta))
    other = analysis.get("other_torque")
    if other == "yz_quadratic":
        _record_torque_yz(results, torque_yz(body, m1, delta))
    elif other == "grammel":
        _record_torque_grammel(results, torque_grammel(body, m1, nu, delta))
