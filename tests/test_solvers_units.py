"""Unit tests of the solver study's parts (studies/solvers: sweeps, long_horizon, inertia, hard_cases,
heavy_top, the scene check), each against something the module does not compute: Euler's equations written
out here and integrated by scipy's solve_ivp, closed forms of masses and moments (Pappus, the textbook
tables), quadratures by scipy.integrate.quad, roots of the turning-point quadratic by numpy, the conservation
of energy and of the Casimir |m|^2, and the orders of convergence h^2 and h^4."""

import importlib
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from classical_dynamics.models import heavy_top as top_model
from classical_dynamics.results import Results
from classical_dynamics.studies.solvers import hard_cases, heavy_top, inertia, long_horizon, sweeps

from .conftest import assert_refused, values

HNW_I = np.array([0.5, 2.0, 3.0])  # Hairer, Nørsett and Wanner vol. I p. 244
HNW_W0 = np.array([1.0, 0.0, 0.9])
TOP = top_model.Top(1.0, 0.5, 1.0)  # the shipped scene's top: A = Mgh = 1, C = 1/2


def euler_free(_, w, I=HNW_I):
    """Euler's equations of a free body, written out: I1 w1' = (I2 - I3) w2 w3 and cyclically."""
    return [
        (I[1] - I[2]) * w[1] * w[2] / I[0],
        (I[2] - I[0]) * w[2] * w[0] / I[1],
        (I[0] - I[1]) * w[0] * w[1] / I[2],
    ]


def scene(**data):
    return SimpleNamespace(data=data, name="s", title="t")


# ---- sweeps.py: the work-precision sweeps of HNW's body and DETEST B5


@pytest.mark.parametrize("problem", ["hnw_rigid_body", "detest_b5"])
def test_the_sweeps_exact_solutions_solve_their_equations_and_keep_their_invariants(problem):
    case, I = sweeps.case_for(problem)
    t = np.linspace(0.0, 20.0, 41)
    if problem == "hnw_rigid_body":
        assert np.array_equal(I, HNW_I)
        rhs, y0 = euler_free, HNW_W0
    else:  # DETEST B5 (Hull et al. 1972): y1' = y2 y3, y2' = -y1 y3, y3' = -0.51 y1 y2
        assert I is None
        rhs, y0 = (lambda _, y: [y[1] * y[2], -y[0] * y[2], -0.51 * y[0] * y[1]]), [0.0, 1.0, 1.0]
    # scipy's DOP853 on the equations written out here: the elliptic-function solution to 1e-10
    sol = solve_ivp(rhs, (0.0, 20.0), y0, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=t)
    exact = case.exact(t)
    assert np.max(np.abs(exact - sol.y.T)) < 1e-10
    for name, invariant in case.invariants.items():
        along = invariant(exact)  # energy and Casimir (or sn^2 + cn^2, m sn^2 + dn^2) are constants
        assert np.max(np.abs(along - along[0])) < 1e-13 * abs(along[0]), name
    headers = sweeps.accuracy_headers(problem)
    assert set(headers) >= {"error_final", "energy_drift", "casimir_drift"}
    assert sweeps.INVARIANTS[problem][0] in headers["energy_drift"]


def test_the_hnw_sweep_measures_errors_against_an_independent_integration_and_the_splittings_orders():
    results = Results("solvers", "hnw_rigid_body", "t")
    numerics = {
        "methods": ["dop853", "scipy:DOP853", "splitting2", "splitting4"],
        "tolerances": [1e-5, 1e-7, 1e-12],  # quick drops 1e-12
        "steps": [0.1, 0.05, 0.01],  # quick drops 0.01
    }
    sweeps.run(scene(problem="hnw_rigid_body", numerics=numerics), results, True)
    frame = results.tables["accuracy"][0]
    assert sorted(set(frame.setting[frame.kind == "tolerance"])) == [1e-7, 1e-5]
    assert sorted(set(frame.setting[frame.kind == "step"])) == [0.05, 0.1]
    # omega(20) from scipy's solve_ivp at rtol 1e-13 on Euler's equations written out here
    reference = solve_ivp(euler_free, (0.0, 20.0), HNW_W0, method="DOP853", rtol=1e-13, atol=1e-15).y[:, -1]
    from classical_dynamics.solvers import workprecision as wp

    case, _ = sweeps.case_for("hnw_rigid_body")
    for rtol in (1e-5, 1e-7):
        ours = wp.adaptive(case, "dop853").run(rtol, False).y_final
        row = frame[(frame.method == "dop853") & (frame.setting == rtol)].iloc[0]
        assert row.error_final == pytest.approx(np.max(np.abs(ours - reference)), rel=1e-4)
    loose, tight = (frame[(frame.method == "dop853") & (frame.setting == s)].iloc[0] for s in (1e-5, 1e-7))
    assert tight.error_final < loose.error_final and tight.steps > loose.steps
    # the splittings keep the Casimir |m|^2 exactly (exact rotations): round-off only
    splits = frame[frame.kind == "step"]
    assert (splits.casimir_drift < 1e-13).all() and (splits.energy_drift > 1e-9).all()
    # the error at t = 20 falls like h^2 and h^4 (halving h: 4 and 16 times)
    n = values(results)
    assert n["fitted_order_splitting_order_2"] == pytest.approx(2.0, abs=0.1)
    assert n["fitted_order_splitting_order_4"] == pytest.approx(4.0, abs=0.2)
    # DOP853's invariants at rtol 1e-12 (a run of its own): T and |m|^2 kept to ~1e-12
    assert (
        0 < n["dop853_rtol_1e-12_energy_drift"] < 1e-11 and 0 < n["dop853_rtol_1e-12_casimir_drift"] < 1e-11
    )
    # the compiled pair against scipy's (same tableau and step control, an independent implementation)
    assert n["dop853_same_steps_as_scipy"] is True and n["dop853_vs_scipy_max_relative_difference"] < 1e-6
    assert n["dop853_error_at_tightest"] == pytest.approx(tight.error_final)
    assert set(results.timing_tables) == {"work_precision", "first_call"} and "work_precision" in (
        results.timing_figures
    )
    # two legends below the panels: the adaptive methods under the work-precision panel, the splittings under
    # their convergence panel, each method once
    fig = results.timing_figures["work_precision"][0]
    left, right = ([t.get_text() for t in legend.get_texts()] for legend in fig.legends)
    assert sorted(left) == ["dop853", "scipy:DOP853"], left
    assert [label for label in right if label.startswith("splitting, order")] == [
        f"splitting, order {k} (fitted order {n[f'fitted_order_splitting_order_{k}']:.2f})" for k in (2, 4)
    ]


