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

import numpy as np
import pandas as pd

from ...models import self_excited as se
from ...solvers import symplectic
from ...solvers import workprecision as wp
from ...solvers.ode import Problem, solve
from ...solvers.timing import min_time
from ..results import new_figure

SEPARATRIX_OFFSET = 1e-6
PERIODS = 10
TOLERANCES = (1e-6, 1e-8, 1e-10, 1e-12)
STEPS = (0.1, 0.05, 0.02, 0.01, 0.005)
ADAPTIVE = ("dop853", "dopri5", "scipy:DOP853", "scipy:RK45", "scipy:LSODA")


def _adaptive_rows(problem, error_of, quick):
    rows = []
    for method in ADAPTIVE:
        for rtol in TOLERANCES[:3] if (quick or method.startswith("scipy")) else TOLERANCES:
            run = lambda: solve(problem, method, rtol=rtol, atol=rtol * 1e-2)        # noqa: E731
            seconds, sol, _ = min_time(run, repeats=1 if method.startswith("scipy") else 5, budget_s=0.5)
            rows.append({"method": method, "kind": "tolerance", "setting": rtol, **error_of(sol.y),
                         "steps": sol.n_steps, "seconds": seconds})
    return rows


def separatrix(results, m1, quick):
    """The unperturbed plane, a start SEPARATRIX_OFFSET inside the loop, heading for the saddle."""
    phi_s = -np.arcsin(m1)
    side = -1.0 if m1 >= 0 else 1.0
    phi_c = phi_s + side * (np.pi - 2.0 * abs(np.arcsin(m1)))
    p_sep = -side * float(np.sqrt(se.separatrix_p1_squared(np.array([phi_c]), m1, 0.0, phi_s))[0])
    y0 = np.array([phi_c, p_sep * (1.0 - SEPARATRIX_OFFSET)])
    E0 = float(se.energy(y0, m1)[0])
    gap = float(se.energy(np.array([phi_s, 0.0]), m1)[0]) - E0         # energy below the separatrix's
    period = _period_estimate(m1, y0)
    span = PERIODS * period

    def error_of(y):
        dE = float(se.energy(np.asarray(y), m1)[0]) - E0
        return {"energy_error": abs(dE), "wrong_side": bool(dE >= gap)}

    rows = _adaptive_rows(Problem(se.plane_largest, y0, (0.0, span), [m1, 0.0, 1.0]), error_of, quick)
    force = np.array([m1])
    for order in (2, 4):
        for h in STEPS[:3] if quick else STEPS:
            n = int(round(span / h))
            run = lambda: symplectic.integrate(se.plane_largest_force, force, y0[:1], y0[1:], span / n, n, order, n)  # noqa
            seconds, (qs, vs), _ = min_time(run, repeats=3, budget_s=0.5)
            rows.append({"method": f"splitting, order {order}", "kind": "step", "setting": h,
                         **error_of([qs[-1, 0], vs[-1, 0]]), "steps": n, "seconds": seconds})
    frame = pd.DataFrame(rows)
    results.number("separatrix_energy_gap", gap, "1", note=f"the start's energy below the separatrix's "
                   f"(offset {SEPARATRIX_OFFSET:g} in p1)")
    results.number("separatrix_span_tau", span, "τ", note=f"{PERIODS} periods of the orbit")
    results.number("separatrix_runs_on_wrong_side", int(frame.wrong_side.sum()), "1",
                   note="settings whose energy error carried the motion across the separatrix")
    publish(results, frame, "separatrix", "energy_error", f"{PERIODS} periods of a closed orbit a relative "
            f"{SEPARATRIX_OFFSET:g} inside the separatrix (m1 = {m1:g}): energy error at the end, and whether it "
            "crossed to the wrong side (the motion then runs away).", "energy error at the end")


def limit_cycle(results, m1, nu, quick):
    sigma3 = np.arctan(-1.0 / (2.0 * nu))
    y0 = np.array([-sigma3, float(se.limit_cycle_p1(np.array([-sigma3]), m1, nu)[0])])
    span = PERIODS * se.limit_cycle_period(m1, nu)
    target = y0 + np.array([2.0 * np.pi * PERIODS, 0.0])

    def error_of(y):
        return {"error": float(np.hypot(*(np.asarray(y) - target)))}

    rows = _adaptive_rows(Problem(se.plane_largest, y0, (0.0, span), [m1, -nu, 1.0]), error_of, quick)
    frame = pd.DataFrame(rows)
    publish(results, frame, "limit_cycle", "error", f"{PERIODS} periods on the limit cycle F (m1 = {m1:g}, "
            f"ν = {nu:g}): distance at the end from the closed form (φ2 advanced by 20π, p1 back at its start).",
            "error at the end against the closed form")


def huge_excursion(results, M, start, quick):
    """start: middle_axis.excursion_start."""
    from .middle_axis import EXCURSION_PERIODS
    w0, T, _, sizes = start
    scale = float(sizes.max())

    def error_of(y):
        return {"error": float(np.linalg.norm(np.asarray(y) - w0)) / scale}

    problem = Problem(se.euler_middle, w0, (0.0, EXCURSION_PERIODS * T), M.euler_parameters())
    frame = pd.DataFrame(_adaptive_rows(problem, error_of, quick))
    publish(results, frame, "excursion", "error", f"Euler's equations over {EXCURSION_PERIODS} periods of a huge "
            f"excursion (q0 = {w0[1]:g}, ν = {-M.mu1:.4g} against ν_c = {se.MiddleAxis.plane_nu('nu_c', M.body):.4g}): "
            "distance at the end from the start, relative to the largest |ω| on the orbit.", "relative error at the end")


def publish(results, frame, name, error, caption, xlabel):
    """A work-precision frame as table, timing table, figure and best error per method."""
    results.table(f"accuracy_{name}", frame.drop(columns=["seconds"]), caption)
    results.timing_table(f"accuracy_{name}", frame, caption + " With wall times.")
    fig, ax = new_figure(6.0, 3.8)
    wp.plot(frame, ax, error=error, floor=1e-16, xlabel=xlabel)
    ax.legend(fontsize=7)
    results.timing_figure(f"work_precision_{name}", fig, "What accuracy costs: " + caption)
    for key, (best, setting) in wp.best_by_method(frame, error).items():
        results.number(f"best_{error}_{name}_{key}", best, "1", note=f"at {setting:g}")


def _period_estimate(m1, y0):
    from .portrait import period
    return period(se.plane_largest, [m1, 0.0, 1.0], y0, span=400.0)
