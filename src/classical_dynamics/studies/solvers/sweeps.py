"""Work-precision diagrams for the HNW rigid body and DETEST B5."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...figure_style import legend_below
from ...models import rigid_body as rhs
from ...provenance import software_stamp
from ...results import new_figure, new_figures
from ...solvers import references as ref
from ...solvers import workprecision as wp
from ...solvers.ode import Problem, compile_time

INVARIANTS = {
    "hnw_rigid_body": ("energy", "Casimir $|\\mathbf{m}|^2$"),
    "detest_b5": ("$y_1^2 + y_2^2$", "$0.51y_1^2 + y_3^2$"),
}
NAMES = {"HNW rigid body": "rigid body of Hairer, Nørsett and Wanner", "DETEST B5": "DETEST problem B5"}


def accuracy_headers(problem: str) -> dict:
    """What the reader sees above each column of the accuracy tables."""
    first, second = INVARIANTS[problem]
    return {
        "problem": "problem",
        "method": "method",
        "kind": "control",
        "setting": "rtol or step $h$",
        "error_final": "error at $t = 20$",
        "error_max_steps": "largest error at the steps",
        "error_dense": "largest error on 100 points of the dense output",
        "digits": "correct digits at $t = 20$",
        "steps": "steps",
        "evaluations": "evaluations",
        "energy_drift": f"drift of {first}",
        "casimir_drift": f"drift of {second}",
    }


def case_for(problem: str) -> tuple[wp.Case, np.ndarray | None]:
    if problem == "hnw_rigid_body":
        I = ref.HNW_I
        case = wp.Case(
            "HNW rigid body",
            Problem(rhs.euler_free, ref.HNW_Y0, (0.0, 20.0), rhs.euler_coefficients(I)),
            ref.hnw_rigid_body,
            {
                "energy": lambda y: 0.5 * np.sum(I * y * y, axis=-1),
                "casimir": lambda y: np.sum((I * y) ** 2, axis=-1),
            },
        )
        return case, I
    case = wp.Case(
        "DETEST B5",
        Problem(rhs.detest_b5, [0.0, 1.0, 1.0], (0.0, 20.0)),
        ref.detest_b5,
        {
            "energy": lambda y: y[..., 0] ** 2 + y[..., 1] ** 2,
            "casimir": lambda y: 0.51 * y[..., 0] ** 2 + y[..., 2] ** 2,
        },
    )
    return case, None


class Sweep(NamedTuple):
    problem: str  # hnw_rigid_body or detest_b5
    case_name: str
    frame: pd.DataFrame  # wp.sweep's: per method and setting, errors, steps, evaluations, wall time
    orders: dict  # the splittings' fitted orders
    first_call_s: float  # the compiled integrator's first call over a warm one
    invariant_drifts: dict  # (HNW only) energy, casimir -> largest relative drift along DOP853 at rtol 1e-12
    tightest: dict  # dop853, scipy:DOP853 -> the row at the tightest tolerance
    pair_difference: float | None  # largest |dop853/scipy - 1| of the error, rtol >= 1e-10; None without both
    same_steps: bool | None  # the two take the same steps, rtol >= 1e-10


def sweep(problem, methods, tolerances, steps, repeats, budget_s) -> Sweep:
    """The work-precision sweep of one problem: each method at each tolerance (or step, for a splitting)."""
    case, I = case_for(problem)
    entries = []
    for method in methods:
        if method.startswith("splitting"):
            entry = wp.splitting(case, I, 4 if method.endswith("4") else 2)
            entry.settings = steps
        else:
            entry = wp.adaptive(case, method)
            slow = method in ("scipy:Radau", "scipy:BDF")
            entry.settings = [t for t in tolerances if not (slow and t < 1e-10)]  # minutes otherwise
        entries.append(entry)
    first_call_s = compile_time(case.problem, "dop853")  # one compiled loop serves both pairs
    frame = wp.sweep(case, entries, repeats=repeats, budget_s=budget_s)
    orders = wp.fitted_orders(frame)
    # handbook (2.154)-(2.155): T and L^2 kept, to DOP853's accuracy
    drifts = {}
    if problem == "hnw_rigid_body":
        run = wp.adaptive(case, "dop853").run(1e-12, True)  # its own run: a quick build's sweep stops at 1e-9
        for invariant in ("energy", "casimir"):
            values = case.invariants[invariant](run.y_steps)
            drifts[invariant] = float(np.max(np.abs(values - values[0])) / abs(values[0]))
    # the error reached at each tolerance by the compiled pair and scipy's: the same step sequence
    tightest = {}
    for method in ("dop853", "scipy:DOP853"):
        part = frame[(frame.method == method)]
        if len(part):
            tightest[method] = part[part.setting == part.setting.min()].iloc[0]
    pair = frame[frame.method.isin(["dop853", "scipy:DOP853"]) & (frame.setting >= 1e-10)]
    both = pair.pivot_table(index="setting", columns="method", values="error_final")
    pair_steps = pair.pivot_table(index="setting", columns="method", values="steps")
    difference = same = None
    if both.shape[1] == 2:
        # above round-off only: at rtol 1e-12 both errors are ~1e-13 and differ by round-off
        difference = float(np.max(np.abs(both["dop853"] / both["scipy:DOP853"] - 1)))
        same = bool((pair_steps["dop853"] == pair_steps["scipy:DOP853"]).all())
    return Sweep(problem, case.name, frame, orders, first_call_s, drifts, tightest, difference, same)


def run(scene, results, quick):
    numerics = scene.data["numerics"]
    tolerances = [t for t in numerics["tolerances"] if not quick or t >= 1e-9]
    steps = [h for h in numerics.get("steps", []) if not quick or h >= 0.02]
    repeats = 3 if quick else numerics.get("repeats", 10)
    values = sweep(
        scene.data["problem"], numerics["methods"], tolerances, steps, repeats, 0.5 if quick else 2.0
    )
    _record_sweep(results, values)


def _record_sweep(results, values: Sweep):
    frame, orders = values.frame, values.orders
    accuracy = frame.drop(columns=["seconds", "runs"])
    for invariant, drift in values.invariant_drifts.items():
        label = {"energy": "$T$", "casimir": "$L^2$"}[invariant]
        results.number(
            f"dop853_rtol_1e-12_{invariant}_drift",
            drift,
            "1",
            note=f"largest relative drift of {label} at the steps of DOP853, rtol $10^{{-12}}$",
        )
    headers = accuracy_headers(values.problem)
    name = NAMES[values.case_name]
    results.table(
        "accuracy",
        accuracy,
        # the columns a chapter prints; the report's table names the ones it leaves to the CSV (the largest
        # error over the steps and on 100 points of the dense output, the correct digits at t = 20)
        f"The {name}: the error at the final time $t = 20$ against the exact elliptic-function solution, by "
        "method and relative tolerance (absolute tolerance 1000 times smaller) or step $h$, with the steps, "
        "the right-hand-side evaluations (for the splittings, exact rotations) and the largest relative "
        "drift of the two quadratic invariants.",
        headers=headers,
    )
    results.timing_table(
        "work_precision",
        frame[["method", "setting", "error_final", "steps", "evaluations", "seconds", "runs"]],
        f"The {name}: wall time of each run, the minimum over repeated runs after a warm-up. "
        f"{software_stamp()}.",
        headers={**headers, "seconds": "wall time (s)", "runs": "runs timed"},
    )
    has_steps = bool((frame.kind == "step").any())
    if has_steps:
        fig, (ax, bx) = new_figures(2, height=3.3)
    else:
        fig, ax = new_figure()
    wp.plot(frame, ax, xlabel="error at $t = 20$")
    what = (
        f"What accuracy costs on the {name}: wall time against the error at $t = 20$, one line per method "
        "(solid: this library's compiled pairs; dashed: SciPy's integrators"
    )
    if has_steps:
        wp.plot_convergence(frame, bx, orders, xlabel="step $h$", ylabel="error at $t = 20$")
        # below the left panel the adaptive methods, below the right the splittings with their fitted orders
        # and the reference slopes (the splittings' lines keep their style in both panels)
        handles, labels = ax.get_legend_handles_labels()
        adaptive = [(h, lab) for h, lab in zip(handles, labels) if not lab.startswith("splitting")]
        fig.legend(*zip(*adaptive), loc="outside lower left", ncol=2)
        fig.legend(*bx.get_legend_handles_labels(), loc="outside lower right", ncol=1)
        ax.set_title("work and precision")
        bx.set_title("convergence of the splittings")
        caption = (
            what + "; dotted squares: the Lie–Poisson splittings at fixed steps); accuracy grows to the "
            "right. Right: the splittings' error at $t = 20$ against the step $h$, with dashed reference "
            "slopes $h^2$ and $h^4$; the legend gives the fitted orders. The compiled DOP853 and SciPy's "
            "take "
            "the same steps, so the distance between their lines is interpreter overhead."
        )
    else:
        legend_below(fig, *ax.get_legend_handles_labels(), ncol=4)
        caption = (
            what + "). Accuracy grows to the right; the compiled DOP853 and SciPy's take the same steps, so "
            "the distance between their lines is interpreter overhead."
        )
    results.timing_figure("work_precision", fig, caption)
    for method, order in orders.items():
        key = method.replace(", ", "_").replace(" ", "_")
        results.number(f"fitted_order_{key}", order, "1", note="slope of log error against log h")
    # A measured time belongs with the timings, not in summary.json (which two builds must write identically).
    results.timing_table(
        "first_call",
        pd.DataFrame([{"first_call_extra_s": values.first_call_s}]),
        f"The {name}: how much longer the first call of the compiled integrator for this right-hand "
        "side took than a warm call (compilation, or loading the cached machine code); it is kept "
        "out of the run times.",
        headers={"first_call_extra_s": "extra time of the first call (s)"},
    )
    for method, tight in values.tightest.items():
        results.number(
            f"{method.replace(':', '_').lower()}_error_at_tightest",
            tight.error_final,
            "1",
            note=f"rtol = {tight.setting:g}",
        )
        results.number(f"{method.replace(':', '_').lower()}_steps_at_tightest", int(tight.steps), "steps")
    if values.pair_difference is not None:
        # above round-off only: at rtol 1e-12 both errors are ~1e-13 and differ by round-off
        results.number(
            "dop853_vs_scipy_max_relative_difference",
            values.pair_difference,
            "1",
            note="rtol >= 1e-10: the compiled DOP853 reproduces scipy's errors (same tableau and control)",
        )
        results.number("dop853_same_steps_as_scipy", values.same_steps, "bool", note="rtol >= 1e-10")
