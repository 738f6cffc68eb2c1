"""Lee §5, checks beyond the constant-torque quadratures of viscous.py, each switched on by a scene's
`analysis`:

time_dependent_torque  (5.3)-(5.15): a torque fixed in direction whose modulus changes, F_i = m_i F(t), with
                       F = 1 + sin(2t)/2 and F = 1 - e^{-t}; Lee's quadratures (5.5), (5.10), their
                       fixed-direction form (5.11)-(5.12) and the frictionless (5.13)-(5.15), by scipy
                       quadrature, against Euler's equations integrated; Theorem 1's bounds for it.
case_one               Case I ((5.18), Figures 5.1, 5.2): the scene's body, medium and torque with r0 = 0,
                       with and without friction, several starts.
case_four              Case IV ((5.31)): the same medium and torque on a body with C = A (h = 0).
spiral                 (5.30), Figure 5.5: a start in the plane r = m3/mu spirals into the limit at the rates
                       nu and g1 = h m3/mu.
singular_curve         (5.50)-(5.52), Figure 5.3: without friction and m3 = 0, the curve of permanent
                       rotations q r = -m1/h, p r = m2/h, a hyperbola q'r' = k' in the plane q/p = -m1/m2.
reduction_formulas     (5.32)-(5.37): Lee's explicit reduction of si, ci of order w = K + w' to Si, Ci of
                       order w' (0 < Re w' < 1), at 40 digits, against the incomplete gamma function; A, B of
                       (5.37) against mpmath's quadrature.
re_w                   Re w = 1 + nu/mu = 1 + mu1 C/(mu0 A) (after (5.29)) over symmetric bodies.
Each check takes the medium and returns its values (no Results); _record_<check> beside it writes them, and
case_one_panels, singular_curve_panels draw the panels they add (viscous.run calls them: ANALYSES, PANELS).
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

import mpmath
import numpy as np
from scipy import integrate

from ...models.viscous_medium import ViscousMedium, modulation, viscous_modulated, viscous_symmetric
from ...solvers import sine_cosine_integrals as sc
from ...solvers.ode import Problem, solve

RTOL, ATOL = 1e-13, 1e-15
MODULATIONS = ((0, 0.5, 2.0, "$F = 1 + \\tfrac12\\sin 2t$"), (1, 1.0, 1.0, "$F = 1 - e^{-t}$"))
TD_TIMES = np.linspace(0.0, 30.0, 7)
CASE_T = 80.0  # Case I and IV with friction: long enough that e^{-nu t} is below 10^-10


def _euler(V: ViscousMedium, omega0, t_eval, rhs=viscous_symmetric, extra=()):
    params = np.concatenate([V.parameters(), np.asarray(extra, float)])
    sol = solve(
        Problem(rhs, list(omega0), (0.0, float(t_eval[-1])), params),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t_eval,
    )
    return sol.y_eval


# --- (5.3)-(5.15): a time-dependent torque fixed in direction -----------------------------------------------
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(20)


def _gauss(f, s: float) -> float:
    """int_0^s f by composite 20-point Gauss-Legendre on panels of length at most 1/2 (f smooth, vectorized;
    the integrands of xi vary on the scale 1/2 at most, so the rule is exact to rounding: the tests compare it
    with quad)."""
    n = max(1, int(np.ceil(2.0 * s)))
    edges = np.linspace(0.0, s, n + 1)
    half = 0.5 * (edges[1:] - edges[:-1])
    u = (0.5 * (edges[1:] + edges[:-1]))[:, None] + half[:, None] * _NODES
    return float(np.sum(half * (f(u) @ _WEIGHTS)))


def _quadratures(V: ViscousMedium, F, t: float) -> dict:
    """omega(t) by Lee's quadratures for F_i = m_i F(s): r by (5.5) (= (5.12)), xi by (5.9) (or (5.13)), p, q
    by (5.10) (the general form, with F1 = m1 F, F2 = m2 F) and by (5.11) (the fixed-direction form, delta1 =
    sqrt(m1^2 + m2^2), sigma1 the angle with sin sigma1 = m1/delta1, cos sigma1 = m2/delta1). scipy quad,
    relative 1e-13; the inner integrals of xi are swapped (Fubini) into one, int_0^s R = int_0^s m3 F(u)(1 -
    e^{-mu(s-u)})/mu du, taken by composite Gauss-Legendre (_gauss), since it is evaluated at every node of
    the outer integral. Also p, q of (5.11) with sigma1 = arctan(m1/m2), the principal value."""
    h, nu, mu = V.h, V.nu, V.mu
    (m1, m2, m3), (p0, q0, r0) = V.m, V.omega0
    opts = dict(epsabs=1e-15, epsrel=1e-13, limit=200)

    def R(s):  # (5.5): int_0^s e^{-mu(s-u)} F3(u) du
        return (
            integrate.quad(lambda u: np.exp(-mu * (s - u)) * m3 * F(u), 0.0, s, **opts)[0] if s > 0 else 0.0
        )

    def xi(s):  # (5.9), (5.13)
        if s <= 0.0:
            return 0.0
        if mu > 0.0:
            inner = _gauss(lambda u: m3 * F(u) * (1.0 - np.exp(-mu * (s - u))) / mu, s)
            return h * (r0 * (1.0 - np.exp(-mu * s)) / mu + inner)
        return h * (r0 * s + _gauss(lambda u: m3 * F(u) * (s - u), s))

    delta, sigma = np.hypot(p0, q0), np.arctan2(p0, q0)
    delta1, sigma1 = np.hypot(m1, m2), np.arctan2(m1, m2)
    sigma1_principal = np.arctan(m1 / m2)
    xt = xi(t)

    def integrand(s):
        d = xi(s) - xt
        e, f = np.exp(-nu * (t - s)), F(s)
        return np.array(
            [
                e * f * (m1 * np.cos(d) - m2 * np.sin(d)),
                e * f * (m1 * np.sin(d) + m2 * np.cos(d)),
                -delta1 * e * f * np.sin(d - sigma1),
                delta1 * e * f * np.cos(d - sigma1),
                -delta1 * e * f * np.sin(d - sigma1_principal),
                delta1 * e * f * np.cos(d - sigma1_principal),
            ]
        )

    I = (
        integrate.quad_vec(integrand, 0.0, t, epsabs=1e-14, epsrel=1e-13, limit=400)[0]
        if t > 0
        else np.zeros(6)
    )
    free = delta * np.exp(-nu * t) * np.array([np.sin(xt + sigma), np.cos(xt + sigma)])
    r_general = r0 * np.exp(-mu * t) + R(t)
    r_fixed = (
        r0 * np.exp(-mu * t) + m3 * integrate.quad(lambda u: np.exp(-mu * (t - u)) * F(u), 0.0, t, **opts)[0]
    )
    return {
        "general": np.array([*(free + I[0:2]), r_general]),
        "fixed": np.array([*(free + I[2:4]), r_fixed]),
        "principal": np.array([*(free + I[4:6]), r_fixed]),
    }


class TimeDependent(NamedTuple):
    """Lee's quadratures against Euler's equations for the time-dependent torques (largest |d omega|)."""

    friction: dict  # general (5.10), fixed (5.11), principal (5.11 with the principal arctan)
    frictionless: dict  # general (5.13), (5.14); fixed (5.15)
    theorem_1_ratio: float  # Theorem 1: the larger of |p|, |q| and |r| over their bounds


def time_dependent_torque(V: ViscousMedium) -> TimeDependent:
    """(5.3)-(5.15) for both modulations, with the scene's drags and without."""
    friction = {"general": 0.0, "fixed": 0.0, "principal": 0.0}
    frictionless = {"general": 0.0, "fixed": 0.0}
    ratio = 0.0
    for kind, a, b, _ in MODULATIONS:
        F = modulation(kind, a, b)
        for W, store in ((V, friction), (replace(V, nu=0.0, mu=0.0), frictionless)):
            ode = _euler(W, W.omega0, TD_TIMES, viscous_modulated, (kind, a, b))
            for k, t in enumerate(TD_TIMES):
                q = _quadratures(W, F, float(t))
                for name in store:
                    store[name] = max(store[name], float(np.max(np.abs(q[name] - ode[k]))))
            if W.friction:  # Theorem 1 with |F_i| <= M_i' = |m_i| max F
                fine = _euler(W, W.omega0, np.linspace(0.0, 30.0, 601), viscous_modulated, (kind, a, b))[1:]
                Fmax = 1.0 + a if kind == 0 else 1.0
                delta = np.hypot(*W.omega0[:2])
                pq = delta + (abs(W.m[0]) + abs(W.m[1])) * Fmax / W.nu
                rb = abs(W.omega0[2]) + abs(W.m[2]) * Fmax / W.mu
                ratio = max(
                    ratio, float(np.max(np.abs(fine[:, :2]))) / pq, float(np.max(np.abs(fine[:, 2]))) / rb
                )
    return TimeDependent(friction, frictionless, ratio)


