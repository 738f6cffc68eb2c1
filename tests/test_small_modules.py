"""Direct tests of small modules the pipeline uses: provenance, the effect registry, figure data. Each
against what the test itself knows: files it wrote, git and /proc read here, the arrays it plotted."""

import hashlib
import subprocess
from importlib import metadata

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest

from classical_dynamics import provenance
from classical_dynamics.figure_data import figure_data
from classical_dynamics.scenes.effects import EffectRegistry

from .conftest import ROOT


def test_provenance_against_git_metadata_and_hashlib(tmp_path):
    path = tmp_path / "scene.yaml"
    path.write_bytes(b"title: x\n")
    assert provenance.sha256_file(path) == hashlib.sha256(b"title: x\n").hexdigest()
    versions = provenance.package_versions()
    assert versions["numpy"] == metadata.version("numpy") and versions["classical-dynamics"] == "0.1.0"
    assert set(provenance.KEY_PACKAGES) < set(versions)
    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout
    state = provenance.git_state()
    assert state["commit"] == head.strip() and isinstance(state["dirty"], bool)
    assert provenance.git(tmp_path, "rev-parse", "HEAD") is None  # not a checkout
    assert provenance.git(tmp_path, "no-such-command") is None
    m = provenance.machine()
    assert m["cores"] >= 1 and m["python"].count(".") == 2
    cpuinfo = open("/proc/cpuinfo").read()
    assert m["cpu_model"] in cpuinfo
    stamp = provenance.software_stamp()
    assert (
        stamp.startswith(f"{m['cpu_model']}, {m['cores']} cores;") and f"numpy {versions['numpy']}" in stamp
    )


def test_package_versions_names_a_missing_package(monkeypatch):
    monkeypatch.setattr(provenance, "KEY_PACKAGES", ("numpy", "no-such-package-here"))
    provenance.package_versions.cache_clear()
    try:
        assert provenance.package_versions()["no-such-package-here"] == "not installed"
    finally:
        provenance.package_versions.cache_clear()


def test_the_registry_builds_the_listed_effects_only_in_order():
    registry = EffectRegistry("demo")
    built = []

    @registry.register("b", "torque", "B")
    def build_b(params, context):
        built.append("b")
        return ("b", params, context)

    @registry.register("a", "force", "A")
    def build_a(params, context):
        built.append("a")
        return ("a", params, context)

    @registry.register("never", "force", "N")
    def build_never(params, context):
        raise AssertionError("an effect not listed was built")

    assert registry.names() == ["a", "b", "never"]
    assert registry["a"].kind == "force" and registry["b"].summary == "B"
    components = registry.assemble({"b": {"k": 1}, "a": None}, "ctx")
    assert list(components) == ["b", "a"] and built == ["b", "a"]
    assert components == {"b": ("b", {"k": 1}, "ctx"), "a": ("a", {}, "ctx")}  # None is no parameters
    with pytest.raises(ValueError, match="'a' registered twice in demo"):
        registry.register("a", "force", "again")(build_a)
    with pytest.raises(KeyError):
        registry.assemble({"unknown": {}}, None)


def test_figure_data_is_what_was_drawn():
    x = np.linspace(0.0, 1.0, 5)
    fig, (left, right) = plt.subplots(1, 2)
    left.plot(x, x**2, label="square")
    left.plot([], [])  # nothing drawn: no rows, and no place in the numbering
    left.plot(x, -x)  # no label: named by kind and place
    left.set_xlabel("t")
    left.set_title("one")
    right.scatter([1.0, 2.0], [3.0, 4.0], label="dots")
    right.plot([0.5], [0.5], "o")
    X, Y = np.meshgrid(np.linspace(-1, 1, 21), np.linspace(-1, 1, 21))
    right.contour(X, Y, X**2 + Y**2, levels=[0.25])
    fig.colorbar(right.collections[0], ax=right)
    data, axes = figure_data(fig)
    plt.close(fig)
    assert axes[0] == {"panel": 1, "title": "one", "x": "t", "y": ""} and len(axes) == 2  # no colorbar
    square = data[data.series == "square"]
    np.testing.assert_array_equal(square.x, x)
    np.testing.assert_array_equal(square.y, x**2)
    np.testing.assert_array_equal(data[data.series == "line 2"].y, -x)
    right_rows = data[data.panel == 2]
    dots = right_rows[right_rows.series == "dots"]
    assert list(zip(dots.x, dots.y)) == [(1.0, 3.0), (2.0, 4.0)]
    assert list(right_rows[right_rows.series.str.startswith("points")].x) == [0.5]
    ring = right_rows[right_rows.series.str.contains("level 0.25")]
    assert len(ring) > 10
    # the circle r = 1/2, to marching squares on a 0.1 grid (r^2 interpolated linearly along each edge)
    np.testing.assert_allclose(np.hypot(ring.x, ring.y), 0.5, atol=5e-3)
    assert set(data.panel) == {1, 2}


def test_figure_data_of_an_empty_figure():
    fig = plt.figure()
    fig.add_subplot()
    data, axes = figure_data(fig)
    plt.close(fig)
    assert list(data.columns) == ["panel", "series", "x", "y"] and data.empty and len(axes) == 1


