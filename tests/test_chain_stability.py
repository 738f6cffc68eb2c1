"""Lamb's stability (studies/chains/stability.py) and the handbook checks added beside it: each computation
against its closed form, and the cases that must fail when the physics is wrong."""

from types import SimpleNamespace

import numpy as np
import pytest
import yaml
from scipy.special import jn_zeros

from classical_dynamics.models import linear
from classical_dynamics.scenes import SceneError
from classical_dynamics.studies import validate
from classical_dynamics.studies.chains import stability, symbolic

from .conftest import values


class Recorder:
    def __init__(self):
        self.values, self.hard = {}, {}

    def number(self, name, value, unit, **_):
        self.values[name] = value

    def hard_case(self, name, description, measured, bound, unit=""):
        self.hard[name] = (measured, bound)


def test_sympy_references():
    assert symbolic.equal_root_minors() == (True, 2)
    assert symbolic.kinetic_stability() == (True, True)
    assert symbolic.bowl_relative_equilibrium()
    assert symbolic.exponential_force_bounds() == (1, 2)
    sigma2, printed, equal = symbolic.revolving_string()
    assert printed and equal == 5


def test_equal_roots_bounded_but_a_jordan_block_grows():
    rng = np.random.default_rng(0)
    L = np.array([[2.0, -1, -1], [-1, 2, -1], [-1, -1, 2]])
    # roots 1 and 4: the motion has period 2 pi, no later period exceeds the first (ratio 1, any start)
    assert abs(stability._bounded(np.eye(3) + L, np.eye(3), 2 * np.pi, 500, rng) - 1) < 1e-10
    growth = stability._bounded(np.array([[1.0, 1.0], [0.0, 1.0]]), np.eye(2), 2 * np.pi, 500, rng)
    assert growth > 100  # secular: the amplitude grows as t


def test_gyroscopic_switch_secular_instability_and_bowl():
    v = stability.gyroscopic({"beta": 3.0, "epsilon": 1e-4, "bowl_friction": 0.1})
    assert abs(v.switch_beta - 2.0) < 1e-10
    assert v.positive_c_unstable_count == 0 and v.mixed_c_stable_count == 0
    negative, positive = v.secular
    assert (negative.label, positive.label) == ("negative", "positive")
    slower, faster = negative.real_parts
    assert slower > 0 > faster  # the slower mode grows: secular instability
    assert max(positive.real_parts) < 0  # positive c: both decay
    assert negative.deviation < 1e-6
    assert abs(v.bowl.switch_omega - 1.0) < 1e-10
    assert np.allclose(v.bowl.space_rates_frictionless, [-1.0, 1.0], atol=1e-12)
    assert v.bowl.growing_space_rate > 0 and v.bowl.growing_real_part > 0
    # the record writes the same values under the report's names
    r = Recorder()
    stability.record_gyroscopic(r, v)
    assert r.values["secular_real_parts_c_negative"] == negative.real_parts
    assert r.values["bowl_switch_omega_over_n"] == v.bowl.switch_omega


def test_revolving_examples():
    v = stability.revolving()
    # by hand: kappa^2 = 3f/r + f' is e^-r (1/r^3 - 1/r^2) for f = e^-r/r^2 (zero at r = a),
    # e^-r (2/r^2 - 1/r) for the OCR's e^-r/r (zero at 2a); the module bisects a complex-step derivative
    assert abs(v.force_switch - 1.0) < 1e-10
    assert abs(v.force_switch_ocr - 2.0) < 1e-10
    # independent sides: a nonlinear integration of Lagrange's equations against Routh's sigma^2 from sympy
    assert v.sigma2_fitted_vs_formula < 1e-8


def test_ball_modes_are_conjugate_and_fixed_axes():
    v = stability.ball_modes(seed=3)
    # conjugacy in I and V is what scipy's eigh guarantees: these two show the reported figures are
    # computed, not that project code is right; the axis check integrates linear.state_matrix (tested below)
    assert v.conjugate_inertia < 1e-13 and v.conjugate_potential < 1e-13
    assert v.axis_fixed < 1e-10