def _record_time_dependent_torque(results, values: TimeDependent):
    friction, frictionless = values.friction, values.frictionless
    note = (
        "F = 1 + sin(2t)/2 and F = 1 − e^(−t) along the scene's torque; max over p, q, r, both F and t = 0, "
        "5, "
        "..., 30, against Euler's equations (DOP853, rtol 1e-13)"
    )
    results.number(
        "td_general_vs_ode",
        friction["general"],
        "1/time",
        note="Lee (5.5), (5.9), (5.10) by quadrature; " + note,
    )
    results.number(
        "td_fixed_vs_ode", friction["fixed"], "1/time", note="Lee (5.11), (5.12) by quadrature; " + note
    )
    results.number(
        "td_fixed_principal_arctan_gap",
        friction["principal"],
        "1/time",
        note="(5.11) with σ1 = arctan(m1/m2) taken as the principal value (m2 < 0 here): off by the sign of "
        "the torque term; the quadrant of (m1, m2) is meant",
    )
    results.number(
        "td_frictionless_general_vs_ode",
        frictionless["general"],
        "1/time",
        note="Lee (5.13), (5.14) by quadrature, ν = μ = 0; " + note,
    )
    results.number(
        "td_frictionless_fixed_vs_ode",
        frictionless["fixed"],
        "1/time",
        note="Lee (5.15) by quadrature, ν = μ = 0; " + note,
    )
    results.number(
        "td_theorem_1_ratio",
        values.theorem_1_ratio,
        "1",
        note="Theorem 1 for the time-dependent torques: the largest "
        "|p|, |q| over δ + (M1' + M2')/ν and |r| over |r0| + M3'/μ, M_i' = |m_i| max F, 0 < t ≤ 30",
    )
    results.hard_case(
        "time_dependent_quadratures",
        "Time-dependent torque: Lee's quadratures (5.10)–(5.15) against "
        "Euler's equations (largest $|\\Delta\\boldsymbol{\\omega}|$)",
        max(friction["general"], friction["fixed"], *frictionless.values()),
        1e-9,
    )


