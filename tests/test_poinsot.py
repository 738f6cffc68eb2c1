"""Poinsot's kinematics (chandler/poinsot.py) and Lamb's inertia examples (precession/examples.py)."""

import numpy as np
import pytest
import yaml
from scipy.integrate import solve_ivp

from classical_dynamics.models import earth, wobble
from classical_dynamics.results import Results
from classical_dynamics.scenes import SceneError
from classical_dynamics.studies import validate
from classical_dynamics.studies.chandler import poinsot
from classical_dynamics.studies.precession import examples

from .conftest import ROOT, values


class Recorder:
    def __init__(self):
        self.numbers, self.hard = {}, {}

    def number(self, name, value, unit, note=None, **kw):
        self.numbers[name] = value

    def hard_case(self, name, description, measured, bound, unit=""):
        self.hard[name] = (measured, bound)

    def figure(self, name, fig, caption):
        self.figures = {**getattr(self, "figures", {}), name: caption}


def test_attitude_turns_the_body_the_right_way():
    """A spin about the body's z axis at rate 1: after time t the body's x axis points at (cos t, sin t,
    0)."""
    t, w, q = poinsot._integrate([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 1.3, 3)
    x = poinsot._to_space(q, np.tile([1.0, 0.0, 0.0], (3, 1)))
    assert x[-1] == pytest.approx([np.cos(1.3), np.sin(1.3), 0.0], abs=1e-12)


def _scipy_radius_extremes(I, w0, span=60.0):
    """The herpolhode's radius from omega alone, by scipy's DOP853: |x|^2 - (2T/H^2), x = omega/sqrt(2T)."""
    I = np.asarray(I, float)
    f = lambda t, w: [
        (I[1] - I[2]) / I[0] * w[1] * w[2],
        (I[2] - I[0]) / I[1] * w[2] * w[0],
        (I[0] - I[1]) / I[2] * w[0] * w[1],
    ]
    sol = solve_ivp(
        f, (0, span), w0, method="DOP853", rtol=1e-12, atol=1e-14, t_eval=np.linspace(0, span, 60001)
    )
    w = sol.y.T
    T2, H2 = np.sum(I * w0**2), np.sum((I * w0) ** 2)
    rho = np.sqrt(np.sum(w**2, axis=1) / T2 - T2 / H2)
    return rho.min(), rho.max()


@pytest.mark.parametrize("w0", [[1.0, 0.3, 1.0], [1.0, 0.2, 0.3]])  # about the greatest, the least axis
def test_herpolhode_circles_closed_form_against_scipy(w0):
    I = [1.0, 2.0, 2.5]
    lo, hi = poinsot.herpolhode_radii(I, w0)
    slo, shi = _scipy_radius_extremes(I, np.asarray(w0))
    assert lo < hi
    assert lo == pytest.approx(slo, rel=1e-6) and hi == pytest.approx(shi, rel=1e-6)


def test_symmetric_body_herpolhode_is_a_circle():
    lo, hi = poinsot.herpolhode_radii([1.0, 1.0, 2.0], [0.3, 0.1, 1.0])
    assert lo == pytest.approx(hi, rel=1e-12)


def test_poinsot_body_numbers():
    body = poinsot.poinsot_body([1.0, 2.0, 2.5], [1.0, 0.3, 1.0], 40.0, 40001)
    plane = poinsot.conjugate_plane(body.moments)
    triangle = poinsot.triangle_inequality()
    cone = poinsot.invariable_cone(body.moments)
    # Why these are checks: the plane, the herpolhode's bounds and the rolling are measured on the motion
    # integrated from Euler's equations and quaternion kinematics, which compute none of them; the plane is
    # Lamb Art. 46's theorem, the bounds are herpolhode_radii (against scipy above), the arcs Art. 47's
    # rolling without slipping. The curvature ratio and half periods show the run is not trivial.
    assert body.half_periods >= 4
    assert body.plane_error < 1e-10
    assert body.herpolhode_bounds_error < 1e-8
    assert body.herpolhode_curvature_ratio > 0.1
    assert body.rolling_arc_difference < 1e-5
    assert plane.midplane_error < 1e-13
    assert plane.momentum_parallel_only_on_axes == 1 and cone.sympy_checks == 1
    assert 0 <= triangle.least_margin < 1e-3  # flat bodies come near the bound, none beyond it
    assert triangle.hnw_margin < 0
    assert cone.planes_residual < 1e-9
    r = Recorder()
    poinsot.record_poinsot_body(r, body, "test")
    assert r.numbers["poinsot_plane_error"] == body.plane_error
    assert r.hard["poinsot_plane_fixed"] == (body.plane_error, 1e-11)
    assert "herpolhode" in r.figures and "$" in r.figures["herpolhode"]
    # the count of half periods says whose sign changes it counts: the body component p of omega
    results = Results("chandler", "x", "x")
    poinsot.record_poinsot_body(results, body, "test")
    assert "$p$" in results.numbers["poinsot_half_periods"]["note"]


def test_cone_rates_signs_and_forms():
    """On the oblate Earth the plane ZOC turns prograde once a day; Euler's chi' is negative (J runs prograde
    in the body); both agree with Lamb Art. 47 (3)."""
    model = wobble.assemble(earth.H_MHB2000, {})
    rates = poinsot.cone_rates(model, 0.1 * earth.ARCSEC)
    assert rates.psi_dot_measured > 0 > rates.chi_dot_measured
    assert rates.cone_rates_error < 1e-10
    # the forms above are evaluated on the run's own angles; Lamb Art. 47 for the symmetric body, closed form
    # from H alone (A/C = 1 - H, C = 1, omega0 = n (0.1", 0, 1), n one turn a sidereal day):
    # psi' = |L|/A, chi' = -(C - A) r/A
    a, spin = 1.0 - earth.H_MHB2000, 2 * np.pi / earth.sidereal_to_solar_days(1.0)
    L = spin * np.hypot(a * 0.1 * earth.ARCSEC, 1.0)
    assert rates.psi_dot_measured == pytest.approx(L / a, rel=1e-10)
    assert rates.chi_dot_measured == pytest.approx(-(1.0 - a) * spin / a, rel=1e-10)
    assert rates.no_slip_cones_ratio == pytest.approx(1.0, rel=1e-10)
    r = Recorder()
    poinsot.record_cone_rates(r, rates)
    assert r.numbers["psi_dot_closed_form"] == pytest.approx(L / a, rel=1e-10)
    assert r.numbers["chi_dot_closed_form"] == pytest.approx(-(1.0 - a) * spin / a, rel=1e-10)


def _scene(tmp_path, moments):
    data = yaml.safe_load((ROOT / "workflow" / "scenes" / "chandler" / "triaxial.yaml").read_text())
    data["analysis"]["poinsot"]["moments"] = moments
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True))
    return path


