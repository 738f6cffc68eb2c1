import os
import shutil
import subprocess
import sys
from pathlib import Path

# One BLAS thread per test process, as scene_job gives each job, set before anything imports numpy:
# pytest-xdist runs a worker per core, and OpenBLAS's default, a thread per core in each worker, had them spin
# against each other (the chains, chandler, precession and poinsot tests: 26.8 and 27.8 s of CPU with
# them, 16.6 and 17.2 s without, on 2 cores). An exported value wins.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
# Each timing is one run, here and in the builds the tests start: a test reads values, never times (the
# benchmarks and the report's build time as they should, without this).
os.environ.setdefault("CLASSICAL_DYNAMICS_TIME_ONCE", "1")

import pytest  # noqa: E402

from classical_dynamics.studies import STUDIES  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = STUDIES["chains"].schema


def copy_repository(target: Path, source: Path = ROOT) -> Path:
    """A copy of a working tree (this checkout's by default) as git sees it (tracked and untracked-not-ignored
    files)."""
    listed = (
        subprocess.run(
            ["git", "ls-files", "-co", "--exclude-standard", "-z"],
            cwd=source,
            capture_output=True,
            check=True,
        )
        .stdout.decode()
        .split("\0")
    )
    for rel in filter(None, listed):
        original = source / rel
        if original.is_symlink():  # the package's link to report/: a link in the copy too
            (target / rel).parent.mkdir(parents=True, exist_ok=True)
            (target / rel).symlink_to(os.readlink(original))
        elif original.is_file():
            (target / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(original, target / rel)
    return copy_compiled(target, source)


def copy_compiled(target: Path, source: Path = ROOT) -> Path:
    """Compiled code travels with the sources it was compiled from (bytecode, numba's cache): each entry is
    checked against its source file's time and size, which copy2 keeps, so a copy of src/ starts as warm as
    the checkout (cold, the first parse alone compiles runge_kutta's typed loops: 9 s). No result changes."""
    for cached in (source / "src").glob("**/__pycache__/*"):
        try:
            (target / cached.relative_to(source)).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(cached, target / cached.relative_to(source))
        except FileNotFoundError:  # replaced meanwhile by a compile in another test worker
            pass
    return target


def run_env(repo: Path) -> dict:
    """Run the copy's own package, not the editable install of the original."""
    env = dict(os.environ)
    env["PYTHONPATH"] = str(repo / "src") + os.pathsep + env.get("PYTHONPATH", "")
    return env


def snakemake(repo: Path, *args, check=True, timeout=1200):
    command = [str(Path(sys.executable).parent / "snakemake"), *args]
    result = subprocess.run(
        command, cwd=repo, env=run_env(repo), capture_output=True, text=True, timeout=timeout
    )
    if check and result.returncode != 0:
        raise AssertionError(
            f"snakemake {' '.join(args)} failed:\n{result.stdout[-4000:]}\n{result.stderr[-4000:]}"
        )
    return result


@pytest.fixture(scope="session")
def built_repo(tmp_path_factory, worker_id):
    """A copy of the repository with a complete quick build, shared by the end-to-end tests: built once per
    test session, by whichever pytest-xdist worker asks first, while the others wait on a file lock."""
    from filelock import FileLock

    shared = tmp_path_factory.getbasetemp()
    if worker_id != "master":  # each worker has its own basetemp; their parent is the session's
        shared = shared.parent
    repo, done = shared / "built" / "repo", shared / "built" / "done"
    with FileLock(str(shared / "built.lock")):
        if not done.exists():
            shutil.rmtree(repo.parent, ignore_errors=True)  # a build that failed in another worker
            snakemake(copy_repository(repo), "-c", "2", "--config", "quick=1")
            done.touch()
    return repo


@pytest.fixture()
def scratch(built_repo, tmp_path):
    """A private copy of the built repository (results and Snakemake's records included)."""
    target = tmp_path / "repo"
    shutil.copytree(built_repo, target, symlinks=True)
    return target


def pytest_collection_modifyitems(items):
    """Tests that need the shared build, or rebuild scenes as verify does, are pipeline tests, and run last:
    while one worker builds, the others run everything else."""

    def needs_build(item):
        # archived: test_verify's archive of two scenes, which verify rebuilds by running their jobs
        return bool({"built_repo", "scratch", "archived"} & set(getattr(item, "fixturenames", ())))

    for item in items:
        if needs_build(item):  # fixturenames is the transitive closure: a fixture built on the build counts
            item.add_marker(pytest.mark.pipeline)
    items.sort(key=needs_build)  # stable: the order within each group is kept


def values(results) -> dict:
    """A real Results' numbers (units checked where they were recorded) as plain values, by name."""
    return {name: entry["value"] for name, entry in results.numbers.items()}


def assert_refused(tmp_path: Path, study: str, data: dict, field: str) -> None:
    """Writing `data` as a scene of `study` is refused with one line that names the file and `field`."""
    import yaml

    from classical_dynamics.scenes import SceneError
    from classical_dynamics.studies import validate

    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(SceneError) as err:
        validate(study, path)
    message = str(err.value)
    assert field in message and "bad.yaml" in message and "\n" not in message