def test_the_detest_sweep_without_steps_has_one_panel_and_scipys_errors():
    results = Results("solvers", "detest_b5", "t")
    numerics = {"methods": ["dop853", "scipy:DOP853"], "tolerances": [1e-6, 1e-8]}
    sweeps.run(scene(problem="detest_b5", numerics=numerics), results, True)
    frame = results.tables["accuracy"][0]
    reference = solve_ivp(
        lambda _, y: [y[1] * y[2], -y[0] * y[2], -0.51 * y[0] * y[1]],
        (0.0, 20.0),
        [0.0, 1.0, 1.0],
        method="DOP853",
        rtol=1e-13,
        atol=1e-15,
    ).y[:, -1]
    for rtol in (1e-6, 1e-8):
        theirs = solve_ivp(
            lambda _, y: [y[1] * y[2], -y[0] * y[2], -0.51 * y[0] * y[1]],
            (0.0, 20.0),
            [0.0, 1.0, 1.0],
            method="DOP853",
            rtol=rtol,
            atol=rtol * 1e-3,
        ).y[:, -1]
        row = frame[(frame.method == "scipy:DOP853") & (frame.setting == rtol)].iloc[0]
        assert row.error_final == pytest.approx(np.max(np.abs(theirs - reference)), rel=1e-3)
    assert len(results.timing_figures["work_precision"][0].axes) == 1
    assert "dop853_rtol_1e-12_energy_drift" not in results.numbers  # HNW's body only


# ---- long_horizon.py: energy and Casimir over many periods


def test_long_horizon_splitting_keeps_the_casimir_to_round_off_and_its_energy_error_is_second_order():
    def run(step, periods):
        results = Results("solvers", "long_horizon", "t")
        numerics = {"max_periods": periods, "step": step, "rtol": 1e-8}
        long_horizon.run(scene(numerics=numerics), results, True)
        return results

    coarse, fine = values(run(0.1, 100)), run(0.05, 1000)
    n = values(fine)
    frame = fine.tables["long_horizon"][0]
    assert list(frame.periods.unique()) == [100.0, 1000.0]
    # the Casimir is kept by exact rotations: what is left is rounding, Brouwer's sqrt(N) eps
    N = 1000 * long_horizon.ref.HNW_PERIOD / 0.05
    assert n["splitting2_casimir_error_at_max"] < 10 * np.sqrt(N) * np.finfo(float).eps
    assert n["splitting2_casimir_over_brouwer"] < 10
    # the hard case the report names: the same ratio over ten Brouwer's, which must stay under 1
    cases = {case["name"]: case for case in fine.stability}
    assert cases["splitting_casimir_brouwer"]["measured"] == pytest.approx(
        n["splitting2_casimir_over_brouwer"] / 10, rel=1e-12
    )
    assert cases["splitting_casimir_brouwer"]["bound"] == 1.0
    # the energy error of a symplectic splitting stays bounded, DOP853's drifts (about linearly: 10x)
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert n["splitting2_energy_growth"] < 1.5 and fine.stability[0]["holds"]
    assert 3 < n["dop853_energy_drift_ratio"] < 30
    # order 2 and order 4: halving h divides the energy error by 4 and 16
    assert coarse["splitting2_energy_error_at_max"] / n["splitting2_energy_error_at_max"] == pytest.approx(
        4.0, rel=0.05
    )
    assert coarse["splitting4_energy_error_at_max"] / n["splitting4_energy_error_at_max"] == pytest.approx(
        16.0, rel=0.1
    )
    # DOP853's numbers are those of scipy's DOP853 run here on the written-out equations, to its tolerance
    t = np.linspace(0.0, 100 * long_horizon.ref.HNW_PERIOD, 2001)
    w = solve_ivp(euler_free, (0.0, t[-1]), HNW_W0, method="DOP853", rtol=1e-8, atol=1e-11, t_eval=t).y.T
    energy = 0.5 * np.sum(HNW_I * w * w, axis=1)
    theirs = np.max(np.abs(energy / energy[0] - 1))
    assert coarse["dop853_energy_error_at_max"] == pytest.approx(theirs, rel=0.5)


# ---- inertia.py: moments by quadrature


