"""Speed of the solver layer, side by side in one run (printed, not asserted).

solve() runs the final-state loop when no dense output, events or step record is asked for;
specialize=True compiles that loop for the one right-hand side (seconds, reported apart).

1. HNW rigid body, time to reach error 1e-10 at t = 20: this library's best adaptive method against
   scipy's solve_ivp DOP853, and against a hand-written compiled fixed-step order-8 loop (the RHS
   inlined, the step the largest that reaches 1e-10): the limit for this problem; and against the same
   method written by hand with its error control (the RHS inlined, ours' error norm, no calls):
   the limit for an adaptive DOP853, which pays for its error estimate and its rejected steps.
2. A batch of 1000 trajectories in one compiled call against 1000 calls one at a time (ours, and
   solve_ivp's).
3. The fixed-step door (fixed_step.solve_fixed) against its kernels called directly, the same steps: what the
   door's checks and packing cost, long runs and short ones.
Times are minima over repeated runs after a warm-up.

    python benchmarks/solver_speed.py
    python benchmarks/solver_speed.py --door           # part 3 only
    python benchmarks/solver_speed.py --against REV    # the compiled paths here and at commit REV

With --against, the same calls through the public interface (solve, solve_batch) are timed in this tree and in
a git worktree of REV, each in processes of its own, alternating three times (the minimum of each is kept, so
that a change in the machine's load falls on both): the final-state loop (plain and specialized), the full
loop (dense output, events), and the batches; and geometric fixed-step methods through the fixed-step door
(through the functions it replaced where a tree has no door).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from numba import njit

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))
from classical_dynamics.models import rigid_body as rhs
from classical_dynamics.provenance import software_stamp
from classical_dynamics.solvers import references as ref
from classical_dynamics.solvers import runge_kutta as rk
from classical_dynamics.solvers.ode import Problem, solve, solve_batch
from classical_dynamics.solvers.timing import min_time

TARGET = 1e-10
T = 20.0
EXACT = ref.hnw_rigid_body(T)
HNW = Problem(rhs.euler_free, ref.HNW_Y0, (0.0, T), rhs.euler_coefficients(ref.HNW_I))


@njit(cache=True)
def hand_written_dop853(y0, h, n, A, B, C):
    """Fixed-step DOP853 with the HNW right-hand side written in: no calls, no error control."""
    y = y0.copy()
    K = np.zeros((12, 3))
    tmp = np.empty(3)
    for _ in range(n):
        for i in range(12):
            for j in range(3):
                acc = 0.0
                for l in range(i):
                    acc += A[i, l] * K[l, j]
                tmp[j] = y[j] + h * acc
            K[i, 0] = -2.0 * tmp[1] * tmp[2]
            K[i, 1] = 1.25 * tmp[0] * tmp[2]
            K[i, 2] = -0.5 * tmp[0] * tmp[1]
        for j in range(3):
            acc = 0.0
            for l in range(12):
                acc += B[l] * K[l, j]
            y[j] += h * acc
    return y


@njit(cache=True)
def hand_written_adaptive_dop853(y0, t1, h, rtol, atol, A, B, C, E5, E3):
    """DOP853 with error control (ours' stages, embedded estimates and norm; its controller's safety factor
    and limits, from a given first step), the HNW right-hand side written in, no calls: the fair limit for an
    adaptive method. (steps, rejected, y)."""
    y = y0.copy()
    y_new = np.empty(3)
    K = np.zeros((13, 3))
    tmp = np.empty(3)
    K[0, 0], K[0, 1], K[0, 2] = -2.0 * y[1] * y[2], 1.25 * y[0] * y[2], -0.5 * y[0] * y[1]
    t, steps, rejected = 0.0, 0, 0
    while t < t1:
        h = min(h, t1 - t)
        for i in range(1, 12):
            for j in range(3):
                acc = 0.0
                for l in range(i):
                    acc += A[i, l] * K[l, j]
                tmp[j] = y[j] + h * acc
            K[i, 0], K[i, 1], K[i, 2] = -2.0 * tmp[1] * tmp[2], 1.25 * tmp[0] * tmp[2], -0.5 * tmp[0] * tmp[1]
        for j in range(3):
            acc = 0.0
            for l in range(12):
                acc += B[l] * K[l, j]
            y_new[j] = y[j] + h * acc
        K[12, 0] = -2.0 * y_new[1] * y_new[2]
        K[12, 1] = 1.25 * y_new[0] * y_new[2]
        K[12, 2] = -0.5 * y_new[0] * y_new[1]
        n5 = 0.0
        n3 = 0.0
        for j in range(3):
            scale = atol + max(abs(y[j]), abs(y_new[j])) * rtol
            a5 = 0.0
            a3 = 0.0
            for l in range(13):
                a5 += E5[l] * K[l, j]
                a3 += E3[l] * K[l, j]
            n5 += (a5 / scale) ** 2
            n3 += (a3 / scale) ** 2
        err = abs(h) * n5 / np.sqrt((n5 + 0.01 * n3) * 3) if n5 + n3 > 0.0 else 0.0
        factor = 10.0 if err == 0.0 else min(10.0, max(0.2, 0.9 / np.sqrt(np.sqrt(np.sqrt(err)))))
        if err < 1.0:
            t += h
            y[:] = y_new
            K[0] = K[12]
            steps += 1
        else:
            rejected += 1
            factor = min(1.0, factor)
        h *= factor
    return steps, rejected, y


def error(y):
    return float(np.max(np.abs(y - EXACT)))


VARIANTS = {
    "dop853": ("dop853", {}),
    "dop853, specialized": ("dop853", {"specialize": True}),
    "dopri5": ("dopri5", {}),
    "scipy:DOP853": ("scipy:DOP853", {}),
    "scipy:RK45": ("scipy:RK45", {}),
}


def fastest_adaptive():
    """(label, rtol, seconds, error) of the quickest setting of each variant reaching TARGET."""
    results = {}
    for label, (method, options) in VARIANTS.items():
        best = None
        for rtol in 10.0 ** -np.arange(6, 13.5, 0.125):  # as fine as the hand-written loop's step count
            err = error(solve(HNW, method, rtol=rtol, atol=rtol * 1e-3, **options).y)
            if err <= TARGET:
                seconds, _, _ = min_time(
                    lambda: solve(HNW, method, rtol=rtol, atol=rtol * 1e-3, **options),
                    repeats=300 if method in ("dop853", "dopri5") else 5,
                    budget_s=1.0,
                )
                best = (label, rtol, seconds, err)
                break
        results[label] = best
    return results


def hand_written_limit():
    d = rk.DOP853
    for n in range(20, 2000):
        y = hand_written_dop853(ref.HNW_Y0, T / n, n, d.A, d.B, d.C)
        if error(y) <= TARGET:
            seconds, _, _ = min_time(
                lambda: hand_written_dop853(ref.HNW_Y0, T / n, n, d.A, d.B, d.C), repeats=200, budget_s=1.0
            )
            return n, seconds, error(y)
    raise RuntimeError("no fixed step reached the target")


def hand_written_adaptive(rtol):
    """(seconds, error, steps, rejected) of the hand-written adaptive loop at ours' tolerance."""
    d = rk.DOP853
    args = (ref.HNW_Y0, T, 0.05, rtol, rtol * 1e-3, d.A, d.B, d.C, d.E5, d.E3)
    steps, rejected, y = hand_written_adaptive_dop853(*args)
    seconds, _, _ = min_time(lambda: hand_written_adaptive_dop853(*args), repeats=200, budget_s=1.0)
    return seconds, error(y), steps, rejected


