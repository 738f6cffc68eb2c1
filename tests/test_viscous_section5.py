"""Lee §5 checks of studies/self_excited/section5.py: the time-dependent torque's quadratures, Cases I and IV,
the spiral, the hyperbola of permanent rotations, the reduction formulas (5.32)-(5.37) and Re w."""

from __future__ import annotations

from dataclasses import replace

import mpmath
import numpy as np
import pytest

from classical_dynamics import units
from classical_dynamics.models.viscous_medium import ViscousMedium, modulation, viscous_modulated
from classical_dynamics.results import Results
from classical_dynamics.solvers import sine_cosine_integrals as sc
from classical_dynamics.solvers.ode import Problem, solve
from classical_dynamics.studies.self_excited import section5 as s5

V3 = ViscousMedium.from_moments(2.5, 1.0, 0.3, 0.5, (0.4, -0.2, 0.3), (0.5, 0.8, 2.0))
V2 = replace(V3, m=(0.4, -0.2, 0.0))
FREE2 = replace(V2, nu=0.0, mu=0.0)


@pytest.mark.parametrize("kind, a, b", [(0, 0.5, 2.0), (1, 1.0, 1.0)])
@pytest.mark.parametrize("V", [V3, replace(V3, nu=0.0, mu=0.0)])
def test_time_dependent_quadratures_against_eulers_equations(V, kind, a, b):
    t = 7.0
    ode = solve(
        Problem(viscous_modulated, list(V.omega0), (0.0, t), np.r_[V.parameters(), kind, a, b]),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
    ).y
    q = s5._quadratures(V, modulation(kind, a, b), t)
    assert np.max(np.abs(q["general"] - ode)) < 1e-10
    assert np.max(np.abs(q["fixed"] - ode)) < 1e-10
    assert np.max(np.abs(q["principal"] - ode)) > 1e-2  # m2 < 0: the principal arctan is the wrong angle


def test_constant_modulus_reduces_to_the_constant_torque_solution():
    """F = 1 (a = 0): the time-dependent quadratures equal the model's constant-torque solution (si, ci)."""
    q = s5._quadratures(V3, modulation(0, 0.0, 1.0), 5.0)
    assert np.max(np.abs(q["fixed"] - V3.closed_form([5.0])[0][0])) < 1e-10


def test_case_one_and_four_are_straight_and_reach_the_point():
    one, four = s5.case_one(V2), s5.case_four(V3)
    for name, value in (
        ("case_one_lee_vs_ode", one.linear.lee),
        ("case_one_line_distance", one.linear.line_pq),
        ("case_one_frictionless_gap", one.linear.frictionless),
        ("case_four_lee_vs_ode", four.linear.lee),
        ("case_four_line_distance", four.linear.line_pq),
        ("case_four_frictionless_gap", four.linear.frictionless),
        ("case_four_space_line_distance_equal_drags", four.line_equal_drags),
    ):
        assert value < 1e-11, name
    assert one.linear.gap < 1e-8 and four.linear.gap < 1e-8
    assert one.r_max == 0.0
    assert four.linear.line_space > 0.1  # nu != mu: curved in space


def test_case_four_records_its_checks_under_their_names():
    four = s5.case_four(V3)
    results = Results("self_excited", "t", "t")
    s5._record_case_four(results, four)
    got = {name: entry["value"] for name, entry in results.numbers.items()}
    assert got == {
        "case_four_lee_vs_ode": four.linear.lee,
        "case_four_model_vs_ode": four.linear.model,
        "case_four_line_distance": four.linear.line_pq,
        "case_four_space_line_distance": four.linear.line_space,
        "case_four_limit_gap": four.linear.gap,
        "case_four_frictionless_gap": four.linear.frictionless,
        "case_four_space_line_distance_equal_drags": four.line_equal_drags,
    }
    # distances of angular velocities: rates, per time unit
    assert {entry["unit"] for entry in results.numbers.values()} == {"1/time"}
    # h = 0 (C = A) is Lee's Case IV: Euler's equations are linear, and the model's solution of that case
    # follows them
    assert four.linear.case == "IV" and four.linear.model < 1e-11
    # a note names what it checks: no label left out as None
    assert not any("None" in entry.get("note", "") for entry in results.numbers.values())


def test_lee_linear_formula_is_not_the_integrator():
    """A wrong drag in Lee's (5.18) must be caught: the check compares two independent things."""
    t = np.linspace(0.0, 10.0, 11)
    V1 = replace(V2, omega0=(0.5, 0.8, 0.0))
    y = s5._euler(V1, V1.omega0, t)
    assert np.max(np.abs(s5._lee_linear(V1, V1.omega0, t) - y)) < 1e-12
    assert np.max(np.abs(s5._lee_linear(replace(V1, nu=0.31), V1.omega0, t) - y)) > 1e-3


