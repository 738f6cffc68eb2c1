"""The warm job server (classical_dynamics/jobserver.py): a job through it behaves as the same job run
alone."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from classical_dynamics import jobserver

ROOT = Path(__file__).resolve().parents[1]
CLIENT = [sys.executable, "-m", "classical_dynamics.jobserver"]


@pytest.fixture(scope="module")
def server():
    jobserver.start()
    yield os.environ[jobserver.ENV], jobserver._server.pid
    jobserver.stop()


def children(pid):
    """Processes whose parent is pid."""
    found = []
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            fields = dict(line.split(":\t", 1) for line in status.read_text().splitlines() if ":\t" in line)
        except OSError:
            continue
        if int(fields.get("PPid", "0")) == pid:
            found.append(int(fields["Pid"]))
    return found


def through(server_path, *args, env_server=True, **kwargs):
    env = dict(os.environ)
    env.pop(jobserver.ENV, None)
    if env_server:
        env[jobserver.ENV] = server_path
    return subprocess.run(
        [*CLIENT, *args], cwd=ROOT, env=env, capture_output=True, text=True, timeout=120, **kwargs
    )


def test_a_job_gets_the_same_streams_and_status_with_and_without_the_server(server, tmp_path):
    path, pid = server
    bad = tmp_path / "bad.yaml"
    bad.write_text("title: [unclosed\n")
    args = ("classical_dynamics", "run", "chains", str(bad), str(tmp_path / "out"), str(tmp_path / "timings"))
    served, alone = through(path, *args), through(path, *args, env_server=False)
    assert served.returncode == alone.returncode == 2
    assert (
        served.stderr == alone.stderr and served.stderr.count("\n") == 1 and "YAML at line" in served.stderr
    )
    assert not (tmp_path / "out").exists()
    ok = through(path, "timeit", "-n", "1", "-r", "1", "pass")
    assert ok.returncode == 0 and "1 loop" in ok.stdout
    assert children(pid) == []  # the job's process is gone with it


def test_a_job_runs_in_the_clients_folder_with_its_environment(server, tmp_path):
    path, _ = server
    env = {**os.environ, jobserver.ENV: path, "JOBSERVER_PROBE": "42"}
    code = "import os; print(os.getcwd(), os.environ['JOBSERVER_PROBE'])"
    done = subprocess.run(
        [*CLIENT, "timeit", "-n", "1", "-r", "1", "-s", code, "pass"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0 and done.stdout.splitlines()[0] == f"{tmp_path} 42"


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL])
def test_stopping_the_client_stops_its_job(server, sig):
    """Snakemake stops a job by signalling its shell's process: the work must not run on unseen."""
    path, pid = server
    env = {**os.environ, jobserver.ENV: path}
    client = subprocess.Popen(
        [*CLIENT, "timeit", "-n", "1", "-r", "1", "import time; time.sleep(60)"],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    deadline = time.monotonic() + 30
    while not children(pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert children(pid), "the job never started in the server"
    client.send_signal(sig)
    assert client.wait(timeout=10) != 0
    deadline = time.monotonic() + 10
    while children(pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert children(pid) == []


def test_without_a_server_the_client_runs_the_job_itself(tmp_path):
    gone = tmp_path / "no-server.sock"
    done = through(str(gone), "timeit", "-n", "1", "-r", "1", "pass")
    assert done.returncode == 0 and "1 loop" in done.stdout


def test_a_job_alone_exits_with_its_objects_frozen_and_its_status_kept(tmp_path):
    """A job run by the client in its own process ends without the last garbage collections over its objects
    (frozen once it returns: 2.9 s of the PDF job's exit): its atexit handlers still run, after the freeze,
    and its exit status and output are kept."""
    (tmp_path / "job_at_exit.py").write_text(
        "import atexit, gc, sys\n"
        "cycle = [[]]; cycle[0].append(cycle)\n"
        "atexit.register(lambda: print('frozen at exit:', gc.get_freeze_count() > 0, flush=True))\n"
        "print('frozen while running:', gc.get_freeze_count() > 0)\n"
        "sys.exit(3)\n"
    )
    env = {k: v for k, v in os.environ.items() if k != jobserver.ENV}
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path), str(ROOT / "src")])
    done = subprocess.run([*CLIENT, "job_at_exit"], env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 3
    assert done.stdout.splitlines() == ["frozen while running: False", "frozen at exit: True"]
