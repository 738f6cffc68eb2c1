"""Every light scene's claims hold when the scene runs in this process: the sources' printed values (Lamb,
Routh, Lee, the notes, IAU, IERS) are the reference, not anything the study computed, so a wrong number a
study records fails here in seconds, not only in the quick build. A light scene is one the cost model
estimates at LIGHT_SECONDS or less on one core; the heavy ones are checked by the pipeline tests' build."""

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


def _light_scenes_with_claims():
    cases = []
    for study in sorted(STUDIES):
        required = {c.scene for c in _claims(study) if c.must_hold}
        for path in sorted((SCENES / study).glob("*.yaml")):
            if path.stem in required and validate(study, path).estimate.seconds <= LIGHT_SECONDS:
                cases.append(pytest.param(study, path.stem, id=f"{study}/{path.stem}"))
    return cases


def test_light_scenes_cover_every_study():
    studies = {case.values[0] for case in _light_scenes_with_claims()}
    assert studies == set(STUDIES), f"no light scene with a claim in {set(STUDIES) - studies}"


@pytest.mark.parametrize("study,scene", _light_scenes_with_claims())
def test_a_light_scenes_claims_hold(study, scene):
    """The scene runs quick, as in the quick build; its numbers as its summary.json would record them."""
    validated = validate(study, SCENES / study / f"{scene}.yaml")
    numbers = study_module(study).run(validated, quick=True).numbers
    required = [r for r in _claims(study, numbers, scene) if r.scene == scene and r.must_hold]
    assert required, f"{study}/{scene}: no must-hold claim"
    failed = [
        f"{r.id}: {r.number} = {r.computed}, the source's {r.source.get('value')} ({r.check}) {r.problem}"
        for r in required
        if not r.passed
    ]
    assert not failed, "\n".join(failed)