def batch(count=1000):
    """Seconds per trajectory: one call each (plain and specialized), one batch call (plain and
    specialized, the rows over both cores), and solve_ivp one call each (on 20 of them)."""
    rng = np.random.default_rng(1)
    Y0 = ref.HNW_Y0 + 0.05 * rng.standard_normal((count, 3))
    a = rhs.euler_coefficients(ref.HNW_I)
    rtol = 1e-10
    out = {}
    for label, options in (("", {}), (", specialized", {"specialize": True})):
        solve_batch(rhs.euler_free, Y0[:2], (0.0, T), a, rtol=rtol, atol=rtol * 1e-3, **options)  # compile
        one = lambda: [
            solve(Problem(rhs.euler_free, y, (0.0, T), a), "dop853", rtol=rtol, atol=rtol * 1e-3, **options)
            for y in Y0
        ]
        together = lambda: solve_batch(
            rhs.euler_free, Y0, (0.0, T), a, rtol=rtol, atol=rtol * 1e-3, **options
        )
        out[f"ours, one call each{label}"] = min_time(one, repeats=3, budget_s=2.0)[0] / count
        out[f"ours, one batch call{label}"] = min_time(together, repeats=5, budget_s=2.0)[0] / count
    few = Y0[:20]
    out["solve_ivp DOP853, one call each"] = min_time(
        lambda: [
            solve(Problem(rhs.euler_free, y, (0.0, T), a), "scipy:DOP853", rtol=rtol, atol=rtol * 1e-3)
            for y in few
        ],
        repeats=2,
        budget_s=2.0,
    )[0] / len(few)
    return out


