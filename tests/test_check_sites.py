"""Every refusal of a study's check() is met by a bad scene of tests/bad_scenes/ (issue 38): the raise sites
are read from the studies' source with ast, the site of each case's refusal from its traceback. It reads the
tree, so mutation testing (mutmut rewrites every function of a module into a trampoline and its mutants)
leaves it out; a mutant that moves a refusal is caught by test_bad_input.py's message checks."""

import ast
import traceback
from pathlib import Path

from classical_dynamics import studies
from classical_dynamics.scenes import SceneError
from classical_dynamics.scenes.cost import Budget
from classical_dynamics.studies import validate

from .bad_scenes import ROOT, all_cases

CASES = all_cases()
BUDGET = Budget.from_file(ROOT / "workflow/config.yaml")

UNREACHABLE = {
    # the schema takes exactly two entries in elastic_yielding, source and one of k2 or period_solar_days
    # (required: [source], min/maxProperties: 2, additionalProperties: false): never both, never neither
    ("chandler", "one of k2 or period_solar_days"),
    # the schema's maximum of step_hours is 24, MAX_STEP_HOURS itself: no step above it reaches check()
    ("precession", "the full rung resolves the daily spin"),
}


def _check_sites() -> dict[tuple[str, int, int], str]:
    """Every `raise SceneError(...)` of the studies' __init__.py (their check()): (study, first line, last
    line) -> the statement's source."""
    sites = {}
    for module in sorted(Path(studies.__file__).resolve().parent.glob("*/__init__.py")):
        source = module.read_text(encoding="utf-8")
        for node in ast.walk(ast.parse(source)):
            if (
                isinstance(node, ast.Raise)
                and isinstance(node.exc, ast.Call)
                and getattr(node.exc.func, "id", "") == "SceneError"
            ):
                key = (module.parent.name, node.lineno, node.end_lineno)
                sites[key] = ast.get_source_segment(source, node)
    return sites


def test_every_refusal_of_a_check_is_met_by_a_bad_scene(tmp_path):
    """Each refusal a study's check() can make is the one some bad scene gets: the line of the raise is the
    innermost frame of that scene's SceneError. A refusal no scene meets is untested (its condition, field
    and words may be wrong unseen), unless UNREACHABLE says why no scene can."""
    sites = _check_sites()
    package = Path(studies.__file__).resolve().parent
    met = {}  # (study, line) -> a case that was refused there
    for i, case in enumerate(CASES):
        folder = tmp_path / str(i)
        folder.mkdir()
        try:
            validate(case.study, case.write(folder), BUDGET)
        except SceneError as error:
            frame = traceback.extract_tb(error.__traceback__)[-1]
            where = Path(frame.filename).resolve()
            if where.name == "__init__.py" and where.parent.parent == package:
                met.setdefault((where.parent.name, frame.lineno), case.id)

    def meeting(site):
        study, first, last = site
        return next((case for (s, line), case in met.items() if s == study and first <= line <= last), None)

    unreachable = set()
    for study, phrase in UNREACHABLE:
        named = [site for site, source in sites.items() if site[0] == study and phrase in source]
        assert len(named) == 1, f"UNREACHABLE's {(study, phrase)} names {len(named)} refusals, not one"
        assert meeting(named[0]) is None, (
            f"{named[0]} is met by {meeting(named[0])}: drop it from UNREACHABLE"
        )
        unreachable.add(named[0])
    missing = [
        f"{study}/__init__.py:{first}: {' '.join(sites[study, first, last].split())[:160]}"
        for study, first, last in sorted(sites)
        if (study, first, last) not in unreachable and meeting((study, first, last)) is None
    ]
    assert len(sites) > 100 and missing == [], f"{len(missing)} refusals met by no bad scene: {missing}"
