"""Checks of Lee §3 and §4.1 along Euler's equations and the plane systems, for the middle-axis scenes:

  general_solution: with phi = int q dt integrated beside Euler's equations, p and r against Lee (3.3)
    (in plane I or II its special cases (3.40), (3.41)), and phi'' - mu phi'^2 against m0 + k1 sinh + k2 cosh
    (3.8);
  plane_departure: in plane I or II, omega stays in its plane (|r/sqrt c -+ p/sqrt a| against |omega|);
  center_at_rest, middle_axis_unstable: the center is a permanent rotation; the rotation about y is unstable;
  large_q0: in plane I with drag, a start at the center above F escapes however large m3 is, one below
    returns;
  theta_series: Lee's theta2 (4.6) and theta3 (4.7)-(4.8) against the integrated orbit about the center: the
    residual falls like eta^2, eta^3, eta^4 as the terms are added.
The references are closed forms (Lee's, evaluated here from his printed formulas) and the full equations; the
coefficients themselves are checked against a sympy Lindstedt-Poincare expansion in symbolic.py. Each check
returns its values and takes no Results; record_<check> beside it writes them.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from ...solvers.runge_kutta import rhs_function
from . import portrait


class GeneralSolution(NamedTuple):
    """Lee (3.3) and (3.8) along Euler's equations (relative errors)."""

    error: float  # p, r against (3.3), over the largest |omega|
    k_identity_error: float  # phi'' - mu phi'^2 against (3.8), over |m| + (b + |mu|)|omega|^2
    span: float  # the range of sqrt(ac) phi covered


