"""One interface for every integrator: a Problem, a method, tolerances or a step, dense output, events.

    problem = Problem(rhs, y0, (t0, t1), params)       # rhs: numba f(t, y, p, out)
    sol = solve(problem, "dop853", rtol=1e-10, atol=1e-13, t_eval=..., events=Events(g, 1))
    sol = solve(problem, "scipy:DOP853", rtol=..., atol=...)   # the peers, through the same door

Methods: dopri5, dop853 (compiled, adaptive, dense output, events, blow-up detection) and
scipy:RK45, scipy:DOP853, scipy:Radau, scipy:BDF, scipy:LSODA, scipy:RK23. The geometric fixed-step
methods (Stormer-Verlet, RATTLE, the rigid body's splittings) need the problem's structure: their door is
fixed_step.solve_fixed, which returns the same Solution.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
from numba import njit

from . import runge_kutta as rk

EPS = np.finfo(float).eps
_NO_TIMES = np.zeros(0)
_NO_TIMES.flags.writeable = False
_NO_EVENTS = np.zeros(0, dtype=np.int64)
_NO_EVENTS.flags.writeable = False
_NO_ROWS: dict = {}


def _no_rows(n: int) -> np.ndarray:
    """An empty (0, n) array, read-only and shared: the final-state path's empty outputs, unallocated."""
    if n not in _NO_ROWS:
        _NO_ROWS[n] = np.zeros((0, n))
        _NO_ROWS[n].flags.writeable = False
    return _NO_ROWS[n]


RTOL_FLOOR = 100 * EPS  # below this a double cannot honour rtol (scipy clamps it silently)
COMPILED = ("dopri5", "dop853")
PEERS = ("scipy:RK45", "scipy:DOP853", "scipy:Radau", "scipy:BDF", "scipy:LSODA", "scipy:RK23")


@dataclass(frozen=True)
class Problem:
    rhs: Callable  # numba-compiled f(t, y, p, out)
    y0: np.ndarray
    t_span: tuple
    params: np.ndarray = field(default_factory=lambda: np.zeros(0))
    name: str = ""

    def __post_init__(self):
        """A problem that cannot be integrated is refused when it is made, with a clear message."""
        object.__setattr__(self, "y0", np.ascontiguousarray(self.y0, dtype=float))
        object.__setattr__(self, "params", np.ascontiguousarray(self.params, dtype=float))
        require_signature(self.rhs)
        if not np.isfinite(self.y0).all():
            raise ValueError(f"initial state is not finite: {self.y0}")
        t0, t1 = map(float, self.t_span)
        if not (np.isfinite(t0) and np.isfinite(t1)):
            raise ValueError(f"time span must be finite, got {self.t_span}")
        if t1 <= t0:
            raise ValueError(f"t_end = {t1} is not after t0 = {t0}: integrate forward in time")
        object.__setattr__(self, "t_span", (t0, t1))


def require_signature(func):
    """The integrators take f(t, y, p, out) compiled with RHS_SIG (see runge_kutta.rhs_function)."""
    if rk.RHS_SIG.args not in getattr(func, "signatures", []):
        raise TypeError(
            f"{getattr(func, '__name__', func)} must be compiled with the integrators' signature: "
            "decorate it with classical_dynamics.solvers.runge_kutta.rhs_function"
        )


@dataclass(frozen=True)
class Events:
    g: Callable  # numba g(t, y, p, out) filling n values
    n: int
    directions: tuple = ()  # +1 upward only, -1 downward only, 0 both (default)
    terminal: tuple = ()


@dataclass
class Solution:
    status: str
    t: float  # where the run ended (t1, a terminal event, or the blow-up time)
    y: np.ndarray
    t_eval: np.ndarray
    y_eval: np.ndarray
    nfev: int
    n_steps: int
    n_rejected: int
    t_steps: np.ndarray
    y_steps: np.ndarray
    event_t: np.ndarray
    event_y: np.ndarray
    event_index: np.ndarray
    method: str
    # what a method measures beside the state, by name (fixed_step.py lists them per method); empty here
    extra: dict = field(default_factory=dict)

    @property
    def success(self) -> bool:
        return self.status in ("success", "terminal event")


def check_inputs(rtol=None, atol=None, h=None):
    """Refuse tolerances or steps that cannot be honoured (the problem checked itself when it was made);
    nothing is clamped silently."""
    if rtol is not None:
        if not (rtol > 0 and atol is not None and atol > 0):
            raise ValueError(f"tolerances must be positive, got rtol={rtol}, atol={atol}")
        if rtol < RTOL_FLOOR:
            raise ValueError(
                f"rtol={rtol:g} is below 100*eps = {RTOL_FLOOR:.3g}, which double precision cannot "
                "honour (scipy would silently clamp it); use an exact reference or mpmath instead"
            )
    if h is not None and not h > 0:
        raise ValueError(f"step size must be positive, got h={h}")


