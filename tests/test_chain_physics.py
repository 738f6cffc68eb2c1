"""Chains against exact values: Laguerre zeros, J0 zeros (mpmath), Southwell, sine law, Rayleigh."""

import mpmath
import numpy as np
import pytest
import scipy.linalg as sla
from scipy import special

from classical_dynamics.models.chains import (
    continuum_frequencies,
    exact_discrete_frequencies,
    particle_chain,
    rigid_links_matrices,
)
from classical_dynamics.solvers import chain_eigen
from classical_dynamics.solvers.special import (
    laguerre_lowest_zero_asymptotic,
    laguerre_zero_mp,
    mcmahon_j0_zero,
)
from classical_dynamics.solvers.spectral import hanging_chain_sigma
from classical_dynamics.studies.chains.continuum import rayleigh_quotient, rayleigh_ritz_2x2
from classical_dynamics.studies.chains.discrete import hanging_particles_scaled, links_frequencies

G = 9.81
J0_MP = [float(mpmath.besseljzero(0, k)) for k in range(1, 6)]


def hanging(n, length=1.0):
    return particle_chain(n, "fixed-free", length, length / n, {"gravity": {"g_m_per_s2": G}})


@pytest.mark.parametrize("method", chain_eigen.METHODS)
@pytest.mark.parametrize("n", [1, 2, 3, 5, 10, 25, 50])
def test_discrete_hanging_chain_is_laguerre(n, method):
    # Lamb Ex. XIV.11: omega^2 a / g are the zeros of L_n (reference: scipy's Golub-Welsch roots).
    lam = hanging_particles_scaled(n, 5, method)
    assert np.allclose(lam, special.roots_laguerre(n)[0][: lam.size], rtol=1e-12, atol=0)


def test_two_particles_closed_form():
    assert np.allclose(hanging_particles_scaled(2, 2), [2 - np.sqrt(2), 2 + np.sqrt(2)], rtol=1e-14)


def test_model_assembly_matches_laguerre_in_physical_units():
    chain = hanging(4, length=2.0)
    K, M = chain.stiffness_matrix(), np.diag(chain.masses)
    omega2 = sla.eigh(K, M, eigvals_only=True)
    a = 2.0 / 4
    assert np.allclose(omega2 * a / G, special.roots_laguerre(4)[0], rtol=1e-13)


def test_continuum_zeros_against_mpmath():
    cont = continuum_frequencies({"gravity": {"g_m_per_s2": G}}, "fixed-free", 1.0, 1.0, 5)
    assert np.allclose(cont * 2 / np.sqrt(G), J0_MP, rtol=1e-13)


def test_spectral_collocation_finds_j0_zeros_with_no_condition_at_the_free_end():
    # The free end is a regular singular point: finiteness alone selects J0 (not Y0).
    assert np.allclose(hanging_chain_sigma(41, 5), J0_MP, rtol=1e-12)


def test_lamb_numbers():
    j = np.array(J0_MP)
    assert 4 * np.pi / j[0] == pytest.approx(5.225, abs=5e-4)  # gravest period, Art. 90 (24)
    assert j[:2] / np.pi == pytest.approx([0.7655, 1.7571], abs=5e-5)  # Art. 90 (23)
    assert (j[0] / j[1]) ** 2 == pytest.approx(0.190, abs=5e-4)  # node of mode 2


def test_high_index_j0_zeros_against_mpmath_and_mcmahon():
    zeros = special.jn_zeros(0, 1000)
    for k in (100, 500, 1000):
        assert zeros[k - 1] == pytest.approx(float(mpmath.besseljzero(0, k)), rel=1e-14)
    assert np.max(np.abs(zeros[49:] - mcmahon_j0_zero(np.arange(50, 1001))) / zeros[49:]) < 1e-13


