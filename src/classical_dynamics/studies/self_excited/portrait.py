"""What every phase portrait of the study draws the same way: trajectories both ways in time, and the
singular points by type."""

from __future__ import annotations

import re
from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.lines import Line2D

from ...figure_style import legend_below
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
    sol = solve(
        Problem(rhs, start, (0.0, span), params),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        events=Events(velocity_zero, 1, (-1,)),
    )
    return float(sol.event_t[1] - sol.event_t[0])


class SeriesCheck(NamedTuple):
    """Lee §4: a period series against measured periods (in tau)."""

    frame: pd.DataFrame  # by amplitude eta: measured, series, relative error
    slope: float  # log-log slope of the error against eta: 4 expected
    period_tau: float  # measured about the center, eta = 0.1


def series_periods(measured, series, amplitudes) -> SeriesCheck:
    """measured(eta), series(eta): the period of the orbit started eta from the center, integrated and from
    the series."""
    rows = []
    for eta in amplitudes:
        m, s_ = measured(eta), series(eta)
        rows.append(
            {"eta": eta, "period_measured": m, "period_series": s_, "relative_error": abs(s_ / m - 1.0)}
        )
    frame = pd.DataFrame(rows)
    slope = float(np.polyfit(np.log(frame.eta), np.log(frame.relative_error), 1)[0])
    return SeriesCheck(frame, slope, measured(0.1))


def record_series_check(results, values: SeriesCheck, caption):
    results.table(
        "series",
        values.frame,
        caption,
        headers={
            "eta": "amplitude $\\eta$",
            "period_measured": "period, integrated ($\\tau$)",
            "period_series": "period, series ($\\tau$)",
            "relative_error": "relative error",
        },
    )
    results.number(
        "series_error_slope",
        values.slope,
        "1",
        note="log-log slope of the series' error against η; 4 expected",
    )
    results.number("period_tau", values.period_tau, "τ", note="about the center, η = 0.1")
    results.hard_case(
        "series_order",
        "The period series' error falls like $\\eta^4$: $|s - 4|$ for its fitted "
        "log-log slope $s$ against the amplitude $\\eta$",
        abs(values.slope - 4.0),
        0.5,
    )


def series_figure(ax, frame, slope, ncol=1):
    """A period series' relative error against the amplitude (log-log), the fitted slope in the legend, and
    the dashed reference slope eta^4 through the points' centre, moved down by a factor 3 so both stay
    visible."""
    from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator

    from ...formatting import format_number, shortest

    eta, err = frame.eta.to_numpy(), frame.relative_error.to_numpy()
    ax.loglog(
        eta,
        err,
        "o-",
        color="k",
        ms=3.5,
        label=f"series against integration (fitted slope {format_number(slope, 3)})",
    )
    centre_eta, centre_err = np.exp(np.mean(np.log(eta))), np.exp(np.mean(np.log(err)))
    line = np.geomspace(eta.min(), eta.max(), 20)
    ax.loglog(
        line,
        centre_err / 3.0 * (line / centre_eta) ** 4,
        "--",
        color="#D55E00",
        lw=1.0,
        label="reference slope $\\eta^4$",
    )
    ax.xaxis.set_major_locator(FixedLocator(sorted(eta)))  # less than a decade: the amplitudes themselves
    ax.xaxis.set_major_formatter(lambda x, _: shortest(float(x)))
    ax.xaxis.set_minor_locator(NullLocator())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("amplitude $\\eta$")
    ax.set_ylabel("relative error of the period")
    ax.figure.legend(loc="outside lower center", ncol=ncol)


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
            sol = solve(
                Problem(rhs, start, (0.0, tau_max), parameters(direction)),
                "dop853",
                rtol=RTOL,
                atol=RTOL * 1e-2,
                t_eval=t,
                bound=BLOW_UP_BOUND,
            )
            out.append(sol.y_eval[np.all(np.isfinite(sol.y_eval), axis=1)])
    return out


LIMIT_CYCLE_COLOUR = "#D55E00"  # F and F1 (vermillion), in the portrait and on the cylinder
EULER_COLOUR = "#0072B2"  # Euler's equations mapped into the plane (blue dots)


POINT_STYLE = {"saddle": ("x", "saddle"), "center": ("o", "center"), "degenerate": ("^", "degenerate point")}


def mark_points(ax, points, size=6):
    seen = set()
    for pt in points:
        marker, label = POINT_STYLE[pt["type"]]
        # whole at the window's edge
        ax.plot(
            pt["phi2"],
            0.0,
            marker,
            color="k",
            ms=size,
            mew=1.2 * size / 6,
            mfc="white" if marker == "o" else None,
            label=None if label in seen else label,
            zorder=5,
            clip_on=False,
        )
        seen.add(label)


