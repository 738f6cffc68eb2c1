"""What accuracy costs on Lee's plane (2.10): next to a separatrix, and on the limit cycle F.

Next to a separatrix (mu1 = 0): a start 1e-6 inside the homoclinic loop, ten periods. The reference is
the energy E = p1^2/2 - m1 phi2 + cos phi2, exact; an energy error larger than the start's distance from
the separatrix (in energy) carries the motion to the wrong side, where it runs away: those runs are
counted. Stormer-Verlet (symplectic: the plane is a one-degree-of-freedom Hamiltonian system) against
adaptive Runge-Kutta, compiled and through solve_ivp.

On F (mu1 = -nu): ten periods from a point of F. The reference is the closed form: after ten of Jacobi's
periods phi2 has advanced 20 pi and p1 is back where it started.

A huge excursion just below mu_c (torque along the middle axis): Euler's equations themselves, ten periods of
an orbit on which |omega| grows by hundreds; the reference is the start, after ten periods of the closed form.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...formatting import format_number, power_of_ten, shortest
from ...models import self_excited as se
from ...results import new_figure
from ...solvers import workprecision as wp
from ...solvers.fixed_step import FixedProblem, Save, solve_fixed
from ...solvers.ode import Problem, solve
from ...solvers.timing import min_time
from .bounds import EXCURSION_PERIODS
from .portrait import param_text

SEPARATRIX_OFFSET = 1e-6
PERIODS = 10
TOLERANCES = (1e-6, 1e-8, 1e-10, 1e-12)
STEPS = (0.1, 0.05, 0.02, 0.01, 0.005)
ADAPTIVE = ("dop853", "dopri5", "scipy:DOP853", "scipy:RK45", "scipy:LSODA")


def _adaptive_rows(problem, error_of, quick):
    rows = []
    for method in ADAPTIVE:
        for rtol in TOLERANCES[:3] if (quick or method.startswith("scipy")) else TOLERANCES:
            run = lambda: solve(problem, method, rtol=rtol, atol=rtol * 1e-2)
            seconds, sol, _ = min_time(run, repeats=1 if method.startswith("scipy") else 5, budget_s=0.5)
            rows.append(
                {
                    "method": method,
                    "kind": "tolerance",
                    "setting": rtol,
                    **error_of(sol.y),
                    "steps": sol.n_steps,
                    "seconds": seconds,
                }
            )
    return rows


class SeparatrixRuns(NamedTuple):
    """Work and precision next to a separatrix."""

    m1: float
    gap: float  # the start's energy below the separatrix's
    span: float  # PERIODS periods of the orbit (tau)
    frame: pd.DataFrame  # a row per method and setting: the energy's error and change, the side it ends on


def separatrix(m1, quick) -> SeparatrixRuns:
    """The unperturbed plane, a start SEPARATRIX_OFFSET inside the loop, heading for the saddle."""
    phi_s = -np.arcsin(m1)
    side = -1.0 if m1 >= 0 else 1.0
    phi_c = phi_s + side * (np.pi - 2.0 * abs(np.arcsin(m1)))
    p_sep = -side * float(np.sqrt(se.separatrix_p1_squared(np.array([phi_c]), m1, 0.0, phi_s))[0])
    y0 = np.array([phi_c, p_sep * (1.0 - SEPARATRIX_OFFSET)])
    E0 = float(se.energy(y0, m1)[0])
    gap = float(se.energy(np.array([phi_s, 0.0]), m1)[0]) - E0  # energy below the separatrix's
    period = _period_estimate(m1, y0)
    span = PERIODS * period

    def error_of(y):
        # crossed: the end lies past the saddle. Beyond it the potential falls without bound, so a motion that
        # passed the saddle never returns; its energy at the end, far out, is no guide to which side it is on
        y = np.asarray(y)
        dE = float(se.energy(y, m1)[0]) - E0
        return {"energy_error": abs(dE), "energy_change": dE, "wrong_side": bool(side * (y[0] - phi_s) < 0)}

    rows = _adaptive_rows(Problem(se.plane_largest, y0, (0.0, span), [m1, 0.0, 1.0]), error_of, quick)
    plane = FixedProblem(y0, [m1], se.plane_largest_force)
    for order, method in ((2, "stormer-verlet"), (4, "yoshida4")):
        for h in STEPS[:3] if quick else STEPS:
            n = int(round(span / h))
            run = lambda: solve_fixed(plane, method, h=span / n, n_steps=n, save=Save(final=True))
            seconds, sol, _ = min_time(run, repeats=3, budget_s=0.5)
            rows.append(
                {
                    "method": f"splitting, order {order}",
                    "kind": "step",
                    "setting": h,
                    **error_of(sol.y),
                    "steps": n,
                    "seconds": seconds,
                }
            )
    return SeparatrixRuns(m1, gap, span, pd.DataFrame(rows))


def record_separatrix(results, values: SeparatrixRuns):
    """The gap, the runs that crossed or kept large errors inside (counted from the frame), and the work and
    precision's table and figure."""
    m1, gap, span, frame = values
    results.number(
        "separatrix_energy_gap",
        gap,
        "1",
        note=f"the start's energy below the separatrix's (offset {SEPARATRIX_OFFSET:g} in p1)",
    )
    results.number("separatrix_span_tau", span, "τ", note=f"{PERIODS} periods of the orbit")
    results.number(
        "separatrix_runs_on_wrong_side",
        int(frame.wrong_side.sum()),
        "1",
        note="settings that carried the motion across the separatrix (past the saddle at the end)",
    )
    # the size of the energy error does not decide the side, its sign does: errors above the gap that lowered
    # the energy (deeper inside the loop) and kept the motion inside
    inside = frame[~frame.wrong_side & (frame.energy_error > gap)]
    results.number(
        "separatrix_large_errors_inside",
        len(inside),
        "1",
        note="settings whose energy error exceeds the gap, yet the motion stayed inside",
    )
    results.number(
        "separatrix_large_errors_inside_lowered",
        int((inside.energy_change < 0).sum()),
        "1",
        note="of those, the settings whose error lowered the energy",
    )
    if len(inside):
        results.number(
            "separatrix_largest_error_inside",
            float(inside.energy_error.max()),
            "1",
            note="the largest energy error of a motion that stayed inside",
        )
    crossed = frame[frame.wrong_side]
    results.number(
        "separatrix_crossed_lowered",
        int((crossed.energy_change < 0).sum()),
        "1",
        note="settings that crossed, yet end with an energy below the start's",
    )
    results.number("separatrix_step_sizes", int((frame.method == "splitting, order 2").sum()), "1")
    for method in ("splitting, order 2", "splitting, order 4"):
        part = frame[frame.method == method]
        results.number(
            f"separatrix_crossed_{method.replace(', order ', '')}",
            int(part.wrong_side.sum()),
            "1",
            note=f"step sizes at which the {method} crossed (of {len(part)})",
        )
    results.number(
        "separatrix_crossed_adaptive",
        int((crossed.kind == "tolerance").sum()),
        "1",
        note="adaptive settings that crossed",
    )
    runs = (
        f"{PERIODS} periods of a closed orbit of Lee (2.10) a relative "
        f"{power_of_ten(round(np.log10(SEPARATRIX_OFFSET)))} inside the separatrix ($m_1$ = {shortest(m1)}, "
        "$\\nu = 0$), by method and relative tolerance or step $h$"
    )
    # "crossed" first: the column the figure and the text are about stays on a phone's screen
    lead = ["method", "kind", "setting", "wrong_side", "energy_change"]
    frame = frame[lead + [c for c in frame.columns if c not in lead]]
    publish(
        results,
        frame,
        "separatrix",
        "energy_error",
        runs + ": whether the motion crossed the separatrix (it ends past the saddle, running away) and the "
        "change of the energy $E = p_1^2/2 - m_1\\varphi_2 + \\cos\\varphi_2$ at the end (absolute; its "
        "magnitude is the energy error).",
        "error of the energy $E$ at the end",
        {
            "energy_error": "energy error",
            "energy_change": "change of $E$",
            "wrong_side": "crossed the separatrix",
        },
        crossed="wrong_side",
        figure_caption=runs + ": the error of the energy $E$ at the end; a black ring marks each run that "
        "crossed the separatrix (it ends past the saddle, running away). The sign of each change of $E$ is "
        "in the table of the same runs.",
    )


