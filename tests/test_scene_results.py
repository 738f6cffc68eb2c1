"""Results as data (scene_results.load): a scene written by the studies' own writer reads back as the
numbers, DataFrames with units and provenance it was written with, from its folder, from a results folder and
from a dist archive; a folder that does not match its provenance is refused."""

import numpy as np
import pandas as pd
import pytest

from classical_dynamics import io, scene_results
from classical_dynamics.report.dist import make_archive
from classical_dynamics.results import Results, new_figure


def _write_scene(results_dir, study="chains", scene="toy"):
    r = Results(study, scene, "A toy scene")
    r.number("gravest_period_s", 5.2254813, "s", note="4π/j₀₁")
    modes = pd.DataFrame({"k": [1, 2], "period": [5.2254813, 2.2764763]})
    r.table("modes", modes, "The modes.", headers={"k": "$k$", "period": "period (s)"})
    fig, ax = new_figure(3.0, 2.0)
    ax.plot([0.0, 1.0], [1.0, 0.5])
    r.figure("line", fig, "A line.")
    r.write(
        results_dir / study / scene,
        results_dir / study / "timings" / scene,
        {"study": study, "scene": scene, "commit": "abc"},
        {"wall_seconds": 0.1},
        {"scene.yaml": b"title: A toy scene\n"},
    )
    return results_dir / study / scene


def test_a_scene_reads_back_as_written(tmp_path):
    folder = _write_scene(tmp_path / "results")
    scene = scene_results.load(folder)
    assert (scene.study, scene.scene, scene.title) == ("chains", "toy", "A toy scene")
    assert scene.number("gravest_period_s") == 5.2254813 and scene.unit("gravest_period_s") == "s"
    modes = scene.table("modes")
    assert list(modes.k) == [1, 2] and np.allclose(modes.period, [5.2254813, 2.2764763])
    assert modes.attrs["units"] == {"k": "", "period": "s"} and modes.attrs["caption"] == "The modes."
    line = scene.figure_data("line")
    assert line is not None and len(line) >= 2  # the plotted data beside the figure
    assert scene.figure_svg("line").startswith(b"<?xml")
    assert scene.provenance["commit"] == "abc" and "summary.json" in scene.provenance["files"]
    with pytest.raises(KeyError, match="no number 'nope'"):
        scene.number("nope")


def test_a_results_folder_and_an_archive_read_alike(tmp_path):
    results = tmp_path / "results"
    _write_scene(results, scene="one")
    _write_scene(results, scene="two")
    folder = scene_results.load(results)
    assert sorted(folder) == [("chains", "one"), ("chains", "two")] and folder.scenes("chains") == [
        "one",
        "two",
    ]
    archive = tmp_path / "dist" / "classical-dynamics-0.0.0.tar.gz"
    archive.parent.mkdir()
    make_archive(results, archive, with_report=False)
    unpacked = scene_results.load(archive)
    assert sorted(unpacked) == sorted(folder)
    for key in folder:
        assert unpacked[key].numbers == folder[key].numbers
        pd.testing.assert_frame_equal(unpacked[key].table("modes"), folder[key].table("modes"))


def test_an_edited_result_is_refused(tmp_path):
    folder = _write_scene(tmp_path / "results")
    (folder / "modes.csv").write_text("k,period\n1,6.0\n")
    with pytest.raises(io.ResultError, match="modes.csv"):
        scene_results.load(folder)
