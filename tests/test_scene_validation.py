"""Bad scenes stop before any computation: one line naming file, field and expectation; nothing written."""

import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from classical_dynamics.models.chains import EFFECTS, particle_chain
from classical_dynamics.scenes import SceneError
from classical_dynamics.scenes.cost import Budget
from classical_dynamics.studies import load_schema, validate

from .conftest import ROOT, SCHEMA

GOOD = {
    "title": "ten particles",
    "chain": {"model": "particles", "n": 10, "ends": "fixed-free", "length_m": 1.0, "mass_kg": 1.0},
    "effects": {"gravity": {"g_m_per_s2": 9.81}},
}


def write(tmp_path, data, name="scene.yaml"):
    path = tmp_path / name
    path.write_text(data if isinstance(data, str) else yaml.safe_dump(data))
    return path


def edited(**changes):
    data = yaml.safe_load(yaml.safe_dump(GOOD))
    for dotted, value in changes.items():
        *parents, last = dotted.split("__")
        target = data
        for p in parents:
            target = target[p]
        if value is KeyError:
            del target[last]
        else:
            target[last] = value
    return data


BAD = [
    ("unknown key", edited(colour="red"), "colour", "no such key"),
    ("unknown nested key", edited(chain__lenght_m=1.0), "chain.lenght_m", "no such key"),
    ("wrong type", edited(chain__n="ten"), "chain.n", "expected an integer"),
    ("negative length", edited(chain__length_m=-1.0), "chain.length_m", "expected a number >= 1e-06"),
    ("negative mass", edited(chain__mass_kg=-2.0), "chain.mass_kg", "expected a number >= 1e-09"),
    ("zero particles", edited(chain__n=0), "chain.n", "expected a number >= 1"),
    (
        "unknown effect",
        edited(effects={"magnetism": {}}),
        "effects.magnetism",
        "known effect: forcing, friction, gravity, rotation, springs, tension",
    ),
    (
        "negative gravity",
        edited(effects={"gravity": {"g_m_per_s2": -9.81}}),
        "effects.gravity.g_m_per_s2",
        "> 0",
    ),
    ("missing title", edited(title=KeyError), "title", "required"),
    ("no effects", edited(effects={}), "effects", "at least 1"),
    ("gravity on a string", edited(chain__ends="fixed-fixed"), "chain.ends", "fixed-free"),
    ("masses list of wrong length", edited(chain__masses_kg=[1.0, 2.0]), "chain.masses_kg", "n = 10"),
    ("continuum with n", edited(chain__model="continuum"), "chain.n", "no n for a continuum"),
    ("not finite", edited(chain__length_m=float("nan")), "chain.length_m", "a finite number"),
    (
        "a response without a force",
        edited(
            analysis={
                "forced": {
                    "sigma_max_over_lowest": 3,
                    "points": 101,
                    "transient_detuning": 1e-6,
                    "transient_periods": 5,
                }
            }
        ),
        "analysis.forced",
        "the effect forcing",
    ),
    (
        "only a force, nothing restoring",
        edited(effects={"forcing": {"newton": 1.0}}),
        "effects",
        "a restoring effect",
    ),
    (
        "a dashpot list of wrong length",
        edited(effects={"gravity": {"g_m_per_s2": 9.81}, "friction": {"b_kg_per_s": [1.0, 2.0]}}),
        "effects.friction.b_kg_per_s",
        "one value per particle, 10",
    ),
]


@pytest.mark.parametrize("case,data,field,expected", BAD, ids=[b[0] for b in BAD])
def test_bad_scene_gives_one_line_naming_file_and_field(tmp_path, case, data, field, expected):
    path = write(tmp_path, data)
    with pytest.raises(SceneError) as error:
        validate("chains", path)
    message = str(error.value)
    assert "\n" not in message
    assert message.startswith(f"{path}: field '{field}'")
    assert expected in message


def test_broken_yaml(tmp_path):
    path = write(tmp_path, "title: x\nchain: {model: particles, n: 3\n")
    with pytest.raises(SceneError) as error:
        validate("chains", path)
    assert (
        "\n" not in str(error.value) and "YAML at line" in str(error.value) and str(path) in str(error.value)
    )


def test_duplicate_key_is_refused(tmp_path):
    path = write(
        tmp_path,
        "title: a\ntitle: b\nchain: {model: continuum, length_m: 1}\neffects: {gravity: {g_m_per_s2: 9.8}}\n",
    )
    with pytest.raises(SceneError, match="given twice"):
        validate("chains", path)


def test_yaml_tags_are_not_code(tmp_path):
    path = write(tmp_path, "title: !!python/object/apply:os.system ['echo hacked']\n")
    with pytest.raises(SceneError, match="valid YAML"):
        validate("chains", path)


