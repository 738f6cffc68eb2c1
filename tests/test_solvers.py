"""The solver layer against exact solutions, and its hard cases."""

import mpmath
import numpy as np
import pytest
from scipy import special

from classical_dynamics.models import linear
from classical_dynamics.models import rigid_body as rhs
from classical_dynamics.solvers import references as ref
from classical_dynamics.solvers import rigid_body
from classical_dynamics.solvers import runge_kutta as rk
from classical_dynamics.solvers.fixed_step import FixedProblem, Save, solve_fixed
from classical_dynamics.solvers.ode import Events, Problem, solve, solve_batch
from classical_dynamics.solvers.runge_kutta import rhs_function

HNW = Problem(rhs.euler_free, ref.HNW_Y0, (0.0, 20.0), rhs.euler_coefficients(ref.HNW_I))


# Right-hand sides and event functions: compiled with the integrators' signature, cached.
@rhs_function
def torqued(t, w, p, out):
    """Axisymmetric body (I, I, I3) = (p0, p0, p1) with body-fixed torque (p2, p3, p4)."""
    out[0] = (p[0] - p[1]) / p[0] * w[1] * w[2] + p[2] / p[0]
    out[1] = (p[1] - p[0]) / p[0] * w[2] * w[0] + p[3] / p[0]
    out[2] = p[4] / p[1]


@rhs_function
def still(t, y, p, out):
    out[0] = 0.0


@rhs_function
def fast_cosine(t, y, p, out):
    out[0] = np.cos(40.0 * t)


@rhs_function
def second_component(t, y, p, out):
    out[0] = y[1]


@pytest.mark.parametrize(
    "method,rtol,bound", [("dop853", 1e-12, 1e-11), ("dopri5", 1e-10, 1e-8), ("scipy:DOP853", 1e-12, 1e-11)]
)
def test_hnw_against_elliptic_functions(method, rtol, bound):
    t = np.linspace(0, 20, 101)
    sol = solve(HNW, method, rtol=rtol, atol=rtol * 1e-3, t_eval=t)
    assert sol.status == "success"
    assert np.max(np.abs(sol.y - ref.hnw_rigid_body(20.0))) < bound
    assert np.max(np.abs(sol.y_eval - ref.hnw_rigid_body(t))) < 5 * bound  # dense output too


def test_detest_b5():
    sol = solve(Problem(rhs.detest_b5, [0.0, 1.0, 1.0], (0.0, 20.0)), "dop853", rtol=1e-12, atol=1e-15)
    assert np.max(np.abs(sol.y - ref.detest_b5(20.0))) < 1e-11


