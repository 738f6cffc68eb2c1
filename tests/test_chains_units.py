"""Unit tests of studies/chains: continuum.py, small_oscillations.py and time_domain.py, each against a
reference the module does not compute: scipy's J0 zeros, matrices built here and solved by numpy or at 50
digits by mpmath, closed forms (Lamb Art. 90 Ex. 1 and Ex. 2, the simple pendulum's elliptic integral), and
conservation of energy along scipy's own integrator."""

from types import SimpleNamespace

import mpmath
import numpy as np
import pytest
import scipy.linalg as sla
from scipy import special
from scipy.optimize import brentq

from classical_dynamics.models.chains import particle_chain
from classical_dynamics.results import Results
from classical_dynamics.solvers import rattle
from classical_dynamics.studies.chains import continuum, small_oscillations, time_domain

from .conftest import values

G = 9.81


def _results():
    return Results("chains", "test", "test")


def _string(m=1.0, P=1.0, **more):
    """Lamb's Art. 90 Ex. 2: three particles m at intervals a = 1 on a string under tension P."""
    return particle_chain(3, "fixed-fixed", 4.0, m, {"tension": {"newton": P}, **more})


def _string_matrices(m, P):
    """The same chain's K and M written out here: K = (P/a) tridiag(-1, 2, -1), M = m I."""
    K = P * (2 * np.eye(3) - np.eye(3, k=1) - np.eye(3, k=-1))
    return K, m * np.eye(3)


# --- continuum.py ---------------------------------------------------------------------------------------


def _continuum_scene(analysis, effects=None, chain=None):
    return SimpleNamespace(
        name="c",
        title="c",
        data={
            "chain": chain or {"model": "continuum", "length_m": 2.0, "mass_kg": 1.0},
            "effects": effects or {"gravity": {"g_m_per_s2": G}},
            "analysis": analysis,
        },
    )


def test_continuum_run_records_bernoullis_frequencies_node_and_rayleigh_bound():
    results = _results()
    analysis = {
        "modes": 4,
        "spectral_check": {"intervals": 21},
        "mcmahon_check": {"k_max": 60},
        "rayleigh": {"beta_min": -1.0, "beta_max": 1.0},
    }
    continuum.run(_continuum_scene(analysis), results, True)
    got = values(results)
    # D. Bernoulli: omega_k = (j_0k / 2) sqrt(g / l), the zeros of J0 from scipy
    j = special.jn_zeros(0, 4)
    exact = j / 2 * np.sqrt(G / 2.0)
    np.testing.assert_allclose(got["frequencies_rad_per_s"], exact, rtol=1e-5)
    np.testing.assert_allclose(got["frequencies_sqrt_g_over_l"], j / 2, rtol=1e-5)
    np.testing.assert_allclose(
        got["relative_error_vs_continuum"], got["frequencies_rad_per_s"] / exact - 1, rtol=1e-6, atol=1e-15
    )
    assert got["first_zero_j0_collocation"] == pytest.approx(j[0], rel=1e-12)
    assert got["gravest_period_s"] == pytest.approx(2 * np.pi / exact[0], rel=1e-12)
    # the node of mode 2 where J0(j02 sqrt(x/l)) vanishes: found here by a root search of scipy's j0
    node = brentq(lambda x: special.j0(j[1] * np.sqrt(x)), 0.05, 0.5)
    assert got["second_mode_node_x_over_l"] == pytest.approx(node, rel=1e-10)
    assert got["frequency_ratio_2_to_1"] == pytest.approx(j[1] / j[0], rel=1e-14)
    # Rayleigh (Lamb Art. 94 Ex. 2): the quotient is stationary where 6 beta^2 + 4 beta - 5 = 0, its value
    # there is the lowest Ritz value on {s, s^2}, and it lies above the exact (j01/2)^2
    beta = max(np.roots([6, 4, -5]))
    assert got["rayleigh_best_beta"] == pytest.approx(beta, rel=1e-14)
    assert got["rayleigh_best_sigma2_l_over_g"] == pytest.approx(
        got["ritz_2x2_sigma2_l_over_g"][0], rel=1e-12
    )
    assert got["rayleigh_best_sigma2_l_over_g"] > (j[0] / 2) ** 2
    assert got["rayleigh_rigid_bar_sigma2_l_over_g"] == 1.5  # a rigid bar: (m g l/2)/(m l^2/3)
    assert got["rayleigh_best_relative_excess"] == pytest.approx(
        got["rayleigh_best_sigma2_l_over_g"] / (j[0] / 2) ** 2 - 1, rel=1e-12
    )
    assert got["tau_substitution_exact"] == got["rayleigh_formula_exact"] == 1
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert all(case["holds"] for case in results.stability)
    assert {"mode_shapes", "rayleigh"} <= set(results.figures)
    # the mode shapes drawn: J0(j_s sqrt(x/l)) against the height x/l, each scaled to a largest swing of 1
    # (the free end's, J0(0) = 1)
    fig, _ = results.figures["mode_shapes"]
    modes = [line for line in fig.axes[0].lines if line.get_label().startswith("mode")]
    assert len(modes) == 3
    for s, line in enumerate(modes):
        x, swing = line.get_ydata(), line.get_xdata()
        np.testing.assert_allclose(swing, special.j0(j[s] * np.sqrt(x)), atol=1e-12)
        assert swing[np.argmin(x)] == pytest.approx(1.0, rel=1e-15)