@pytest.mark.parametrize("moments,expected", [([0.5, 2.0, 3.0], "C ≤ A + B"), ([2.0, 1.0, 2.5], "A < B < C")])
def test_unphysical_poinsot_body_refused(tmp_path, moments, expected):
    path = _scene(tmp_path, moments)
    with pytest.raises(SceneError) as error:
        validate("chandler", path)
    assert "analysis.poinsot.moments" in str(error.value) and expected in str(error.value)


def test_sphere_has_no_couple():
    """A uniform sphere attracts as a point: no couple about its centre (quadrature)."""
    N = examples._spheroid_couple(1.0, 1.0, 10.0, [0.5, 0.0, np.sqrt(0.75)])
    assert np.linalg.norm(N) < 1e-14


def test_least_axis_follows_the_least_moment():
    v = examples.least_axis_stable([3.0, 1.0, 2.0], start_offset_rad=1e-3, span=100.0)
    assert v.stable == 2 and v.on_least_axis == 1
    assert v.growth_least < 1.5 < 100 < v.growth_others
    r = Recorder()
    examples._record_least_axis_stable(r, v)
    assert r.numbers["stable_equilibria"] == 2 and r.numbers["libration_growth_others"] == v.growth_others


def test_inertia_examples():
    helix = examples.whirling_helix(60, [0.1, 0.05, 0.02])
    added = examples.added_mass([1.0, 2.0, 3.0], seed=3, epsilons=[1e-2, 1e-3, 1e-4])
    assert helix.sympy_holds == 1 and examples.uniaxal_products() == 1
    assert helix.order == pytest.approx(2.0, abs=0.02)
    assert added.moment_order == pytest.approx(2.0, abs=0.05)
    assert added.axis_order == pytest.approx(2.0, abs=0.05)
    r = Recorder()
    examples._record_whirling_helix(r, helix)
    examples._record_added_mass(r, added)
    assert (
        r.numbers["helix_bead_order"] == helix.order
        and r.numbers["added_mass_axis_order"] == added.axis_order
    )


