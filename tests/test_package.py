"""The package installed as a wheel works from any directory: it ships its schemas, chapters, claims,
templates, ledgers and bibliography, and finds them through importlib.resources, not from the checkout."""

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from classical_dynamics.studies import STUDIES

from .conftest import ROOT, copy_repository

pytestmark = [pytest.mark.slow, pytest.mark.pipeline]


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(the wheel, a folder it is installed into): built from a copy, so the checkout gets no build/ or
    egg-info."""
    base = tmp_path_factory.mktemp("package")
    source = copy_repository(base / "source")
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check", "--quiet"]
    subprocess.run(
        pip + ["wheel", "--no-deps", "--no-build-isolation", "-w", str(base / "wheel"), str(source)],
        check=True,
        capture_output=True,
        timeout=300,
    )
    (wheel,) = (base / "wheel").glob("classical_dynamics-*.whl")
    subprocess.run(
        pip + ["install", "--no-deps", "--no-index", "--target", str(base / "site"), str(wheel)],
        check=True,
        capture_output=True,
        timeout=300,
    )
    return wheel, base / "site"


def shipped_beside_code() -> set[str]:
    """Every file of the package that is not code, as the checkout has it, and every file of report/ (which
    the package reaches through its link report/files)."""
    package = ROOT / "src"
    beside = {
        path.relative_to(package).as_posix()
        for path in (package / "classical_dynamics").rglob("*")
        if path.is_file() and path.suffix not in (".py", ".pyc") and "__pycache__" not in path.parts
    }
    report = {
        f"classical_dynamics/report/files/{p.relative_to(ROOT / 'report').as_posix()}"
        for p in (ROOT / "report").rglob("*")
        if p.is_file()
    }
    return beside | report


def test_the_wheel_ships_every_file_the_package_reads_and_the_console_script(installed):
    wheel, _ = installed
    names = set(zipfile.ZipFile(wheel).namelist())
    for study in STUDIES:
        for name in ("schema.yaml", "chapter.html.j2", "claims.yaml"):
            assert f"classical_dynamics/studies/{study}/{name}" in names
    assert shipped_beside_code() <= names
    (entry_points,) = (n for n in names if n.endswith(".dist-info/entry_points.txt"))
    assert (
        "classical-dynamics = classical_dynamics.cli:main"
        in zipfile.ZipFile(wheel).read(entry_points).decode()
    )


def run_installed(site: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    """The installed copy first on the path (before the checkout's editable install), in a folder of its
    own."""
    code = (
        "import sys; sys.path.insert(0, sys.argv.pop(1)); from classical_dynamics.cli import main; "
        "import classical_dynamics; assert classical_dynamics.__file__.startswith(sys.path[0]); "
        "sys.exit(main())"
    )
    return subprocess.run(
        [sys.executable, "-c", code, str(site), *args], cwd=cwd, capture_output=True, text=True, timeout=600
    )


def test_the_installed_package_validates_a_scene_from_any_directory(installed, tmp_path):
    _, site = installed
    scene = tmp_path / "a.yaml"
    scene.write_text((ROOT / "workflow/scenes/chains/hanging_continuum.yaml").read_text())
    done = run_installed(site, tmp_path, "validate", "chains", str(scene))
    assert done.returncode == 0, done.stderr
    scene.write_text(scene.read_text().replace("length_m: 1.0", "length_m: -1.0"))
    refused = run_installed(site, tmp_path, "validate", "chains", str(scene))
    assert refused.returncode == 2 and "chain.length_m" in refused.stderr  # the shipped schema was read


def test_the_installed_package_renders_the_report_the_checkout_renders(installed, built_repo, tmp_path):
    """Templates, chapters, claims, ledgers and bibliography from the installed package: the same report."""
    _, site = installed
    done = run_installed(
        site,
        tmp_path,
        "report",
        str(built_repo / "results"),
        str(tmp_path / "report.html"),
        "--root",
        str(built_repo),
        "--quick",
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert (tmp_path / "report.html").read_bytes() == (built_repo / "results/report.html").read_bytes()
