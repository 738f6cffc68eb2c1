"""The pipeline on a real Slurm cluster (tools/local-slurm starts one on this machine, with accounting),
through profiles/slurm and Snakemake's executor plugin for Slurm: the quick build gives the local
quick build's results, every job asks for at least what it used, and a job that fails on the cluster is
reported with its log.

Run by `make test-slurm` (which starts the cluster; CI does), not by `make test`: `pytest -m slurm`.
"""

import re
import subprocess

import pytest

from benchmarks.job_resources import used

from .conftest import copy_repository, snakemake
from .test_pipeline import result_files

pytestmark = [pytest.mark.slurm, pytest.mark.slow, pytest.mark.pipeline]

PROFILE = ("--profile", "profiles/slurm")


@pytest.fixture(scope="module")
def cluster():
    """A Slurm cluster that answers, with a node ready for jobs."""
    try:
        state = subprocess.run(["sinfo", "-h", "-o", "%t"], capture_output=True, text=True, timeout=30).stdout
    except FileNotFoundError:
        state = ""
    if not set(state.split()) & {"idle", "mix", "alloc"}:
        pytest.fail(
            f"no Slurm node ready (sinfo: {state.strip() or 'none'}): start one with `tools/local-slurm up`"
        )


def asked(dry_run: str) -> dict[str, dict]:
    """{benchmark file: {"mem_mb", "runtime"}}: what each job of a dry run asks for (its 'resources:'
    line)."""
    asks, benchmark = {}, None
    for line in dry_run.splitlines():
        line = line.strip()
        if line.startswith("benchmark: "):
            benchmark = line.removeprefix("benchmark: ")
        elif line.startswith("resources: ") and benchmark:
            fields = dict(item.split("=", 1) for item in line.removeprefix("resources: ").split(", "))
            asks[benchmark] = {"mem_mb": float(fields["mem_mb"]), "runtime": float(fields["runtime"])}
            benchmark = None
    return asks


# the build's own budget (2400 s, below) is the guard: pytest-timeout's 900 s cut it first on 2 cores
@pytest.mark.timeout(2400)
def test_the_quick_build_on_slurm_is_the_local_one(cluster, built_repo, tmp_path):
    repo = copy_repository(tmp_path / "repo")
    done = snakemake(repo, *PROFILE, "--config", "quick=1", timeout=2400)
    log = done.stdout + done.stderr
    submitted = re.findall(r"submitted with SLURM jobid (\d+)", log)
    jobs = int(re.search(r"(\d+) of \1 steps \(100%\) done", log).group(1))
    assert submitted and "group_light_scenes" in log  # jobs went to Slurm, light scenes in batches
    assert len(submitted) < jobs / 2, (len(submitted), jobs)
    assert result_files(repo) == result_files(built_repo)
    assert (repo / "results/report.pdf").read_bytes()[:5] == b"%PDF-"
    # Every job asked Slurm for at least the memory and time it used (its own interpreter: no job server
    # there).
    asks = asked(snakemake(repo, "-n", "--forceall", "--config", "quick=1").stdout)
    benchmarks = sorted((repo / "results/benchmarks").rglob("*.tsv"))
    # every job but the target rule `all` and `measured` (a local copy of the benchmarks' data, no Slurm job)
    assert len(benchmarks) == len(asks) == jobs - 2
    for tsv in benchmarks:
        job, ask = used(tsv), asks[tsv.relative_to(repo).as_posix()]
        # above 20 MB: the job's own interpreter and imports were measured (the streamed archive job: ~40)
        assert 20 < job["max_rss_mb"] < ask["mem_mb"], (tsv.name, job, ask)
        assert job["seconds"] < 60 * ask["runtime"], (tsv.name, job, ask)


def test_a_job_failing_on_slurm_is_reported_with_its_log(cluster, tmp_path):
    """A scene that passes validation but fails at run time (here: past a memory limit set too low for it) is
    reported as failed, names its log, and leaves no result."""
    repo = copy_repository(tmp_path / "repo")
    scene = "results/chains/loaded_string"
    done = snakemake(
        repo,
        *PROFILE,
        scene,
        "--set-resources",
        "scene:mem_mb=10",
        "--config",
        "quick=1",
        check=False,
        timeout=900,
    )
    log = done.stdout + done.stderr
    assert done.returncode != 0
    assert "Error in rule scene" in log and "results/logs/chains/loaded_string.log" in log, log[-3000:]
    assert "past its memory limit of 10 MB" in (repo / "results/logs/chains/loaded_string.log").read_text()
    assert re.search(r"SLURM jobid \d+ \(log: \S+\.log\)", log)  # Slurm's own log of the job, named
    assert not (repo / scene).exists()


def test_a_site_without_accounting_reads_job_states_from_squeue(cluster, built_repo, tmp_path):
    """The README's setting for a cluster without accounting: job states from squeue (this cluster keeps a
    finished job visible for MinJobAge = 300 s, at least three times the profile's first status check)."""
    repo = copy_repository(tmp_path / "repo")
    scene = "results/chains/loaded_string"
    done = snakemake(
        repo, *PROFILE, scene, "--slurm-status-command", "squeue", "--config", "quick=1", timeout=900
    )
    assert "submitted with SLURM jobid" in done.stdout + done.stderr
    assert (
        {k: v for k, v in result_files(repo).items() if k.startswith("chains/loaded_string/")}
        == {k: v for k, v in result_files(built_repo).items() if k.startswith("chains/loaded_string/")}
        != {}
    )