def test_compiled_dop853_takes_scipys_steps():
    ours = solve(HNW, "dop853", rtol=1e-9, atol=1e-12)
    theirs = solve(HNW, "scipy:DOP853", rtol=1e-9, atol=1e-12)
    assert ours.n_steps == theirs.n_steps
    assert np.allclose(ours.y, theirs.y, rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize(
    "I,w0",
    [
        ((1.0, 2.0, 3.0), (0.3, -0.8, 0.5)),
        ((1.0, 2.0, 3.0), (1.0, 0.3, -0.1)),
        ((1.0, 2.0, 3.0), (-0.5, 0.2, -0.7)),
        ((0.7, 1.1, 2.9), (0.0, 1.2, 0.4)),
    ],
)
def test_free_rigid_body_closed_form_on_both_sides_of_the_separatrix(I, w0):
    t = np.linspace(0, 30, 31)
    sol = solve(
        Problem(rhs.euler_free, w0, (0, 30), rhs.euler_coefficients(I)),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=t,
    )
    assert np.max(np.abs(ref.free_rigid_body(I, np.array(I) * np.array(w0), t) - sol.y_eval)) < 1e-11


@pytest.mark.parametrize("one_minus_m", [1e-6, 1e-10, 1e-12])
def test_jacobi_functions_near_the_separatrix_against_mpmath(one_minus_m):
    # Hard case: scipy's ellipj is wrong by ~1e11 at m = 1 - 1e-10 (scipy #8480).
    m = 1.0 - one_minus_m
    u = np.linspace(-4 * special.ellipk(m), 8 * special.ellipk(m), 61)
    ours = np.stack(ref.ellipj(u, m)[:3], axis=1)
    with mpmath.workdps(30):
        exact = np.array(
            [
                [float(mpmath.ellipfun(f, mpmath.mpf(x), m=mpmath.mpf(m))) for f in ("sn", "cn", "dn")]
                for x in u
            ]
        )
    assert np.max(np.abs(ours - exact)) < 1e-13


def test_integrators_stay_on_the_energy_surface_near_the_separatrix():
    I = np.array([1.0, 2.0, 3.0])
    w0 = np.array([np.sqrt(3 * (1 - 1e-10)), 0.0, 1.0])
    H0, C0 = 0.5 * np.sum(I * w0 * w0), np.sum((I * w0) ** 2)
    sol = solve(
        Problem(rhs.euler_free, w0, (0.0, 150.0), rhs.euler_coefficients(I)),
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        record_steps=True,
    )
    assert np.max(np.abs(0.5 * np.sum(I * sol.y_steps**2, axis=1) / H0 - 1)) < 1e-10
    body = FixedProblem(rigid_body.packed(I * w0), I)
    ms = solve_fixed(body, "rigid-splitting2", h=0.01, n_steps=15000, save=Save(every=10)).y_eval[:, :3]
    assert np.max(np.abs(np.sum(ms * ms, axis=1) / C0 - 1)) < 1e-12
    assert np.max(np.abs(0.5 * np.sum(ms * ms / I, axis=1) / H0 - 1)) < 1e-3  # bounded O(h^2)


def test_intermediate_axis_growth_rate():
    A, B, C, q0 = 3.0, 2.0, 1.0, 1.5
    theory = q0 * np.sqrt((A - B) * (B - C) / (A * C))
    t = np.linspace(0, 20, 401)
    sol = solve(
        Problem(rhs.euler_free, [1e-10, q0, 1e-10], (0, 20), rhs.euler_coefficients([A, B, C])),
        "dop853",
        rtol=1e-12,
        atol=1e-20,
        t_eval=t,
    )
    size = np.hypot(sol.y_eval[:, 0], sol.y_eval[:, 2])
    window = (size > 1e-8) & (size < 1e-3)
    assert np.polyfit(t[window], np.log(size[window]), 1)[0] == pytest.approx(theory, rel=1e-3)


@pytest.mark.parametrize(
    "m,mu,p0", [(1.0, 1.0, 0.0), (0.5, -0.2, -2.0), (-0.3, -0.5, 0.4), (-0.4, 0.3, 2.0), (0.0, 0.7, 1.5)]
)
def test_blow_up_time_matches_the_closed_form(m, mu, p0):
    t_star = ref.riccati_blow_up_time(m, mu, p0)
    sol = solve(Problem(rhs.riccati, [p0], (0.0, 2 * t_star), [m, mu]), "dop853", rtol=1e-10, atol=1e-12)
    assert sol.status == "blow-up"
    assert sol.t == pytest.approx(t_star, rel=1e-9)
    assert np.isfinite(sol.y).all()


def test_lee_blow_up_number():
    assert ref.riccati_blow_up_time(0.5, -0.2, -2.0) == pytest.approx(3.39296045, abs=1e-8)


@pytest.mark.parametrize("m,mu,p0", [(0.5, -0.2, 0.3), (0.5, -0.2, 2.0), (-0.3, 0.5, 0.2), (1.0, 1.0, 0.5)])
def test_riccati_closed_forms_against_integration(m, mu, p0):
    T = min(3.0, 0.9 * ref.riccati_blow_up_time(m, mu, p0))
    t = np.linspace(0, T, 7)
    sol = solve(Problem(rhs.riccati, [p0], (0.0, T), [m, mu]), "dop853", rtol=1e-12, atol=1e-14, t_eval=t)
    assert np.allclose(sol.y_eval[:, 0], ref.riccati(m, mu, p0, t), rtol=1e-9)


@pytest.mark.parametrize("M3", [0.03, 0.0, -0.03])
def test_bodewadt_fresnel_solution(M3):
    t = np.linspace(0, 50, 11)
    sol = solve(
        Problem(torqued, [0.1, 0.0, 2.0], (0, 50), [1.0, 1.8, 0.05, -0.02, M3]),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=t,
    )
    closed = ref.bodewadt(1.0, 1.8, (0.05, -0.02, M3), np.array([0.1, 0.0, 2.0]), t)
    assert np.max(np.abs(closed - sol.y_eval)) < 1e-11


def test_events_do_not_miss_two_sign_changes_in_one_step():
    # g = cos(40 t) on a trivial ODE: adaptive steps are huge, yet every crossing must be found.
    sol = solve(
        Problem(still, [0.0], (0.0, 1.0)),
        "dop853",
        rtol=1e-6,
        atol=1e-9,
        events=Events(fast_cosine, 1),
        subdivisions=64,
    )
    expected = (np.arange(13) + 0.5) * np.pi / 40
    assert sol.n_steps < 10
    assert np.allclose(sol.event_t, expected[expected < 1.0], atol=1e-12)


def test_terminal_event_and_direction():
    sol = solve(
        HNW,
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        events=Events(second_component, 1, directions=(-1,), terminal=(True,)),
    )
    assert sol.status == "terminal event"
    assert sol.t == pytest.approx(ref.HNW_PERIOD / 2, rel=1e-10)  # y2 = a sn falls through 0 at u = 2K


@pytest.mark.parametrize(
    "kwargs,message",
    [
        ({"rtol": 1e-15, "atol": 1e-18}, "below 100\\*eps"),
        ({"rtol": 0.0, "atol": 1e-9}, "positive"),
        ({"rtol": 1e-6, "atol": -1.0}, "positive"),
    ],
)
def test_tolerances_that_cannot_be_honoured_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        solve(HNW, "dop853", **kwargs)


def test_bad_initial_state_and_span_are_refused():
    with pytest.raises(ValueError, match="not finite"):
        solve(Problem(rhs.euler_free, [np.nan, 0, 1], (0, 1), rhs.euler_coefficients(ref.HNW_I)), "dop853")
    with pytest.raises(ValueError, match="not after"):
        solve(Problem(rhs.euler_free, [1.0, 0, 1], (1.0, 0.0), rhs.euler_coefficients(ref.HNW_I)), "dop853")
    with pytest.raises(ValueError, match="positive"):
        solve_fixed(
            FixedProblem(rigid_body.packed([1, 0, 1]), ref.HNW_I), "rigid-splitting2", h=-0.1, n_steps=10
        )


def test_splitting_orders_and_quaternion():
    I, m0 = ref.HNW_I, ref.HNW_I * ref.HNW_Y0
    body = FixedProblem(rigid_body.packed(m0), I)
    for order, expected in ((2, 2.0), (4, 4.0)):
        errors = [
            np.max(
                np.abs(
                    solve_fixed(
                        body,
                        f"rigid-splitting{order}",
                        h=h,
                        n_steps=int(round(20 / h)),
                        save=Save(final=True),
                    ).y[:3]
                    / I
                    - ref.hnw_rigid_body(20.0)
                )
            )
            for h in (0.05, 0.025)
        ]
        assert np.log2(errors[0] / errors[1]) == pytest.approx(expected, abs=0.15)
    rows = solve_fixed(body, "rigid-splitting2", h=0.05, n_steps=100000, save=Save(every=1000)).y_eval
    ms, qs = rows[:, :3], rows[:, 3:]
    assert np.max(np.abs(np.linalg.norm(qs, axis=1) - 1)) < 1e-12  # Lie-group update
    L = rigid_body.rotate_to_space(qs, ms)
    assert np.max(np.abs(L - L[0])) < 1e-11  # space angular momentum


def test_splitting_with_a_body_fixed_torque_converges_to_bodewadt():
    from numba import njit

    @njit
    def axial(t, m, q, p, out):
        out[0], out[1], out[2] = 0.0, 0.0, p[0]

    I = np.array([1.0, 1.0, 1.8])
    m0 = I * np.array([0.1, 0.0, 2.0])
    exact = ref.bodewadt(1.0, 1.8, (0.0, 0.0, 0.03), np.array([0.1, 0.0, 2.0]), 50.0)
    errors = []
    body = FixedProblem(rigid_body.packed(m0), np.append(I, 0.03), axial)
    for h in (0.002, 0.001):
        y = solve_fixed(body, "rigid-torqued2", h=h, n_steps=int(round(50 / h)), save=Save(final=True)).y
        errors.append(np.max(np.abs(y[:3] / I - exact)))
        assert abs(np.linalg.norm(y[3:]) - 1) < 1e-12
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.05)


