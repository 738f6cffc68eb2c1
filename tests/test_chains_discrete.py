"""More direct unit tests of studies/chains/discrete.py, each against a reference the module does not compute:
Lagrange's sine law of the loaded string, scipy's Laguerre zeros and Bessel zeros, and a sympy Lagrangian of
the compound pendulum of rigid links."""

import numpy as np
import pytest
import sympy as sp
from scipy import special

from classical_dynamics.results import Results
from classical_dynamics.studies.chains import discrete


def test_loaded_string_approaches_the_continuum_by_the_sine_law():
    # Lagrange (Lamb Ex. XIV.10): n particles of rho a on n + 1 intervals a under tension P have
    # omega_s = 2 sqrt(P/(rho a^2)) sin(x), x = s pi/(2(n + 1)); the harmonics are s pi/l sqrt(P/rho),
    # so the ratio is exactly sin(x)/x, whatever P, rho and l
    chain = {"n": 10, "ends": "fixed-fixed", "length_m": 1.7, "mass_kg": 0.6}
    n_values = [10, 20, 40, 80]
    values = discrete.continuum_limit(chain, {"tension": {"newton": 2.5}}, "fixed-fixed", n_values)
    x = np.arange(1, 4)[None, :] * np.pi / (2 * (np.array(n_values)[:, None] + 1))
    errors = np.abs(np.sin(x) / x - 1)
    assert values.error_at_largest == pytest.approx(errors[-1].max(), rel=1e-8)
    intervals = np.log(np.array(n_values) + 1.0)
    order = min(-np.polyfit(intervals, np.log(errors[:, s]), 1)[0] for s in range(3))
    assert values.order == pytest.approx(order, rel=1e-6)
    # the record writes the same values, and the largest n
    results = Results("chains", "t", "t")
    discrete._record_continuum_limit(results, values)
    got = {k: v["value"] for k, v in results.numbers.items()}
    assert got["continuum_limit_error_at_largest"] == values.error_at_largest
    assert got["continuum_limit_order"] == values.order
    assert got["continuum_limit_n_largest"] == 80


@pytest.mark.filterwarnings("ignore:overflow:RuntimeWarning")  # scipy's weights overflow, not the nodes
@pytest.mark.parametrize("n", [1, 7, 64, 1024, 3000])
def test_exact_lambda1_is_the_lowest_laguerre_zero(n):
    # scipy's Golub-Welsch roots; beyond n = 1024 the module uses Tricomi's expansion instead of Newton
    assert discrete.exact_lambda1(n) == pytest.approx(special.roots_laguerre(n)[0][0], rel=1e-11)


def test_richardson_on_laguerre_zeros_gives_bernoullis_frequency():
    # (n + 1/2) lambda_1(n) -> (j01/2)^2 with a 1/N^2 term (Lamb Art. 90, the hanging chain's gravest mode):
    # eliminating it leaves O(1/N^4); the zeros are scipy's, the limit scipy's j0 zero
    exact = special.jn_zeros(0, 1)[0] / 2
    errors = []
    for n1 in (16, 32):
        coarse = (n1, special.roots_laguerre(n1)[0][0])
        fine = (2 * n1, special.roots_laguerre(2 * n1)[0][0])
        raw = abs(np.sqrt((2 * n1 + 0.5) * fine[1]) / exact - 1)
        errors.append(abs(discrete._richardson(coarse, fine) / exact - 1))
        assert errors[-1] < raw / 1000
    assert errors[0] / errors[1] > 12  # fourth order: doubling n divides the error by about 16, not 4


def _links_by_sympy(n):
    """omega / sqrt(g/l) of n uniform rigid rods (mass 1, length a = l/n) hanging end to end, linearised:
    the mass and stiffness matrices as Hessians of the Lagrangian, built from the rods' centres of mass."""
    a, g = sp.Rational(1, n), 1
    th = sp.symbols(f"t0:{n}")
    dth = sp.symbols(f"d0:{n}")
    T, V = 0, 0
    x, y, vx, vy = 0, 0, 0, 0  # the top of rod i, and its velocity
    for i in range(n):
        cy = y - a / 2 * sp.cos(th[i])  # the centre's height
        cvx, cvy = vx + a / 2 * sp.cos(th[i]) * dth[i], vy + a / 2 * sp.sin(th[i]) * dth[i]
        T += (cvx**2 + cvy**2) / 2 + a**2 / 12 * dth[i] ** 2 / 2
        V += g * cy
        x, y = x + a * sp.sin(th[i]), y - a * sp.cos(th[i])
        vx, vy = vx + a * sp.cos(th[i]) * dth[i], vy + a * sp.sin(th[i]) * dth[i]
    at_rest = {**{t: 0 for t in th}, **{d: 0 for d in dth}}
    M = np.array(sp.hessian(T, dth).subs(at_rest), float)
    K = np.array(sp.hessian(V, th).subs(at_rest), float)
    return np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real))  # l = 1, g = 1


@pytest.mark.parametrize("n", [1, 2, 3])
def test_rigid_links_against_a_sympy_lagrangian(n):
    if n == 1:
        # a rod pivoted at its end: omega^2 = 3g/(2l)
        assert discrete.links_frequencies(1, 1) == pytest.approx([np.sqrt(1.5)], rel=1e-14)
    assert discrete.links_frequencies(n, n) == pytest.approx(_links_by_sympy(n), rel=1e-12)


def test_many_links_tend_to_the_hanging_chain():
    # the links' gravest frequency tends to the continuous chain's j01/2 sqrt(g/l) (scipy's Bessel zero)
    exact = special.jn_zeros(0, 1)[0] / 2
    gaps = [abs(discrete.links_frequencies(n, 1)[0] / exact - 1) for n in (50, 100)]
    assert gaps[1] < gaps[0] < 1e-2


def test_relative_leaves_zero_references_blank():
    assert discrete._relative([1.1, 5.0, 3.0], [1.0, 0.0, 4.0]) == pytest.approx([0.1, None, -0.25])