def test_quadrature_masses_are_the_bodies_lengths_areas_and_volumes():
    # the mass is the measure of the body (density 1): Pappus for the tori
    cases = [
        (inertia.rod(2.0, 6), 2.0),
        (inertia.disc(1.5, 6), np.pi * 1.5**2),
        (inertia.rectangle(2.0, 3.0, 4), 6.0),
        (inertia.sphere(2.0, 8), 4 / 3 * np.pi * 8.0),
        (inertia.cylinder(1.0, 3.0, 6), np.pi * 3.0),
        (inertia.torus_circular(3.0, 1.0, 8), 2 * np.pi * 3.0 * np.pi),
        (inertia.torus_square(3.0, 0.5, 6), 2 * np.pi * 3.0 * 1.0),
    ]
    for body, volume in cases:
        M, I = inertia.tensor(*body)
        assert M == pytest.approx(volume, rel=1e-13)
        assert np.allclose(I, I.T) and np.all(np.linalg.eigvalsh(I) > -1e-12)


def test_the_discs_rule_has_the_captions_nodes():
    """The moments table's caption: n Gauss-Legendre nodes a radius, 2n trapezoidal nodes an angle; the
    weights sum to the area pi a^2."""
    points, weights = inertia.disc(1.5, 6)
    assert points.shape == (6 * 12, 3) and weights.sum() == pytest.approx(np.pi * 1.5**2, rel=1e-13)
    angles = np.unique(np.round(np.arctan2(points[:, 1], points[:, 0]) % (2 * np.pi), 12))
    assert angles.size == 12


def test_every_moment_matches_the_textbook_closed_form_and_the_axis_theorems_hold():
    results = Results("solvers", "inertia", "t")
    inertia.run(scene(numerics={"nodes": 8}), results, True)
    n = values(results)
    # the tables of any mechanics text, in units of M (length)^2: l = a = 1, cylinder l = 2a, tori d = 3
    closed = {
        "rod_centre": 1 / 12,
        "rod_end": 1 / 3,
        "disc_axial": 1 / 2,
        "disc_diameter": 1 / 4,
        "disc_rim": 1 / 2 + 1,
        "rectangle_axial": (2**2 + 1**2) / 12,
        "sphere": 2 / 5,
        "sphere_x": 2 / 5,
        "cylinder_transverse": 1 / 4 + 2**2 / 12,
        "cylinder_axial": 1 / 2,
        "torus_circular": 3**2 + 3 / 4,
        "torus_square": 3**2 + 1,
    }
    for name, value in closed.items():
        assert n[name] == pytest.approx(value, rel=1e-12), name
    frame = results.tables["moments"][0]
    assert len(frame) == len(closed) and frame.relative_difference.abs().max() < 1e-12
    for key in (
        "moments_max_relative_difference",
        "perpendicular_axes_residual",
        "parallel_axes_residual",
        "parallel_axis_general_residual",
        "dumbbell_tensor_residual",
    ):
        assert n[key] < 1e-12, key
    # the dumbbell (m at +-(1, -1, 0)/sqrt 2, omega = e_y): J = sum m r x (omega x r), by hand (1, 1, 0)
    r = np.array([[1, -1, 0], [-1, 1, 0]]) / np.sqrt(2)
    J = sum(np.cross(p, np.cross([0, 1, 0], p)) for p in r)
    assert np.allclose(J, [1, 1, 0])
    assert n["dumbbell_J_angle_deg"] == pytest.approx(45.0, rel=1e-12)
    assert n["dumbbell_couple_z"] == pytest.approx(np.cross([0, 1, 0], J)[2], rel=1e-12)


# ---- hard_cases.py


def test_tenth_power_writes_a_tolerance_as_a_power_of_ten():
    assert hard_cases.tenth_power(1e-9) == "10⁻⁹"
    assert hard_cases.tenth_power(1e-12) == "10⁻¹²"


@pytest.fixture(scope="module")
def damping():
    return hard_cases.numerical_damping(periods=5)  # a short run


def test_numerical_damping_of_verlet_is_its_closed_form_and_bdf_loses_energy(damping):
    """Störmer–Verlet on q'' = -q from (1, 0) moves on cos(k θ), cos θ = 1 - h²/2, and keeps
    (v² + (1 - h²/4) q²)/2 exactly: its energy's relative change after k steps is -(h²/4) sin²(k θ). BDF and
    Radau IIA are dissipative (L-stable): on an undamped oscillator they lose energy, a positive Q."""
    frame, periods = damping.frame, damping.periods
    verlet = frame[frame.method == "Störmer–Verlet"]
    assert len(verlet) == 2
    for h, change in zip(verlet.setting, verlet.energy_change):
        k = round(periods * 2 * np.pi / h)
        theta = np.arccos(1 - h * h / 2)
        assert change == pytest.approx(-(h * h / 4) * np.sin(k * theta) ** 2, rel=1e-6)
    for method in ("scipy:BDF", "scipy:Radau"):
        rows = frame[frame.method == method]
        assert len(rows) == 2 and (rows.energy_change < 0).all() and (rows.spurious_Q > 0).all()
    adaptive = frame[frame.kind == "tolerance"]
    assert np.allclose(adaptive.spurious_Q * adaptive.energy_change, -2 * np.pi * periods, rtol=1e-14)


