"""The fixed-step door (solvers/fixed_step.py): the same numbers as its kernels and as the methods' steps
taken one at a time, what Save keeps, each method's order or invariant, and the inputs it refuses."""

import numpy as np
import pytest
from numba import njit

from classical_dynamics.models import linear
from classical_dynamics.solvers import rattle, rigid_body, symplectic
from classical_dynamics.solvers import references as ref
from classical_dynamics.solvers.fixed_step import METHODS, FixedProblem, Save, solve_fixed
from classical_dynamics.solvers.ode import Solution
from classical_dynamics.solvers.runge_kutta import rhs_function

EPS = np.finfo(float).eps
I3 = np.array([1.0, 2.0, 3.0])
M0 = np.array([0.3, 1.0, 0.2])
Q0 = np.array([np.cos(0.2), np.sin(0.2) * 0.6, 0.0, np.sin(0.2) * 0.8])  # a unit quaternion, not the identity


@rhs_function
def constant_torque(t, q, p, out):
    """A body-fixed torque (p0, p1, p2): the symmetric-torqued methods' form torque(t, q, p, out)."""
    out[0], out[1], out[2] = p[0], p[1], p[2]


@njit
def constant_torque_m(t, m, q, p, out):
    """The same torque in the rigid-torqued methods' form torque(t, m, q, p, out)."""
    out[0], out[1], out[2] = p[0], p[1], p[2]


def chain(n=3, amplitude=0.4):
    """n particles of mass 1/n on links of 1/n, g = 9.81, the links at alternating angles."""
    a = 1.0 / n
    q0 = rattle.positions_from_angles(amplitude * (-1.0) ** np.arange(n), a)
    return FixedProblem(
        np.concatenate([q0.ravel(), np.zeros(2 * n)]), np.concatenate([[a, 9.81], np.full(n, a)])
    )


def observed_order(problem, method, span, n, error):
    """The order read off the largest final-state error at n and 2n steps over `span` (log2 of the ratio)."""
    errors = [
        np.max(np.abs(error(solve_fixed(problem, method, h=span / k, n_steps=k, save=Save(final=True)).y)))
        for k in (n, 2 * n)
    ]
    return np.log2(errors[0] / errors[1])


def bits(x):
    x = np.asarray(x)
    return x.shape, x.tobytes()


# --- the door against its kernels and against the steps one at a time --------------------------------------


def test_rigid_splitting_is_its_kernel_and_its_steps_one_at_a_time():
    h, n, every = 0.03, 50, 7
    for order in (2, 4):
        sol = solve_fixed(
            FixedProblem(rigid_body.packed(M0, Q0), I3), f"rigid-splitting{order}", h=h, n_steps=n
        )
        rows, final = rigid_body.integrate_free(I3, M0, Q0, h, n, order, 1)
        assert bits(sol.y_eval) == bits(rows) and bits(sol.y) == bits(final)
        m, q = M0.copy(), Q0.copy()
        for i in range(1, n + 1):
            rigid_body.free_composed(m, q, I3, h, order)
            assert bits(sol.y_eval[i]) == bits(np.concatenate([m, q]))
        strided = solve_fixed(
            FixedProblem(rigid_body.packed(M0, Q0), I3),
            f"rigid-splitting{order}",
            h=h,
            n_steps=n,
            save=Save(every),
        )
        assert bits(strided.y_eval) == bits(sol.y_eval[::every]) and bits(strided.y) == bits(sol.y)


@pytest.mark.parametrize("method, order", [("stormer-verlet", 2), ("yoshida4", 4)])
def test_verlet_methods_are_their_kernel_and_their_steps_one_at_a_time(method, order):
    h, n, p = 0.1, 40, np.array([1.3])
    sol = solve_fixed(FixedProblem([0.7, -0.2], p, linear.harmonic_force), method, h=h, n_steps=n)
    rows, final = symplectic.integrate(
        linear.harmonic_force, p, np.array([0.7]), np.array([-0.2]), h, n, order, 1
    )
    assert bits(sol.y_eval) == bits(rows) and bits(sol.y) == bits(final)
    q, v, a = np.array([0.7]), np.array([-0.2]), np.empty(1)
    linear.harmonic_force(q, p, a)
    weights = [1.0] if order == 2 else [rigid_body.YOSHIDA[0], rigid_body.YOSHIDA[1], rigid_body.YOSHIDA[0]]
    for i in range(1, n + 1):
        for w in weights:
            symplectic._verlet(linear.harmonic_force, p, q, v, w * h, a)
        assert bits(sol.y_eval[i]) == bits(np.concatenate([q, v]))
    assert sol.nfev == 1 + n * len(weights)