def test_rayleigh_is_an_upper_bound_and_its_stationary_value():
    exact = (J0_MP[0] / 2) ** 2
    beta = np.linspace(-50, 50, 200001)
    assert np.all(rayleigh_quotient(beta) > exact)
    assert rayleigh_quotient(0.0) == pytest.approx(1.5, rel=1e-15)  # rigid bar
    best = (-2 + np.sqrt(34)) / 6
    assert rayleigh_quotient(best) == pytest.approx(1.446032, abs=1e-6)  # the minimum, derived below by sympy
    assert rayleigh_quotient(best) <= rayleigh_quotient(beta).min() + 1e-15
    ritz = rayleigh_ritz_2x2()
    assert ritz[0] == pytest.approx(rayleigh_quotient(best), rel=1e-12)  # the same minimum
    assert ritz[1] > (J0_MP[1] / 2) ** 2  # Poincare: 2nd Ritz value bounds 2nd


def test_rayleigh_quotient_and_ritz_values_against_sympys_energies():
    """The two energies of the hanging chain (l = 1, s from the top, tension (1 - s) g per unit mass) for the
    trial y = s + beta s^2, integrated by sympy here: T = int y^2 ds, V = int (1 - s) y'^2 ds. The module's
    quotient and Ritz matrices are typed integrals; this derives them (the test above compared the module's
    quotient with the module's Ritz value, both from the same hand integration)."""
    import sympy as sp

    s, b = sp.symbols("s beta", real=True)
    y = s + b * s**2
    T = sp.integrate(y**2, (s, 0, 1))
    V = sp.integrate((1 - s) * sp.diff(y, s) ** 2, (s, 0, 1))
    quotient = sp.lambdify(b, V / T)
    for beta in (-3.0, -0.4, 0.0, 0.5, 2.0, 40.0):
        assert rayleigh_quotient(beta) == pytest.approx(quotient(beta), rel=1e-14)
    stationary = [r for r in sp.solve(sp.diff(V / T, b), b) if r.is_real]
    best = min(stationary, key=lambda r: float((V / T).subs(b, r)))
    least = float((V / T).subs(b, best))
    assert rayleigh_quotient(float(best)) == pytest.approx(least, rel=1e-14)
    # Ritz in the basis {s, s^2}: the pencil (V, T) with sympy's integrals, its eigenvalues by scipy
    basis = (s, s**2)
    Tm = np.array([[float(sp.integrate(f * g, (s, 0, 1))) for g in basis] for f in basis])
    Vm = np.array(
        [
            [float(sp.integrate((1 - s) * sp.diff(f, s) * sp.diff(g, s), (s, 0, 1))) for g in basis]
            for f in basis
        ]
    )
    ritz = sla.eigh(Vm, Tm, eigvals_only=True)
    assert rayleigh_ritz_2x2() == pytest.approx(ritz, rel=1e-13)
    assert ritz[0] == pytest.approx(least, rel=1e-12)  # the span's least quotient is the trial's minimum


def test_random_trial_functions_never_beat_the_gravest_mode():
    # Rayleigh's principle on the discrete chain: V/T >= lambda_1 for any admissible vector.
    chain = hanging(30)
    K, m = chain.stiffness_matrix(), chain.masses
    lam1 = chain_eigen.lowest_eigenvalues(chain.segment_stiffness, None, m, "fixed-free", 1, "pliability")[0]
    rng = np.random.default_rng(7)
    for _ in range(200):
        v = rng.standard_normal(30)
        assert v @ K @ v / (v @ (m * v)) >= lam1 * (1 - 1e-13)


def test_a_constraint_raises_the_gravest_frequency_but_not_past_the_second():
    # Lamb Art. 93: one constraint puts the new gravest sigma^2 in [sigma_1^2, sigma_2^2].
    chain = hanging(12)
    K, M = chain.stiffness_matrix(), np.diag(chain.masses)
    lam = sla.eigh(K, M, eigvals_only=True)
    for fixed in range(12):
        keep = [i for i in range(12) if i != fixed]
        new = sla.eigh(K[np.ix_(keep, keep)], M[np.ix_(keep, keep)], eigvals_only=True)[0]
        assert lam[0] <= new <= lam[1] * (1 + 1e-12)