def test_numerical_damping_of_an_undamped_oscillator():
    problem = Problem(rhs.oscillator, [1.0, 0.0], (0.0, 200 * np.pi), [1.0])
    change = {}
    for method in ("scipy:BDF", "dop853"):
        y = solve(problem, method, rtol=1e-6, atol=1e-9).y
        change[method] = y[0] ** 2 + y[1] ** 2 - 1
    assert change["scipy:BDF"] < -1e-4  # BDF damps: not a physical Q
    assert abs(change["dop853"]) < abs(change["scipy:BDF"]) / 10
    oscillator = FixedProblem([1.0, 0.0], [1.0], linear.harmonic_force)
    rows = solve_fixed(oscillator, "stormer-verlet", h=2 * np.pi / 50, n_steps=5000).y_eval
    energy = rows[:, 0] ** 2 + rows[:, 1] ** 2
    assert np.max(np.abs(energy - 1)) < 5e-3 and abs(energy[-1000:].mean() - energy[:1000].mean()) < 1e-4


def test_batch_equals_one_at_a_time():
    Y0 = np.array([[1.0, 0.0, 0.9], [0.5, 0.2, 0.9], [1.0, -0.3, 0.2]])
    status, t_end, final, _ = solve_batch(
        rhs.euler_free, Y0, (0.0, 20.0), rhs.euler_coefficients(ref.HNW_I), rtol=1e-10, atol=1e-13
    )
    for row, y in zip(Y0, final):
        single = solve(
            Problem(rhs.euler_free, row, (0.0, 20.0), rhs.euler_coefficients(ref.HNW_I)),
            "dop853",
            rtol=1e-10,
            atol=1e-13,
        )
        assert np.array_equal(single.y, y)
    assert status == ["success"] * 3


