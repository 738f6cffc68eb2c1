"""Lee §2.2–§2.4 without drag, checked on Euler's equations themselves: the general solution (2.3) in Lee's
auxiliary angle, the time by quadrature (2.17), the motions of the first and second kind, the periodic
motions' period as a line integral, the permanent rotations, and for |m1| > 1 the stability of the direction
of the x-axis.

Every reference here is independent of the integration it checks: a closed form typed from Lee, a quadrature
(scipy's QUADPACK or mpmath's tanh-sinh) of the plane's energy, or a linear rate. Each check returns its
values and takes no Results; _record_<check> beside it writes them, and run picks the checks and records them.
"""

from __future__ import annotations

from typing import NamedTuple

import mpmath
import numpy as np
from scipy.integrate import quad

from ...models import self_excited as se
from ...solvers.ode import Events, Problem, solve
from ...solvers.runge_kutta import rhs_function

RTOL, ATOL = 1e-13, 1e-15
FIRST_KIND_P1 = 2.0  # a start at phi2 = 0 with p1 = 2 runs past every saddle (p1 never vanishes)
# the time at which phi2 reaches 10 pi, by quadrature and along Euler's equations
QUADRATURE_PHI2 = 10 * np.pi
FIRST_KIND_T = 400.0  # time units
CLOSED_ORBIT_OFFSET = 0.7  # the closed orbit starts at phi2c + 0.7, p1 = 0
KICK = 1e-6  # relative kick off a permanent rotation
CENTER_SPAN = 100.0  # time units


@rhs_function
def phase_reaches(t, w, p, out):
    """The event phi = p[5] on (p, q, r, phi): Lee's auxiliary angle reaches a target."""
    out[0] = w[3] - p[5]


@rhs_function
def spin_zero(t, w, p, out):
    """The event p = 0 (the plane's p1 through zero: a turning point in phi2)."""
    out[0] = w[0]


def run(results, L: se.LargestAxis, m1: float, points: list[dict]):
    """All checks for one unperturbed plane (nu = 0): those that need saddles and centers only when it has
    them."""
    b, c = L.body.b, L.body.c
    params = np.array([L.body.a, b, c, L.m, 0.0, 0.0])
    _record_general_solution(results, general_solution(L, params, points))
    _record_first_kind(results, first_kind(L, params, m1))
    saddles = [pt["phi2"] for pt in points if pt["type"] == "saddle"]
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    if saddles and centers:
        _record_second_kind(results, second_kind(L, params, m1))
        _record_closed_orbit_period(results, closed_orbit_period(L, params, m1, centers[0]))
        _record_permanent_rotations(results, permanent_rotations(L, params, m1, saddles, centers))
        _record_only_permanent_rotations(results, only_permanent_rotations())
    if abs(m1) > 1.0:
        _record_x_axis_stable(results, x_axis_stable(L, params))


def general_solution(L, params, points) -> float:
    """(2.3): with d phi = p dt, q and r are the harmonic functions of phi printed by Lee, alpha1 =
    q0/sqrt(b), alpha2 = r0/sqrt(c) (phi(0) = 0); Euler's equations with phi integrated beside them, two
    starts, 40 time units: the largest |(q, r) - Lee (2.3)|/delta."""
    b, c = L.body.b, L.body.c
    starts = [(0.0, FIRST_KIND_P1)]
    centers = [pt["phi2"] for pt in points if pt["type"] == "center"]
    if centers:
        starts.append((centers[0] + CLOSED_ORBIT_OFFSET, 0.0))
    worst = 0.0
    for phi2, p1 in starts:
        w0 = L.from_plane(phi2, p1)
        t = np.linspace(0.0, 40.0, 401)
        sol = solve(
            Problem(se.euler_largest_phase, np.r_[w0, 0.0], (0.0, t[-1]), params),
            "dop853",
            rtol=RTOL,
            atol=ATOL,
            t_eval=t,
        )
        p, q, r, phi = sol.y_eval.T
        a1, a2, s = w0[1] / np.sqrt(b), w0[2] / np.sqrt(c), np.sqrt(b * c) * phi
        q_lee = a1 * np.sqrt(b) * np.cos(s) - a2 * np.sqrt(b) * np.sin(s)
        r_lee = a1 * np.sqrt(c) * np.sin(s) + a2 * np.sqrt(c) * np.cos(s)
        worst = max(worst, float(np.max(np.hypot(q - q_lee, r - r_lee))) / L.delta)
    return worst