def test_continuum_string_without_gravity_stops_at_its_harmonics():
    # a tense string fixed at both ends: omega_s = (s pi / l) sqrt(P / rho), no Bessel analysis follows
    results = _results()
    scene = _continuum_scene(
        {"modes": 3},
        effects={"tension": {"newton": 4.0}},
        chain={"model": "continuum", "length_m": 2.0, "mass_kg": 0.5, "ends": "fixed-fixed"},
    )
    continuum.run(scene, results, True)
    got = values(results)
    np.testing.assert_allclose(
        got["frequencies_rad_per_s"], np.arange(1, 4) * np.pi / 2.0 * np.sqrt(4.0 / 0.25)
    )
    assert "gravest_period_s" not in got and not results.figures


def test_rayleigh_ritz_values_are_the_generalized_eigenvalues_of_the_two_energies():
    # T = int_0^1 phi_i phi_j ds, V = int_0^1 (1 - s) phi_i' phi_j' ds for phi = s, s^2, integrated by
    # numpy's polynomial class here; Ritz values are the roots of det(V - lambda T) = 0
    P = np.polynomial.Polynomial
    basis = [P([0, 1]), P([0, 0, 1])]
    T = np.array([[(a * b).integ()(1.0) for b in basis] for a in basis])
    V = np.array([[(P([1, -1]) * a.deriv() * b.deriv()).integ()(1.0) for b in basis] for a in basis])
    a, b, c = (
        np.linalg.det(T),
        -(V[0, 0] * T[1, 1] + V[1, 1] * T[0, 0] - 2 * V[0, 1] * T[0, 1]),
        np.linalg.det(V),
    )
    np.testing.assert_allclose(continuum.rayleigh_ritz_2x2(), np.sort(np.roots([a, b, c])), rtol=1e-12)


# --- small_oscillations.py: forced response (Art. 95) ------------------------------------------------


