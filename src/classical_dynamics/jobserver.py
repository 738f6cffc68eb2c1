"""A warm process that runs the pipeline's jobs, so that a job does not pay the imports of its own
interpreter.

A job of this pipeline spends about a second starting Python and importing numpy, scipy, matplotlib, numba and
our solvers before its own work, often longer than the work (95 jobs: over a minute of a build on two cores).
For a local run the Snakefile starts one server (`start`, from `onstart:`); it imports all that once, then
forks a child per job. The job's command line is this module's client:

    python -m classical_dynamics.jobserver MODULE ARG...     # as `python -m MODULE ARG...` would run it

The client hands the server its arguments, working folder, environment and its stdin, stdout and stderr (the
job's log), waits for the child's exit status and exits with it. Without a server (none started: a dry run, a
cluster job, a test calling the command itself) the client runs the module in its own process, as before; a
job behaves the same either way. The child is its own process group: a signal to the client (Ctrl-C, Snakemake
stopping the job) is passed on, and if the client disappears the server kills the group. The server stops when
Snakemake stops it or exits.

A child's environment and folder are its client's; its modules are the server's, imported when the run started
(as Snakemake's code digests were taken when it parsed). The client imports nothing but the standard library:
a cheap scene takes 0.10 s through the server against 1.4 s in its own interpreter.
"""

from __future__ import annotations

import json
import os
import signal
import socket
import sys

ENV = "CLASSICAL_DYNAMICS_JOBSERVER"  # the server's socket, in the environment of the jobs it serves
_MAX_REQUEST = 1 << 20


# --- the client ---------------------------------------------------------------------------------------------


def run_module(module: str, args: list[str]) -> int:
    """`python -m module args...` in this process; its exit status."""
    import runpy
    import warnings

    sys.argv = [module, *args]
    try:
        with warnings.catch_warnings():  # the server imported it already: runpy runs it afresh, as python -m
            warnings.filterwarnings(
                "ignore", "'.*' found in sys.modules after import of package", RuntimeWarning
            )
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
    if not started:  # no server there, or it could not start: the job runs here
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


# --- the server ---------------------------------------------------------------------------------------------

# What the jobs import: loaded once here, shared by every child (copy-on-write). Every module of the packages
# below (sympy for the closed forms among them), and the report's HTML. Not WeasyPrint: one job, the PDF, uses
# it.
WARM = (
    "classical_dynamics.cli",
    "numpy",
    "scipy.integrate",
    "scipy.special",
    "scipy.linalg",
    "scipy.optimize",
    "matplotlib",
    "matplotlib.figure",
    "matplotlib.backends.backend_svg",
    "jsonschema",
    "yaml",
    "sympy",
    # imported by some jobs on first use: sympy's simplify and integrate (0.3 s), IAU models, IERS data, CSV
    "sympy.physics.units",
    "sympy.integrals.risch",
    "sympy.integrals.manualintegrate",
    "erfa",
    "astropy_iers_data",
    "pandas.io.formats.csvs",
    "classical_dynamics.report.build",
)
WARM_PACKAGES = (
    "classical_dynamics.solvers",
    "classical_dynamics.models",
    "classical_dynamics.scenes",
    "classical_dynamics.studies",
)


def _warm_up() -> None:
    import importlib
    import pkgutil

    for name in WARM:
        importlib.import_module(name)
    for name in WARM_PACKAGES:
        package = importlib.import_module(name)
        for module in pkgutil.walk_packages(package.__path__, f"{name}."):
            importlib.import_module(module.name)
    _draw_a_figure()


