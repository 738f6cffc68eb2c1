"""Direct unit tests of studies/solvers/heavy_top.py (scene heavy_top) against references it does not compute:
Lamb's quadratic of steady precession solved here, the nutation frequency from sympy's second derivative of
the effective potential in theta (not Lamb's formula (13) the module uses), the conical pendulum, and the
roots' approach to their limits in closed form."""

import matplotlib.pyplot as plt
import numpy as np
import pytest
import sympy as sp

from classical_dynamics.models import heavy_top as top_model
from classical_dynamics.results import Results
from classical_dynamics.studies.solvers import heavy_top

TOP = top_model.Top(1.0, 0.5, 1.0)  # the scene's body: A = Mgh = 1, C = 1/2
SPIN = 6.0


def effective_sigma(A, Mgh, J3, alpha, omega):
    """Small oscillations of theta about a steady precession at rate omega: with
    Jz = A omega sin^2 a + J3 cos a (so that phi' = omega at theta = a), theta obeys A theta'' = -U'(theta)
    with the effective potential U = (Jz - J3 cos theta)^2 / (2 A sin^2 theta) + Mgh cos theta;
    sigma^2 = U''(a) / A."""
    th = sp.Symbol("theta")
    Jz = A * omega * np.sin(alpha) ** 2 + J3 * np.cos(alpha)
    U = (Jz - J3 * sp.cos(th)) ** 2 / (2 * A * sp.sin(th) ** 2) + Mgh * sp.cos(th)
    assert abs(float(sp.diff(U, th).subs(th, alpha))) < 1e-9 * max(1.0, abs(Jz))  # a steady state
    return np.sqrt(float(sp.diff(U, th, 2).subs(th, alpha)) / A)


def test_steady_precession_rates_solve_lambs_quadratic_and_hold(monkeypatch):
    spans, run = [], heavy_top._run
    monkeypatch.setattr(
        heavy_top, "_run", lambda top, y0, T, *a, **k: spans.append(T) or run(top, y0, T, *a, **k)
    )
    r = heavy_top.steady(TOP, SPIN, 1e-10)
    frame = r.frame
    J3 = TOP.C * SPIN
    for row in frame.itertuples():
        c = np.cos(np.radians(row.alpha_deg))
        # A w^2 cos a - J3 w + Mgh = 0, the smaller root the slow one
        assert TOP.A * row.rate**2 * c - J3 * row.rate + TOP.Mgh == pytest.approx(0.0, abs=1e-12)
        other = J3 / (TOP.A * c) - row.rate  # the sum of the roots
        assert abs(row.rate) < abs(other) if row.root == "slow" else abs(row.rate) > abs(other)
    assert (
        len(frame) == 6 and frame.theta_deviation.max() < 1e-8 and frame.rate_relative_difference.max() < 1e-8
    )
    # each run is the table caption's ten turns of its precession
    assert np.array(spans[:6]) * np.abs(frame.rate.to_numpy()) == pytest.approx(
        np.full(6, 20 * np.pi), rel=1e-14
    )
    # the conical pendulum (no spin) at 120 degrees: g/(l |cos a|) with A = M l^2, Mgh = M g l
    assert r.conical_rate == pytest.approx(np.sqrt(TOP.Mgh / (TOP.A * 0.5)), rel=1e-14)
    assert r.conical_theta_deviation < 1e-8
    # no steady state below J3^2 = 4 A Mgh cos 60 = 2 A Mgh
    assert r.threshold_spin_60deg == pytest.approx(np.sqrt(2 * TOP.A * TOP.Mgh) / TOP.C, rel=1e-14)
    assert r.roots_exist_just_below is False and r.conical_roots_exist_above_support is False


def test_roots_approach_their_limits_as_the_spin_grows():
    # with x = 4 A Mgh cos a / J3^2 = 1/ratio: slow = (Mgh/J3) 2/(1 + sqrt(1 - x)), fast = (J3/(A cos a))
    # (1 + sqrt(1 - x))/2, so both differences are x/4 + O(x^2): slope -2 in J3
    r = heavy_top.roots_limits(TOP)
    x = 1.0 / np.geomspace(10.0, 1e4, 7)
    root = np.sqrt(1.0 - x)
    d_slow, d_fast = 2.0 / (1.0 + root) - 1.0, 1.0 - (1.0 + root) / 2.0
    assert r.slow_difference_at_10 == pytest.approx(d_slow[0], rel=1e-12)
    assert r.fast_difference_at_10 == pytest.approx(d_fast[0], rel=1e-12)
    log_j3 = -0.5 * np.log(x)  # log J3 up to a constant, which the slope does not see
    assert r.slow_slope == pytest.approx(np.polyfit(log_j3, np.log(d_slow), 1)[0], rel=1e-6)
    assert r.fast_slope == pytest.approx(np.polyfit(log_j3, np.log(d_fast), 1)[0], rel=1e-6)
    assert r.slow_slope == pytest.approx(-2.0, abs=0.02)
    assert r.fast_free_difference == pytest.approx(0.0, abs=1e-15)


