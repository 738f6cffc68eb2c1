"""The study's phase portraits redrawn as small multiples, grouped as Lee groups his figures.

Each portrait scene saves what it draws as a table (portrait.csv; the smallest axis also body_view.csv); this
step reads those tables and the scenes' summaries and draws one grid per group: shared axes where the windows
agree, each panel titled by its letter and its parameters, one legend per grid. Nothing is integrated here. A
scene whose results are missing is left out, and the panels that remain are lettered in order.

  python -m classical_dynamics.studies.self_excited.gallery STUDY_RESULTS OUT_DIR TIMINGS_DIR SCENE...
      [--quick]
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

from ...io import ResultError

GALLERY = "gallery"
ROOT = Path(__file__).resolve().parents[4]


@dataclass(frozen=True)
class Group:
    name: str  # the grid's figure and table: grid_<name>.svg, grid_<name>.csv
    axis: str  # largest (phi2 an angle, p1) or middle (phi2 a logarithm, q1)
    lead: str  # the caption's first sentences: what every panel shows
    panels: tuple  # (scene, what to notice in its panel), in Lee's order


EULER = (
    "The dots, integrations of Euler's equations in three dimensions mapped into the plane, lie on the "
    "plane's trajectories."
)
# Lee's middle-axis planes start integrations on the window's edge too: one that leaves at once is one dot
EDGE = " One that leaves the window at once is a lone dot where it starts, on the window's edge."

GROUPS = (
    Group(
        "largest_unperturbed",
        "largest",
        "Phase planes of Lee (2.10) for the torque along the largest axis $x$, unperturbed ($\\nu = 0$). "
        + EULER,
        (
            (
                "largest_unperturbed",
                "Grammel's problem (Lee's Figure 2.2; Grammel is Lee's reference 13, which this report "
                "cannot cite: the copy of the thesis consulted breaks off after its bibliography's first "
                "entry): "
                "closed orbits inside the homoclinic "
                "loops are periodic motions about permanent axes in the $yz$-plane; outside them "
                "$\\boldsymbol{\\omega}$ runs to the positive $x$-axis.",
            ),
            (
                "largest_unperturbed_negative",
                "The mirror image (Lee's Figure 2.4): the motions of the first kind "
                "run to the negative $x$-axis.",
            ),
            (
                "largest_unperturbed_critical",
                "At $m_1 = 1$ the saddle and the center of each pair coalesce into a "
                "degenerate point (Lee's Figure 2.5): no periodic motion remains.",
            ),
            (
                "largest_unperturbed_critical_negative",
                "The mirror image at $m_1 = -1$ (Lee's Figure 2.6): "
                "degenerate points, and the motions of the first kind run to the negative $x$-axis.",
            ),
            (
                "largest_unperturbed_strong",
                "For $m_1 > 1$ there are no singular points (Lee's Figure 2.7) and "
                "every motion runs to the $x$-axis. Since a small $\\delta$ makes $|m_1|$ large, the "
                "rotation about "
                "the $x$-axis is stable.",
            ),
            (
                "largest_unperturbed_strong_negative",
                "For $m_1 < -1$ (Lee's Figure 2.8) every motion runs to the negative $x$-axis.",
            ),
            (
                "force_free",
                "The force-free body (Lee's Figure 2.9), the plane of the pendulum: the saddles are the "
                "unstable rotations about the middle axis, the centers the stable rotations about the "
                "smallest.",
            ),
        ),
    ),
    Group(
        "largest_perturbed",
        "largest",
        "Phase planes of Lee (2.10) for the torque along the largest axis $x$ with the drag-like term "
        "$-\\nu p_1^2$. " + EULER,
        (
            (
                "largest_perturbed_cycles",
                "With $\\nu < \\nu^*$ (Lee's Figure 2.10) the limit cycles $F$ and $F_1$ "
                "appear. On $F$, $\\boldsymbol{\\omega}$ turns about the $x$-axis and returns after two "
                "turns of "
                "$\\varphi_2$ ($4\\pi$), twice the period of $p$.",
            ),
            (
                "largest_perturbed_critical",
                "At $\\nu = \\nu^*$ the limit cycles touch the saddles (Lee's Figure 2.15).",
            ),
            (
                "largest_perturbed_no_cycles",
                "Above $\\nu^*$ the limit cycles are gone (Lee's Figure 2.14); the "
                "closed orbits about the centers remain.",
            ),
            (
                "largest_perturbed_negative",
                "For $-1 < m_1 < 0$ with drag (Lee's Figure 2.16) there are no limit "
                "cycles: closed orbits about the centers, and otherwise $\\boldsymbol{\\omega}$ runs to the "
                "negative "
                "$x$-axis.",
            ),
            (
                "largest_perturbed_zero",
                "The same at $m_1 = 0$ (Lee's Figure 2.16): saddles at even, centers at "
                "odd multiples of $\\pi$.",
            ),
            (
                "largest_perturbed_unit",
                "At $m_1 = 1$ with drag (Lee's Figure 2.17) the points are degenerate as "
                "without drag, but $F$ and $F_1$ exist.",
            ),
            (
                "largest_perturbed_unit_negative",
                "At $m_1 = -1$ with drag (Lee's Figure 2.18): degenerate points, no limit cycles.",
            ),
            (
                "largest_perturbed_reversed",
                "For $m_1 < -1$ with drag (Lee's Figure 2.19), $\\boldsymbol{\\omega}$ "
                "runs to the negative $x$-axis from every start.",
            ),
            (
                "largest_perturbed_strong",
                "For $m_1 > 1$ with drag (Lee's Figure 2.20) there are no singular "
                "points, but $F$ and $F_1$ exist; above $F_1$, $\\boldsymbol{\\omega}$ tends to $F$.",
            ),
            (
                "largest_perturbed_cycles/zoom",
                "One period of the first plane (Lee's Figure 2.12): the separatrix "
                "$T_1$ out of the saddle $S_1$ crosses the vertical through the center at $f_1$, above the "
                "point "
                "$f_2$ where $T_2$ into $S_2$ crosses it; so $T_1$ goes on to the vertical through $S_2$ "
                "($g_1$) and "
                "$T_2$ comes from the $\\varphi_2$-axis ($g_2$). Below $\\nu^*$ $f_1$ lies above $f_2$, "
                "above "
                "$\\nu^*$ below it.",
            ),
        ),
    ),
    Group(
        "smallest",
        "largest",
        "The torque along the smallest axis $z$. Lee's title says “largest or smallest”: the same plane, "
        "Lee (2.10), serves, with $p$ and $r$, $a$ and $c$ exchanged. Euler's equations with the torque "
        "along $z$, integrated "
        "and read as $(r, q, p)$, lie on it (dots).",
        (
            ("smallest_unperturbed", "The plane."),
            (
                "smallest_unperturbed/body_view",
                "The same integrations in the body, seen along the torque axis "
                "$z$: the end of $\\boldsymbol{\\omega}$ runs on the ellipse $p^2/a + q^2/b = \\delta^2$ "
                "about $z$ "
                "(black), where for the torque along the largest axis it runs about $x$; the plane is the "
                "same.",
            ),
        ),
    ),
    Group(
        "middle_below_critical",
        "middle",
        "Phase planes of Lee (3.52) for the torque along the middle axis $y$, below the critical drag "
        "($\\nu < \\nu_\\mathrm{c}$): one center, every trajectory closed. " + EULER,
        (
            (
                "middle_unperturbed_negative",
                "Unperturbed, $m_1 < 0$ (Lee's Figure 3.3): the end of "
                "$\\boldsymbol{\\omega}$ moves on a hyperbolic cylinder; one center, at "
                "$\\operatorname{arcsinh}m_1$, "
                "and every motion is periodic.",
            ),
            ("middle_unperturbed_zero", "$m_1 = 0$, the force-free body on its cylinder: the center at 0."),
            ("middle_unperturbed", "$m_1 > 0$: the center moves to the right."),
            (
                "middle_perturbed",
                "With the drag-like term, $\\nu$ below $\\nu_\\mathrm{c}$: still one center and "
                "every motion periodic.",
            ),
            (
                "middle_near_critical",
                "Nearer $\\nu_\\mathrm{c}$, in a wider window: the orbits about the center "
                "swing far out before they close (the huge excursions).",
            ),
        ),
    ),
    Group(
        "middle_beyond_critical",
        "middle",
        "Phase planes of the cosh form, Lee (3.56), for the torque along the middle axis above the critical "
        "drag "
        "($\\nu > \\nu_\\mathrm{c}$). " + EULER,
        (
            (
                "middle_beyond_critical",
                "$m_2 > 1$ (Lee's Figure 3.9): a saddle and a center; periodic motions "
                "inside the saddle's loop, motions of the third kind outside it.",
            ),
            (
                "middle_beyond_critical_degenerate",
                "$m_2 = 1$ (Lee's Figure 3.10): saddle and center merged into "
                "one degenerate point; motions of the second kind into it, of the third kind elsewhere.",
            ),
            (
                "middle_beyond_critical_none",
                "$m_2 < 1$ (Lee's Figure 3.11): no singular point; every motion is "
                "of the third kind and leaves every bound in finite time.",
            ),
            (
                "middle_beyond_critical_resonant",
                "$\\nu = \\tfrac12$, where Lee's (3.19) divides by zero: the "
                "separatrix from the resonant closed form; the portrait is that of $m_2 > 1$.",
            ),
        ),
    ),
    Group(
        "middle_planes",
        "middle",
        "Phase planes for the torque along the middle axis in the planes of the separating polhodes, Lee "
        "(3.58) "
        "and (3.59), with drag, and at the critical drag $|\\mu| = \\mu_\\mathrm{c}$, where every cylinder "
        "obeys "
        "the form of plane I. " + EULER,
        (
            (
                "middle_plane_one",
                "Plane I (Lee's Figure 3.12): a center; periodic motions inside Lee's "
                "separatrix $F$ ($c_1 = 0$ in Lee (3.60)); outside it $\\boldsymbol{\\omega}$ runs to the "
                "$-y$ axis.",
            ),
            (
                "middle_critical",
                "At $|\\mu| = \\mu_\\mathrm{c}$ on a cylinder off the planes: the portrait of plane I.",
            ),
            (
                "middle_plane_two",
                "Plane II below $\\nu_\\mathrm{c}$ (Lee's Figure 3.14): a center, every orbit closed.",
            ),
        ),
    ),
    Group(
        "middle_plane_two_saddles",
        "middle",
        "Phase planes of Lee (3.59) for the torque along the middle axis in plane II above the critical "
        "drag, "
        "where $k_1$ changes sign and the singular point becomes a saddle whose separatrices divide the "
        "plane into "
        "four regions (Lee's Figure 3.16). " + EULER,
        (
            ("middle_plane_two_saddle", "$m_3 > 1$."),
            ("middle_plane_two_saddle_unit", "$m_3 = 1$."),
            ("middle_plane_two_saddle_weak", "$0 < m_3 < 1$."),
            (
                "middle_plane_two_resonant",
                "$\\nu = \\tfrac12$, where Lee's (3.63) divides by zero: the "
                "separatrix from the resonant closed form; one saddle, as at $\\nu = 0.45$.",
            ),
        ),
    ),
    Group(
        "middle_planes_unperturbed",
        "middle",
        "Phase planes for the torque along the middle axis in the planes of the separating polhodes without "
        "drag "
        "(Lee's Figures 3.4 and 3.5), Lee (3.43) and (3.44). " + EULER,
        (
            (
                "middle_plane_one_unperturbed",
                "Plane I, $m_3 > 0$ (Lee's Figure 3.4 (a)–(c)): a center, every orbit closed.",
            ),
            (
                "middle_plane_one_force_free",
                "Plane I without torque (Lee's Figure 3.4 (d)): no singular point; "
                "the trajectories level off, the separatrix motion of the force-free body.",
            ),
            (
                "middle_plane_one_negative",
                "Plane I, $m_3 < 0$ (Lee's Figure 3.4 (e)): no singular point; "
                "$\\boldsymbol{\\omega}$ runs to the $-y$ axis, $|q_1|$ growing like $|m_3|\\tau$.",
            ),
            (
                "middle_plane_two_unperturbed",
                "Plane II, $m_3 < 0$ (Lee's Figure 3.5): a center, every orbit closed.",
            ),
            (
                "middle_plane_two_runaway",
                "Plane II, $m_3 > 0$ (Lee's Figure 3.5 (e)): no singular point; "
                "$\\boldsymbol{\\omega}$ runs to the $+y$ axis.",
            ),
        ),
    ),
    Group(
        "middle_planes_unperturbed_more",
        "middle",
        "More subcases of Lee's Figures 3.4 and 3.5 without drag, Lee (3.43) and (3.44): the positive "
        "torques of "
        "Figure 3.4 (a)–(c) and the negative ones of Figure 3.5 (a)–(c) beside those of the previous figure, "
        "and "
        "plane II without torque. " + EULER,
        (
            (
                "middle_plane_one_unperturbed_unit",
                "Plane I, $m_3 = 1$ (Lee's Figure 3.4 (a)–(c)): the center at "
                "$\\ln m_3 = 0$, every orbit closed.",
            ),
            ("middle_plane_one_unperturbed_strong", "Plane I, $m_3 = 2$: the center at $\\ln 2$."),
            (
                "middle_plane_two_force_free",
                "Plane II without torque (Lee's Figure 3.5 (d)): no singular point; "
                "$q_1$ levels off at $+\\sqrt{2E}$ and $\\boldsymbol{\\omega}$ tends to the $y$ axis with "
                "finite "
                "modulus.",
            ),
            (
                "middle_plane_two_unperturbed_unit",
                "Plane II, $m_3 = -1$ (Lee's Figure 3.5 (a)–(c)): the center at "
                "$-\\ln(-m_3) = 0$, every orbit closed.",
            ),
            ("middle_plane_two_unperturbed_strong", "Plane II, $m_3 = -2$: the center at $-\\ln 2$."),
        ),
    ),
    Group(
        "middle_escape",
        "middle",
        "Phase planes for the torque along the middle axis in the planes of the separating polhodes with "
        "drag, "
        "where nothing turns the motion back or the drag alone stops it. " + EULER,
        (
            (
                "middle_plane_one_no_center",
                "Plane I, $m_3 < 0$ (Lee's Figure 3.13): no singular point; "
                "$\\boldsymbol{\\omega}$ leaves every bound in finite time from every start.",
            ),
            (
                "middle_plane_one_no_torque",
                "Plane I, $m_3 = 0$, the quadratic torque alone (Lee's Figure 3.13, "
                "“non-positive”): the same.",
            ),
            (
                "middle_plane_two_no_saddle",
                "Plane II above $\\nu_\\mathrm{c}$, $m_3 < 0$ (Lee's Figure 3.17): the same.",
            ),
            (
                "middle_plane_two_positive",
                "Plane II below $\\nu_\\mathrm{c}$, $m_3 > 0$ (Lee's Figure 3.15): "
                "$q_1$ tends to $\\sqrt{m_3/\\nu}$, the rotation about $+y$.",
            ),
        ),
    ),
    Group(
        "middle_rare",
        "middle",
        "Lee's rare case, Lee (3.65): the torque along the middle axis in plane II at $\\nu = "
        "\\nu_\\mathrm{c}$ "
        "(Lee's Figure 3.18; here $\\tau = t$, $\\varphi_2 = 2\\sqrt{ac}\\,\\varphi$ and "
        "$m = 2\\sqrt{ac}\\,m_0$). " + EULER,
        (
            (
                "middle_rare",
                "$m > 0$: above the line $q_1 = -\\sqrt{m/\\nu}$ the motion tends to "
                "$q_1 = \\sqrt{m/\\nu}$ (black: the lines $c_1 = 0$ of Lee (3.66)); below it "
                "$\\boldsymbol{\\omega}$ leaves every bound.",
            ),
            (
                "middle_rare_no_torque",
                "Without torque: the line of rest points $q_1 = 0$; above it "
                "$\\boldsymbol{\\omega} \\to 0$ along $+y$, below it $\\boldsymbol{\\omega}$ leaves every "
                "bound.",
            ),
            (
                "middle_rare_negative",
                "$m < 0$: from every start $\\boldsymbol{\\omega}$ leaves every bound, "
                "towards an axis of plane II perpendicular to $y$.",
            ),
        ),
    ),
)
LETTERS = "abcdefghijklmnopqrstuvwxyz"


def portrait_scenes():
    """Every scene a grid draws (its portrait, or another table of it), once each."""
    return sorted({scene.split("/")[0] for group in GROUPS for scene, _ in group.panels})


def parameter_symbol(numbers):
    """m1 of Lee's plane, named as Lee names it for the middle axis' forms: m2 (cosh), m3 (planes), m
    (rare)."""
    form = numbers.get("form", {}).get("value", "sinh")
    return {"cosh": "$m_2$", "exp": "$m_3$", "exp-": "$m_3$", "rare": "$m$"}.get(form, "$m_1$")


def panel_title(letter, numbers):
    from .portrait import param_text

    return (
        f"({letter}) {parameter_symbol(numbers)} = {param_text(numbers['m1']['value'])}, "
        f"$\\nu$ = {param_text(numbers['nu']['value'])}"
    )


@dataclass
class Panel:
    letter: str
    scene: str
    kind: str  # "portrait", "body_view" or "zoom" (one period of a plane, its own window)
    title: str
    text: str
    frame: object  # the scene's table
    numbers: dict


def panels(group, study_dir: Path, scenes):
    """The group's panels whose scene is among `scenes` and has its table, lettered in order."""
    import pandas as pd

    from ... import io

    out = []
    for entry, text in group.panels:
        scene, _, table = entry.partition("/")
        folder = study_dir / scene
        path = folder / f"{table or 'portrait'}.csv"
        if scene not in scenes or not path.exists() or not (folder / "summary.json").exists():
            continue
        io.check_result_folder(folder)  # a portrait is redrawn only from a whole scene folder
        numbers = io.read_json(folder / "summary.json")["numbers"]
        letter = LETTERS[len(out)]
        of = next(
            (f"({p.letter})" for p in out if p.scene == scene and p.kind == "portrait"),
            panel_title("", numbers),
        )
        title = {"body_view": f"({letter}) seen along $z$", "zoom": f"({letter}) one period of {of}"}.get(
            table, panel_title(letter, numbers)
        )
        out.append(Panel(letter, scene, table or "portrait", title, text, pd.read_csv(path), numbers))
    return out