def test_modes_are_mass_orthogonal():
    chain = hanging(40)
    _, shapes = chain_eigen.modes(chain.segment_stiffness, None, chain.masses, "fixed-free", 6)
    gram = shapes.T @ (chain.masses[:, None] * shapes)
    assert np.allclose(gram, np.eye(6), atol=1e-12)


def test_convergence_orders():
    j1 = J0_MP[0] / 2
    err = {}
    for n in (256, 512):
        lam = hanging_particles_scaled(n, 1)[0]
        err[n] = (np.sqrt(n * lam) / j1 - 1, np.sqrt((n + 0.5) * lam) / j1 - 1)
    assert err[256][0] < 0 and err[256][0] / err[512][0] == pytest.approx(2.0, rel=0.01)  # first order, below
    assert err[256][1] / err[512][1] == pytest.approx(4.0, rel=0.02)  # second order


def test_rigid_links():
    K, M = rigid_links_matrices(1)
    assert sla.eigh(K, M, eigvals_only=True)[0] == pytest.approx(1.5, rel=1e-15)  # compound pendulum
    e16, e32 = (links_frequencies(n, 1)[0] / (J0_MP[0] / 2) - 1 for n in (16, 32))
    assert e16 > e32 > 0  # from above
    assert e16 / e32 == pytest.approx(4.0, rel=0.03)  # second order


@pytest.mark.parametrize("n", [1, 2, 3, 4, 6, 10])
@pytest.mark.parametrize("motion,shift", [("out_of_plane", 0.0), ("in_plane", 1.0)])
def test_southwell_law_is_exact_for_the_uniform_discrete_chain(n, motion, shift):
    chain = particle_chain(
        n, "fixed-free", 1.0, 1.0 / n, {"rotation": {"omega_rad_per_s": 2.0, "motion": motion}}
    )
    lam = sla.eigh(chain.stiffness_matrix(), np.diag(chain.masses), eigvals_only=True)
    odd = 2 * np.arange(1, n + 1) - 1
    assert np.allclose(lam / 4.0, odd * (odd + 1) / 2 - shift, rtol=1e-11, atol=1e-11)


def test_loaded_string_sine_law():
    n, P = 9, 3.0
    chain = particle_chain(n, "fixed-fixed", 1.0, 2.0 / n, {"tension": {"newton": P}})
    lam = sla.eigh(chain.stiffness_matrix(), np.diag(chain.masses), eigvals_only=True)
    a, m = 1.0 / (n + 1), 2.0 / n
    s = np.arange(1, n + 1)
    assert np.allclose(np.sqrt(lam), 2 * np.sqrt(P / (m * a)) * np.sin(s * np.pi / (2 * (n + 1))), rtol=1e-13)


def test_small_spring_systems():
    two = particle_chain(2, "fixed-fixed", 1.0, 1.0, {"springs": {"k_n_per_m": [1.0, 3.0, 1.0]}})
    lam = sla.eigh(two.stiffness_matrix(), np.diag(two.masses), eigvals_only=True)
    assert np.allclose(np.sqrt(lam), [1.0, np.sqrt(7.0)], rtol=1e-14)  # handbook Ex. 2.4
    m, M, k = 16.0, 12.0, 2.0
    tri = particle_chain(3, "free-free", 1.0, [m, M, m], {"springs": {"k_n_per_m": k}})
    lam = sla.eigh(tri.stiffness_matrix(), np.diag(tri.masses), eigvals_only=True)
    assert abs(lam[0]) < 1e-14 * lam[-1]  # translation
    assert np.allclose(lam[1:], [k / m, k * (M + 2 * m) / (M * m)], rtol=1e-13)
    exact = exact_discrete_frequencies(tri, {"springs": {"k_n_per_m": k}}, 3)
    assert np.allclose(exact**2, [0.0, k / m, k * (M + 2 * m) / (M * m)])