def test_the_herpolhode_curvature_takes_omega_double_dot_from_the_motion():
    """_curvature forms omega'' by differentiating Euler's equations; here omega'' is a central difference of
    omega' along a solve_ivp run (omega' from Euler's equations, the physics itself): the curvatures agree."""
    I = np.array([1.0, 2.0, 3.0])
    A, B, C = I

    def euler(t, w):
        return [(B - C) / A * w[1] * w[2], (C - A) / B * w[2] * w[0], (A - B) / C * w[0] * w[1]]

    run = solve_ivp(
        euler, (0.0, 8.0), [1.0, 0.3, 0.5], method="DOP853", rtol=1e-13, atol=1e-13, dense_output=True
    )
    t, h = np.linspace(0.5, 7.5, 41), 1e-4
    w = run.sol(t).T
    wd = np.array(euler(0.0, w.T)).T
    wdd = (np.array(euler(0.0, run.sol(t + h))).T - np.array(euler(0.0, run.sol(t - h))).T) / (2 * h)
    L_hat = w * I / np.linalg.norm(w * I, axis=1)[:, None]
    acc = np.cross(w, wd) + wdd  # the space acceleration R(omega x omega' + omega''), in the body frame
    expected = np.einsum("ij,ij->i", L_hat, np.cross(wd, acc)) / np.linalg.norm(wd, axis=1) ** 3
    assert np.ptp(expected) > 0.1 * np.max(np.abs(expected))  # a curve whose curvature changes along it
    assert poinsot._curvature(I, w) == pytest.approx(expected, rel=1e-6, abs=1e-9 * np.max(np.abs(expected)))


def test_a_scene_asking_for_poinsot_gets_each_of_its_records(tmp_path):
    """The study's dispatcher (chandler._poinsot) reads analysis.poinsot and records the body's run with the
    scene's own moments, the conjugate plane, the triangle inequality and the invariable cone; a scene
    without it gets none of them."""
    import classical_dynamics.studies.chandler as study

    data = yaml.safe_load((ROOT / "workflow" / "scenes" / "chandler" / "triaxial.yaml").read_text())
    data["analysis"] = {
        "poinsot": {**data["analysis"]["poinsot"], "moments": [1.0, 1.5, 2.0], "samples": 2001}
    }
    path = tmp_path / "poinsot_only.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True))
    results = Results("chandler", "t", "t")
    study._poinsot(validate("chandler", path), results)
    got = values(results)
    assert [got["poinsot_A"], got["poinsot_B"], got["poinsot_C"]] == [1.0, 1.5, 2.0]
    assert got["poinsot_plane_distance_error"] < 1e-8  # the plane stays put: the run is the body's
    for name in ("conjugate_midplane_error", "triangle_least_margin", "invariable_cone_sympy"):
        assert name in got
    del data["analysis"]
    path.write_text(yaml.safe_dump(data, allow_unicode=True))
    none = Results("chandler", "t", "t")
    study._poinsot(validate("chandler", path), none)
    assert not none.numbers
