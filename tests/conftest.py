import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = ROOT / "workflow" / "schemas" / "chains.schema.yaml"


def copy_repository(target: Path) -> Path:
    """A copy of the working tree as git sees it (tracked and untracked-not-ignored files)."""
    listed = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT,
                            capture_output=True, check=True).stdout.decode().split("\0")
    for rel in filter(None, listed):
        source = ROOT / rel
        if source.is_file():
            (target / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target / rel)
    return target


def run_env(repo: Path) -> dict:
    """Run the copy's own package, not the editable install of the original."""
    env = dict(os.environ)
    env["PYTHONPATH"] = str(repo / "src") + os.pathsep + env.get("PYTHONPATH", "")
    return env


def snakemake(repo: Path, *args, check=True, timeout=1200):
    command = [str(Path(sys.executable).parent / "snakemake"), *args]
    result = subprocess.run(command, cwd=repo, env=run_env(repo), capture_output=True, text=True,
                            timeout=timeout)
    if check and result.returncode != 0:
        raise AssertionError(f"snakemake {' '.join(args)} failed:\n{result.stdout[-4000:]}\n{result.stderr[-4000:]}")
    return result


@pytest.fixture(scope="session")
def built_repo(tmp_path_factory):
    """A copy of the repository with a complete quick build (shared by the end-to-end tests)."""
    repo = copy_repository(tmp_path_factory.mktemp("built") / "repo")
    snakemake(repo, "-c", "2", "--config", "quick=1")
    return repo


def assert_refused(tmp_path: Path, study: str, data: dict, field: str) -> None:
    """Writing `data` as a scene of `study` is refused with one line that names the file and `field`."""
    import yaml

    from classical_dynamics.scenes import SceneError
    from classical_dynamics.studies import validate

    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(SceneError) as err:
        validate(study, path, ROOT / "workflow" / "schemas" / f"{study}.schema.yaml")
    message = str(err.value)
    assert field in message and "bad.yaml" in message and "\n" not in message
