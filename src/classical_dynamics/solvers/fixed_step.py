"""One door to the fixed-step geometric integrators: a method by name, a step, what to save; one Solution.

    problem = FixedProblem(y0, params, force)     # the physics: packed state, parameters, force or torque
    sol = solve_fixed(problem, "rigid-splitting4", h=1e-3, n_steps=2000, save=Save(every=10))
    sol.t_eval, sol.y_eval                         # the saved steps: their times and packed states
    sol = solve_fixed(problem, "stormer-verlet", h=0.1, n_steps=600, save=Save(final=True))  # sol.y only

The adaptive methods have their door in ode.solve (a right-hand side, tolerances, dense output, events). These
methods need the problem's structure (a separable Hamiltonian, link constraints, a rigid body's exact
rotations), so the problem gives its pieces rather than one right-hand side. As in scipy's integrate/_ivp (one
small interface that every method fills in) and diffrax (the terms, the solver, the step and the output as
separate small objects): FixedProblem holds the physics, METHODS the compiled kernels by name, h and n_steps
the step, Save what is kept. The door checks the inputs and makes one compiled call: the kernels are the loops
symplectic.integrate, rattle.integrate and rigid_body.integrate_*, which no study calls directly.

Methods, their state y (packed in one vector), params and force:

    name                  order  y                                params              force
    stormer-verlet        2      (q, v): d coordinates, d speeds  the force's p       accel(q, p, out): q''
    yoshida4              4      (q, v)                           the force's p       accel(q, p, out)
    rattle                2      (q, p) of n particles in the     (a, g, m_1..m_n)    none (gravity g,
                                 plane: x_0, y_0, x_1, ..., then                      links of length a
                                 px_0, py_0, ...                                      from 0)
    rigid-splitting2, 4   2, 4   (m, q): body angular momentum,   (I_1, I_2, I_3)     none (free body)
                                 unit quaternion body to space
    rigid-torqued2, 4     2, 4   (m, q)                           (I_1, I_2, I_3, p)  torque(t, m, q, p, out)
    symmetric-torqued2, 4 2, 4   (m, q), A = B                    (A, C, p)           torque(t, q, p, out),
                                                                                      rhs_function-compiled
    (p: the force's or torque's own parameters, after the structure's)

Every method returns ode.Solution: t_eval the saved times t0 + i h (i the step's index), y_eval the saved
states (rows; none with Save(final=True)), y and t the final state and time whatever was saved, n_steps,
nfev the evaluations of the force or torque (0 for the methods that call none), n_rejected 0, no separate
step record (Save(every=1) is one) and no events. What a method measures beside the state is in
Solution.extra:

    rattle: tip_x       the last particle's x at every step (its zero crossings give the frequency)
            energy      the energy at the start and at each saved step (the start and the end with final)
            constraint  the largest | |q_j - q_{j-1}| - a | over the saved steps after the start

rigid_body.invariant_errors (the running maxima of the free body's energy and Casimir errors over blocks of
steps, no state stored) stays a named measurement beside the door; its docstring says why.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from . import rattle, rigid_body, symplectic
from .ode import _NO_EVENTS, _NO_TIMES, Solution, require_signature


@dataclass(frozen=True)
class FixedProblem:
    """The physics a fixed-step method integrates: the packed state y0, the parameters, the force or torque
    (a numba function, for the methods that take one) and the start time. Each method's table row above says
    what y0, params and force are."""

    y0: np.ndarray
    params: np.ndarray = ()
    force: Callable | None = None
    t0: float = 0.0
    name: str = ""

    def __post_init__(self):
        object.__setattr__(self, "y0", np.ascontiguousarray(self.y0, dtype=float))
        object.__setattr__(self, "params", np.ascontiguousarray(self.params, dtype=float))
        object.__setattr__(self, "t0", float(self.t0))
        if self.y0.ndim != 1 or not self.y0.size:
            raise ValueError(f"the state must be one non-empty vector, got shape {self.y0.shape}")
        if not np.isfinite(self.y0).all():
            raise ValueError(f"initial state is not finite: {self.y0}")
        if not np.isfinite(self.params).all():
            raise ValueError(f"parameters are not finite: {self.params}")
        if not np.isfinite(self.t0):
            raise ValueError(f"start time is not finite: {self.t0}")


@dataclass(frozen=True)
class Save:
    """What the run keeps: the state every `every` steps (the start, step every, 2 every, ...; every=1: each
    step), or with final=True the final state only (no rows). Times off the step grid and events are the
    adaptive door's (ode.solve, dense output)."""

    every: int = 1
    final: bool = False

    def __post_init__(self):
        if isinstance(self.every, bool) or not isinstance(self.every, (int, np.integer)) or self.every < 1:
            raise ValueError(f"Save(every=...) must be a whole number of steps >= 1, got {self.every!r}")
        if self.final and self.every != 1:
            raise ValueError("Save(final=True) keeps the final state only: give no 'every' with it")


@dataclass(frozen=True)
class Method:
    name: str
    order: int
    force: str  # what the problem's force is ("" when the method takes none)
    run: Callable  # (problem, h, n_steps, every) -> (rows, final state, nfev, extra)
    check: Callable  # (problem) -> None; raises ValueError on a problem the method cannot take


def _need(condition, method, message):
    if not condition:
        raise ValueError(f"{method}: {message}")


def _verlet(order):
    name = "stormer-verlet" if order == 2 else "yoshida4"

    def check(problem):
        _need(problem.y0.size % 2 == 0, name, f"the state is (q, v), of even size; got {problem.y0.size}")

    def run(problem, h, n_steps, every):
        d = problem.y0.size // 2
        y0 = problem.y0
        rows, final = symplectic.integrate(
            problem.force, problem.params, y0[:d], y0[d:], h, n_steps, order, every
        )
        return rows, final, 1 + n_steps * (1 if order == 2 else 3), {}

    return Method(name, order, "accel(q, p, out)", run, check)