def _record_general_solution(results, worst: float):
    results.number(
        "general_solution_difference",
        worst,
        "1",
        note="largest |(q, r) − Lee (2.3)|/δ, Euler's "
        "equations with φ = ∫p dt beside them, two starts (first kind, closed orbit), t in [0, 40]",
    )
    results.hard_case(
        "general_solution",
        "Lee (2.3): $q$, $r$ as harmonic functions of $\\varphi = \\int p\\,dt$ "
        "along Euler's equations (largest difference over $\\delta$)",
        worst,
        1e-10,
    )


def _energy(phi2, p1, m1):
    return 0.5 * p1**2 - m1 * phi2 + np.cos(phi2)


class FirstKind(NamedTuple):
    t_quad: float  # the time to phi2 = 10 pi by the quadrature (2.17)
    t_euler: float  # the same along Euler's equations
    relative_difference: float
    rate_over_m: float  # (p(400) - p(200))/(200 m)
    p_over_t: float  # p/t at t = 400
    angle_t400: float  # between omega and +x
    angle_times_t: float


def first_kind(L, params, m1) -> FirstKind:
    """A start at phi2 = 0, p1 = 2 (outside every loop): the time to reach phi2 = 10 pi by the quadrature
    (2.17) t = (1/sqrt(2d)) int dphi2/p1, p1 from the energy, against Euler's equations; then on to t = 400,
    where p grows like m t (Grammel's motion of the first kind) and the angle between omega and x falls like
    1/t."""
    b, c = L.body.b, L.body.c
    E = _energy(0.0, FIRST_KIND_P1, m1)
    p1 = lambda x: np.sqrt(2.0 * (E + m1 * x - np.cos(x)))
    tau, err = quad(lambda x: 1.0 / p1(x), 0.0, QUADRATURE_PHI2, epsabs=0.0, epsrel=1e-13, limit=200)
    t_quad = tau / L.time_scale
    w0 = L.from_plane(0.0, FIRST_KIND_P1)
    target = QUADRATURE_PHI2 / (2.0 * np.sqrt(b * c))  # phi2 = 2 sqrt(bc) phi + phi2(0), phi2(0) = 0
    P = params.copy()
    P[5] = target
    t = np.array([FIRST_KIND_T / 2, FIRST_KIND_T])
    sol = solve(
        Problem(se.euler_largest_phase, np.r_[w0, 0.0], (0.0, FIRST_KIND_T), P),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t,
        events=Events(phase_reaches, 1, (1,)),
    )
    t_euler = float(sol.event_t[0])
    p_half, p_end = sol.y_eval[:, 0]
    rate = (p_end - p_half) / (t[1] - t[0])
    angle = np.arctan2(np.hypot(sol.y_eval[:, 1], sol.y_eval[:, 2]), sol.y_eval[:, 0])
    return FirstKind(
        t_quad,
        t_euler,
        abs(t_euler / t_quad - 1.0),
        rate / L.m,
        p_end / FIRST_KIND_T,
        float(angle[1]),
        float(angle[1] * FIRST_KIND_T),
    )


def _record_first_kind(results, values: FirstKind):
    results.number(
        "quadrature_time_10pi",
        values.t_quad,
        "time units",
        note="(2.17): (1/√(2d)) ∫ dφ2/p1 from φ2 = 0 (p1 = 2) to 10π, p1 from the energy, scipy quad",
    )
    results.number(
        "euler_time_10pi",
        values.t_euler,
        "time units",
        note="the same start along Euler's equations: when φ2 = 2√(bc) ∫p dt reaches 10π",
    )
    results.number(
        "euler_quadrature_time_relative_difference",
        values.relative_difference,
        "1",
        note="|the time along Euler's equations over the quadrature's, less one| (full doubles)",
    )
    results.number(
        "first_kind_rate_over_m", values.rate_over_m, "1", note="(p(400) − p(200))/(200 m): p grows like m t"
    )
    results.number("first_kind_p_over_t", values.p_over_t, "1/time²", note="p/t at t = 400")
    results.number(
        "first_kind_angle_t400", values.angle_t400, "rad", note="angle between ω and +x at t = 400"
    )
    results.number(
        "first_kind_angle_times_t",
        values.angle_times_t,
        "rad·time",
        note="t times that angle: bounded (the angle falls like 1/t)",
    )