def test_spiral_rates_and_hyperbola():
    spiral = s5.spiral(V3)
    assert abs(spiral.decay_rate / V3.nu - 1) < 1e-8
    assert abs(spiral.turn_rate / V3.g1 - 1) < 1e-8
    # started on the plane r = m3/mu, omega stays in it (r' = m3 - mu r for the equal moments A = B)
    results = Results("self_excited", "x", "x")
    s5._record_spiral(results, spiral)
    assert results.numbers["spiral_plane_gap"]["value"] < 1e-12
    curve = s5.singular_curve(FREE2)
    panels, _ = s5.singular_curve_panels(curve)
    assert curve.drift < 1e-12
    assert abs(curve.k_mean + np.hypot(0.4, 0.2) / FREE2.h) < 1e-14
    assert curve.circle_center_gap < 1e-10 and len(panels) == 1


def test_a_point_off_the_hyperbola_moves():
    """The drift check can fail: a point beside the curve runs round a circle."""
    pt = np.array([-0.2 / (0.6 * 2.0) + 0.1, -0.4 / (0.6 * 2.0), 2.0])
    y = s5._euler(FREE2, pt, np.linspace(0.0, 5.0, 11))
    assert np.max(np.abs(y - pt)) > 0.05


@pytest.mark.parametrize("K", [1, 2, 3, 4, 5])
@pytest.mark.parametrize("x", [0.3, 3.0])
def test_reduction_formulas_and_the_printed_sign(K, x):
    w = K + complex(0.6, 0.72)
    with mpmath.workdps(40):
        si, ci = s5.lee_reduction(x, w)
        ref_si, ref_ci = sc.reference(x, w, dps=40)
        assert abs(si - ref_si) < 1e-30 * abs(ref_si) and abs(ci - ref_ci) < 1e-30 * abs(ref_ci)
        if K in (3, 5):  # P != 0 for K odd only from K = 3
            wrong, _ = s5.lee_reduction(x, w, ocr_sign=True)
            assert abs(wrong - ref_si) > 1e-3 * abs(ref_si)


def test_reduction_a_b_and_re_w():
    reduction = s5.reduction_formulas(V3)
    assert reduction.a_b_error < 1e-25 and reduction.relative_error < 1e-30
    # w' = w - floor(Re w), w = 1 + (nu + i g1)/mu (5.27), g1 = h m3/mu, h = (A - C)/A: the fractional order
    # the formulas run at
    w = 1 + (0.3 + 1j * 0.6 * 0.3 / 0.5) / 0.5
    assert reduction.w1 == pytest.approx(w - np.floor(w.real), rel=1e-14)
    results = Results("self_excited", "t", "t")
    s5._record_reduction_formulas(results, reduction)
    recorded = results.numbers
    assert {name: entry["value"] for name, entry in recorded.items()} == {
        "reduction_relative_error": reduction.relative_error,
        "reduction_ocr_sign_error": reduction.ocr_sign_error,
        "reduction_A_B_error": reduction.a_b_error,
    }
    assert all(units.lookup(entry["unit"]) is None for entry in recorded.values())  # relative errors
    assert reduction.ocr_sign_error > 1e-3  # the OCR's +P cos x in si (K = 3) is wrong
    # how wrong: at w = 3 + w', x = 0.5, 2, 8, against the incomplete gamma function (mpmath), as printed
    with mpmath.workdps(40):
        ocr = max(
            float(abs(s5.lee_reduction(x, 3 + reduction.w1, ocr_sign=True)[0] - ref) / abs(ref))
            for x in (0.5, 2.0, 8.0)
            for ref in [sc.reference(x, 3 + reduction.w1, dps=40)[0]]
        )
    assert reduction.ocr_sign_error == pytest.approx(ocr, rel=1e-9)
    re_w = s5.re_w(V3)
    assert re_w.formula == pytest.approx(1.6, rel=1e-15)
    assert 1.0 < min(re_w.elongated) < max(re_w.elongated) < 2.0 < min(re_w.disc)
    assert max(re_w.disc) == pytest.approx(3.0, rel=1e-15)


@pytest.mark.parametrize("s", [0.3, 7.0, 30.0])
def test_gauss_rule_of_xi_against_quad(s):
    from scipy import integrate

    f = lambda u: (1.0 + 0.5 * np.sin(2.0 * u)) * (1.0 - np.exp(-0.5 * (s - u)))
    assert (
        abs(s5._gauss(f, s) - integrate.quad(f, 0.0, s, epsabs=1e-15, epsrel=1e-14, limit=200)[0]) < 1e-13 * s
    )


def test_every_added_panel_labels_both_axes_with_units():
    """The panels Cases I and IV add beside the solution: each axis named, in Lee's scaled units."""
    import matplotlib.pyplot as plt

    drawers = s5.case_one_panels(s5.case_one(V2))[0] + s5.singular_curve_panels(s5.singular_curve(FREE2))[0]
    fig, axes = plt.subplots(1, len(drawers))
    for draw, ax in zip(drawers, axes):
        draw(ax)
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            assert label.endswith("(rad per time unit)"), label
    plt.close(fig)
