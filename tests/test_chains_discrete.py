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


def test_a_links_scene_records_the_lagrangian_frequencies_its_convergence_and_nothing_unasked():
    """A scene of 3 rigid links with a convergence sweep, run as the study runs it: its frequencies are the
    sympy Lagrangian's, its table calls it a chain of links, the sweep converges at second order and from
    above (the scene file's Ritz bound, against scipy's j01/2), and the orthogonality it did not ask for is
    absent."""
    from types import SimpleNamespace

    g, length = 9.81, 1.0
    data = {
        "chain": {"model": "links", "n": 3, "length_m": length, "mass_kg": 1.0},
        "effects": {"gravity": {"g_m_per_s2": g}},
        "analysis": {"modes": 3, "convergence": {"n_values": [4, 8, 16, 32, 64]}},
    }
    results = Results("chains", "t", "t")
    discrete.run(SimpleNamespace(name="t", title="t", data=data), results, True)
    got = {k: v["value"] for k, v in results.numbers.items()}
    np.testing.assert_allclose(
        got["frequencies_rad_per_s"], _links_by_sympy(3) * np.sqrt(g / length), rtol=1e-12
    )
    assert "3-link chain" in results.tables["frequencies"][1]
    assert got["links_convergence_order"] == pytest.approx(2.0, abs=0.05)
    assert got["links_all_above_continuum"]
    # neither closed_form nor constraint asked: Art. 91's orthogonality is not computed
    assert not any(name.startswith("orthogonality") for name in results.numbers)


def test_closed_form_takes_the_printed_formula_below_one_rad_per_s():
    """Two masses m between three springs k (the lecture notes' equal_springs): omega^2 = k/m and 3k/m written
    out here, with k/m = 1/4 so that both omega^2 are below 1; the printed formula must give them."""
    from classical_dynamics.models.chains import particle_chain

    k, m = 0.25, 1.0
    built = particle_chain(2, "fixed-fixed", 1.0, m, {"springs": {"k_n_per_m": [k, k, k]}})
    exact = np.sqrt([k / m, 3 * k / m])
    values = discrete.closed_form(
        built.masses, built.segment_stiffness, "fixed-fixed", "equal_springs", exact
    )
    np.testing.assert_allclose(values.derived, exact, rtol=1e-14)
    assert values.formula_exact
    assert values.formula_vs_solver < 1e-14
    assert values.solver_vs_derived < 1e-14


def test_accuracy_cost_quick_keeps_small_sizes_and_records_each_solver():
    """The solver sweep against scipy's Laguerre zero and Bessel zero: the quick run drops the sizes above
    QUICK_MAX_N, every solver's lambda_1 at n = 16 is scipy's lowest zero of L_16, omega_1 end-corrected is
    (n + 1/2) lambda_1 against j01/2, and the record has one worst error per solver."""
    frame = discrete.accuracy_cost([16, 2048], 1, True)
    assert 16 <= discrete.QUICK_MAX_N < 2048
    assert set(frame.n) == {16}
    lam1 = special.roots_laguerre(16)[0][0]
    j1 = special.jn_zeros(0, 1)[0] / 2
    np.testing.assert_allclose(frame.algebraic_relative_error, 0.0, atol=1e-12)
    np.testing.assert_allclose(
        frame.discretization_relative_error, abs(np.sqrt(16.5 * lam1) / j1 - 1), rtol=1e-8
    )
    results = Results("chains", "t", "t")
    discrete._record_accuracy_cost(results, frame)
    for method in frame.solver.unique():
        assert results.numbers[f"{method}_worst_relative_error_lambda1"]["value"] < 1e-12
    assert set(results.timing_figures) >= {"solver_cost"}


def test_cost_to_target_richardson_reaches_a_target_with_fewer_particles():
    """The quick sweep n = 2 ... 2^12 (pliability): the end-corrected error falls as 1/n^2 (Lamb Art. 90's
    correction; scipy's j01 the reference), and Richardson's fourth order reaches 1e-6 with a smaller n; the
    record's table is the sweep's frame."""
    values = discrete.cost_to_target([1e-6], True)
    assert values.top == 12
    frame = values.frame.set_index("scheme")
    end = frame.loc[discrete.END_CORRECTED]
    rich = frame.loc[discrete.RICHARDSON]
    assert end.measured and rich.measured
    assert rich.n < end.n
    assert end.error <= 1e-6 and rich.error <= 1e-6
    results = Results("chains", "t", "t")
    discrete._record_cost_to_target(results, values)
    assert results.timing_tables["cost_to_target"][0] is values.frame
    assert "work_precision" in results.timing_figures