@pytest.mark.parametrize("method", ["dop853", "dopri5"])
def test_the_final_state_loop_takes_the_full_loops_steps(method):
    """solve() without dense output, events or a step record runs the lean loop: same steps, same result."""
    lean = solve(HNW, method, rtol=1e-9, atol=1e-12)
    full = solve(HNW, method, rtol=1e-9, atol=1e-12, record_steps=True)
    assert np.array_equal(lean.y, full.y)
    assert (lean.nfev, lean.n_steps, lean.n_rejected, lean.status) == (
        full.nfev,
        full.n_steps,
        full.n_rejected,
        full.status,
    )


def test_blow_up_is_located_without_dense_output_asked_for():
    m, mu, p0 = 1.0, 1.0, 0.0  # p' = 1 + p^2: p = tan t, blows up at pi/2
    sol = solve(Problem(rhs.riccati, [p0], (0.0, 3.0), [m, mu]), "dop853", rtol=1e-10, atol=1e-12)
    assert sol.status == "blow-up"
    assert sol.t == pytest.approx(ref.riccati_blow_up_time(m, mu, p0), rel=1e-6)


def test_the_specialized_loop_takes_the_plain_loops_steps():
    """specialize=True compiles the final-state loop for one right-hand side: the same steps and the same
    numbers as the plain loop, for both methods, to the end and to a blow-up (at riccati_blow_up_time, a
    closed form). One right-hand side for every case: each compilation takes seconds."""
    m, mu = 1.0, 1.0  # p' = 1 + p^2
    for method in ("dop853", "dopri5"):
        for t1 in (1.0, 3.0):  # p = tan t: whole to t = 1, a blow-up at pi/2 before t = 3
            problem = Problem(rhs.riccati, [0.0], (0.0, t1), [m, mu])
            plain = solve(problem, method, rtol=1e-10, atol=1e-12)
            fast = solve(problem, method, rtol=1e-10, atol=1e-12, specialize=True)
            assert np.array_equal(fast.y, plain.y) and fast.t == plain.t
            assert (fast.nfev, fast.n_steps, fast.n_rejected, fast.status) == (
                plain.nfev,
                plain.n_steps,
                plain.n_rejected,
                plain.status,
            )
        assert fast.status == "blow-up"
        assert fast.t == pytest.approx(ref.riccati_blow_up_time(m, mu, 0.0), rel=1e-6)


def test_the_specialized_batch_is_the_plain_batch():
    """specialize=True compiles the batch's loop over rows (shared out over the cores) for one right-hand
    side: the same numbers as the plain batch, row by row, a blow-up among them located at its closed-form
    time."""
    m, mu = 1.0, 1.0
    Y0 = np.array([[0.0], [0.5], [-0.3], [1.5]])  # the last blows up at pi/2 - atan(1.5) = 0.59 < 1
    plain = solve_batch(rhs.riccati, Y0, (0.0, 1.0), [m, mu], rtol=1e-10, atol=1e-12)
    fast = solve_batch(rhs.riccati, Y0, (0.0, 1.0), [m, mu], rtol=1e-10, atol=1e-12, specialize=True)
    assert fast[0] == plain[0] == ["success"] * 3 + ["blow-up"]
    assert np.array_equal(fast[1], plain[1]) and np.array_equal(fast[2], plain[2])
    assert fast[1][3] == pytest.approx(ref.riccati_blow_up_time(m, mu, 1.5), rel=1e-6)
    assert fast[1][:3].tolist() == [1.0] * 3


