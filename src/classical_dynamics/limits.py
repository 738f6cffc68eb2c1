"""A job run under a time and a memory limit: the scene's own estimate with room to spare (scenes/cost.py).

The work runs in a forked child; the parent only watches the wall clock and the child's resident memory, every
0.1 s, and stops it with one line when it passes either. A watcher outside the work is the only kind that can
stop a numba loop holding the interpreter, and resident memory (not address space, which numba and BLAS
reserve by the gigabyte) is what exhausts a machine.

Also the limits on what a reader (verify, diff, dist) takes from a user's file, each with why that size.
"""

from __future__ import annotations

import math
import os
import select
import signal
import sys
import time
import traceback
from typing import Callable

POLL_S = 0.1

# --- what a reader (verify, diff, dist) takes from a user's file -------------------------------------------
# Sized from a full build (about 650 archived files, 60 MB in all; the largest file the 12 MB report.html, the
# largest summary.json 42 kB), with room for a much larger one; a hostile file is refused before it is read.
READ_CHUNK_BYTES = 1 << 20  # files are read and hashed in pieces of this size, never held whole
MAX_MEMBER_BYTES = 256 << 20  # one file of an archive or results folder: 20 times the largest of a full build
MAX_MEMBERS = 20_000  # files in an archive: 30 times a full build's
MAX_ARCHIVE_BYTES = 1 << 30  # an archive's files unpacked, all told: 15 times a full build's; seconds to read
# A tar header's own data (a long name, PAX records) is read whole by tarfile: a few hundred bytes in ours.
MAX_TAR_HEADER_BYTES = READ_CHUNK_BYTES
MAX_MANIFEST_BYTES = 16 << 20  # a SHA256SUMS: MAX_MEMBERS lines of 800 characters
MAX_JSON_BYTES = 16 << 20  # a summary.json or provenance.json: 400 times the largest of a full build
MAX_JSON_DEPTH = 64  # a JSON file's nesting: ours nest 6 deep; far deeper would recurse past Python's stack
MAX_INT_DIGITS = 300  # an integer in a results file (a count, a seed): 300 digits still convert to a float


def resident_mb(pid: int) -> float:
    """A process's resident memory (VmRSS), MB; 0 once it is gone."""
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024
    except (OSError, ValueError):
        pass
    return 0.0


def run_limited(work: Callable[[], int], what: str, time_limit_s: float, memory_limit_mb: float) -> int:
    """work() in a child process; its exit status, or 3 with one line on stderr if it passed a limit."""
    sys.stdout.flush()
    sys.stderr.flush()
    # The child holds the write end of a pipe until it exits: the parent's wait between checks ends at once
    # when it does, instead of up to POLL_S later (a job's exit is not delayed by the watcher).
    exited, alive = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: do the work, never return into the caller
        os.close(exited)
        status = 1
        try:
            status = work()
        except SystemExit as exit_:
            status = exit_.code if isinstance(exit_.code, int) else 1
        except BaseException:  # a fault of ours: its traceback in the job's log
            traceback.print_exc()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(status)

    def forward(signum, _frame):  # Ctrl-C or Snakemake stopping the job: stop the work too
        os.kill(pid, signum)

    os.close(alive)
    previous = {sig: signal.signal(sig, forward) for sig in (signal.SIGINT, signal.SIGTERM)}
    start, reason = time.monotonic(), None
    try:
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                return os.waitstatus_to_exitcode(status)
            elapsed, memory = time.monotonic() - start, resident_mb(pid)
            if elapsed > time_limit_s:
                reason = f"ran past its time limit of {time_limit_s:g} s"
            elif memory > memory_limit_mb:
                reason = f"used {memory:.0f} MB, past its memory limit of {memory_limit_mb:g} MB"
            if reason:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                print(
                    f"{what}: stopped: it {reason} (limits are set from the scene's estimated cost; "
                    f"see budget: in workflow/config.yaml)",
                    file=sys.stderr,
                )
                return 3
            if select.select([exited], [], [], POLL_S)[0]:
                time.sleep(0.001)  # closed as it exits: waitable in a moment
    finally:
        os.close(exited)
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def rule_resources(peak: dict) -> dict:
    """What a job that is not a scene asks a scheduler for, from its rule's measured peak
    (workflow/resources.yaml): twice the memory and 200 MB more, four times the time and at least 5 minutes (a
    node slower or busier than the one measured, a report that has grown since)."""
    return {
        "mem_mb": 100 * math.ceil((2 * peak["max_rss_mb"] + 200) / 100),
        "runtime": max(5, math.ceil(4 * peak["seconds"] / 60)),
    }
