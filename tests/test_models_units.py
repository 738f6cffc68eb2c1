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