def test_batch_with_parameters_per_row():
    """Each row its own parameters (a sweep): the same as one at a time."""
    Y0 = np.tile([0.0, 1.0], (3, 1))
    P = np.array([[0.5, 1.0], [1.0, 2.0], [2.0, 0.5]])  # p' = m + mu p^2, as (m, mu) rows
    status, t_end, final, _ = solve_batch(rhs.riccati, Y0[:, :1], (0.0, 0.3), P, rtol=1e-10, atol=1e-12)
    for row, p, y in zip(Y0[:, :1], P, final):
        assert np.array_equal(solve(Problem(rhs.riccati, row, (0.0, 0.3), p), rtol=1e-10, atol=1e-12).y, y)


# --- the heavy symmetric top (models/heavy_top.py) against its closed forms ------------------------
def test_heavy_top_nutation_frequency_is_lambs_art57_with_a_not_one():
    """Lamb Art. 57 (13), sigma^2 = omega^2 sin^2 alpha + (J3 - 2 A omega cos alpha)^2 / A^2, written out here
    with A = 2.5 (A = 1 would hide a slip of A into 1/A)."""
    from classical_dynamics.models import heavy_top as tm

    A, J3, alpha, omega = 2.5, 3.0, np.radians(50.0), 0.7
    sigma2 = omega**2 * np.sin(alpha) ** 2 + (J3 - 2 * A * omega * np.cos(alpha)) ** 2 / A**2
    assert tm.nutation_frequency(A, J3, alpha, omega) == pytest.approx(np.sqrt(sigma2), rel=1e-15)


def test_heavy_top_steady_roots_solve_lambs_quadratic():
    from classical_dynamics.models import heavy_top as tm

    A, Mgh, J3 = 1.0, 1.0, 3.0
    for alpha in np.radians([20.0, 60.0, 89.0, 120.0]):
        for w in tm.steady_roots(A, J3, Mgh, alpha):
            assert abs(A * w * w * np.cos(alpha) - J3 * w + Mgh) <= 1e-13 * max(1.0, A * w * w)
    assert tm.steady_roots(A, J3, Mgh, np.pi / 2)[0] == pytest.approx(Mgh / J3, rel=1e-15)  # the gyroscope
    threshold = np.sqrt(4 * A * Mgh * np.cos(np.radians(60.0)))
    assert tm.steady_roots(A, 0.999 * threshold, Mgh, np.radians(60.0)) is None  # spin too slow
    assert tm.steady_roots(A, 0.0, Mgh, np.radians(60.0)) is None  # conical pendulum


def test_heavy_top_nutates_between_the_roots_of_the_cubic():
    from classical_dynamics.models import heavy_top as tm

    top = tm.Top(1.0, 0.5, 1.0)
    y0 = top.state(np.radians(50.0), 0.0, 0.1, 5.0)
    J3, Jz, E = (float(v[0]) for v in top.integrals(y0))
    nut = tm.Nutation.from_integrals(top.A, top.C, top.Mgh, J3, Jz, E)
    t = np.linspace(0.0, 10 * nut.period, 201)
    sol = solve(
        Problem(top.rhs, y0, (0.0, t[-1]), top.params),
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        t_eval=t,
        events=Events(tm.apse, tm.APSE_EVENTS_N),
    )
    assert np.max(np.abs(sol.y_eval[:, 5] - nut.cos_theta(t, y0[5]))) < 1e-9  # Jacobi's sn^2
    theta = tm.angles(sol.event_y[sol.event_t > 1e-9])[0]
    assert np.allclose(np.sort(np.unique(np.round(np.cos(theta), 8))), [nut.u1, nut.u2], atol=1e-9)
    drift = [np.max(np.abs(v - v[0])) / abs(v[0]) for v in top.integrals(sol.y_eval)]
    assert max(drift) < 1e-10


