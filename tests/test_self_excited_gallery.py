"""The self-excited study's gallery: the portrait scenes redrawn as grids of small multiples, from the tables
the scenes save. A few real scenes are run (quick) into a scratch results folder; the others of their groups
are absent."""

import dataclasses
import json
import re

import pandas as pd
import pytest

from classical_dynamics.cli import main as cli
from classical_dynamics.figure_style import GRID_MAX_HEIGHT_IN, MIN_FONT_PT, TEXT_WIDTH_IN
from classical_dynamics.studies.self_excited import gallery

from .conftest import ROOT

SCENES = [
    "force_free",
    "largest_unperturbed_strong",
    "largest_perturbed_strong",
    "smallest_unperturbed",
    "middle_rare_no_torque",
    "middle_plane_two_saddle_weak",
]


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    study = tmp_path_factory.mktemp("results") / "self_excited"
    for scene in SCENES:
        assert (
            cli(
                [
                    "run",
                    "self_excited",
                    str(ROOT / "workflow/scenes/self_excited" / f"{scene}.yaml"),
                    str(study / scene),
                    str(study / "timings" / scene),
                    "--quick",
                ]
            )
            == 0
        )
    # one scene named on the command line has no results: it must be left out, not fail the step
    assert (
        gallery.main(
            [
                str(study),
                str(study / "gallery"),
                str(study / "timings" / "gallery"),
                *[str(study / s) for s in SCENES],
                str(study / "largest_unperturbed"),
            ]
        )
        == 0
    )
    return study


def summary(folder):
    return json.loads((folder / "summary.json").read_text())


def svg_texts(path):
    """The texts of a figure as matplotlib writes them in an SVG with paths for glyphs: a comment per text."""
    return re.findall(r'<g id="text_\d+">\s*<!-- (.*?) -->', path.read_text())


def test_every_portrait_scene_of_the_study_is_in_a_group_once():
    scene_files = {p.stem for p in (ROOT / "workflow/scenes/self_excited").glob("*.yaml")}
    listed = [entry for group in gallery.GROUPS for entry, _ in group.panels if "/" not in entry]
    assert len(listed) == len(set(listed)) and set(listed) <= scene_files
    planes = {
        p.stem
        for p in (ROOT / "workflow/scenes/self_excited").glob("*.yaml")
        if "viscous" not in p.read_text()
    }
    assert set(gallery.portrait_scenes()) == planes


def test_each_scene_present_is_a_panel_titled_with_its_parameters(built):
    got = summary(built / "gallery")
    numbers = got["numbers"]
    for scene in SCENES:
        letter, grid = numbers[f"panel_{scene}"]["value"], numbers[f"grid_{scene}"]["value"]
        plane = summary(built / scene)["numbers"]
        texts = svg_texts(built / "gallery" / f"grid_{grid}.svg")
        title = next(t for t in texts if t.startswith(f"({letter}) "))
        shown = re.fullmatch(r"\([a-z]\) \$m(_\d)?\$ = (\S+), \$\\nu\$ = (\S+)", title)
        assert shown, title
        for text, key in ((shown.group(2), "m1"), (shown.group(3), "nu")):  # as given, or to four figures
            assert float(text.replace("\u2212", "-")) == pytest.approx(
                plane[key]["value"], rel=5e-4, abs=1e-12
            )
    assert "panel_largest_unperturbed" not in numbers  # no results, no panel
    assert not any(k.startswith("panel_viscous") for k in numbers)
    # letters run on without gaps in each grid, in the group's order
    for group in gallery.GROUPS:
        present = [e.split("/")[0] for e, _ in group.panels if e.split("/")[0] in SCENES]
        assert (f"grid_{group.name}" in got["figures"]) == bool(present)
        letters = [numbers[f"panel_{s}"]["value"] for s in dict.fromkeys(present)]
        assert letters == sorted(letters) and letters[0:1] in ([], ["a"])