# --- Case I and Case IV: straight lines ---------------------------------------------------------------------
def _starts(center, start, n=6, radius=1.5):
    angles = np.linspace(0.0, 2 * np.pi, n, endpoint=False) + 0.4
    return [tuple(start)] + [
        (center[0] + radius * np.cos(a), center[1] + radius * np.sin(a), start[2]) for a in angles
    ]


def _line_distance(xy, a, b):
    """Largest distance of the rows xy from the line through a and b (any dimension)."""
    d = (b - a) / np.linalg.norm(b - a)
    rel = xy - a
    return float(np.max(np.linalg.norm(rel - np.outer(rel @ d, d), axis=1)))


def _lee_linear(V: ViscousMedium, omega0, t):
    """(5.18) and (5.31): p = (p0 - m1/nu)e^{-nu t} + m1/nu, likewise q; r = (r0 - m3/mu)e^{-mu t} + m3/mu, as
    printed (friction); without friction p0 + m1 t etc."""
    t = np.asarray(t, float)[:, None]
    m, w0 = np.array(V.m), np.array(omega0)
    if not V.friction:
        return w0 + m * t
    rates = np.array([V.nu, V.nu, V.mu])
    return (w0 - m / rates) * np.exp(-rates * t) + m / rates


class LinearCase(NamedTuple):
    """Case I or IV: several starts, with friction to CASE_T and without to 10."""

    case: str  # the model's case
    lee: float  # Lee's formula as printed against Euler's equations
    model: float  # the model's quadrature solution against Euler's equations
    line_pq: float  # largest distance of (p, q) from the line to the limit
    line_space: float  # the same in (p, q, r)
    gap: float  # |omega(CASE_T) - the limit|
    frictionless: float  # |omega - omega0 - m t| without friction
    limit: np.ndarray  # (m1/nu, m2/nu, m3/mu)
    drawn: dict  # the trajectories: "friction" and "frictionless", one array per start


