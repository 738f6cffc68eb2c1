"""Unit tests of solvers/runge_kutta.py, ode.py and rigid_body.py against references they do not compute:
the Butcher order conditions (exact rationals of the rooted trees), the exact solution exp(lambda t) of a
linear ODE, the blow-up time 1/y0 of y' = y^2, and scipy's RK45, DOP853 and solve_ivp events."""

from fractions import Fraction

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from classical_dynamics.solvers import rigid_body
from classical_dynamics.solvers import runge_kutta as rk
from classical_dynamics.solvers.fixed_step import FixedProblem, Save, solve_fixed
from classical_dynamics.solvers.ode import Events, Problem, check_inputs, compile_time, solve


@rk.rhs_function
def rotation_decay(t, y, p, out):
    """y' = A y with A = [[-a, -w], [w, -a]]: y(t) = e^{-a t} R(w t) y0, p = (a, w)."""
    out[0] = -p[0] * y[0] - p[1] * y[1]
    out[1] = p[1] * y[0] - p[0] * y[1]


@rk.rhs_function
def square(t, y, p, out):
    """y' = y^2: y = y0/(1 - y0 t), infinite at t = 1/y0."""
    out[0] = y[0] * y[0]


@rk.rhs_function
def height(t, y, p, out):
    """The event g = y[0] of rotation_decay: the first component's zeros."""
    out[0] = y[0]


def _exact(t, a=0.3, w=2.0, y0=(1.0, 0.5)):
    c, s = np.cos(w * t), np.sin(w * t)
    return np.exp(-a * t) * np.array([c * y0[0] - s * y0[1], s * y0[0] + c * y0[1]])


# --- the tableaus: Butcher's order conditions ------------------------------------------------------------


def _trees(order):
    """Order conditions up to `order` as (function of (A, b, c), exact value): b^T c^(k-1) = 1/k (bushy
    trees), b^T A c^(k-2) = 1/(k(k-1)), b^T (c * A c^(k-3)) = 1/(k(k-2)) and the tall tree b^T A^(k-1) 1 =
    1/k!; every condition of order <= 4 is among these."""
    conditions = []
    for k in range(1, order + 1):
        conditions.append((lambda A, b, c, k=k: b @ c ** (k - 1), Fraction(1, k)))
        if k >= 2:
            conditions.append((lambda A, b, c, k=k: b @ A @ c ** (k - 2), Fraction(1, k * (k - 1))))
        if k >= 3:
            conditions.append((lambda A, b, c, k=k: b @ (c * (A @ c ** (k - 3))), Fraction(1, k * (k - 2))))
            factorial = np.prod(range(1, k + 1))
            conditions.append(
                (
                    lambda A, b, c, k=k: b @ np.linalg.matrix_power(A, k - 1) @ np.ones(len(c)),
                    Fraction(1, factorial),
                )
            )
    return conditions


@pytest.mark.parametrize("tableau", [rk.DOPRI5, rk.DOP853], ids=["dopri5", "dop853"])
def test_tableaus_satisfy_the_order_conditions_and_the_row_sums(tableau):
    s = tableau.B.size
    A = np.zeros((s, s))
    A[:, : min(s, tableau.A.shape[1])] = tableau.A[:s, :s]  # scipy stores RK45's A without the zero column
    b, c = tableau.B, tableau.C[:s]
    np.testing.assert_allclose(A.sum(axis=1), c, atol=1e-14)  # c_i = sum_j a_ij
    assert np.allclose(np.triu(A), 0.0)  # explicit
    for condition, value in _trees(tableau.order):
        assert condition(A, b, c) == pytest.approx(float(value), rel=1e-12, abs=1e-14)
    # the embedded estimate is a difference of two consistent methods: its weights sum to 0
    assert abs(tableau.E5.sum()) < 1e-14


