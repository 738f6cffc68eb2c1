"""Issue 19: malformed, oversized and hostile scenes are refused before anything runs, in one line naming the
file and the field; through Snakemake, results/ stays byte-identical. How long a refusal takes is a benchmark
figure (benchmarks/bad_input.py), not a test's: a loaded machine must not fail a right refusal."""

import hashlib
import shutil
from collections import Counter
from pathlib import Path

import pytest

from classical_dynamics.scenes import SceneError
from classical_dynamics.scenes.cost import Budget
from classical_dynamics.studies import STUDIES, validate

from .bad_scenes import KINDS, ROOT, all_cases
from .conftest import snakemake

CASES = all_cases()
BUDGET = Budget.from_file(ROOT / "workflow/config.yaml")


def refuse(case, folder: Path) -> str:
    """The one-line refusal of a case."""
    path = case.write(folder)
    with pytest.raises(SceneError) as error:
        validate(case.study, path, BUDGET)
    return str(error.value)


def _field(case) -> str:
    """The field as the message must name it: whole (its closing quote too, so that 'chain' is not taken for
    'chain.n'), except a YAML error's place, whose line and column depend on the scene it was written into."""
    return case.field if case.field.startswith("(YAML at") else case.field + "'"


def test_the_suite_covers_every_study_and_kind():
    assert len(CASES) >= 120
    by_study, by_kind = Counter(c.study for c in CASES), Counter(c.kind for c in CASES)
    assert set(by_kind) == set(KINDS), by_kind
    assert all(
        by_study[study] >= 20 for study in ("precession", "chandler", "chains", "self_excited", "solvers")
    )


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_a_bad_scene_is_refused_in_one_line_naming_its_field(tmp_path, case):
    # imports and caches warm
    validate(case.study, next((ROOT / "workflow/scenes" / case.study).glob("*.yaml")), BUDGET)
    message = refuse(case, tmp_path)
    assert "\n" not in message
    assert message.startswith(f"{tmp_path / case.name}: field '{_field(case)}"), message
    # refused for its reason: a physical refusal says which consistency the scene broke
    assert case.kind != "physics" or case.says, f"{case.id}: a physics case names what its refusal says"
    assert case.says in message.split(": expected ", 1)[-1], message
    # a missing field shows nothing as what it got; "got None" is an empty file, read as YAML's null
    assert not message.endswith(", got None") or case.id.endswith("-empty"), message


# Refusals of a study's check() that no scene can meet, each as (study, a phrase of its raise statement that
# names it alone), with the reason.
def _digest(folder: Path) -> str:
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


def test_snakemake_refuses_one_of_each_kind_and_touches_nothing(built_repo, tmp_path):
    """Snakemake validates every scene when it reads the Snakefile: one case of each kind, each study in turn,
    through `snakemake -n` on a built copy: exit 1, one line naming the file, results/ byte-identical."""
    studies = ("precession", "chandler", "chains", "self_excited", "solvers")
    picked = [
        next(c for c in sorted(CASES, key=lambda c: c.study != studies[i % len(studies)]) if c.kind == kind)
        for i, kind in enumerate(KINDS)
    ]
    # once each study
    picked += [next(c for c in CASES if c.id == f"{study}-alias-bomb") for study in studies]
    repo = tmp_path / "repo"  # a copy: the shared build is read by other tests meanwhile
    shutil.copytree(built_repo, repo, symlinks=True)
    before = _digest(repo / "results")
    for case in picked:
        folder = repo / "workflow/scenes" / case.study
        path = case.write(folder)
        try:
            result = snakemake(repo, "-n", check=False, timeout=120)
        finally:
            path.rmdir() if path.is_dir() and not path.is_symlink() else path.unlink()
        assert result.returncode == 1, case.id
        # Snakemake's own
        lines = [
            line
            for line in result.stderr.splitlines()
            if line.strip() and not line.startswith("Using workflow specific profile")
        ]
        assert (
            lines == [lines[-1]]
            and f"workflow/scenes/{case.study}/{case.name}: field '{_field(case)}" in lines[-1]
        ), (case.id, result.stderr[-2000:])
        assert _digest(repo / "results") == before, case.id