@pytest.mark.parametrize("m", [1.0, 3.0])
def test_detuned_response_against_a_50_digit_solve_at_1e_10_from_resonance(m):
    # sigma_1^2 = (2 - sqrt 2) P/(m a) exactly (Lamb Art. 90 Ex. 2); the reference solves
    # (K - sigma^2 M) y = F at 50 digits with sigma = sigma_1 (1 - delta). Forming sigma_1^2 - sigma^2 in
    # double loses eps/delta (1e-6 here): the module must keep the detuning apart to agree to 1e-12
    K, M = _string_matrices(m, 1.0)
    F = np.array([1.0, 0.0, 0.0])
    lam, phi = sla.eigh(K, M)
    sigma = np.sqrt(lam)
    delta = 1e-10
    y, s = small_oscillations.detuned_response(sigma, phi, phi.T @ F, delta)
    assert s == pytest.approx(sigma[0] * (1 - delta), rel=1e-15)
    with mpmath.workdps(50):
        s1 = mpmath.sqrt((2 - mpmath.sqrt(2)) / mpmath.mpf(m)) * (1 - mpmath.mpf(delta))
        A = mpmath.matrix(K.tolist()) - s1**2 * mpmath.matrix(M.tolist())
        reference = np.array([float(v) for v in mpmath.lu_solve(A, mpmath.matrix(F.tolist()))])
    assert np.linalg.norm(y - reference) / np.linalg.norm(reference) < 1e-12


def test_forced_response_by_normal_coordinates_matches_a_direct_solve_and_the_statical_limit():
    # m = 3 so that sigma_1 is no simple binary number: the 50-digit reference must be exact for it too
    built = _string(m=3.0, forcing={"newton": [1.0, 0.0, 0.0]})
    spec = {"sigma_max_over_lowest": 3.0, "points": 31, "transient_detuning": 1e-12, "transient_periods": 2}
    forced = small_oscillations.forced(built, spec)
    assert forced.direct_vs_normal < 1e-12  # a term dropped from Lamb's sum: O(1)
    assert forced.static_limit < 1e-12
    assert forced.residue_slope == pytest.approx(1.0, abs=0.01)  # the deviation is O(delta)
    assert forced.transient.integrator_vs_closed_form < 1e-8
    # the record's hard-case verdicts as the report prints them, not a reference (the other asserts are)
    results = _results()
    small_oscillations.record_forced(results, forced)
    assert values(results)["forced_direct_vs_normal"] == forced.direct_vs_normal
    assert all(case["holds"] for case in results.stability), results.stability
    # the reader sees a header for every column (not the code's name), and the detuning as the caption's delta
    table, caption, headers = results.tables["resonance"]
    assert set(headers) == set(table.columns)
    assert "\\delta" in caption and "\\delta" in headers["detuning"]
    # the table's amplitudes against numpy's solve on the matrices written out here, at delta = 1e-2
    K, M = _string_matrices(3.0, 1.0)
    F = np.array([1.0, 0.0, 0.0])
    frame = forced.resonance
    row = frame[frame.detuning == 1e-2].iloc[0]
    s = np.sqrt((2 - np.sqrt(2)) / 3.0) * (1 - 1e-2)
    expected = np.linalg.norm(np.linalg.solve(K - s**2 * M, F)) / np.linalg.norm(np.linalg.solve(K, F))
    assert row.amplitude_over_static == pytest.approx(expected, rel=1e-10)


def test_initial_value_sum_of_modes_follows_the_integrator_and_shares_the_energy():
    values = small_oscillations.initial_value(_string(m=2.0, P=3.0), {"seed": 4, "periods": 2})
    assert values.modal_vs_integrator < 1e-9  # one mode left out, or its sine: O(1)
    assert values.energy_sum_of_modes < 1e-12


# --- small_oscillations.py: friction (Arts. 96-97) -----------------------------------------------------


