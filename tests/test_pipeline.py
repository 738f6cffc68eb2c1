"""The pipeline end to end: real Snakemake runs on copies of this repository (quick=1)."""

import hashlib
import json
import re
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

import pytest
import yaml

from .conftest import copy_repository, run_env, snakemake

pytestmark = [pytest.mark.slow, pytest.mark.pipeline]

HANGING = ["hanging_continuum", "hanging_particles", "hanging_links", "hanging_time_domain"]


def tree_digest(folder):
    return {
        str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


def result_files(repo):
    """The deterministic results: everything under results/<study>/<scene>/ except provenance (and Snakemake's
    benchmark files, results/benchmarks/, which are timings)."""
    return {
        k: v
        for k, v in tree_digest(repo / "results").items()
        if re.match(r"^(?!benchmarks/)[a-z_]+/(?!timings/)[a-z0-9_]+/", k)
        and not k.endswith("provenance.json")
    }


def job_counts(dry_run_output):
    """{rule: count} from the 'Job stats' table of a dry run."""
    counts, in_table = {}, False
    for line in dry_run_output.splitlines():
        if line.startswith("job") and "count" in line:
            in_table = True
            continue
        if in_table:
            parts = line.split()
            if len(parts) == 2 and parts[1].isdigit():
                if parts[0] != "total":
                    counts[parts[0]] = int(parts[1])
            elif parts and not set(line.strip()) <= {"-", " "}:
                break
    return counts


# What a dry run wants after one scene is edited, added or cut short: that scene, the archive and the report.
ONE_SCENE_AND_THE_REPORT = {"scene": 1, "results_archive": 1, "report_html": 1, "report_pdf": 1, "all": 1}


def test_build_writes_the_results_contract(built_repo):
    results = built_repo / "results"
    assert (results / "report.html").stat().st_size > 10_000
    assert (results / "report.pdf").read_bytes()[:5] == b"%PDF-"
    scenes = sorted(p.stem for p in (built_repo / "workflow/scenes/chains").glob("*.yaml"))
    for scene in scenes:
        folder = results / "chains" / scene
        summary = json.loads((folder / "summary.json").read_text())
        provenance = json.loads((folder / "provenance.json").read_text())
        for entry in summary["numbers"].values():
            assert set(entry) >= {"value", "unit"}
        for name in summary["figures"]:
            assert (folder / f"{name}.svg").exists()
        for name in summary["tables"]:
            assert (folder / f"{name}.csv").exists()
        assert (results / "chains" / "timings" / scene / "run.csv").exists()
        for key in (
            "commit",
            "dirty",
            "packages",
            "machine",
            "scene_sha256",
            "started",
            "finished",
            "wall_seconds",
            "cpu_seconds",
            "effects_simulated",
        ):
            assert key in provenance
        assert provenance["effects_simulated"] == sorted(
            yaml.safe_load((built_repo / f"workflow/scenes/chains/{scene}.yaml").read_text())["effects"]
        )
    for scene in HANGING:
        numbers = json.loads((results / "chains" / scene / "summary.json").read_text())["numbers"]
        assert len(numbers["frequencies_sqrt_g_over_l"]["value"]) == 5
        assert len(numbers["relative_error_vs_continuum"]["value"]) == 5
        assert numbers["n"]["value"] == (
            0
            if scene == "hanging_continuum"
            else yaml.safe_load((built_repo / f"workflow/scenes/chains/{scene}.yaml").read_text())["chain"][
                "n"
            ]
        )


def test_every_hard_case_holds_in_the_quick_build(built_repo):
    """Each study's named hard cases (results' stability entries) hold in the quick build, scene by scene."""
    failing, count = [], 0
    for path in sorted((built_repo / "results").glob("*/*/summary.json")):
        for case in json.loads(path.read_text()).get("stability", []):
            count += 1
            if not case["holds"]:
                failing.append(
                    f"{path.parent.relative_to(built_repo)}: {case['name']} {case['measured']} > "
                    f"{case['bound']}"
                )
    assert count > 100 and not failing, failing


def test_nothing_to_do_after_a_build(built_repo):
    out = snakemake(built_repo, "-n", "--config", "quick=1")
    assert "Nothing to be done" in out.stdout + out.stderr


def test_another_environment_marks_nothing_stale(built_repo, tmp_path):
    """Jobs call `python3` by name: Snakemake run from another environment (same packages, another path, as on
    a cluster node or after moving the venv) finds nothing to do after the build."""
    other = tmp_path / "env"
    (other / "bin").mkdir(parents=True)
    (other / "pyvenv.cfg").write_text((Path(sys.prefix) / "pyvenv.cfg").read_text())
    (other / "lib").symlink_to(Path(sys.prefix) / "lib")
    (other / "bin" / "python3").symlink_to(Path(sys.executable).resolve())
    probe = subprocess.run(
        [other / "bin" / "python3", "-c", "import sys, snakemake; print(sys.prefix)"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert probe.stdout.strip() == str(other)
    out = subprocess.run(
        [other / "bin" / "python3", "-m", "snakemake", "-n", "--config", "quick=1"],
        cwd=built_repo,
        env=run_env(built_repo),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert "Nothing to be done" in out.stdout + out.stderr, out.stdout[-3000:] + out.stderr[-3000:]


def test_lint_reports_nothing(built_repo):
    out = snakemake(built_repo, "--lint", check=False)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "Lints for" not in out.stdout + out.stderr


def test_editing_one_scene_reruns_that_scene_and_the_report_only(scratch):
    scene = scratch / "workflow/scenes/chains/loaded_string.yaml"
    scene.write_text(scene.read_text().replace("newton: 1.0", "newton: 2.0"))
    out = snakemake(scratch, "-n", "--config", "quick=1")
    assert job_counts(out.stdout) == ONE_SCENE_AND_THE_REPORT
    assert "results/chains/loaded_string" in out.stdout
    # Built up to the HTML: the PDF renders the same HTML (29 s), checked by the shared build and the dist
    # test.
    snakemake(scratch, "-c", "2", "results/report.html", "--config", "quick=1")
    summary = json.loads((scratch / "results/chains/loaded_string/summary.json").read_text())
    # frequencies scale as sqrt(P)
    assert summary["numbers"]["frequencies_rad_per_s"]["value"][0] == pytest.approx(
        2**0.5 * 2.985221, rel=1e-5
    )


def test_an_edit_to_what_the_archives_pack_from_the_checkout_rebuilds_them(scratch):
    """The archives carry the Snakefile, configuration, licence, citation and lock for their RO-Crate: an edit
    to the licence reruns the archives and what prints the archive's checksum (the report), no scene."""
    licence = scratch / "LICENSE"
    licence.write_text(licence.read_text() + "\n")
    counts = job_counts(snakemake(scratch, "-n", "dist", "--config", "quick=1").stdout)
    assert counts == {"results_archive": 1, "report_html": 1, "report_pdf": 1, "dist": 1}


def test_a_new_scene_file_is_picked_up_with_no_rule_edit(scratch):
    source = scratch / "workflow/scenes/chains/loaded_string.yaml"
    (scratch / "workflow/scenes/chains/short_string.yaml").write_text(
        source.read_text().replace("n: 10", "n: 4").replace("modes: 10", "modes: 4")
    )
    out = snakemake(scratch, "-n", "--config", "quick=1")
    assert "results/chains/short_string" in out.stdout
    snakemake(scratch, "-c", "2", "results/report.html", "--config", "quick=1")
    assert "short_string" in (scratch / "results/report.html").read_text()


# A study of its own, written as the README says: a study package (code, schema, chapter, claims), a scenes
# folder, one line in the registry.
PENDULUM = {
    "__init__.py": '''"""A throwaway study: the small oscillations of a simple pendulum."""
import math

from ...scenes.cost import Work
from ...scenes.effects import EffectRegistry
from ...results import Results

EFFECTS = EffectRegistry("pendulum")


@EFFECTS.register("gravity", "force", "uniform gravity")
def gravity(params, context):
    return params["g_m_per_s2"]


def check(path, data):
    pass


def cost(data):
    return [Work("pendulum", 0.01)]


def run(scene, quick):
    g = EFFECTS.assemble(scene.data["effects"], None)["gravity"]
    results = Results("pendulum", scene.name, scene.data["title"])
    results.number("period_s", 2 * math.pi * math.sqrt(scene.data["pendulum"]["length_m"] / g), "s")
    return results
''',
    "schema.yaml": """\
$schema: "https://json-schema.org/draft/2020-12/schema"
type: object
additionalProperties: false
required: [title, pendulum, effects]
properties:
  title: {type: string, minLength: 1, maxLength: 200}
  pendulum:
    type: object
    additionalProperties: false
    required: [length_m]
    properties:
      length_m: {type: number, minimum: 1.0e-3, maximum: 1.0e+3}
  effects:
    type: object
    additionalProperties: false
    required: [gravity]
    properties:
      gravity:
        type: object
        additionalProperties: false
        required: [g_m_per_s2]
        properties:
          g_m_per_s2: {type: number, minimum: 0.1, maximum: 100}
""",
    "chapter.html.j2": """\
<section id="pendulum" class="chapter">
<h2>{{ study_title("pendulum") }}</h2>
<p>A pendulum of one metre swings with a period of {{ num("pendulum/one_metre", "period_s") }}.</p>
{{ m.claims_table("pendulum", "tab:pendulum-claims") }}
</section>
""",
    "claims.yaml": """\
- id: seconds_pendulum
  statement: 'Period of a pendulum one metre long'
  kind: statement
  source: {value: 2.006, text: "2.006", cite: lamb1920, where: "a test"}
  computed: {scene: one_metre, number: period_s}
  unit: s
  check: {absolute: 5.0e-4}
  must_hold: true
""",
}


def test_a_new_study_is_one_package_one_scenes_folder_and_one_registry_line(scratch):
    package = scratch / "src/classical_dynamics/studies/pendulum"
    package.mkdir()
    for name, text in PENDULUM.items():
        (package / name).write_text(text)
    (scratch / "workflow/scenes/pendulum").mkdir()
    (scratch / "workflow/scenes/pendulum/one_metre.yaml").write_text(
        "title: One metre\npendulum: {length_m: 1.0}\neffects: {gravity: {g_m_per_s2: 9.81}}\n"
    )
    registry = scratch / "src/classical_dynamics/studies/registry.yaml"
    text = registry.read_text()
    line = "precession: Precession of the equinoxes\n"
    assert line in text
    # chapter 1
    registry.write_text(text.replace(line, "pendulum: The simple pendulum\n" + line))

    out = snakemake(scratch, "-n", "--config", "quick=1")
    assert job_counts(out.stdout) == ONE_SCENE_AND_THE_REPORT
    assert "results/pendulum/one_metre" in snakemake(scratch, "-n", "pendulum", "--config", "quick=1").stdout
    snakemake(scratch, "-c", "2", "results/report.html", "--config", "quick=1")
    summary = json.loads((scratch / "results/pendulum/one_metre/summary.json").read_text())
    assert summary["numbers"]["period_s"]["value"] == pytest.approx(2 * 3.141592653589793 * (1 / 9.81) ** 0.5)
    page = (scratch / "results/report.html").read_text()
    chapters = [
        c for c in re.findall(r'<section id="([a-z_]+)" class="chapter"', page) if c != "introduction"
    ]
    assert chapters == ["pendulum", "precession", "chandler", "chains", "self_excited", "solvers"]
    assert "The simple pendulum" in page and "Period of a pendulum one metre long" in page
    assert "pendulum" in snakemake(scratch, "--list-rules").stdout.split()


@pytest.mark.parametrize(
    "text,field",
    [
        (
            "title: x\nchain: {model: particles, n: 3, length_m: -1, mass_kg: 1}\neffects: {gravity: "
            "{g_m_per_s2: 9.8}}\n",
            "chain.length_m",
        ),
        (
            "title: x\nchain: {model: particles, n: 3, length_m: 1, mass_kg: 1}\neffects: {magic: {}}\n",
            "effects.magic",
        ),
        ("title: [unclosed\n", "YAML at line"),
        (
            "title: x\nobservation: {series: eopc04, start_year: 1962, end_year: 2100, window_years: 6.4, "
            "step_years: 1,"
            " compare: {H: 0.00327, k2: 0.3}}\n",
            "observation.end_year",
        ),
        (
            "title: x\nearth: {H: 0.00327, H_definition: (C-A)/C, H_source: s}\n"
            "effects: {elastic_yielding: {k2: 0.3, source: s}, dissipation: {Q: -1, source: s}}\n",
            "effects.dissipation.Q",
        ),
        (
            "title: x\nfidelity: full\nconstants: modern\nearth: {H: 0.00327, H_definition: (C-A)/C, "
            "H_source: s,"
            " obliquity_deg: 23.4, obliquity_source: s}\neffects: {solar_torque: }\nanalysis: {span_years: "
            "10}\n",
            "analysis.step_hours",
        ),
        (
            "title: x\nbody: {moments: [4.0, 2.5, 1.0]}\ntorque_axis: largest\nplane: {delta: 1}\n"
            "effects: {body_torque: {m1: 0.5}}\n",
            "body.moments",
        ),
    ],
)
def test_a_bad_scene_stops_the_build_and_touches_nothing(scratch, text, field):
    before = tree_digest(scratch / "results")
    study = (
        "precession"
        if "fidelity" in text
        else "self_excited"
        if "torque_axis" in text
        else "chandler"
        if "observation" in text or "earth" in text
        else "chains"
    )
    (scratch / f"workflow/scenes/{study}/broken.yaml").write_text(text)
    out = snakemake(scratch, "-c", "2", "--config", "quick=1", check=False)
    assert out.returncode != 0
    lines = [line for line in (out.stdout + out.stderr).splitlines() if "broken.yaml" in line]
    assert len(lines) == 1 and field in lines[0]
    assert tree_digest(scratch / "results") == before
    snakemake(scratch, "--unlock")  # runs no job: the bad scene does not stand in its way
    other = snakemake(
        scratch, "-n", "solvers", "results/precession/lamb_1920" if study != "precession" else "chains"
    )
    assert (
        "note: not needed by this command, and not valid either: " in other.stderr and field in other.stderr
    )


def test_a_failing_must_hold_claim_fails_the_build_naming_it(scratch):
    claims = scratch / "src/classical_dynamics/studies/chains/claims.yaml"
    text = claims.read_text()
    block = re.search(r"- id: lamb_gravest_period\n.*?(?=\n- id:)", text, re.S).group(0)
    assert "check: {absolute: 5.0e-4}" in block
    claims.write_text(
        text.replace(block, block.replace("check: {absolute: 5.0e-4}", "check: {absolute: 1.0e-9}"))
    )
    good = {name: (scratch / "results" / name).read_bytes() for name in ("report.html", "report.pdf")}
    out = snakemake(scratch, "-c", "1", "--config", "quick=1", check=False)
    assert out.returncode != 0
    assert "claim 'lamb_gravest_period'" in out.stdout + out.stderr
    assert "Traceback" not in out.stdout + out.stderr  # the claim is named, no traceback
    # the last good report is kept (Snakemake restores an update() output when its job fails); no leftovers
    assert {name: (scratch / "results" / name).read_bytes() for name in good} == good
    assert not list((scratch / "results").glob(".report*"))


def test_two_clean_builds_give_identical_results(built_repo, tmp_path):
    other = copy_repository(tmp_path / "again")
    snakemake(
        other,
        "-c",
        "2",
        "results/chains/hanging_particles",
        "results/chains/hanging_continuum",
        "results/chains/hanging_time_domain",
        "results/chains/spring_chain",
        "results/chandler/excited",
        "results/chandler/observed",
        "results/chandler/triaxial",
        "results/precession/lamb_1920",
        "results/precession/full_sun",
        "results/precession/averaged_cycle",
        "results/self_excited/largest_perturbed_cycles",
        "--config",
        "quick=1",
    )
    mine = {k: v for k, v in result_files(built_repo).items() if k in result_files(other)}
    assert len(mine) > 10
    assert mine == result_files(other)


def test_dist_archive_with_checksums(scratch):
    snakemake(scratch, "-c", "1", "dist", "--config", "quick=1")
    archives = [
        a
        for a in (scratch / "results/dist").glob("classical-dynamics-*.tar.gz")
        if not a.name.endswith("-results.tar.gz")
    ]
    assert len(archives) == 1
    with tarfile.open(archives[0]) as tar:
        names = tar.getnames()
        prefix = names[0].split("/")[0]
        sums = tar.extractfile(f"{prefix}/SHA256SUMS").read().decode().splitlines()
        assert f"{prefix}/report.pdf" in names and f"{prefix}/report.html" in names
        assert any(n.endswith("chains/hanging_particles/summary.json") for n in names)
        for line in sums:
            digest, name = line.split("  ")
            assert hashlib.sha256(tar.extractfile(f"{prefix}/{name}").read()).hexdigest() == digest
        assert len(sums) == len(names) - 1  # every member but the manifest itself
        tar.extractall(scratch / "unpacked", filter="data")
    # Each manifest checks where it lies, with the standard tool: the archive beside it, the members unpacked.
    for folder in (scratch / "results/dist", scratch / "unpacked" / prefix):
        check = subprocess.run(
            ["sha256sum", "--check", "--strict", "SHA256SUMS"], cwd=folder, capture_output=True, text=True
        )
        assert check.returncode == 0, check.stdout[-500:] + check.stderr[-500:]
    outer = (scratch / "results/dist/SHA256SUMS").read_text().splitlines()
    assert outer == [f"{hashlib.sha256(archives[0].read_bytes()).hexdigest()}  {archives[0].name}"]
    # Packed again from the same results: the same archive, byte for byte (no pack-time stamp).
    first = hashlib.sha256(archives[0].read_bytes()).hexdigest()
    snakemake(scratch, "-c", "1", "dist", "--forcerun", "dist", "--config", "quick=1")
    assert hashlib.sha256(archives[0].read_bytes()).hexdigest() == first
    # The HTML rendered again here, by the report job's own command: the shared build rendered it in another
    # folder, and its bytes must not depend on where it ran (the PDF's: test_report_units, on a small page,
    # rather than a second render of this one).
    again = scratch / "again.html"
    subprocess.run(
        [
            sys.executable,
            "-m",
            "classical_dynamics.report.build",
            "results",
            str(again),
            "--root",
            ".",
            "--quick",
        ],
        cwd=scratch,
        env=run_env(scratch),
        check=True,
        capture_output=True,
    )
    assert again.read_bytes() == (scratch / "results/report.html").read_bytes()


# The RO-Crate 1.1 JSON-LD context, which roc-validator downloads (and caches) before it reads a crate: this
# machine reaches no such host, so the test serves it from the cache. It is rocrate's own copy of the 1.3
# context (a superset) with the terms 1.1 maps otherwise: those of the RO-Crate repository's
# docs/_specification/1.1/context.jsonld (CC0), compared term by term.
RO_CRATE_11_CONTEXT = "https://w3id.org/ro/crate/1.1/context"
TERMS_OF_1_1 = {
    "ComputationalWorkflow": "https://bioschemas.org/ComputationalWorkflow",
    "FormalParameter": "https://bioschemas.org/FormalParameter",
    "input": "https://bioschemas.org/ComputationalWorkflow#input",
    "output": "https://bioschemas.org/ComputationalWorkflow#output",
    "cite-as": "https://www.w3.org/ns/iana/link-relations/relation#cite-as",
    "AuthenticContent": "http://schema.org/AuthenticContent",
    "MissingContext": "http://schema.org/MissingContext",
    "constrainingProperty": "http://schema.org/constrainingProperty",
    "measuredValue": "http://schema.org/measuredValue",
    "observedNode": "http://schema.org/observedNode",
}


def offline_validator_cache(cache: Path) -> Path:
    """A roc-validator HTTP cache (requests-cache, SQLite) holding the RO-Crate 1.1 context, for --offline."""
    import io
    from importlib import resources

    import urllib3
    from requests.adapters import HTTPAdapter
    from requests_cache import CachedSession

    document = json.loads(resources.files("rocrate").joinpath("data/ro-crate.jsonld").read_text())
    document["@id"] = RO_CRATE_11_CONTEXT
    document["@context"].update(TERMS_OF_1_1)
    body = json.dumps(document).encode()

    class Serve(HTTPAdapter):
        def send(self, request, **kwargs):
            raw = urllib3.HTTPResponse(
                body=io.BytesIO(body),
                headers={"Content-Type": "application/ld+json"},
                status=200,
                preload_content=False,
                request_url=request.url,
            )
            return self.build_response(request, raw)

    with CachedSession(cache_name=str(cache), backend="sqlite", allowable_methods=("GET",)) as session:
        session.mount("https://", Serve())
        session.get(RO_CRATE_11_CONTEXT, headers={"Accept": "application/ld+json, application/json"})
    return cache


def test_the_dist_archive_carries_a_workflow_run_crate_that_validates(scratch, tmp_path):
    """Issue 36, item 2: the dist archive's ro-crate-metadata.json, made with rocrate, validates with
    roc-validator (offline) against the Workflow Run Crate and Provenance Run Crate profiles 0.5 at their
    required level, and describes the run: the Snakefile the mainEntity, one CreateAction of the workflow
    with the configuration and each scene as objects and every result (with its SHA-256) and the report as
    results, one CreateAction per scene job, the software of the lock, the license and the citation."""
    from rocrate.rocrate import ROCrate
    from rocrate_validator import services
    from rocrate_validator.models import Severity, ValidationSettings

    snakemake(scratch, "-c", "1", "dist", "--config", "quick=1")
    (archive,) = (scratch / "results/dist").glob("classical-dynamics-*[0-9].tar.gz")
    with tarfile.open(archive) as tar:
        tar.extractall(tmp_path / "unpacked", filter="data")
    (folder,) = (tmp_path / "unpacked").iterdir()
    cache = offline_validator_cache(tmp_path / "validator-cache")
    for profile in ("workflow-run-crate-0.5", "provenance-run-crate-0.5"):
        settings = ValidationSettings(
            rocrate_uri=str(folder),
            profile_identifier=profile,
            requirement_severity=Severity.REQUIRED,
            offline=True,
            cache_path=str(cache),
        )
        result = services.validate(settings)
        issues = [f"{i.check.identifier}: {i.message}" for i in result.get_issues()]
        assert result.passed() and not issues, f"{profile}: {issues}"

    crate = ROCrate(folder)
    assert crate.mainEntity.id == "Snakefile" and crate.mainEntity.lang.id.endswith("#snakemake")
    sums = dict(reversed(line.split("  ", 1)) for line in (folder / "SHA256SUMS").read_text().splitlines())
    files = {e.id: e for e in crate.data_entities if "File" in e.type}
    assert sorted(files) == sorted(set(sums) - {"ro-crate-metadata.json"})
    assert all(files[name]["sha256"] == digest for name, digest in sums.items() if name in files)
    actions = [e for e in crate.contextual_entities if e.type == "CreateAction"]
    (run,) = [a for a in actions if a["instrument"] is crate.mainEntity]
    scenes = {p.parent.relative_to(folder).as_posix() for p in folder.glob("*/*/provenance.json")}
    objects = {e.id for e in run["object"]}
    assert "workflow/config.yaml" in objects and "#pv-quick" in objects
    assert {f"{s}/scene.yaml" for s in scenes if (folder / s / "scene.yaml").is_file()} <= objects
    results = {e.id for e in run["result"]}
    assert {"report.html", "report.pdf", "chains/hanging_particles/summary.json"} <= results
    assert len(actions) == 1 + len(scenes)  # the run, and one per scene job (Provenance Run Crate)
    assert run["startTime"] <= run["endTime"] == crate.root_dataset["datePublished"]
    software = {
        e["name"]: e["softwareVersion"]
        for e in crate.contextual_entities
        if e.type == "SoftwareApplication" and "softwareVersion" in e
    }
    lock = (scratch / "requirements/pipeline.lock").read_text()
    assert software["rocrate"] == re.search(r"^rocrate==(\S+)", lock, re.M).group(1)
    assert software["snakemake"] == re.search(r"^snakemake==(\S+)", lock, re.M).group(1)
    assert crate.root_dataset["license"].id == "https://spdx.org/licenses/MIT"
    assert crate.root_dataset["citation"].id == "CITATION.cff" and "LICENSE" in files


def test_the_report_prints_the_sha256_of_the_results_archive(built_repo):
    """The archive of every result but the report is made first; the report and its BibTeX name its
    checksum."""
    (archive,) = (built_repo / "results/dist").glob("classical-dynamics-*-results.tar.gz")
    digest = hashlib.sha256(archive.read_bytes()).hexdigest()
    page = (built_repo / "results/report.html").read_text()
    assert page.count(digest) >= 2  # the how-to-cite text and the BibTeX note
    with tarfile.open(archive) as tar:
        names = tar.getnames()
    assert not any(n.endswith(("report.html", "report.pdf")) for n in names)
    assert any(n.endswith("chains/hanging_particles/summary.json") for n in names)


def test_a_checkout_path_with_a_space_runs(tmp_path):
    """make puts .venv inside the checkout, so the interpreter's path carries the checkout's space: every
    shell rule quotes its paths. A venv in the spaced folder, seeing this environment's packages through a
    .pth file."""
    import site
    import sys

    repo = copy_repository(tmp_path / "my checkout")
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(repo / ".venv")], check=True)
    (venv_site,) = (repo / ".venv/lib").glob("python3*/site-packages")
    (venv_site / "parent.pth").write_text("\n".join(site.getsitepackages()) + "\n")
    done = subprocess.run(
        [
            str(repo / ".venv/bin/python"),
            "-m",
            "snakemake",
            "-c",
            "1",
            "results/chains/two_masses_three_springs",
            "--config",
            "quick=1",
        ],
        cwd=repo,
        env=run_env(repo),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    summary = json.loads((repo / "results/chains/two_masses_three_springs/summary.json").read_text())
    assert summary["numbers"]


def test_the_workflow_runs_from_another_directory(tmp_path):
    """snakemake -s <checkout>/Snakefile -d <elsewhere>: results/ and .snakemake/ are made there,
    everything else is read beside the Snakefile and from the package; the checkout gets nothing."""
    repo, elsewhere = copy_repository(tmp_path / "checkout"), tmp_path / "elsewhere"
    (tmp_path / "cwd").mkdir()
    command = [
        str(Path(sys.executable).parent / "snakemake"),
        "-s",
        str(repo / "Snakefile"),
        "-d",
        str(elsewhere),
        "--config",
        "quick=1",
    ]
    scene = "results/chains/two_masses_three_springs"
    done = subprocess.run(
        command + ["-c", "1", scene],
        cwd=tmp_path / "cwd",
        env=run_env(repo),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    provenance = json.loads((elsewhere / scene / "provenance.json").read_text())
    assert (
        elsewhere / provenance["scene_file"]
    ).resolve() == repo / "workflow/scenes/chains/two_masses_three_springs.yaml"
    assert not (repo / "results").exists() and not (repo / ".snakemake").exists()
    assert not any((tmp_path / "cwd").iterdir())
    plan = subprocess.run(
        command + ["-n"], cwd=tmp_path / "cwd", env=run_env(repo), capture_output=True, text=True, timeout=300
    )
    assert plan.returncode == 0, plan.stderr[-2000:]
    counts = job_counts(plan.stdout)
    assert counts["report_html"] == counts["report_pdf"] == 1
    # all but the one built
    assert counts["scene"] == len(list((repo / "workflow/scenes").glob("*/*.yaml"))) - 1


def test_a_cut_short_result_is_refused_by_the_report_and_rerun_by_the_pipeline(scratch):
    """A truncated summary.json: the report names it in one line; a dry run lists that scene (and what follows
    from it) and nothing else; a kill's staging folder is read by nobody; the rerun restores the same
    bytes."""
    summary = scratch / "results/chains/loaded_string/summary.json"
    whole = summary.read_bytes()
    summary.write_bytes(whole[: len(whole) // 2])
    staging = scratch / "results/chains/.loaded_string.k1ll3d"
    staging.mkdir()
    (staging / "summary.json").write_text("{")
    done = subprocess.run(
        [sys.executable, "-m", "classical_dynamics", "report", "results", "/dev/null", "--quick"],
        cwd=scratch,
        env=run_env(scratch),
        capture_output=True,
        text=True,
    )
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert done.stderr.strip() == (
        "results/chains/loaded_string/summary.json: does not match its checksum in "
        "provenance.json (truncated or edited); rebuild the scene"
    )
    out = snakemake(scratch, "-n", "--config", "quick=1")
    assert job_counts(out.stdout) == ONE_SCENE_AND_THE_REPORT
    assert "results/chains/loaded_string" in out.stdout
    snakemake(scratch, "-c", "2", "results/report.html", "--config", "quick=1")
    assert summary.read_bytes() == whole
    with tarfile.open(next((scratch / "results/dist").glob("*-results.tar.gz"))) as tar:
        assert not any(".loaded_string.k1ll3d" in name for name in tar.getnames())


@pytest.mark.parametrize("signal_name", ["SIGINT", "SIGKILL"])
def test_a_build_killed_mid_job_resumes_to_the_same_results(scratch, signal_name):
    """Kill a real build while a scene runs; the README's recovery (rerun; --unlock first after kill -9) gives
    the same results files as the uninterrupted build."""
    import os
    import signal
    import time

    target = scratch / "results/chains/hanging_links"

    def contents():  # provenance.json also records when and how long: compare the checksums it records
        files = {p.relative_to(target): p.read_bytes() for p in target.rglob("*") if p.is_file()}
        files[Path("provenance.json")] = json.loads(files[Path("provenance.json")])["files"]
        return files

    before = contents()
    log = scratch / "results/logs/chains/hanging_links.log"
    command = [
        str(Path(sys.executable).parent / "snakemake"),
        "-c",
        "1",
        "results/chains/hanging_links",
        "--config",
        "quick=1",
    ]

    def job_running(build):  # the scene's job command in the build's session (its client, or the job itself)
        for stat in Path("/proc").glob("[0-9]*/stat"):
            try:
                session = int(stat.read_text().rsplit(")", 1)[1].split()[3])
                cmdline = (stat.parent / "cmdline").read_bytes()
            except (OSError, ValueError, IndexError):
                continue
            if session == build.pid and b"hanging_links" in cmdline and b"snakemake" not in cmdline:
                return True
        return False

    # The kill must hit the job mid-run. The build is frozen (SIGSTOP) the moment its job is seen, so that the
    # check and the kill see one state: the job there, its result not yet written. A job so quick that it ends
    # between being seen and being frozen is tried again (the scene takes about half a second).
    for attempt in range(5):
        shutil.rmtree(target, ignore_errors=True)
        log.unlink(missing_ok=True)
        build = subprocess.Popen(
            command,
            cwd=scratch,
            env=run_env(scratch),
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            start_new_session=True,
        )
        deadline = time.monotonic() + 120
        while not (log.exists() and job_running(build)) and time.monotonic() < deadline:
            time.sleep(0.01)
        os.killpg(build.pid, signal.SIGSTOP)
        mid_run = job_running(build) and not (target / "summary.json").exists()
        if mid_run:
            os.killpg(build.pid, getattr(signal, signal_name))
        try:
            os.killpg(build.pid, signal.SIGCONT)
        except ProcessLookupError:  # SIGKILL left no one to continue
            pass
        build.wait(timeout=60)
        if mid_run:
            break
    assert mid_run, "the scene's job was never caught mid-run in 5 tries"
    if signal_name == "SIGKILL":
        snakemake(scratch, "--unlock")
    snakemake(scratch, "-c", "1", "results/chains/hanging_links", "--config", "quick=1")
    assert contents() == before
