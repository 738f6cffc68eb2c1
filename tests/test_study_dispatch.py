"""Direct tests of studies/__init__.py and studies/registry.py, the dispatch every scene goes through: an
unknown study named with the known ones, each registered study's module and its effects (schema against
registry), and a scene whose cost cannot even be estimated refused in one line naming its values."""

import pytest
import yaml

from classical_dynamics.scenes import SceneError
from classical_dynamics.studies import STUDIES, study_module, validate

from .conftest import ROOT

OZONE = ROOT / "workflow/scenes/chains/ozone_molecule.yaml"


def test_an_unknown_study_is_refused_naming_the_known_ones():
    with pytest.raises(KeyError) as error:
        study_module("pendulum")
    message = str(error.value)
    assert "unknown study 'pendulum'" in message
    assert message.split("known: ")[1].rstrip("\"'") == ", ".join(sorted(STUDIES))


@pytest.mark.parametrize("name", sorted(STUDIES))
def test_each_study_is_its_package_with_the_schemas_effects(name):
    # the folder of the same name under src/, exposing the interface; the effects its schema allows, read
    # here from the YAML, are those its module registers, in the schema's order
    module = study_module(name)
    assert module.__name__ == f"classical_dynamics.studies.{name}"
    assert all(callable(getattr(module, f)) for f in ("check", "cost", "run"))
    schema = yaml.safe_load((ROOT / "src/classical_dynamics/studies" / name / "schema.yaml").read_text())
    listed = list(schema["properties"]["effects"]["properties"])
    assert STUDIES[name].effect_names() == listed
    assert sorted(listed) == sorted(module.EFFECTS.names())


@pytest.mark.parametrize("error", [OverflowError("int too large"), ValueError("array is too big")])
def test_a_cost_that_cannot_be_estimated_is_a_one_line_refusal(monkeypatch, error):
    def cost(data):
        raise error

    monkeypatch.setattr(study_module("chains"), "cost", cost)
    with pytest.raises(SceneError) as refused:
        validate("chains", OZONE)
    message = str(refused.value)
    assert message.startswith(f"{OZONE}: field '(values)'") and "\n" not in message
    assert f"{type(error).__name__}: {error}" in message


def test_a_fault_in_the_cost_model_is_not_taken_for_a_bad_scene(monkeypatch):
    # only arithmetic, value and type errors mean sizes too large to estimate; anything else is a bug
    def cost(data):
        raise RuntimeError("a bug in the cost model")

    monkeypatch.setattr(study_module("chains"), "cost", cost)
    with pytest.raises(RuntimeError, match="a bug in the cost model"):
        validate("chains", OZONE)
