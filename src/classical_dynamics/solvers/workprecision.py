"""What accuracy costs: sweep methods x tolerances (or step sizes) against an exact reference.

For every cell: error against the reference at the final time, the maximum over the method's own
steps, and on 100 equispaced points through the dense output (SciML's final / l_inf / L_inf); correct
digits -log10(max relative error); steps; right-hand-side evaluations; wall time as the minimum over
repeated runs after a warm-up; and the drift of the invariants. The reference is a closed form,
never the method itself. Tolerances are paired reltol = 1000 x abstol.
"""

from __future__ import annotations

import re

from dataclasses import dataclass
from typing import Callable

import numpy as np
import pandas as pd

from . import rigid_body
from .ode import Problem, solve
from .timing import min_time


@dataclass
class Run:
    t_steps: np.ndarray
    y_steps: np.ndarray
    y_dense: np.ndarray          # on the 100 points of Case.dense_t
    y_final: np.ndarray
    nfev: int
    n_steps: int


@dataclass
class Case:
    name: str
    problem: Problem
    exact: Callable               # t -> y
    invariants: dict              # name -> f(y rows) -> values

    @property
    def dense_t(self):
        return np.linspace(self.problem.t_span[0], self.problem.t_span[1], 100)


@dataclass
class Entry:
    """One line of a work-precision diagram: a method and how to run it at a setting."""
    label: str
    kind: str                     # "tolerance" or "step"
    run: Callable                 # run(setting, record) -> Run (record=False may return only y_final)
    settings: list


def adaptive(case: Case, method: str) -> Entry:
    def run(rtol, record):
        atol = rtol * 1e-3
        if not record:
            sol = solve(case.problem, method, rtol=rtol, atol=atol)
            return Run(None, None, None, sol.y, sol.nfev, sol.n_steps)
        sol = solve(case.problem, method, rtol=rtol, atol=atol, record_steps=True)
        dense = solve(case.problem, method, rtol=rtol, atol=atol, t_eval=case.dense_t)
        return Run(sol.t_steps, sol.y_steps, dense.y_eval, sol.y, sol.nfev, sol.n_steps)
    return Entry(method, "tolerance", run, [])


def splitting(case: Case, I, order: int) -> Entry:
    """The Lie-Poisson splitting on a free body with y = omega = m / I."""
    I = np.asarray(I, float)
    t0, t1 = case.problem.t_span
    m0 = I * case.problem.y0

    def run(h, record):
        n = 99 * max(1, int(round((t1 - t0) / h / 99)))    # a multiple of 99: the 100 dense points are steps
        h = (t1 - t0) / n
        evals = n * (5 if order == 2 else 15)           # exact rotations (the analogue of f-evaluations)
        if not record:
            ms, _ = rigid_body.free_body(I, m0, h, n, order, n)
            return Run(None, None, None, ms[-1] / I, evals, n)
        ms, _ = rigid_body.free_body(I, m0, h, n, order, 1)
        t = t0 + h * np.arange(n + 1)
        idx = np.arange(100) * (n // 99)
        return Run(t, ms / I, ms[idx] / I, ms[-1] / I, evals, n)
    return Entry(f"splitting, order {order}", "step", run, [])


def sweep(case: Case, entries: list[Entry], *, repeats: int = 10, budget_s: float = 1.0) -> pd.DataFrame:
    rows = []
    t1 = case.problem.t_span[1]
    y_end = case.exact(t1)
    scale = np.max(np.abs(y_end))
    for entry in entries:
        for setting in entry.settings:
            seconds, _, runs = min_time(lambda: entry.run(setting, False), repeats=repeats, budget_s=budget_s)
            r = entry.run(setting, True)
            exact_steps = case.exact(r.t_steps)
            dense_err = np.max(np.abs(r.y_dense - case.exact(case.dense_t)))
            final_err = np.max(np.abs(r.y_final - y_end))
            row = {"problem": case.name, "method": entry.label, "kind": entry.kind, "setting": setting,
                   "error_final": final_err, "error_max_steps": np.max(np.abs(r.y_steps - exact_steps)),
                   "error_dense": dense_err, "digits": -np.log10(max(final_err / scale, 1e-17)),
                   "steps": r.n_steps, "evaluations": r.nfev, "seconds": seconds, "runs": runs}
            for name, f in case.invariants.items():
                values = f(r.y_steps)
                row[f"{name}_drift"] = float(np.max(np.abs(values - values[0])) / abs(values[0]))
            rows.append(row)
    return pd.DataFrame(rows)


def fitted_orders(frame: pd.DataFrame) -> dict:
    """Least-squares slope of log(final error) against log(h) for each fixed-step method."""
    out = {}
    for method, part in frame[frame.kind == "step"].groupby("method"):
        good = part.error_final > 1e-14
        if good.sum() >= 2:
            out[method] = float(np.polyfit(np.log(part.setting[good]), np.log(part.error_final[good]), 1)[0])
    return out


def plot(frame: pd.DataFrame, ax, orders: dict | None = None, error: str = "error_final", floor: float = 1e-17,
         xlabel: str = "error at the final time (max over components)"):
    """Log-log, error on x and time on y, one line per method (x inverted: accuracy grows to the right):
    solid for this library's adaptive methods, dashed for scipy's, dotted squares for fixed-step splittings."""
    for method, part in frame.groupby("method", sort=False):
        label = method + (f" (order {orders[method]:.2f})" if orders and method in orders else "")
        style = "o--" if method.startswith("scipy:") else ("s:" if method.startswith("splitting") else "o-")
        ax.loglog(np.maximum(part[error], floor), part.seconds, style, ms=3, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("wall time (s), min over repeats")
    ax.invert_xaxis()


def method_key(method: str) -> str:
    """A method's label as part of a results number's name: 'scipy:DOP853' -> 'scipy_DOP853',
    'splitting, order 2' -> 'splitting2', any other run of non-word characters -> '_'."""
    key = method.replace("scipy:", "scipy_").replace(", order ", "")
    return re.sub(r"\W+", "_", key).strip("_")


def best_by_method(frame: pd.DataFrame, error: str = "error_final") -> dict:
    """{method_key: (smallest error, the setting that reached it)} per method."""
    out = {}
    for method, part in frame.groupby("method", sort=False):
        best = part.loc[part[error].idxmin()]
        out[method_key(method)] = (float(best[error]), float(best.setting))
    return out