def test_the_grid_table_holds_each_panels_data(built):
    numbers = summary(built / "gallery")["numbers"]
    for scene in SCENES:
        grid = pd.read_csv(built / "gallery" / f"grid_{numbers[f'grid_{scene}']['value']}.csv")
        mine = grid[grid.scene == scene]
        own = pd.read_csv(built / scene / "portrait.csv")
        y = "p1" if "p1" in own else "q1"
        rows = mine[mine.element.isin(own.element.unique())].dropna(subset=[y])
        assert len(rows) == len(own)
        pd.testing.assert_frame_equal(rows[own.columns].reset_index(drop=True), own, check_dtype=False)
        assert set(mine.m1) == {summary(built / scene)["numbers"]["m1"]["value"]}
        for kind in ("saddle", "center", "degenerate"):  # the singular points, typed
            assert (own.element == kind).sum() == summary(built / scene)["numbers"][f"n_{kind}s"]["value"]
    body = pd.read_csv(built / "gallery" / "grid_smallest.csv")
    assert set(body[body.panel == "b"].element) == {"ellipse", "euler"}


def test_grids_fit_the_page_and_their_text_is_legible(built):
    for path in sorted((built / "gallery").glob("grid_*.svg")):
        svg = path.read_text()
        width, height = (float(v) for v in re.search(r'width="([\d.]+)pt" height="([\d.]+)pt"', svg).groups())
        assert width <= TEXT_WIDTH_IN * 72 and height <= GRID_MAX_HEIGHT_IN * 72
        for group in re.findall(r'<g id="text_\d+">(.*?)</g>\s*</g>', svg, re.S):
            sizes = [100 * float(s) for s in re.findall(r"scale\(([\d.]+) -[\d.]+\)", group)]
            assert not sizes or max(sizes) >= MIN_FONT_PT - 0.05
        assert "Date" not in svg and (built / "gallery" / path.with_suffix(".csv").name).exists()


def test_provenance_names_the_input_scenes(built):
    record = json.loads((built / "gallery" / "provenance.json").read_text())
    assert record["input_scenes"] == sorted(SCENES) and record["scene"] == "gallery"
    for key in ("commit", "scene_sha256", "wall_seconds", "cpu_seconds", "finished", "effects_simulated"):
        assert key in record


def _panel(letter, lo, hi, y_max):
    """A panel of the middle axis whose table holds only its window and one trajectory."""
    frame = pd.DataFrame(
        {
            "element": ["trajectory", "trajectory", "window", "window"],
            "curve": [0, 0, 1, 1],
            "phi2": [lo, hi, lo, hi],
            "q1": [-1.0, 1.0, -y_max, y_max],
        }
    )
    return gallery.Panel(letter, f"scene_{letter}", "portrait", f"({letter})", "", frame, {})


def test_a_taller_window_keeps_the_others_tick_step_and_the_caption_says_so():
    import matplotlib.pyplot as plt

    group = next(g for g in gallery.GROUPS if g.name == "middle_below_critical")
    found = [_panel("a", -4.0, 4.0, 3.0), _panel("b", -4.0, 4.0, 3.0), _panel("c", -6.0, 6.0, 6.0)]
    fig = gallery.grid_figure(group, found)
    fig.canvas.draw()
    portraits = [ax for ax in fig.axes if ax.get_title(loc="left")]
    for which in ("y", "x"):
        steps = set()
        for ax in portraits:
            low, high = sorted(ax.get_ylim() if which == "y" else ax.get_xlim())
            ticks = [t for t in (ax.get_yticks() if which == "y" else ax.get_xticks()) if low <= t <= high]
            steps.add(round(ticks[1] - ticks[0], 9))
        assert steps == {2.0}, (which, steps)  # without the common step the taller panel would tick by 5
    plt.close(fig)
    text = gallery.caption(group, found)
    assert "The window of (c) reaches $|q_1|$ = 6, that of the others 3" in text
    assert "reaches" not in gallery.caption(group, found[:2])  # windows alike: shared, nothing to say


def test_only_the_middle_axis_captions_explain_the_lone_dots_on_the_window_edge():
    """Lee's middle-axis planes start Euler integrations on the window's edge too (a lone dot where one leaves
    at once): their captions say so after the sentence on the dots; the other axes' do not."""
    middle = [_panel("a", -4.0, 4.0, 3.0)]
    other = [dataclasses.replace(middle[0], frame=middle[0].frame.rename(columns={"q1": "p1"}))]
    for group in gallery.GROUPS:
        text = gallery.caption(group, middle if group.axis == "middle" else other)
        if gallery.EULER in group.lead:
            assert (gallery.EULER + gallery.EDGE in text) == (group.axis == "middle"), group.name
    assert any(g.axis == "middle" and gallery.EULER in g.lead for g in gallery.GROUPS)