def _rattle_check(problem):
    n = problem.y0.size // 4
    _need(
        problem.y0.size == 4 * n and n > 0, "rattle", "the state is (q, p) of n planar particles, 4n numbers"
    )
    _need(problem.params.size == 2 + n, "rattle", f"params are (a, g, m_1 .. m_{n}): {2 + n} numbers")
    a, masses = problem.params[0], problem.params[2:]
    _need(a > 0 and np.all(masses > 0), "rattle", "the link length and the masses must be positive")


def _rattle_run(problem, h, n_steps, every):
    n = problem.y0.size // 4
    q0 = problem.y0[: 2 * n].reshape(n, 2)
    p0 = problem.y0[2 * n :].reshape(n, 2)
    a, g, masses = problem.params[0], problem.params[1], problem.params[2:]
    rows, final, tip_x, energies, constraint = rattle.integrate(q0, p0, masses, a, g, h, n_steps, every)
    return rows, final, 0, {"tip_x": tip_x, "energy": energies, "constraint": constraint}


def _rigid_check(name, n_params, exact=False):
    def check(problem):  # in plain Python on lists: a few numbers, checked at every call
        y, size = problem.y0.tolist(), problem.params.size
        _need(len(y) == 7, name, "the state is (m, q): 7 numbers")
        _need(size == n_params if exact else size >= n_params, name, f"params: {n_params} moments of inertia")
        _need(min(problem.params[:n_params].tolist()) > 0, name, "the moments of inertia must be positive")
        _need(
            abs(math.sqrt(sum(c * c for c in y[3:])) - 1) < 1e-12,
            name,
            "the attitude quaternion must be a unit one",
        )

    return check


def _rigid_free(order):
    def run(problem, h, n_steps, every):
        y0, I = problem.y0, problem.params
        rows, final = rigid_body.integrate_free(I, y0[:3], y0[3:], h, n_steps, order, every)
        return rows, final, 0, {}

    name = f"rigid-splitting{order}"
    return Method(name, order, "", run, _rigid_check(name, 3, exact=True))


def _rigid_torqued(order):
    def run(problem, h, n_steps, every):
        y0, p = problem.y0, problem.params
        rows, final = rigid_body.integrate_torqued(
            p[:3], y0[:3], y0[3:], problem.t0, h, n_steps, order, every, problem.force, p[3:]
        )
        return rows, final, 4 * n_steps * (1 if order == 2 else 3), {}

    name = f"rigid-torqued{order}"
    return Method(name, order, "torque(t, m, q, p, out)", run, _rigid_check(name, 3))


def _symmetric_torqued(order):
    name = f"symmetric-torqued{order}"
    base = _rigid_check(name, 2)

    def check(problem):
        base(problem)
        require_signature(problem.force)

    def run(problem, h, n_steps, every):
        y0, p = problem.y0, problem.params
        rows, final = rigid_body.integrate_symmetric_torqued(
            p[0], p[1], y0[:3], y0[3:], problem.t0, h, n_steps, order, every, problem.force, p[2:]
        )
        return rows, final, 1 + n_steps * (1 if order == 2 else 3), {}

    return Method(name, order, "torque(t, q, p, out), rhs_function", run, check)


METHODS = {
    m.name: m
    for m in (
        _verlet(2),
        _verlet(4),
        Method("rattle", 2, "", _rattle_run, _rattle_check),
        _rigid_free(2),
        _rigid_free(4),
        _rigid_torqued(2),
        _rigid_torqued(4),
        _symmetric_torqued(2),
        _symmetric_torqued(4),
    )
}


def solve_fixed(
    problem: FixedProblem, method: str, *, h: float, n_steps: int, save: Save = Save()
) -> Solution:
    """n_steps steps of size h of `method` from problem.y0 at problem.t0; keeps what `save` says."""
    if method not in METHODS:
        raise ValueError(f"unknown fixed-step method {method!r}; known: {', '.join(METHODS)}")
    spec = METHODS[method]
    if not (isinstance(h, (float, int, np.floating, np.integer)) and math.isfinite(h) and h > 0):
        raise ValueError(f"step size must be positive and finite, got h={h!r}")
    if isinstance(n_steps, bool) or not isinstance(n_steps, (int, np.integer)) or n_steps < 1:
        raise ValueError(f"n_steps must be a whole number >= 1, got {n_steps!r}")
    if spec.force and problem.force is None:
        raise ValueError(f"{method} needs a force: {spec.force}")
    if not spec.force and problem.force is not None:
        raise ValueError(f"{method} takes no force (the problem gives one)")
    spec.check(problem)
    h, n_steps = float(h), int(n_steps)
    every = n_steps if save.final else int(save.every)
    rows, final, nfev, extra = spec.run(problem, h, n_steps, every)
    t0 = problem.t0
    if save.final:
        t_eval, rows = _NO_TIMES, rows[:0]
    else:
        # the kernels' clock: the step's index (exact in a double) times h, one rounding
        t_eval = np.arange(0, every * rows.shape[0], every, dtype=float)
        t_eval *= h
        if t0:
            t_eval += t0
    empty = rows[:0]
    return Solution(
        "success",
        t0 + h * n_steps,
        final,
        t_eval,
        rows,
        nfev,
        n_steps,
        0,
        _NO_TIMES,
        empty,
        _NO_TIMES,
        empty,
        _NO_EVENTS,
        method,
        extra,
    )