def test_numerical_damping_figure_names_each_method_as_its_table_does(damping):
    """scipy's DOP853 and this library's dop853 are different methods: the figure keeps the table's names."""
    import matplotlib.pyplot as plt

    results = Results("solvers", "hard_cases", "t")
    hard_cases._record_numerical_damping(results, damping)
    frame = damping.frame
    assert results.tables["numerical_damping"][0] is frame
    fig, _ = results.figures["numerical_damping"]
    ax = fig.axes[0]
    names = [t.get_text().replace("\n", "") for t in ax.get_xticklabels()]
    assert names == [m for m in dict.fromkeys(frame.method) if m != "Störmer–Verlet"]
    assert "dop853" in names and "scipy:DOP853" in names
    # the grey line stands between this library's pairs and SciPy's integrators
    (line,) = [v for v in ax.lines if v.get_xdata()[0] == v.get_xdata()[-1]]
    assert line.get_xdata()[0] == names.index("scipy:RK45") - 0.5
    # every point drawn inside the axes, and each series of markers named by its tolerance, as in the table
    lo, hi = ax.get_xlim()
    points = [v for v in ax.lines if v is not line]
    assert all(lo < x < hi for v in points for x in v.get_xdata())
    assert lo < 0 and hi > len(names) - 1
    rtols = sorted(set(frame[frame.method != "Störmer–Verlet"].setting), reverse=True)
    superscript = str.maketrans(
        "-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079"
    )
    expected = [f"relative tolerance 10{str(round(math.log10(r))).translate(superscript)}" for r in rtols]
    assert [v.get_label() for v in points] == expected
    plt.close(fig)


def test_intermediate_axis_grows_at_the_linearised_rate():
    axis = hard_cases.intermediate_axis()
    theory = np.sqrt((3 - 2) * (2 - 1) / (3 * 1))  # A, B, C = 3, 2, 1, q0 = 1: linearised Euler equations
    assert axis.theory == pytest.approx(theory, rel=1e-15)
    assert axis.measured == pytest.approx(theory, rel=1e-3)
    results = Results("solvers", "hard_cases", "t")
    hard_cases._record_intermediate_axis(results, axis)
    assert values(results)["intermediate_axis_growth_rate"] == axis.measured
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert results.stability[0]["holds"]


def test_blow_up_times_are_the_integral_of_dp_over_m_plus_mu_p_squared():
    frame = hard_cases.blow_up()
    results = Results("solvers", "hard_cases", "t")
    hard_cases._record_blow_up(results, frame)
    for row in frame.itertuples():
        # t* = integral from p0 to +-infinity of dp / (m + mu p^2), by scipy's quad
        end = np.inf if (row.mu > 0 or (row.mu == 0 and row.m > 0)) else -np.inf
        t_star = abs(quad(lambda p: 1.0 / (row.m + row.mu * p * p), row.p0, end, epsabs=1e-13)[0])
        assert row.t_star_closed_form == pytest.approx(t_star, rel=1e-8)
        assert row.t_star_measured == pytest.approx(t_star, rel=1e-8)
        assert row.status == "blow-up"
    assert values(results)["blow_up_lee_case_t_star"] == pytest.approx(frame.t_star_measured[1])


def test_near_the_separatrix_the_period_returns_the_body_and_the_invariants_hold():
    sep = hard_cases.separatrix(1e-4, True)
    results = Results("solvers", "hard_cases", "t")
    hard_cases._record_separatrix(results, sep)
    n = values(results)
    assert n["separatrix_period"] == sep.period and n["separatrix_ellipj_error_ours"] == sep.ellipj_error_ours
    # scipy's solve_ivp over one period from omega0 = (sqrt(3 m), 0, 1), I = (1, 2, 3): back at the start
    I, m = np.array([1.0, 2.0, 3.0]), 1 - 1e-4
    w0 = np.array([np.sqrt(3 * m), 0.0, 1.0])
    sol = solve_ivp(
        lambda t, w: euler_free(t, w, I), (0, sep.period), w0, method="DOP853", rtol=1e-13, atol=1e-14
    )
    assert np.max(np.abs(sol.y[:, -1] - w0)) < 1e-6
    assert sep.ellipj_error_ours < 1e-13
    assert sep.dop853_energy_error < 1e-10 and sep.splitting_casimir_error < 1e-12
    assert sep.reference_vs_dop853 < 1e-8
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert all(case["holds"] for case in results.stability)


def test_the_spring_keeps_its_energy_and_the_handbooks_rotation_turns_60_degrees():
    spring, turn = hard_cases.energy_kept(), hard_cases.rotations()
    assert spring.hamilton_exact == 1
    # the implicit midpoint rule keeps a quadratic invariant of a linear system to rounding
    assert spring.midpoint_energy_change["lagrangian"] < 1e-12
    assert spring.midpoint_energy_change["hamiltonian"] < 1e-12
    # Tr R = (3 + 2 + 3)/4 = 2 = 1 + 2 cos phi: phi = 60 degrees, about (1, 0, 1)/sqrt 2
    assert turn.angle_deg == pytest.approx(60.0, rel=1e-12)
    assert turn.angle_from_trace_deg == pytest.approx(60.0, rel=1e-12)
    for key in ("trace_identity", "orthogonality", "axis_misalignment", "rotvec_misalignment"):
        assert 0.0 <= getattr(turn, key) < 1e-12, key
    # the records write them under the report's names
    results = Results("solvers", "hard_cases", "t")
    hard_cases._record_energy_kept(results, spring)
    # a flag of 1 or 0 says what 1 means, and by what it was found
    flag = results.numbers["spring_hamilton_equations_exact"].get("note", "")
    assert flag.startswith("1:") and "sympy" in flag
    hard_cases._record_rotations(results, turn)
    n = values(results)
    assert n["oscillator_hamiltonian_midpoint_energy_change"] == spring.midpoint_energy_change["hamiltonian"]
    assert {name: n[name] for name in n if name.startswith(("rotation_", "ex2_2_"))} == {
        "rotation_trace_identity": turn.trace_identity,
        "ex2_2_orthogonality": turn.orthogonality,
        "ex2_2_axis_misalignment": turn.axis_misalignment,
        "ex2_2_rotvec_misalignment": turn.rotvec_misalignment,
        "ex2_2_angle_deg": turn.angle_deg,
        "ex2_2_angle_from_trace_deg": turn.angle_from_trace_deg,
    }