def _linear_case(V: ViscousMedium) -> LinearCase:
    """Several starts of Case I or IV with friction (to CASE_T) and without (to 10), with their
    trajectories."""
    limit = np.array(V.m) / np.array([V.nu, V.nu, V.mu])
    t = np.linspace(0.0, CASE_T, 401)
    lee = model = line_pq = line_space = gap = 0.0
    drawn = {"friction": [], "frictionless": []}
    for w0 in _starts(limit, V.omega0):
        y = _euler(V, w0, t)
        lee = max(lee, float(np.max(np.abs(_lee_linear(V, w0, t) - y))))
        model = max(model, float(np.max(np.abs(replace(V, omega0=w0).closed_form(t)[0] - y))))
        line_pq = max(line_pq, _line_distance(y[:, :2], np.array(w0[:2]), limit[:2]))
        if np.linalg.norm(np.array(w0) - limit) > 0:
            line_space = max(line_space, _line_distance(y, np.array(w0), limit))
        gap = max(gap, float(np.max(np.abs(y[-1] - limit))))
        drawn["friction"].append(y)
    W = replace(V, nu=0.0, mu=0.0)
    tf = np.linspace(0.0, 10.0, 101)
    free = 0.0
    for w0 in _starts(limit, V.omega0):
        y = _euler(W, w0, tf)
        free = max(free, float(np.max(np.abs(y - _lee_linear(W, w0, tf)))))
        drawn["frictionless"].append(y)
    return LinearCase(V.case, lee, model, line_pq, line_space, gap, free, limit, drawn)


def _record_linear_case(results, values: LinearCase, prefix: str, label: str):
    results.number(
        f"{prefix}_lee_vs_ode",
        values.lee,
        "1/time",
        note=f"{label} as printed against Euler's equations "
        f"(DOP853, rtol 1e-13), 7 starts, t ≤ {CASE_T:g}, max over p, q, r",
    )
    results.number(
        f"{prefix}_model_vs_ode",
        values.model,
        "1/time",
        note=f"the model's quadrature solution (its case {values.case}) against Euler's equations, "
        "same starts",
    )
    results.number(
        f"{prefix}_line_distance",
        values.line_pq,
        "1/time",
        note="largest distance of (p, q) from the line through (p0, q0) and (m1/ν, m2/ν)",
    )
    results.number(
        f"{prefix}_space_line_distance",
        values.line_space,
        "1/time",
        note="largest distance of (p, q, r) from "
        "the line through ω0 and the limit (zero unless the axial part r − m3/μ decays with μ ≠ ν)",
    )
    results.number(
        f"{prefix}_limit_gap", values.gap, "1/time", note=f"largest |ω(t = {CASE_T:g}) − (m1/ν, m2/ν, m3/μ)|"
    )
    results.number(
        f"{prefix}_frictionless_gap",
        values.frictionless,
        "1/time",
        note="without friction: largest |ω − ω0 − m t| (p0 + m1 t, ...), 7 starts, t ≤ 10",
    )


class CaseOne(NamedTuple):
    linear: LinearCase
    r_max: float  # largest |r| over every run (r0 = 0, m3 = 0: r stays 0)


def case_one(V: ViscousMedium) -> CaseOne:
    """Case I: the scene's body, medium and torque with r0 = 0."""
    V1 = replace(V, omega0=(V.omega0[0], V.omega0[1], 0.0))
    linear = _linear_case(V1)
    r_max = max(float(np.max(np.abs(y[:, 2]))) for part in linear.drawn.values() for y in part)
    return CaseOne(linear, r_max)


def _record_case_one(results, values: CaseOne):
    _record_linear_case(results, values.linear, "case_one", "Lee (5.18)")
    results.number("case_one_r_max", values.r_max, "1/time", note="largest |r| (r0 = 0, m3 = 0: r stays 0)")


def case_one_panels(values: CaseOne):
    """Two panels to draw beside the solution (with friction, without) and what the caption says of them."""
    limit, drawn = values.linear.limit, values.linear.drawn

    def with_friction(ax):
        for y in drawn["friction"]:
            ax.plot(y[:, 0], y[:, 1], color="0.35", lw=0.8)
            ax.plot(y[0, 0], y[0, 1], ".", color="0.35", ms=3)
        ax.plot(limit[0], limit[1], "+", color="#D55E00", ms=9, mew=1.5)
        ax.set_title("Case I, friction", fontsize=8)
        ax.set_xlabel("$p$ (rad per time unit)")
        ax.set_ylabel("$q$ (rad per time unit)")
        ax.set_aspect("equal", adjustable="datalim")

    def without(ax):
        for y in drawn["frictionless"]:
            ax.plot(y[:, 0], y[:, 1], color="0.35", lw=0.8)
            ax.plot(y[0, 0], y[0, 1], ".", color="0.35", ms=3)
        ax.set_title("Case I, no friction", fontsize=8)
        ax.set_xlabel("$p$ (rad per time unit)")
        ax.set_ylabel("$q$ (rad per time unit)")
        ax.set_aspect("equal", adjustable="datalim")

    caption = (
        "; third and fourth panels: Lee's Case I ($r_0 = 0$, the same body, torque and starts about the "
        "point "
        "(+)), with friction straight lines into $(m_1/\\nu, m_2/\\nu)$ for $t \\le$ "
        f"{CASE_T:g} (Lee's Figure 5.1), without friction parallel lines to infinity for $t \\le 10$ "
        "(Lee's Figure 5.2)"
    )
    return [with_friction, without], caption