@pytest.mark.parametrize("tableau,order", [(rk.DOPRI5, 5), (rk.DOP853, 8)], ids=["dopri5", "dop853"])
def test_one_step_error_on_y_equals_y_shrinks_as_h_to_the_order_plus_one(tableau, order):
    # y' = y from y(0) = 1: one step of size h leaves e^h - y1 = O(h^(p+1)); the stages from the module's
    # own _stages (run as Python), the exact value numpy's exp
    def f(t, y, p, out):
        out[0] = y[0]

    hs = np.array([0.4, 0.2, 0.1]) if order == 5 else np.array([0.8, 0.4, 0.2])
    errors = []
    for h in hs:
        K = np.zeros((tableau.B.size + 1, 1))
        y, y_new = np.ones(1), np.empty(1)
        K[0, 0] = 1.0
        rk._stages.py_func(f, np.zeros(0), 0.0, h, y, y_new, tableau.steps, (K, np.ones(1), np.empty(1)), 1)
        errors.append(abs(np.exp(h) - y_new[0]))
    slope = np.polyfit(np.log(hs), np.log(errors), 1)[0]
    assert slope == pytest.approx(order + 1, abs=0.3)


# --- the final-state loop, run as Python ---------------------------------------------------------------


@pytest.fixture
def python_loop(monkeypatch):
    """_final_state_loop with its compiled helpers replaced by their Python originals: the same lines run
    (and are measured), here against the compiled loop and the exact solutions."""
    for name in (
        "_final_state_steps",
        "_stages",
        "_error_norm",
        "_step_factor",
        "_max_abs",
        "_min_step",
        "_initial_step",
    ):
        monkeypatch.setattr(rk, name, getattr(rk, name).py_func)
    return rk._final_state_loop


def _control(rtol=1e-8, atol=1e-10, max_steps=10**6, bound=1e12):
    return (rtol, atol, max_steps, bound)


@pytest.mark.parametrize("method", ["dopri5", "dop853"])
def test_python_loop_takes_the_compiled_loops_steps_and_meets_exp(python_loop, method):
    steps = rk.TABLEAUS[method].steps
    problem = (np.array([0.3, 2.0]), 0.0, 3.0, np.array([1.0, 0.5]))
    status, t, y, nfev, naccept, nreject = python_loop(rotation_decay.py_func, problem, steps, _control())
    compiled = rk.final_state(rotation_decay, problem, steps, _control())
    assert status == rk.SUCCESS and t == 3.0
    assert (nfev, naccept, nreject) == tuple(compiled[3:])
    np.testing.assert_array_equal(y, compiled[2])
    np.testing.assert_allclose(y, _exact(3.0), rtol=1e-7)


def test_python_loop_reports_blow_up_max_steps_and_a_collapsing_step(python_loop):
    steps = rk.DOPRI5.steps
    start = (np.zeros(0), 0.0, 2.0, np.array([1.0]))
    # y' = y^2 from 1 is infinite at t = 1: the first step past |y| = 1e6 ends the run, at t < 1
    status, t, y, *_ = python_loop(square.py_func, start, steps, _control(bound=1e6))
    assert status == rk.BLOW_UP and 1.0 - 1e-5 < t < 1.0 and y[0] > 1e6 * 0.5
    status, t, *_ = python_loop(square.py_func, start, steps, _control(max_steps=5))
    assert status == rk.MAX_STEPS and t < 1.0
    # no bound: the steps shrink towards the singularity until they fall below the resolution of t
    status, t, *_ = python_loop(square.py_func, start, steps, _control(bound=np.inf))
    assert status == rk.STEP_TOO_SMALL and t == pytest.approx(1.0, abs=1e-6)


def test_error_norm_is_infinite_for_a_non_finite_state_and_zero_for_an_exact_step():
    K = np.zeros((rk.DOP853.B.size + 1, 1))
    control = _control()
    for tableau in (rk.DOPRI5, rk.DOP853):
        norm = rk._error_norm.py_func
        assert norm(tableau.steps, control, K, 0.1, np.ones(1), np.array([np.inf]), 1) == np.inf
        assert norm(tableau.steps, control, K, 0.1, np.ones(1), np.ones(1), 1) == 0.0


# --- ode.solve against scipy ---------------------------------------------------------------------------