def door_against_kernels():
    """(label, seconds through the door, seconds of its kernel called directly), side by side, one process."""
    from classical_dynamics.models import linear
    from classical_dynamics.solvers import rattle, rigid_body, symplectic
    from classical_dynamics.solvers.fixed_step import FixedProblem, Save, solve_fixed

    I, m0, q0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0, np.array([1.0, 0.0, 0.0, 0.0])
    body = FixedProblem(rigid_body.packed(m0, q0), I)
    oscillator = FixedProblem([1.0, 0.0], [1.0], linear.harmonic_force)
    n = 4
    a = 1.0 / n
    chain_q = rattle.positions_from_angles(np.full(n, 0.3), a)
    chain = FixedProblem(np.concatenate([chain_q.ravel(), np.zeros(2 * n)]), np.r_[a, 9.81, np.full(n, a)])
    one, v0, p0, masses = np.array([1.0]), np.array([0.0]), np.zeros((n, 2)), np.full(n, a)
    cases = []
    for steps, label in ((100_000, "100000 steps"), (100, "100 steps")):
        cases += [
            (
                f"rigid-splitting4, {label}, final state",
                lambda k=steps: solve_fixed(
                    body, "rigid-splitting4", h=0.01, n_steps=k, save=Save(final=True)
                ),
                lambda k=steps: rigid_body.integrate_free(I, m0, q0, 0.01, k, 4, k),
            ),
            (
                f"rigid-splitting2, {label}, every 10th saved",
                lambda k=steps: solve_fixed(body, "rigid-splitting2", h=0.01, n_steps=k, save=Save(every=10)),
                lambda k=steps: rigid_body.integrate_free(I, m0, q0, 0.01, k, 2, 10),
            ),
            (
                f"stormer-verlet, {label}, every step saved",
                lambda k=steps: solve_fixed(oscillator, "stormer-verlet", h=0.01, n_steps=k),
                lambda k=steps: symplectic.integrate(linear.harmonic_force, one, one, v0, 0.01, k, 2, 1),
            ),
            (
                f"rattle (4 particles), {label}, every 10th",
                lambda k=steps: solve_fixed(chain, "rattle", h=1e-3, n_steps=k, save=Save(every=10)),
                lambda k=steps: rattle.integrate(chain_q, p0, masses, a, 9.81, 1e-3, k, 10),
            ),
        ]
    out = []
    for label, door, kernel in cases:
        door(), kernel()  # compiled (or loaded) first
        best = {"door": np.inf, "kernel": np.inf}
        for _ in range(3):  # alternating, so that a change in the machine's load falls on both
            best["door"] = min(best["door"], min_time(door, repeats=20, budget_s=0.5)[0])
            best["kernel"] = min(best["kernel"], min_time(kernel, repeats=20, budget_s=0.5)[0])
        out.append((label, best["door"], best["kernel"]))
    return out