def limit_cycle(m1, nu, quick) -> pd.DataFrame:
    """PERIODS periods on F: the distance at the end from the closed form's point, by method and setting."""
    sigma3 = np.arctan(-1.0 / (2.0 * nu))
    y0 = np.array([-sigma3, float(se.limit_cycle_p1(np.array([-sigma3]), m1, nu)[0])])
    span = PERIODS * se.limit_cycle_period(m1, nu)
    target = y0 + np.array([2.0 * np.pi * PERIODS, 0.0])

    def error_of(y):
        return {"error": float(np.hypot(*(np.asarray(y) - target)))}

    rows = _adaptive_rows(Problem(se.plane_largest, y0, (0.0, span), [m1, -nu, 1.0]), error_of, quick)
    return pd.DataFrame(rows)


def record_limit_cycle(results, frame, m1, nu):
    publish(
        results,
        frame,
        "limit_cycle",
        "error",
        f"{PERIODS} periods on the limit cycle $F$ of Lee (2.10) "
        f"($m_1$ = {shortest(m1)}, $\\nu$ = {shortest(nu)}), by method and relative tolerance: the distance "
        "in $(\\varphi_2, p_1)$ at the end from the closed form ($\\varphi_2$ advanced by $20\\pi$, $p_1$ "
        "back "
        "at its start).",
        "error in $(\\varphi_2, p_1)$ at the end",
        {"error": "error", "setting": "rtol"},
    )


