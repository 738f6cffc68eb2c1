"""A job's code is derived from the package's import graph (code_graph.py), never listed by hand: a code
edit reruns exactly the jobs whose code it changes. Checked three ways: facts of the graph that a reader can
verify in the sources; the modules a real scene job imports at run time all lie inside its digest (so no edit
to code a result ran goes unnoticed); and real dry runs in a copy of the built repository after one edit."""

import functools
import json
import re
import subprocess
import sys

import pytest

from classical_dynamics import code_graph
from classical_dynamics.studies import STUDIES

from .conftest import ROOT, copy_repository, snakemake

PACKAGE = "classical_dynamics"


@functools.cache
def graph():
    """The package's import graph, parsed on first use, not at collection (each test worker collects)."""
    return code_graph.import_graph()


def scene_job(study):
    """What a scene job of `study` runs (its rule's digest and its result's dirty flag start from these)."""
    return code_graph.reached(graph(), code_graph.scene_job_entries(study))


def job(entry):
    """What `python3 -m classical_dynamics.jobserver classical_dynamics.<entry>` runs."""
    return code_graph.reached(graph(), [f"{PACKAGE}.jobserver", f"{PACKAGE}.{entry}"])


def test_the_graph_follows_imports_in_functions_lazy_modules_and_parent_packages():
    chains = scene_job("chains")
    # figure_data and lazy: the two modules the hand-written list of shared code had left out
    assert all(f"{PACKAGE}.figure_data" in scene_job(study) for study in STUDIES)
    assert f"{PACKAGE}.lazy" in chains
    # loaded only through lazy_module(f"{__package__}.symbolic") in chains/discrete.py
    assert f"{PACKAGE}.studies.chains.symbolic" in chains
    assert f"{PACKAGE}.studies.chains.symbolic" not in graph()[f"{PACKAGE}.studies.chains"]
    # a submodule brings its packages: importing models.wobble runs models/__init__.py
    assert f"{PACKAGE}.models" in code_graph.reached(graph(), [f"{PACKAGE}.models.wobble"])


def test_a_scene_job_reaches_no_report_verify_or_other_study_code():
    for study in STUDIES:
        reached = scene_job(study)
        assert not {m for m in reached if m.startswith(f"{PACKAGE}.report")}, study
        assert f"{PACKAGE}.verify" not in reached and f"{PACKAGE}.cli" not in reached
        others = {f"{PACKAGE}.studies.{other}" for other in STUDIES if other != study}
        assert not others & reached, (study, others & reached)
    assert f"{PACKAGE}.report.pdf" not in job("report.build")  # the PDF is its own job


def test_the_digest_changes_with_exactly_the_modules_reached(tmp_path):
    """The digest of a copy of the package changes when a module it reaches changes, and only then. The graph
    is kept in a parse cache, as the workflow keeps it (code_graph.cache_parses_in): an edited module must be
    parsed afresh, not taken from the cache; the others are not parsed eight times (0.5 s each)."""
    copy = copy_repository(tmp_path / "repo") / "src" / PACKAGE
    modules = code_graph.modules(copy)
    entries = code_graph.scene_job_entries("chandler")
    cache = tmp_path / "parses.json"

    def digest():
        graph, meanings = code_graph.parse(copy, cache)
        return code_graph.digest_of(graph, modules, entries, copy, meanings)

    reached = code_graph.reached(code_graph.import_graph(copy, cache), entries)
    assert code_graph.parse(copy, cache) == code_graph.parse(copy)  # the cache as the parse
    before = digest()
    for name in (
        f"{PACKAGE}.lazy",
        f"{PACKAGE}.figure_data",
        f"{PACKAGE}.report.pdf",
        f"{PACKAGE}.studies.chandler.model",
        f"{PACKAGE}.studies.chains.symbolic",
    ):
        path = modules[name]
        source = path.read_bytes()
        path.write_bytes(source + b"\nEDITED = 1\n")
        assert (digest() != before) == (name in reached), name
        path.write_bytes(source)
    assert digest() == before


def test_a_comment_or_docstring_edit_changes_no_digest_and_a_code_edit_does(tmp_path):
    """What a job depends on is what its code does: a comment, a docstring, blank lines, reformatting leave
    the digest (and so every result) standing; a changed constant or a new line of code change it."""
    copy = copy_repository(tmp_path / "repo") / "src" / PACKAGE
    modules = code_graph.modules(copy)
    entries = code_graph.scene_job_entries("chains")
    path = modules[f"{PACKAGE}.formatting"]  # reached by every study
    source = path.read_text(encoding="utf-8")

    cache = (
        tmp_path / "parses.json"
    )  # the others are parsed once, not seven times (as the workflow keeps them)

    def digest_with(text):
        path.write_text(text, encoding="utf-8")
        graph, meanings = code_graph.parse(copy, cache)
        return code_graph.digest_of(graph, modules, entries, copy, meanings)

    before = digest_with(source)
    assert source.startswith('"""') and "def format_number(" in source
    for same in (
        source + "\n# a comment\n\n",
        source.replace('"""', '"""Reworded. ', 1),  # the module's docstring
        source.replace("def format_number(", "def format_number(  ", 1),  # spacing
    ):
        assert digest_with(same) == before
    for different in (
        source.replace('MINUS = "\\u2212"', 'MINUS = "-"', 1),
        source.replace("FIXED_RANGE = (-3, 5)", "FIXED_RANGE = (-3, 6)", 1),
        source + "\nEDITED = 1\n",
    ):
        assert different != source
        assert digest_with(different) != before