def test_small_friction_orders_and_decay_rates_against_numpy():
    built = _string(friction={"b_kg_per_s": [0.5, 0.0, 0.0]})
    values = small_oscillations.friction(built, {"scales": [0.01, 0.001]})
    # Lamb Art. 96: the frequency moves at second order, the decay is c_kk/2 to second order, and the
    # second-order term leaves third order
    assert values.orders["frequency_shift"] == pytest.approx(2.0, abs=0.05)
    assert values.orders["decay_vs_first_order"] == pytest.approx(2.0, abs=0.05)
    assert values.orders["second_order_remainder"] == pytest.approx(3.0, abs=0.1)
    # the table's frequency shift at scale 0.001 from numpy's roots of det(K + lambda B + lambda^2 M)
    K, M = _string_matrices(1.0, 1.0)
    B = np.diag([0.5e-3, 0.0, 0.0])
    companion = np.block([[np.zeros((3, 3)), np.eye(3)], [-K, -B]])
    roots = np.linalg.eigvals(companion)
    roots = roots[roots.imag > 0]
    roots = roots[np.argsort(roots.imag)]
    sigma = np.sqrt(np.array([2 - np.sqrt(2), 2, 2 + np.sqrt(2)]))
    frame = values.table
    assert frame[frame.scale == 0.001]["mode"].tolist() == [1, 2, 3]  # Lamb's modes, numbered from 1
    table = frame[frame.scale == 0.001].sort_values("mode").frequency_shift.to_numpy()
    np.testing.assert_allclose(table, np.abs(roots.imag - sigma) / sigma, rtol=1e-3, atol=1e-15)
    # the decay rate at first order, c_kk/2 with c = phi^T B phi, phi the M-normalized shapes of Fig. 57
    shapes = np.array(
        [
            [1 / 2, np.sqrt(2) / 2, 1 / 2],
            [1 / np.sqrt(2), 0, -1 / np.sqrt(2)],
            [1 / 2, -np.sqrt(2) / 2, 1 / 2],
        ]
    )
    np.testing.assert_allclose(-roots.real, np.diag(shapes @ B @ shapes.T) / 2, rtol=1e-2)


def test_dissipation_balance_and_aperiodic_roots_past_critical_friction():
    built = _string(friction={"b_kg_per_s": [0.5, 0.0, 0.0]})
    values = small_oscillations.dissipation(built, 50.0)
    assert values.balance < 1e-9  # T + V + the work against friction is constant
    # the real roots of det(K + lambda 50 B + lambda^2 M), by numpy here
    K, M = _string_matrices(1.0, 1.0)
    roots = np.linalg.eigvals(np.block([[np.zeros((3, 3)), np.eye(3)], [-K, -np.diag([25.0, 0, 0])]]))
    real = roots[np.abs(roots.imag) < 1e-9].real
    assert values.real_roots == real.size == 2
    assert values.largest_real_root == pytest.approx(real.max() / np.sqrt(2 - np.sqrt(2)), rel=1e-9)
    assert values.largest_real_root < 0


# --- small_oscillations.py: the statical theorems (Arts. 90-94) ---------------------------------------


def test_separation_of_two_roots_by_the_diagonal_values():
    # Lamb Art. 90 Ex. 1, springs k, 2k, 3k between walls, m = 1: a = 3, b = 5, h = -2, so
    # (3 - s)(5 - s) = 4 has roots 4 -+ sqrt 5, separated by 3 and 5
    built = particle_chain(2, "fixed-fixed", 1.0, 1.0, {"springs": {"k_n_per_m": [1.0, 2.0, 3.0]}})
    values = small_oscillations.separation(built)
    assert values.proved
    assert values.margin == pytest.approx((np.sqrt(5) - 1) / (4 + np.sqrt(5)), rel=1e-12)
    assert values.direction_residual < 1e-14
    unequal = particle_chain(2, "fixed-fixed", 1.0, [1.0, 2.0], {"springs": {"k_n_per_m": 1.0}})
    with pytest.raises(ValueError, match="equal masses"):
        small_oscillations.separation(unequal)


