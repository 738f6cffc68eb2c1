"""What every phase portrait of the study draws the same way: trajectories both ways in time, and the
singular points by type."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
from matplotlib.lines import Line2D

from ...solvers.workprecision import legend_below

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
    results.table("series", frame, caption, headers={"eta": "amplitude $\\eta$",
                                                     "period_measured": "period, integrated ($\\tau$)",
                                                     "period_series": "period, series ($\\tau$)",
                                                     "relative_error": "relative error"})
    slope = float(np.polyfit(np.log(frame.eta), np.log(frame.relative_error), 1)[0])
    results.number("series_error_slope", slope, "1", note="log-log slope of the series' error against η; 4 expected")
    results.number("period_tau", measured(0.1), "τ", note="about the center, η = 0.1")
    results.hard_case("series_order", "The period series' error falls like $\\eta^4$: $|s - 4|$ for its fitted "
                      "log-log slope $s$ against the amplitude $\\eta$", abs(slope - 4.0), 0.5)
    return frame


def series_figure(ax, frame, slope):
    """A period series' relative error against the amplitude (log-log), the fitted slope in the legend, and the
    dashed reference slope eta^4 through the points' centre, moved down by a factor 3 so both stay visible."""
    from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator
    from ...formatting import format_number, shortest
    eta, err = frame.eta.to_numpy(), frame.relative_error.to_numpy()
    ax.loglog(eta, err, "o-", color="k", ms=3.5, label=f"series against integration (fitted slope "
              f"{format_number(slope, 3)})")
    centre_eta, centre_err = np.exp(np.mean(np.log(eta))), np.exp(np.mean(np.log(err)))
    line = np.geomspace(eta.min(), eta.max(), 20)
    ax.loglog(line, centre_err / 3.0 * (line / centre_eta) ** 4, "--", color="#D55E00", lw=1.0,
              label="reference slope $\\eta^4$")
    ax.xaxis.set_major_locator(FixedLocator(sorted(eta)))        # less than a decade: the amplitudes themselves
    ax.xaxis.set_major_formatter(lambda x, _: shortest(float(x)))
    ax.xaxis.set_minor_locator(NullLocator())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("amplitude $\\eta$")
    ax.set_ylabel("relative error of the period")
    ax.figure.legend(loc="outside lower center", ncol=1)


COUNTS = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}


def param_text(value) -> str:
    """A parameter as the scene gave it (0.3), or to four figures when it was computed (0.4091 for nu_c)."""
    from ...formatting import format_number, shortest
    text = shortest(float(value))
    return text if len(re.sub(r"\D", "", text.split(" ")[0])) <= 6 else format_number(float(value), 4)


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


LIMIT_CYCLE_COLOUR = "#D55E00"      # F and F1 (vermillion), in the portrait and on the cylinder
EULER_COLOUR = "#0072B2"            # Euler's equations mapped into the plane (blue dots)


def mark_points(ax, points):
    style = {"saddle": ("x", "saddle"), "center": ("o", "center"), "degenerate": ("^", "degenerate point")}
    seen = set()
    for pt in points:
        marker, label = style[pt["type"]]
        ax.plot(pt["phi2"], 0.0, marker, color="k", ms=6, mew=1.2, mfc="white" if marker == "o" else None,
                label=None if label in seen else label, zorder=5, clip_on=False)   # whole at the window's edge
        seen.add(label)


def pi_ticks(axis, low, high):
    """Ticks at multiples of pi (of 2 pi on a long axis), labelled -2π, −π, 0, π, 2π."""
    from matplotlib.ticker import FuncFormatter, MultipleLocator
    step = 1 if (high - low) / np.pi <= 8 else 2

    def label(x, _):
        k = int(round(x / np.pi))
        return "0" if k == 0 else {1: "$\\pi$", -1: "$-\\pi$"}.get(k, f"${k}\\pi$")

    axis.set_major_locator(MultipleLocator(step * np.pi))
    axis.set_major_formatter(FuncFormatter(label))


def finish(ax, points, phi2_range, y_max, y_label, angle=False):
    """Singular points, the window, the labels and the legend of a portrait. angle: phi2 is an angle (the
    largest axis' plane), with ticks at multiples of pi; otherwise a logarithm (the middle axis'), no unit."""
    mark_points(ax, points)
    ax.set_xlim(*phi2_range)
    ax.set_ylim(-y_max, y_max)
    if angle:
        pi_ticks(ax.xaxis, *phi2_range)
    ax.set_xlabel("$\\varphi_2$ (rad)" if angle else "$\\varphi_2$")
    ax.set_ylabel(y_label)
    handles, labels = ax.get_legend_handles_labels()
    handles.insert(0, Line2D([], [], color="0.6", lw=0.6))
    labels.insert(0, "trajectories of the plane")
    legend_below(ax.figure, handles, labels, ncol=4)