def pi_ticks(axis, low, high, most=9):
    """Ticks at multiples of pi (of 2 pi on a long axis), labelled -2π, −π, 0, π, 2π. most: the most ticks the
    axis has room for (a narrow panel of a grid takes fewer: every 2 pi)."""
    from matplotlib.ticker import FuncFormatter, MultipleLocator

    step = 1 if (high - low) / np.pi <= min(8, most - 1) else 2

    def label(x, _):
        k = int(round(x / np.pi))
        return "0" if k == 0 else {1: "$\\pi$", -1: "$-\\pi$"}.get(k, f"${k}\\pi$")

    axis.set_major_locator(MultipleLocator(step * np.pi))
    axis.set_major_formatter(FuncFormatter(label))


def finish(ax, drawing, y_label, angle=False):
    """Draw a portrait from its recorded elements, with its window, labels and legend. angle: phi2 is an angle
    (the largest axis' plane), with ticks at multiples of pi; otherwise a logarithm (the middle axis'), no
    unit."""
    draw(ax, drawing.frame(), drawing.y_name)
    lo, hi = ax.get_xlim()
    axes_labels(ax, y_label, angle, (lo, hi))
    legend_below(ax.figure, *legend_entries(drawing.elements()), ncol=4)


def axes_labels(ax, y_label, angle, phi2_range, x=True, y=True, most_ticks=9):
    if angle:
        pi_ticks(ax.xaxis, *phi2_range, most=most_ticks)
    if x:
        ax.set_xlabel("$\\varphi_2$ (rad)" if angle else "$\\varphi_2$")
    if y:
        ax.set_ylabel(y_label)


# --- what a portrait draws, as data -------------------------------------------------------------------------
# A portrait is drawn from a tidy table (one row per plotted point) so that the study's gallery can redraw it
# as a panel of a grid: element, curve (one line per curve number), phi2 and the plane's velocity (p1 or q1).
ELEMENTS = {  # element: (plot keywords, legend label); the singular points are drawn by mark_points
    "trajectory": ({"color": "0.6", "lw": 0.55}, "trajectories of the plane"),
    "separatrix": ({"color": "k", "lw": 1.1}, "separatrices (closed form)"),
    "curve_C0": ({"color": "k", "lw": 1.1}, "$c_1 = 0$ (closed form)"),
    "limit_cycle_F": ({"color": LIMIT_CYCLE_COLOUR, "lw": 1.4}, "$F$ (stable limit cycle)"),
    "limit_cycle_F1": ({"color": LIMIT_CYCLE_COLOUR, "lw": 1.4, "ls": "--"}, "$F_1$ (unstable limit cycle)"),
    "rest_line": ({"color": LIMIT_CYCLE_COLOUR, "lw": 1.6}, "line of rest points"),
    "euler": ({"color": EULER_COLOUR, "ls": "", "marker": ".", "ms": 3}, "Euler's equations, mapped"),
    "separatrix_T": ({"color": "#009E73", "lw": 1.3}, "$T_1$, $T_2$ (integrated from the saddles)"),
    "crossing": (
        {"color": "k", "ls": "", "marker": "s", "ms": 3.5, "mfc": "white"},
        "$f_1$, $f_2$, $g_1$, $g_2$ (Lee's Figure 2.12)",
    ),
}
CROSSING_NAMES = {1: "$f_1$", 2: "$f_2$", 3: "$g_1$", 4: "$g_2$"}  # the curve numbers of the crossings
# their names' places (points): f2 straight under its point, inside T2's arch and clear of both its sides;
# g2 left of its point, clear of T2 rising from it
CROSSING_OFFSETS = {1: (-11, -9), 2: (-4, -13), 3: (-12, -9), 4: (-13, 2)}
POINT_TYPES = ("saddle", "center", "degenerate")
DIGITS = 5  # decimals kept in the table: far below what a printed portrait resolves


class Drawing:
    """The elements of one portrait, recorded as they are computed; `frame()` is the table, `draw()` the
    figure."""

    def __init__(self, y_name: str, reach: tuple):
        self.y_name, self.reach, self.parts, self.curves = y_name, reach, [], 0

    def curve(self, element, phi2, y):
        """A line (or the dots of Euler's integrations), kept only where it can be seen: inside `reach`, a box
        wider than any window it is drawn in, plus the first point beyond, so a line leaves the frame."""
        phi2, y = np.asarray(phi2, float), np.asarray(y, float)
        lo, hi, y_max = self.reach
        seen = np.isfinite(phi2) & np.isfinite(y) & (phi2 >= lo) & (phi2 <= hi) & (np.abs(y) <= y_max)
        keep = seen | np.r_[seen[1:], False] | np.r_[False, seen[:-1]]
        keep &= np.isfinite(phi2) & np.isfinite(y)
        runs = np.split(np.arange(len(y)), np.nonzero(np.diff(keep.astype(int)))[0] + 1)
        for run in runs:
            if keep[run[0]] and (len(run) > 1 or element == "euler"):
                if element != "euler":
                    run = run[_simplified(phi2[run] / (hi - lo), y[run] / (2 * y_max), SIMPLIFY)]
                self.parts.append(
                    pd.DataFrame(
                        {
                            "element": element,
                            "curve": self.curves,
                            "phi2": phi2[run].round(DIGITS),
                            self.y_name: y[run].round(DIGITS),
                        }
                    )
                )
                self.curves += 1

    def points(self, points):
        for pt in points:
            self.parts.append(
                pd.DataFrame(
                    {
                        "element": [pt["type"]],
                        "curve": [self.curves],
                        "phi2": [round(float(pt["phi2"]), 12)],
                        self.y_name: [0.0],
                    }
                )
            )
            self.curves += 1

    def window(self, lo, hi, y_max):
        self.parts.append(
            pd.DataFrame(
                {"element": "window", "curve": self.curves, "phi2": [lo, hi], self.y_name: [-y_max, y_max]}
            )
        )
        self.curves += 1

    def elements(self):
        return {element for part in self.parts for element in part.element}

    def frame(self) -> pd.DataFrame:
        return pd.concat(self.parts, ignore_index=True)

    def save(self, results, caption):
        results.table("portrait", self.frame(), caption, headers=TABLE_HEADERS)


