"""Energy and Casimir error over 10^2 ... 10^6 periods: the splitting against adaptive Runge-Kutta."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...figure_style import legend_below, method_colour
from ...formatting import format_number, shortest
from ...models import rigid_body as rhs
from ...results import new_figure
from ...solvers import references as ref
from ...solvers import rigid_body
from ...solvers import workprecision as wp
from ...solvers.ode import Problem, solve

EPS = np.finfo(float).eps


class LongHorizon(NamedTuple):
    max_periods: float
    step: float  # the splittings' h
    rtol: float  # DOP853's
    decades: np.ndarray  # the numbers of periods the table reads
    curves: dict  # label -> (time in periods, energy error, Casimir error, steps per period)
    frame: pd.DataFrame  # per method and decade: the largest energy and Casimir errors up to it
    energy_growth: float  # the order-2 splitting's energy error up to the last decade over up to the first
    casimir_over_brouwer: float  # its Casimir error over sqrt(N) eps, N steps
    casimir_over_ten_brouwer: float  # the hard case's: over 10 sqrt(N) eps
    dop853_drift_ratio: float  # DOP853's energy error, last decade over first


def long_horizon(max_periods, h, rtol) -> LongHorizon:
    """The HNW rigid body over max_periods: the splittings (order 2, 4) at step h and DOP853 at rtol."""
    I, m0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0
    period = ref.HNW_PERIOD
    H0, C0 = 0.5 * np.sum(m0 * m0 / I), np.sum(m0 * m0)
    decades = 10.0 ** np.arange(2, int(round(np.log10(max_periods))) + 1)
    rows = []
    curves = {}
    for order in (2, 4):
        n_steps = int(max_periods * period / h)
        block = max(1, n_steps // 20000)
        dH, dC = rigid_body.invariant_errors(I, m0, h, n_steps, order, block)
        t_periods = (np.arange(dH.size) + 1) * block * h / period  # end of each block
        curves[f"splitting, order {order}"] = (t_periods, dH, dC, block * h / period)
    t_eval = np.unique(np.concatenate([np.linspace(0, max_periods, 20001) * period]))
    sol = solve(
        Problem(rhs.euler_free, ref.HNW_Y0, (0.0, max_periods * period), rhs.euler_coefficients(I)),
        "dop853",
        rtol=rtol,
        atol=rtol * 1e-3,
        t_eval=t_eval,
    )
    m = sol.y_eval * I
    curves["DOP853"] = (
        t_eval / period,
        np.abs(0.5 * np.sum(m * m / I, axis=1) - H0) / H0,
        np.abs(np.sum(m * m, axis=1) - C0) / C0,
        sol.n_steps / max_periods,
    )
    for label, (tp, dH, dC, steps_per_period) in curves.items():
        for decade in decades:
            upto = tp <= decade * (1 + 1e-9)
            rows.append(
                {
                    "method": label,
                    "periods": decade,
                    "energy_error_max": float(dH[upto].max()),
                    "casimir_error_max": float(dC[upto].max()),
                }
            )
    frame = pd.DataFrame(rows)
    s2 = frame[frame.method == "splitting, order 2"]
    n_total = max_periods * period / h
    d = frame[frame.method == "DOP853"]
    return LongHorizon(
        max_periods,
        h,
        rtol,
        decades,
        curves,
        frame,
        s2.energy_error_max.iloc[-1] / s2.energy_error_max.iloc[0],
        s2.casimir_error_max.iloc[-1] / (np.sqrt(n_total) * EPS),
        s2.casimir_error_max.iloc[-1] / (10 * np.sqrt(n_total) * EPS),
        d.energy_error_max.iloc[-1] / d.energy_error_max.iloc[0],
    )


def run(scene, results, quick):
    numerics = scene.data["numerics"]
    max_periods = min(numerics["max_periods"], 1e4) if quick else numerics["max_periods"]
    _record_long_horizon(results, long_horizon(max_periods, numerics["step"], numerics["rtol"]))


def _record_long_horizon(results, values: LongHorizon):
    max_periods, h, rtol, decades = values.max_periods, values.step, values.rtol, values.decades
    curves, frame = values.curves, values.frame
    results.table(
        "long_horizon",
        frame,
        "The rigid body of Hairer, Nørsett and Wanner: the largest relative error "
        "of the energy and of the Casimir $|\\mathbf{m}|^2$ up to each number of periods, for the "
        f"Lie–Poisson splittings at step $h$ = {shortest(h)} and DOP853 at relative tolerance "
        f"{format_number(rtol, 1)}.",
        headers={
            "method": "method",
            "periods": "periods",
            "energy_error_max": "energy error",
            "casimir_error_max": "Casimir error",
        },
    )
    fig, axes = new_figure(height=3.0)  # fits below the section that opens its page
    for label, (tp, dH, dC, _) in curves.items():
        keep = tp > 0
        running_H = np.maximum.accumulate(dH)
        method = label.replace(", order ", "")
        axes.loglog(
            tp[keep],
            np.maximum(running_H[keep], 1e-17),
            color=method_colour(method),
            label=f"energy, {label}",
        )
        if label == "splitting, order 2":
            axes.loglog(
                tp[keep],
                np.maximum(np.maximum.accumulate(dC)[keep], 1e-17),
                ":",
                color=method_colour(method),
                label=f"Casimir, {label}",
            )
    steps_per_period = ref.HNW_PERIOD / h
    tt = np.logspace(0, np.log10(max_periods), 50)
    axes.loglog(
        tt,
        np.sqrt(tt * steps_per_period) * EPS,
        "--",
        color="0.4",
        lw=0.9,
        label="$\\sqrt{N}\\,\\varepsilon$ (Brouwer), $N$ steps",
    )
    axes.set_xlabel("time (periods of the body)")
    axes.set_ylabel("relative error, running maximum")
    wp.decade_ticks(axes.xaxis)
    wp.decade_ticks(axes.yaxis)
    legend_below(fig, *axes.get_legend_handles_labels(), ncol=3)
    results.figure(
        "long_horizon",
        fig,
        "The rigid body of Hairer, Nørsett and Wanner over "
        f"{format_number(max_periods, 2)} periods: the largest relative error so far of the energy (solid) "
        "and of the Casimir $|\\mathbf{m}|^2$ (dotted), for the Lie–Poisson splittings at step $h$ = "
        f"{shortest(h)} and adaptive DOP853 at relative tolerance {format_number(rtol, 1)}. The "
        "splitting's energy error stays bounded and its Casimir error follows Brouwer's random walk of "
        "rounding errors, $\\sqrt{N}\\,\\varepsilon$ after $N$ steps ($\\varepsilon$ the machine "
        "epsilon, dashed); DOP853's energy error drifts linearly.",
    )
    last = frame[frame.periods == decades[-1]]
    for _, row in last.iterrows():
        key = {"splitting, order 2": "splitting2", "splitting, order 4": "splitting4", "DOP853": "dop853"}[
            row.method
        ]
        results.number(
            f"{key}_energy_error_at_max", row.energy_error_max, "1", note=f"{decades[-1]:g} periods"
        )
        results.number(
            f"{key}_casimir_error_at_max", row.casimir_error_max, "1", note=f"{decades[-1]:g} periods"
        )
    results.number("max_periods", max_periods, "periods")
    results.number(
        "splitting2_energy_growth",
        values.energy_growth,
        "1",
        note=f"error up to {decades[-1]:g} periods / up to {decades[0]:g}",
    )
    results.number(
        "splitting2_casimir_over_brouwer",
        values.casimir_over_brouwer,
        "1",
        note="Casimir error / (sqrt(N) eps)",
    )
    results.hard_case(
        "splitting_energy_bounded",
        "The second-order splitting's energy error does not grow from "
        f"{format_number(decades[0], 1)} to {format_number(decades[-1], 1)} periods: its largest value "
        "over the whole run against that over the first (ratio, at most 2)",
        values.energy_growth,
        2.0,
    )
    results.hard_case(
        "splitting_casimir_brouwer",
        "The second-order splitting's Casimir error over "
        "$10\\sqrt{N}\\,\\varepsilon$ after $N$ steps (round-off only)",
        values.casimir_over_ten_brouwer,
        1.0,
    )
    results.number(
        "dop853_energy_drift_ratio",
        values.dop853_drift_ratio,
        "1",
        note=f"error up to {decades[-1]:g} periods / up to {decades[0]:g}: linear drift gives "
        f"{decades[-1] / decades[0]:g}",
    )