def test_three_on_string_shapes_symmetric_type_orthogonality_and_constraints():
    built = _string()
    masses = np.ones(3)
    shapes = small_oscillations.printed_shapes(built, masses, "three_on_string")
    assert shapes.exact and shapes.vs_solver < 1e-14
    # Art. 94 Ex. 1: theta = -+1/sqrt2, where the quotient is (2 -+ sqrt2) P/(m a), exactly the roots
    symmetric = small_oscillations.rayleigh_symmetric(built, masses)
    np.testing.assert_allclose(symmetric.stationary_theta, [-1 / np.sqrt(2), 1 / np.sqrt(2)], rtol=1e-14)
    assert symmetric.exact and symmetric.vs_solver < 1e-14
    orthogonal = small_oscillations.orthogonality(built)
    assert orthogonal.mass < 1e-14 and orthogonal.stiffness < 1e-14
    # Arts. 91-93: a constraint interlaces, holding phi_1 leaves the rest, the quotient errs at second order
    held = small_oscillations.constraint(built, 10, 3)
    assert held.interlacing_violations == 0 and held.interlacing_margin >= -1e-13
    assert held.constraints_tried == 3 + 10
    assert held.successive_minima_error < 1e-13
    assert held.stationary_order == pytest.approx(2.0, abs=0.05)
    assert held.general_roots_imaginary < 1e-8 and held.general_roots_not_positive == 0


def test_a_free_molecules_vibrations_carry_no_momentum():
    # the triatomic molecule m-M-m: the vibrations (1, 0, -1) and (1, -2m/M, 1) have sum m_i X_i = 0
    built = particle_chain(3, "free-free", 1.0, [1.0, 3.0, 1.0], {"springs": {"k_n_per_m": 1.0}})
    values = small_oscillations.printed_shapes(built, built.masses, "triatomic")
    assert values.exact and values.vs_solver < 1e-12
    assert values.vibration_momentum < 1e-14


# --- time_domain.py ---------------------------------------------------------------------------------------


def test_one_link_at_finite_amplitude_swings_at_the_simple_pendulums_elliptic_frequency():
    # n = 1 is the simple pendulum: omega/omega_0 = pi / (2 K(sin^2(theta_0/2))), scipy's ellipk
    for degrees in (1.0, 40.0):
        theta0 = np.radians(degrees)
        omega, h, tip, energies, constraint, _ = time_domain.simulate(1, 0.5, G, 1, theta0, 12, 400)
        assert omega[0] == pytest.approx(np.sqrt(G / 0.5), rel=1e-14)
        measured, _ = rattle.crossing_frequency(tip, h)
        expected = np.pi / (2 * special.ellipk(np.sin(theta0 / 2) ** 2))
        assert measured / omega[0] == pytest.approx(expected, rel=1e-4)
        assert constraint < 1e-10


def test_mode_angles_of_two_particles_against_the_laguerre_eigenvector():
    # n = 2, m = a = g = 1: K = diag(2, 1) (mass below each link), M = I on displacements; the lower mode is
    # (1, 2 + sqrt2)... built here with numpy and turned into link angles by differences
    K = np.array([[3.0, -1.0], [-1.0, 1.0]])
    lam, vec = np.linalg.eigh(K)
    assert lam[0] == pytest.approx(min(np.roots([1, -4, 2])), rel=1e-14)  # Laguerre L_2: x^2 - 4x + 2
    u = vec[:, 0] * np.sign(vec[0, 0])
    theta = np.diff(u, prepend=0.0)
    theta *= 0.1 / np.max(np.abs(theta))
    got = time_domain._mode_angles(2, 1, 0.1)
    np.testing.assert_allclose(got * np.sign(got[0]), theta, rtol=1e-12)


def test_time_domain_run_on_two_particles_reads_the_laguerre_frequencies():
    spec = {
        "small_amplitude_deg": 0.05,
        "long_run_periods": 20,
        "long_run_amplitude_deg": 10,
        "large_amplitudes_deg": [1, 40],
        "steps_per_fastest_period": 60,
    }
    data = {
        "chain": {"model": "particles", "n": 2, "ends": "fixed-free", "length_m": 1.0, "mass_kg": 1.0},
        "effects": {"gravity": {"g_m_per_s2": G}},
        "analysis": {"time_domain": spec},
    }
    results = _results()
    time_domain.run(SimpleNamespace(name="t", title="t", data=data), results, True)
    got = values(results)
    # omega^2 a/g are the zeros of L_2 (Lamb Ex. XIV.11), 2 -+ sqrt 2, a = l/2
    frame = results.tables["time_domain_small_amplitude"][0]
    expected = np.sqrt(np.array([2 - np.sqrt(2), 2 + np.sqrt(2)]) * 2)
    np.testing.assert_allclose(frame.eigenvalue_omega_sqrt_g_over_l, expected, rtol=1e-12)
    np.testing.assert_allclose(frame.measured_omega_sqrt_g_over_l, expected, rtol=2e-3)
    assert got["time_domain_max_relative_frequency_difference"] < 2e-3
    assert got["time_domain_energy_error_max"] < 1e-2  # symplectic: bounded, small at 60 steps a period
    assert got["time_domain_constraint_error_m"] < 1e-10
    shift = results.tables["amplitude_shift"][0]
    assert shift.omega_over_linear.iloc[0] == pytest.approx(1.0, abs=1e-3)
    assert 0.9 < shift.omega_over_linear.iloc[1] < 0.99  # larger swings are slower