@pytest.mark.parametrize("name", ["Bad-Name.yaml", "timings.yaml", "x.yml"])
def test_scene_names_are_restricted(tmp_path, name):
    path = write(tmp_path, GOOD, name)
    with pytest.raises(SceneError, match="file name"):
        validate("chains", path)


def test_shipped_scenes_are_valid():
    scenes = sorted((ROOT / "workflow" / "scenes" / "chains").glob("*.yaml"))
    assert len(scenes) >= 8
    for path in scenes:
        validate("chains", path)


def test_schema_and_registry_name_the_same_effects():
    schema = load_schema(SCHEMA)
    assert sorted(schema["properties"]["effects"]["properties"]) == EFFECTS.names()


def test_cli_run_refuses_a_bad_scene_and_creates_nothing(tmp_path):
    path = write(tmp_path, edited(chain__length_m=-1.0))
    out, timings = (
        tmp_path / "results" / "chains" / "scene",
        tmp_path / "results" / "chains" / "timings" / "scene",
    )
    result = subprocess.run(
        [sys.executable, "-m", "classical_dynamics", "run", "chains", str(path), str(out), str(timings)],
        capture_output=True,
        text=True,
    )
    assert result.returncode != 0
    assert result.stderr.strip().count("\n") == 0
    assert "field 'chain.length_m'" in result.stderr
    assert not (tmp_path / "results").exists()


def test_only_listed_effects_are_evaluated(monkeypatch):
    called = []
    for name in EFFECTS.names():
        effect = EFFECTS[name]
        monkeypatch.setitem(
            EFFECTS._effects,
            name,
            effect.__class__(
                effect.name,
                effect.kind,
                effect.summary,
                lambda params, geometry, _build=effect.build, _name=name: (
                    called.append(_name) or _build(params, geometry)
                ),
            ),
        )
    chain = particle_chain(5, "fixed-fixed", 1.0, 0.2, {"tension": {"newton": 2.0}})
    assert called == ["tension"]
    assert set(chain.contributions) == {"tension"}


# Hostile or accidental files: refused in one line before parsing runs away (issue 19).
BOMB = "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]\n" for i in range(8)
)


@pytest.mark.parametrize(
    "case,text,field,expected",
    [
        ("alias bomb", BOMB, "(YAML at line 2", "an alias (*a)"),
        ("one alias", yaml.safe_dump(GOOD) + "extra: &x 1\nagain: *x\n", "(YAML at", "an alias (*x)"),
        ("deep nesting", "title: " + "[" * 20000 + "]" * 20000 + "\n", "(YAML at", "nesting deeper than"),
        ("oversized", "title: x\n" + "# padding\n" * 120_000, "(file)", "at most 1000 kB"),
        ("not UTF-8", b"title: \xff\xfe\n", "(file)", "UTF-8 text"),
    ],
)
def test_hostile_scene_files_are_refused_in_one_line(tmp_path, case, text, field, expected):
    """(How fast: benchmarks/bad_input.py tallies it; no test reads the clock.)"""
    path = tmp_path / "scene.yaml"
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    with pytest.raises(SceneError) as error:
        validate("chains", path)
    message = str(error.value)
    assert "\n" not in message and message.startswith(f"{path}: field '{field}")
    assert expected in message


@pytest.mark.parametrize("kind", ["symlink", "fifo", "device"])
def test_a_scene_that_is_not_a_regular_file_is_refused_without_reading_it(tmp_path, kind):
    path = tmp_path / "scene.yaml"
    if kind == "symlink":
        (tmp_path / "elsewhere.yaml").write_text(yaml.safe_dump(GOOD))
        path.symlink_to(tmp_path / "elsewhere.yaml")
    elif kind == "fifo":
        os.mkfifo(path)  # reading it would block for ever
    else:
        path.symlink_to("/dev/zero")  # reading it would never end
    with pytest.raises(SceneError, match=r"field '\(file\)': expected a regular file"):
        validate("chains", path)


def test_a_physical_check_that_overflows_is_one_line(tmp_path):
    """alpha = (1e308, 1e308) passes the schema; its square overflows in the middle-axis check."""
    scene = (ROOT / "workflow/scenes/self_excited/middle_perturbed.yaml").read_text()
    path = tmp_path / "scene.yaml"
    path.write_text(scene.replace("alpha: [0.8, 0.3]", "alpha: [1.0e+308, 1.0e+308]"))
    with pytest.raises(SceneError) as error:
        validate("self_excited", path)
    assert "\n" not in str(error.value) and str(error.value).startswith(f"{path}: field '")


