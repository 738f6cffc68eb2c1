"""A warm process that runs the pipeline's jobs, so that a job does not pay the imports of its own interpreter.

A job of this pipeline spends about a second starting Python and importing numpy, scipy, matplotlib, numba and
our solvers before its own work, often longer than the work (95 jobs: over a minute of a build on two cores).
For a local run the Snakefile starts one server (`start`, from `onstart:`); it imports all that once, then forks
a child per job. The job's command line is this module's client:

    python -m classical_dynamics.jobserver MODULE ARG...     # as `python -m MODULE ARG...` would run it

The client hands the server its arguments, working folder, environment and its stdin, stdout and stderr (the job's
log), waits for the child's exit status and exits with it. Without a server (none started: a dry run, a cluster
job, a test calling the command itself) the client runs the module in its own process, as before; a job behaves
the same either way. The child is its own process group: a signal to the client (Ctrl-C, Snakemake stopping the
job) is passed on, and if the client disappears the server kills the group. The server stops when Snakemake
stops it or exits.

The client imports nothing but the standard library: its own start is about 20 ms.
"""

from __future__ import annotations

import json
import os
import signal
import socket
import sys

ENV = "CLASSICAL_DYNAMICS_JOBSERVER"        # the server's socket, in the environment of the jobs it serves
_MAX_REQUEST = 1 << 20


# ---------------------------------------------------------------------------------------------------- the client

def run_module(module: str, args: list[str]) -> int:
    """`python -m module args...` in this process; its exit status."""
    import runpy
    sys.argv = [module, *args]
    try:
        runpy.run_module(module, run_name="__main__", alter_sys=True)
    except SystemExit as exit_:
        code = exit_.code
        if code is None:
            return 0
        if isinstance(code, int):
            return code
        print(code, file=sys.stderr)
        return 1
    return 0


def client(argv: list[str]) -> int:
    """Run `python -m argv[0] argv[1:]` through the server named in the environment, or here without one."""
    module, args = argv[0], argv[1:]
    path = os.environ.get(ENV)
    if not path:
        return run_module(module, args)
    try:
        conn = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        conn.connect(path)
        request = json.dumps({"module": module, "args": args, "cwd": os.getcwd(), "env": dict(os.environ)})
        socket.send_fds(conn, [request.encode() + b"\n"], [0, 1, 2])
        replies = conn.makefile("r", encoding="utf-8")
        started = replies.readline()
    except OSError:
        started = ""
    if not started:                     # no server there, or it could not start: the job runs here
        return run_module(module, args)
    pid = json.loads(started)["pid"]

    def forward(signum, _frame):
        try:
            os.kill(pid, signum)
        except ProcessLookupError:
            pass
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, forward)
    finished = replies.readline()
    if not finished:
        print(f"job server: the job ({module} {' '.join(args)}) was lost", file=sys.stderr)
        return 1
    return json.loads(finished)["status"]


# ---------------------------------------------------------------------------------------------------- the server

# What nearly every job imports: loaded once here, shared by every child (copy-on-write).
WARM = ("classical_dynamics.cli", "numpy", "scipy.integrate", "scipy.special", "scipy.linalg", "scipy.optimize",
        "matplotlib", "matplotlib.pyplot", "jsonschema", "yaml", "classical_dynamics.studies",
        "classical_dynamics.solvers.runge_kutta", "classical_dynamics.solvers.rigid_body",
        "classical_dynamics.studies.results", "classical_dynamics.limits")


def _child(request: dict, fds: list[int]) -> None:
    """In the forked child: become the job (its streams, folder, environment) and run it; never returns."""
    status = 1
    try:
        os.setpgid(0, 0)
        for sig in (signal.SIGCHLD, signal.SIGTERM, signal.SIGHUP):
            signal.signal(sig, signal.SIG_DFL)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        for target, fd in enumerate(fds):
            os.dup2(fd, target)
            os.close(fd)
        os.chdir(request["cwd"])
        os.environ.clear()
        os.environ.update(request["env"])
        status = run_module(request["module"], request["args"])
    except BaseException:               # a fault of the job's own: its traceback in its log, as a process would
        import traceback
        traceback.print_exc()
    finally:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        os._exit(status if 0 <= status < 256 else 1)


