"""What accuracy costs for the spin-resolved Earth: the splitting against adaptive Runge-Kutta and solve_ivp.

Error: the angle between the final angular-momentum axis and a reference's, in mas. The reference is
DOP853 at rtol 1e-13; the fourth-order splitting at half an hour, an independent method, checks it, and
their agreement is the sweep's resolution: an error below it is not resolved (the figure draws it there).
Smaller splitting steps do not help: kicks of about 1e-10 of |m|, added thousands of times a year,
accumulate round-off (the order-4 error rises below a few hours; at a quarter of an hour it is 1e-3 mas).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...formatting import format_number, plural, shortest
from ...models import earth
from ...models import precession as prec
from ...results import new_figure
from ...solvers import rigid_body
from ...solvers import workprecision as wp
from ...solvers.ode import Problem, solve
from ...solvers.timing import min_time
from . import full

QUICK_SPAN_YEARS = 0.1
REFERENCE_RTOL = 1e-13  # DOP853's tightest: double precision cannot honour rtol below 100 eps
CHECK_STEP_HOURS = 0.5  # the order-4 splitting's check of it (a smaller step gathers more round-off)
SCATTER_STEP_HOURS = 3.0  # at and below it, round-off decides the order-4 splitting's error
REFERENCE_AGREEMENT_BOUND_MAS = 1e-3


def _axis_splitting(model, span, step_hours, order):
    _, ms, qs = full.integrate(model, span, step_hours / 24.0, order, sample_days=span)
    return _unit(full.angular_momentum_axis(ms[-1:], qs[-1:])[0])


def _axis_rk(model, span, method, rtol):
    m0, q0 = prec.initial_state(model)
    problem = Problem(
        prec.full_rhs, np.concatenate([m0, q0]), (0.0, span), model.parameters(), name="full Earth"
    )
    sol = solve(problem, method, rtol=rtol, atol=rtol * model.n)
    q = sol.y[3:] / np.linalg.norm(sol.y[3:])
    return _unit(rigid_body.rotate_to_space(q, sol.y[:3])[0]), sol.n_steps


def _unit(v):
    return v / np.linalg.norm(v)


def _angle_mas(a, b):
    return float(np.arctan2(np.linalg.norm(np.cross(a, b)), np.dot(a, b)) / earth.MAS)


class AccuracyCost(NamedTuple):
    span_years: float
    agreement: float  # the two references' (mas)
    frame: pd.DataFrame  # per method and step or tolerance: the error (mas), steps and wall time
    resolution: float  # the larger of the agreement and the order-4 splitting's scatter (mas)
    best: dict  # wp.best_by_method: method -> (smallest error, its setting)


def accuracy_cost(model, span_years, methods, steps_hours, tolerances, repeats=3) -> AccuracyCost:
    """The work-precision sweep of the spin-resolved Earth over span_years against DOP853 at rtol 1e-13."""
    span = span_years * earth.JULIAN_YEAR_DAYS
    reference, _ = _axis_rk(model, span, "dop853", REFERENCE_RTOL)
    check = _axis_splitting(model, span, CHECK_STEP_HOURS, 4)
    agreement = _angle_mas(reference, check)
    rows = []
    for method in methods:
        if method.startswith("splitting"):
            order = int(method[-1])
            for h in steps_hours:
                seconds, axis, _ = min_time(
                    lambda: _axis_splitting(model, span, h, order), repeats=repeats, budget_s=2.0
                )
                rows.append(
                    {
                        "method": f"splitting, order {order}",
                        "kind": "step",
                        "setting": h,
                        "error_mas": _angle_mas(axis, reference),
                        "steps": int(round(span / (h / 24.0))),
                        "seconds": seconds,
                    }
                )
            continue
        for rtol in tolerances:
            budget = 0.5 if method.startswith("scipy") else 2.0
            seconds, (axis, n_steps), _ = min_time(
                lambda: _axis_rk(model, span, method, rtol),
                repeats=1 if method.startswith("scipy") else repeats,
                budget_s=budget,
            )
            rows.append(
                {
                    "method": method,
                    "kind": "tolerance",
                    "setting": rtol,
                    "error_mas": _angle_mas(axis, reference),
                    "steps": n_steps,
                    "seconds": seconds,
                }
            )
    frame = pd.DataFrame(rows)
    # The two references' agreement does not bound the reference's own error: the order-4 splitting's errors
    # at the smallest steps, where round-off decides them, scatter above it. The resolution is the larger.
    small = frame[(frame["method"] == "splitting, order 4") & (frame["setting"] <= SCATTER_STEP_HOURS)]
    resolution = max([agreement, *small["error_mas"]])
    return AccuracyCost(span_years, agreement, frame, resolution, wp.best_by_method(frame, "error_mas"))


def run(scene, model, results, quick):
    spec = scene.data["analysis"]["accuracy_cost"]
    span_years = QUICK_SPAN_YEARS if quick else spec["span_years"]
    values = accuracy_cost(
        model, span_years, spec["methods"], spec["steps_hours"], spec["tolerances"], spec.get("repeats", 3)
    )
    _record_accuracy_cost(results, values)


def _record_accuracy_cost(results, values: AccuracyCost):
    span_years, agreement, frame, resolution = (
        values.span_years,
        values.agreement,
        values.frame,
        values.resolution,
    )
    results.number("accuracy_span_years", span_years, "yr")
    results.number(
        "reference_agreement_mas",
        agreement,
        "mas",
        note=f"DOP853 at rtol $10^{{-13}}$ against the splitting (order 4, {shortest(CHECK_STEP_HOURS)} h): "
        "the sweep's resolution",
    )
    results.hard_case(
        "reference_agreement",
        "Two independent references for the work-precision sweep agree (final angular-momentum axis, mas)",
        agreement,
        REFERENCE_AGREEMENT_BOUND_MAS,
        "mas",
    )
    span_text = f"{shortest(span_years)} {plural(span_years, 'year')}"
    results.number(
        "resolution_mas",
        resolution,
        "mas",
        note=f"the larger of the references' agreement and the order-4 splitting's errors at steps of "
        f"{shortest(SCATTER_STEP_HOURS)} h and below",
    )
    # a step in hours and a tolerance are different quantities: a column each, each in one notation
    fixed = frame["kind"] == "step"
    columns = ["method", "step_hours", "rtol", "error_mas", "resolved", "steps"]
    shown = frame.assign(
        step_hours=frame["setting"].where(fixed),
        rtol=frame["setting"].where(~fixed),
        resolved=frame["error_mas"] > resolution,  # an error under the resolution is an upper bound only
    )
    shown = shown[columns]
    results.table(
        "accuracy",
        shown,
        f"The spin-resolved Earth over {span_text}, by method and step (h) or tolerance (rtol): the "
        "angle between the final angular-momentum axis and the reference's (DOP853 at rtol $10^{-13}$), and "
        "the steps taken. The reference agrees with the order-4 splitting at "
        f"{shortest(CHECK_STEP_HOURS)} h to {format_number(agreement, 2)} mas, but the splitting's errors "
        f"at steps of {shortest(SCATTER_STEP_HOURS)} h and below scatter up to "
        f"{format_number(resolution, 2)} mas: an error below that is not resolved (“resolved: no”; its "
        "digits then bound it, they do not measure it). The splittings' error "
        "falls with the step until round-off in the kicks takes over.",
        headers={
            "method": "method",
            "step_hours": "step (h)",
            "rtol": "rtol",
            "resolved": "resolved",
            **HEADERS,
        },
    )
    results.timing_table(
        "accuracy",
        frame,
        f"Work-precision of the spin-resolved Earth over {span_text}: the runs "
        "of the accuracy table with their wall times (minimum of repeats).",
        headers={**HEADERS, "seconds": "wall time (s)"},
    )
    fig, ax = new_figure(6.2, 3.3)
    floor = float(f"{resolution:.1e}")  # the resolution, as the caption says it
    wp.plot(frame, ax, error="error_mas", floor=floor, xlabel=r"error of the final $\mathbf{L}$ axis (mas)")
    ax.legend(loc="best")
    results.timing_figure(
        "work_precision",
        fig,
        f"Wall time against the error of the final angular-momentum axis "
        f"after {span_text} of the spin-resolved Earth, one line per method (errors below the "
        f"reference's resolution, {format_number(floor, 2)} mas, drawn at it): the splitting with the exact "
        "free flow (fixed steps, dotted) against adaptive Runge–Kutta on Euler's equations and the "
        "quaternion, compiled (solid) and through SciPy (dashed). Accuracy grows to the right.",
    )
    for key, (best, setting) in values.best.items():
        results.number(f"best_error_mas_{key}", best, "mas", note=f"at {format_number(setting, 3)}")


HEADERS = {
    "method": "method",
    "kind": "control",
    "setting": "step (h) or rtol",
    "error_mas": "error (mas)",
    "steps": "steps",
}
