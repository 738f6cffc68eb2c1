"""The huge excursions just below the critical drag (Lee §3, the cosh form): an orbit about the center that
swings far out, its turning points and period from the closed form, and Euler's equations over many periods
against them."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...figure_style import legend_below
from ...formatting import format_number, shortest
from ...models import self_excited as se
from ...results import new_figure
from ...solvers.ode import Events, Problem, solve
from . import portrait
from .bounds import EXCURSION_PERIODS


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


class ExcursionOrbit(NamedTuple):
    """A huge excursion along Euler's equations against the closed form (rates per time unit)."""

    q0: float  # the start's spin about the torque axis
    nu: float  # the plane's drag, and the critical one
    nu_c: float
    period: float  # T in t, from the closed form
    left: float  # the turning points (phi2) of the closed form
    right: float
    predicted: np.ndarray  # |omega| at the turning points, closed form
    t_steps: np.ndarray  # Euler's steps and |omega| at each
    sizes: np.ndarray
    max_omega_closed_form: float  # |omega| at the far turning point: what the errors are measured against
    turning: float  # |omega| where Euler's equations turn against the closed form's (worst, relative)
    closure: float  # |omega - omega0| after EXCURSION_PERIODS periods (relative)
    c1_spread: float  # relative spread of C1 from Euler's state
    cylinder_spread: float  # spread of p^2/a - r^2/c, relative to the largest p^2/a + r^2/c


def excursion_orbit(M, start) -> ExcursionOrbit:
    """The huge excursions just below mu_c (digest §7.5): from phi = 0 on the cylinder with a large spin q0
    about the torque axis, the orbit closes, but p and r swing out like cosh(sqrt(ac) phi) on the way. The
    turning points and the period come from the closed form; Euler's equations must reach the same points,
    close after every period and stay on their cylinder. Rounding errors in omega are relative to the largest
    |omega| the orbit reaches, so the errors are measured against it. start: excursion_start."""
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
    return ExcursionOrbit(
        q0=q0,
        nu=-M.mu1,
        nu_c=se.MiddleAxis.plane_nu("nu_c", M.body),
        period=T,
        left=float(left),
        right=float(right),
        predicted=predicted,
        t_steps=full.t_steps,
        sizes=sizes,
        max_omega_closed_form=scale,
        turning=turning,
        closure=closure,
        c1_spread=float(np.ptp(c1) / np.max(np.abs(c1))),
        cylinder_spread=hyp_spread,
    )


def record_excursion(results, values: ExcursionOrbit):
    """The figure of |omega| over the first two periods, the numbers and the hard cases."""
    T, sizes, predicted, scale = values.period, values.sizes, values.predicted, values.max_omega_closed_form
    fig, ax = new_figure(height=2.6)
    first = values.t_steps <= 2 * T
    ax.semilogy(
        values.t_steps[first],
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
    q0, nu_c = values.q0, values.nu_c
    results.figure(
        "excursion",
        fig,
        "A huge excursion below the critical drag "
        f"($\\nu$ = {portrait.param_text(values.nu)}, "
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
        "excursion_phi2_left", values.left, "1", note="the left turning point of the closed form (q1 = 0)"
    )
    results.number(
        "excursion_phi2_right", values.right, "1", note="the right turning point of the closed form"
    )
    results.number(
        "excursion_closure",
        values.closure,
        "1",
        note=f"|ω − ω0| after {EXCURSION_PERIODS} periods, relative to the largest |ω|",
    )
    results.number(
        "excursion_c1_spread",
        values.c1_spread,
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
        values.turning,
        1e-10,
    )
    results.hard_case(
        "excursion_closes",
        f"Huge excursions below $\\mu_\\mathrm{{c}}$: $\\boldsymbol{{\\omega}}$ "
        f"back at its start after {EXCURSION_PERIODS} periods of the closed form (relative to the "
        "largest $|\\boldsymbol{\\omega}|$)",
        values.closure,
        1e-8,
    )
    results.hard_case(
        "excursion_cylinder",
        "Huge excursions below $\\mu_\\mathrm{c}$: spread of $p^2/a - r^2/c$ "
        "along Euler's equations, relative to the largest $p^2/a + r^2/c$",
        values.cylinder_spread,
        1e-12,
    )