class SecondKind(NamedTuple):
    closest: float  # closest approach of omega to Lee's vector, over delta
    time_closest: float  # lambda t there
    vector_q: float  # Lee's vector
    vector_r: float


def second_kind(L, params, m1) -> SecondKind:
    """Started on the upper branch of the saddle's loop (2.23), heading for the saddle, Euler's equations
    bring omega to Lee's vector delta(sqrt(b) cos(phi2S/2) j + sqrt(c) sin(phi2S/2) k) (sigma1 = 0 without
    drag), until the round-off of the start (1e-16) has grown like e^{lambda t} and carries it away."""
    b, c = L.body.b, L.body.c
    phi_s = -np.arcsin(m1)  # the saddle, loop to its left for m1 > 0
    side = -1.0 if m1 >= 0 else 1.0
    phi_c = phi_s + side * (np.pi - 2.0 * abs(np.arcsin(m1)))
    p1 = -side * float(np.sqrt(se.separatrix_p1_squared(np.array([phi_c]), m1, 0.0, phi_s))[0])
    target = L.delta * np.array([0.0, np.sqrt(b) * np.cos(phi_s / 2), np.sqrt(c) * np.sin(phi_s / 2)])
    lam = (1.0 - m1**2) ** 0.25 * L.time_scale
    span = 60.0 / lam
    t = np.linspace(0.0, span, 6001)
    sol = solve(
        Problem(se.euler_largest, L.from_plane(phi_c, p1), (0.0, span), params[:5]),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t,
    )
    dist = np.linalg.norm(sol.y_eval - target, axis=1) / L.delta
    k = int(np.argmin(dist))
    return SecondKind(float(dist[k]), float(t[k] * lam), float(target[1]), float(target[2]))


def _record_second_kind(results, values: SecondKind):
    results.number(
        "second_kind_closest", values.closest, "1", note="closest approach of ω to Lee's vector, over δ"
    )
    results.number(
        "second_kind_time_closest",
        values.time_closest,
        "1",
        note="λt at the closest approach, λ = (1 − m1²)^(1/4)√(2d)",
    )
    results.number("second_kind_vector_q", values.vector_q, "rad/time", note="Lee's vector, q")
    results.number("second_kind_vector_r", values.vector_r, "rad/time", note="Lee's vector, r")


class ClosedOrbit(NamedTuple):
    line_integral: float  # the period by mpmath's quadrature
    euler: float  # omega's return time along Euler's equations
    relative_difference: float
    return_gap: float  # |omega(T) - omega(0)|/|omega(0)| after that period


def closed_orbit_period(L, params, m1, phi_c) -> ClosedOrbit:
    """The closed orbit through phi2c + 0.7 (p1 = 0): its period in t as the line integral 2 int
    dphi2/(sqrt(2d) p1) between the turning points (mpmath, tanh-sinh, 30 digits), against the time omega
    takes to return along Euler's equations (two upward crossings of p = 0)."""
    phi_a = phi_c + CLOSED_ORBIT_OFFSET
    with mpmath.workdps(30):
        m = mpmath.mpf(m1)
        a = mpmath.mpf(phi_a)
        E = -m * a + mpmath.cos(a)
        f = lambda x: -m * x + mpmath.cos(x) - E
        b_ = mpmath.findroot(
            f, (mpmath.mpf(phi_c) - 1.2 * CLOSED_ORBIT_OFFSET, mpmath.mpf(phi_c)), solver="anderson"
        )
        mid, half = (a + b_) / 2, (a - b_) / 2  # x = mid + half sin(theta): no endpoint singularity
        g = lambda th: (
            half
            * mpmath.cos(th)
            / mpmath.sqrt(
                abs(2 * (E + m * (mid + half * mpmath.sin(th)) - mpmath.cos(mid + half * mpmath.sin(th))))
            )
        )
        tau = 2 * mpmath.quad(g, [-mpmath.pi / 2, mpmath.pi / 2])
        period_quad = float(tau) / L.time_scale
    w0 = L.from_plane(phi_a, 0.0)
    span = 3.0 * period_quad
    sol = solve(
        Problem(se.euler_largest, w0, (0.0, span), params[:5]),
        "dop853",
        rtol=RTOL,
        atol=ATOL,
        events=Events(spin_zero, 1, (1,)),
    )
    period_euler = float(sol.event_t[1] - sol.event_t[0])
    back = solve(
        Problem(se.euler_largest, w0, (0.0, period_euler), params[:5]), "dop853", rtol=RTOL, atol=ATOL
    )
    return ClosedOrbit(
        period_quad,
        period_euler,
        abs(period_euler / period_quad - 1.0),
        float(np.linalg.norm(back.y - w0) / np.linalg.norm(w0)),
    )