class CaseFour(NamedTuple):
    linear: LinearCase
    line_equal_drags: float  # largest distance from the line in space with mu = nu


def case_four(V: ViscousMedium) -> CaseFour:
    """Case IV: the same medium and torque on a body with C = A (h = 0)."""
    V4 = replace(V, h=0.0)
    linear = _linear_case(V4)
    # Lee: "all trajectories in the phase space are rectilinear": so in space only when nu = mu
    same = replace(V4, mu=V4.nu)
    limit = np.array(same.m) / same.nu
    t = np.linspace(0.0, CASE_T, 401)
    line = max(_line_distance(_euler(same, w0, t), np.array(w0), limit) for w0 in _starts(limit, same.omega0))
    return CaseFour(linear, line)


def _record_case_four(results, values: CaseFour):
    _record_linear_case(results, values.linear, "case_four", "Lee (5.31)")
    results.number(
        "case_four_space_line_distance_equal_drags",
        values.line_equal_drags,
        "1/time",
        note="the same with μ = ν: the trajectories are straight in space",
    )


# --- (5.30): the spiral in the plane r = m3/mu --------------------------------------------------------------
class Spiral(NamedTuple):
    t_fit: float
    case: str  # the model's case for the start in the plane
    model_vs_ode: float  # the model's elementary solution against Euler's equations
    plane_gap: float  # largest |r - m3/mu|
    decay_rate: float  # -d ln|z|/dt fitted (Lee: nu)
    turn_rate: float  # d arg z/dt fitted (Lee: g1)


def spiral(V: ViscousMedium, t_fit=20.0) -> Spiral:
    Vg = replace(V, omega0=(V.omega0[0], V.omega0[1], V.m[2] / V.mu))
    t = np.linspace(0.0, t_fit, 201)
    y = _euler(Vg, Vg.omega0, t)
    model_vs_ode = float(np.max(np.abs(Vg.closed_form(t)[0] - y)))
    plane_gap = float(np.max(np.abs(y[:, 2] - V.m[2] / V.mu)))
    nu, g1 = Vg.nu, Vg.g1
    m1, m2 = Vg.m[:2]
    d = nu**2 + g1**2
    z = (y[:, 1] - (nu * m2 - g1 * m1) / d) + 1j * (y[:, 0] - (nu * m1 + g1 * m2) / d)
    decay = -np.polyfit(t, np.log(np.abs(z)), 1)[0]
    turn = np.polyfit(t, np.unwrap(np.angle(z)), 1)[0]
    return Spiral(t_fit, Vg.case, model_vs_ode, plane_gap, float(decay), float(turn))


def _record_spiral(results, values: Spiral):
    results.number(
        "spiral_model_vs_ode",
        values.model_vs_ode,
        "1/time",
        note=f"the model's case {values.case} (elementary) against Euler's equations, t ≤ {values.t_fit:g}",
    )
    results.number("spiral_plane_gap", values.plane_gap, "1/time", note="largest |r − m3/μ|")
    results.number(
        "spiral_decay_rate",
        values.decay_rate,
        "1/time",
        note="(5.30): −d ln|z|/dt fitted along Euler's equations, z = (q − q∞) + i(p − p∞); Lee: ν",
    )
    results.number("spiral_turn_rate", values.turn_rate, "1/time", note="d arg z/dt fitted; Lee: g1 = h m3/μ")


