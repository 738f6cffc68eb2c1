"""What accuracy costs for a century of wobble: methods against the closed form, and their spurious Q.

Error: |m(T) - m_exact(T)| / |m(0)| at the final time (m = p + iq, the pole about the figure axis).
Numerical damping: a method that changes the amplitude by rho over T behaves like a quality factor
Q_num = sigma T / (-2 ln rho) (negative: it pumps energy in); compare with the Earth's Q of about 100.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...figure_style import legend_below
from ...formatting import format_number, plural, shortest
from ...models import earth
from ...results import new_figure
from ...solvers import references as ref
from ...solvers import rigid_body
from ...solvers import workprecision as wp
from ...solvers.fixed_step import FixedProblem, Save, solve_fixed
from ...solvers.timing import min_time
from . import model as wobble_model
from .cost import DEFAULT_SPAN_YEARS
from .model import arcsec_text

QUICK_SPAN_YEARS = 10.0


def _exact(model, amplitude, T):
    a, b = earth.moments_over_c(model.H, model.b_minus_a_over_c)
    w0 = model.n * np.array([amplitude, 0.0, 1.0])
    if model.b_minus_a_over_c == 0.0:
        lam = model.n * model.wobble_frequency()
        return amplitude * np.exp(1j * lam * T)
    I = np.array([a, b, 1.0])
    w = ref.free_rigid_body(I, I * w0, np.array([T]))[0] / model.n
    return w[0] + 1j * w[1]


def run(scene, results, quick):
    H, amplitude, model = wobble_model.setup(scene)
    spec = scene.data["analysis"]["accuracy_cost"]
    span_years = QUICK_SPAN_YEARS if quick else scene.data["analysis"].get("span_years", DEFAULT_SPAN_YEARS)
    frame = work_precision(model, amplitude, span_years, spec)
    _record_work_precision(results, frame, span_years, amplitude)


def work_precision(model, amplitude, span_years, spec) -> pd.DataFrame:
    """Each method of spec at each step (splittings) or tolerance, over span_years of a wobble of
    `amplitude`: the table's rows (error at the end and amplitude change relative to the amplitude, the
    spurious Q that change amounts to, steps, wall time as the minimum of repeats)."""
    T = span_years * earth.JULIAN_YEAR_DAYS
    exact = _exact(model, amplitude, T)
    sigma = model.n * model.wobble_frequency()
    repeats = spec.get("repeats", 5)
    a, b = earth.moments_over_c(model.H, model.b_minus_a_over_c)
    I = np.array([a, b, 1.0])
    rows = []

    def record(method, setting, kind, seconds, z, steps):
        rho = abs(z) / amplitude
        log_rho = np.log(rho)
        rows.append(
            {
                "method": method,
                "kind": kind,
                "setting": setting,
                "error_final": abs(z - exact) / amplitude,
                "amplitude_change": rho - 1.0,
                "spurious_Q": sigma * T / (-2.0 * log_rho) if log_rho != 0.0 else np.inf,
                "steps": steps,
                "seconds": seconds,
            }
        )

    for method in spec["methods"]:
        if method.startswith("splitting"):
            order = int(method[-1])
            for h in spec["steps"]:
                n = int(round(T / h))
                problem = FixedProblem(rigid_body.packed(I * model.n * np.array([amplitude, 0.0, 1.0])), I)
                run = lambda: solve_fixed(
                    problem, f"rigid-splitting{order}", h=T / n, n_steps=n, save=Save(final=True)
                )
                seconds, sol, _ = min_time(run, repeats=min(repeats, 3), budget_s=2.0)
                y = sol.y[:3] / I / model.n
                record(f"splitting, order {order}", h, "step", seconds, y[0] + 1j * y[1], n)
            continue
        for rtol in spec["tolerances"]:
            run = lambda: wobble_model.integrate(model, amplitude, T, rtol, None, method)
            seconds, sol, _ = min_time(run, repeats=repeats, budget_s=1.0)
            record(method, rtol, "tolerance", seconds, sol.y[0] + 1j * sol.y[1], sol.n_steps)
    return pd.DataFrame(rows)


def _record_work_precision(results, frame, span_years, amplitude):
    """The accuracy table, its timings, the work-precision figure, the best errors and the speed-up."""
    results.number("accuracy_span_years", span_years, "yr")
    span_text = f"{shortest(span_years)} {plural(span_years, 'year')}"
    results.table(
        "accuracy",
        frame.drop(columns=["seconds"]),
        f"A {arcsec_text(amplitude)}″ wobble over {span_text}, by method and step (d) or "
        "tolerance (rtol): the error at the end relative to the wobble's amplitude, the amplitude's "
        "relative change, and the quality factor $Q_\\mathrm{num}$ that change amounts to (negative: the "
        "method pumps energy in; ∞: no change at all in double precision). Compare with the Earth's "
        "own $Q$ (the damped scene's, in the text).",
        headers=HEADERS,
    )
    results.timing_table(
        "accuracy",
        frame,
        f"Work-precision of the {shortest(span_years)}-year wobble: the runs "
        "of the accuracy table with their wall times (minimum of repeats).",
        headers={**HEADERS, "seconds": "wall time (s)"},
    )
    fig, ax = new_figure(6.2, 3.6)
    wp.plot(frame, ax, floor=1e-16, xlabel="error at the final time / wobble amplitude")
    legend_below(fig)  # below the axes: no line hidden under it
    results.timing_figure(
        "work_precision",
        fig,
        f"Wall time against the error at the end of {span_text} of wobble "
        "(relative to the amplitude; errors below "
        f"{format_number(1e-16, 1)} drawn at that floor), one line per method: adaptive Runge–Kutta "
        "in the body frame, compiled (solid) and through SciPy (dashed), and the "
        "Lie–Poisson splitting (fixed steps, dotted). Runge–Kutta follows only the slow wobble; "
        "the splitting turns the body through every day of spin and pays for it.",
    )
    for key, (best, setting) in wp.best_by_method(frame).items():
        results.number(f"best_error_{key}", best, "1", note=f"at {format_number(setting, 3)}")
    for method, part in frame.groupby("method", sort=False):
        results.number(
            f"min_abs_spurious_Q_{wp.method_key(method)}",
            float(np.min(np.abs(part.spurious_Q))),
            "1",
            note="smallest $|Q_\\mathrm{num}|$ over the settings",
        )
    _record_speedup(results, speedup_rows(frame))


def speedup_rows(frame):
    """Compiled DOP853 against scipy's DOP853 at the same tolerance: same steps, the ratio is overhead.
    The table's rows (rtol, the two wall times in seconds, their ratio), one per common setting."""
    ours, peer = frame[frame.method == "dop853"], frame[frame.method == "scipy:DOP853"]
    common = sorted(set(ours.setting) & set(peer.setting))
    rows = [
        {
            "rtol": s,
            "dop853_seconds": float(ours[ours.setting == s].seconds.iloc[0]),
            "scipy_DOP853_seconds": float(peer[peer.setting == s].seconds.iloc[0]),
        }
        for s in common
    ]
    for row in rows:
        row["speedup"] = row["scipy_DOP853_seconds"] / row["dop853_seconds"]
    return rows


def _record_speedup(results, rows):
    if rows:
        results.timing_table(
            "speedup",
            pd.DataFrame(rows),
            "The compiled DOP853 against SciPy's at the same tolerance (same method, same steps): "
            "the ratio of wall times is the overhead of the interpreted loop.",
            headers={
                "rtol": "rtol",
                "dop853_seconds": "DOP853, compiled (s)",
                "scipy_DOP853_seconds": "SciPy DOP853 (s)",
                "speedup": "speed-up",
            },
        )


HEADERS = {
    "method": "method",
    "kind": "control",
    "setting": "step (d) or rtol",
    "error_final": "final error / amplitude",
    "amplitude_change": "amplitude change",
    "spurious_Q": "$Q_\\mathrm{num}$",
    "steps": "steps",
}
