"""What every phase portrait of the study draws the same way: trajectories both ways in time, and the
singular points by type."""

from __future__ import annotations

import numpy as np

from ...solvers.ode import Problem, solve

RTOL = 1e-12
BLOW_UP_BOUND = 1e8


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