def test_state_matrix_has_the_characteristic_roots():
    # M q'' + (B + G) q' + K q = 0: for one coordinate the roots of m s^2 + c s + k (numpy), and for two
    # with a gyroscopic G the roots of det(M s^2 + (B + G) s + K), a quartic expanded by hand
    A = linear.state_matrix(np.array([[3.0]]), np.array([[2.0]]), np.array([[0.5]]))
    assert np.sort_complex(np.linalg.eigvals(A)) == pytest.approx(np.sort_complex(np.roots([2.0, 0.5, 3.0])))
    k1, k2, b, g = 2.0, 5.0, 0.3, 1.7
    A = linear.state_matrix(np.diag([k1, k2]), np.eye(2), np.diag([b, 0.0]), np.array([[0.0, g], [-g, 0.0]]))
    # det [[s^2 + b s + k1, g s], [-g s, s^2 + k2]] = (s^2 + b s + k1)(s^2 + k2) + g^2 s^2
    quartic = [1.0, b, k1 + k2 + g * g, b * k2, k1 * k2]
    expected = np.sort_complex(np.roots(quartic))
    assert np.sort_complex(np.linalg.eigvals(A)) == pytest.approx(expected, rel=1e-10)
    # the spectrum does not see G's sign (g^2 only); the motion does: q'' = -K q - (B + G) q' with M = 1
    q, v = np.array([0.2, -0.4]), np.array([1.0, 0.5])
    accel = -np.array([k1 * q[0] + b * v[0] + g * v[1], k2 * q[1] - g * v[0]])
    assert A @ np.concatenate([q, v]) == pytest.approx(np.concatenate([v, accel]), rel=1e-14)


def test_hamilton_chain_converges_at_order_two_to_the_j0_zeros():
    v = stability.hamilton_chain([250, 500, 1000, 2000])
    # the errors are against (j_0k/2)^2 from scipy's jn_zeros (a library's Bessel zeros, not the module's
    # finite elements); a wrong reference (j_0k/2.02) stops the convergence and fails the order
    assert abs(v.order - 2.0) < 0.02
    assert v.richardson_error < v.errors[-1] / 100


def test_hamilton_chain_record_names_its_meshes_and_the_finest_error():
    """The record of two meshes, 250 and 500 elements: the meshes as asked, and second order (the docstring's
    linear elements) makes the finest mesh's error a quarter of the coarser one's; every unit registered."""
    from classical_dynamics.results import Results
    from classical_dynamics.units import lookup

    results = Results("chains", "t", "t")
    stability.record_hamilton_chain(results, stability.hamilton_chain([250, 500]))
    got = values(results)
    assert got["galerkin_elements"] == [250, 500]
    assert got["galerkin_finest_error"] / got["galerkin_relative_errors"][0] == pytest.approx(0.25, rel=0.02)
    for entry in results.numbers.values():
        lookup(entry["unit"])  # raises UnknownUnit for a unit nobody registered


def test_drum_collocation_finds_the_bessel_zeros_not_their_roots():
    v = stability.drum(41)
    computed = np.array(v.collocation)
    assert abs(computed[0] - jn_zeros(0, 1)[0]) < 1e-12
    assert abs(computed[0] - 1.551) > 0.8  # the notes' 1.551 is sqrt(j01), not a frequency
    assert v.collocation_vs_bessel < 1e-12
    assert [tuple(x) for x in v.modes_mn[:4]] == [(0, 1), (1, 1), (2, 1), (0, 2)]


RING = {
    "title": "ring",
    "chain": {"model": "ring", "n": 16, "length_m": 1.0, "mass_kg": 1.0},
    "effects": {"rotation": {"omega_rad_per_s": 1.0}, "springs": {"k_n_per_m": 1.0e4}},
    "analysis": {"ring_waves": {"s_max": 4}},
}
CONTINUUM = {
    "title": "c",
    "chain": {"model": "continuum", "length_m": 1.0, "mass_kg": 1.0},
    "effects": {"gravity": {"g_m_per_s2": 9.81}},
}