def _record_closed_orbit_period(results, values: ClosedOrbit):
    results.number(
        "closed_orbit_period_line_integral",
        values.line_integral,
        "time units",
        note="2∫dφ2/(√(2d)p1) between the turning points of the orbit through φ2c + 0.7, mpmath at 30 digits",
    )
    results.number(
        "closed_orbit_period_euler",
        values.euler,
        "time units",
        note="ω's return time along Euler's equations (two upward crossings of p = 0)",
    )
    results.number(
        "closed_orbit_period_relative_difference",
        values.relative_difference,
        "1",
        note="|the return time along Euler's equations over the line integral's, less one| (full doubles)",
    )
    results.number(
        "closed_orbit_return", values.return_gap, "1", note="|ω(T) − ω(0)|/|ω(0)| after that period"
    )


class PermanentRotations(NamedTuple):
    residual: float  # largest |a q r/m + 1| over the singular points mapped to omega
    saddle_rate: float  # fitted growth rate of a kick at the saddle
    saddle_rate_lee: float  # (1 - m1^2)^(1/4) sqrt(2d)
    center_kick: float  # largest |omega - omega*|/|omega*| over t = 100 after a kick at the center


def permanent_rotations(L, params, m1, saddles, centers) -> PermanentRotations:
    """Each singular point mapped to omega is a permanent rotation: p = 0, qr = -m/a (relative residual); a
    kick of 1e-6 in p grows at the saddle at the rate lambda = (1 - m1^2)^(1/4) sqrt(2d) (fitted while the
    deviation lies between 1e-9 and 1e-4 of |omega|) and stays small at the center over t = 100."""
    a = L.body.a
    residual = 0.0
    for phi in saddles + centers:
        w = L.from_plane(phi, 0.0)
        residual = max(residual, abs(a * w[1] * w[2] / L.m + 1.0))
    lam = (1.0 - m1**2) ** 0.25 * L.time_scale
    w = L.from_plane(saddles[0], 0.0)
    size = np.linalg.norm(w)
    t = np.linspace(0.0, 25.0 / lam, 2501)
    sol = solve(
        Problem(se.euler_largest, w + [KICK * size, 0.0, 0.0], (0.0, t[-1]), params[:5]),
        "dop853",
        rtol=RTOL,
        atol=1e-18,
        t_eval=t,
    )
    dev = np.linalg.norm(sol.y_eval - w, axis=1) / size
    window = (dev > 1e-5) & (dev < 1e-3) & (t > 3.0 / lam)
    rate = float(np.polyfit(t[window], np.log(dev[window]), 1)[0])
    w = L.from_plane(centers[0], 0.0)
    size = np.linalg.norm(w)
    t = np.linspace(0.0, CENTER_SPAN, 2001)
    sol = solve(
        Problem(se.euler_largest, w + [KICK * size, 0.0, 0.0], (0.0, CENTER_SPAN), params[:5]),
        "dop853",
        rtol=RTOL,
        atol=1e-18,
        t_eval=t,
    )
    dev = float(np.max(np.linalg.norm(sol.y_eval - w, axis=1)) / size)
    return PermanentRotations(residual, rate, lam, dev)