LIGHT_SCENE = {  # one light scene per study
    "precession": "lamb_1920",
    "chandler": "rigid_lamb",
    "chains": "loaded_string",
    "self_excited": "force_free",
    "solvers": "hnw_rigid_body",
}
RUN_AND_LIST_MODULES = """
import json, sys
from classical_dynamics import scene_job
status = scene_job.main(sys.argv[1:])
mine = (m for m in sys.modules if m == "classical_dynamics" or m.startswith("classical_dynamics."))
print(json.dumps(sorted(mine)))
sys.exit(status)
"""


@pytest.mark.slow
@pytest.mark.pipeline  # a real scene job of each study
@pytest.mark.parametrize("study", sorted(STUDIES))
def test_every_module_a_real_scene_job_imports_is_in_its_digest(study, tmp_path):
    """Run one scene as its job does and list the package's modules it imported: each must be in what its
    digest covers, or an edit to it would leave the result standing."""
    scene = ROOT / "workflow/scenes" / study / f"{LIGHT_SCENE[study]}.yaml"
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            RUN_AND_LIST_MODULES,
            study,
            str(scene),
            str(tmp_path / "out"),
            str(tmp_path / "timings"),
            "--quick",
        ],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=ROOT,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    imported = set(json.loads(done.stdout.strip().splitlines()[-1]))
    assert f"{PACKAGE}.studies.{study}" in imported
    assert imported <= scene_job(study), imported - scene_job(study)


def stale_scenes(dry_run_output):
    """{(study, scene)} of the scene jobs a dry run would run, and the other rules it would run."""
    scenes = set(re.findall(r"wildcards: study=(\w+), scene=(\w+)", dry_run_output))
    rules = set(re.findall(r"^rule (\w+):", dry_run_output, re.MULTILINE)) - {"scene"}
    return scenes, rules


def every_scene(repo, studies):
    return {(s, p.stem) for s in studies for p in (repo / "workflow/scenes" / s).glob("*.yaml")}


def expected_after_editing(name, repo):
    """What a dry run should list after `name` is edited, from the graph: the scenes of the studies whose
    scene job reaches it, the gallery if its job does, and the report chain from whatever reruns."""
    studies = {study for study in STUDIES if name in scene_job(study)}
    gallery = name in code_graph.reached(
        graph(), [f"{PACKAGE}.jobserver", f"{PACKAGE}.studies.self_excited.gallery"]
    )
    archive = name in code_graph.reached(graph(), [f"{PACKAGE}.jobserver", f"{PACKAGE}.report.dist"])
    html = name in job("report.build")
    pdf = name in code_graph.reached(graph(), [f"{PACKAGE}.jobserver", f"{PACKAGE}.report.pdf"])
    rules = set()
    if studies or gallery or archive:
        rules |= {"results_archive", "report_html", "report_pdf"}
    if html:
        rules |= {"report_html", "report_pdf"}
    if pdf:
        rules |= {"report_pdf"}
    if studies & {"self_excited"} or gallery:
        rules.add("self_excited_gallery")
    return every_scene(repo, studies), rules | ({"all"} if rules else set())


# One module of each kind: shared by every study, one study's only, loaded lazily, the report's, the PDF's
EDITED = [
    f"{PACKAGE}.figure_data",
    f"{PACKAGE}.lazy",
    f"{PACKAGE}.studies.chains.symbolic",
    f"{PACKAGE}.studies.chandler.observed",
    f"{PACKAGE}.report.claims",
    f"{PACKAGE}.report.pdf",
]


@pytest.mark.slow
@pytest.mark.parametrize("name", EDITED)
def test_editing_a_module_reruns_exactly_the_jobs_that_run_it(scratch, name):
    path = scratch / "src" / (name.replace(".", "/") + ".py")
    path.write_text(path.read_text() + "\nEDITED = 1\n")  # code, not a comment: comments rerun nothing
    out = snakemake(scratch, "-n", "--config", "quick=1")
    assert stale_scenes(out.stdout) == expected_after_editing(name, scratch), out.stdout[-3000:]
