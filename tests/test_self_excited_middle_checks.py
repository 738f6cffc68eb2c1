"""Lee §3.1-§3.4 and §4.1 checks (middle_checks.py, symbolic.py): each passes on Lee's formulas and fails on a
deliberately wrong one."""

import numpy as np
import sympy as sp

from classical_dynamics.models import self_excited as se
from classical_dynamics.studies.self_excited import middle_checks as mc
from classical_dynamics.studies.self_excited import symbolic

BODY = se.Body.from_moments([3.0, 2.2, 1.2])


def test_lindstedt_matches_lee_and_detects_a_wrong_coefficient():
    differ, total, found = symbolic.lindstedt()
    assert differ == [] and total == 10
    k2, b2, b3, m1 = sp.symbols("k2 beta2 beta3 mu1")
    wrong = (
        sp.Rational(28, 576) * b2**2 / k2**2
        + sp.Rational(137, 288) * b2 * m1 / k2
        + b3 / (192 * k2)
        + sp.Rational(61, 72) * m1**2
    )
    assert sp.simplify(found["theta3_1"] - wrong) != 0
    assert found["h1"] == 0


def test_k_constants_mu_c_and_nu_c_by_sympy():
    assert symbolic.k_constants() == 0
    factors, exceptions, samples, below = symbolic.mu_c_regimes(np.random.default_rng(0), samples=400)
    assert factors == 0 and exceptions == 0 and 0 < below < samples
    identity, exact, largest, bodies = symbolic.nu_c(np.random.default_rng(0), samples=20000)
    assert identity == 0 and exact == sp.Rational(9, 22) and 0.45 < largest < 0.5


def _sinh(nu=0.2):
    return se.MiddleAxis.with_plane_parameters(BODY, 0.5, -nu, 0.8, 0.3)


def test_theta_series_orders_and_a_wrong_theta2_is_caught(monkeypatch):
    M = _sinh()
    center = float(np.arcsinh(0.5))
    k_sq, beta2, beta3 = np.sqrt(1.25), -0.5, -np.sqrt(1.25)
    slopes = mc.theta_series(M, center, k_sq, beta2, beta3).slopes
    assert abs(slopes[0] - 2) < 0.3 and abs(slopes[1] - 3) < 0.3 and abs(slopes[2] - 4) < 0.3
    right = mc.lee_theta2
    monkeypatch.setattr(mc, "lee_theta2", lambda s, k, b, m: 1.1 * right(s, k, b, m))
    assert mc.theta_series(M, center, k_sq, beta2, beta3).slopes[1] < 2.3


def test_general_solution_and_k_identity_along_euler():
    M = _sinh()
    out = mc.general_solution(M, M.from_plane(0.2, 0.5), 12.0 / M.time_scale)
    # independent methods: Euler's equations integrated (DOP853) against Lee's (3.3) and (3.8) in closed form,
    # which call no integrator; a coefficient of m0 scaled 0.5 -> 0.45, or Euler's r' scaled by 0.9, fails it
    assert out.error < 1e-10 and out.k_identity_error < 1e-10


def test_center_rests_and_middle_axis_is_unstable():
    M = se.MiddleAxis.with_plane_parameters(BODY, 0.5, 0.0, 0.8, 0.3)
    assert mc.center_at_rest(M, float(np.arcsinh(0.5))).drift < 1e-12
    assert mc.middle_axis_unstable(M) > 0.5


def test_plane_one_large_q0_has_no_exceptions():
    M = se.MiddleAxis.with_plane_parameters(BODY, 0.5, -0.2, 0.6, 0.6)
    out = mc.large_q0(M, m3s=(5.0,))
    assert out.runs == 8 and out.exceptions == 0


def test_plane_departure_is_rounding_in_plane_two():
    M = se.MiddleAxis.with_plane_parameters(BODY, -0.5, -0.1, 0.6, -0.6)
    assert mc.plane_departure(M, M.from_plane(0.5, 0.0), 12.0 / M.time_scale) < 1e-12


def test_a_middle_plane_with_a_saddle_draws_its_separatrix_through_it():
    """The curve drawn through a saddle of a middle-axis plane is its separatrix: named so in the portrait's
    table, and it meets q1 = 0 at the saddle's phi2 (geometry of the drawing, not the module's own label)."""
    from pathlib import Path

    from classical_dynamics.studies import study_module, validate

    scenes = Path(__file__).resolve().parents[1] / "workflow" / "scenes" / "self_excited"
    scene = validate("self_excited", scenes / "middle_plane_two_saddle.yaml")
    portrait = study_module("self_excited").run(scene, quick=True).tables["portrait"][0]
    (saddle,) = portrait.phi2[portrait.element == "saddle"]
    separatrix = portrait[portrait.element == "separatrix"]
    assert not separatrix.empty and "curve_C0" not in set(portrait.element)
    near = separatrix.iloc[np.argsort(np.abs(separatrix.phi2.values - saddle))[:4]]
    assert np.min(np.abs(near.phi2 - saddle)) < 1e-3 and np.min(np.abs(near.q1)) < 1e-3  # the drawn grid