@pytest.mark.parametrize("ours,theirs", [("dopri5", "RK45"), ("dop853", "DOP853")])
def test_compiled_pairs_match_scipys_on_the_linear_ode(ours, theirs):
    # the same pair and controller as scipy's: the same answer to well within the tolerance
    problem = Problem(rotation_decay, [1.0, 0.5], (0.0, 3.0), [0.3, 2.0])
    sol = solve(problem, ours, rtol=1e-9, atol=1e-12)
    ref = solve_ivp(
        lambda t, y: [-0.3 * y[0] - 2 * y[1], 2 * y[0] - 0.3 * y[1]],
        (0, 3),
        [1.0, 0.5],
        method=theirs,
        rtol=1e-9,
        atol=1e-12,
    )
    np.testing.assert_allclose(sol.y, ref.y[:, -1], rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(sol.y, _exact(3.0), rtol=1e-7)
    assert sol.n_steps == pytest.approx(ref.t.size - 1, rel=0.1)


def test_scipy_path_finds_the_events_and_records_the_steps():
    # y[0] = e^{-a t}(cos 2t - 0.5 sin 2t) vanishes where tan 2t = 2: t = (arctan 2 + k pi)/2
    problem = Problem(rotation_decay, [1.0, 0.5], (0.0, 3.0), [0.3, 2.0])
    zeros = (np.arctan(2.0) + np.pi * np.arange(2)) / 2
    for method in ("scipy:RK45", "dop853"):
        sol = solve(problem, method, rtol=1e-10, atol=1e-12, events=Events(height, 1), record_steps=True)
        np.testing.assert_allclose(sol.event_t, zeros, rtol=1e-8)
        assert sol.t_steps.size == sol.y_steps.shape[0] > 2 and sol.success
    terminal = solve(
        problem, "scipy:DOP853", rtol=1e-10, atol=1e-12, events=Events(height, 1, (-1,), (True,))
    )
    assert terminal.status == "terminal event" and terminal.t == pytest.approx(zeros[0], rel=1e-8)


def test_solve_locates_a_blow_up_and_refuses_what_it_cannot_do():
    problem = Problem(square, [2.0], (0.0, 1.0))
    sol = solve(problem, "dop853", rtol=1e-10, atol=1e-12, bound=1e8)
    assert sol.status == "blow-up" and sol.t == pytest.approx(0.5, abs=1e-6)  # y = 2/(1 - 2t)
    with pytest.raises(ValueError, match="unknown method"):
        solve(problem, "euler")
    with pytest.raises(ValueError, match="t_eval"):
        solve(problem, "dop853", t_eval=[0.5, 0.2])
    with pytest.raises(ValueError, match="below 100"):
        solve(problem, "dop853", rtol=1e-17)
    with pytest.raises(ValueError, match="step size"):
        check_inputs(h=0.0)
    with pytest.raises(ValueError, match="not after"):
        Problem(square, [1.0], (1.0, 0.0))
    with pytest.raises(ValueError, match="finite"):
        Problem(square, [np.nan], (0.0, 1.0))
    with pytest.raises(TypeError, match="signature"):
        Problem(lambda t, y, p, out: None, [1.0], (0.0, 1.0))
    assert np.isfinite(compile_time(Problem(rotation_decay, [1.0, 0.5], (0.0, 1.0), [0.3, 2.0])))


# --- rigid_body.py --------------------------------------------------------------------------------


def test_free_body_keeps_energy_and_momentum_and_refuses_bad_input():
    # Euler's free body: |m| is kept exactly by the splitting and the energy to O(h^2); the invariants are
    # written out here, sum m_i^2 / I_i / 2 and sum m_i^2
    I, m0 = np.array([1.0, 2.0, 3.0]), np.array([0.3, 1.0, 0.2])
    body = FixedProblem(rigid_body.packed(m0), I)
    rows = solve_fixed(body, "rigid-splitting2", h=0.01, n_steps=200, save=Save(every=50)).y_eval
    m, q = rows[:, :3], rows[:, 3:]
    assert rows.shape == (5, 7) and np.allclose(np.linalg.norm(q, axis=1), 1.0)
    assert np.allclose(rigid_body.casimir(m), m0 @ m0, rtol=1e-12)
    assert np.allclose(rigid_body.energy(I, m), 0.5 * np.sum(m0**2 / I), rtol=1e-4)
    with pytest.raises(ValueError, match="step size"):
        solve_fixed(body, "rigid-splitting2", h=0.0, n_steps=10)
    with pytest.raises(ValueError, match="not finite"):
        FixedProblem(rigid_body.packed([np.nan, 0.0, 0.0]), I)
