"""Unit tests of models/chains.py and models/self_excited/body.py against references they do not compute:
numpy's eigenvalues of stiffness and mass matrices written out here, scipy's Laguerre zeros, the wave
equation's harmonics and Lee's definitions of the inertia numbers."""

import numpy as np
import pytest
import scipy.linalg as sla
from scipy import special

from classical_dynamics.models.chains import (
    continuum_frequencies,
    difference_matrix,
    exact_discrete_frequencies,
    frequency_unit,
    particle_chain,
)
from classical_dynamics.models.self_excited import Body


def _tridiagonal(n, ends):
    """Second differences for n particles: both ends fixed, or both free (the end rows have 1)."""
    K = 2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)
    if ends == "free-free":
        K[0, 0] = K[-1, -1] = 1.0
    return K


def _numpy_frequencies(K, masses):
    return np.sqrt(np.clip(np.linalg.eigvalsh(K / np.sqrt(np.outer(masses, masses))), 0.0, None))


@pytest.mark.parametrize("ends", ["fixed-fixed", "free-free"])
def test_spring_chains_follow_the_sine_law_and_the_wave_equations_harmonics(ends):
    n, k, mass = 12, 3.0, 2.4  # mass: the total, m = mass/n each
    chain = particle_chain(n, ends, 1.0, mass / n, {"springs": {"k_n_per_m": k}})
    np.testing.assert_allclose(chain.stiffness_matrix(), k * _tridiagonal(n, ends), atol=1e-15)
    expected = _numpy_frequencies(k * _tridiagonal(n, ends), np.full(n, mass / n))
    np.testing.assert_allclose(
        exact_discrete_frequencies(chain, {"springs": {}}, 4), expected[:4], atol=1e-12
    )
    # the continuum with Y = k a, rho = m/a on L = (n + 1) a (fixed) or n a (free): omega_s = s pi c/L with
    # c = a sqrt(k/m)
    s = np.arange(1, 4) if ends == "fixed-fixed" else np.arange(0, 3)
    L = n + 1 if ends == "fixed-fixed" else n
    cont = continuum_frequencies({"springs": {"k_n_per_m": k}}, ends, 1.0, mass, 3, n=n)
    np.testing.assert_allclose(cont, s * np.pi / L * np.sqrt(k / (mass / n)), rtol=1e-14)
    _, name, _ = frequency_unit({"springs": {"k_n_per_m": [k]}}, 1.0, mass, 1.0 / n, mass / n)
    assert name == "sqrt_k_over_m"


def test_loaded_string_sine_law_and_its_unit():
    n, P, mass, length = 7, 5.0, 1.4, 2.0
    chain = particle_chain(n, "fixed-fixed", length, mass / n, {"tension": {"newton": P}})
    a = length / (n + 1)
    expected = _numpy_frequencies(P / a * _tridiagonal(n, "fixed-fixed"), np.full(n, mass / n))
    np.testing.assert_allclose(
        exact_discrete_frequencies(chain, {"tension": {}}, 3), expected[:3], rtol=1e-12
    )
    unit, name, _ = frequency_unit({"tension": {"newton": P}}, length, mass, a, mass / n)
    assert name == "over_fundamental" and unit == pytest.approx(np.pi / length * np.sqrt(P / (mass / length)))


def test_triatomic_molecule_closed_form_against_numpy():
    m, M, k = 1.0, 3.0, 2.0
    chain = particle_chain(3, "free-free", 1.0, [m, M, m], {"springs": {"k_n_per_m": k}})
    K = k * np.array([[1.0, -1, 0], [-1, 2, -1], [0, -1, 1]])
    expected = _numpy_frequencies(K, np.array([m, M, m]))
    np.testing.assert_allclose(exact_discrete_frequencies(chain, {"springs": {}}, 3), expected, atol=1e-7)
    # unequal masses with no closed form
    other = particle_chain(3, "fixed-fixed", 1.0, [1.0, 2.0, 3.0], {"springs": {"k_n_per_m": k}})
    assert exact_discrete_frequencies(other, {"springs": {}}, 3) is None


