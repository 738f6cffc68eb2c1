"""RATTLE on the hanging chain: a single pendulum against its elliptic-integral period; long-run energy."""

import numpy as np
import pytest
from scipy import special

from classical_dynamics.solvers import rattle
from classical_dynamics.solvers.fixed_step import FixedProblem, Save, solve_fixed
from classical_dynamics.solvers.special import laguerre_zeros
from classical_dynamics.studies.chains.time_domain import simulate


def pendulum(theta0, h, n_steps, every):
    """One particle of unit mass on a link of unit length, g = 1, through the door: its Solution."""
    q0 = rattle.positions_from_angles([theta0], 1.0)
    problem = FixedProblem(np.concatenate([q0.ravel(), np.zeros(2)]), [1.0, 1.0, 1.0])
    return solve_fixed(problem, "rattle", h=h, n_steps=n_steps, save=Save(every=every))


@pytest.mark.parametrize("theta0", [0.3, 1.0, 2.0])
def test_pendulum_period_against_elliptic_integral(theta0):
    # Exact: omega = pi sqrt(g/a) / (2 K(sin^2(theta0/2))). RATTLE's phase error is O(h^2).
    h = 2 * np.pi / 800
    extra = pendulum(theta0, h, 800 * 60, 50).extra
    tip, constraint = extra["tip_x"], extra["constraint"]
    measured, _ = rattle.crossing_frequency(tip, h)
    exact = np.pi / (2 * special.ellipk(np.sin(theta0 / 2) ** 2))
    assert measured == pytest.approx(exact, rel=2e-5)
    assert constraint < 1e-14


def test_order_two():
    theta0, exact = 0.8, np.pi / (2 * special.ellipk(np.sin(0.4) ** 2))
    errors = []
    for per in (100, 200):
        h = 2 * np.pi / per
        tip = pendulum(theta0, h, per * 40, 10).extra["tip_x"]
        errors.append(abs(rattle.crossing_frequency(tip, h)[0] - exact))
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.1)


def test_small_amplitude_chain_swings_at_its_eigenfrequencies():
    n = 4
    for mode in (1, 2):
        omega, h, tip, _, _, _ = simulate(n, 1.0, 9.81, mode, np.radians(0.05), 60, 80)
        measured, _ = rattle.crossing_frequency(tip, h)
        assert measured == pytest.approx(np.sqrt(9.81 * laguerre_zeros(n)[mode - 1] * n), rel=2e-4)


@pytest.mark.slow
def test_energy_error_stays_bounded_over_ten_thousand_periods():
    omega, h, tip, energies, constraint, sample = simulate(3, 1.0, 9.81, 1, np.radians(10), 10000, 30)
    rest = -9.81 * 1.0 * 4 / 2 / 3
    drift = np.abs(energies - energies[0]) / (energies[0] - rest)
    tenth = energies.size // 10
    assert drift.max() < 1e-3
    assert drift[-tenth:].max() < 2 * drift[:tenth].max()  # no growth: bounded, not drifting
    assert constraint < 1e-13