# ---- heavy_top.py


def test_reciprocal_theorem_holds_in_the_reversed_motion_and_not_in_the_forward_one():
    r = heavy_top.reciprocal(TOP, 6.0, np.radians(60.0))
    assert r.d_psi_reversed == pytest.approx(r.d_theta, rel=1e-6)
    assert r.relative_difference < 1e-6 < 1e-2 < r.unreversed_relative_difference
    assert r.energy_check < 1e-11  # energy conserved by the Euler-angle run


def test_a_top_released_at_rest_descends_to_the_root_of_its_turning_point_quadratic():
    d = heavy_top.descent(TOP, 1e-12)
    alpha = np.radians(60.0)
    # released at rest at alpha: Jz = J3 cos alpha, E = J3^2/2C + Mgh cos alpha; theta' = 0 again where
    # 2 A Mgh u^2 - J3^2 u + J3^2 cos alpha - 2 A Mgh = 0 (u = cos theta != cos alpha), by numpy's roots
    for s in np.geomspace(1e-2, 1e-4, 5):
        J3sq = TOP.A * TOP.Mgh / s
        u = np.roots([2 * TOP.A * TOP.Mgh, -J3sq, J3sq * np.cos(alpha) - 2 * TOP.A * TOP.Mgh])
        u = u[np.abs(u) <= 1][0]
        assert np.arccos(u) - alpha == pytest.approx(2 * s * np.sin(alpha), rel=5 * s)  # Lamb Ex. XI.8
    assert np.max(np.abs(d.frame.descent / d.frame.exact - 1)) < 1e-7
    # Lamb's 2 A Mgh sin(alpha)/(C n)^2 is the first term: the rest falls like (C n)^-2, slope -2 in n
    assert d.slope == pytest.approx(-2.0, abs=0.05)


def test_the_sleeping_top_is_stable_above_four_A_Mgh_and_falls_below():
    s = heavy_top.sleeping(TOP, 1e-12, True)
    nu2 = 1.01 * 4 * TOP.A * TOP.Mgh
    bound = 1e-4 * np.sqrt(nu2) / np.sqrt(nu2 - 4 * TOP.A * TOP.Mgh)  # the linearised bound, here sqrt(101)
    assert s.above_linear_bound == pytest.approx(bound, rel=1e-12)
    assert s.above_largest_tilt == pytest.approx(bound, rel=1e-3)
    assert np.degrees(s.below_largest_tilt) > 10.0
    # the small-tilt frequencies at nu^2 = 16 A Mgh: A s^2 - nu s + Mgh = 0, s = 2 -+ sqrt 3
    assert s.upright_sigma_fitted.tolist() == pytest.approx([2 - np.sqrt(3), 2 + np.sqrt(3)], rel=1e-7)
    results = Results("solvers", "heavy_top", "t")
    heavy_top._record_sleeping(results, s)
    assert values(results)["upright_ellipse_period"] == pytest.approx(4 * np.pi / (2 * np.sqrt(3)), rel=1e-7)
    # the axis revolves at the mean of the two, nu/2A (Lamb Art. 58), nu = 4 sqrt(A Mgh) here
    nu = 4 * np.sqrt(TOP.A * TOP.Mgh)
    assert values(results)["upright_revolving_rate"] == pytest.approx(nu / (2 * TOP.A), rel=1e-7)
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert [c["holds"] for c in results.stability] == [True, True]


def test_the_tops_work_precision_errors_are_those_of_scipys_dop853_against_jacobis_solution():
    numerics = {"methods": ["dop853", "scipy:DOP853"], "tolerances": [1e-6, 1e-8, 1e-12], "repeats": 1}
    timed = heavy_top.work_precision(TOP, 6.0, np.radians(60.0), numerics, True)
    results = Results("solvers", "heavy_top", "t")
    heavy_top._record_work_precision(results, timed)
    frame = results.tables["top_accuracy"][0]
    assert sorted(set(frame.rtol)) == [1e-8, 1e-6]  # quick: nothing below 1e-9
    a, b = (frame[frame.method == m].reset_index() for m in ("dop853", "scipy:DOP853"))
    assert np.allclose(a.error, b.error, rtol=1e-4) and list(a.steps) == list(b.steps)
    assert a.error[1] < a.error[0] and (frame.drift < 100 * frame.rtol).all()
    # the error is against cos theta(t): checked here against scipy's own tight run of the same top
    y0 = heavy_top._general_start(TOP, 6.0, np.radians(60.0))
    nut = top_model.Nutation.from_integrals(TOP.A, TOP.C, TOP.Mgh, *(float(v[0]) for v in TOP.integrals(y0)))
    t = np.linspace(0.0, 20 * nut.period, 100)

    def rhs(t, y):
        out = np.empty(9)
        TOP.rhs(t, y, TOP.params, out)
        return out

    tight = solve_ivp(rhs, t[[0, -1]], y0, "DOP853", t_eval=t, rtol=1e-13, atol=1e-15)
    assert np.max(np.abs(tight.y[5] - nut.cos_theta(t, y0[5]))) < 1e-9
    assert values(results)["top_dop853_error_at_tightest"] == pytest.approx(a.error[1])


