"""verify and diff: a small archive of two cheap chain scenes, rebuilt and compared through the CLI."""

import gzip
import hashlib
import io
import json
import shutil
import subprocess
import sys
import tarfile

import pytest

from classical_dynamics.report.dist import make_archive
from classical_dynamics.verify import compare

from .conftest import ROOT, copy_compiled, run_env

SCENES = ["two_masses_three_springs", "triatomic_molecule"]
ARCHIVE = "classical-dynamics-0.1.0.tar.gz"
CHANGED = "chains/two_masses_three_springs/summary.json"


def cli(*args, cwd, tmpdir=None):
    """The CLI as a user runs it; TMPDIR is a folder of the test's, to see that it is left empty."""
    env = run_env(ROOT)
    if tmpdir is not None:
        env["TMPDIR"] = str(tmpdir)
    return subprocess.run(
        [sys.executable, "-m", "classical_dynamics", *map(str, args)],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )


def checkout_copy(target):
    """What a rebuild reads: the code, the Snakefile and the workflow (rules, scenes, configuration)."""
    for part in ("src", "workflow"):
        shutil.copytree(ROOT / part, target / part, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy2(ROOT / "Snakefile", target / "Snakefile")
    return copy_compiled(target)  # as warm as the checkout: a cold rebuild compiles the solvers again (9 s)


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if "__pycache__" not in p.parts)


@pytest.fixture(scope="module")
def archived(tmp_path_factory):
    """results/ with two quick chain scenes, a stand-in report, and its dist archive."""
    base = tmp_path_factory.mktemp("verify")
    results = base / "results"
    for scene in SCENES:
        done = cli(
            "run",
            "chains",
            ROOT / f"workflow/scenes/chains/{scene}.yaml",
            results / "chains" / scene,
            results / "chains/timings" / scene,
            "--quick",
            cwd=ROOT,
        )
        assert done.returncode == 0, done.stderr
    (results / "report.html").write_text("<html></html>")  # dist packs the report too
    (results / "report.pdf").write_bytes(b"%PDF-1.7\n")
    make_archive(results, base / "dist" / ARCHIVE)
    return {
        "results": results,
        "archive": base / "dist" / ARCHIVE,
        "checkout": checkout_copy(base / "checkout"),
    }


@pytest.fixture()
def sandbox(tmp_path):
    """An empty working folder and an empty TMPDIR, both checked to stay empty."""
    (tmp_path / "cwd").mkdir()
    (tmp_path / "tmp").mkdir()
    yield tmp_path
    assert listing(tmp_path / "cwd") == [] and listing(tmp_path / "tmp") == []