def test_rattle_is_its_kernel_and_its_steps_one_at_a_time():
    problem, h, n = chain(), 0.002, 60
    sol = solve_fixed(problem, "rattle", h=h, n_steps=n, save=Save(every=4))
    k = problem.y0.size // 4
    q0, p0 = problem.y0[: 2 * k].reshape(k, 2), problem.y0[2 * k :].reshape(k, 2)
    masses, a, g = problem.params[2:], problem.params[0], problem.params[1]
    rows, final, tip, energies, constraint = rattle.integrate(q0, p0, masses, a, g, h, n, 4)
    assert bits(sol.y_eval) == bits(rows) and bits(sol.y) == bits(final)
    assert bits(sol.extra["tip_x"]) == bits(tip) and bits(sol.extra["energy"]) == bits(energies)
    assert sol.extra["constraint"] == constraint
    q, p, q_new, p_new, work = q0.copy(), p0.copy(), np.empty((k, 2)), np.empty((k, 2)), rattle._workspace(k)
    for i in range(1, n + 1):
        assert rattle.rattle_step(q, p, masses, a, g, h, q_new, p_new, work)
        q, q_new, p, p_new = q_new, q, p_new, p
        assert sol.extra["tip_x"][i] == q[-1, 0]
        if i % 4 == 0:
            assert bits(sol.y_eval[i // 4]) == bits(np.concatenate([q.ravel(), p.ravel()]))
            assert sol.extra["energy"][i // 4] == rattle.energy(q, p, masses, g)


def test_torqued_methods_are_their_kernels():
    h, n, t0, tau = 0.05, 30, 2.5, np.array([0.01, -0.02, 0.03])
    A, C = 1.0, 1.8
    sym = FixedProblem(rigid_body.packed(M0, Q0), np.concatenate([[A, C], tau]), constant_torque, t0=t0)
    gen = FixedProblem(rigid_body.packed(M0, Q0), np.concatenate([I3, tau]), constant_torque_m, t0=t0)
    for order in (2, 4):
        sol = solve_fixed(sym, f"symmetric-torqued{order}", h=h, n_steps=n, save=Save(every=3))
        rows, final = rigid_body.integrate_symmetric_torqued(
            A, C, M0, Q0, t0, h, n, order, 3, constant_torque, tau
        )
        assert bits(sol.y_eval) == bits(rows) and bits(sol.y) == bits(final)
        sol = solve_fixed(gen, f"rigid-torqued{order}", h=h, n_steps=n, save=Save(every=3))
        rows, final = rigid_body.integrate_torqued(I3, M0, Q0, t0, h, n, order, 3, constant_torque_m, tau)
        assert bits(sol.y_eval) == bits(rows) and bits(sol.y) == bits(final)


# --- what Save keeps, and the Solution ----------------------------------------------------------------------


def test_save_every_and_final_and_the_solution_fields():
    problem = FixedProblem(rigid_body.packed(M0, Q0), I3, t0=1.5)
    every_step = solve_fixed(problem, "rigid-splitting2", h=0.1, n_steps=23)
    assert isinstance(every_step, Solution) and every_step.success and every_step.method == "rigid-splitting2"
    assert every_step.y_eval.shape == (24, 7) and every_step.n_steps == 23 and every_step.n_rejected == 0
    assert every_step.t_eval == pytest.approx(1.5 + 0.1 * np.arange(24), abs=1e-15)
    assert every_step.t == 1.5 + 0.1 * 23 and every_step.nfev == 0
    assert every_step.t_steps.size == 0 and every_step.event_t.size == 0 and every_step.extra == {}
    # a stride that does not divide n_steps: the rows at 0, 5, ..., 20, and still the final state in y
    strided = solve_fixed(problem, "rigid-splitting2", h=0.1, n_steps=23, save=Save(every=5))
    assert bits(strided.y_eval) == bits(every_step.y_eval[::5]) and strided.y_eval.shape == (5, 7)
    assert np.array_equal(strided.t_eval, 1.5 + 0.1 * np.array([0, 5, 10, 15, 20]))
    assert bits(strided.y) == bits(every_step.y) == bits(every_step.y_eval[-1])
    final = solve_fixed(problem, "rigid-splitting2", h=0.1, n_steps=23, save=Save(final=True))
    assert final.y_eval.shape == (0, 7) and final.t_eval.size == 0 and bits(final.y) == bits(every_step.y)


# --- each method's order or invariant -----------------------------------------------------------------------


def test_stormer_verlet_energy_stays_bounded_against_the_closed_form():
    """q'' = -q from (1, 0): the energy (q^2 + v^2)/2 against its closed-form value 1/2. Stormer-Verlet keeps
    v^2 + (1 - h^2/4) q^2 exactly (1 - h^2/4 here), so the energy error stays within h^2/4 over any number of
    steps; the phase drifts (the solution is not kept), the energy does not."""
    h, n = 0.2, 100_000
    sol = solve_fixed(
        FixedProblem([1.0, 0.0], [1.0], linear.harmonic_force), "stormer-verlet", h=h, n_steps=n
    )
    q, v = sol.y_eval[:, 0], sol.y_eval[:, 1]
    energy_error = np.abs(0.5 * (q**2 + v**2) - 0.5) / 0.5
    assert energy_error.max() <= h**2 / 4 * (1 + 1e-9)
    assert energy_error.max() > h**2 / 8  # the bound is reached: the method is not exact
    modified = v**2 + (1 - h**2 / 4) * q**2
    assert np.max(np.abs(modified / (1 - h**2 / 4) - 1)) < 1e-11  # kept to round-off
    tenth = n // 10
    assert energy_error[-tenth:].max() < 1.01 * energy_error[:tenth].max()  # no drift


@pytest.mark.parametrize("method, order", [("stormer-verlet", 2), ("yoshida4", 4)])
def test_verlet_methods_converge_at_their_order_to_the_closed_form(method, order):
    problem = FixedProblem([1.0, 0.0], [1.0], linear.harmonic_force)
    exact = [np.cos(10.0), -np.sin(10.0)]
    assert observed_order(problem, method, 10.0, 100, lambda y: y - exact) == pytest.approx(order, abs=0.1)


def test_rattle_keeps_the_links_to_round_off_and_the_energy_bounded():
    problem = chain(4, 0.6)
    sol = solve_fixed(problem, "rattle", h=0.002, n_steps=20_000, save=Save(every=20))
    assert 0 < sol.extra["constraint"] < 1e-12
    k = 4
    q = sol.y_eval[:, : 2 * k].reshape(-1, k, 2)
    links = np.diff(np.concatenate([np.zeros((len(q), 1, 2)), q], axis=1), axis=1)
    assert np.max(np.abs(np.linalg.norm(links, axis=2) - 0.25)) < 1e-12  # from the saved rows themselves
    energy = sol.extra["energy"]
    drift = np.abs(energy - energy[0])
    tenth = energy.size // 10
    assert drift[-tenth:].max() < 2 * drift[:tenth].max()


def test_rigid_splitting_keeps_the_casimir_to_round_off_and_converges_at_its_order():
    I, m0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0
    body = FixedProblem(rigid_body.packed(m0), I)
    n = 100_000
    rows = solve_fixed(body, "rigid-splitting2", h=0.05, n_steps=n, save=Save(every=100)).y_eval
    C0 = m0 @ m0
    assert np.max(np.abs(rigid_body.casimir(rows[:, :3]) / C0 - 1)) < 10 * np.sqrt(n) * EPS
    assert np.max(np.abs(np.linalg.norm(rows[:, 3:], axis=1) - 1)) < 1e-12
    exact = ref.hnw_rigid_body(20.0)
    for order in (2, 4):
        measured = observed_order(body, f"rigid-splitting{order}", 20.0, 400, lambda y: y[:3] / I - exact)
        assert measured == pytest.approx(order, abs=0.15)


def test_invariant_errors_measures_the_doors_steps():
    """rigid_body.invariant_errors (a named measurement beside the door) takes the same steps as
    "rigid-splitting2/4": its block maxima are those of the door's every-step rows."""
    I, m0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0
    n, block = 3000, 100
    for order in (2, 4):
        dH, dC = rigid_body.invariant_errors(I, m0, 0.05, n, order, block)
        m = solve_fixed(FixedProblem(rigid_body.packed(m0), I), f"rigid-splitting{order}", h=0.05, n_steps=n)
        m = m.y_eval[1:, :3]
        H0, C0 = 0.5 * np.sum(m0**2 / I), m0 @ m0
        H = 0.5 * (m[:, 0] ** 2 / I[0] + m[:, 1] ** 2 / I[1] + m[:, 2] ** 2 / I[2])
        C = m[:, 0] ** 2 + m[:, 1] ** 2 + m[:, 2] ** 2
        assert np.array_equal(dH, np.abs(H - H0).reshape(-1, block).max(axis=1) / H0)
        assert np.array_equal(dC, np.abs(C - C0).reshape(-1, block).max(axis=1) / C0)


def test_symmetric_torqued_free_flow_is_exact_and_the_torque_converges_at_its_order():
    A, C, w0 = 1.0, 1.8, np.array([0.1, 0.0, 2.0])
    m0 = np.array([A, A, C]) * w0
    free = FixedProblem(rigid_body.packed(m0), [A, C, 0.0, 0.0, 0.0], constant_torque)
    exact_free = ref.bodewadt(A, C, (0.0, 0.0, 0.0), w0, 50.0)
    for order in (2, 4):
        y = solve_fixed(free, f"symmetric-torqued{order}", h=2.5, n_steps=20, save=Save(final=True)).y
        assert np.max(np.abs(y[:3] / [A, A, C] - exact_free)) < 1e-13  # any step: the free flow is exact
    tau = (0.02, -0.01, 0.03)
    torqued = FixedProblem(rigid_body.packed(m0), [A, C, *tau], constant_torque)
    exact = ref.bodewadt(A, C, tau, w0, 50.0)
    for order, n in ((2, 2000), (4, 250)):
        measured = observed_order(
            torqued, f"symmetric-torqued{order}", 50.0, n, lambda y: y[:3] / [A, A, C] - exact
        )
        assert measured == pytest.approx(order, abs=0.15)


# --- bad inputs ---------------------------------------------------------------------------------------------


def test_bad_inputs_are_refused():
    body = FixedProblem(rigid_body.packed(M0), I3)
    for h in (0.0, -0.1, np.nan, np.inf):
        with pytest.raises(ValueError, match="step size"):
            solve_fixed(body, "rigid-splitting2", h=h, n_steps=10)
    for n in (0, -3, 2.5, True):
        with pytest.raises(ValueError, match="n_steps"):
            solve_fixed(body, "rigid-splitting2", h=0.1, n_steps=n)
    with pytest.raises(
        ValueError, match="unknown fixed-step method 'verlet'; known: stormer-verlet, yoshida4, rattle"
    ):
        solve_fixed(body, "verlet", h=0.1, n_steps=10)
    for every in (0, -1, 1.5):
        with pytest.raises(ValueError, match="every"):
            Save(every=every)
    with pytest.raises(ValueError, match="final state only"):
        Save(every=3, final=True)
    with pytest.raises(ValueError, match="initial state is not finite"):
        FixedProblem(rigid_body.packed([np.nan, 0.0, 1.0]), I3)
    with pytest.raises(ValueError, match="parameters are not finite"):
        FixedProblem(rigid_body.packed(M0), [1.0, np.inf, 3.0])
    with pytest.raises(ValueError, match="start time is not finite"):
        FixedProblem(rigid_body.packed(M0), I3, t0=np.nan)
    with pytest.raises(ValueError, match="7 numbers"):
        solve_fixed(FixedProblem(M0, I3), "rigid-splitting2", h=0.1, n_steps=10)
    with pytest.raises(ValueError, match="unit"):
        solve_fixed(
            FixedProblem(np.concatenate([M0, [2.0, 0, 0, 0]]), I3), "rigid-splitting2", h=0.1, n_steps=10
        )
    with pytest.raises(ValueError, match="moments of inertia"):
        solve_fixed(
            FixedProblem(rigid_body.packed(M0), [1.0, -2.0, 3.0]), "rigid-splitting2", h=0.1, n_steps=10
        )
    with pytest.raises(ValueError, match="needs a force"):
        solve_fixed(FixedProblem([1.0, 0.0], [1.0]), "stormer-verlet", h=0.1, n_steps=10)
    with pytest.raises(ValueError, match="takes no force"):
        solve_fixed(
            FixedProblem(rigid_body.packed(M0), I3, linear.harmonic_force),
            "rigid-splitting2",
            h=0.1,
            n_steps=1,
        )
    with pytest.raises(ValueError, match="even size"):
        solve_fixed(
            FixedProblem([1.0, 0.0, 2.0], [1.0], linear.harmonic_force), "stormer-verlet", h=0.1, n_steps=1
        )
    with pytest.raises(ValueError, match="params"):
        solve_fixed(FixedProblem(chain().y0, [0.3, 9.81]), "rattle", h=0.1, n_steps=1)
    with pytest.raises(TypeError, match="signature"):  # the symmetric methods' torque is typed
        solve_fixed(
            FixedProblem(rigid_body.packed(M0), [1.0, 1.8, 0.0, 0.0, 0.0], constant_torque_m),
            "symmetric-torqued2",
            h=0.1,
            n_steps=1,
        )
    assert set(METHODS) == {
        "stormer-verlet",
        "yoshida4",
        "rattle",
        "rigid-splitting2",
        "rigid-splitting4",
        "rigid-torqued2",
        "rigid-torqued4",
        "symmetric-torqued2",
        "symmetric-torqued4",
    }


# --- one door: no study calls a kernel ----------------------------------------------------------------------

KERNELS = {
    "symplectic": {"integrate"},
    "rattle": {"integrate", "rattle_step"},
    "rigid_body": {
        "integrate_free",
        "integrate_torqued",
        "integrate_symmetric_torqued",
        "free_composed",
        "step",
    },
}


def kernel_calls(source):
    """(module, name) of every use of a fixed-step kernel in `source`, as an attribute or imported by name."""
    import ast

    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            if node.attr in KERNELS.get(node.value.id, ()):
                found.append((node.value.id, node.attr))
        elif isinstance(node, ast.ImportFrom) and node.module:
            module = node.module.rsplit(".", 1)[-1]
            found += [(module, a.name) for a in node.names if a.name in KERNELS.get(module, ())]
    return found


def test_no_study_calls_a_fixed_step_kernel():
    from pathlib import Path

    import classical_dynamics.studies as studies

    assert kernel_calls("from ...solvers import rattle\nrattle.integrate(q, p)") == [("rattle", "integrate")]
    assert kernel_calls("from ...solvers.rigid_body import integrate_free") == [
        ("rigid_body", "integrate_free")
    ]
    assert kernel_calls("rigid_body.rotate_to_space(q, m)\nrattle.crossing_frequency(x, h)") == []
    root = Path(studies.__file__).parent
    files = sorted(root.rglob("*.py"))
    assert len(files) > 20
    calls = {str(f.relative_to(root)): kernel_calls(f.read_text()) for f in files}
    assert {f: c for f, c in calls.items() if c} == {}


def test_one_compiled_verlet_loop_serves_every_acceleration():
    """The accelerations reach the loop typed by their signature: one compiled loop, cached once on disk.
    Typed by each dispatcher, numba keyed a new cache entry in every process, and the index grew until
    saving it failed ("underlying object has vanished")."""
    from classical_dynamics.models.self_excited import largest_axis

    one = np.array([1.0])
    for force in (linear.harmonic_force, largest_axis.plane_largest_force):
        symplectic.integrate(force, one, one.copy(), one.copy(), 0.1, 3, 2, 1)
    # a plain dispatcher is compiled to the signature, and the loop stays the one loop
    symplectic.integrate(njit(lambda q, p, out: None), one, one.copy(), one.copy(), 0.1, 3, 2, 1)
    assert len(symplectic.integrate.overloads) == 1 and len(symplectic._verlet.overloads) == 1
