"""Work-precision diagrams for the HNW rigid body and DETEST B5."""

from __future__ import annotations

import numpy as np

from ...models import rigid_body as rhs
from ...provenance import software_stamp
from ...solvers import references as ref
from ...solvers import workprecision as wp
from ...solvers.ode import Problem, compile_time
from ..results import new_figure


def case_for(problem: str) -> tuple[wp.Case, np.ndarray | None]:
    if problem == "hnw_rigid_body":
        I = ref.HNW_I
        case = wp.Case("HNW rigid body", Problem(rhs.euler_free, ref.HNW_Y0, (0.0, 20.0), rhs.euler_coefficients(I)),
                       ref.hnw_rigid_body,
                       {"energy": lambda y: 0.5 * np.sum(I * y * y, axis=-1),
                        "casimir": lambda y: np.sum((I * y) ** 2, axis=-1)})
        return case, I
    case = wp.Case("DETEST B5", Problem(rhs.detest_b5, [0.0, 1.0, 1.0], (0.0, 20.0)), ref.detest_b5,
                   {"energy": lambda y: y[..., 0] ** 2 + y[..., 1] ** 2,
                    "casimir": lambda y: 0.51 * y[..., 0] ** 2 + y[..., 2] ** 2})
    return case, None


def run(scene, results, quick):
    numerics = scene.data["numerics"]
    case, I = case_for(scene.data["problem"])
    tolerances = [t for t in numerics["tolerances"] if not quick or t >= 1e-9]
    steps = [h for h in numerics.get("steps", []) if not quick or h >= 0.02]
    repeats = 3 if quick else numerics.get("repeats", 10)
    entries = []
    for method in numerics["methods"]:
        if method.startswith("splitting"):
            entry = wp.splitting(case, I, 4 if method.endswith("4") else 2)
            entry.settings = steps
        else:
            entry = wp.adaptive(case, method)
            slow = method in ("scipy:Radau", "scipy:BDF")
            entry.settings = [t for t in tolerances if not (slow and t < 1e-10)]   # minutes otherwise
        entries.append(entry)
    first_call_s = compile_time(case.problem, "dop853")       # one compiled loop serves both pairs
    frame = wp.sweep(case, entries, repeats=repeats, budget_s=0.5 if quick else 2.0)
    orders = wp.fitted_orders(frame)
    accuracy = frame.drop(columns=["seconds", "runs"])
    results.table("accuracy", accuracy, f"{case.name}: error against the exact elliptic-function solution by "
                  "method and tolerance (reltol = 1000 × abstol) or step: at the final time, the largest over "
                  "the method's steps, on 100 points of the dense output; correct digits; steps; evaluations; "
                  "drift of the invariants.")
    results.timing_table("work_precision", frame[["method", "setting", "error_final", "steps", "evaluations",
                                                  "seconds", "runs"]],
                         f"{case.name}: wall time (minimum over repeats after a warm-up). {software_stamp()}.")
    fig, ax = new_figure(6.2, 4.4)
    wp.plot(frame, ax, orders)
    ax.legend(fontsize=7, ncol=2)
    results.timing_figure("work_precision", fig, f"What accuracy costs on the {case.name}: error at t = 20 "
                          "against wall time, one line per method (dashed: scipy's solve_ivp).")
    for method, order in orders.items():
        key = method.replace(", ", "_").replace(" ", "_")
        results.number(f"fitted_order_{key}", order, "1", note="slope of log error against log h")
    results.notes.append(f"{case.name}: the first call of the compiled integrator for this right-hand side "
                         f"took {first_call_s:.2f} s more than a warm call (compilation, or loading the cached "
                         "machine code); it is kept out of the run times.")
    # the error reached at each tolerance by the compiled pair and scipy's: the same step sequence
    for method in ("dop853", "scipy:DOP853"):
        part = frame[(frame.method == method)]
        if len(part):
            tight = part[part.setting == part.setting.min()].iloc[0]
            results.number(f"{method.replace(':', '_').lower()}_error_at_tightest", tight.error_final, "1",
                           note=f"rtol = {tight.setting:g}")
            results.number(f"{method.replace(':', '_').lower()}_steps_at_tightest", int(tight.steps), "steps")
    pair = frame[frame.method.isin(["dop853", "scipy:DOP853"]) & (frame.setting >= 1e-10)]
    both = pair.pivot_table(index="setting", columns="method", values="error_final")
    steps = pair.pivot_table(index="setting", columns="method", values="steps")
    if both.shape[1] == 2:
        # above round-off only: at rtol 1e-12 both errors are ~1e-13 and differ by round-off
        results.number("dop853_vs_scipy_max_relative_difference",
                       float(np.max(np.abs(both["dop853"] / both["scipy:DOP853"] - 1))), "1",
                       note="rtol >= 1e-10: the compiled DOP853 reproduces scipy's errors (same tableau and control)")
        results.number("dop853_same_steps_as_scipy", bool((steps["dop853"] == steps["scipy:DOP853"]).all()), "bool",
                       note="rtol >= 1e-10")