def print_door():
    print("The fixed-step door against its kernels called directly (the same steps; minima, alternating):")
    print(f"  {'method and run':50s} {'door':>11s} {'kernel':>11s} {'ratio':>7s}")
    for label, door, kernel in door_against_kernels():
        print(f"  {label:50s} {door * 1e6:8.1f} us {kernel * 1e6:8.1f} us {door / kernel:7.3f}")


def main():
    start = time.perf_counter()
    solve(HNW, "dop853", rtol=1e-8, atol=1e-11)
    print(f"machine: {software_stamp()}")
    print(
        f"first call in this process (compiled loop loaded from cache): {time.perf_counter() - start:.2f} s"
    )
    start = time.perf_counter()
    solve(HNW, "dop853", rtol=1e-8, atol=1e-11, specialize=True)
    print(
        "first specialized call (compiles the loop for this right-hand side): "
        f"{time.perf_counter() - start:.2f} s\n"
    )
    adaptive = fastest_adaptive()
    print(f"HNW rigid body, t = {T:g}, time to reach error <= {TARGET:g} (solve(), from Python):")
    for label, (m, rtol, seconds, err) in adaptive.items():
        print(f"  {m:20s} rtol {rtol:8.1e}  error {err:8.2e}  {seconds * 1e6:10.1f} us")
    ours = min((v for k, v in adaptive.items() if not k.startswith("scipy")), key=lambda v: v[2])
    n, limit_s, limit_err = hand_written_limit()
    print(f"  {'hand-written':20s} {n:4d} fixed steps error {limit_err:8.2e}  {limit_s * 1e6:10.1f} us")
    adaptive_s, adaptive_err, steps, rejected = hand_written_adaptive(ours[1])
    print(
        f"  {'hand-written adaptive':20s} rtol {ours[1]:8.1e}  error {adaptive_err:8.2e}  "
        f"{adaptive_s * 1e6:10.1f} us"
        f"   ({steps} steps, {rejected} rejected)"
    )
    print(
        f"\n  best of ours ({ours[0]}) vs solve_ivp DOP853: {adaptive['scipy:DOP853'][2] / ours[2]:7.1f}x "
        "faster"
        "   (goal >= 100x)"
    )
    print(
        "  plain dop853 vs solve_ivp DOP853:                 "
        f"{adaptive['scipy:DOP853'][2] / adaptive['dop853'][2]:7.1f}x"
    )
    print(
        f"  best of ours vs hand-written limit:               {ours[2] / limit_s:7.2f}x slower   (goal <= 2x)"
    )
    print(
        f"  best of ours vs hand-written adaptive, same rtol:  {ours[2] / adaptive_s:7.2f}x slower   (goal "
        "<= 1.3x)"
    )
    per = batch()
    print("\nA batch of 1000 trajectories (HNW body, perturbed starts, rtol 1e-10), time per trajectory:")
    for label, seconds in per.items():
        print(f"  {label:36s} {seconds * 1e6:9.1f} us")
    best_batch = per["ours, one batch call, specialized"]
    print(
        "\n  batch (specialized) vs solve_ivp one at a time:   "
        f"{per['solve_ivp DOP853, one call each'] / best_batch:6.1f}x"
        "   (goal >= 10x)"
    )
    print(
        "  batch (specialized) vs ours one at a time (plain): "
        f"{per['ours, one call each'] / best_batch:6.1f}x"
    )
    print(
        "  batch (specialized) vs ours one at a time (spec.): "
        f"{per['ours, one call each, specialized'] / best_batch:6.1f}x"
    )
    print()
    print_door()


