"""Results that change, and scenes that change back, are noticed by the dry run, with or without Snakemake's
own records (.snakemake/): a scene folder with a file missing or edited, and a scene file whose SHA-256 is not
the one its results were built from, whatever the file times say (workflow/rules/common.smk,
io.stale_reason)."""

import json
import os
import shutil
import time

import pytest

from .conftest import snakemake
from .test_code_dependencies import stale_scenes

pytestmark = [pytest.mark.slow, pytest.mark.pipeline]
SCENE = ("chains", "loaded_string")


def dry_run(repo):
    return stale_scenes(snakemake(repo, "-n", "--config", "quick=1").stdout)[0]


def without_records(repo):
    """As if the results had been copied to another machine: Snakemake's records gone, times kept."""
    shutil.rmtree(repo / ".snakemake")
    return repo


@pytest.mark.parametrize("records", ["kept", "removed"])
def test_a_deleted_figure_is_noticed(scratch, records):
    repo = scratch if records == "kept" else without_records(scratch)
    assert dry_run(repo) == set()
    folder = repo / "results/chains/loaded_string"
    listed = json.loads((folder / "provenance.json").read_text())["files"]
    (folder / next(name for name in sorted(listed) if name != "summary.json")).unlink()
    assert dry_run(repo) == {SCENE}


@pytest.mark.parametrize("records", ["kept", "removed"])
def test_an_edited_number_is_noticed(scratch, records):
    repo = scratch if records == "kept" else without_records(scratch)
    summary = repo / "results/chains/loaded_string/summary.json"
    stat = summary.stat()
    edited = summary.read_text().replace("2.98522", "2.98523", 1)
    assert edited != summary.read_text()
    summary.write_text(edited)
    os.utime(summary, ns=(stat.st_atime_ns, stat.st_mtime_ns))  # the file's times say nothing changed
    assert dry_run(repo) == {SCENE}


def test_a_scene_restored_with_its_old_time_is_rebuilt_then_left_alone(scratch, tmp_path):
    scene = scratch / "workflow/scenes/chains/loaded_string.yaml"
    kept = tmp_path / "loaded_string.yaml"
    shutil.copy2(scene, kept)  # as `cp -p` keeps it
    time.sleep(0.01)
    scene.write_text(scene.read_text().replace("newton: 1.0", "newton: 2.0"))
    snakemake(scratch, "-c", "2", "results/chains/loaded_string", "--config", "quick=1")
    shutil.copy2(kept, scene)  # restored with its old time: older than the results of the edit
    assert scene.stat().st_mtime < (scratch / "results/chains/loaded_string/summary.json").stat().st_mtime
    assert dry_run(scratch) == {SCENE}
    snakemake(scratch, "-c", "2", "results/chains/loaded_string", "--config", "quick=1")
    assert dry_run(scratch) == set()  # and once rebuilt, it stays built