# --- (5.50)-(5.52): the hyperbola of permanent rotations ----------------------------------------------------
class SingularCurve(NamedTuple):
    drift: float  # the points as starts of Euler's equations: largest |omega(t) - omega(0)|, t <= 30
    plane: float  # (5.51): |m1 p + m2 q| relative to its terms, largest
    p_rot: float  # (5.52): largest |p'|/|q'| in the turned frame
    k_mean: float  # k' = q'r' (5.52), mean over the points
    k_spread: float  # relative
    circle_center_gap: float  # the fitted center of the circle of omega0 against Theorem 2's
    q_rot: np.ndarray  # the points in the turned frame: q'
    r: np.ndarray  # and r'
    center_q: float  # Theorem 2's center at r0, q'
    r0: float


def singular_curve(V: ViscousMedium) -> SingularCurve:
    h, (m1, m2, _) = V.h, V.m
    rs = np.concatenate([-np.linspace(4.0, 0.5, 8), np.linspace(0.5, 4.0, 8)])
    points = np.column_stack([m2 / (h * rs), -m1 / (h * rs), rs])
    t = np.linspace(0.0, 30.0, 61)
    drift = float(np.max([np.max(np.abs(_euler(V, pt, t) - pt)) for pt in points]))  # a NaN comes through
    theta = np.arctan(-m2 / m1)  # Lee: the turn about r, (5.52)
    p_rot = points[:, 0] * np.cos(theta) - points[:, 1] * np.sin(theta)
    q_rot = points[:, 0] * np.sin(theta) + points[:, 1] * np.cos(theta)
    k = q_rot * points[:, 2]
    plane = float(
        np.max(
            np.abs(m1 * points[:, 0] + m2 * points[:, 1])
            / (np.abs(m1 * points[:, 0]) + np.abs(m2 * points[:, 1]))
        )
    )
    # the circle of the scene's start, its center fitted (Kasa) against Theorem 2's
    r0 = V.omega0[2]
    y = _euler(V, V.omega0, np.linspace(0.0, 2 * np.pi / abs(h * r0), 41))
    M = np.column_stack([2 * y[:, 0], 2 * y[:, 1], np.ones(len(y))])
    cx, cy, _ = np.linalg.lstsq(M, y[:, 0] ** 2 + y[:, 1] ** 2, rcond=None)[0]
    gap = float(np.hypot(cx - m2 / (h * r0), cy + m1 / (h * r0)))
    center_q = (m2 / (h * r0)) * np.sin(theta) - (m1 / (h * r0)) * np.cos(theta)
    return SingularCurve(
        drift,
        plane,
        float(np.max(np.abs(p_rot) / np.abs(q_rot))),
        float(np.mean(k)),
        float(np.ptp(k) / abs(np.mean(k))),
        gap,
        q_rot,
        points[:, 2],
        center_q,
        r0,
    )


def _record_singular_curve(results, values: SingularCurve):
    results.number(
        "singular_curve_drift",
        values.drift,
        "1/time",
        note="points (m2/(hr), −m1/(hr), r), r = ±0.5 ... ±4, as "
        "starts of Euler's equations: largest |ω(t) − ω(0)|, t ≤ 30",
    )
    results.number(
        "singular_curve_plane",
        values.plane,
        "1",
        note="(5.51) q/p = −m1/m2: |m1 p + m2 q| relative to its terms, largest",
    )
    results.number(
        "singular_curve_p_rot",
        values.p_rot,
        "1",
        note="(5.52): |p'|/|q'| in the frame turned by θ = arctan(−m2/m1), largest",
    )
    results.number("singular_curve_k", values.k_mean, "1/time", note="k' = q'r' (5.52), mean over the points")
    results.number("singular_curve_k_spread", values.k_spread, "1", note="relative spread of q'r'")
    results.number(
        "circle_center_fit_gap",
        values.circle_center_gap,
        "1/time",
        note="center of the circle of ω0 fitted (least squares) against (m2/(hr0), −m1/(hr0))",
    )


def singular_curve_panels(values: SingularCurve):
    """The panel to draw beside the solution and what the caption says of it."""
    k_mean, q_rot, r_points, center_q, r0 = values.k_mean, values.q_rot, values.r, values.center_q, values.r0

    def panel(ax):
        for sign in (-1.0, 1.0):
            r = sign * np.linspace(0.3, 4.5, 200)
            ax.plot(k_mean / r, r, color="#000000", lw=0.9)
        ax.plot(q_rot, r_points, ".", color="0.35", ms=4)
        ax.plot(center_q, r0, "+", color="#D55E00", ms=9, mew=1.5)
        ax.set_xlabel("$q'$ (rad per time unit)")
        ax.set_ylabel("$r'$ (rad per time unit)")
        ax.set_xlim(-3.0, 3.0)

    caption = (
        "; third panel: the permanent rotations (5.50) in the plane (5.51), coordinates turned about $r$ so "
        "that "
        "$p' = 0$: the hyperbola $q'r' = k'$ (Lee's Figure 5.3, $p'$ normal to the page), points checked as "
        "starts of Euler's equations (dots) and the center of the circles at $r_0$ (+)"
    )
    return [panel], caption