@pytest.mark.parametrize(
    "data,field,expected",
    [
        (
            {**RING, "analysis": {"gyroscopic": {"beta": 3.0, "epsilon": 1e-4, "bowl_friction": 0.1}}},
            "analysis",
            "ring_waves",
        ),
        (
            {
                **RING,
                "analysis": {
                    "ring_waves": {"s_max": 4},
                    "gyroscopic": {"beta": 1.5, "epsilon": 1e-4, "bowl_friction": 0.1},
                },
            },
            "analysis.gyroscopic.beta",
            "> 2",
        ),
        ({**CONTINUUM, "analysis": {"membrane": {"points": 40}}}, "analysis.membrane.points", "odd"),
        (
            {**CONTINUUM, "analysis": {"galerkin": {"elements": [1000, 1000000]}}},
            "analysis.galerkin.elements",
            "at most 100000",
        ),
        (
            {
                "title": "t",
                "chain": {
                    "model": "particles",
                    "n": 4,
                    "ends": "fixed-free",
                    "length_m": 1.0,
                    "mass_kg": 1.0,
                },
                "effects": {"gravity": {"g_m_per_s2": 9.81}},
                "analysis": {"stability": True},
            },
            "analysis.stability",
            "springs",
        ),
    ],
)
def test_bad_stability_scenes(tmp_path, data, field, expected):
    path = tmp_path / "scene.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(SceneError) as error:
        validate("chains", path)
    assert str(error.value).startswith(f"{path}: field '{field}'") and expected in str(error.value)


def test_rotation_checks_and_kept_energy():
    from classical_dynamics.studies.solvers import hard_cases

    turn, spring = hard_cases.rotations(), hard_cases.energy_kept()
    assert turn.trace_identity < 1e-14
    assert turn.axis_misalignment < 1e-15 and abs(turn.angle_deg - 60.0) < 1e-12
    assert spring.hamilton_exact == 1
    assert spring.midpoint_energy_change["hamiltonian"] < 1e-12


def test_reciprocal_theorem_needs_the_reversal():
    from classical_dynamics.models import heavy_top as top_model
    from classical_dynamics.studies.solvers import heavy_top

    r = heavy_top.reciprocal(top_model.Top(1.0, 0.5, 1.0), 6.0, np.radians(60.0))
    assert r.relative_difference < 1e-6
    assert r.unreversed_relative_difference > 0.1


def test_equilibrium_of_two_masses_on_three_springs_and_lambs_three_examples():
    """stability.equilibrium on two masses m on three springs k (roots k/m and 3k/m: the smallest is 1 in k/m)
    beside Art. 85-89's springs k, -k, k (K's eigenvalues -k and k, a root sqrt(k/m), growth exp(sqrt(k/m) t)
    from t = 15 to 30 over it), Art. 92's ring (1, 4, 4, bounded), and a double root not from a potential,
    whose secular term grows as t: over 10^4 periods a factor of order 10^4, not of order 1."""
    k, m = 2.0, 1.5
    built = SimpleNamespace(
        stiffness_matrix=lambda: np.array([[2 * k, -k], [-k, 2 * k]]),
        masses=np.array([m, m]),
        segment_stiffness=np.array([k, k, k]),
    )
    e = stability.equilibrium(built)
    assert e.scene_smallest_eigenvalue == pytest.approx(1.0, rel=1e-14)
    assert e.indefinite_eigenvalues == pytest.approx([-1.0, 1.0], abs=1e-14)
    assert e.indefinite_root_vs_exact < 1e-14 and e.indefinite_growth_rate == pytest.approx(1.0, rel=1e-9)
    assert np.log(e.indefinite_growth_factor) == pytest.approx(30.0, abs=3.0)  # |q0| of a random start
    assert e.equal_roots == pytest.approx([1.0, 4.0, 4.0], rel=1e-14)
    assert e.minors_vanish and e.multiplicity == 2 and e.periods == 10_000
    assert 0.0 <= e.equal_roots_growth < 1e-9
    assert 0.1 * e.periods < e.non_symmetric_growth < 10 * e.periods