def test_a_heavy_top_scene_without_an_rtol_runs(monkeypatch):
    """numerics.rtol is optional in the schema: without it every part is run at a relative tolerance in
    (0, 1). The parts are replaced by recorders of their arguments: only the tolerance they get is tested."""
    got = {}
    for name in ("general", "steady", "gyroscope", "oscillation", "sleeping", "descent"):
        monkeypatch.setattr(heavy_top, name, lambda *args, _name=name: got.setdefault(_name, args))
    for name in ("roots_limits", "reciprocal", "work_precision"):
        monkeypatch.setattr(heavy_top, name, lambda *args: None)
    for name in dir(heavy_top):
        if name.startswith("_record_"):
            monkeypatch.setattr(heavy_top, name, lambda *args: None)
    data = {
        "top": {"A": 1.0, "C": 0.5, "spin": 6.0, "inclination_deg": 60.0},
        "effects": {"gravity": {"Mgh": 1.0}},
    }
    heavy_top.run(scene(**data), Results("solvers", "heavy_top", "t"), True)
    rtols = [got["general"][4], got["steady"][2], got["gyroscope"][1]]
    rtols += [got["oscillation"][1], got["sleeping"][1], got["descent"][1]]
    assert all(isinstance(r, float) and 0.0 < r < 1.0 for r in rtols)


def test_the_sleeping_tops_bound_says_its_formula():
    """The linear bound's note gives the formula it is: theta0 nu / sqrt(nu^2 - 4 A Mgh) (Lamb Art. 79)."""
    values = heavy_top.Sleeping(
        1e-4, 100, 1e-3, 1e-3, 0.5, 0.5, np.array([1.0, 2.0]), np.array([1.0, 2.0]), 1.0
    )
    results = Results("solvers", "heavy_top", "t")
    heavy_top._record_sleeping(results, values)
    note = results.numbers["sleeping_above_linear_bound"].get("note", "")
    assert "theta0" in note and "nu^2 - 4AMgh" in note


def test_the_work_precision_table_counts_each_methods_own_steps():
    """DOPRI5 (order 5) takes more steps than DOP853 (order 8) to the same rtol on the same top (HNW vol. I,
    II.10): each row's steps are its own method's."""
    numerics = {"methods": ["dop853", "dopri5"], "tolerances": [1e-8], "repeats": 1}
    frame = heavy_top.work_precision(TOP, 6.0, np.radians(60.0), numerics, True).set_index("method")
    assert frame.steps["dopri5"] > 2 * frame.steps["dop853"]


def test_the_heavy_top_run_records_the_top_and_every_part():
    data = {
        "top": {"A": 1.0, "C": 0.5, "spin": 6.0, "inclination_deg": 60.0, "nutations": 20},
        "effects": {"gravity": {"Mgh": 1.0}},
        "numerics": {"rtol": 1e-10, "methods": ["dop853"], "tolerances": [1e-6], "repeats": 1},
    }
    results = Results("solvers", "heavy_top", "t")
    heavy_top.run(scene(**data), results, True)
    n = values(results)
    assert (n["A"], n["C"], n["Mgh"], n["nutations"]) == (1.0, 0.5, 1.0, 2)
    assert n["integrals_max_drift"] < 1e-8  # J3, Jz, E conserved
    assert {"steady_precession", "nutation_frequency", "top_accuracy"} <= set(results.tables)


# ---- the scene check (studies/solvers/__init__.py)

HEAVY = {
    "title": "t",
    "problem": "heavy_top",
    "effects": {"gravity": {"Mgh": 1.0}},
    "top": {"A": 1.0, "C": 0.5, "spin": 6.0, "inclination_deg": 60.0},
}


@pytest.mark.parametrize(
    "change,field",
    [
        ({"problem": "inertia", "effects": {"gravity": {"Mgh": 1.0}}}, "effects"),
        ({"effects": {}}, "effects.gravity"),
        ({"top": None}, "top"),
        ({"top": {"A": 1.0, "C": 2.5, "spin": 6.0, "inclination_deg": 60.0}}, "top.C"),
        ({"top": {"A": 1.0, "C": 0.5, "spin": 0.5, "inclination_deg": 60.0}}, "top.spin"),
        ({"top": {"A": 4.0, "C": 0.1, "spin": 60.0, "inclination_deg": 60.0}}, "top.C"),
        ({"numerics": {"methods": ["splitting2"]}}, "numerics.methods"),
        ({"problem": "long_horizon", "effects": None, "top": None, "numerics": {"step": 0.1}}, "max_periods"),
        (
            {
                "problem": "long_horizon",
                "effects": None,
                "top": None,
                "numerics": {"max_periods": 5e6, "step": 0.1, "rtol": 1e-13},
            },
            "numerics.max_periods",
        ),
        (
            {"problem": "hnw_rigid_body", "effects": None, "top": None, "numerics": {"methods": ["dop853"]}},
            "tolerances",
        ),
        (
            {
                "problem": "hnw_rigid_body",
                "effects": None,
                "top": None,
                "numerics": {"methods": ["splitting4"], "tolerances": [1e-6, 1e-8]},
            },
            "numerics.steps",
        ),
    ],
)
def test_a_solver_scene_that_cannot_run_is_refused_naming_its_field(tmp_path, change, field):
    data = {k: v for k, v in {**HEAVY, **change}.items() if v is not None}
    assert_refused(tmp_path, "solvers", data, field)


# ---- the dispatch of a scene and its cost (studies/solvers/__init__.py, cost.py)


def test_a_scene_runs_the_part_its_problem_names():
    solvers = importlib.import_module("classical_dynamics.studies.solvers")
    inertia_scene = SimpleNamespace(name="inertia", title="t", data={"problem": "inertia"})
    results = solvers.run(inertia_scene, quick=True)
    assert results.scene == "inertia" and values(results)["sphere"] == pytest.approx(2 / 5, rel=1e-12)
    numerics = {"max_periods": 100, "step": 0.1, "rtol": 1e-6}
    long = solvers.run(
        SimpleNamespace(name="lh", title="t", data={"problem": "long_horizon", "numerics": numerics})
    )
    assert values(long)["splitting2_casimir_error_at_max"] < 1e-12  # the Casimir kept by exact rotations


