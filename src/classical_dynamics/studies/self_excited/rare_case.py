"""Lee's rare case (§3, (3.65)-(3.66)): the torque along the middle axis in plane II at nu = nu_c, where
k1 = k2 = 0 and no hyperbolic term is left: dq1/dtau = m - nu q1^2, a Riccati equation. Its blow-up below the
rest points, in closed form; without torque (m = 0) the line of rest points q1 = 0 and the decay above it."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...models import self_excited as se
from ...solvers.ode import Problem, solve
from . import portrait
from .bounds import PLANE_DEPARTURE

RARE_REST = (
    "a line of rest points $q_1 = 0$ (permanent rotations about axes of plane II); above it $q_1$ falls "
    "like $1/(\\nu\\tau)$ and $\\boldsymbol{\\omega} \\to 0$ along $+y$, below it $\\boldsymbol{\\omega}$ "
    "leaves every bound in finite time"
)
ESCAPE_EXPONENT_BOUND = 1e-3  # hard case: the rare case's escape, ln|q| against ln|(p, r)|, slope b/(a + c)


class RareEscape(NamedTuple):
    """The rare case's blow-up on the plane and Euler's escape to an axis of plane II."""

    q0: float  # the start (phi2 = 0)
    blow_up_time: float  # when q1 passed -BLOW_UP_BOUND, integrated (tau)
    blow_up_time_closed_form: float
    blow_up_time_error: float  # relative; inf if the plane did not blow up
    exponent: float  # slope of ln|q| against ln|(p, r)| along Euler's equations
    exponent_expected: float  # b/(a + c)
    q_share: float  # |q|/|omega| when |omega| passes 1e12


def escape_motion(M) -> RareEscape:
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
    closed = riccati_time(m, nu, q0, -bound)
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
    return RareEscape(
        q0=q0,
        blow_up_time=flat.t,
        blow_up_time_closed_form=closed,
        blow_up_time_error=abs(flat.t / closed - 1.0) if flat.status == "blow-up" else np.inf,
        exponent=float(np.polyfit(np.log(pr[late]), np.log(q[late]), 1)[0]),
        exponent_expected=M.body.b / (M.body.a + M.body.c),
        q_share=float(q[-1] / np.linalg.norm(w[-1])),
    )


def record_escape(results, values: RareEscape):
    bound = portrait.BLOW_UP_BOUND
    results.number(
        "blow_up_time",
        values.blow_up_time,
        "τ",
        note=f"from φ2 = 0, q1 = {values.q0:.4g}: q1 passes −{bound:g}",
    )
    results.number(
        "blow_up_time_closed_form",
        values.blow_up_time_closed_form,
        "τ",
        note="dq1/dτ = m − νq1² integrated in closed form between the start and the bound",
    )
    results.hard_case(
        "rare_blow_up_time",
        "The blow-up time of the rare case against its closed form (relative)",
        values.blow_up_time_error,
        1e-9,
    )
    results.number(
        "escape_exponent",
        values.exponent,
        "1",
        note="slope of ln|q| against ln|(p, r)| as ω leaves every bound "
        "(Euler's equations, |(p, r)| from 1e4 to 1e11)",
    )
    results.number(
        "escape_exponent_expected",
        values.exponent_expected,
        "1",
        note="b/(a + c) = |μ|/√(ac) at |μ| = μ_c: below 1, so "
        "ω turns towards plane II's axis perpendicular to y",
    )
    results.number("escape_q_share", values.q_share, "1", note="|q|/|ω| when |ω| passes 1e12")
    results.hard_case(
        "rare_escape_direction",
        "Lee: below the line $\\boldsymbol{\\omega}$ runs to an axis of plane "
        "II perpendicular to $y$: $|s - b/(a + c)|$ for the slope $s$ of $\\ln|q|$ against "
        "$\\ln|(p, r)|$",
        abs(values.exponent - values.exponent_expected),
        ESCAPE_EXPONENT_BOUND,
    )


def riccati_time(m, nu, q_from, q_to):
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


class RestLine(NamedTuple):
    """The rare case without torque: the line of rest points q1 = 0 and the decay above it."""

    drift: float  # largest |omega(t) - omega0|/|omega0| from three points of the line
    q10: float  # the start above the line (phi2 = 0)
    tau_end: float  # the last time the state is in plane II
    decay_error: float  # Euler's q1 against q10/(1 + nu q10 tau), largest relative error
    exponent: float  # slope of ln|q| against ln|(p, r)| along that motion
    exponent_expected: float  # b/(a + c)


def rest_line_motion(M) -> RestLine:
    """Lee's Figure 3.18(b), the rare case without torque (m0 = 0): dq1/dtau = -nu q1^2, so every point of q1
    = 0 is at rest (a permanent rotation about an axis of plane II: -b r p + mu |omega|^2 = 0 there at |mu| =
    mu_c). Above the line q1 = q10/(1 + nu q10 tau) falls to 0 while phi2 runs to +infinity, so p and r decay
    like e^{-phi2/2} = (1 + nu q10 tau)^{-1/(2 nu)}, faster than q: omega -> 0 along +y. Along Euler's
    equations ln|q| against ln|(p, r)| has slope 2 nu_c = b/(a + c) exactly."""
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
    return RestLine(drift, q10, t[-1], decay, slope, M.body.b / (M.body.a + M.body.c))


def record_rest_line(drawing, results, values: RestLine):
    """The line drawn across the portrait (drawing), its numbers and hard cases."""
    drawing.curve("rest_line", drawing.reach[:2], [0.0, 0.0])
    drift, decay, slope = values.drift, values.decay_error, values.exponent
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
    results.number(
        "rest_decay_error",
        decay,
        "1",
        note=f"Euler's q1 against q10/(1 + νq10τ) from φ2 = 0, q10 = "
        f"{values.q10:g}, while the state is in plane II (to τ = {values.tau_end:g}; largest relative "
        "error)",
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
        abs(slope - values.exponent_expected),
        ESCAPE_EXPONENT_BOUND,
    )
