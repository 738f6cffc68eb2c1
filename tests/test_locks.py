"""The lock files: every package pinned with hashes, the tests' packages apart from the pipeline's, the conda
environment with the pipeline's pins, and this environment installed from them."""

import re
import tomllib
from importlib import metadata

import pytest
import yaml

from .conftest import ROOT

LOCKS = ROOT / "requirements"


def normalized(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def pins(lock: str) -> dict[str, tuple[str, int]]:
    """{package: (version, number of hashes)} of a lock file."""
    found, name = {}, None
    for line in (LOCKS / lock).read_text().splitlines():
        match = re.match(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==(\S+)", line)
        if match:
            name = normalized(match.group(1))
            found[name] = (match.group(2), 0)
        elif name and line.strip().startswith("--hash=sha256:"):
            found[name] = (found[name][0], found[name][1] + 1)
        elif line and not line.startswith((" ", "#", "-r ")):
            pytest.fail(f"{lock}: not a pin: {line}")
    return found


def test_every_package_is_pinned_with_hashes():
    for lock in ("pipeline.lock", "test.lock", "slurm.lock"):
        unhashed = [name for name, (_, hashes) in pins(lock).items() if hashes == 0]
        assert pins(lock) and not unhashed, (lock, unhashed)


def test_the_tests_lock_adds_to_the_pipelines():
    pipeline, test = pins("pipeline.lock"), pins("test.lock")
    assert (LOCKS / "test.lock").read_text().count("-r pipeline.lock\n") == 1
    assert not set(pipeline) & set(test)
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    for requirement in project["dependencies"]:
        assert normalized(requirement) in pipeline, requirement
    for requirement in project["optional-dependencies"]["test"]:
        assert normalized(requirement) in pipeline | test, requirement
    assert {"weasyprint", "setuptools"} <= set(pipeline)
    assert "pytest" in test and "pytest" not in pipeline


def test_slurm_is_an_extra_a_bare_install_goes_without():
    """The Slurm executor is pinned apart (requirements/slurm.lock, the `slurm` extra): `make report` installs
    only pipeline.lock, so a machine with Slurm's commands but no cluster never waits on the plugin."""
    pipeline, slurm = pins("pipeline.lock"), pins("slurm.lock")
    assert (LOCKS / "slurm.lock").read_text().count("-r pipeline.lock\n") == 1
    assert "snakemake-executor-plugin-slurm" in slurm and not set(slurm) & set(pipeline)
    assert not any(name.startswith("snakemake-executor-plugin-slurm") for name in pipeline)
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert [normalized(r) for r in project["optional-dependencies"]["slurm"]] == [
        "snakemake-executor-plugin-slurm"
    ]


def test_the_conda_environment_has_the_pipelines_pins():
    environment = yaml.safe_load((ROOT / "workflow/envs/pipeline.yaml").read_text())
    pip = next(entry["pip"] for entry in environment["dependencies"] if isinstance(entry, dict))
    pinned = {
        normalized(name): version for name, version in (line.split("==") for line in pip if "==" in line)
    }
    assert pinned == {name: version for name, (version, _) in pins("pipeline.lock").items()}
    assert "-e ../.." in pip  # this package, from the checkout
    assert {"python=3.11", "pango"} <= {
        entry for entry in environment["dependencies"] if isinstance(entry, str)
    }
    assert "Python 3.11" in (LOCKS / "pipeline.lock").read_text()  # what pip-compile resolved for


def test_this_environment_is_installed_from_the_locks():
    locked = pins("pipeline.lock") | pins("test.lock")
    differ = {}
    for name, (version, _) in locked.items():
        try:
            installed = metadata.version(name)
        except metadata.PackageNotFoundError:
            installed = None
        if installed != version:
            differ[name] = (version, installed)
    assert not differ, differ