def _simplified(x, y, tolerance):
    """Indices of the points of a polyline that keep it within `tolerance` of itself (Ramer-Douglas-Peucker):
    a curve sampled finely enough for its sharpest bend needs far fewer points along its straight
    stretches."""
    keep = np.zeros(len(x), bool)
    keep[[0, -1]] = True
    stack = [(0, len(x) - 1)]
    while stack:
        first, last = stack.pop()
        if last - first < 2:
            continue
        dx, dy = x[last] - x[first], y[last] - y[first]
        xs, ys = x[first + 1 : last] - x[first], y[first + 1 : last] - y[first]
        norm = np.hypot(dx, dy)
        distance = np.abs(dx * ys - dy * xs) / norm if norm > 0 else np.hypot(xs, ys)
        worst = int(np.argmax(distance))
        if distance[worst] > tolerance:
            middle = first + 1 + worst
            keep[middle] = True
            stack += [(first, middle), (middle, last)]
    return np.nonzero(keep)[0]


SIMPLIFY = 2e-4  # of the reach's width and height: about a hundredth of a millimetre in print
TABLE_HEADERS = {
    "element": "what is drawn",
    "curve": "curve",
    "phi2": "$\\varphi_2$",
    "p1": "$p_1$",
    "q1": "$q_1$",
}


def window_of(frame, y_name):
    rows = frame[frame.element == "window"]
    return float(rows.phi2.min()), float(rows.phi2.max()), float(rows[y_name].max())


def draw(ax, frame, y_name, window=None, small=False):
    """A portrait from its table: every element in its style, the singular points by type, the window (the
    table's own, or the one given). small: thinner lines and smaller markers, for a panel of a grid."""
    shrink = 0.75 if small else 1.0
    for element, (style, label) in ELEMENTS.items():
        rows = frame[frame.element == element]
        first = True
        for _, curve in rows.groupby("curve", sort=True):
            kw = dict(style)
            kw["lw"] = kw.get("lw", 1.0) * shrink
            if "ms" in kw:
                kw["ms"] = kw["ms"] * shrink
                curve = curve.iloc[::2] if small else curve  # dots: half of them suffice in a panel
            ax.plot(
                curve.phi2, curve[y_name], label=label if first and element != "trajectory" else None, **kw
            )
            first = False
            if element == "crossing":
                # each name where no line passes: f1 under T1's crest (F runs just above), f2 under its
                # point inside T2's arch, g1 inside the frame's right edge under T1, g2 right of where T2
                # leaves the axis
                ax.annotate(
                    CROSSING_NAMES[int(curve.curve.iloc[0])],
                    (curve.phi2.iloc[0], curve[y_name].iloc[0]),
                    xytext=CROSSING_OFFSETS[int(curve.curve.iloc[0])],
                    textcoords="offset points",
                    fontsize=7.5 if small else 8,  # its subscript at 7 pt or more
                )
    points = [
        {"phi2": row.phi2, "type": row.element} for row in frame[frame.element.isin(POINT_TYPES)].itertuples()
    ]
    mark_points(ax, points, size=4.5 if small else 6)
    lo, hi, y_max = window or window_of(frame, y_name)
    ax.set_xlim(lo, hi)
    ax.set_ylim(-y_max, y_max)


def legend_entries(elements, small=False):
    """Handles and labels for the elements drawn (in the order of ELEMENTS), the singular points last."""
    shrink = 0.75 if small else 1.0
    handles, labels = [], []
    for element, (style, label) in ELEMENTS.items():
        if element in elements:
            kw = dict(style)
            kw["lw"] = kw.get("lw", 1.0) * (0.6 / 0.55 if element == "trajectory" else shrink)
            handles.append(Line2D([], [], **kw))
            labels.append(label)
    for kind, (marker, label) in POINT_STYLE.items():
        if kind in elements:
            handles.append(
                Line2D(
                    [],
                    [],
                    ls="",
                    marker=marker,
                    color="k",
                    ms=6 * shrink,
                    mew=1.2,
                    mfc="white" if marker == "o" else None,
                )
            )
            labels.append(label)
    return handles, labels