def test_hanging_chain_is_laguerre_and_the_rotating_chain_is_southwell():
    n, g = 6, 9.81
    chain = particle_chain(n, "fixed-free", 1.5, 1.0 / n, {"gravity": {"g_m_per_s2": g}})
    a = 1.5 / n
    zeros = special.roots_laguerre(n)[0]
    np.testing.assert_allclose(
        exact_discrete_frequencies(chain, {"gravity": {"g_m_per_s2": g}}, 3),
        np.sqrt(zeros[:3] * g / a),
        rtol=1e-12,
    )
    unit, name, _ = frequency_unit({"gravity": {"g_m_per_s2": g}}, 1.5, 1.0, a, 1.0 / n)
    assert name == "sqrt_g_over_l" and unit == pytest.approx(np.sqrt(g / 1.5))
    # a chain whirling at omega: Southwell's sigma^2/omega^2 = s(s + 1)/2 (s odd), less 1 in the plane, and
    # the discrete chain's own lowest roots from numpy on its matrices
    for motion, shift in (("out_of_plane", 0.0), ("in_plane", 1.0)):
        effects = {"rotation": {"omega_rad_per_s": 2.0, "motion": motion}}
        cont = continuum_frequencies(effects, "fixed-free", 1.0, 1.0, 3)
        odd = np.array([1, 3, 5])
        np.testing.assert_allclose(cont, 2.0 * np.sqrt(odd * (odd + 1) / 2 - shift), rtol=1e-14)
        whirl = particle_chain(n, "fixed-free", 1.0, 1.0 / n, effects)
        lam = sla.eigh(whirl.stiffness_matrix(), np.diag(whirl.masses), eigvals_only=True)
        own = np.sqrt(np.clip(lam, 0, None))[
            int(shift) : int(shift) + 2
        ]  # in the plane: the rigid turn first
        np.testing.assert_allclose(
            exact_discrete_frequencies(whirl, effects, 3)[int(shift) : int(shift) + 2], own, rtol=1e-9
        )
    # springs with another effect beside them have no closed form here: that wave equation is the springs'
    both = {"springs": {"k_n_per_m": 4.0}, "gravity": {"g_m_per_s2": 9.81}}
    assert continuum_frequencies(both, "fixed-fixed", 1.0, 1.0, 3, n=5) is None
    assert frequency_unit({"rotation": {"omega_rad_per_s": 2.0}}, 1.0, 1.0, 0.1, 0.1)[1] == "over_omega"


def test_chain_models_refuse_what_they_do_not_describe():
    with pytest.raises(ValueError, match="fixed at one end"):
        particle_chain(3, "fixed-fixed", 1.0, 1.0, {"gravity": {"g_m_per_s2": 9.81}})
    with pytest.raises(ValueError, match="one value per particle"):
        particle_chain(
            3,
            "fixed-fixed",
            1.0,
            1.0,
            {"springs": {"k_n_per_m": 1.0}, "friction": {"b_kg_per_s": [1.0, 2.0]}},
        )
    with pytest.raises(ValueError, match="at least two"):
        particle_chain(1, "free-free", 1.0, 1.0, {"springs": {"k_n_per_m": 1.0}})
    assert (
        continuum_frequencies({"gravity": {"g_m_per_s2": 9.81}, "springs": {}}, "fixed-free", 1.0, 1.0, 2)
        is None
    )
    # stretches: segment j joins particles j - 1 and j (fixed-fixed: the walls beyond the ends)
    np.testing.assert_array_equal(difference_matrix(2, "fixed-fixed"), [[1, 0], [-1, 1], [0, -1]])
    np.testing.assert_array_equal(difference_matrix(3, "free-free"), [[-1, 1, 0], [0, -1, 1]])


def test_lees_inertia_numbers_and_the_smallest_axis_swap():
    # Lee: a = (B - C)/A, b = (A - C)/B, c = (A - B)/C, with A > B > C whatever order the moments come in
    body = Body.from_moments([1.0, 3.0, 2.0])
    assert (body.A, body.B, body.C) == (3.0, 2.0, 1.0)
    assert (body.a, body.b, body.c) == pytest.approx((1 / 3, 1.0, 1.0))
    swapped = body.swapped()
    assert (swapped.a, swapped.b, swapped.c) == pytest.approx((body.c, body.b, body.a))


def test_the_elastic_wobbles_invariants_are_the_legendre_pair_of_its_K_by_sympy():
    """wobble.invariants returns |l| and E = y.l - K with l = grad K, K = y.Jy/2 + beta(|y|^4/6 - y3^2/2
    + |y|^2/6) (Lamb Art. 71's bulge, the docstring's K): K written out here, differentiated by sympy."""
    import sympy as sp

    from classical_dynamics.models import wobble

    model = wobble.assemble(
        0.0032738, {"triaxiality": {"b_minus_a_over_c": 2.2e-5}, "elastic_yielding": {"k2": 0.3}}
    )
    params = model.parameters()
    a, b, beta = params[wobble.A_C], params[wobble.B_C], params[wobble.BETA]
    assert params[wobble.ELASTIC] and beta > 0 and a != b
    y1, y2, y3 = sp.symbols("y1:4")
    w2 = y1**2 + y2**2 + y3**2
    K = (a * y1**2 + b * y2**2 + y3**2) / 2 + beta * (w2**2 / 6 - y3**2 / 2 + w2 / 6)
    grad = [sp.lambdify((y1, y2, y3), sp.diff(K, v)) for v in (y1, y2, y3)]
    K_of = sp.lambdify((y1, y2, y3), K)
    y = np.random.default_rng(71).normal(0.0, 0.6, (5, 3))
    l = np.array([[g(*row) for g in grad] for row in y])
    expected_E = np.sum(y * l, axis=1) - np.array([K_of(*row) for row in y])
    size, E = wobble.invariants(y, params)
    assert np.allclose(size, np.linalg.norm(l, axis=1), rtol=1e-13)
    assert np.allclose(E, expected_E, rtol=1e-12)


