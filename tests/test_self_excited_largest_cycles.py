"""Lee §2.5-§2.6 for the torque along the largest axis (studies/self_excited/largest_cycles.py): Figure 2.12's
crossings, the motions on and off F, and the other torques of §2.6 that reduce to the same planes."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import sympy as sp

from classical_dynamics import units
from classical_dynamics.models import self_excited as se
from classical_dynamics.results import Results
from classical_dynamics.solvers.ode import Problem, solve
from classical_dynamics.studies.self_excited import largest_cycles as lc
from classical_dynamics.studies.self_excited import portrait

BODY = se.Body.from_moments([3.0, 2.2, 1.2])


def test_c1_of_2_29_is_zero_at_lees_start_symbolically():
    """(2.29) with C1 = 0 at phi2 = -sigma3 has p1^2 = m1/nu: solved for C1 there it is exactly zero
    (sympy)."""
    m1, nu = sp.symbols("m1 nu", positive=True)
    sigma3 = sp.atan(-1 / (2 * nu))
    phi = -sigma3
    p1_sq = m1 / nu  # the start sqrt(m1/nu), squared
    C1 = sp.exp(2 * nu * phi) * (p1_sq - m1 / nu - 2 / sp.sqrt(1 + 4 * nu**2) * sp.sin(phi + sigma3))
    assert sp.simplify(C1) == 0
    # and (2.29)'s sine form is Lee's (2.13) with mu1 = -nu: 2(2 mu1 sin + cos)/(1 + 4 mu1^2) = -2 sin(x +
    # s3)/sqrt
    x = sp.symbols("x", real=True)
    lhs = -2 * (-2 * nu * sp.sin(x) + sp.cos(x)) / (1 + 4 * nu**2)
    rhs = 2 / sp.sqrt(1 + 4 * nu**2) * sp.sin(x + sigma3)
    for xv, nv in ((0.3, 0.1), (2.0, 0.7), (-1.1, 2.5)):
        assert float((lhs - rhs).subs({x: xv, nu: nv})) == pytest.approx(0.0, abs=1e-14)


def test_start_with_c1_zero_closes_and_a_start_just_off_it_does_not():
    closure = lc.c1_zero_start(0.5, 0.1)
    assert abs(closure) < 1e-9
    results = Results("self_excited", "t", "t")
    lc._record_c1_zero_start(results, closure)
    recorded = results.numbers["c1_zero_start_closure"]
    assert recorded["value"] == closure and units.lookup(recorded["unit"]) is None  # a difference of p1
    sigma3 = np.arctan(-1.0 / 0.2)
    start = np.sqrt(5.0) + 1e-3  # C1 != 0: the term C1 e^{2 nu phi2} grows over the turn
    sol = solve(
        Problem(se.plane_by_phase, [0.0, start], (-sigma3, -sigma3 + 2 * np.pi), [0.5, -0.1]),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
    )
    assert abs(sol.y[1] - start) > 1e-4


@pytest.mark.parametrize("offset, escapes", [(-1e-3, True), (1e-3, False), (-0.5, True), (0.05, False)])
def test_just_below_F1_runs_away_just_above_tends_to_F(offset, escapes):
    """The hard case: F1 is unstable, so a start 1e-3 below it still leaves every bound in finite time, and
    one 1e-3 above it winds onto F."""
    m1, nu = 0.5, 0.1
    F1 = -float(se.limit_cycle_p1(np.zeros(1), m1, nu)[0])
    sol = solve(
        Problem(se.plane_largest, [0.0, F1 + offset], (0.0, 150.0), [m1, -nu, 1.0]),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        bound=portrait.BLOW_UP_BOUND,
    )
    assert (sol.status == "blow-up") == escapes
    if not escapes:
        assert abs(sol.y[1] - se.limit_cycle_p1(np.array([sol.y[0]]), m1, nu)[0]) < 1e-6


def test_reversal_in_eulers_equations_runs_to_the_negative_x_axis():
    v = lc.reversal(BODY, 0.5, 0.1, 1.0)
    assert v.escaped
    assert v.direction == pytest.approx(-1.0, abs=1e-9)
    assert v.above_distance < 1e-6


def test_f1_above_f2_below_nu_star_and_below_above_it():
    for nu, sign in (
        (0.1, 1),
        (0.5, -1),
        (se.nu_star(0.5) * (1 - 1e-4), 1),
        (se.nu_star(0.5) * (1 + 1e-4), -1),
    ):
        x = lc.crossings(0.5, nu)
        assert np.sign(x["f1"] - x["f2"]) == sign
    x = lc.crossings(0.5, 0.1)
    assert x["g1_kind"] == "vertical" and x["g2_kind"] == "axis"  # Lee's reading of Figure 2.12
    assert x["g1"][0] == pytest.approx(np.arcsin(-0.5) + 2 * np.pi, abs=1e-10)
    assert abs(x["g2"][1]) < 1e-10 and np.arcsin(-0.5) < x["g2"][0] < np.pi - np.arcsin(-0.5)


@pytest.mark.parametrize("m1", [0.3, 0.5, 0.8])
def test_the_sign_change_of_f1_minus_f2_is_lees_nu_star(m1):
    assert lc.nu_where_f1_meets_f2(m1, 0.01, 3.0) == pytest.approx(m1 / (2 * np.sqrt(1 - m1**2)), rel=1e-9)


def test_figure_2_12_numbers_and_zoom_table_against_the_closed_form():
    v = lc.figure_2_12(0.5, 0.1)
    assert v.deviation < lc.CROSSING_BOUND
    zoom = lc.zoom_table(0.5, 0.1, v.crossings)
    crossing = zoom[zoom.element == "crossing"].sort_values("curve")
    assert list(crossing.curve) == [1, 2, 3, 4]
    assert crossing.p1.iloc[0] == pytest.approx(v.crossings["f1"], abs=1e-5)
    assert set(zoom.element) >= {
        "separatrix_T",
        "limit_cycle_F",
        "limit_cycle_F1",
        "saddle",
        "center",
        "window",
    }
    # every element is one the gallery's panel styles (portrait.draw): another would vanish from the grid
    assert set(zoom.element) <= set(portrait.ELEMENTS) | set(portrait.POINT_TYPES) | {"window"}
    # F and its mirror F1 of (2.30), written out here: p1^2 = m1/nu + 2 sin(phi2 + sigma3)/sqrt(1 + 4 nu^2)
    sigma3 = np.arctan(-1 / 0.2)
    for element, sign in (("limit_cycle_F", 1.0), ("limit_cycle_F1", -1.0)):
        rows = zoom[zoom.element == element]
        closed = sign * np.sqrt(5.0 + 2 * np.sin(rows.phi2 + sigma3) / np.sqrt(1.04))
        np.testing.assert_allclose(rows.p1, closed, atol=1e-4)  # the table keeps five decimals


def _separatrix_p1_squared(phi, m1, nu, saddle):
    """Lee (2.13) solved here: with u = p1^2, (2.10) is du/dphi2 + 2 nu u = 2 (m1 + sin phi2), so
    u = m1/nu + (4 nu sin phi2 - 2 cos phi2)/(1 + 4 nu^2) + C e^(-2 nu phi2), C fixed by u = 0 at the
    saddle."""
    g = lambda x: m1 / nu + (4 * nu * np.sin(x) - 2 * np.cos(x)) / (1 + 4 * nu**2)  # noqa: E731
    return g(phi) - g(saddle) * np.exp(-2 * nu * (phi - saddle))


def test_figure_2_12_records_the_heights_of_the_closed_form_and_where_t1_ends():
    m1, nu = 0.5, 0.1
    values = lc.figure_2_12(m1, nu)
    zoom = lc.zoom_table(m1, nu, values.crossings)
    results = Results("self_excited", "t", "t")
    lc._record_figure_2_12(results, values, zoom)
    got = {name: entry["value"] for name, entry in results.numbers.items()}
    s1 = np.arcsin(-m1)
    center, s2 = np.pi - s1, s1 + 2 * np.pi
    f1, f2 = (np.sqrt(_separatrix_p1_squared(center, m1, nu, s)) for s in (s1, s2))
    assert got["f1_height"] == pytest.approx(f1, abs=1e-8) and got["f2_height"] == pytest.approx(f2, abs=1e-8)
    # below Lee's nu* = m1/(2 sqrt(1 - m1^2)) (0.289 here) f1 lies above f2
    assert nu < m1 / (2 * np.sqrt(1 - m1**2)) and got["f1_minus_f2"] == pytest.approx(f1 - f2, abs=2e-8)
    assert got["f1_minus_f2"] > 0
    # T1 reaches the vertical through S2 (g1 on it, above the axis by the closed form's height there); T2,
    # traced back, falls to the phi2-axis (g2) between the saddles
    assert got["g1_kind_vertical"] == 1 and got["g1_phi2"] == pytest.approx(s2, abs=1e-10)
    assert got["g1_p1"] == pytest.approx(np.sqrt(_separatrix_p1_squared(s2, m1, nu, s1)), abs=1e-7)
    assert got["g2_kind_axis"] == 1 and s1 < got["g2_phi2"] < s2
    assert got["crossing_closed_deviation"] == pytest.approx(
        max(abs(got["f1_height"] - f1), abs(got["f2_height"] - f2)), abs=1e-12
    )
    assert results.stability[0]["measured"] == got["crossing_closed_deviation"]
    assert results.tables["zoom"][0] is zoom


def test_omega_on_F_returns_after_two_turns_of_phi2_not_one():
    v = lc.periodic_motion(BODY, 0.5, 0.1, 1.0)
    assert v.period_tau == pytest.approx(2 * se.limit_cycle_period(0.5, 0.1), rel=1e-9)
    assert v.return_error < 1e-9
    assert v.half_reversed_error < 1e-9
    assert v.half_distance > 0.5
    results = Results("self_excited", "x", "x")
    lc._record_periodic_motion(results, v)
    recorded = {name: (e["value"], e["unit"]) for name, e in results.numbers.items()}
    assert recorded == {
        "omega_period_tau_F_measured": (v.period_tau, "τ"),  # in Lee's time tau, as the series' periods
        "omega_return_error": (v.return_error, "1"),
        "omega_half_reversed_error": (v.half_reversed_error, "1"),
        "omega_half_distance": (v.half_distance, "1"),
    }


def test_permanent_rotations_about_x_and_F_shrinking_onto_the_stable_one():
    v = lc.permanent_rotations(BODY, 0.5, 0.1, 1.0)
    L = se.LargestAxis.with_plane_parameters(BODY, 0.5, -0.1, 1.0)
    assert v.P == pytest.approx(np.sqrt(L.m / -L.mu), rel=1e-14)
    assert v.drift < 1e-12
    assert v.plus_kicked < 1e-5
    assert v.minus_rate == pytest.approx(2 * np.sqrt(-L.m * L.mu), rel=1e-3)
    results = Results("self_excited", "x", "x")
    lc._record_permanent_rotations(results, v)
    assert results.numbers["x_rotation_minus_rate"]["value"] == pytest.approx(
        2 * np.sqrt(-L.m * L.mu), rel=1e-3
    )
    ratio = v.limit.ratio.to_numpy()
    assert np.all(np.diff(np.abs(1 - ratio)) < 0) and abs(1 - ratio[-1]) < 0.01


def test_m1_passes_one_where_the_closed_form_says_and_x_stays_stable():
    v = lc.axis_stable(BODY, 1.5, 0.1, 1.0)
    L = se.LargestAxis.with_plane_parameters(BODY, 1.5, -0.1, 1.0)
    b, c = BODY.b, BODY.c
    assert v.delta_m1_one == pytest.approx(np.sqrt(2 * L.m / (L.R - L.mu * (b + c))), rel=1e-12)
    assert se.LargestAxis(BODY, L.m, L.mu, 0.5 * v.delta_m1_one).m1 > 1.0
    assert v.angle_ratio < 10


def test_other_torques_of_section_2_6_reduce_to_the_planes():
    yz = lc.torque_yz(BODY, 0.5, 1.0)
    grammel = lc.torque_grammel(BODY, 0.5, 0.1, 1.0)
    assert yz.m1 == pytest.approx(0.5, rel=1e-12)
    assert yz.overlay < 1e-8 and yz.energy_spread < 1e-10
    assert grammel.overlay < 1e-8 and grammel.c1_spread < 1e-10 and grammel.to_F < 1e-6


def test_the_torque_laws_differ_so_the_overlay_can_fail():
    """Integrating the |omega|^2 torque but mapping as Grammel's (sigma1 = 0) must not lie on the plane."""
    bc = np.sqrt(BODY.b * BODY.c)
    m = 0.5 * 0.5 * BODY.a * bc
    L = se.LargestAxis(BODY, m, 0.0, 1.0)
    wrong = np.array([BODY.a, BODY.b, BODY.c, m, -2.0 * bc * 0.1])  # euler_largest with mu < 0
    deviation, _ = lc._overlay(se.euler_largest, wrong, L, (0.5, -0.1), lc.OTHER_STARTS)
    assert deviation > 1e-3


def test_the_zoom_panel_draws_its_crossings_with_their_names():
    from classical_dynamics.results import new_figure

    zoom = lc.zoom_table(0.5, 0.1, lc.figure_2_12(0.5, 0.1).crossings)
    fig, ax = new_figure()
    portrait.draw(ax, zoom, "p1", small=True)
    assert sorted(t.get_text() for t in ax.texts) == ["$f_1$", "$f_2$", "$g_1$", "$g_2$"]
    assert isinstance(zoom, pd.DataFrame)