def test_verify_passes_on_an_unchanged_archive(archived, sandbox):
    before = listing(archived["checkout"])
    done = cli(
        "verify",
        archived["archive"],
        "--root",
        archived["checkout"],
        cwd=sandbox / "cwd",
        tmpdir=sandbox / "tmp",
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "OK: all" in done.stdout and "2 scenes" in done.stdout and "(quick build)" in done.stdout
    assert listing(archived["checkout"]) == before


def test_verify_fails_naming_the_number_when_a_scene_value_changes(archived, sandbox):
    checkout = checkout_copy(sandbox / "checkout")
    scene = checkout / "workflow/scenes/chains/two_masses_three_springs.yaml"
    scene.write_text(scene.read_text().replace("[1.0, 3.0, 1.0]", "[1.0, 3.5, 1.0]"))
    done = cli(
        "verify",
        archived["archive"],
        "--root",
        checkout,
        "--scenes",
        "chains/two_masses_three_springs",
        cwd=sandbox / "cwd",
        tmpdir=sandbox / "tmp",
    )
    assert done.returncode == 1, done.stdout + done.stderr
    assert "scene file changed since the archive" in done.stdout
    moved = [line for line in done.stdout.splitlines() if "frequencies_rad_per_s[1]" in line]
    assert (
        moved
        and "2.64575131106459" in moved[0]
        and "2.82842712474619" in moved[0]
        and "+6.904e-02" in moved[0]
    )
    assert "frequencies_rad_per_s[0]" not in done.stdout  # the first mode does not involve the middle spring
    shutil.rmtree(checkout)


def _rewrite(archive, target, change):
    """A copy of the archive with member data passed through change(name, data)."""
    buffer = io.BytesIO()
    with (
        tarfile.open(archive) as src,
        tarfile.open(fileobj=buffer, mode="w", format=tarfile.PAX_FORMAT) as out,
    ):
        for member in src.getmembers():
            data = change(member.name, src.extractfile(member).read())
            member.size = len(data)
            out.addfile(member, io.BytesIO(data))
    target.write_bytes(gzip.compress(buffer.getvalue(), mtime=0))


@pytest.mark.parametrize(
    "kind, message",
    [
        ("truncated", "truncated"),
        ("tampered", f"checksum mismatch for classical-dynamics-0.1.0/{CHANGED}"),
        ("foreign", "not a classical-dynamics archive"),
        ("not gzip", "not a readable tar.gz"),
    ],
)
def test_a_bad_archive_is_refused_in_one_line(archived, sandbox, kind, message):
    bad = sandbox / "bad" / ARCHIVE
    bad.parent.mkdir()
    if kind == "truncated":
        bad.write_bytes(archived["archive"].read_bytes()[:-2000])
    elif kind == "tampered":
        _rewrite(
            archived["archive"],
            bad,
            lambda name, data: (
                data.replace(b"2.64575131106459", b"2.6457513110646") if name.endswith(CHANGED) else data
            ),
        )
    elif kind == "foreign":
        with tarfile.open(bad, "w:gz") as tar:
            tar.add(archived["results"] / "chains", arcname="chains")
    else:
        bad.write_text("not an archive\n")
    done = cli("verify", bad, "--root", archived["checkout"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 2 and done.stdout == ""
    assert message in done.stderr and done.stderr.count("\n") == 1 and "Traceback" not in done.stderr
    assert listing(sandbox / "bad") == [ARCHIVE]


def _crate_changed(kind):
    """change(name, data) for _rewrite: the crate edited (`kind`), SHA256SUMS made to agree with the new
    crate, so that only the crate disagrees with the members."""
    state = {}

    def change(name, data):
        if name.endswith("/ro-crate-metadata.json"):
            crate = json.loads(data)
            entity = next(e for e in crate["@graph"] if e["@id"] == CHANGED)
            if kind == "sha256":
                entity["sha256"] = "0" * 64
            else:  # the File dropped from the crate
                crate["@graph"].remove(entity)
                for other in crate["@graph"]:
                    if isinstance(other.get("hasPart"), list):
                        other["hasPart"] = [p for p in other["hasPart"] if p != {"@id": CHANGED}]
            data = json.dumps(crate, indent=4).encode()
            state["digest"] = hashlib.sha256(data).hexdigest()
        elif name.endswith("/SHA256SUMS"):
            lines = data.decode().splitlines()
            data = "".join(
                f"{state['digest']}  ro-crate-metadata.json\n"
                if line.endswith("  ro-crate-metadata.json")
                else line + "\n"
                for line in lines
            ).encode()
        return data

    return change


def test_verify_reads_the_crate_and_refuses_one_that_disagrees_with_sha256sums(archived, sandbox):
    """The archive's RO-Crate, read back through rocrate, names every member with its SHA-256: a crate edited
    (its SHA256SUMS line made to match) is refused in one line, exit 2, before anything is rebuilt."""
    from rocrate.rocrate import ROCrate

    from classical_dynamics.verify import unpack_archive

    crate = ROCrate(unpack_archive(archived["archive"], sandbox / "tmp" / "into"))
    shutil.rmtree(sandbox / "tmp" / "into")
    assert crate.mainEntity.id == "Snakefile"
    (run,) = [e for e in crate.contextual_entities if e.id == "#run"]
    assert run["instrument"] is crate.mainEntity
    assert {e.id for e in run["result"]} >= {"report.html", "report.pdf", CHANGED}
    assert (
        crate.dereference(CHANGED)["sha256"]
        == hashlib.sha256((archived["results"] / CHANGED).read_bytes()).hexdigest()
    )
    for kind, message in (
        ("sha256", f"ro-crate-metadata.json disagrees with SHA256SUMS for {CHANGED}"),
        ("missing", f"{CHANGED} is not a File of the crate"),
    ):
        bad = sandbox / kind / ARCHIVE
        bad.parent.mkdir()
        _rewrite(archived["archive"], bad, _crate_changed(kind))
        done = cli("verify", bad, "--root", archived["checkout"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
        assert done.returncode == 2 and done.stdout == "", done.stdout + done.stderr
        assert message in done.stderr and done.stderr.count("\n") == 1 and "Traceback" not in done.stderr
        shutil.rmtree(bad.parent)


@pytest.mark.parametrize(
    "given, message",
    [
        ("missing.tar.gz", "no such file"),
        ("a-folder", "a folder, but not a results folder"),
        ("/dev/null", "not a regular file"),
    ],
)
def test_what_is_not_an_archive_gets_its_own_line(archived, sandbox, given, message):
    """A typo, a folder that holds no results, a device: each one accurate line, exit 2, nothing written."""
    (sandbox / "a-folder").mkdir()
    given = given if given.startswith("/") else sandbox / given
    done = cli("verify", given, "--root", archived["checkout"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 2 and done.stdout == ""
    assert message in done.stderr and done.stderr.count("\n") == 1 and "Traceback" not in done.stderr


def test_verify_takes_a_results_folder_checked_as_an_archive_is(archived, sandbox):
    """The folder itself, and an unpacked archive (its SHA256SUMS checked too); an edited file is refused by
    name, as in an archive, before anything is rebuilt."""
    done = cli(
        "verify",
        archived["results"],
        "--root",
        archived["checkout"],
        cwd=sandbox / "cwd",
        tmpdir=sandbox / "tmp",
    )
    assert done.returncode == 0 and "OK: all" in done.stdout, done.stdout + done.stderr
    unpacked = sandbox / "unpacked"
    with tarfile.open(archived["archive"]) as tar:
        tar.extractall(unpacked, filter="data")
    folder = unpacked / ARCHIVE.removesuffix(".tar.gz")
    (folder / "report.html").write_text("<html>edited</html>")  # listed in SHA256SUMS only
    done = cli("verify", folder, "--root", archived["checkout"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 2 and "checksum mismatch for" in done.stderr and "report.html" in done.stderr
    edited = sandbox / "edited"
    shutil.copytree(archived["results"], edited)
    (edited / CHANGED).write_text(
        (edited / CHANGED).read_text().replace("2.64575131106459", "2.6457513110646")
    )
    done = cli("verify", edited, "--root", archived["checkout"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 2 and done.stdout == "" and done.stderr.count("\n") == 1
    assert f"{edited / CHANGED}: does not match its checksum" in done.stderr
    shutil.rmtree(unpacked)
    shutil.rmtree(edited)


def test_diff_of_a_build_against_itself_is_empty(archived, sandbox):
    done = cli("diff", archived["results"], archived["results"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert (
        done.returncode == 0 and done.stdout.startswith("no numbers changed") and done.stdout.count("\n") == 1
    )
    done = cli("diff", archived["archive"], archived["results"], cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 0 and done.stdout.startswith("no numbers changed"), done.stdout + done.stderr


def test_diff_names_each_changed_number_with_its_relative_change(archived, sandbox):
    other = sandbox / "other"
    shutil.copytree(archived["results"], other)
    path = other / CHANGED
    summary = json.loads(path.read_text())
    summary["numbers"]["frequencies_rad_per_s"]["value"][1] *= 1.01
    del summary["numbers"]["n"]
    path.write_text(json.dumps(summary))
    done = cli("diff", archived["results"], other, cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 1, done.stdout + done.stderr
    rows = {line.split()[1]: line for line in done.stdout.splitlines()[1:-1]}
    assert set(rows) == {"frequencies_rad_per_s[1]", "n"}
    assert "+1.000e-02" in rows["frequencies_rad_per_s[1]"] and "removed" in rows["n"]


def test_diff_refuses_a_folder_that_is_not_results(archived, sandbox):
    done = cli("diff", archived["results"], sandbox / "cwd", cwd=sandbox / "cwd", tmpdir=sandbox / "tmp")
    assert done.returncode == 2 and done.stdout == ""
    assert "not a results folder" in done.stderr and done.stderr.count("\n") == 1


def test_tolerance_rule():
    def moved(old, new, **entry):
        return compare({("s", "c", "x"): {"value": old, **entry}}, {("s", "c", "x"): {"value": new, **entry}})

    assert not moved(1.0, 1.0 + 1e-12) and moved(1.0, 1.0 + 1e-8)  # floats: 1e-9 relative
    assert not moved(0.0, 1e-16) and moved(0.0, 1e-14)  # ... with a tiny floor at zero
    assert moved(3, 4) and moved(True, False) and moved("a", "b")  # exact otherwise
    assert not moved(1.0, 1.05, tolerance=0.1) and moved(1.0, 1.2, tolerance=0.1)  # bare: absolute
    assert not moved(100.0, 101.0, tolerance={"relative": 0.02}) and moved(
        100.0, 103.0, tolerance={"relative": 0.02}
    )
    assert [c.number for c in moved([1.0, 2.0, 3.0], [1.0, 2.5, 3.0])] == ["x[1]"]
    assert moved([1.0], [1.0, 2.0]) and not moved(None, None)  # a changed shape; NaN is stored as null


@pytest.mark.slow
@pytest.mark.pipeline
def test_the_snakemake_target_verifies_and_writes_only_its_log(archived, sandbox):
    from .conftest import snakemake

    repo = checkout_copy(sandbox / "repo")
    shutil.copy2(ROOT / "pyproject.toml", repo / "pyproject.toml")
    done = snakemake(repo, "-c", "1", "verify", "--config", f"archive={archived['archive']}")
    assert "OK: all" in done.stdout + done.stderr
    assert listing(repo / "results") == ["logs", "logs/verify.log"]
    shutil.rmtree(repo)