def _same(spans, slack=0.25):
    """Spans close enough to share an axis: each within `slack` of the widest (the union is then drawn)."""
    return all(span >= (1 - slack) * max(spans) for span in spans)


def _y_axis(group, found):
    """The plane's velocity (p1 or q1) and its label, the portraits' windows and whether they share y."""
    from . import portrait

    angle = group.axis == "largest"
    y_name, y_label = ("p1", "$p_1$") if angle else ("q1", "$q_1$")
    windows = [portrait.window_of(p.frame, y_name) for p in found if p.kind == "portrait"]
    share_y = _same([y for _, _, y in windows]) and not any(p.kind == "body_view" for p in found)
    return y_name, y_label, windows, share_y


MOST_TICKS = 7  # a common tick step is kept only where it leaves a panel this many labels or fewer


def _common_ticks(axes, which="y"):
    """Panels of one quantity whose windows differ (one needs more room): one tick step in every panel, so
    the ticks of all read alike (2 apart, not 2 in one and 2.5 in the next): the smallest window's own step,
    or the next of 1, 2, 5 times a power of ten that leaves every panel at most MOST_TICKS labels."""
    import math

    from matplotlib.ticker import MultipleLocator

    def limits(ax):
        return sorted(ax.get_ylim() if which == "y" else ax.get_xlim())

    smallest = min(axes, key=lambda ax: limits(ax)[1] - limits(ax)[0])
    low, high = limits(smallest)
    ticks = [
        t for t in (smallest.get_yticks() if which == "y" else smallest.get_xticks()) if low <= t <= high
    ]
    if len(ticks) < 2:
        return
    widest = max(limits(ax)[1] - limits(ax)[0] for ax in axes)
    power = 10.0 ** math.floor(math.log10(ticks[1] - ticks[0]))
    nice = [m * power * 10**k for k in range(3) for m in (1, 2, 5)]
    step = next(s for s in nice if s >= (ticks[1] - ticks[0]) * (1 - 1e-9) and widest / s < MOST_TICKS)
    for ax in axes:
        (ax.yaxis if which == "y" else ax.xaxis).set_major_locator(MultipleLocator(step))