def test_the_cost_models_steady_roots_solve_lambs_quadratic_and_the_period_is_the_quadrature():
    cost = importlib.import_module(
        "classical_dynamics.studies.solvers.cost"
    )  # the package's `cost` is a function
    A, C, Mgh, spin, alpha = 1.0, 0.5, 1.0, 6.0, np.radians(60.0)
    for root in cost.steady_roots(A, C * spin, Mgh, alpha):  # A w^2 cos a - J3 w + Mgh = 0
        assert A * root**2 * np.cos(alpha) - C * spin * root + Mgh == pytest.approx(0.0, abs=1e-12)
    assert (
        cost.steady_roots(A, 0.1, Mgh, alpha) is None
        and cost.nutation_period(A, C, Mgh, 0.1, alpha) == np.inf
    )
    # heavy_top._general's start: theta' = 0 at alpha, phi' = 0.3 of the slow root. With u = cos theta,
    # u'^2 = f(u) = 2 (E' - Mgh u)(1 - u^2)/A - (Jz - J3 u)^2/A^2 = (2 Mgh/A)(u - u2)(u1 - u)(u3 - u): the
    # period 2 * integral of du/sqrt(f) between the roots, by quad with u = mid + half sin s (no singularity)
    J3, rate = C * spin, 0.3 * cost.steady_roots(A, C * spin, Mgh, alpha)[0]
    s, c = np.sin(alpha), np.cos(alpha)
    Jz, E1 = A * rate * s * s + J3 * c, 0.5 * A * (rate * s) ** 2 + Mgh * c
    f = (
        np.polynomial.Polynomial([2 * E1 / A, -2 * Mgh / A, -2 * E1 / A, 2 * Mgh / A])
        - np.polynomial.Polynomial([Jz, -J3]) ** 2 / A**2
    )
    roots = np.sort(f.roots().real)
    u2, u1, u3 = roots
    mid, half = (u1 + u2) / 2, (u1 - u2) / 2
    period = (
        2 * quad(lambda t: 1 / np.sqrt(2 * Mgh / A * (u3 - mid - half * np.sin(t))), -np.pi / 2, np.pi / 2)[0]
    )
    assert cost.nutation_period(A, C, Mgh, spin, alpha) == pytest.approx(period, rel=1e-10)
    # the estimate scales as its model says: nutations linearly, nodes as n^3, DOP853 steps as rtol^(-1/8)
    data = {"problem": "heavy_top", "top": {"A": A, "C": C, "spin": spin, "inclination_deg": 60.0}}

    def seconds(d, field):
        return next(w.seconds for w in cost.cost(d) if w.field == field)

    twice = {**data, "top": {**data["top"], "nutations": 400}}
    assert seconds(twice, "top.nutations") == pytest.approx(2 * seconds(data, "top.nutations"), rel=1e-12)
    nodes = [seconds({"problem": "inertia", "numerics": {"nodes": n}}, "numerics.nodes") for n in (10, 20)]
    assert nodes[1] == pytest.approx(8 * nodes[0])
    rtols = [
        seconds({"problem": "long_horizon", "numerics": {"rtol": r}}, "numerics.rtol") for r in (1e-6, 1e-14)
    ]
    assert rtols[1] / rtols[0] == pytest.approx(10.0, rel=1e-12)
    sweep = cost.cost(
        {
            "problem": "hnw_rigid_body",
            "numerics": {
                "methods": ["dop853", "splitting2", "RK99"],
                "tolerances": [1e-6],
                "steps": [0.1, 0.05],
            },
        }
    )
    split = next(w for w in sweep if w.field == "numerics.steps")
    assert "600 splitting steps" in split.what  # 20/0.1 + 20/0.05
    assert cost.cost({"problem": "hard_cases"})[0].seconds > 0


def test_a_heavy_top_scaled_in_every_moment_and_its_weight_costs_what_it_did():
    """A, C and Mgh multiplied by one factor give the same equations of motion (A w' and Mgh scale alike), so
    the same runs and the same estimate, part by part; a top not so scaled does not."""
    cost = importlib.import_module("classical_dynamics.studies.solvers.cost")

    def parts(A, C, Mgh):
        top = {"A": A, "C": C, "spin": 6.0, "inclination_deg": 60.0, "nutations": 50}
        data = {"problem": "heavy_top", "top": top, "effects": {"gravity": {"Mgh": Mgh}}}
        return {w.field: (w.seconds, w.memory_mb) for w in cost.cost(data)}

    shipped = parts(1.0, 0.5, 1.0)
    for factor in (0.25, 7.0):
        scaled = parts(factor, 0.5 * factor, factor)
        assert scaled.keys() == shipped.keys()
        for field, (seconds, memory_mb) in shipped.items():
            assert scaled[field] == pytest.approx((seconds, memory_mb), rel=1e-12), field
    assert parts(7.0, 3.5, 1.0)["top.C"] != pytest.approx(shipped["top.C"], rel=1e-3)


def test_an_adaptive_methods_steps_grow_as_rtol_to_the_minus_one_over_its_order():
    """cost.adaptive_steps's model: an order-p method's steps over a span grow as rtol^(-1/p) (its error
    over the span ~ n h^(p+1) ~ span h^p), linearly with the span; DOP853 is order 8, dopri5 order 5."""
    cost = importlib.import_module("classical_dynamics.studies.solvers.cost")
    for method, order in (("dop853", 8), ("dopri5", 5), ("scipy:RK23", 3)):
        ratio = cost.adaptive_steps(method, 1e-12, 20.0) / cost.adaptive_steps(method, 1e-6, 20.0)
        assert ratio == pytest.approx(1e6 ** (1 / order), rel=1e-12)
        assert cost.adaptive_steps(method, 1e-9, 40.0) == pytest.approx(
            2 * cost.adaptive_steps(method, 1e-9, 20.0), rel=1e-14
        )