def test_heavy_top_scene_lists_gravity_and_is_a_real_body(tmp_path):
    import yaml

    from classical_dynamics.scenes import SceneError
    from classical_dynamics.studies import validate

    root = __import__("pathlib").Path(__file__).resolve().parents[1]
    shipped = root / "workflow" / "scenes" / "solvers" / "heavy_top.yaml"
    validate("solvers", shipped)
    good = yaml.safe_load(shipped.read_text())
    for change, field in (
        (lambda d: d.pop("effects"), "effects.gravity"),
        (lambda d: d["top"].update(C=2.5), "top.C"),
        (lambda d: d["effects"]["gravity"].update(Mgh=-1.0), "effects.gravity.Mgh"),
    ):
        data = yaml.safe_load(yaml.safe_dump(good))
        change(data)
        path = tmp_path / "heavy_top.yaml"
        path.write_text(yaml.safe_dump(data))
        with pytest.raises(SceneError, match=field.replace(".", r"\.")):
            validate("solvers", path)


def test_moments_of_inertia_by_quadrature():
    from classical_dynamics.studies.solvers import inertia

    M, I = inertia.tensor(*inertia.sphere(1.0, 16))
    assert np.allclose(I / M, 0.4 * np.eye(3), rtol=0, atol=1e-13)
    M, I = inertia.tensor(*inertia.torus_circular(3.0, 1.0, 16))
    assert I[2, 2] / M == pytest.approx(9.75, rel=1e-13)  # Lamb Ex. VII.10: a^2 + 3 kappa^2
    s = 1 / np.sqrt(2)
    _, I = inertia.tensor(np.array([[s, -s, 0.0], [-s, s, 0.0]]), np.ones(2))
    assert np.allclose(I, [[1, 1, 0], [1, 1, 0], [0, 0, 2]], atol=1e-15)  # the lecture notes' dumbbell


@rhs_function
def oscillators(t, y, p, out):
    """Five uncoupled unit oscillators, y = (x1..x5, v1..v5)."""
    for k in range(5):
        out[k] = y[5 + k]
        out[5 + k] = -y[k]


@rhs_function
def first_position(t, y, p, out):
    out[0] = y[0]


def test_a_short_event_vector_leaves_later_steps_exact():
    """Locating an event must not touch the stages' scratch: a 10-component state with one event, found many
    times, ends where the exact solution does (the fault this guards against wrote past a 1-element array)."""
    y0 = np.array([1.0, 0.5, -0.3, 0.2, 0.9, 0.0, 0.4, 0.1, -0.7, 0.3])
    sol = solve(
        Problem(oscillators, y0, (0.0, 30.0)), rtol=1e-12, atol=1e-14, events=Events(first_position, 1)
    )
    t = 30.0
    exact = np.concatenate(
        [y0[:5] * np.cos(t) + y0[5:] * np.sin(t), -y0[:5] * np.sin(t) + y0[5:] * np.cos(t)]
    )
    assert sol.event_t.size == 10  # x1 = cos t crosses zero at pi/2 + k pi, k = 0..9
    np.testing.assert_allclose(sol.event_t, np.pi / 2 + np.pi * np.arange(10), atol=1e-10)
    np.testing.assert_allclose(sol.y, exact, atol=1e-9)


def test_lee_cases_every_closed_form_and_blow_up_time():
    from classical_dynamics.studies.solvers import hard_cases

    class Collect:
        def __init__(self):
            self.numbers, self.cases = {}, []

        def number(self, name, value, unit, **kw):
            self.numbers[name] = value

        def hard_case(self, name, description, measured, bound, unit=""):
            self.cases.append((name, measured, bound))

    cases = hard_cases.lee_cases()
    assert {c.name for c in cases if c.t_star is not None} == {"i", "iii", "iv", "vi"}
    assert max(c.difference for c in cases) < 1e-10
    r = Collect()
    hard_cases._record_lee_cases(r, cases)
    assert {n for n in r.numbers if n.endswith("_t_star")} == {
        f"lee_case_{c}_t_star" for c in ("i", "iii", "iv", "vi")
    }
    assert r.numbers["lee_cases_worst_difference"] < 1e-10
    # Lee's printed forms, typed here: (i) and (iv) with tan, (iii) with arcoth
    k, w = np.sqrt(2.0), np.sqrt(0.18)
    assert r.numbers["lee_case_i_t_star"] == pytest.approx((np.pi / 2 - np.arctan(0.5 / k)) / w, abs=1e-9)
    k, w = np.sqrt(0.4 / 0.3), np.sqrt(0.12)
    assert r.numbers["lee_case_iii_t_star"] == pytest.approx(np.arctanh(k / 2.0) / w, abs=1e-9)
    k, w = np.sqrt(0.6), np.sqrt(0.15)
    assert r.numbers["lee_case_iv_t_star"] == pytest.approx((np.arctan(0.4 / k) + np.pi / 2) / w, abs=1e-9)