def test_free_chain_zero_mode_is_a_translation():
    chain = particle_chain(20, "free-free", 1.0, 1.0, {"springs": {"k_n_per_m": 5.0}})
    lam, shapes = chain_eigen.modes(chain.segment_stiffness, None, chain.masses, "free-free", 2)
    assert abs(lam[0]) < 1e-12 * lam[1]
    v = shapes[:, 0] / np.linalg.norm(shapes[:, 0])
    assert abs(abs(v.sum()) / np.sqrt(20) - 1) < 1e-12


@pytest.mark.slow
def test_lowest_mode_of_a_hundred_thousand_particles_to_1e_12():
    # Hard case: an ordinary symmetric solver loses ~n^2 eps; the pliability form keeps relative accuracy.
    n = 100_000
    lam = hanging_particles_scaled(n, 1, "pliability")[0]
    assert abs(lam / laguerre_lowest_zero_asymptotic(n) - 1) < 1e-12


def test_pliability_solver_against_30_digit_laguerre_zero():
    n = 1000
    exact = laguerre_zero_mp(n, laguerre_lowest_zero_asymptotic(n))
    lam = hanging_particles_scaled(n, 5, "pliability")
    assert abs(lam[0] / float(exact) - 1) < 1e-13
    # and Tricomi's expansion, used as the reference at larger n, is itself right here
    assert abs(laguerre_lowest_zero_asymptotic(n) / float(exact) - 1) < 1e-13


def test_pliability_refuses_what_it_cannot_do():
    with pytest.raises(ValueError):
        chain_eigen.lowest_eigenvalues(np.ones(4), None, np.ones(3), "fixed-fixed", 2, "pliability")


def test_sympy_derives_the_small_chains_and_proves_the_printed_formulas():
    """The characteristic polynomial's roots in closed form; a printed formula must equal them for every value
    of its symbols, so a wrong one (2k/m for 3k/m) is caught, and so is a right value at one point only."""
    import sympy as sp

    from classical_dynamics.studies.chains import symbolic as sy

    _, roots, values = sy.derive([1.0, 2.0], 1.0, "fixed-fixed")
    assert sy.formula_is_exact(sy.SOURCE_FORMULAS["unequal_masses"], roots)
    assert np.allclose(sy.evaluate(roots, values), [(3 - 3**0.5) / 2, (3 + 3**0.5) / 2], rtol=1e-15)
    _, roots, _ = sy.derive([1.0, 1.0], 1.0, "fixed-fixed")
    assert sy.formula_is_exact(sy.SOURCE_FORMULAS["equal_springs"], roots)
    assert not sy.formula_is_exact([sy.k / sy.m1, 2 * sy.k / sy.m1], roots)
    # right at m1 = m2 but not for every m1, m2: the equal-springs values against the unequal-mass roots
    _, roots, _ = sy.derive([1.0, 2.0], 1.0, "fixed-fixed")
    assert not sy.formula_is_exact([sy.k / sy.m1, 3 * sy.k / sy.m1], roots)
    _, roots, values = sy.derive([15.995, 12.0, 15.995], 1.0, "free-free")
    assert sy.formula_is_exact(sy.SOURCE_FORMULAS["triatomic"], roots) and roots[0] == sp.Integer(0)


# --- Lamb's theory of small oscillations (Arts. 90-97) --------------------------------------------------


def test_second_order_friction_shift_reduces_to_the_one_degree_case():
    """One mode alone: lambda^2 + eps c lambda + sigma^2 = 0 has lambda = -eps c/2 + i sqrt(sigma^2 -
    eps^2c^2/4), whose expansion is i sigma - eps c/2 - i eps^2 c^2/(8 sigma) (Lamb Art. 96); the
    order-by-order derivation for n modes must give that when the coupling terms vanish."""
    import sympy as sp

    from classical_dynamics.studies.chains.symbolic import damped_frequency_shift

    sigma, C, l1, l2 = damped_frequency_shift(3, 1)
    uncoupled = {C[0, 1]: 0, C[1, 2]: 0}
    c, s = C[1, 1], sigma[1]
    assert sp.simplify(l1 + c / 2) == 0
    assert sp.simplify(l2.subs(uncoupled) + sp.I * c**2 / (8 * s)) == 0