def general_solution(M, w0, t_end) -> GeneralSolution:
    """(3.3) and (3.8) along Euler's equations from w0 (phi = 0 there, so alpha1 = p0/sqrt a, alpha2 = r0/sqrt
    c)."""
    a, b, c = M.body.a, M.body.b, M.body.c
    t = np.linspace(0.0, t_end, 401)
    sol = solve(
        Problem(se.euler_middle_phase, np.r_[w0, 0.0], (0.0, t_end), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=t,
        bound=portrait.BLOW_UP_BOUND,
    )
    y = sol.y_eval[np.all(np.isfinite(sol.y_eval), axis=1)]
    p, q, r, phi = y.T
    al1, al2 = w0[0] / np.sqrt(a), w0[2] / np.sqrt(c)
    X = np.sqrt(a * c) * phi
    p_cf = al1 * np.sqrt(a) * np.cosh(X) + al2 * np.sqrt(a) * np.sinh(X)
    r_cf = al1 * np.sqrt(c) * np.sinh(X) + al2 * np.sqrt(c) * np.cosh(X)
    size = np.max(np.linalg.norm(y[:, :3], axis=1))
    err = float(max(np.max(np.abs(p - p_cf)), np.max(np.abs(r - r_cf))) / size)
    # (3.8): phi'' - mu phi'^2 = q' - mu q^2, q' from Euler's equations, against m0 + k1 sinh 2X + k2 cosh 2X
    m, mu = M.m, M.mu
    lhs = -b * r * p + m + mu * (p * p + q * q + r * r) - mu * q * q
    s2 = al1**2 + al2**2
    m0 = m + 0.5 * mu * (a - c) * (al1**2 - al2**2)  # Lee (3.8), typed from the ledger, not MiddleAxis
    k1 = mu * (a + c) * al1 * al2 - 0.5 * b * np.sqrt(a * c) * s2
    k2 = 0.5 * mu * (a + c) * s2 - b * np.sqrt(a * c) * al1 * al2
    rhs = m0 + k1 * np.sinh(2 * X) + k2 * np.cosh(2 * X)
    scale = abs(m) + (b + abs(mu)) * size**2
    k_err = float(np.max(np.abs(lhs - rhs)) / scale)
    return GeneralSolution(err, k_err, float(np.ptp(phi) * np.sqrt(a * c)))


def record_general_solution(results, values: GeneralSolution):
    results.number(
        "general_solution_error",
        values.error,
        "1",
        note="Euler's p, r (with φ = ∫q dt integrated beside them) "
        "against Lee (3.3), (3.40) or (3.41): largest difference over the run, relative to the largest |ω|",
    )
    results.number(
        "k_identity_error",
        values.k_identity_error,
        "1",
        note="φ'' − μφ'² from Euler's equations against m0 + k1 sinh "
        "2√(ac)φ + k2 cosh 2√(ac)φ of Lee (3.8): largest difference relative to |m| + (b + |μ|)|ω|²",
    )
    results.number("general_solution_span", values.span, "1", note="range of √(ac)φ the check covers")


def plane_departure(M, w0, t_end) -> float:
    """In plane I or II: the largest |r/sqrt c -+ p/sqrt a| / |omega| while |phi2| < 5 along Euler's
    equations."""
    t = np.linspace(0.0, t_end, 801)
    sol = solve(
        Problem(se.euler_middle, w0, (0.0, t_end), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=t,
        bound=portrait.BLOW_UP_BOUND,
    )
    w = sol.y_eval[np.all(np.isfinite(sol.y_eval), axis=1)]
    u, v = w[:, 0] / np.sqrt(M.body.a), w[:, 2] / np.sqrt(M.body.c)
    off = np.abs(v - u) if M.alpha1 == M.alpha2 else np.abs(v + u)
    phi2 = M.to_plane(w)[:, 0]
    inside = np.cumprod(np.abs(phi2) < 5.0).astype(bool)
    return float(np.max(off[inside] / np.linalg.norm(w[inside], axis=1)))


def record_plane_departure(results, worst: float):
    results.number(
        "plane_off_share",
        worst,
        "1",
        note="largest |r/√c ∓ p/√a|/|ω| along Euler's equations while "
        "|φ2| < 5 (Lee (3.38)-(3.41): ω stays in its plane)",
    )


class CenterAtRest(NamedTuple):
    w0: np.ndarray  # the center's omega
    drift: float  # largest |omega(t) - omega0|/|omega0|, t <= 100


def center_at_rest(M, center) -> CenterAtRest:
    """The center (q1 = 0) is a permanent rotation about an axis in the xz-plane: Euler's equations stay
    put."""
    w0 = M.from_plane(center, 0.0)
    sol = solve(
        Problem(se.euler_middle, w0, (0.0, 100.0), M.euler_parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        record_steps=True,
    )
    drift = float(np.max(np.linalg.norm(sol.y_steps - w0, axis=1)) / np.linalg.norm(w0))
    return CenterAtRest(w0, drift)


def record_center_at_rest(results, values: CenterAtRest):
    w0 = values.w0
    results.number(
        "center_drift",
        values.drift,
        "1",
        note="largest |ω(t) − ω0|/|ω0| for t ≤ 100 from the center's ω "
        f"(q = 0, ω0 = ({w0[0]:.4g}, 0, {w0[2]:.4g}))",
    )


def middle_axis_unstable(M) -> float:
    """From a start 1e-6 off the y-axis (q = 1), the angle between omega and y reaches order 1: its largest
    value over t <= 60."""
    w0 = np.array([1e-6, 1.0, 1e-6])
    sol = solve(
        Problem(se.euler_middle, w0, (0.0, 60.0), M.euler_parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-16,
        record_steps=True,
        bound=portrait.BLOW_UP_BOUND,
    )
    w = sol.y_steps
    angle = np.arctan2(np.hypot(w[:, 0], w[:, 2]), w[:, 1])
    return float(np.max(angle))


def record_middle_axis_unstable(results, angle: float):
    results.number(
        "y_axis_escape_angle",
        angle,
        "rad",
        note="largest angle between ω and +y over t ≤ 60 from ω0 = (10⁻⁶, 1, 10⁻⁶)",
    )


class LargeQ0(NamedTuple):
    m3s: tuple  # the m3 of the scene's plane, then those added
    nu: float
    exceptions: int
    runs: int


def large_q0(M, m3s=(5.0, 50.0), factors=(1.01, 0.99)) -> LargeQ0:
    """Plane I with drag (Lee §3.4, Case 2): at the center phi2 = ln m3 the separatrix F (c1 = 0 of (3.60),
    q1^2 = m3/nu - 2 e^phi2/(1 + 2 nu)) has q1^2 = m3/(nu(1 + 2 nu)). Euler's equations from the center with
    q1 just above F (either sign) must leave every bound, just below must return (q crosses 0 twice):
    exceptions counted."""
    nu = -M.mu1
    exceptions, runs = 0, 0
    for m3 in (M.m1,) + tuple(m3s):
        P = se.MiddleAxis.with_plane_parameters(M.body, m3, -nu, M.alpha1, M.alpha2)
        height = np.sqrt(m3 / (nu * (1 + 2 * nu)))
        for sign in (1.0, -1.0):
            for f in factors:
                w0 = P.from_plane(np.log(m3), sign * f * height)
                T = 400.0 / P.time_scale
                sol = solve(
                    Problem(se.euler_middle, w0, (0.0, T), P.euler_parameters()),
                    "dop853",
                    rtol=1e-12,
                    atol=1e-14,
                    events=Events(_q_zero, 1),
                    bound=portrait.BLOW_UP_BOUND * np.linalg.norm(w0),
                )
                escaped = sol.status == "blow-up"
                returned = len(sol.event_t) >= 2 and not escaped
                exceptions += (escaped != (f > 1)) or (returned != (f < 1))
                runs += 1
    return LargeQ0((M.m1,) + tuple(m3s), nu, exceptions, runs)


def record_large_q0(results, values: LargeQ0):
    m3, *m3s = values.m3s
    results.number(
        "large_q0_exceptions",
        values.exceptions,
        "1",
        note=f"of {values.runs} starts at the center of plane I "
        f"(m3 = {m3:g}, {', '.join(f'{m:g}' for m in m3s)}; ν = {values.nu:g}) with q1 = ±1.01 and ±0.99 "
        "times F's height there: those that do not escape (above F) or do not return (below F)",
    )
    results.number("large_q0_runs", values.runs, "1")


@rhs_function
def _q_zero(t, y, p, out):
    out[0] = y[1]


# --- Lee §4.1: the Lindstedt-Poincare series (4.5) with (4.6)-(4.8) -----------------------------------------
def lee_theta2(s, k_sq, beta2, mu1):
    """Lee (4.6)."""
    return (
        (beta2 / (4 * k_sq) + mu1 / 2)
        - (beta2 / (6 * k_sq) + 2 * mu1 / 3) * np.cos(s)
        - (beta2 / (12 * k_sq) - mu1 / 6) * np.cos(2 * s)
    )


def lee_theta3_coefficients(k_sq, beta2, beta3, mu1):
    """Lee (4.7)-(4.8): c0, c1, c2, c3 of theta3 = c0 + c1 cos s + c2 cos 2s + c3 cos 3s (k_sq = k^2)."""
    k4 = k_sq**2
    c0 = -(beta2**2) / (12 * k4) - beta2 * mu1 / (2 * k_sq) - 2 * mu1**2 / 3
    c1 = (
        29 * beta2**2 / (576 * k4)
        + 137 * beta2 * mu1 / (288 * k_sq)
        + beta3 / (192 * k_sq)
        + 61 * mu1**2 / 72
    )
    c2 = beta2**2 / (36 * k4) + beta2 * mu1 / (18 * k_sq) - 2 * mu1**2 / 9
    c3 = beta2**2 / (192 * k4) - beta2 * mu1 / (32 * k_sq) - beta3 / (192 * k_sq) + mu1**2 / 24
    return c0, c1, c2, c3


def lee_h(k_sq, beta2, beta3, mu1):
    """Lee (4.6), (4.8): h2 and h3."""
    h2 = (5 * beta2**2 + 10 * beta2 * k_sq * mu1 + 3 * beta3 * k_sq + 8 * k_sq**2 * mu1**2) / (48 * k_sq**2)
    return h2, -(beta2 + 4 * k_sq * mu1) / (3 * k_sq) * h2


THETA_AMPLITUDES = (0.2, 0.1, 0.05, 0.025)


class ThetaSeries(NamedTuple):
    """Residuals of the orbit about the center against the series (4.5) cut after eta, eta^2, eta^3."""

    slopes: list  # log-log slopes over THETA_AMPLITUDES: 2, 3, 4 expected
    residuals: np.ndarray  # rows: THETA_AMPLITUDES; columns: first, theta2, theta3


def theta_series(M, center, k_sq, beta2, beta3) -> ThetaSeries:
    """The orbit of the plane about the center from phi2c + eta (q1 = 0) over one period, against eta cos s, +
    eta^2 theta2(s), + eta^3 theta3(s) with s = k tau/(1 + h2 eta^2 + h3 eta^3): the largest residual must
    fall like eta^2, eta^3 and eta^4."""
    mu1 = M.mu1
    k = np.sqrt(k_sq)
    h2, h3 = lee_h(k_sq, beta2, beta3, mu1)
    c = lee_theta3_coefficients(k_sq, beta2, beta3, mu1)
    residuals = []
    for eta in THETA_AMPLITUDES:
        T = 2 * np.pi / k * (1 + h2 * eta**2 + h3 * eta**3)
        tau = np.linspace(0.0, T, 201)
        sol = solve(
            Problem(se.plane_middle, [center + eta, 0.0], (0.0, T), M.plane_parameters()),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=tau,
        )
        theta = sol.y_eval[:, 0] - center
        s = k * tau / (1 + h2 * eta**2 + h3 * eta**3)
        r1 = theta - eta * np.cos(s)
        r2 = r1 - eta**2 * lee_theta2(s, k_sq, beta2, mu1)
        r3 = r2 - eta**3 * (c[0] + c[1] * np.cos(s) + c[2] * np.cos(2 * s) + c[3] * np.cos(3 * s))
        residuals.append([float(np.max(np.abs(r))) for r in (r1, r2, r3)])
    residuals = np.array(residuals)
    slopes = [float(np.polyfit(np.log(THETA_AMPLITUDES), np.log(residuals[:, j]), 1)[0]) for j in range(3)]
    return ThetaSeries(slopes, residuals)


def record_theta_series(results, values: ThetaSeries):
    slopes, residuals = values
    amps = ", ".join(f"{e:g}" for e in THETA_AMPLITUDES)
    for j, (name, order) in enumerate((("first", 2), ("theta2", 3), ("theta3", 4))):
        results.number(
            f"theta_residual_slope_{name}",
            slopes[j],
            "1",
            note=f"log-log slope of the largest residual "
            f"over a period of φ2 − φ2c against the series (4.5) up to η{'' if j == 0 else '^' + str(j + 1)}"
            f" (η = {amps}); {order} expected",
        )
        results.number(f"theta_residual_{name}", float(residuals[1, j]), "1", note="that residual at η = 0.1")