# The compiled paths, through the public interface only (the same in every commit since it was written).
PATHS = """
import json, sys
import numpy as np
from classical_dynamics.models import rigid_body as rhs
from classical_dynamics.solvers import references as ref
from classical_dynamics.solvers.ode import Events, Problem, solve, solve_batch
from classical_dynamics.solvers.timing import min_time
from classical_dynamics.solvers.runge_kutta import rhs_function

@rhs_function
def q_zero(t, y, p, out):
    out[0] = y[1]

a = rhs.euler_coefficients(ref.HNW_I)
hnw = Problem(rhs.euler_free, ref.HNW_Y0, (0.0, 20.0), a)
Y0 = ref.HNW_Y0 + 0.05 * np.random.default_rng(1).standard_normal((200, 3))
tol = dict(rtol=1e-10, atol=1e-13)
calls = {
    "final state, dop853": lambda: solve(hnw, "dop853", **tol),
    "final state, dop853 specialized": lambda: solve(hnw, "dop853", specialize=True, **tol),
    "final state, dopri5": lambda: solve(hnw, "dopri5", **tol),
    "full loop, dense output at 200 times": lambda: solve(
        hnw, "dop853", t_eval=np.linspace(0, 20, 200), **tol),
    "full loop, events (q = 0)": lambda: solve(hnw, "dop853", events=Events(q_zero, 1), **tol),
    "batch of 200, final states": lambda: solve_batch(rhs.euler_free, Y0, (0.0, 20.0), a, **tol),
    "batch of 200, dense output": lambda: solve_batch(
        rhs.euler_free, Y0, (0.0, 20.0), a, t_eval=np.linspace(0, 20, 50), **tol),
}
out = {}
for name, call in calls.items():
    call()
    out[name] = min_time(call, repeats=200 if "batch" not in name else 10, budget_s=1.0)[0]
print(json.dumps(out))
"""


# Geometric fixed-step methods: through the door where the tree has one, else through the functions it
# replaced (same kernels, same steps): the door's cost and the kernels' speed against a tree from before it.
FIXED_PATHS = """
import json
import numpy as np
from classical_dynamics.models import earth
from classical_dynamics.models import precession as prec
from classical_dynamics.solvers import rattle, rigid_body, symplectic
from classical_dynamics.solvers import references as ref
from classical_dynamics.solvers.timing import min_time

I, m0, q0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0, np.array([1.0, 0.0, 0.0, 0.0])
model = prec.assemble(earth.H_P03, 84381.406 * earth.ARCSEC, prec.modern(),
                      {e: {} for e in ("solar_torque", "lunar_torque", "orbit_eccentricity")})
pm0, pq0 = prec.initial_state(model, True)
n = 4
chain_q = rattle.positions_from_angles(np.full(n, 0.3), 1.0 / n)
try:
    from classical_dynamics.models import linear
    from classical_dynamics.solvers.fixed_step import FixedProblem, Save, solve_fixed
    body = FixedProblem(rigid_body.packed(m0, q0), I)
    earth_body = FixedProblem(rigid_body.packed(pm0, pq0), np.r_[1.0 - model.H, 1.0, model.parameters()],
                              prec.torque_body)
    oscillator = FixedProblem([1.0, 0.0], [1.0], linear.harmonic_force)
    chain = FixedProblem(np.r_[chain_q.ravel(), np.zeros(2 * n)], np.r_[1.0 / n, 9.81, np.full(n, 1.0 / n)])
    calls = {
        "rigid-splitting4, 1e5 steps, final": lambda: solve_fixed(
            body, "rigid-splitting4", h=0.01, n_steps=100000, save=Save(final=True)),
        "rigid-splitting2, 1e5 steps, every 10th": lambda: solve_fixed(
            body, "rigid-splitting2", h=0.01, n_steps=100000, save=Save(every=10)),
        "symmetric-torqued2, 1 yr at 3 h, daily": lambda: solve_fixed(
            earth_body, "symmetric-torqued2", h=0.125, n_steps=2922, save=Save(every=8)),
        "stormer-verlet, 1e5 steps, every step": lambda: solve_fixed(
            oscillator, "stormer-verlet", h=0.01, n_steps=100000),
        "rattle 4 particles, 1e4 steps, every 10th": lambda: solve_fixed(
            chain, "rattle", h=1e-3, n_steps=10000, save=Save(every=10)),
    }
except ImportError:  # a tree from before the door
    one = np.array([1.0])
    calls = {
        "rigid-splitting4, 1e5 steps, final": lambda: rigid_body.free_body(I, m0, 0.01, 100000, 4, 100000),
        "rigid-splitting2, 1e5 steps, every 10th": lambda: rigid_body.free_body(I, m0, 0.01, 100000, 2, 10),
        "symmetric-torqued2, 1 yr at 3 h, daily": lambda: rigid_body.integrate_symmetric_torqued(
            1.0 - model.H, 1.0, pm0, pq0, 0.125, 2922, 2, 8, prec.torque_body, model.parameters()),
        "stormer-verlet, 1e5 steps, every step": lambda: symplectic.integrate(
            symplectic.harmonic, one, one, np.array([0.0]), 0.01, 100000, 2, 1),
        "rattle 4 particles, 1e4 steps, every 10th": lambda: rattle.integrate(
            chain_q, np.zeros((n, 2)), np.full(n, 1.0 / n), 1.0 / n, 9.81, 1e-3, 10000, 10),
    }
out = {}
for name, call in calls.items():
    call()
    out[name] = min_time(call, repeats=20, budget_s=1.0)[0]
print(json.dumps(out))
"""


