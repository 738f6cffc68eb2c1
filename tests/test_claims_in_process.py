"""Every light scene's claims hold when the scene runs in this process: the sources' printed values (Lamb,
Routh, Lee, the notes, IAU, IERS) are the reference, not anything the study computed, so a wrong number a
study records fails here in seconds, not only in the quick build. And every number, figure and table its
chapter cites from it is recorded under the name the chapter uses, and its named hard cases hold. A light
scene is one the cost model estimates at LIGHT_SECONDS or less on one core; the heavy ones are checked by the
pipeline tests' build."""

import re
from pathlib import Path

import pytest

from classical_dynamics.report import claims
from classical_dynamics.studies import STUDIES, study_module, validate

SCENES = Path(__file__).resolve().parents[1] / "workflow" / "scenes"
LIGHT_SECONDS = 3.0


def _claims(study, numbers=None, scene=None):
    """The study's claims, evaluated with the numbers one scene recorded (none: as if no scene had run)."""

    def lookup(_study, scene_of_claim, number):
        if numbers is None or scene_of_claim != scene:
            raise KeyError(scene_of_claim)
        return numbers[number]

    return claims.evaluate(study, STUDIES[study].file("claims.yaml"), lookup)


# what a chapter cites of a scene: {% set X = S ~ "/scene" %}, then num(X, "key"), fig(X, "name"), ...
BINDING = re.compile(r'\{%-?\s*set\s+(\w+)\s*=\s*S\s*~\s*"/(\w+)"\s*-?%\}')
USE = re.compile(r'\b(num|rel|value|fig|table)\((\w+),\s*"(\w+)"(?:,\s*"(\w+)")?')
SUMMARY = re.compile(r'summary\(S,\s*"(\w+)"\)\.(numbers|figures)(?:\.(\w+)|\[\s*"(\w+)"\s*\])')
KIND = {"num": "numbers", "rel": "numbers", "value": "numbers", "fig": "figures", "table": "tables"}


def cited(study) -> set[tuple[str, str, str]]:
    """(scene, numbers/figures/tables, name) of everything the study's chapter cites by a scene's name."""
    text = STUDIES[study].file("chapter.html.j2").read_text(encoding="utf-8")
    found, bound = set(), {}
    marks = [(m.start(), m) for pattern in (BINDING, USE, SUMMARY) for m in pattern.finditer(text)]
    for _, m in sorted(marks, key=lambda mark: mark[0]):
        if m.re is BINDING:
            bound[m[1]] = m[2]  # a name is bound again further on: the latest binding counts
        elif m.re is USE and m[2] in bound:
            found |= {(bound[m[2]], KIND[m[1]], name) for name in (m[3], m[4]) if name}
        elif m.re is SUMMARY:
            found.add((m[1], m[2], m[3] or m[4]))
    return found


def _light_scenes_with_claims():
    cases = []
    for study in sorted(STUDIES):
        required = {c.scene for c in _claims(study) if c.must_hold} | {scene for scene, *_ in cited(study)}
        for path in sorted((SCENES / study).glob("*.yaml")):
            if path.stem in required and validate(study, path).estimate.seconds <= LIGHT_SECONDS:
                cases.append(pytest.param(study, path.stem, id=f"{study}/{path.stem}"))
    return cases


def test_light_scenes_cover_every_study_and_the_chapters_are_read():
    studies = {case.values[0] for case in _light_scenes_with_claims()}
    assert studies == set(STUDIES), f"no light scene with a claim in {set(STUDIES) - studies}"
    # the chapter's citations are found (a pattern that stopped matching would check nothing)
    assert ("lamb_1920", "numbers", "secular_per_orbit_arcsec") in cited("precession")
    assert ("observed", "figures", "periodogram") in cited("chandler")


@pytest.mark.parametrize("study,scene", _light_scenes_with_claims())
def test_a_light_scenes_claims_hold_and_what_its_chapter_cites_is_recorded(study, scene):
    """The scene runs quick, as in the quick build; its numbers as its summary.json would record them."""
    validated = validate(study, SCENES / study / f"{scene}.yaml")
    results = study_module(study).run(validated, quick=True)
    recorded = {
        "numbers": set(results.numbers),
        "figures": set(results.figures) | set(results.timing_figures),
        "tables": set(results.tables) | set(results.timing_tables),
    }
    missing = sorted(
        (kind, name) for of, kind, name in cited(study) if of == scene and name not in recorded[kind]
    )
    assert not missing, f"{study}/{scene}: its chapter cites what the run did not record: {missing}"
    required = [r for r in _claims(study, results.numbers, scene) if r.scene == scene and r.must_hold]
    failed = [
        f"{r.id}: {r.number} = {r.computed}, the source's {r.source.get('value')} ({r.check}) {r.problem}"
        for r in required
        if not r.passed
    ]
    assert not failed, "\n".join(failed)
    # Its named hard cases hold, as the quick build must show them: each sets one computation against another
    # that does not share its error (Euler's equations against the reduced plane, an integration against a
    # closed form, the energy along a step), with the bound the hard case states.
    broken = [f"{c['name']}: {c['measured']} > {c['bound']}" for c in results.stability if not c["holds"]]
    assert not broken, f"{study}/{scene}: " + "; ".join(broken)


def _recordable(study) -> list[re.Pattern]:
    """Every name the study's code can record a number under: its string literals, and its f-strings with
    each {field} free (f"best_error_{method}" records best_error_dop853)."""
    import ast

    patterns = []
    for path in STUDIES[study].file("claims.yaml").parent.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                patterns.append(re.compile(re.escape(node.value)))
            elif isinstance(node, ast.JoinedStr):
                parts = [
                    re.escape(part.value) if isinstance(part, ast.Constant) else ".+" for part in node.values
                ]
                patterns.append(re.compile("".join(parts)))
    return patterns


@pytest.mark.parametrize("study", sorted(STUDIES))
def test_every_number_a_chapter_or_claim_cites_is_a_name_its_study_records(study):
    """Of every scene, light or heavy, read from the code: a number the chapter or a claim cites is a name the
    study's code writes, as a literal or an f-string, so a key renamed on one side fails here, not only in
    the build."""
    cited_numbers = {name for _, kind, name in cited(study) if kind == "numbers"}
    cited_numbers |= {c.number for c in _claims(study)}
    patterns = _recordable(study)
    unknown = sorted(name for name in cited_numbers if not any(p.fullmatch(name) for p in patterns))
    assert not unknown, f"{study}: cited, but no code of the study records them: {unknown}"
