"""The right-hand sides in models/ that the studies integrate through solve(), against closed forms, first
integrals and the equations written out with numpy (not the compiled code under test)."""

import numpy as np
import pytest

from classical_dynamics.models import linear, revolving
from classical_dynamics.solvers.ode import Events, Problem, solve


def test_a_forced_undamped_oscillator_follows_its_closed_form():
    """x'' + x = cos(s t) from rest: x = (cos t - cos s t)/(s² - 1)."""
    s = 1.7
    A = linear.state_matrix(np.eye(1), np.eye(1))
    t = np.linspace(0.0, 20.0, 41)
    run = solve(
        Problem(linear.linear_system, [0.0, 0.0], (0.0, 20.0), linear.pack(A, [0.0, 1.0], s)),
        "dop853",
        t_eval=t,
        rtol=1e-12,
        atol=1e-14,
    )
    exact = (np.cos(t) - np.cos(s * t)) / (s**2 - 1)
    assert np.max(np.abs(run.y_eval[:, 0] - exact)) < 1e-10


def test_the_work_channel_integrates_the_quadratic_form_along_the_motion():
    """x'' + b x' + x = 0: the energy lost equals the integral of b x'² (the extra component); x itself
    follows the damped closed form."""
    b = 0.3
    A = linear.state_matrix(np.eye(1), np.eye(1), B=[[b]])
    W = np.array([[0.0, 0.0], [0.0, b]])
    t = np.linspace(0.0, 15.0, 31)
    run = solve(
        Problem(linear.linear_system, [1.0, 0.0, 0.0], (0.0, 15.0), linear.pack(A, work=W)),
        "dop853",
        t_eval=t,
        rtol=1e-12,
        atol=1e-14,
    )
    x, v, lost = run.y_eval.T
    w = np.sqrt(1 - b**2 / 4)
    assert np.max(np.abs(x - np.exp(-b * t / 2) * (np.cos(w * t) + b / (2 * w) * np.sin(w * t)))) < 1e-10
    assert np.max(np.abs(0.5 * (v**2 + x**2) - (0.5 - lost))) < 1e-10


def test_the_packed_system_is_a_z_plus_f_cos_st_and_a_work_channel_only_when_asked():
    """One evaluation against numpy: z' = A z + F cos(s t), and z^T W z in one more component only with W
    (without it the state has m components: a work flag set by mistake would write past its end)."""
    rng = np.random.default_rng(7)
    A, F, W, z = rng.normal(size=(3, 3)), rng.normal(size=3), rng.normal(size=(3, 3)), rng.normal(size=3)
    t, s = 0.7, 1.9
    plain = linear.pack(A, F)  # no frequency given: a constant force
    assert list(plain[:3]) == [3.0, 0.0, 0.0]
    out = np.empty(3)
    linear.linear_system(t, z, plain, out)
    assert np.allclose(out, A @ z + F, rtol=1e-15, atol=1e-15)
    with_work = linear.pack(A, F, s, W)
    assert list(with_work[:3]) == [3.0, s, 1.0]
    out = np.empty(4)
    linear.linear_system(t, np.append(z, 0.0), with_work, out)
    assert np.allclose(out, np.append(A @ z + F * np.cos(s * t), z @ W @ z), rtol=1e-14, atol=1e-15)


def test_the_state_matrix_holds_friction_and_gyroscopic_terms():
    K, M = np.array([[2.0, -1.0], [-1.0, 2.0]]), np.diag([1.0, 2.0])
    B, G = np.diag([0.1, 0.2]), np.array([[0.0, 0.5], [-0.5, 0.0]])
    A = linear.state_matrix(K, M, B, G)
    q, qd = np.array([0.3, -0.2]), np.array([0.7, 0.1])
    acc = np.linalg.solve(M, -K @ q - (B + G) @ qd)
    assert np.allclose(A @ np.concatenate([q, qd]), np.concatenate([qd, acc]), rtol=0, atol=1e-15)


def test_the_revolving_pair_is_lagranges_equations_solved_for_the_accelerations():
    """The compiled right-hand side against the mass matrix solved by numpy, at random states."""
    M, m, a, b = 2.0, 1.0, 1.0, 0.7
    rng = np.random.default_rng(18)
    for z in rng.standard_normal((5, 4)):
        d = -z[1]
        rates = (z[2], z[2] + z[3])
        mass = np.array([[(M + m) * a**2, m * a * b * np.cos(d)], [m * a * b * np.cos(d), m * b**2]])
        force = np.array([-m * a * b * np.sin(d) * rates[1] ** 2, m * a * b * np.sin(d) * rates[0] ** 2])
        acc = np.linalg.solve(mass, force)
        out = np.empty(4)
        revolving.revolving_pair(0.0, z, np.array([M, m, a, b]), out)
        assert out == pytest.approx([z[2], z[3], acc[0], acc[1] - acc[0]], rel=1e-13, abs=1e-15)


