"""The package's layout: no module imports itself back through others (imports inside functions included,
since a circle that only closes at run time is still one the reader has to untangle). The import graph is the
package's own (code_graph.py), the one a job's code digest is derived from."""

import pytest

from classical_dynamics.code_graph import import_graph


@pytest.fixture(scope="module")
def graph():
    """The package's import graph, parsed once for the tests below (each parse reads every module: 0.5 s)."""
    return import_graph()


def circles(graph):
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(node):
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for other in graph[node]:
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = set()
            while not component or node not in component:
                component.add(stack.pop())
            on_stack.difference_update(component)
            if len(component) > 1:
                found.append(sorted(component))

    for node in graph:
        if node not in index:
            visit(node)
    return found


def test_the_circle_finder_finds_one():
    assert circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert circles({"a": {"b"}, "b": set()}) == []


def test_no_module_imports_itself_back(graph):
    assert (
        "classical_dynamics.studies.self_excited.bounds"
        in graph["classical_dynamics.studies.self_excited.accuracy"]
    )
    assert circles(graph) == []


# docs/design.md's layers, lowest first; the rest of the package's top (io, formatting, units, ...)
# is the base, below them all, and the entry points are above them all.
LAYERS = {"solvers": 1, "scenes": 2, "models": 3, "studies": 4, "report": 5}
ENTRY_POINTS = {"cli", "scene_job", "jobserver", "__main__"}  # verify's reading of archives is a library


def layer(module):
    parts = module.split(".")
    if len(parts) == 1:
        return None  # the package itself
    return 6 if parts[1] in ENTRY_POINTS else LAYERS.get(parts[1], 0)


def upward_imports(graph):
    return sorted(
        (a, b)
        for a, targets in graph.items()
        for b in targets
        if layer(a) is not None and layer(b) is not None and layer(b) > layer(a)
    )


def test_imports_point_down_the_layers(graph):
    """A solver never imports a model, a model never a study, a study never the report (the report reads
    results files), and nothing below the entry points imports one."""
    # an empty graph would pass: the check must see the package's own downward imports
    assert "classical_dynamics.models.precession" in graph["classical_dynamics.studies.precession.full"]
    assert "classical_dynamics.solvers.ode" in graph["classical_dynamics.studies.chandler.model"]
    assert upward_imports(graph) == []


def test_the_layer_check_finds_an_upward_import():
    graph = {"p.solvers.ode": {"p.models.earth"}, "p.models.earth": set(), "p.io": {"p.cli"}, "p.cli": set()}
    assert upward_imports(graph) == [("p.io", "p.cli"), ("p.solvers.ode", "p.models.earth")]


def test_the_top_level_is_the_layout_the_project_card_names():
    """Snakefile at the top (the rules in workflow/rules), Snakemake's default profile beside it, and report/
    holding the report's templates, styles, ledgers and bibliography, which the package reads through its link
    report/files (the wheel ships them as files)."""
    from pathlib import Path

    from classical_dynamics.report import assets

    root = Path(__file__).resolve().parents[1]
    assert (root / "Snakefile").is_file() and not (root / "workflow/Snakefile").exists()
    assert sorted(p.name for p in (root / "workflow/rules").glob("*.smk"))
    assert (root / "profiles/default/config.yaml").is_file()  # where Snakemake looks beside a top Snakefile
    for name in ("templates/report.html.j2", "templates/print.css", "references.bib", "ledger/lee1964.yaml"):
        assert (root / "report" / name).is_file()
    assert assets.TEMPLATES == (root / "report/templates").resolve()


# Test modules that import models/ or a study but read the tree itself (import graphs, digests, the package's
# files, the built report): mutmut runs the tests in its rewritten copy, where they would fail for its sake
READS_THE_TREE = {
    "test_code_dependencies.py",
    "test_code_layout.py",
    "test_package.py",
    "test_report_navigation.py",
    "test_report_render.py",
    "test_snakemake_report.py",
    "test_report_units.py",
    "test_io_and_report_units.py",
    "test_check_sites.py",
}


def test_mutation_testing_runs_every_test_of_the_code_it_mutates():
    """`make mutants` scores the studies and models by pyproject's test selection: a test module that imports
    them and is left out of it lets a mutant it would kill survive (test_bad_input.py was, and every refusal
    message of check() survived)."""
    import re
    import tomllib

    from .conftest import ROOT

    selection = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["mutmut"]
    selected = {path.removeprefix("tests/") for path in selection["pytest_add_cli_args_test_selection"]}
    reaching = {
        path.name
        for path in (ROOT / "tests").glob("test_*.py")
        if re.search(r"classical_dynamics(\.| import .*\b)(studies|models)\b", path.read_text())
    }
    assert reaching - READS_THE_TREE <= selected, sorted(reaching - READS_THE_TREE - selected)
    assert not (selected & READS_THE_TREE)
