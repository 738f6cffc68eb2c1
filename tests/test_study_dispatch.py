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


def _spy(monkeypatch, module, name, calls):
    """Replace module.name by a recorder of its arguments (the dispatch is under test, not the analysis)."""
    monkeypatch.setattr(module, name, lambda *args: calls.append((f"{module.__name__}.{name}", args)))


def test_the_chandler_study_sends_each_kind_of_scene_to_its_analysis(monkeypatch):
    """A body to the retarding couple, an observation to the IERS fit, a model Earth to the model (then
    Poinsot where asked, the accuracy sweep where asked), each with the scene, the one Results and quick."""
    from types import SimpleNamespace

    from classical_dynamics.studies import chandler
    from classical_dynamics.studies.chandler import accuracy, model, observed, retarding

    calls = []
    for module in (accuracy, model, observed, retarding):
        _spy(monkeypatch, module, "run", calls)
    monkeypatch.setattr(chandler, "_poinsot", lambda *args: calls.append(("_poinsot", args)))
    kinds = {
        "body": ["classical_dynamics.studies.chandler.retarding.run"],
        "observation": ["classical_dynamics.studies.chandler.observed.run"],
        "earth": ["classical_dynamics.studies.chandler.model.run", "_poinsot"],
        "accuracy": [
            "classical_dynamics.studies.chandler.model.run",
            "_poinsot",
            "classical_dynamics.studies.chandler.accuracy.run",
        ],
    }
    for kind, expected in kinds.items():
        data = {"analysis": {"accuracy_cost": {}}, "earth": {}} if kind == "accuracy" else {kind: {}}
        scene = SimpleNamespace(name="s", title="t", data=data)
        calls.clear()
        results = chandler.run(scene, quick=True)
        assert [name for name, _ in calls] == expected, kind
        for name, args in calls:
            assert args[:2] == (scene, results) and (name == "_poinsot" or args[2] is True), (kind, name)


def test_the_chains_study_sends_each_model_to_its_analysis(monkeypatch):
    """The continuum to its module, a ring or a triangle to the planar one, any discrete chain to the discrete
    one and, where asked, to the time domain after it: each with the scene, the one Results and quick."""
    from types import SimpleNamespace

    from classical_dynamics.studies import chains
    from classical_dynamics.studies.chains import continuum, discrete, planar, time_domain

    calls = []
    for module, name in (
        (continuum, "run"),
        (discrete, "run"),
        (time_domain, "run"),
        (planar, "run_ring"),
        (planar, "run_triangle"),
    ):
        _spy(monkeypatch, module, name, calls)
    expected = {
        ("continuum", None): ["continuum.run"],
        ("ring", None): ["planar.run_ring"],
        ("triangle", None): ["planar.run_triangle"],
        ("particles", None): ["discrete.run"],
        ("particles", "time_domain"): ["discrete.run", "time_domain.run"],
    }
    for (model, analysis), names in expected.items():
        data = {"chain": {"model": model}} | ({"analysis": {analysis: {}}} if analysis else {})
        scene = SimpleNamespace(name="s", title="t", data=data)
        calls.clear()
        results = chains.run(scene, quick=True)
        assert [name.split(".", 3)[-1] for name, _ in calls] == names, model
        assert all(args == (scene, results, True) for _, args in calls), model


def test_the_precession_study_runs_its_rung_and_compares_a_modern_rate_with_psi_A(monkeypatch):
    """Every rung starts from the secular model and Lamb's examples; the averaged and full rungs add theirs
    (the accuracy sweep where asked); with today's constants the rate is set against IAU 2006's psi_A as
    rate/psi_A - 1 and against P03's first-order term r0 as rate/r0 - 1, here of numbers the spies record."""
    from types import SimpleNamespace

    from classical_dynamics.studies import precession
    from classical_dynamics.studies.precession import accuracy, averaged, examples, full, secular

    calls = []

    def secular_run(scene, results):
        calls.append(("secular", (scene, results)))
        results.number("precession_rate_arcsec_per_year", 50.0, "″/yr")
        results.number("iau2006_psi_A_rate_arcsec_per_year", 40.0, "″/yr")
        results.number("p03_first_order_rate_arcsec_per_year", 45.0, "″/yr")
        return "the model"

    monkeypatch.setattr(secular, "run", secular_run)
    for module in (examples, averaged, full, accuracy):
        _spy(monkeypatch, module, "run", calls)
    for fidelity, constants, analysis, expected in (
        ("secular", "lamb1920", {}, ["examples"]),
        ("averaged", "modern", {}, ["examples", "averaged"]),
        ("full", "modern", {"accuracy_cost": {}}, ["examples", "full", "accuracy"]),
        ("full", "modern", {}, ["examples", "full"]),
        ("full", "modern", None, ["examples", "full"]),  # no analysis block (the schema makes it optional)
    ):
        data = {"fidelity": fidelity, "constants": constants, "analysis": analysis}
        scene = SimpleNamespace(name="s", title="t", data={k: v for k, v in data.items() if v is not None})
        calls.clear()
        results = precession.run(scene, quick=True)
        assert [name.rsplit(".")[-2] if "." in name else name for name, _ in calls] == ["secular", *expected]
        assert all(args[0] is scene for _, args in calls) and calls[0][1][1] is results
        assert all(args[1:3] == ("the model", results) for _, args in calls[1:])
        assert all(args[3] is True for _, args in calls[2:])  # quick, where the rung takes it
        relative = results.numbers.get("rate_minus_psi_A_relative")
        assert (relative is None) == (constants == "lamb1920")
        if relative:
            assert relative["value"] == pytest.approx(50.0 / 40.0 - 1.0, rel=1e-15)
            assert "IAU 2006" in relative["note"] and "luni-solar" in relative["note"]
            against_r0 = results.numbers["rate_minus_r0_relative"]
            assert against_r0["value"] == pytest.approx(50.0 / 45.0 - 1.0, rel=1e-15)
            assert "$r_0$" in against_r0["note"]
        else:
            assert "rate_minus_r0_relative" not in results.numbers


def test_the_solvers_study_sends_each_problem_to_its_analysis(monkeypatch):
    """Each problem to its module (the two test problems to the sweeps, anything else to the hard cases),
    with the scene, the one Results and quick."""
    from types import SimpleNamespace

    from classical_dynamics.studies import solvers
    from classical_dynamics.studies.solvers import hard_cases, heavy_top, inertia, long_horizon, sweeps

    calls = []
    for module in (hard_cases, heavy_top, inertia, long_horizon, sweeps):
        _spy(monkeypatch, module, "run", calls)
    for problem, expected in (
        ("hnw_rigid_body", "sweeps"),
        ("detest_b5", "sweeps"),
        ("heavy_top", "heavy_top"),
        ("inertia", "inertia"),
        ("long_horizon", "long_horizon"),
        ("hard_cases", "hard_cases"),
    ):
        scene = SimpleNamespace(name="s", title="t", data={"problem": problem})
        calls.clear()
        results = solvers.run(scene, quick=True)
        assert [name for name, _ in calls] == [f"classical_dynamics.studies.solvers.{expected}.run"], problem
        assert calls[0][1][0] is scene and calls[0][1][1] is results and calls[0][1][2] is True, problem