def test_the_pair_s_crossings_are_found_going_up_only():
    """psi oscillates: upward crossings of zero come once a period, the same period scipy's events find."""
    from scipy.integrate import solve_ivp

    z0, p = np.array([0.0, 0.0, 1.0, 1e-3]), np.array([2.0, 1.0, 1.0, 0.7])
    run = solve(
        Problem(revolving.revolving_pair, z0, (0.0, 200.0), p),
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        events=Events(revolving.revolving_pair_crossing, 1, directions=(1,)),
    )

    def rhs(t, z):
        out = np.empty(4)
        revolving.revolving_pair(t, np.ascontiguousarray(z), p, out)
        return out

    def crossing(t, z):
        return z[1]

    crossing.direction = 1.0
    ref = solve_ivp(rhs, (0.0, 200.0), z0, method="DOP853", rtol=1e-12, atol=1e-15, events=crossing)
    ours, theirs = run.event_t[run.event_t > 1e-9], ref.t_events[0][ref.t_events[0] > 1e-9]
    assert len(ours) == len(theirs) >= 3
    assert np.max(np.abs(ours - theirs)) < 1e-7


def test_the_free_body_with_its_attitude_matrix_keeps_r_orthogonal_and_omega_as_eulers_equations():
    from classical_dynamics.models import rigid_body

    I = np.array([1.0, 2.0, 3.5])
    w0 = np.array([0.3, 1.0, -0.4])
    run = solve(
        Problem(rigid_body.free_attitude_matrix, np.concatenate([w0, np.eye(3).ravel()]), (0.0, 20.0), I),
        "dop853",
        t_eval=np.linspace(0.0, 20.0, 11),
        rtol=1e-12,
        atol=1e-14,
    )
    alone = solve(
        Problem(rigid_body.euler_free, w0, (0.0, 20.0), rigid_body.euler_coefficients(I)),
        "dop853",
        t_eval=np.linspace(0.0, 20.0, 11),
        rtol=1e-12,
        atol=1e-14,
    )
    assert np.max(np.abs(run.y_eval[:, :3] - alone.y_eval)) < 1e-9
    for w, R in zip(run.y_eval[:, :3], run.y_eval[:, 3:].reshape(-1, 3, 3)):
        assert np.max(np.abs(R @ R.T - np.eye(3))) < 1e-9
        # the angular momentum is fixed in space: R (I w) stays what it was
        assert np.allclose(R @ (I * w), I * w0, rtol=0, atol=1e-9)


def test_many_free_bodies_are_each_eulers_equations():
    from classical_dynamics.models import rigid_body

    I = np.array([1.0, 2.0, 3.5])
    w = np.random.default_rng(4).standard_normal((5, 3))
    out, one = np.empty(15), np.empty(3)
    rigid_body.euler_free_many(0.0, w.T.ravel(), I, out)
    for i in range(5):
        rigid_body.euler_free(0.0, w[i], rigid_body.euler_coefficients(I), one)
        assert out.reshape(3, 5)[:, i] == pytest.approx(one, rel=1e-14, abs=1e-15)


def test_a_body_under_a_distant_mass_keeps_its_energy_and_the_direction_unit():
    """I w' = Iw x w + s x Is, s' = s x w: T + s.Is/2 is constant and |s| = 1 (both follow from the
    equations by hand: d/dt(s.Is/2) = w.(Is x s) cancels dT/dt = w.(s x Is))."""
    from classical_dynamics.models import rigid_body

    I = np.array([1.0, 1.6, 2.3])
    s0 = np.array([0.6, 0.0, 0.8])
    run = solve(
        Problem(rigid_body.distant_attraction, np.concatenate([[0.1, -0.2, 0.05], s0]), (0.0, 50.0), I),
        "dop853",
        t_eval=np.linspace(0.0, 50.0, 51),
        rtol=1e-12,
        atol=1e-14,
    )
    w, s = run.y_eval[:, :3], run.y_eval[:, 3:]
    energy = 0.5 * np.sum(I * w * w, axis=1) + 0.5 * np.sum(I * s * s, axis=1)
    assert np.ptp(energy) < 1e-10 and np.max(np.abs(np.linalg.norm(s, axis=1) - 1)) < 1e-10


def test_the_heavy_top_in_euler_angles_keeps_its_hamiltonian():
    from classical_dynamics.models import rigid_body

    A, C, Mgh = 1.0, 0.6, 0.4
    z0 = np.array([0.7, 0.0, 0.0, 0.2, 0.9, 3.0])
    run = solve(
        Problem(rigid_body.heavy_top_euler_angles, z0, (0.0, 30.0), [A, C, Mgh]),
        "dop853",
        t_eval=np.linspace(0.0, 30.0, 31),
        rtol=1e-12,
        atol=1e-14,
    )
    th, pth, pph, pps = run.y_eval[:, 0], run.y_eval[:, 3], run.y_eval[:, 4], run.y_eval[:, 5]
    H = pth**2 / (2 * A) + (pph - pps * np.cos(th)) ** 2 / (2 * A * np.sin(th) ** 2) + pps**2 / (2 * C)
    H += Mgh * np.cos(th)
    assert np.ptp(H) < 1e-10