def test_figure_data_of_line_collections_path_by_path():
    # a collection of several paths (not a contour set): one series per path, its points as drawn; an empty
    # scatter adds no rows and takes no place in the numbering
    from matplotlib.collections import LineCollection

    first, second = np.array([[0.0, 1.0], [1.0, 2.0], [2.0, 0.5]]), np.array([[3.0, 3.0], [4.0, 1.0]])
    fig, ax = plt.subplots()
    ax.scatter([], [])
    ax.add_collection(LineCollection([first, second], label="pair"))
    ax.add_collection(LineCollection([second]))
    data, _ = figure_data(fig)
    plt.close(fig)
    assert list(dict.fromkeys(data.series)) == ["pair, path 1", "pair, path 2", "curve 2"]
    for series, xy in (("pair, path 1", first), ("pair, path 2", second), ("curve 2", second)):
        rows = data[data.series == series]
        np.testing.assert_array_equal(np.column_stack([rows.x, rows.y]), xy)


def test_provenance_outside_git_and_without_proc(monkeypatch, tmp_path):
    # a checkout-less install says so ("unknown", dirty not known); a machine without /proc/cpuinfo falls back
    # to what platform reports
    monkeypatch.setattr(provenance, "git", lambda root, *args: None)
    provenance.git_state.cache_clear()
    try:
        assert provenance.git_state() == {"commit": "unknown", "dirty": None}
    finally:
        provenance.git_state.cache_clear()
    import platform
    from pathlib import Path

    def unreadable(self, *args, **kwargs):
        raise PermissionError(f"{self}: denied")

    monkeypatch.setattr(Path, "read_text", unreadable)
    monkeypatch.setattr(platform, "processor", lambda: "a test processor")
    provenance.cpu_model.cache_clear()
    try:
        assert provenance.cpu_model() == "a test processor"
        monkeypatch.setattr(platform, "processor", lambda: "")
        provenance.cpu_model.cache_clear()
        assert provenance.cpu_model() == "unknown"
    finally:
        monkeypatch.undo()
        provenance.cpu_model.cache_clear()
    assert provenance.cpu_model() in open("/proc/cpuinfo").read()


def test_a_result_is_marked_dirty_only_where_its_own_inputs_changed(tmp_path):
    """A scene job's provenance says dirty where its scene or the code it runs differs from the commit, not
    where the tree changed elsewhere (a template, another study): git itself, in a committed copy, decides."""
    import sys

    from .conftest import copy_repository, run_env

    repo = copy_repository(tmp_path / "repo")
    quiet = {"cwd": repo, "check": True, "capture_output": True}
    subprocess.run(["git", "init", "-q"], **quiet)
    subprocess.run(["git", "add", "-A"], **quiet)
    subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "x"], **quiet)
    scene = "workflow/scenes/chains/loaded_string.yaml"
    # one process asks on each line it reads (the graph parsed once; git asked afresh each time)
    probe = (
        "import sys\nfrom types import SimpleNamespace\n"
        "from classical_dynamics import provenance, scene_job\n"
        "from classical_dynamics import code_graph\n"
        "gallery = code_graph.job_entries('studies.self_excited.gallery')\n"
        "for _ in sys.stdin:\n"
        "    provenance.git_state.cache_clear()\n"
        f"    args = SimpleNamespace(study='chains', scene={scene!r})\n"
        "    flags = scene_job._git_state(args)['dirty'], provenance.git_state_of(gallery)['dirty']\n"
        "    print(*flags, flush=True)\n"
    )
    asker = subprocess.Popen(
        [sys.executable, "-c", probe],
        cwd=repo,
        env=run_env(repo),
        text=True,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
    )

    def dirty(of="scene"):
        """The scene job's flag, or the self-excited gallery's (a job that reads results, not a scene)."""
        asker.stdin.write("\n")
        asker.stdin.flush()
        scene_flag, gallery_flag = asker.stdout.readline().split()
        return (scene_flag if of == "scene" else gallery_flag) == "True"

    assert not dirty()
    for elsewhere in ("report/templates/report.css", "src/classical_dynamics/studies/precession/secular.py"):
        with open(repo / elsewhere, "a") as f:
            f.write("\n")
    assert not dirty()  # the tree is dirty, this result's inputs are not
    assert not dirty("gallery")  # nor the gallery's: another study, a template
    with open(repo / "src/classical_dynamics/studies/self_excited/gallery.py", "a") as f:
        f.write("\n# changed\n")
    assert dirty("gallery") and not dirty()
    with open(repo / "src/classical_dynamics/studies/chains/discrete.py", "a") as f:
        f.write("\n# changed\n")
    assert dirty()
    subprocess.run(
        ["git", "checkout", "-q", "--", "src/classical_dynamics/studies/chains/discrete.py"], **quiet
    )
    assert not dirty()
    with open(repo / scene, "a") as f:
        f.write("\n")
    assert dirty()
    asker.stdin.close()
    assert asker.wait(timeout=60) == 0