def excursion_runs(M, start, quick) -> pd.DataFrame:
    """EXCURSION_PERIODS periods of a huge excursion: omega's distance at the end from its start, relative to
    the largest |omega|, by method and setting. start: excursions.excursion_start."""
    w0, T, _, sizes = start
    scale = float(sizes.max())

    def error_of(y):
        return {"error": float(np.linalg.norm(np.asarray(y) - w0)) / scale}

    problem = Problem(se.euler_middle, w0, (0.0, EXCURSION_PERIODS * T), M.euler_parameters())
    return pd.DataFrame(_adaptive_rows(problem, error_of, quick))


def record_huge_excursion(results, frame, M, q0):
    """q0: the start's spin about the torque axis."""
    publish(
        results,
        frame,
        "excursion",
        "error",
        f"Euler's equations over {EXCURSION_PERIODS} periods of a huge "
        f"excursion ($q_0$ = {shortest(q0)}, $\\nu$ = {param_text(-M.mu1)} against $\\nu_\\mathrm{{c}}$ "
        f"= {format_number(se.MiddleAxis.plane_nu('nu_c', M.body), 4)}), by method and relative tolerance: "
        "the "
        "distance of $\\boldsymbol{\\omega}$ at the end from its start, relative to the largest "
        "$|\\boldsymbol{\\omega}|$ on the orbit.",
        "error at the end, relative to the largest $|\\omega|$",
        {"error": "relative error", "setting": "rtol"},
    )


HEADERS = {
    "method": "method",
    "kind": "control",
    "setting": "rtol or step $h$",
    "steps": "steps",
    "seconds": "wall time (s)",
}


def publish(
    results, frame, name, error, caption, xlabel, headers=None, floor=1e-16, crossed=None, figure_caption=None
):
    """A work-precision frame as table, timing table, figure and best error per method. headers: those of the
    columns particular to this frame (the error's); the common ones are HEADERS. crossed: a column of flags,
    marked on the figure by a ring; figure_caption: the figure's own, where it draws less than the table holds
    (a caption says only what its figure draws)."""
    headers = {**HEADERS, **(headers or {})}
    results.table(f"accuracy_{name}", frame.drop(columns=["seconds"]), caption, headers=headers)
    results.timing_table(
        f"accuracy_{name}",
        frame,
        caption + " With the wall time of each run, the minimum over repeated runs.",
        headers=headers,
    )
    fig, ax = new_figure(height=2.7)  # with its caption, at most 40 % of a page
    wp.plot(frame, ax, error=error, floor=floor, xlabel=xlabel)
    if crossed:
        hit = frame[frame[crossed].astype(bool)]
        ax.loglog(
            np.maximum(hit[error], floor),
            hit.seconds,
            "o",
            ms=8,
            mfc="none",
            mec="black",
            mew=0.8,
            label="crossed the separatrix",
        )
    fig.legend(loc="outside right upper")
    styles = ["solid: this library's methods"]
    if frame.method.str.startswith("scipy:").any():
        styles.append("dashed: SciPy's integrators")
    if (frame.kind == "step").any():
        styles.append("dotted squares: fixed steps")
    results.timing_figure(
        f"work_precision_{name}",
        fig,
        (figure_caption or caption) + " Wall time against the error, one line per method "
        f"({'; '.join(styles)}); accuracy grows to the right, and errors below "
        f"{power_of_ten(round(np.log10(floor)))} are drawn at that floor.",
    )
    for key, (best, setting) in wp.best_by_method(frame, error).items():
        results.number(f"best_{error}_{name}_{key}", best, "1", note=f"at {setting:g}")


def _period_estimate(m1, y0):
    from .portrait import period

    return period(se.plane_largest, [m1, 0.0, 1.0], y0, span=400.0)