def test_the_moons_perigee_at_j2000_is_the_iers_delaunay_arguments():
    """The modern orbits' lunar perigee longitude: F + Omega - l at J2000 from pyerfa's IERS 2003 Delaunay
    arguments (varpi = L - l, L = F + Omega)."""
    import erfa

    from classical_dynamics.models import precession

    varpi = (erfa.faf03(0.0) + erfa.faom03(0.0) - erfa.fal03(0.0)) % (2 * np.pi)
    assert precession.modern().moon_varpi == pytest.approx(varpi, abs=1e-6)


def test_a_viscous_body_settles_only_with_both_frictions_and_then_where_theorem_3_says():
    """Lee Theorem 3: with nu > 0 and mu > 0 omega tends to a limit; with either zero (r' = m3 unchecked, or
    p, q undamped) it has none. The limit is checked against scipy's integration of (5.49) to late times."""
    from scipy.integrate import solve_ivp

    from classical_dynamics.models.viscous_medium import ViscousMedium

    m, w0 = (0.3, -0.2, 0.5), (0.4, 0.1, 1.0)
    assert ViscousMedium.from_moments(1.0, 0.6, 0.5, 0.0, m, w0).limit() is None
    assert ViscousMedium.from_moments(1.0, 0.6, 0.0, 0.7, m, w0).limit() is None
    medium = ViscousMedium.from_moments(1.0, 0.6, 0.5, 0.7, m, w0)
    h, nu, mu = medium.h, medium.nu, medium.mu

    def f(t, w):
        return [h * w[1] * w[2] + m[0] - nu * w[0], -h * w[0] * w[2] + m[1] - nu * w[1], m[2] - mu * w[2]]

    late = solve_ivp(f, (0.0, 80.0), w0, rtol=1e-12, atol=1e-14).y[:, -1]
    assert np.allclose(medium.limit(), late, atol=1e-9)


def test_a_tops_turning_point_is_a_root_of_its_nutation_cubic():
    """Started with theta' = 0, the top is at a turning point: u0 = cos(theta0) is u1 or u2 of the cubic
    f(u) = (1 - u^2)(2/A)(E' - Mgh u) - (Jz - J3 u)^2/A^2 (written out here), and each root is one of f."""
    from classical_dynamics.models.heavy_top import Nutation, Top

    top = Top(A=1.3, C=0.5, Mgh=0.8)  # A != 1: no power of A may be lost unseen
    theta0 = np.radians(40.0)
    J3, Jz, E = (float(v[0]) for v in top.integrals(top.state(theta0, 0.0, 0.3, 6.0)))
    nut = Nutation.from_integrals(top.A, top.C, top.Mgh, J3, Jz, E)
    Ep = E - 0.5 * J3 * J3 / top.C

    def f(u):
        return (1 - u * u) * 2.0 / top.A * (Ep - top.Mgh * u) - (Jz - J3 * u) ** 2 / top.A**2

    assert min(abs(nut.u1 - np.cos(theta0)), abs(nut.u2 - np.cos(theta0))) < 1e-12
    assert nut.u1 < nut.u2 < 1.0 < nut.u3
    assert all(abs(f(u)) < 1e-12 for u in (nut.u1, nut.u2, nut.u3))


def test_a_tops_rates_read_back_the_euler_angles_rates_it_was_built_from():
    """Top.state from Euler's angles and rates (z-x-z), then rates() from the body rates and the vertical:
    phi' as given and psi' = omega_3 - phi' cos theta (Lamb Art. 51), at a psi that mixes w1 and w2; and at
    phi = psi = 0 the space x axis is the body's (1, 0, 0)."""
    from classical_dynamics.models.heavy_top import Top, rates

    top = Top(1.0, 0.5, 1.0)
    theta, theta_dot, phi_dot, omega3 = 0.7, 0.3, 1.9, 6.0
    y = top.state(theta, theta_dot, phi_dot, omega3, phi=0.4, psi=1.1)
    phi_rate, psi_rate = rates(top, y)
    assert phi_rate[0] == pytest.approx(phi_dot, rel=1e-13)
    assert psi_rate[0] == pytest.approx(omega3 - phi_dot * np.cos(theta), rel=1e-13)
    assert y[5] == pytest.approx(np.cos(theta), rel=1e-15)  # the vertical's body z component
    assert top.state(theta, theta_dot, phi_dot, omega3)[6:] == pytest.approx([1.0, 0.0, 0.0], abs=1e-15)
