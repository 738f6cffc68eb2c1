"""What every phase portrait of the study draws the same way: trajectories both ways in time, and the
singular points by type."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...solvers.ode import Events, Problem, solve
from ...solvers.runge_kutta import rhs_function

RTOL = 1e-12
BLOW_UP_BOUND = 1e8


@rhs_function
def velocity_zero(t, y, p, out):
    """The event y[1] = 0: p1 or q1 through zero, a turning point in phi2."""
    out[0] = y[1]


def period(rhs, params, start, span=80.0):
    """tau between two downward crossings of y[1] through zero: the period of a closed orbit."""
    sol = solve(Problem(rhs, start, (0.0, span), params), "dop853", rtol=1e-13, atol=1e-15,
                events=Events(velocity_zero, 1, (-1,)))
    return float(sol.event_t[1] - sol.event_t[0])


def series_check(results, measured, series, amplitudes, caption):
    """Lee §4: a period series against measured periods; its error must fall like eta^4."""
    rows = []
    for eta in amplitudes:
        m, s_ = measured(eta), series(eta)
        rows.append({"eta": eta, "period_measured": m, "period_series": s_, "relative_error": abs(s_ / m - 1.0)})
    frame = pd.DataFrame(rows)
    results.table("series", frame, caption)
    slope = float(np.polyfit(np.log(frame.eta), np.log(frame.relative_error), 1)[0])
    results.number("series_error_slope", slope, "1", note="log-log slope of the series' error against η; 4 expected")
    results.number("period_tau", measured(0.1), "τ", note="about the center, η = 0.1")
    results.hard_case("series_order", "The series' period error falls like η⁴ (|slope − 4|)", abs(slope - 4.0), 0.5)
    return frame


def trajectories(rhs, parameters, starts, tau_max, samples=600):
    """Each start integrated forward and backward in tau; parameters(direction) gives the rhs parameters."""
    out = []
    t = np.linspace(0.0, tau_max, samples)
    for start in starts:
        for direction in (1.0, -1.0):
            sol = solve(Problem(rhs, start, (0.0, tau_max), parameters(direction)), "dop853", rtol=RTOL,
                        atol=RTOL * 1e-2, t_eval=t, bound=BLOW_UP_BOUND)
            out.append(sol.y_eval[np.all(np.isfinite(sol.y_eval), axis=1)])
    return out


def mark_points(ax, points):
    style = {"saddle": ("x", "saddle"), "center": ("o", "center"), "degenerate": ("^", "degenerate point")}
    seen = set()
    for pt in points:
        marker, label = style[pt["type"]]
        ax.plot(pt["phi2"], 0.0, marker, color="C0", ms=6, mfc="none" if marker == "o" else None,
                label=None if label in seen else label)
        seen.add(label)


def finish(ax, points, phi2_range, y_max, y_label):
    """Singular points, the window, the labels and the legend of a portrait."""
    mark_points(ax, points)
    ax.set_xlim(*phi2_range)
    ax.set_ylim(-y_max, y_max)
    ax.set_xlabel("φ2")
    ax.set_ylabel(y_label)
    ax.legend(fontsize=6, loc="upper left", framealpha=0.9)