def test_a_full_time_domain_run_takes_the_periods_the_scene_asks_for():
    """Quick runs cap the long run at 1000 gravest periods (the study's quick mode); a full run takes the
    1001 the scene asks for."""
    data = {
        "chain": {"model": "particles", "n": 1, "ends": "fixed-free", "length_m": 1.0, "mass_kg": 1.0},
        "effects": {"gravity": {"g_m_per_s2": G}},
        "analysis": {
            "time_domain": {
                "small_amplitude_deg": 0.05,
                "long_run_periods": 1001,
                "long_run_amplitude_deg": 10,
                "large_amplitudes_deg": [1],
                "steps_per_fastest_period": 20,
            }
        },
    }
    results = _results()
    time_domain.run(SimpleNamespace(name="t", title="t", data=data), results, False)
    assert values(results)["time_domain_periods"] == 1001


# --- cost.py: what a scene costs ----------------------------------------------------------------------------


def test_the_modes_of_a_long_particle_chain_cost_at_least_the_measured_time_and_more_for_more_modes():
    """cost.py's docstring: the lowest modes of 10^5 particles took 0.11 s (LAPACK's tridiagonal select); the
    estimate for 5 modes is at least that, and asking for 10 modes costs more, not less."""
    from classical_dynamics.studies.chains.cost import cost  # the package's `cost` is this function

    def seconds(modes):
        data = {"chain": {"model": "particles", "n": 100_000}, "analysis": {"modes": modes}}
        return sum(w.seconds for w in cost(data) if w.field == "chain.n")

    assert seconds(5) >= 0.11
    assert seconds(10) > seconds(5)


@pytest.mark.parametrize("name", ["convergence", "continuum_limit"])
def test_a_links_sweep_is_priced_at_least_its_dense_matrix(name):
    """A chain of n links is a dense generalized eigenproblem: at least one n x n matrix of doubles, 8 n^2
    bytes, whichever sweep asks for it; a particle chain's tridiagonal one grows only like n."""
    from classical_dynamics.studies.chains.cost import cost

    def memory_mb(model, n):
        data = {"chain": {"model": model, "n": 10}, "analysis": {name: {"n_values": [10, n]}}}
        return next(w.memory_mb for w in cost(data) if w.field == f"analysis.{name}.n_values")

    assert memory_mb("links", 3000) >= 8 * 3000**2 / 1e6
    assert memory_mb("particles", 3000) < 8 * 3000**2 / 1e6 / 10


@pytest.mark.parametrize(("model", "order"), [("ring", 4), ("links", 1), ("particles", 1)])
def test_a_dense_eigenproblem_is_priced_at_least_its_matrix(model, order):
    """A dense eigenproblem of order N holds at least one N x N matrix of doubles, 8 N^2 bytes: the ring's of
    order 4n (its state), a links chain's of order n, a particle chain's dense analyses of order n."""
    from classical_dynamics.studies.chains.cost import cost

    n = 1500
    data = {"chain": {"model": model, "n": n}, "analysis": {"closed_form": True}}
    (dense,) = [w.memory_mb for w in cost(data) if w.field == "chain.n" and w.what != f"{n} particles"]
    assert dense >= 8 * (order * n) ** 2 / 1e6  # in MB of 10^6 bytes, cost.py's unit


