"""Energy and Casimir error over 10^2 ... 10^6 periods: the splitting against adaptive Runge-Kutta."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...models import rigid_body as rhs
from ...solvers import references as ref
from ...solvers import rigid_body
from ...solvers.ode import Problem, solve
from ..results import new_figure

EPS = np.finfo(float).eps


def run(scene, results, quick):
    numerics = scene.data["numerics"]
    max_periods = min(numerics["max_periods"], 1e4) if quick else numerics["max_periods"]
    I, m0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0
    period = ref.HNW_PERIOD
    H0, C0 = 0.5 * np.sum(m0 * m0 / I), np.sum(m0 * m0)
    decades = 10.0 ** np.arange(2, int(round(np.log10(max_periods))) + 1)
    rows = []
    curves = {}
    h = numerics["step"]
    for order in (2, 4):
        n_steps = int(max_periods * period / h)
        block = max(1, n_steps // 20000)
        dH, dC = rigid_body.invariant_errors(I, m0, h, n_steps, order, block)
        t_periods = (np.arange(dH.size) + 1) * block * h / period      # end of each block
        curves[f"splitting order {order}, h = {h}"] = (t_periods, dH, dC, block * h / period)
    rtol = numerics["rtol"]
    t_eval = np.unique(np.concatenate([np.linspace(0, max_periods, 20001) * period]))
    sol = solve(Problem(rhs.euler_free, ref.HNW_Y0, (0.0, max_periods * period), rhs.euler_coefficients(I)), "dop853",
                rtol=rtol,
                atol=rtol * 1e-3, t_eval=t_eval)
    m = sol.y_eval * I
    curves[f"dop853, rtol = {rtol:g}"] = (t_eval / period, np.abs(0.5 * np.sum(m * m / I, axis=1) - H0) / H0,
                                         np.abs(np.sum(m * m, axis=1) - C0) / C0, sol.n_steps / max_periods)
    for label, (tp, dH, dC, steps_per_period) in curves.items():
        for decade in decades:
            upto = tp <= decade * (1 + 1e-9)
            rows.append({"method": label, "periods": decade, "energy_error_max": float(dH[upto].max()),
                         "casimir_error_max": float(dC[upto].max())})
    frame = pd.DataFrame(rows)
    results.table("long_horizon", frame, "HNW rigid body: largest relative error of the energy and of the Casimir "
                  "|m|² up to each number of periods.")
    fig, axes = new_figure(6.4, 4.2)
    for label, (tp, dH, dC, _) in curves.items():
        keep = tp > 0
        running_H = np.maximum.accumulate(dH)
        axes.loglog(tp[keep], np.maximum(running_H[keep], 1e-17), label=f"energy, {label}")
        if label.startswith("splitting order 2"):
            axes.loglog(tp[keep], np.maximum(np.maximum.accumulate(dC)[keep], 1e-17), ":",
                        label=f"Casimir, {label}")
    steps_per_period = period / h
    tt = np.logspace(0, np.log10(max_periods), 50)
    axes.loglog(tt, np.sqrt(tt * steps_per_period) * EPS, "k--", lw=0.9, label="√N·eps (Brouwer), N = steps")
    axes.set_xlabel("time (periods of the HNW body)")
    axes.set_ylabel("relative error, running maximum")
    axes.legend(fontsize=7)
    results.figure("long_horizon", fig, f"Long horizons: the splitting's energy error is bounded and its Casimir "
                   f"error follows Brouwer's √N·eps random walk; adaptive DOP853's energy error drifts linearly. "
                   f"Up to {max_periods:g} periods.")
    last = frame[frame.periods == decades[-1]]
    for _, row in last.iterrows():
        key = "splitting2" if row.method.startswith("splitting order 2") else (
            "splitting4" if row.method.startswith("splitting order 4") else "dop853")
        results.number(f"{key}_energy_error_at_max", row.energy_error_max, "1", note=f"{decades[-1]:g} periods")
        results.number(f"{key}_casimir_error_at_max", row.casimir_error_max, "1", note=f"{decades[-1]:g} periods")
    s2 = frame[frame.method.str.startswith("splitting order 2")]
    first, final = s2.energy_error_max.iloc[0], s2.energy_error_max.iloc[-1]
    n_total = max_periods * period / h
    results.number("max_periods", max_periods, "periods")
    results.number("splitting2_energy_growth", final / first, "1",
                   note=f"error up to {decades[-1]:g} periods / up to {decades[0]:g}")
    results.number("splitting2_casimir_over_brouwer", s2.casimir_error_max.iloc[-1] / (np.sqrt(n_total) * EPS), "1",
                   note="Casimir error / (sqrt(N) eps)")
    results.hard_case("splitting_energy_bounded", f"Splitting energy error does not grow from {decades[0]:g} to "
                      f"{decades[-1]:g} periods (ratio ≤ 2)", final / first, 2.0)
    results.hard_case("splitting_casimir_brouwer", "Splitting Casimir error within 10·√N·eps (round-off only)",
                      s2.casimir_error_max.iloc[-1] / (10 * np.sqrt(n_total) * EPS), 1.0)
    d = frame[frame.method.str.startswith("dop853")]
    results.number("dop853_energy_drift_ratio", d.energy_error_max.iloc[-1] / d.energy_error_max.iloc[0], "1",
                   note=f"error up to {decades[-1]:g} periods / up to {decades[0]:g}: linear drift gives "
                        f"{decades[-1] / decades[0]:g}")