def test_second_order_friction_shift_against_the_quadratic_eigenproblem():
    """The derived correction leaves a third-order rest on a random three-mode system (seeded)."""
    import sympy as sp

    from classical_dynamics.studies.chains.symbolic import damped_frequency_shift

    rng = np.random.default_rng(3)
    sig = np.array([1.0, 1.7, 2.9])
    C0 = rng.standard_normal((3, 3))
    C0 = C0 @ C0.T
    rests = []
    for eps in (1e-2, 1e-3):
        A = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.diag(sig**2), -eps * C0]])
        full = np.linalg.eigvals(A)
        full = full[full.imag > 0]
        full = full[np.argsort(full.imag)]
        symbols, C, l1, l2 = damped_frequency_shift(3, 0)
        values = {**dict(zip(symbols, sig)), **{C[i, j]: eps * C0[i, j] for i in range(3) for j in range(3)}}
        predicted = 1j * sig[0] + complex(sp.N(l1.subs(values))) + complex(sp.N(l2.subs(values)))
        rests.append(abs(full[0] - predicted))
    assert rests[1] < rests[0] / 500  # third order: a thousandfold per decade


def test_three_particles_on_a_string_lamb_art_90():
    """sigma^2 = (2 -+ sqrt2) mu and 2 mu, with mu = P/(m a), and the modes of Fig. 57 (independent of sympy:
    the sine law of the loaded string, 2 sqrt(mu) sin(s pi / 8))."""
    chain = particle_chain(3, "fixed-fixed", 4.0, 1.0, {"tension": {"newton": 1.0}})
    lam, shapes = chain_eigen.modes(chain.segment_stiffness, None, chain.masses, "fixed-fixed", 3)
    np.testing.assert_allclose(lam, [2 - np.sqrt(2), 2.0, 2 + np.sqrt(2)], rtol=1e-14)
    np.testing.assert_allclose(np.sqrt(lam), 2 * np.sin(np.arange(1, 4) * np.pi / 8), rtol=1e-14)
    first = shapes[:, 0] / shapes[0, 0]
    np.testing.assert_allclose(first, [1.0, np.sqrt(2), 1.0], rtol=1e-14)


def test_resonant_response_kept_apart_beats_the_direct_solve():
    """Near resonance forming K - sigma^2 M loses eps/delta; the module's normal-coordinate sum with the
    detuning apart does not (Lamb Art. 95), against a 50-digit solve at the exact sigma_1^2 = 2 - sqrt 2 (the
    three particles of Art. 90, written out here, not the module's sympy root)."""
    from classical_dynamics.studies.chains import small_oscillations

    chain = particle_chain(
        3, "fixed-fixed", 4.0, 1.0, {"tension": {"newton": 1.0}, "forcing": {"newton": [1.0, 0.0, 0.0]}}
    )
    K, M = chain.stiffness_matrix(), np.diag(chain.masses)
    np.testing.assert_array_equal(K, [[2, -1, 0], [-1, 2, -1], [0, -1, 2]])  # P/a = 1, m = 1
    sigma, phi = small_oscillations._modes(chain)
    for delta in (1e-4, 1e-10):
        with mpmath.workdps(50):
            s = mpmath.sqrt(2 - mpmath.sqrt(2)) * (1 - mpmath.mpf(delta))
            A = mpmath.matrix(K.tolist()) - s**2 * mpmath.matrix(M.tolist())
            reference = np.array([float(v) for v in mpmath.lu_solve(A, mpmath.matrix([1, 0, 0]))])
        normal, s = small_oscillations.detuned_response(sigma, phi, phi.T @ chain.force, delta)
        assert np.linalg.norm(normal - reference) / np.linalg.norm(reference) < 1e-13
    direct = np.linalg.solve(K - s**2 * M, chain.force)
    assert np.linalg.norm(direct - reference) / np.linalg.norm(reference) > 1e-9