def solve(
    problem: Problem,
    method: str = "dop853",
    *,
    rtol: float = 1e-8,
    atol: float = 1e-11,
    t_eval=None,
    events: Events | None = None,
    max_steps: int = 10**8,
    bound: float = 1e12,
    subdivisions: int = 8,
    record_steps: bool = False,
    specialize: bool = False,
) -> Solution:
    """Integrate `problem` with `method`. With no t_eval, events or step record the final-state loop runs
    (the same steps, without the machinery); specialize=True compiles it for this right-hand side (see
    runge_kutta.specialized_final_state): the fastest path, for sweeps and benchmarks."""
    check_inputs(rtol, atol)
    t0, t1 = problem.t_span
    if method not in rk.TABLEAUS and method not in PEERS:
        raise ValueError(f"unknown method {method!r}; known: {', '.join(COMPILED + PEERS)}")
    if t_eval is None and events is None and not record_steps and method in rk.TABLEAUS:
        # the final state only: the lean loop, and as little Python around it as possible
        control = (float(rtol), float(atol), int(max_steps), float(bound))
        if specialize:
            run = rk.specialized_final_state(problem.rhs, problem.y0.size)
            status, t, y, nfev, nacc, nrej = run(
                rk.METHOD_INDEX[method], problem.params, t0, t1, problem.y0, *control
            )
        else:
            start = (problem.params, t0, t1, problem.y0)
            status, t, y, nfev, nacc, nrej = rk.final_state(
                problem.rhs, start, rk.TABLEAUS[method].steps, control
            )
        if status != rk.BLOW_UP:  # a blow-up is located on the dense output by the full loop below
            rows = _no_rows(y.size)
            return Solution(
                rk.STATUS[status],
                t,
                y,
                _NO_TIMES,
                rows,
                nfev,
                nacc,
                nrej,
                _NO_TIMES,
                rows,
                _NO_TIMES,
                rows,
                _NO_EVENTS,
                method,
            )
    t_eval = np.zeros(0) if t_eval is None else np.ascontiguousarray(t_eval, dtype=float)
    if t_eval.size and (np.any(np.diff(t_eval) < 0) or t_eval[0] < t0 or t_eval[-1] > t1):
        raise ValueError("t_eval must be increasing and inside the time span")
    if method in PEERS:
        return _solve_scipy(problem, method, rtol, atol, t_eval, events, record_steps)
    tableau = rk.TABLEAUS[method]
    g, n_events = (events.g, events.n) if events else (rk._no_events, 0)
    require_signature(g)
    directions = np.array(events.directions or (0,) * n_events if events else (0,), dtype=np.int64)
    terminal = np.array(events.terminal or (False,) * n_events if events else (False,), dtype=np.bool_)
    # the right-hand side goes in as itself (numba's direct calling convention, the fast path per call);
    # the event function by address (usually the no-op: converting it at every call would cost ~20 us)
    out = rk.integrate(
        problem.rhs,
        rk.by_address(g),
        (problem.params, t0, t1, problem.y0),
        tableau.pair,
        (float(rtol), float(atol), int(max_steps), float(bound)),
        (n_events, directions, terminal, int(subdivisions)),
        (t_eval, bool(record_steps)),
    )
    status, t, y, y_eval, nfev, nacc, nrej, ts, ys, et, ey, ei = out
    return Solution(rk.STATUS[status], t, y, t_eval, y_eval, nfev, nacc, nrej, ts, ys, et, ey, ei, method)


def _solve_scipy(problem, method, rtol, atol, t_eval, events, record_steps):
    from scipy.integrate import solve_ivp

    p = problem.params
    rhs = problem.rhs

    def fun(t, y):
        y = np.ascontiguousarray(y, dtype=float)  # scipy may pass a strided view
        out = np.empty_like(y)
        rhs(t, y, p, out)
        return out

    scipy_events = None
    if events is not None:

        def make(e):
            def event(t, y):
                out = np.empty(events.n)
                events.g(t, np.ascontiguousarray(y, dtype=float), p, out)
                return out[e]

            event.terminal = bool(events.terminal[e]) if events.terminal else False
            event.direction = float(events.directions[e]) if events.directions else 0.0
            return event

        scipy_events = [make(e) for e in range(events.n)]
    result = solve_ivp(
        fun,
        problem.t_span,
        problem.y0,
        method=method.split(":")[1],
        rtol=rtol,
        atol=atol,
        t_eval=t_eval if t_eval.size else None,
        events=scipy_events,
        dense_output=False,
    )
    n = problem.y0.size
    y_eval = result.y.T if t_eval.size else np.zeros((0, n))
    ev_t, ev_y, ev_i = [], [], []
    if events is not None:
        for e, (te, ye) in enumerate(zip(result.t_events, result.y_events)):
            ev_t += list(te)
            ev_y += list(ye)
            ev_i += [e] * len(te)
    order = np.argsort(ev_t) if ev_t else np.zeros(0, dtype=int)
    status = {0: "success", 1: "terminal event", -1: "failed"}[result.status]
    t_steps = result.t if (record_steps and not t_eval.size) else np.zeros(0)
    y_steps = result.y.T if (record_steps and not t_eval.size) else np.zeros((0, n))
    return Solution(
        status,
        float(result.t[-1]),
        result.y[:, -1].copy(),
        t_eval,
        y_eval,
        int(result.nfev),
        len(result.t) - 1,
        0,
        t_steps,
        y_steps,
        np.asarray(ev_t)[order],
        np.asarray(ev_y).reshape(-1, n)[order],
        np.asarray(ev_i, dtype=int)[order],
        method,
    )


