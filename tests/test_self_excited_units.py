"""Unit tests of studies/self_excited: viscous.py (Lee §5), accuracy.py and space.py, each against a
reference the module does not compute: Lee's equations (5.49) integrated here by scipy's solve_ivp, the
steady rotations of Theorems 2 and 3 solved here from the same equations, the energy integral of Lee's plane
(2.10), and the closed form of his limit cycle F."""

from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from classical_dynamics.studies.results import Results
from classical_dynamics.studies.self_excited import viscous


def _results():
    return Results("self_excited", "test", "test")


def _values(results):
    return {name: entry["value"] for name, entry in results.numbers.items()}


# --- viscous.py: Lee §5 ----------------------------------------------------------------------------------


def _viscous_scene(viscous_block, drag=True, moments=(2.5, 2.5, 1.0), analysis=None):
    effects = {"body_torque": None, **({"drag": None} if drag else {})}
    data = {"body": {"moments": list(moments)}, "viscous": viscous_block, "effects": effects}
    return SimpleNamespace(name="v", title="v", data={**data, "analysis": analysis or {}})


def _lee_549(h, nu, mu, m, omega0, t_max, t_eval):
    """Lee (5.49) written out here: p' - h q r = m1 - nu p, q' + h p r = m2 - nu q, r' = m3 - mu r."""

    def rhs(_, w):
        p, q, r = w
        return [h * q * r + m[0] - nu * p, -h * p * r + m[1] - nu * q, m[2] - mu * r]

    return solve_ivp(rhs, (0.0, t_max), omega0, method="DOP853", rtol=1e-12, atol=1e-14, t_eval=t_eval)


def test_viscous_run_with_friction_tends_to_theorem_3s_rotation():
    block = {"nu": 0.3, "mu": 0.5, "torque": [0.4, -0.2, 0.3], "omega0": [0.5, 0.8, 2.0], "t_max": 60}
    results = _results()
    viscous.run(_viscous_scene(block), results, True)
    got = _values(results)
    h = (2.5 - 1.0) / 2.5
    assert got["h"] == pytest.approx(h) and got["case"] == "III"
    # Theorem 3: the steady state of (5.49), r = m3/mu and (p, q) from the 2x2 linear system it leaves
    r = 0.3 / 0.5
    p, q = np.linalg.solve([[-0.3, h * r], [-h * r, -0.3]], [-0.4, 0.2])
    assert (got["limit_p"], got["limit_q"], got["limit_r"]) == pytest.approx((p, q, r), rel=1e-12)
    run = _lee_549(h, 0.3, 0.5, (0.4, -0.2, 0.3), [0.5, 0.8, 2.0], 60.0, [60.0])
    assert got["limit_gap"] == pytest.approx(np.max(np.abs(run.y[:, -1] - [p, q, r])), rel=1e-4)
    assert got["closed_vs_ode"] < 1e-9
    # Theorem 1: |p|, |q| <= delta + (|m1| + |m2|)/nu, |r| <= |r0| + |m3|/mu
    assert 0 < got["theorem_1_ratio"] <= 1
    assert got["singular_points"][0]["type"] == "stable focus"
    # w = 1 + (nu + i g1)/mu, g1 = h m3/mu, xi's final rate (5.27)
    g1 = h * r
    assert complex(got["w_real"], got["w_imag"]) == pytest.approx(1 + (0.3 + 1j * g1) / 0.5, rel=1e-14)
    assert all(case["holds"] for case in results.stability)
    assert "solution" in results.figures


def test_viscous_run_without_friction_circles_about_theorem_2s_center():
    block = {"torque": [0.4, -0.2, 0.0], "omega0": [0.5, 0.8, 2.0], "t_max": 10}
    results = _results()
    viscous.run(_viscous_scene(block, drag=False), results, True)
    got = _values(results)
    h, r0 = 0.6, 2.0
    # Theorem 2: the permanent rotation (m2/(h r0), -m1/(h r0), r0), period 2 pi/|h r0|
    center = got["singular_points"][0]
    assert (center["p"], center["q"], center["r"]) == pytest.approx((-0.2 / (h * r0), -0.4 / (h * r0), r0))
    assert got["period_tau"] == pytest.approx(2 * np.pi / (h * r0), rel=1e-14)
    assert got["period_measured"] == pytest.approx(2 * np.pi / (h * r0), rel=1e-9)
    assert got["radius_spread"] < 1e-10
    run = _lee_549(h, 0.0, 0.0, (0.4, -0.2, 0.0), [0.5, 0.8, 2.0], 10.0, np.linspace(0, 10, 101))
    radius = np.hypot(run.y[0] - center["p"], run.y[1] - center["q"])
    assert np.ptp(radius) < 1e-9  # the circle, from scipy's integration of (5.49)