def test_disturbed_precession_nutates_at_the_effective_potentials_frequency():
    frame = heavy_top.oscillation(TOP, 1e-10)
    assert len(frame) == 6
    for row in frame.itertuples():
        alpha = np.radians(row.alpha_deg)
        rate = top_model.steady_roots(TOP.A, TOP.C * 6.0, TOP.Mgh, alpha)[row.root == "fast"]
        sigma = effective_sigma(TOP.A, TOP.Mgh, TOP.C * 6.0, alpha, rate)
        assert row.sigma == pytest.approx(sigma, rel=1e-12)
        # measured from 80 apses of a 1e-4 disturbance: the amplitude's own correction is O(1e-8)
        assert row.measured == pytest.approx(sigma, rel=1e-7)


def test_horizontal_gyroscope():
    g = heavy_top.gyroscope(TOP, 1e-10)
    J3 = 10.0 * np.sqrt(TOP.A * TOP.Mgh)
    assert g.J3 == pytest.approx(J3, rel=1e-15)  # J3^2/(A Mgh) = 100
    rate = TOP.Mgh / J3  # theta = 90 degrees: the quadratic's only finite root
    assert g.rate_measured == pytest.approx(rate, rel=1e-7)
    sigma = effective_sigma(TOP.A, TOP.Mgh, J3, np.pi / 2, rate)
    assert g.nutation_frequency == pytest.approx(sigma, rel=1e-7)
    # sigma^2 = (J3/A)^2 + rate^2 there: above J3/A by rate^2 A^2 / (2 J3^2) = 5e-5
    assert g.nutation_vs_J3_over_A == pytest.approx(5e-5, rel=1e-3)


def test_integrals_in_euler_angles_and_conserved():
    # Lagrange's top in Euler angles: J3 = C w3, Jz = A phi' sin^2 theta + J3 cos theta,
    # E = A (theta'^2 + phi'^2 sin^2 theta)/2 + C w3^2/2 + Mgh cos theta, whatever phi and psi
    theta, theta_dot, phi_dot, w3 = 0.9, 0.4, -0.7, SPIN
    y0 = TOP.state(theta, theta_dot, phi_dot, w3, phi=0.3, psi=1.1)
    J3, Jz, E = (float(v[0]) for v in TOP.integrals(y0))
    assert J3 == pytest.approx(TOP.C * w3, rel=1e-15)
    assert Jz == pytest.approx(TOP.A * phi_dot * np.sin(theta) ** 2 + J3 * np.cos(theta), rel=1e-14)
    kinetic = 0.5 * TOP.A * (theta_dot**2 + (phi_dot * np.sin(theta)) ** 2) + 0.5 * TOP.C * w3**2
    assert E == pytest.approx(kinetic + TOP.Mgh * np.cos(theta), rel=1e-14)
    # the study's run: 20 nutations at rtol 1e-12 keep all three within 1e-10 (DOP853's global error)
    general = heavy_top.general(TOP, SPIN, np.radians(60.0), 20, 1e-12)
    assert 0 < max(general.drift) < 1e-10
    # each drift is recorded under its integral's name, and the hard case is the largest
    results = Results("solvers", "heavy_top", "t")
    heavy_top._record_general(results, general)
    recorded = {
        name: results.numbers[name]["value"] for name in results.numbers if name.startswith("integrals_")
    }
    assert recorded == {
        "integrals_J3_drift": general.drift[0],
        "integrals_Jz_drift": general.drift[1],
        "integrals_E_drift": general.drift[2],
        "integrals_max_drift": max(general.drift),
    }
    (case,) = [c for c in results.stability if c["name"] == "top_integrals"]
    assert case["measured"] == max(general.drift) and case["holds"]
    plt.close("all")