def compile_time(problem: Problem, method: str = "dop853") -> float:
    """Seconds the first call takes beyond a warm call (compilation or cache load), reported apart."""
    short = Problem(problem.rhs, problem.y0, (problem.t_span[0], problem.t_span[0] + 1e-3), problem.params)
    start = time.perf_counter()
    solve(short, method, rtol=1e-6, atol=1e-9)
    first = time.perf_counter() - start
    start = time.perf_counter()
    solve(short, method, rtol=1e-6, atol=1e-9)
    return first - (time.perf_counter() - start)


@njit((rk.FUNC, rk.ROWS, rk.PAIR, rk.CONTROL, rk.VEC), cache=True)
def _batch(f, rows, pair, control, t_eval):
    """The full loop over the rows of Y0 (and of P), rows = (P, t0, t1, Y0), saving the states at t_eval."""
    P, t0, t1, Y0 = rows
    m, n = Y0.shape
    out = np.full((m, t_eval.size, n), np.nan)
    final = np.empty((m, n))
    status = np.empty(m, dtype=np.int64)
    t_end = np.empty(m)
    no_events = (0, np.zeros(1, dtype=np.int64), np.zeros(1, dtype=np.bool_), 1)
    for i in range(m):
        r = rk.integrate(f, rk._no_events, (P[i], t0, t1, Y0[i]), pair, control, no_events, (t_eval, False))
        status[i], t_end[i], final[i], out[i] = r[0], r[1], r[2], r[3]
    return status, t_end, final, out


def solve_batch(
    rhs,
    Y0,
    t_span,
    params,
    method="dop853",
    *,
    rtol=1e-8,
    atol=1e-11,
    t_eval=None,
    bound=1e12,
    specialize=False,
):
    """Many initial conditions (rows of Y0; params one row each or shared) in one compiled call.

    Without t_eval only the final states are computed, by the final-state loop (specialize=True: compiled
    for this right-hand side, the rows shared out over the cores); a row that blows up is rerun alone by
    the full loop, which locates the blow-up. Returns (statuses, end times, final states, states at t_eval).
    """
    require_signature(rhs)
    Y0 = np.ascontiguousarray(Y0, dtype=float)
    P = np.atleast_1d(np.asarray(params, dtype=float))
    # writable: numba's type
    P = np.array(np.broadcast_to(P, (Y0.shape[0], P.shape[-1])), dtype=float, order="C")
    for row in Y0:
        Problem(rhs, row, t_span)  # checks the state and the span
    check_inputs(rtol, atol)
    t_eval = np.zeros(0) if t_eval is None else np.ascontiguousarray(t_eval, dtype=float)
    t0, t1 = float(t_span[0]), float(t_span[1])
    rows, tableau = (P, t0, t1, Y0), rk.TABLEAUS[method]
    control = (float(rtol), float(atol), 10**8, float(bound))
    if t_eval.size:
        status, t_end, final, out = _batch(rhs, rows, tableau.pair, control, t_eval)
        return [rk.STATUS[s] for s in status], t_end, final, out
    if specialize:
        status, t_end, final = rk.specialized_final_state_rows(rhs)(rows, tableau.steps, control)
    else:
        status, t_end, final = rk.final_state_rows(rhs, rows, tableau.steps, control)
    for i in np.nonzero(status == rk.BLOW_UP)[0]:
        # the full loop, which locates the blow-up
        sol = solve(
            Problem(rhs, Y0[i], (t0, t1), P[i]), method, rtol=rtol, atol=atol, bound=bound, record_steps=True
        )
        status[i], t_end[i], final[i] = rk.BLOW_UP, sol.t, sol.y
    return [rk.STATUS[s] for s in status], t_end, final, np.zeros((Y0.shape[0], 0, Y0.shape[1]))