def _taller(group, found):
    """The caption's note of the panels whose window is taller than the rest (their orbits need the room),
    or "" when the panels share their y axis."""
    from .portrait import param_text

    _, y_label, windows, share_y = _y_axis(group, found)
    if share_y:
        return ""
    planes = [p for p in found if p.kind == "portrait"]
    low = min(y for _, _, y in windows)
    taller = [(p, y) for p, (_, _, y) in zip(planes, windows) if y > low * (1 + 1e-9)]
    if not taller:
        return ""

    def listed(words):
        return ", ".join(words[:-1]) + " and " + words[-1] if len(words) > 1 else words[0]

    letters = listed([f"({p.letter})" for p, _ in taller])
    values = listed([param_text(round(y, 1)) for _, y in taller])
    windows_reach = "The windows of {} reach" if len(taller) > 1 else "The window of {} reaches"
    return (
        f" {windows_reach.format(letters)} $|{y_label.strip('$')}|$ = {values}, that of the others "
        f"{param_text(round(low, 1))}, to hold their orbits; the ticks are spaced alike."
    )


def layout(n):
    """Columns and rows of a grid of n panels: at most three columns (a panel keeps its aspect and its
    text)."""
    columns = min(n, 3)
    return columns, -(-n // columns)


ROW_HEIGHT_IN = 1.3  # a panel's plot, title and tick labels at three columns across the text width
# a grid of one or two rows can afford taller panels (its orbits read apart), still fitting below a paragraph
ROW_HEIGHTS_IN = {1: 1.7, 2: 1.45, 3: 1.25}
LEGEND_HEIGHT_IN = 0.4


def grid_figure(group, found):
    """The grid of one group: panels in Lee's order, shared axes where the windows agree, one legend (in a
    spare slot when there is one, otherwise below)."""
    from ...figure_style import FULL_WIDTH_IN, GRID_MAX_HEIGHT_IN, legend_below
    from ...results import subplots  # with the report's figure style
    from . import portrait
    from .largest_axis import draw_seen_along_z

    angle = group.axis == "largest"
    y_name, y_label, windows, share_y = _y_axis(group, found)
    body = any(p.kind == "body_view" for p in found)
    share_x = _same([hi - lo for lo, hi, _ in windows]) and not body
    columns, rows = layout(len(found))
    spare = columns * rows > len(found)
    height = min(
        GRID_MAX_HEIGHT_IN,
        rows * ROW_HEIGHTS_IN.get(rows, ROW_HEIGHT_IN)
        + (0.0 if spare else LEGEND_HEIGHT_IN)
        + (0.5 if body else 0),
    )
    zoom = any(p.kind == "zoom" for p in found)  # a zoom keeps its own window: share by hand, not by subplots
    fig, axes = subplots(
        rows,
        columns,
        figsize=(FULL_WIDTH_IN, height),
        layout="constrained",
        squeeze=False,
        sharex=share_x and not zoom,
        sharey=share_y and not zoom,
        width_ratios=[2.6, 1.0] if body else None,
    )
    if zoom:
        shared = [ax for ax, p in zip(axes.flat, found) if p.kind == "portrait"]
        for ax in shared[1:]:
            if share_x:
                ax.sharex(shared[0])
            if share_y:
                ax.sharey(shared[0])
    if zoom and columns * rows - len(found) >= 2 and columns >= 3:
        axes = _widened_last(fig, axes, len(found))  # a zoom takes the slot beside it: its labels stand apart
    elements = set()
    for k, (ax, panel) in enumerate(zip(axes.flat, found)):
        ax.grid(True, which="both", alpha=0.25, linewidth=0.6)
        bottom, left = k + columns >= len(found) - zoom, k % columns == 0  # a zoom (last) has its own axes
        if panel.kind == "body_view":
            draw_seen_along_z(ax, panel.frame, small=True)
            elements.add("euler")
        elif panel.kind == "zoom":
            portrait.draw(ax, panel.frame, y_name, small=True)
            portrait.axes_labels(ax, y_label, angle, portrait.window_of(panel.frame, y_name)[:2])
            ax.set_ylim(-0.15 * portrait.window_of(panel.frame, y_name)[2], None)  # the upper half: T1, T2
            elements |= set(panel.frame.element.unique())
        else:
            lo, hi, y_max = portrait.window_of(panel.frame, y_name)
            window = (
                min(w[0] for w in windows) if share_x else lo,
                max(w[1] for w in windows) if share_x else hi,
                max(w[2] for w in windows) if share_y else y_max,
            )
            portrait.draw(ax, panel.frame, y_name, window=window, small=True)
            portrait.axes_labels(
                ax, y_label, angle, window[:2], x=bottom or not share_x, y=left or not share_y, most_ticks=5
            )  # a third of the width: ticks every 2π once the window is wider than 4π, so labels stand apart
            ax.tick_params(labelbottom=bottom or not share_x, labelleft=left or not share_y)
            elements |= set(panel.frame.element.unique())
        ax.set_title(panel.title, loc="left")
    portraits = [ax for ax, p in zip(axes.flat, found) if p.kind == "portrait"]
    if not share_y and not body:
        _common_ticks(portraits, "y")
    if not share_x and not body and not angle:  # an angle keeps its ticks in multiples of pi
        _common_ticks(portraits, "x")
    for ax in list(axes.flat)[len(found) :]:
        ax.axis("off")
    handles, labels = portrait.legend_entries(elements, small=True)
    if spare:
        axes.flat[-1].legend(handles, labels, loc="center", ncol=1, borderaxespad=0.0)
    else:
        legend_below(fig, handles, labels, ncol=3)
    return fig


def _widened_last(fig, axes, count):
    """The grid's axes with the last panel (slot count - 1) spread over its own slot and the next one, which
    is removed; the axes after it shift back by one, so the spare slots stay last."""
    import numpy as np

    columns = axes.shape[1]
    row, column = divmod(count - 1, columns)
    spec = axes[row, column].get_subplotspec()
    axes[row, column].remove()
    axes[row, column + 1].remove()
    wide = fig.add_subplot(spec.get_gridspec()[row, column : column + 2])
    flat = list(axes.flat)
    flat[count - 1 : count + 1] = [wide]
    return np.array(flat, dtype=object).reshape(1, -1)


def grid_table(group, found):
    """The data of every panel: its letter, scene and parameters, then the scene's own rows."""
    import pandas as pd

    parts = []
    for panel in found:
        frame = panel.frame.copy()
        frame.insert(0, "panel", panel.letter)
        frame.insert(1, "scene", panel.scene)
        frame.insert(2, "m1", panel.numbers["m1"]["value"])
        frame.insert(3, "nu", panel.numbers["nu"]["value"])
        parts.append(frame)
    return pd.concat(parts, ignore_index=True)


TABLE_HEADERS = {
    "panel": "panel",
    "scene": "scene",
    "m1": "$m_1$ ($m_2$, $m_3$ or $m$ as the panel's title names it)",
    "nu": "$\\nu$",
    "element": "what is drawn",
    "curve": "curve",
    "phi2": "$\\varphi_2$",
    "p1": "$p_1$",
    "q1": "$q_1$",
    "p": "$p$ (rad per time unit)",
    "q": "$q$ (rad per time unit)",
}


def caption(group, found):
    lead = group.lead.replace(EULER, EULER + EDGE) if group.axis == "middle" else group.lead
    return lead + _taller(group, found) + " " + " ".join(f"({p.letter}) {p.text}" for p in found)


# Lee's closed-form figures (no integration): the potential of the unperturbed plane (2.20), Figures 2.1 and
# 2.3, and the coefficients k1, k2 of the middle-axis reduction against |mu|, Figures 3.6 and 3.7, for the
# study's body.
CLOSED_FORM_BODY = (3.0, 2.2, 1.2)  # the moments of every scene of the study
CLOSED_FORM_M1 = (0.5, -0.5)  # the planes of largest_unperturbed and largest_unperturbed_negative
# the middle-axis scenes' cylinder, and alpha2 of the other sign
CLOSED_FORM_ALPHA = ((0.8, 0.3), (0.8, -0.3))
K_COLOURS = {"k1": "#0072B2", "k2": "#D55E00"}


def closed_form_data():
    """The curves of the closed-form figure as one table (panel, curve, x, y), and the crossings of k1 and k2
    found by root finding, against Lee's mu_c = b sqrt(ac)/(a + c)."""
    import numpy as np
    import pandas as pd
    from scipy.optimize import brentq

    from ...models import self_excited as se

    rows, crossings = [], {}
    phi = np.linspace(-3 * np.pi, 3 * np.pi, 601)
    for letter, m1 in zip("ab", CLOSED_FORM_M1):
        rows.append(pd.DataFrame({"panel": letter, "curve": "V", "x": phi, "y": -m1 * phi + np.cos(phi)}))
        for pt in se.singular_points(m1, 0.0, phi[0], phi[-1]):
            rows.append(
                pd.DataFrame(
                    {
                        "panel": [letter],
                        "curve": [pt["type"]],
                        "x": [pt["phi2"]],
                        "y": [-m1 * pt["phi2"] + np.cos(pt["phi2"])],
                    }
                )
            )
    body = se.Body.from_moments(list(CLOSED_FORM_BODY))
    mu_c = body.b * np.sqrt(body.a * body.c) / (body.a + body.c)
    size = np.linspace(0.0, 2.0 * mu_c, 201)
    for letter, (alpha1, alpha2) in zip("cd", CLOSED_FORM_ALPHA):

        def k(name, s):
            return getattr(se.MiddleAxis(body, 0.0, -s, alpha1, alpha2), name)

        for name in ("k1", "k2"):
            rows.append(
                pd.DataFrame({"panel": letter, "curve": name, "x": size, "y": [k(name, s) for s in size]})
            )
        cross = brentq(lambda s: k("k1", s) - k("k2", s), 0.0, 2.0 * mu_c, xtol=1e-16, rtol=1e-15)
        crossings[letter] = cross
        rows.append(
            pd.DataFrame({"panel": [letter], "curve": ["crossing"], "x": [cross], "y": [k("k1", cross)]})
        )
    return pd.concat(rows, ignore_index=True), crossings, float(mu_c), body


def closed_form_figure(frame, mu_c, body):
    import numpy as np
    from matplotlib.lines import Line2D

    from ...figure_style import FULL_WIDTH_IN, legend_below
    from ...results import subplots
    from . import portrait

    fig, axes = subplots(1, 4, figsize=(FULL_WIDTH_IN, 1.95), layout="constrained")
    for ax in axes:
        ax.grid(True, which="both", alpha=0.25, linewidth=0.6)
    for ax, letter, m1 in zip(axes[:2], "ab", CLOSED_FORM_M1):
        part = frame[frame.panel == letter]
        curve = part[part.curve == "V"]
        ax.plot(curve.x, curve.y, color="k", lw=1.0)
        for x, y, kind in zip(part.x, part.y, part.curve):
            if kind != "V":
                marker = portrait.POINT_STYLE[kind][0]
                ax.plot(
                    x, y, marker, color="k", ms=4, mew=0.8, mfc="white" if marker == "o" else None, zorder=5
                )
        portrait.pi_ticks(ax.xaxis, -9 * np.pi, 9 * np.pi)  # a narrow panel: ticks every 2π
        ax.set_xlabel("$\\varphi_2$ (rad)")
        ax.set_title(f"({letter}) $m_1$ = {portrait.param_text(m1)}", loc="left")
    axes[0].set_ylabel("$V(\\varphi_2)$")
    axes[1].sharey(axes[0])
    axes[1].tick_params(labelleft=False)
    for ax, letter, (alpha1, alpha2) in zip(axes[2:], "cd", CLOSED_FORM_ALPHA):
        part = frame[frame.panel == letter]
        for name in ("k1", "k2"):
            curve = part[part.curve == name]
            ax.plot(curve.x, curve.y, color=K_COLOURS[name], lw=1.2)
        ax.axvline(mu_c, color="0.4", lw=0.8, ls=":")
        ax.axhline(0.0, color="0.6", lw=0.6)
        cross = part[part.curve == "crossing"]
        ax.plot(cross.x, cross.y, "o", color="k", ms=3.5, zorder=5)
        ax.set_xlabel("$|\\mu|$")
        ax.set_title(f"({letter}) $\\alpha_2$ = {portrait.param_text(alpha2)}", loc="left")
    axes[2].set_ylabel("$k_1$, $k_2$")
    axes[3].sharey(axes[2])
    axes[3].tick_params(labelleft=False)
    for ax in axes[
        2:
    ]:  # ticks every 0.2 short of the axis' end: the last stays clear of the next panel's first
        ax.set_xticks(np.arange(0.0, 0.85 * frame[frame.panel == "c"].x.max(), 0.2))
    handles = [
        Line2D([], [], color="k", lw=1.0),
        Line2D([], [], ls="", marker="x", color="k", ms=4),
        Line2D([], [], ls="", marker="o", color="k", ms=4, mfc="white"),
        Line2D([], [], color=K_COLOURS["k1"], lw=1.2),
        Line2D([], [], color=K_COLOURS["k2"], lw=1.2),
        Line2D([], [], ls="", marker="o", color="k", ms=3.5),
        Line2D([], [], color="0.4", lw=0.8, ls=":"),
    ]
    labels = [
        "$V = -m_1\\varphi_2 + \\cos\\varphi_2$",
        "saddle (maximum)",
        "center (minimum)",
        "$k_1$",
        "$k_2$",
        "$k_1 = k_2$, found",
        "$\\mu_\\mathrm{c} = b\\sqrt{ac}/(a + c)$",
    ]
    legend_below(fig, handles, labels, ncol=7)
    return fig


def _record_closed_forms(results, data):
    """Lee's Figures 2.1, 2.3, 3.6 and 3.7 as one figure with its table and the crossings as numbers (data:
    closed_form_data())."""
    from ...formatting import shortest

    frame, crossings, mu_c, body = data
    moments = ", ".join(shortest(m) for m in CLOSED_FORM_BODY)
    (a1, a2), (_, b2) = CLOSED_FORM_ALPHA
    caption = (
        "Lee's closed-form figures. (a), (b) The potential $V(\\varphi_2) = -m_1\\varphi_2 + "
        "\\cos\\varphi_2$ "
        "of the unperturbed plane, Lee (2.20), for $m_1 = 0.5$ and $-0.5$ (Lee's Figures 2.1 and 2.3): its "
        "maxima are the saddles and its minima the centers, $2\\pi$ apart on a falling or rising line. "
        "(c), (d) The coefficients $k_1$ and $k_2$ of the reduction for the torque along the middle axis, "
        f"against the drag $|\\mu|$, for the moments {moments} and $\\alpha_1 = {shortest(a1)}$, "
        f"$\\alpha_2 = {shortest(a2)}$ or ${shortest(b2)}$ (Lee's Figures 3.6 and 3.7): "
        "straight lines, Lee (3.50) and (3.51), that cross below the $|\\mu|$-axis (dot: the crossing "
        "found by root finding) at the critical drag $\\mu_\\mathrm{c}$ (dotted). Below $\\mu_\\mathrm{c}$, "
        "$|k_1| > |k_2|$ and the sinh form (3.52) holds; above it the cosh form (3.56)."
    )
    results.figure("closed_forms", closed_form_figure(frame, mu_c, body), caption)
    results.table(
        "closed_forms",
        frame,
        "The curves and points of closed_forms.svg, panel by panel.",
        headers={
            "panel": "panel",
            "curve": "curve or point",
            "x": "$\\varphi_2$ (rad) or $|\\mu|$",
            "y": "$V$ or $k_1$, $k_2$",
        },
    )
    results.number(
        "mu_c_closed_form", mu_c, "1", note=f"Lee's critical drag b√(ac)/(a + c) for the moments {moments}"
    )
    results.number(
        "mu_c_crossing", crossings["c"], "1", note=f"k1 = k2 by root finding, α = ({a1:g}, {a2:g})"
    )
    results.number("mu_c_crossing_opposite", crossings["d"], "1", note=f"the same for α = ({a1:g}, {b2:g})")


def build(study_dir: Path, scenes, quick=False):
    """The gallery's Results: one grid figure and its table per group that has a panel."""
    from ...results import Results

    results = Results("self_excited", GALLERY, "The phase portraits of the study's scenes, redrawn as grids")
    for group in GROUPS:
        found = panels(group, Path(study_dir), set(scenes))
        if not found:
            continue
        name = f"grid_{group.name}"
        results.figure(name, grid_figure(group, found), caption(group, found))
        results.table(
            name, grid_table(group, found), f"The data of {name}.svg, panel by panel.", headers=TABLE_HEADERS
        )
        results.number(f"panels_{group.name}", len(found), "1", note="panels in the grid")
        for panel in found:
            if panel.kind == "portrait":
                results.number(
                    f"panel_{panel.scene}",
                    panel.letter,
                    "",
                    note=f"the panel of grid_{group.name} that draws the scene's portrait",
                )
                results.number(
                    f"grid_{panel.scene}", group.name, "", note="the grid that draws the scene's portrait"
                )
    _record_closed_forms(results, closed_form_data())
    _record_body_views(results, body_view_data())
    _record_symbolic_checks(results, symbolic_checks())
    return results


# Lee's Figures 3.1 and 3.2: the end of omega seen along y, on the hyperbolas (3.34), (3.35) and on the lines
# (3.38), (3.39) of the planes of the separating polhodes; the parameters are those of middle_unperturbed and
# the two unperturbed plane scenes, the conjugate cylinder that of middle_unperturbed with alpha1 and alpha2
# exchanged.
BODY_VIEW_CASES = (
    ("a", "3.34", 0.5, (0.8, 0.3)),
    ("a", "3.35", None, (0.3, 0.8)),
    ("b", "3.38", 0.5, (0.6, 0.6)),
    ("b", "3.39", -0.5, (0.6, -0.6)),
)
BODY_VIEW_COLOURS = ("#0072B2", "#D55E00")


def body_view_data():
    """Euler's equations from three starts on each cylinder, (p, r) at 121 times each; the closed-form
    curves."""
    import numpy as np
    import pandas as pd

    from ...models import self_excited as se
    from ...solvers.ode import Problem, solve

    body = se.Body.from_moments(list(CLOSED_FORM_BODY))
    a, c = body.a, body.c
    rows, first = [], None
    for panel, eq, m1, (al1, al2) in BODY_VIEW_CASES:
        M = (
            se.MiddleAxis(body, first.m, 0.0, al1, al2)
            if m1 is None
            else se.MiddleAxis.with_plane_parameters(body, m1, 0.0, al1, al2)
        )
        first = M if eq == "3.34" else first
        for q0 in (0.4, 0.8, 1.2):
            w0 = np.array([al1 * np.sqrt(a), q0, al2 * np.sqrt(c)])
            t = np.linspace(0.0, 8.0, 121)
            sol = solve(
                Problem(se.euler_middle, w0, (0.0, t[-1]), M.euler_parameters()),
                "dop853",
                rtol=1e-12,
                atol=1e-14,
                t_eval=t,
            )
            rows.append(
                pd.DataFrame(
                    {"panel": panel, "curve": f"euler ({eq})", "p": sol.y_eval[:, 0], "r": sol.y_eval[:, 2]}
                )
            )
    u = np.linspace(-2.2, 2.2, 201)
    h = np.sqrt(0.8**2 - 0.3**2)
    for sign in (1, -1):
        rows.append(
            pd.DataFrame(
                {
                    "panel": "a",
                    "curve": "hyperbola (3.34)",
                    "p": sign * h * np.sqrt(a) * np.cosh(u),
                    "r": h * np.sqrt(c) * np.sinh(u),
                }
            )
        )
        rows.append(
            pd.DataFrame(
                {
                    "panel": "a",
                    "curve": "hyperbola (3.35)",
                    "p": h * np.sqrt(a) * np.sinh(u),
                    "r": sign * h * np.sqrt(c) * np.cosh(u),
                }
            )
        )
        for panel in "ab":
            p_line = np.linspace(-3.0, 3.0, 2)
            rows.append(
                pd.DataFrame(
                    {
                        "panel": panel,
                        "curve": f"line {'(3.38)' if sign > 0 else '(3.39)'}",
                        "p": p_line,
                        "r": sign * np.sqrt(c / a) * p_line,
                    }
                )
            )
    return pd.concat(rows, ignore_index=True)


def body_view_figure(frame):
    from matplotlib.lines import Line2D

    from ...figure_style import FULL_WIDTH_IN, legend_below
    from ...results import subplots

    fig, axes = subplots(1, 2, figsize=(FULL_WIDTH_IN, 2.25), layout="constrained", sharey=True)
    for ax, panel in zip(axes, "ab"):
        part = frame[frame.panel == panel]
        ax.grid(True, alpha=0.25, linewidth=0.6)
        for curve, rows in part.groupby("curve", sort=False):
            if curve.startswith("line"):
                ax.plot(
                    rows.p,
                    rows.r,
                    color="k" if panel == "b" else "0.6",
                    lw=1.0 if panel == "b" else 0.7,
                    ls="-" if panel == "b" else ":",
                )
            elif curve.startswith("hyperbola"):
                ax.plot(rows.p, rows.r, color="k", lw=1.0)
        euler = part[part.curve.str.startswith("euler")]
        for k, (curve, rows) in enumerate(euler.groupby("curve", sort=True)):
            ax.plot(rows.p, rows.r, ".", color=BODY_VIEW_COLOURS[k], ms=2.2)
        ax.set_xlim(-2.0, 2.0)
        ax.set_ylim(-2.0, 2.0)
        ax.set_aspect("equal")
        ax.set_xlabel("$p$ (rad per time unit)")
    axes[0].set_ylabel("$r$ (rad per time unit)")
    axes[0].set_title("(a) hyperbolas (3.34), (3.35)", loc="left")
    axes[1].set_title("(b) planes I and II, (3.38), (3.39)", loc="left")
    handles = [
        Line2D([], [], color="k", lw=1.0),
        Line2D([], [], color="0.6", lw=0.7, ls=":"),
        Line2D([], [], ls="", marker=".", color=BODY_VIEW_COLOURS[0], ms=5),
        Line2D([], [], ls="", marker=".", color=BODY_VIEW_COLOURS[1], ms=5),
    ]
    labels = [
        "closed form",
        "asymptotes",
        "Euler: (3.34) in (a), plane I in (b)",
        "Euler: (3.35) in (a), plane II in (b)",
    ]
    legend_below(fig, handles, labels, ncol=4)
    return fig


def _record_body_views(results, frame):
    """Lee's Figures 3.1 and 3.2 as one figure with its table (frame: body_view_data())."""
    results.figure(
        "body_views",
        body_view_figure(frame),
        "The end of $\\boldsymbol{\\omega}$ for the torque along the "
        "middle axis seen along $y$ (Lee's Figures 3.1 and 3.2), moments 3, 2.2, 1.2. (a) Unperturbed with "
        "$m_1 = 0.5$: Euler's equations from three spins $q_0$ = 0.4, 0.8, 1.2 on the cylinder "
        "$\\alpha = (0.8, 0.3)$ run on the hyperbola $p^2/a - r^2/c = 0.55$, Lee (3.34), and with "
        "$\\alpha_1$, $\\alpha_2$ exchanged on its conjugate $p^2/a - r^2/c = -0.55$, (3.35) (black: the "
        "closed forms). (b) For $|\\alpha_1| = |\\alpha_2|$ the hyperbolas degenerate into the lines "
        "$r = \\pm\\sqrt{c/a}\\,p$, planes I and II, Lee (3.38), (3.39), in which the separating polhodes "
        "lie: Euler's equations started in them (plane I, $m_3 = 0.5$; plane II, $m_3 = -0.5$) stay there.",
    )
    results.table(
        "body_views",
        frame,
        "The curves and points of body_views.svg, panel by panel.",
        headers={
            "panel": "panel",
            "curve": "curve",
            "p": "$p$ (rad per time unit)",
            "r": "$r$ (rad per time unit)",
        },
    )


class SymbolicChecks(NamedTuple):
    """Lee §3's k1, k2, mu_c and nu_c, and §4.1's series coefficients, by sympy (see symbolic.py)."""

    k_constants: int  # terms of (3.3) in Euler's q equation that do not cancel against (3.8)
    mu_c_factors: int  # factorisations of k1 -+ k2 sympy does not confirm
    mu_c_exceptions: int  # random bodies, cylinders and drags breaking Lee's rule
    mu_c_samples: int
    mu_c_below: int  # of them below mu_c
    nu_c_identity: int  # a - b + c - abc simplified (0: the identity holds)
    nu_c_exact: object  # b/(2(a + c)) for the moments 3, 2.2, 1.2, exact (sympy)
    nu_c_largest: float  # over random bodies
    nu_c_bodies: int
    lindstedt_differ: list  # Lee's printed coefficients that differ from the expansion
    lindstedt_total: int


def symbolic_checks() -> SymbolicChecks:
    import numpy as np

    from . import symbolic

    rng = np.random.default_rng(1964)
    k_constants = symbolic.k_constants()
    factors, exceptions, samples, below = symbolic.mu_c_regimes(rng)
    identity, exact, largest, bodies = symbolic.nu_c(rng)
    differ, total, _ = symbolic.lindstedt()
    return SymbolicChecks(
        k_constants, factors, exceptions, samples, below, identity, exact, largest, bodies, differ, total
    )


def _record_symbolic_checks(results, values: SymbolicChecks):
    results.number(
        "k_constants_mismatch",
        values.k_constants,
        "1",
        note="terms of (3.3) put into Euler's q "
        "equation that do not cancel against Lee's (3.8) with his m0, k1, k2 (sympy)",
    )
    results.number(
        "mu_c_factor_mismatch",
        values.mu_c_factors,
        "1",
        note="of k1 − k2 = ½(α1 − α2)²(a + c)(|μ| − μc) and "
        "k1 + k2 = −½(α1 + α2)²(a + c)(|μ| + μc), those sympy does not confirm",
    )
    results.number(
        "mu_c_regime_exceptions",
        values.mu_c_exceptions,
        "1",
        note=f"of {values.mu_c_samples} random bodies, cylinders and "
        f"drags |μ| in (0, 2μc) ({values.mu_c_below} below μc), those breaking Lee's rule: below μc "
        "|k1| > |k2| and k1 < 0, above it |k2| > |k1| and k2 < 0",
    )
    results.number(
        "nu_c_identity_mismatch",
        values.nu_c_identity,
        "1",
        note="a − b + c − abc simplified by sympy for symbolic "
        "A, B, C (0: the identity holds, so b < a + c and νc < ½)",
    )
    results.number(
        "nu_c_exact",
        float(values.nu_c_exact),
        "1",
        note=f"b/(2(a + c)) in exact arithmetic for the moments 3, 2.2, 1.2: {values.nu_c_exact}",
    )
    results.number(
        "nu_c_sweep_max",
        values.nu_c_largest,
        "1",
        note=f"largest νc = b/(2(a + c)) over {values.nu_c_bodies} random bodies A > B > C, A < B + C",
    )
    differ = values.lindstedt_differ
    results.number(
        "lindstedt_mismatch",
        len(differ),
        "1",
        note=f"of Lee's {values.lindstedt_total} printed coefficients of (4.6)–"
        "(4.8) (h1, θ2's three, h2, c0 … c3, h3), those that differ from a sympy Lindstedt–Poincaré "
        "expansion of (4.1) to third order" + (f": {', '.join(differ)}" if differ else ""),
    )


def main(argv=None) -> int:
    import argparse
    import hashlib
    import time
    from datetime import datetime, timezone

    from ... import code_graph, io, provenance

    parser = argparse.ArgumentParser(prog="classical_dynamics.studies.self_excited.gallery")
    parser.add_argument("study_results")
    parser.add_argument("out_dir")
    parser.add_argument("timings_dir")
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    now = lambda: datetime.now(timezone.utc).isoformat(timespec="seconds")
    started, wall0, cpu0 = now(), time.perf_counter(), time.process_time()
    study_dir = Path(args.study_results)
    scenes = sorted(Path(s).name for s in args.scenes)
    results = build(study_dir, scenes, args.quick)
    wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    inputs = {
        s: provenance.sha256_file(study_dir / s / "summary.json")
        for s in scenes
        if (study_dir / s / "summary.json").exists()
    }
    record = {
        "study": "self_excited",
        "scene": GALLERY,
        "scene_file": str(Path(__file__).resolve().relative_to(ROOT)),
        "scene_sha256": hashlib.sha256(io.dumps_json(inputs).encode()).hexdigest(),
        "input_scenes": sorted(inputs),
        "input_sha256": inputs,
        "effects_simulated": [],
        "effects_registry": {},
        "quick": bool(args.quick),
        **provenance.git_state_of(code_graph.job_entries("studies.self_excited.gallery")),  # its rule's code
        "packages": provenance.package_versions(),
        "machine": provenance.machine(),
        "started": started,
        "finished": now(),
        "wall_seconds": round(wall, 3),
        "cpu_seconds": round(cpu, 3),
    }
    timing = {
        "study": "self_excited",
        "scene": GALLERY,
        "wall_seconds": wall,
        "cpu_seconds": cpu,
        "started": started,
        "cpu_model": record["machine"]["cpu_model"],
        "cores": record["machine"]["cores"],
    }
    results.write(Path(args.out_dir), Path(args.timings_dir), record, timing)
    return 0


if __name__ == "__main__":
    try:
        raise SystemExit(main())
    except ResultError as error:  # a scene folder cut short or edited, named in one line
        raise SystemExit(f"{error}")