def test_viscous_run_without_friction_with_an_axial_torque_has_no_singular_point():
    block = {"torque": [0.4, -0.2, 0.3], "omega0": [0.5, 0.8, 2.0], "t_max": 6}
    results = _results()
    viscous.run(_viscous_scene(block, drag=False), results, True)
    got = _values(results)
    assert got["singular_points"] == []
    assert got["r_final"] == pytest.approx(2.0 + 0.3 * 6, rel=1e-13)  # r = r0 + m3 t
    t = np.linspace(0.0, 6.0, viscous.SAMPLES)
    run = _lee_549(0.6, 0.0, 0.0, (0.4, -0.2, 0.3), [0.5, 0.8, 2.0], 6.0, t)
    assert got["pq_max"] == pytest.approx(np.max(np.abs(run.y[:2])), rel=1e-9)
    assert got["closed_form_error"] <= got["closed_form_bound"] + 1e-13


def test_large_order_bound_holds_and_the_factor_is_lees():
    V = viscous.medium(
        _viscous_scene(
            {"nu": 0.3, "mu": 0.5, "torque": [0.4, -0.2, 0.3], "omega0": [0.5, 0.8, 2.0], "t_max": 1}
        ).data
    )
    results = _results()
    viscous.large_order(results, V, nu=0.32, mu=0.05, times=(5.0, 20.0))
    got = _values(results)
    h, g1 = 0.6, 0.6 * 0.3 / 0.05  # xi's final rate h m3/mu
    assert complex(got["large_order_w_real"], got["large_order_w_imag"]) == pytest.approx(
        1 + (0.32 + 1j * g1) / 0.05, rel=1e-13
    )
    # the formula in double precision loses digits here (w = 7.4 + 72i, |g| = 48): its error against 30
    # digits is its distance from the true motion, scipy's integration of (5.49), and its bound covers it
    run = _lee_549(h, 0.32, 0.05, (0.4, -0.2, 0.3), [0.5, 0.8, 2.0], 20.0, [5.0, 20.0])
    y, _ = replace(V, nu=0.32, mu=0.05).closed_form([5.0, 20.0])
    distance = np.max(np.hypot(*(y[:, :2] - run.y.T[:, :2]).T))
    assert got["large_order_error"] == pytest.approx(distance, rel=1e-6)
    assert 1e-3 < got["large_order_error"] <= got["large_order_bound"] + 1e-13


def test_solution_costs_reach_the_30_digit_state_by_series_and_integration():
    V = viscous.medium(
        _viscous_scene(
            {"nu": 0.3, "mu": 0.5, "torque": [0.4, -0.2, 0.3], "omega0": [0.5, 0.8, 2.0], "t_max": 1}
        ).data
    )
    results = _results()
    viscous.solution_costs(results, V, True, t_end=2.0)
    frame = results.tables["accuracy_solution"][0]
    # more terms of the series, a smaller error; the best integrator reaches 1e-10
    series = frame[frame.method == "Lee formula, series"].sort_values("setting")
    assert series.error.iloc[-1] < 1e-12 < series.error.iloc[0]
    assert frame[frame.method == "scipy:DOP853"].error.min() < 1e-10
    # the state at t = 2 against scipy's own integration of (5.49)
    run = _lee_549(0.6, 0.3, 0.5, (0.4, -0.2, 0.3), [0.5, 0.8, 2.0], 2.0, [2.0])
    state, _ = V.closed_form([2.0])
    np.testing.assert_allclose(state[0], run.y[:, 0], atol=1e-10)


def test_special_function_costs_keep_their_bounds():
    results = _results()
    viscous.special_function_costs(results, True)
    got = _values(results)
    assert got["si_ci_error_over_bound"] <= 1.0
    assert all(case["holds"] for case in results.stability)
    # the series serves small x, the expansion large x (Lee (5.38)-(5.48))
    assert got["si_ci_reaches_1e-12_x2_series"] == 1
    assert got["si_ci_asymptotic_error_x30"] < 1e-12