# --- (5.32)-(5.37): Lee's reduction formulas ----------------------------------------------------------------
def _taylor(x, w1, sine: bool):
    """Si(x, w') (5.38) or Ci(x, w') (5.39) by the Taylor series, in mpmath at the working precision."""
    total, n = mpmath.mpf(0), 1 if sine else 0
    while True:
        e = 2 * n - w1 if sine else 2 * n + 1 - w1
        term = (-1) ** (n + 1 if sine else n) * x**e / (mpmath.factorial(2 * n - 1 if sine else 2 * n) * e)
        total += term
        if abs(term) < mpmath.mpf(10) ** (-mpmath.mp.dps - 5) and n > x:
            return total
        n += 1


def lee_reduction(x, w, ocr_sign=False):
    """si(x, w), ci(x, w) by Lee (5.32)-(5.37) as written (at mpmath's working precision): w = K + w', the
    sums P (5.34) and Q (5.35), Si, Ci of order w' by (5.38), (5.39), A, B by (5.37). ocr_sign: the OCR's +P
    cos x in si for K odd."""
    K, w1 = sc.split(w)
    x, w, w1 = mpmath.mpf(x), mpmath.mpc(w), mpmath.mpc(w1)

    def fall(n):  # (w - 1)(w - 2) ... (w - n)
        return mpmath.fprod([w - j for j in range(1, n + 1)])

    NP, NQ = ((K - 1) // 2, (K + 1) // 2) if K % 2 else (K // 2, K // 2)
    P = mpmath.fsum((-1) ** (n + 1) * x ** (2 * n - w) / fall(2 * n) for n in range(1, NP + 1))
    Q = mpmath.fsum((-1) ** (n + 1) * x ** (2 * n - 1 - w) / fall(2 * n - 1) for n in range(1, NQ + 1))
    A = mpmath.pi / (2 * mpmath.gamma(w1) * mpmath.sin(w1 * mpmath.pi / 2))
    B = mpmath.pi / (2 * mpmath.gamma(w1) * mpmath.cos(w1 * mpmath.pi / 2))
    Si, Ci, prod = _taylor(x, w1, True), _taylor(x, w1, False), fall(K)
    s, c = mpmath.sin(x), mpmath.cos(x)
    if K % 2:
        ci = P * s - Q * c + (-1) ** ((K + 1) // 2) * (Si - A) / prod
        si = (P if ocr_sign else -P) * c - Q * s + (-1) ** ((K - 1) // 2) * (Ci - B) / prod
    else:
        ci = P * s - Q * c + (-1) ** (K // 2) * (Ci - B) / prod
        si = -P * c - Q * s + (-1) ** (K // 2) * (Si - A) / prod
    return si, ci


class ReductionFormulas(NamedTuple):
    w1: complex  # the scene's w'
    relative_error: float  # of si, ci by (5.32)-(5.35) against the incomplete gamma function
    ocr_sign_error: float  # the same for si with the OCR's +P cos x (K = 3)
    a_b_error: float  # (5.37) A, B against mpmath's quadrature


def reduction_formulas(V: ViscousMedium) -> ReductionFormulas:
    w1 = V.w - np.floor(V.w.real)  # the scene's w' (0.6 + 0.72i here)
    worst = ocr = 0.0
    for K in (1, 2, 3, 4):
        for x in (0.5, 2.0, 8.0):
            with mpmath.workdps(40):
                si, ci = lee_reduction(x, K + w1)
                ref_si, ref_ci = sc.reference(x, K + w1, dps=40)
                worst = max(
                    worst, float(abs(si - ref_si) / abs(ref_si)), float(abs(ci - ref_ci) / abs(ref_ci))
                )
                if K == 3:
                    wrong, _ = lee_reduction(x, K + w1, ocr_sign=True)
                    ocr = max(ocr, float(abs(wrong - ref_si) / abs(ref_si)))
    ab = 0.0
    with mpmath.workdps(30):
        for v in (mpmath.mpc(w1), mpmath.mpf(0.6), mpmath.mpc(0.3, 0.4)):
            A = mpmath.pi / (2 * mpmath.gamma(v) * mpmath.sin(v * mpmath.pi / 2))
            B = mpmath.pi / (2 * mpmath.gamma(v) * mpmath.cos(v * mpmath.pi / 2))
            # I+- = int_0^inf u^-w' e^{+-iu} du = B +- iA, turned onto the imaginary axis (u = +-is, Jordan's
            # lemma): e^{+-i pi (1 - w')/2} E, E = int_0^inf s^-w' e^{-s} ds by quadrature (no gamma function)
            # s = x^10 near 0
            E = mpmath.quad(lambda x: 10 * x ** (9 - 10 * v) * mpmath.exp(-(x**10)), [0, 1]) + mpmath.quad(
                lambda s_: s_ ** (-v) * mpmath.exp(-s_), [1, mpmath.inf]
            )
            plus, minus = (mpmath.exp(k * 1j * mpmath.pi * (1 - v) / 2) * E for k in (1, -1))
            qa, qb = (plus - minus) / 2j, (plus + minus) / 2
            ab = max(ab, float(abs(A - qa) / abs(qa)), float(abs(B - qb) / abs(qb)))
    return ReductionFormulas(w1, worst, ocr, ab)


def _record_reduction_formulas(results, values: ReductionFormulas):
    w1 = values.w1
    results.number(
        "reduction_relative_error",
        values.relative_error,
        "1",
        note=f"Lee (5.32)–(5.35) at 40 digits, w = K + w', "
        f"w' = {w1.real:.2g} + {w1.imag:.2g}i, K = 1 ... 4, x = 0.5, 2, 8, against the incomplete gamma "
        "function (mpmath): largest relative error of si, ci",
    )
    results.number(
        "reduction_ocr_sign_error",
        values.ocr_sign_error,
        "1",
        note="the same for si with the OCR's +P cos x (K = 3)",
    )
    results.number(
        "reduction_A_B_error",
        values.a_b_error,
        "1",
        note="(5.37) A(w'), B(w') against mpmath's quadrature of "
        "their integrals turned onto the imaginary axis (20 digits), w' = the scene's, 0.6, 0.3 + 0.4i: "
        "largest relative",
    )


# --- Re w after (5.29) --------------------------------------------------------------------------------------
class ReW(NamedTuple):
    formula: float  # 1 + nu/mu from the scene's drags
    elongated: list  # Re w for mu0 = mu1, A = B = 1, C = 0.05 ... 0.5
    disc: list  # and C = 1.05 ... 2


def re_w(V: ViscousMedium) -> ReW:
    def w_real(A, C):  # mu0 = mu1 = 1: nu = mu1/A, mu = mu0/C
        return ViscousMedium.from_moments(A, C, 1.0 / A, 1.0 / C, (0.4, -0.2, 0.0), (0.5, 0.8, 2.0)).w.real

    elongated = [w_real(1.0, c) for c in np.linspace(0.05, 0.5, 10)]
    disc = [w_real(1.0, c) for c in np.linspace(1.05, 2.0, 20)]
    return ReW(1.0 + V.nu / V.mu, elongated, disc)


def _record_re_w(results, values: ReW):
    elongated, disc = values.elongated, values.disc
    results.number("re_w_formula", values.formula, "1", note="1 + ν/μ from the scene's drags")
    results.number(
        "re_w_elongated_max",
        max(elongated),
        "1",
        note="μ0 = μ1, A = B = 1, C = 0.05 ... 0.5 (elongated): largest Re w",
    )
    results.number("re_w_elongated_min", min(elongated), "1", note="smallest Re w, the same bodies")
    results.number("re_w_disc_min", min(disc), "1", note="μ0 = μ1, C = 1.05 ... 2 (flat): smallest Re w")
    results.number("re_w_disc_max", max(disc), "1", note="largest, at the thin disc C = A + B = 2A")


# the checks a scene's `analysis` switches on, by name: (compute, record), and for those that add panels to
# the solution's figure, (compute, record, panels)
ANALYSES = {
    "time_dependent_torque": (time_dependent_torque, _record_time_dependent_torque),
    "case_four": (case_four, _record_case_four),
    "spiral": (spiral, _record_spiral),
    "reduction_formulas": (reduction_formulas, _record_reduction_formulas),
    "re_w": (re_w, _record_re_w),
}
PANELS = {
    "case_one": (case_one, _record_case_one, case_one_panels),
    "singular_curve": (singular_curve, _record_singular_curve, singular_curve_panels),
}