def test_a_zoom_panel_keeps_its_own_window_and_shows_its_upper_half():
    """A zoom (one period of a plane) is drawn in its own window, not the portraits' shared one: its p1 axis
    runs from -0.15 of its own window's height (the separatrices T1, T2 above the axis)."""
    import matplotlib.pyplot as plt

    group = next(g for g in gallery.GROUPS if any(entry.endswith("/zoom") for entry, _ in g.panels))
    assert group.axis == "largest"

    def panel(letter, kind, lo, hi, y_max):
        frame = pd.DataFrame(
            {
                "element": ["trajectory", "trajectory", "window", "window"],
                "curve": [0, 0, 1, 1],
                "phi2": [lo, hi, lo, hi],
                "p1": [-0.5 * y_max, 0.5 * y_max, -y_max, y_max],
            }
        )
        return gallery.Panel(letter, f"scene_{letter}", kind, f"({letter})", "", frame, {})

    found = [panel("a", "portrait", -4.0, 4.0, 3.0), panel("b", "portrait", -4.0, 4.0, 3.0)]
    found.append(panel("c", "zoom", -1.0, 2.0, 0.8))
    fig = gallery.grid_figure(group, found)
    fig.canvas.draw()
    zoom = next(ax for ax in fig.axes if ax.get_title(loc="left").startswith("(c)"))
    assert zoom.get_ylim()[0] == pytest.approx(-0.15 * 0.8)
    plt.close(fig)


def test_closed_form_panels_are_titled_with_the_parameters_their_curves_are_drawn_for():
    """Lee's closed-form figures: each panel's title names its parameter, and its curves are Lee's formulas,
    written out here, for that parameter: V = -m1 phi2 + cos phi2 (2.20) in (a), (b); k1, k2 (3.50), (3.51)
    against |mu| (mu = -|mu|, a drag) in (c), (d), for alpha1 and the moments the caption states, crossing at
    mu_c = b sqrt(ac)/(a + c)."""
    import matplotlib.pyplot as plt
    import numpy as np

    from classical_dynamics.results import Results

    results = Results("self_excited", "t", "t")
    gallery._record_closed_forms(results, gallery.closed_form_data())
    fig, caption = results.figures["closed_forms"]
    A, B, C = (float(v) for v in re.search(r"for the moments ([\d.]+), ([\d.]+), ([\d.]+)", caption).groups())
    alpha1 = float(re.search(r"\$\\alpha_1 = ([\d.]+)\$", caption).group(1))
    a, b, c = (B - C) / A, (A - C) / B, (A - B) / C
    titles = [ax.get_title(loc="left") for ax in fig.axes[:4]]
    shown = [re.fullmatch(r"\(([a-d])\) \$(m_1|\\alpha_2)\$ = (\S+)", t) for t in titles]
    assert all(shown), titles
    assert [s.group(1) for s in shown] == list("abcd")
    value = [float(s.group(3).replace("\u2212", "-")) for s in shown]
    for ax, m1 in zip(fig.axes[:2], value[:2]):
        x, y = ax.lines[0].get_data()
        np.testing.assert_allclose(y, -m1 * x + np.cos(x), atol=1e-12)
    mu_c = b * np.sqrt(a * c) / (a + c)
    for ax, alpha2 in zip(fig.axes[2:4], value[2:]):
        (size, k1), (_, k2) = (line.get_data() for line in ax.lines[:2])
        mu, s = -np.asarray(size), alpha1**2 + alpha2**2
        np.testing.assert_allclose(
            k1, mu * (a + c) * alpha1 * alpha2 - 0.5 * b * np.sqrt(a * c) * s, atol=1e-12
        )
        np.testing.assert_allclose(
            k2, 0.5 * mu * (a + c) * s - b * np.sqrt(a * c) * alpha1 * alpha2, atol=1e-12
        )
        assert ax.lines[2].get_xdata()[0] == pytest.approx(mu_c, rel=1e-14)  # the dotted line
    assert value[2] == -value[3] != 0  # Lee's Figures 3.6 and 3.7: alpha2 of either sign
    plt.close(fig)