@pytest.mark.parametrize(
    "name,leftover",
    [
        (".loaded_string.yaml.swp", True),
        ("loaded_string.yaml~", True),
        ("#loaded_string.yaml#", True),
        (".hidden.yaml", True),
        ("loaded_string.yaml", False),
        ("loaded_string.yml", False),
    ],
)
def test_editor_leftovers_are_not_scenes(name, leftover):
    from classical_dynamics.scenes.loader import is_leftover

    assert is_leftover(Path(name)) is leftover


def test_validation_is_remembered_until_scene_schema_or_code_change(tmp_path):
    """Each parse of the Snakefile validates only what changed; a scene that fails is never remembered."""
    from classical_dynamics.scenes.validated import validate_all

    scenes_dir = tmp_path / "scenes"
    scenes_dir.mkdir()
    schema = tmp_path / "schema.yaml"
    schema.write_bytes(SCHEMA.read_bytes())
    a, b = write(scenes_dir, GOOD, "a.yaml"), write(scenes_dir, GOOD, "b.yaml")
    record, seen = tmp_path / "record.json", []

    def counting(study, scene, budget):
        seen.append(Path(scene).name)
        return validate(study, scene, budget)

    def run(budget=Budget()):
        seen.clear()
        validate_all([("chains", a, schema), ("chains", b, schema)], counting, record, budget)
        return sorted(seen)

    assert run() == ["a.yaml", "b.yaml"]
    assert run() == []  # nothing changed: nothing validated
    b.write_text(b.read_text() + "# a comment\n")
    assert run() == ["b.yaml"]
    schema.write_text(schema.read_text() + "\n")
    assert run() == ["a.yaml", "b.yaml"]
    assert run(Budget(seconds=1e4)) == ["a.yaml", "b.yaml"]  # a new budget: every scene costed again
    a.write_text(yaml.safe_dump(edited(**{"chain.n": 0})))
    for _ in range(2):  # refused every time, not remembered
        with pytest.raises(SceneError):
            run()


def test_a_bad_scene_stops_only_the_commands_that_need_it():
    """`snakemake chains` does not need a precession scene; the report, dist and a bare `snakemake` need
    all."""
    from classical_dynamics.scenes.targets import needed_scenes

    class Job:
        rulename, wildcards_dict = "scene", {"study": "chains", "scene": "loaded_string"}

    scenes = {"chains": {"loaded_string", "spring_chain"}, "precession": {"lamb_1920"}}
    assert needed_scenes([], [], scenes)("precession", "lamb_1920")
    for targets in (["report"], ["dist"], ["results/report.pdf"], ["chains", "all"]):
        assert needed_scenes(targets, [], scenes)("precession", "lamb_1920"), targets
    for targets, jobs in (
        (["chains"], []),
        (["results/chains/loaded_string"], []),
        (["results/chains/timings/loaded_string/run.csv"], []),
        (["results/logs/chains/loaded_string.log"], []),
        ([], [Job()]),
    ):
        needed = needed_scenes(targets, jobs, scenes)
        assert needed("chains", "loaded_string") and not needed("precession", "lamb_1920"), targets
    assert not needed_scenes(["results/chains/loaded_string"], [], scenes)("chains", "spring_chain")
    assert needed_scenes(["results/chains/unknown_product"], [], scenes)("chains", "spring_chain")


# The scene job with its study's work replaced by 200 MB held and a wait on stdin, which the test holds open:
# the job runs until a limit stops it, however fast the machine (a real scene once had to outlast 1.2 s).
JOB_THAT_WAITS = """
import sys
from classical_dynamics import scene_job
from classical_dynamics.studies import study_module

def wait_for_the_test(scene, quick=False):
    held = b"x" * (200 * 2**20)  # resident: every page written
    sys.stdin.read()  # the test never writes: only a limit ends this
    raise SystemExit(f"the job was not stopped ({len(held)} bytes held)")

study_module(sys.argv[1]).run = wait_for_the_test
sys.exit(scene_job.main(sys.argv[1:]))
"""


@pytest.mark.parametrize(
    "limit,says",
    [
        ("--time-limit-min=0.02", "ran past its time limit of 1.2 s"),
        ("--memory-limit-mb=120", "past its memory limit of 120 MB"),
    ],
)
def test_a_job_past_its_limit_is_stopped_in_one_line_and_writes_nothing(tmp_path, limit, says):
    scene = ROOT / "workflow/scenes/chains/hanging_particles.yaml"
    with subprocess.Popen(
        [
            sys.executable,
            "-c",
            JOB_THAT_WAITS,
            "chains",
            str(scene),
            str(tmp_path / "out"),
            str(tmp_path / "t"),
            limit,
        ],
        stdin=subprocess.PIPE,  # held open until the job has exited
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    ) as job:
        status = job.wait(timeout=120)
        stderr = job.stderr.read()
    assert status == 3, stderr
    assert stderr.count("\n") == 1 and says in stderr and stderr.startswith(str(scene))
    assert list(tmp_path.iterdir()) == []