# --- planar.py: the rotating ring (Lamb Art. 98) ---------------------------------------------------------


def test_ring_run_records_lambs_tension_and_wave_speeds_for_a_small_ring(monkeypatch):
    from classical_dynamics.studies.chains import planar

    # sympy's roots of Lamb's (44) take most of the run's time: test_chains_planar.py checks them
    monkeypatch.setattr(planar, "dispersion", lambda: (None, True))
    n, omega = 40, 1.5
    data = {
        "chain": {"model": "ring", "n": n, "length_m": 2 * np.pi, "mass_kg": 1.0},
        "effects": {"rotation": {"omega_rad_per_s": omega}, "springs": {"k_n_per_m": 1e5}},
        "analysis": {"ring_waves": {"s_max": 3}},
    }
    results = _results()
    planar.run_ring(SimpleNamespace(name="r", title="r", data=data), results, True)
    got = values(results)
    # each bead m = rho 2 pi a/n is held by two tensions T at the angle 2 pi/n: 2 T sin(pi/n) = m omega^2 a,
    # so T/(rho omega^2 a^2) = (pi/n)/sin(pi/n), Lamb's 1 as n grows
    assert got["tension_over_rho_omega2_a2"] == pytest.approx((np.pi / n) / np.sin(np.pi / n), rel=1e-12)
    assert got["stiffness_ratio"] == pytest.approx(1e5 / (1.0 / n * omega**2), rel=1e-12)
    # Lamb: the first wave at rest in space, the second at 2 omega (s^2 - 1)/(s^2 + 1), to O((s/n)^2)
    assert got["stationary_wave_speed_max"] < 2 * (3 / n) ** 2
    assert got["second_wave_deviation_max"] < 4 * (3 / n) ** 2
    frame = results.tables["waves"][0]
    s = frame.s.to_numpy()
    np.testing.assert_allclose(frame.lamb_space_2, 2 * (s**2 - 1) / (s**2 + 1))
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert all(case["holds"] for case in results.stability), results.stability


def test_the_transient_from_rest_against_a_40_digit_closed_form_on_one_particle():
    # one particle of m = 2 on a spring k = 8 (sigma = 2), forced at sigma (1 - 1e-9) from rest:
    # y = (F/m)(cos st - cos sigma t)/(sigma^2 - s^2), written here at 40 digits. The difference of cosines in
    # double loses about eps/delta of the response: the module's figure for it is that loss, measured here
    m, k, F, delta = 2.0, 8.0, 1.0, 1e-9
    built = SimpleNamespace(
        stiffness_matrix=lambda: np.array([[k]]), masses=np.array([m]), force=np.array([F])
    )
    sigma, phi = np.array([2.0]), np.array([[1 / np.sqrt(m)]])
    spec = {"transient_detuning": delta, "transient_periods": 2}
    got = small_oscillations.transient(built, sigma, phi, phi.T @ built.force, spec)
    s = 2.0 * (1 - delta)
    t = np.linspace(0.0, 2 * 2 * np.pi / 2.0, 401)
    with mpmath.workdps(40):
        s_mp = 2 * (1 - mpmath.mpf(delta))
        exact = np.array(
            [float(F / m * (mpmath.cos(s_mp * x) - mpmath.cos(2 * x)) / (4 - s_mp**2)) for x in t]
        )
    naive = F / m * (np.cos(s * t) - np.cos(2.0 * t)) / (4.0 - s**2)
    scale = np.max(np.abs(exact))
    assert got.detuning == delta
    assert got.difference_of_cosines_error == pytest.approx(np.max(np.abs(naive - exact)) / scale, rel=1e-4)
    assert 1e-10 < got.difference_of_cosines_error < 1e-5  # the loss is real, and about eps/delta
    assert got.integrator_vs_closed_form < 1e-9