def paths_in(tree: Path) -> dict:
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    out = {}
    with tempfile.TemporaryDirectory() as tmp:  # a file: numba caches the event function beside it
        for name, text in (("solver_paths.py", PATHS), ("fixed_paths.py", FIXED_PATHS)):
            script = Path(tmp) / name
            script.write_text(text)
            done = subprocess.run(
                [sys.executable, str(script)], cwd=tree, env=env, capture_output=True, text=True
            )
            if done.returncode != 0:
                raise SystemExit(done.stderr)
            out.update(json.loads(done.stdout.splitlines()[-1]))
    return out


def against(rev: str) -> None:
    root = Path(__file__).resolve().parents[1]
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp) / "base"
        subprocess.run(
            ["git", "worktree", "add", "--detach", str(base), rev], cwd=root, check=True, capture_output=True
        )
        try:
            paths_in(base), paths_in(root)  # compile (or load) both trees' loops first
            runs = {"base": [], "here": []}
            for _ in range(3):
                runs["base"].append(paths_in(base))
                runs["here"].append(paths_in(root))
        finally:
            subprocess.run(["git", "worktree", "remove", "--force", str(base)], cwd=root, capture_output=True)
    best = {k: {name: min(r[name] for r in v) for name in v[0]} for k, v in runs.items()}
    print(f"machine: {software_stamp()}")
    print("HNW rigid body to t = 20, rtol 1e-10: minimum of three alternating runs, each its own process;")
    print(
        "the fixed-step methods (FIXED_PATHS) through the door, or in a tree without one what it replaced\n"
    )
    print(f"{'compiled path':40s} {rev[:10]:>12s} {'this tree':>12s} {'ratio':>7s}")
    for name in best["base"]:
        b, h = best["base"][name], best["here"][name]
        print(f"{name:40s} {b * 1e6:9.1f} us {h * 1e6:9.1f} us {h / b:7.3f}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--against", metavar="REV", help="time the compiled paths here and at this commit")
    parser.add_argument("--door", action="store_true", help="the fixed-step door against its kernels only")
    args = parser.parse_args()
    against(args.against) if args.against else print_door() if args.door else main()