def test_a_fault_of_ours_under_limits_leaves_its_traceback_in_the_log(capfd):
    """A job runs in a watched child (limits.run_limited): an exception there is a bug of ours, not a user's
    mistake, and its traceback must reach the job's log (it once left an empty log and exit status 1)."""
    from classical_dynamics.limits import run_limited

    def faulty():
        raise ZeroDivisionError("a bug of ours")

    assert run_limited(faulty, "scene.yaml", 60.0, 4000.0) == 1
    err = capfd.readouterr().err
    assert "Traceback" in err and "ZeroDivisionError: a bug of ours" in err


def test_a_job_validates_under_the_budget_its_run_gives(tmp_path, capsys):
    """The scene rule passes the run's budget (workflow/config.yaml with any --config budget=...) to the job,
    which validates again under it, not under the file's alone (a budget raised with --config once failed in
    the job). The job's own entry point, in this process: what is tested is the budget on its command line,
    not the start of a Python (a scene job in its own process is test_full_disk's and the pipeline's); and a
    light scene, as any scene's estimate is over a millisecond."""
    from classical_dynamics.cli import main

    scene = ROOT / "workflow/scenes/chains/two_masses_three_springs.yaml"
    base = ["run", "chains", str(scene)]
    capsys.readouterr()
    tight = main(base + [str(tmp_path / "a"), str(tmp_path / "ta"), "--quick", "--budget-seconds", "0.001"])
    err = capsys.readouterr().err
    assert tight == 2 and "budget.seconds" in err and not (tmp_path / "a").exists(), err
    done = main(base + [str(tmp_path / "b"), str(tmp_path / "tb"), "--quick", "--budget-seconds", "7200"])
    err = capsys.readouterr().err
    assert done == 0 and (tmp_path / "b/summary.json").is_file(), err


def _first_number(data, path=()):
    """The dotted path of the first number (not a bool) in a scene, depth first."""
    items = data.items() if isinstance(data, dict) else enumerate(data) if isinstance(data, list) else ()
    for key, value in items:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return (*path, key)
        found = _first_number(value, (*path, key))
        if found:
            return found
    return None


@pytest.mark.parametrize("value", [float("nan"), float("inf"), float("-inf")])
@pytest.mark.parametrize("study", ["chains", "chandler", "precession", "self_excited", "solvers"])
def test_a_number_that_is_not_finite_is_refused_by_name_in_every_study(tmp_path, study, value):
    """NaN passes every minimum and maximum of a schema: the loader refuses it by name, in every study,
    before any check() of the study's sees it; an infinity too, or the schema's bound does first."""
    scene = sorted((ROOT / "workflow/scenes" / study).glob("*.yaml"))[0]
    data = yaml.safe_load(scene.read_text())
    *parents, last = _first_number(data)
    target = data
    for key in parents:
        target = target[key]
    target[last] = value
    path = write(tmp_path, data)
    with pytest.raises(SceneError) as error:
        validate(study, path)
    field = ".".join(map(str, (*parents, last)))
    assert str(error.value).startswith(f"{path}: field '{field}'"), str(error.value)
    # a NaN is no number at all; an infinity is one past the schema's bound, where the field has one
    said = str(error.value).split(": expected ", 1)[1]
    if value != value:
        assert said.startswith("a finite number, got nan"), said
    else:
        assert said.startswith(("a finite number", "a number <", "a number >")) and "inf" in said, said


def test_validating_a_chains_scene_loads_neither_numba_nor_lapack(tmp_path):
    """Validation stays light (a 1000-scene sweep's first dry run validates each new scene in Snakemake's
    process): the study's effects, checks and cost estimate, without the compiled integrators (numba, 0.6 s
    to load) or scipy.linalg's LAPACK wrappers (0.3 s), which only running a scene needs."""
    path = write(tmp_path, GOOD)
    script = (
        "import sys\n"
        "from classical_dynamics.studies import validate\n"
        f"scene = validate('chains', {str(path)!r})\n"
        "print(scene.estimate.seconds > 0, 'numba' in sys.modules, 'scipy.linalg._decomp' in sys.modules)\n"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    done = subprocess.run(
        [sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=120
    )
    assert done.stdout.split() == ["True", "False", "False"], done.stderr[-2000:]