class _Clock:
    """A perf_counter that moves only when the work says it took time: min_time's stopping rule, not this
    machine's load, decides each test (a sleep overshoots by milliseconds on a busy machine)."""

    def __init__(self):
        self.now = 0.0

    def perf_counter(self):
        return self.now

    def work(self, delays):
        """A function that takes the given times, one per call; it returns the clock's reading."""
        delays = iter(delays)

        def work():
            self.now += next(delays)
            return self.now

        return work


@pytest.fixture
def clock(monkeypatch):
    from classical_dynamics.solvers import timing

    fake = _Clock()
    monkeypatch.setattr(timing, "time", fake)
    monkeypatch.delenv(timing.ONCE, raising=False)  # the stopping rule itself, as a benchmark runs it
    return fake


def test_with_the_tests_switch_each_timing_is_one_run(monkeypatch):
    from classical_dynamics.solvers import timing

    monkeypatch.setenv(timing.ONCE, "1")
    calls = []
    seconds, result, runs = timing.min_time(lambda: calls.append(1) or "value", repeats=10, budget_s=5.0)
    assert (result, runs, len(calls)) == ("value", 1, 1) and seconds >= 0


def test_min_time_stops_once_two_runs_agree_and_ignores_a_slow_first_run(clock):
    """A first call that compiles (slow) is not the minimum; the repeats stop when the two fastest agree."""
    from classical_dynamics.solvers.timing import min_time

    seconds, result, runs = min_time(clock.work([0.2, 0.030, 0.0305] + [0.03] * 8), repeats=10, budget_s=5.0)
    assert seconds == pytest.approx(0.03) and result == pytest.approx(0.2605)
    assert runs == 3  # the slow first run, then two that agree within 5 %: not ten


def test_min_time_repeats_until_the_two_fastest_agree(clock):
    from classical_dynamics.solvers.timing import min_time

    seconds, _, runs = min_time(clock.work([0.2, 0.03, 0.04, 0.035, 0.0301, 0.05]), repeats=10, budget_s=5.0)
    assert seconds == pytest.approx(0.03) and runs == 5  # 0.03 and 0.0301 are the first two within 5 %


def test_min_time_keeps_to_its_budget_when_runs_disagree(clock):
    from classical_dynamics.solvers.timing import min_time

    delays = [0.01, 0.05, 0.02, 0.08, 0.04, 0.12, 0.06, 0.16, 0.09, 0.2, 0.11]
    seconds, _, runs = min_time(clock.work(delays), repeats=10, budget_s=0.1)
    # stopped by the budget: 0.1 s counted after the first run is passed by the third (0.05 + 0.02 + 0.08)
    assert seconds == pytest.approx(0.01) and runs == 4


def test_a_loop_specialized_for_three_components_takes_the_plain_loops_steps():
    """The specialized loop has the state's dimension as a constant (its loops over the components unrolled):
    on Euler's free body (3 components) the same steps and numbers as the plain loop, and a state of another
    dimension is refused by the loop compiled for 3, not read past its end."""
    problem = Problem(rhs.euler_free, ref.HNW_Y0, (0.0, 20.0), rhs.euler_coefficients(ref.HNW_I))
    plain = solve(problem, "dop853", rtol=1e-10, atol=1e-13)
    fast = solve(problem, "dop853", rtol=1e-10, atol=1e-13, specialize=True)
    assert np.array_equal(fast.y, plain.y) and fast.t == plain.t == 20.0
    assert (fast.nfev, fast.n_steps, fast.n_rejected) == (plain.nfev, plain.n_steps, plain.n_rejected)
    np.testing.assert_allclose(fast.y, ref.hnw_rigid_body(20.0), atol=1e-9)
    run = rk.specialized_final_state(rhs.euler_free, 3)
    with pytest.raises(ValueError, match="dimension"):
        run(rk.METHOD_INDEX["dop853"], problem.params, 0.0, 1.0, np.ones(4), 1e-8, 1e-11, 1000, 1e12)
