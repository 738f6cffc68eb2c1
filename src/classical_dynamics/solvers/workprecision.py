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

from ..formatting import format_number
from . import rigid_body
from .fixed_step import FixedProblem, Save, solve_fixed
from .ode import Problem, solve
from .timing import min_time


@dataclass
class Run:
    t_steps: np.ndarray
    y_steps: np.ndarray
    y_dense: np.ndarray  # on the 100 points of Case.dense_t
    y_final: np.ndarray
    nfev: int
    n_steps: int


@dataclass
class Case:
    name: str
    problem: Problem
    exact: Callable  # t -> y
    invariants: dict  # name -> f(y rows) -> values

    @property
    def dense_t(self):
        return np.linspace(self.problem.t_span[0], self.problem.t_span[1], 100)


@dataclass
class Entry:
    """One line of a work-precision diagram: a method and how to run it at a setting."""

    label: str
    kind: str  # "tolerance" or "step"
    run: Callable  # run(setting, record) -> Run (record=False may return only y_final)
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
    body = FixedProblem(rigid_body.packed(I * case.problem.y0), I, t0=t0)
    method = f"rigid-splitting{order}"

    def run(h, record):
        n = 99 * max(1, int(round((t1 - t0) / h / 99)))  # a multiple of 99: the 100 dense points are steps
        h = (t1 - t0) / n
        evals = n * (5 if order == 2 else 15)  # exact rotations (the analogue of f-evaluations)
        if not record:
            y = solve_fixed(body, method, h=h, n_steps=n, save=Save(final=True)).y
            return Run(None, None, None, y[:3] / I, evals, n)
        sol = solve_fixed(body, method, h=h, n_steps=n)
        ms = sol.y_eval[:, :3]
        idx = np.arange(100) * (n // 99)
        return Run(sol.t_eval, ms / I, ms[idx] / I, ms[-1] / I, evals, n)

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
            row = {
                "problem": case.name,
                "method": entry.label,
                "kind": entry.kind,
                "setting": setting,
                "error_final": final_err,
                "error_max_steps": np.max(np.abs(r.y_steps - exact_steps)),
                "error_dense": dense_err,
                "digits": -np.log10(max(final_err / scale, 1e-17)),
                "steps": r.n_steps,
                "evaluations": r.nfev,
                "seconds": seconds,
                "runs": runs,
            }
            for name, f in case.invariants.items():
                values = f(r.y_steps)
                row[f"{name}_drift"] = float(np.max(np.abs(values - values[0])) / abs(values[0]))
            rows.append(row)
    return pd.DataFrame(rows)


def fitted_orders(frame: pd.DataFrame) -> dict:
    """Least-squares slope of log(final error) against log(h) for each fixed-step method, h the step
    taken: span/steps (a splitting rounds its step count to a multiple of 99, so the nominal h can differ)."""
    out = {}
    for method, part in frame[frame.kind == "step"].groupby("method"):
        good = part.error_final > 1e-14
        if good.sum() >= 2:
            log_h = -np.log(part.steps[good].to_numpy(float))  # log(span/steps) up to a constant
            out[method] = float(np.polyfit(log_h, np.log(part.error_final[good]), 1)[0])
    return out


def _colours(methods) -> dict:
    """Each method's colour of every figure ('splitting, order 2' is splitting2); a method without one takes
    the first palette colour no other method of the figure has (the palette's order otherwise)."""
    from ..figure_style import METHOD_COLOURS, OKABE_ITO, method_colour

    known = {name.lower() for name in METHOD_COLOURS}
    keys = {m: m.replace(", order ", "").lower() for m in methods}
    out = {m: method_colour(k) for m, k in keys.items() if k in known}
    free = [c for c in OKABE_ITO[:-1] if c not in out.values()] + ["#7F7F7F"]  # grey, not the faint yellow
    for index, m in enumerate(m for m in methods if m not in out):
        out[m] = free[index] if index < len(free) else method_colour(m, index)
    return out


def decade_ticks(axis, max_labels: int | None = None) -> None:
    """Label a log axis at powers of ten only, at most max_labels of them (every second or third decade on a
    long axis), so that no two labels run into each other. By default from the width of the axes' column."""
    from matplotlib.ticker import LogLocator, NullFormatter

    if max_labels is None:
        fig, spec = axis.axes.figure, axis.axes.get_subplotspec()
        columns = spec.get_gridspec().ncols if spec is not None else 1
        size = fig.get_figwidth() / columns if axis.axis_name == "x" else fig.get_figheight()
        max_labels = max(3, int(size / 0.55))
    low, high = sorted(abs(v) for v in axis.get_view_interval())
    decades = np.log10(high / low) if low > 0 else 0.0
    axis.set_major_locator(LogLocator(base=10.0, numticks=max_labels))
    # on a long axis the minor ticks mark the unlabelled decades only (2, 3, ... 9 would grey the grid)
    subs = (1.0,) if decades > max_labels else np.arange(2, 10) * 0.1
    axis.set_minor_locator(LogLocator(base=10.0, subs=subs, numticks=100))
    axis.set_minor_formatter(NullFormatter())


def plot(
    frame: pd.DataFrame,
    ax,
    orders: dict | None = None,
    error: str = "error_final",
    floor: float = 1e-17,
    xlabel: str = "error at the final time",
):
    """Log-log, error on x and wall time on y, one line per method (x inverted: accuracy grows to the right):
    solid for this library's adaptive methods, dashed for SciPy's, dotted squares for fixed-step splittings.
    Each line is labelled with its method's name and drawn in that method's colour of every figure; with
    `orders` the fitted order of a fixed-step method joins its label. The caller places the legend."""
    colours = _colours(list(dict.fromkeys(frame.method)))
    for method, part in frame.groupby("method", sort=False):
        label = method + (
            f" (fitted order {format_number(orders[method], 3)})" if orders and method in orders else ""
        )
        style = "o--" if method.startswith("scipy:") else ("s:" if method.startswith("splitting") else "o-")
        ax.loglog(
            np.maximum(part[error], floor), part.seconds, style, ms=3, color=colours[method], label=label
        )
    ax.set_xlabel(xlabel)
    ax.set_ylabel("wall time (s)")
    ax.invert_xaxis()
    decade_ticks(ax.xaxis)
    decade_ticks(ax.yaxis)


def nominal_order(method: str) -> int | None:
    """The order a fixed-step method is built to have, read from its label ('splitting, order 4' -> 4)."""
    match = re.search(r"order (\d+)", method)
    return int(match.group(1)) if match else None


def plot_convergence(
    frame: pd.DataFrame,
    ax,
    orders: dict | None = None,
    error: str = "error_final",
    nominal: dict | None = None,
    xlabel: str = "step $h$",
    ylabel: str = "error at the final time",
):
    """Observed convergence of the fixed-step methods: error against step h (log-log), each method in its
    colour and style of plot() with its fitted order in the label, and dashed reference slopes h^p for the
    nominal orders p, drawn through the centre of the method's points and moved down by a factor 4, so that
    the slopes compare side by side."""
    steps = frame[frame.kind == "step"]
    colours = _colours(list(dict.fromkeys(steps.method)))
    for method, part in steps.groupby("method", sort=False):
        colour = colours[method]
        fitted = (orders or {}).get(method)
        label = method + (f" (fitted order {format_number(fitted, 3)})" if fitted is not None else "")
        part = part.sort_values("setting")
        ax.loglog(part.setting, part[error], "s:", ms=3, color=colour, label=label)
        p = (nominal or {}).get(method, nominal_order(method))
        good = part[part[error] > 1e-14]
        if p is None or len(good) < 1:
            continue
        h = np.geomspace(part.setting.min(), part.setting.max(), 20)
        centre_h = np.exp(np.mean(np.log(good.setting)))
        centre_e = np.exp(np.mean(np.log(good[error])))
        ax.loglog(
            h,
            centre_e / 4.0 * (h / centre_h) ** p,
            "--",
            lw=0.9,
            color=colour,
            label=f"reference slope $h^{{{p}}}$",
        )
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    decade_ticks(ax.xaxis)
    decade_ticks(ax.yaxis)


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