def serve(path: str, parent: int) -> None:
    """Serve jobs on the socket at path until told to stop (SIGTERM) or until process parent is gone."""
    import importlib
    import select

    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(path)
    listener.listen(64)                 # clients may connect (and wait) while the imports below run
    signal.signal(signal.SIGINT, signal.SIG_IGN)     # Ctrl-C reaches the jobs through their clients
    stopping = []
    signal.signal(signal.SIGTERM, lambda *_: stopping.append(True))
    for name in WARM:
        importlib.import_module(name)
    jobs: dict[int, socket.socket] = {}                 # child pid -> its client's connection
    try:
        while not (stopping or os.getppid() != parent) or jobs:
            watched = list(jobs.values()) + ([] if stopping else [listener])
            try:
                ready = select.select(watched, [], [], 0.2)[0]
            except InterruptedError:
                ready = []
            for sock in ready:
                if sock is listener:
                    conn, _ = listener.accept()
                    pid = _start(conn, listener, jobs)
                    if pid:
                        jobs[pid] = conn
                elif not sock.recv(1):          # the client is gone (killed): so is its job
                    pid = next(p for p, c in jobs.items() if c is sock)
                    try:
                        os.killpg(pid, signal.SIGKILL)
                    except ProcessLookupError:
                        pass
            _reap(jobs)
    finally:
        listener.close()
        try:
            os.unlink(path)
        except OSError:
            pass


def _start(conn: socket.socket, listener: socket.socket, jobs: dict) -> int:
    """Fork the child for the request on conn; its pid, or 0 if the request was unreadable."""
    try:
        data, fds, _, _ = socket.recv_fds(conn, _MAX_REQUEST, 3)
        while not data.endswith(b"\n"):            # one line of JSON; the client then only waits
            more = conn.recv(_MAX_REQUEST)
            if not more:
                raise ValueError("incomplete request")
            data += more
        request = json.loads(data)
        if len(fds) != 3:
            raise ValueError("expected the job's stdin, stdout and stderr")
    except (OSError, ValueError):
        conn.close()
        return 0
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        listener.close()
        conn.close()
        for other in jobs.values():
            other.close()
        _child(request, fds)
    for fd in fds:
        os.close(fd)
    conn.sendall(json.dumps({"pid": pid}).encode() + b"\n")
    return pid


def _reap(jobs: dict) -> None:
    """Send each finished child's exit status to its client."""
    while jobs:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        conn = jobs.pop(pid, None)
        if conn is None:
            continue
        code = os.waitstatus_to_exitcode(status)
        try:
            conn.sendall(json.dumps({"status": code if code >= 0 else 128 - code}).encode() + b"\n")
        except OSError:
            pass
        conn.close()


_server: "subprocess.Popen | None" = None


def start() -> None:
    """Start a server for the jobs of this process (the Snakemake run whose `onstart:` calls it): its socket's path
    goes into this process's environment, which Snakemake's local jobs inherit."""
    import subprocess
    import tempfile
    global _server
    path = os.path.join(tempfile.mkdtemp(prefix="classical-dynamics-"), "jobs.sock")
    _server = subprocess.Popen([sys.executable, "-m", __name__, "--serve", path, str(os.getpid())],
                               start_new_session=True, stdin=subprocess.DEVNULL)
    os.environ[ENV] = path


def stop() -> None:
    """Stop the server start() started, once the jobs it runs are done."""
    import shutil
    global _server
    path = os.environ.pop(ENV, None)
    if _server is not None:
        _server.terminate()
        _server.wait()
        _server = None
    if path:
        shutil.rmtree(os.path.dirname(path), ignore_errors=True)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--serve"]:
        serve(sys.argv[2], int(sys.argv[3]))
    else:
        sys.exit(client(sys.argv[1:]))