def test_the_long_horizons_splitting_steps_scale_as_one_over_the_step():
    """Halving numerics.step doubles the splitting's steps and their seconds (span/h steps)."""
    cost = importlib.import_module("classical_dynamics.studies.solvers.cost")

    def work(h):
        data = {"problem": "long_horizon", "numerics": {"max_periods": 1000, "step": h, "rtol": 1e-8}}
        return next(w for w in cost.cost(data) if w.field == "numerics.step")

    assert work(0.025).seconds == pytest.approx(2 * work(0.05).seconds, rel=1e-12)


def test_the_heavy_tops_fixed_checks_are_estimated_above_the_steps_they_take(monkeypatch):
    """cost.py estimates above, not below: its count of the fixed checks' DOP853 steps (gyroscope,
    disturbed precessions, sleeping top, descent; the reciprocal runs are scipy's, priced apart) is not below
    the steps those runs take on the shipped top at its rtol 1e-12, counted here from each solution."""
    cost = importlib.import_module("classical_dynamics.studies.solvers.cost")
    steps, run = [], heavy_top._run

    def counted(*args, **kw):
        sol = run(*args, **kw)
        steps.append(sol.n_steps)
        return sol

    monkeypatch.setattr(heavy_top, "_run", counted)
    heavy_top.gyroscope(TOP, 1e-12)
    heavy_top.oscillation(TOP, 1e-12)
    heavy_top.sleeping(TOP, 1e-12, False)
    heavy_top.descent(TOP, 1e-12)
    data = {"problem": "heavy_top", "top": {"A": 1.0, "C": 0.5, "spin": 6.0, "inclination_deg": 60.0}}
    what = next(w.what for w in cost.cost(data) if w.field == "top.C")
    assert float(what.split()[0]) >= sum(steps) > 0


def test_the_blow_up_times_the_claims_call_evaluated_are_lees_integral():
    """The four blow-up times that the solvers chapter's claims take from Lee (2.4) "evaluated" are the time
    p takes to run off to infinity, ∫ dp/(m + μp²), by mpmath quadrature here (one was once typed to 8 figures
    and sat 4.6 × 10⁻⁹ off, inside its own bound)."""
    import mpmath as mp
    import yaml

    from classical_dynamics.studies import solvers

    claims = {
        c["id"]: c
        for c in yaml.safe_load((Path(solvers.__file__).parent / "claims.yaml").read_text(encoding="utf-8"))
    }
    cases = {  # claim: (m, mu, p0, direction p runs)
        "lee_blow_up_time": (0.5, -0.2, -2.0, -1),
        "lee_blow_up_time_i": (0.6, 0.3, 0.5, 1),
        "lee_blow_up_time_iii": (-0.4, 0.3, 2.0, 1),
        "lee_blow_up_time_iv": (-0.3, -0.5, 0.4, -1),
    }
    with mp.workdps(30):
        for name, (m, mu, p0, direction) in cases.items():
            rate = lambda p: 1 / (m + mu * p**2)  # noqa: E731
            t_star = mp.quad(rate, [p0, mp.inf]) if direction > 0 else -mp.quad(rate, [-mp.inf, p0])
            assert abs(claims[name]["source"]["value"] - float(t_star)) < 1e-14, name


def test_an_apparent_q_is_negative_where_the_method_pumps_energy_in():
    """Q = -2 pi n/(dE/E): a loss of 2 pi 10⁻⁶ in one period reads as Q = 10⁶, a gain as -10⁶, the sign the
    Chandler wobble's table gives its amplitude's change; no change at all is an infinite Q."""
    from classical_dynamics.studies.solvers.hard_cases import _apparent_q

    assert _apparent_q(-2 * math.pi * 1e-6, 1) == pytest.approx(1e6)
    assert _apparent_q(2 * math.pi * 1e-6, 1) == pytest.approx(-1e6)
    assert _apparent_q(0.0, 100) == math.inf


def test_the_general_top_starts_at_rest_in_theta_and_at_three_tenths_of_the_slow_steady_rate():
    """heavy_top.general's start: theta = alpha, theta' = 0 and phi' = 0.3 of the slower root of Lamb's
    A w^2 cos(alpha) - C n w + Mgh = 0 (numpy's roots here); phi' read off the state itself: with theta' = 0,
    omega's part across the axis is phi' times the vertical's, so phi' = (w1 g1 + w2 g2)/sin^2(alpha)."""
    A, C, Mgh, n, alpha = 1.0, 0.5, 1.0, 6.0, np.radians(60.0)
    y = heavy_top._general_start(top_model.Top(A, C, Mgh), n, alpha)
    w, g = y[:3], y[3:6]
    slow = min(np.roots([A * np.cos(alpha), -C * n, Mgh]).real)
    assert g[2] == pytest.approx(np.cos(alpha), rel=1e-14) and w[2] == pytest.approx(n, rel=1e-14)
    assert (w[0] * g[0] + w[1] * g[1]) / np.sin(alpha) ** 2 == pytest.approx(0.3 * slow, rel=1e-12)
    assert w[0] * g[1] - w[1] * g[0] == pytest.approx(
        0.0, abs=1e-14
    )  # no theta': omega's cross part along g's