def _draw_a_figure() -> None:
    """What matplotlib does once per process on its first figure (builds its mathtext parser, loads the fonts,
    fills its text caches: 0.3 s, more than a light scene's own work), done here rather than in every job.
    Its caches are keyed by what they hold, so a job draws the same bytes as in a process of its own."""
    from classical_dynamics import io
    from classical_dynamics.figure_style import legend_below
    from classical_dynamics.results import new_figure

    fig, axes = new_figure()
    axes.loglog([1.0, 10.0], [1e-16, 1e-12], label="$\\sqrt{N}\\,\\varepsilon$, $m_1$")
    axes.set_xlabel("time $t$ (s)")
    legend_below(fig, *axes.get_legend_handles_labels(), ncol=1)
    io.svg_bytes(fig)


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
    except BaseException:  # a fault of the job's own: its traceback in its log, as a process would
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
    import gc
    import select

    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(path)
    listener.listen(64)  # clients may connect (and wait) while the imports below run
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the jobs through their clients
    stopping = []
    signal.signal(signal.SIGTERM, lambda *_: stopping.append(True))
    # A child's exit wakes the loop at once (its status goes to its client without waiting for a timeout).
    wake, woken = os.pipe()
    os.set_blocking(wake, False)
    os.set_blocking(woken, False)
    signal.set_wakeup_fd(woken)
    signal.signal(signal.SIGCHLD, lambda *_: None)
    jobs: dict[int, socket.socket] = {}  # child pid -> its client's connection
    try:
        _warm_up()  # should an import fail, waiting clients see the server gone and run their jobs alone
        # What the jobs share, set aside from the cyclic collector (Python's recipe for a forking server): a
        # child's collections then skip these objects instead of walking them all again (and copying each
        # page they touch, which the children would otherwise share).
        gc.freeze()
        while not (stopping or os.getppid() != parent) or jobs:
            watched = [wake, *jobs.values()] + ([] if stopping else [listener])
            for ready in select.select(watched, [], [], 1.0)[0]:
                if ready is wake:
                    os.read(wake, 4096)
                elif ready is listener:
                    conn, _ = listener.accept()
                    pid = _start(conn, [listener, wake, woken, *jobs.values()])
                    if pid:
                        jobs[pid] = conn
                elif not ready.recv(1):  # the client is gone (killed): so is its job
                    pid = next(p for p, c in jobs.items() if c is ready)
                    try:
                        os.killpg(pid, signal.SIGKILL)
                    except ProcessLookupError:
                        pass
            _reap(jobs)
    finally:
        listener.close()
        for remove in (os.unlink, os.rmdir):  # the socket and the folder start() made for it
            try:
                remove(path if remove is os.unlink else os.path.dirname(path))
            except OSError:
                pass


def _start(conn: socket.socket, inherited: list) -> int:
    """Fork the child for the request on conn; its pid, or 0 if the request was unreadable. The child closes
    what it inherited of the server's (its sockets and pipe)."""
    try:
        data, fds, _, _ = socket.recv_fds(conn, _MAX_REQUEST, 3)
        while not data.endswith(b"\n"):  # one line of JSON; the client then only waits
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
        signal.set_wakeup_fd(-1)
        for item in [conn, *inherited]:
            item.close() if isinstance(item, socket.socket) else os.close(item)
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


_server = None  # the server's subprocess.Popen while one runs (subprocess is imported only to start it)


def skip_last_collections() -> None:
    """Let this process exit without Python's last garbage collections over everything it made: the cyclic
    collector walks every object again as the interpreter finalizes (2.9 s after the PDF job's 30, 0.4 s after
    a light scene's, 0.4 to 0.6 s after Snakemake's), only for the operating system to free the memory anyway.
    Frozen objects are skipped by the collector; atexit handlers, module teardown and reference counting run
    as before. What a job writes is written and closed before it returns (io.atomic_write_*)."""
    import gc

    gc.freeze()


def put_interpreter_first_on_path() -> None:
    """Put this interpreter's folder first on PATH (for the jobs started from this process): rules call
    `python3` by name, which is then the interpreter that runs Snakemake, as activating its environment would
    make it."""
    os.environ["PATH"] = os.pathsep.join([os.path.dirname(sys.executable), os.environ.get("PATH", "")])


def start() -> None:
    """Start a server for the jobs of this process (the Snakemake run whose `onstart:` calls it): its socket's
    path goes into this process's environment, which Snakemake's local jobs inherit."""
    import subprocess
    import tempfile
    import time

    global _server
    path = os.path.join(tempfile.mkdtemp(prefix="classical-dynamics-"), "jobs.sock")
    _server = subprocess.Popen(
        [sys.executable, "-m", __name__, "--serve", path, str(os.getpid())],
        start_new_session=True,
        stdin=subprocess.DEVNULL,
    )
    # Its socket is listening before its imports start (a tenth of a second in): a job that came earlier would
    # find no server and run alone.
    deadline = time.monotonic() + 10.0
    while not os.path.exists(path) and _server.poll() is None and time.monotonic() < deadline:
        time.sleep(0.01)
    os.environ[ENV] = path


def stop() -> None:
    """Stop the server start() started, once the jobs it runs are done (it removes its socket and folder)."""
    global _server
    os.environ.pop(ENV, None)
    if _server is not None:
        _server.terminate()
        _server.wait()
        _server = None


if __name__ == "__main__":
    if sys.argv[1:2] == ["--serve"]:
        serve(sys.argv[2], int(sys.argv[3]))
    else:
        status = client(sys.argv[1:])
        skip_last_collections()
        sys.exit(status)