def _unbounded(schema, where="") -> list[str]:
    """Every field of a schema that takes a number without both bounds, a list without maxItems, or free text
    without maxLength."""
    found = []
    if isinstance(schema, dict):
        kinds = schema.get("type", [])
        kinds = kinds if isinstance(kinds, list) else [kinds]
        if {"number", "integer"} & set(kinds):
            if not (
                {"minimum", "exclusiveMinimum"} & set(schema)
                and {"maximum", "exclusiveMaximum"} & set(schema)
            ):
                found.append(f"{where}: a number without both bounds")
        if "array" in kinds and "maxItems" not in schema:
            found.append(f"{where}: a list without maxItems")
        if "string" in kinds and "maxLength" not in schema and "pattern" not in schema:
            found.append(f"{where}: text without maxLength")
        for key, value in schema.items():
            found += _unbounded(value, f"{where}.{key}" if where else key)
    elif isinstance(schema, list):
        for i, value in enumerate(schema):
            found += _unbounded(value, f"{where}.{i}")
    return found


@pytest.mark.parametrize("study", ["precession", "chandler", "chains", "self_excited", "solvers"])
def test_every_number_a_schema_takes_is_bounded(study):
    """Finite ranges on every float (and integer), a length on every list and text: 1e300 never reaches a
    model."""
    import yaml

    schema = yaml.safe_load((STUDIES[study].schema).read_text())
    assert _unbounded(schema) == []


def test_shipped_scenes_fit_the_default_budget():
    """Every shipped scene is costed, within the budget of workflow/config.yaml, with a positive estimate."""
    for study in ("precession", "chandler", "chains", "self_excited", "solvers"):
        for path in sorted((ROOT / "workflow/scenes" / study).glob("*.yaml")):
            scene = validate(study, path, BUDGET)
            assert 0 < scene.estimate.seconds <= BUDGET.seconds, path
            assert scene.estimate.memory_limit_mb <= BUDGET.memory_mb + 1000, path


BAD_CONFIG = [
    ("quick=banana", "the command line (--config): config 'quick': expected 0 or 1, got 'banana'"),
    ("quick=1.5", "the command line (--config): config 'quick': expected 0 or 1, got 1.5"),
    ("jobserver=2", "the command line (--config): config 'jobserver': expected 0 or 1, got 2"),
    ("budget=5", "the command line (--config): config 'budget': expected a mapping such as"),
    ("budget={hours: 2}", "the command line (--config): config 'budget.hours': expected one of seconds"),
    ("speed=11", "the command line (--config): config 'speed': expected one of the keys quick"),
]


@pytest.mark.slow
def test_a_bad_configuration_is_refused_in_one_line_naming_key_value_and_origin(built_repo, tmp_path):
    """Every --config key and every key of workflow/config.yaml is checked before anything runs: one line with
    the key, the value and where it came from; exit 1; results/ untouched."""
    repo = tmp_path / "repo"
    shutil.copytree(built_repo, repo, symlinks=True)
    before = _digest(repo / "results")
    refusals = [
        (setting, snakemake(repo, "-n", "--config", setting, check=False)) for setting, _ in BAD_CONFIG
    ]
    config = repo / "workflow/config.yaml"
    config.write_text(config.read_text().replace("quick: 0", "quick: maybe"))
    refusals.append(("quick: maybe", snakemake(repo, "-n", check=False)))
    expected = [line for _, line in BAD_CONFIG] + ["workflow/config.yaml: config 'quick': expected 0 or 1"]
    for (setting, result), line in zip(refusals, expected):
        lines = [
            text
            for text in result.stderr.splitlines()
            if text.strip() and not text.startswith(("Using workflow specific profile", "Config file"))
        ]
        assert result.returncode == 1 and len(lines) == 1 and lines[0].startswith(line), (
            setting,
            result.stderr,
        )
    assert _digest(repo / "results") == before