def _record_permanent_rotations(results, values: PermanentRotations):
    results.number(
        "permanent_rotation_residual",
        values.residual,
        "1",
        note="largest |a q r/m + 1| over the window's singular points mapped to ω (p = 0 there)",
    )
    results.number(
        "saddle_growth_rate",
        values.saddle_rate,
        "1/time",
        note="fitted rate of log|ω − ω*| after a kick of 10⁻⁶",
    )
    results.number("saddle_growth_rate_lee", values.saddle_rate_lee, "1/time", note="(1 − m1²)^(1/4)√(2d)")
    results.number(
        "center_kick_largest",
        values.center_kick,
        "1",
        note="largest |ω − ω*|/|ω*| over t = 100 after a kick of 10⁻⁶",
    )


class XAxis(NamedTuple):
    threshold: float  # |m1| > 1 for delta below sqrt(2|m|/(a sqrt(bc)))
    ratio_t100: float  # the angle to +x at t = 100 over its start
    largest_ratio: float  # the largest angle to +x over its start


def x_axis_stable(L, params) -> XAxis:
    """|m1| > 1 on every cylinder with delta < sqrt(2|m|/(a sqrt(bc))): a start 0.01 off the +x axis (delta =
    0.01, p0 = 1) keeps close to it and closes in, the angle to x at t = 100 against the start's."""
    a, b, c = L.body.a, L.body.b, L.body.c
    threshold = np.sqrt(2.0 * abs(L.m) / (a * np.sqrt(b * c)))
    w0 = np.array([1.0, 0.01 * np.sqrt(b), 0.0])
    t = np.linspace(0.0, 100.0, 2001)
    sol = solve(
        Problem(se.euler_largest, w0, (0.0, 100.0), params[:5]), "dop853", rtol=RTOL, atol=ATOL, t_eval=t
    )
    angle = np.arctan2(np.hypot(sol.y_eval[:, 1], sol.y_eval[:, 2]), sol.y_eval[:, 0])
    return XAxis(threshold, float(angle[-1] / angle[0]), float(np.max(angle) / angle[0]))


def _record_x_axis_stable(results, values: XAxis):
    results.number(
        "x_axis_delta_threshold", values.threshold, "rad/time", note="|m1| > 1 for δ below √(2|m|/(a√(bc)))"
    )
    results.number(
        "x_axis_angle_ratio_t100",
        values.ratio_t100,
        "1",
        note="angle to +x at t = 100 over its start (δ = 0.01, p0 = 1)",
    )
    results.number(
        "x_axis_angle_largest_ratio",
        values.largest_ratio,
        "1",
        note="largest angle to +x over the run, over its start",
    )


def only_permanent_rotations() -> int:
    """Lee: besides the one on the x-axis these are the only permanent rotations. With sympy: omega' = 0 is
    the ideal (a q r + m + mu |omega|^2, b r p, c p q); without drag it contains p (so p = 0, and then q r =
    -m/a), with drag it contains p (mu p^2 + m) (p = 0, or p^2 = -m/mu with q = r = 0: the x-axis). Remainders
    of p, resp. p (mu p^2 + m), on its Groebner basis over Q(a, b, c, m, mu): each must be zero. Returns how
    many are not."""
    import sympy as sp

    p, q, r = sp.symbols("p q r")
    a, b, c, m, mu = sp.symbols("a b c m mu")
    nonzero = 0
    for drag, member in ((0, p), (mu, p * (mu * p**2 + m))):
        ideal = [a * q * r + m + drag * (p**2 + q**2 + r**2), b * r * p, c * p * q]
        G = sp.groebner(ideal, p, q, r, order="lex", domain=sp.QQ.frac_field(a, b, c, m, mu))
        nonzero += G.reduce(member)[1] != 0
    return int(nonzero)


def _record_only_permanent_rotations(results, nonzero: int):
    results.number(
        "permanent_rotation_groebner_remainders",
        nonzero,
        "1",
        note="nonzero remainders of p "
        "(no drag) and p(μp² + m) (drag) on the Gröbner basis of ω' = 0: 0 if every permanent rotation "
        "has p = 0 or lies on the x-axis",
    )
