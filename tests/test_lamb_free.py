"""Lamb's free body (Arts. 48-55, Examples X, XIII.11), the notes' free precession, and Art. 61's
identities."""

import numpy as np
import pytest
import yaml

from classical_dynamics.results import Results
from classical_dynamics.scenes import SceneError
from classical_dynamics.studies import validate
from classical_dynamics.studies.chandler import lamb_free as lf

from .conftest import ROOT, values

I = np.array([1.0, 2.0, 2.5])


class Numbers:
    def __init__(self):
        self.numbers = {}

    def number(self, name, value, unit, **kw):
        self.numbers[name] = value


def test_every_symbolic_statement_is_an_identity():
    assert lf.symbolic_residuals() == dict.fromkeys(lf.symbolic_residuals(), 0)


def test_a_wrong_formula_is_not_an_identity():
    """The sympy check can fail: Ex. X.4 with the wrong sign of 2T/H^2 leaves a residual."""
    import sympy as sp

    A, B, C, p, q, r = lf.A_, lf.B_, lf.C_, lf.p_, lf.q_, lf.r_
    H2 = A**2 * p**2 + B**2 * q**2 + C**2 * r**2
    n = sp.Matrix([A * p, B * q, C * r]) / sp.sqrt(H2)
    total = sum((1 - n[i] ** 2) / (A, B, C)[i] for i in range(3))
    wrong = 1 / A + 1 / B + 1 / C + (A * p**2 + B * q**2 + C * r**2) / H2
    assert sp.simplify(total - wrong) != 0


def test_polhode_period_against_the_integration_both_sides_of_the_separatrix():
    """4K(k)/lambda: one period returns omega to its start, about either axis, and near the separatrix."""
    for w0 in ([0.9, 0.3, 0.2], [0.2, 0.3, 0.9], [0.6, 0.5, 0.6 * np.sqrt(1.0 / 2.5) + 1e-4]):
        w0 = np.array(w0)
        period, k2 = lf.polhode_period(I, w0)
        assert 0.0 < k2 < 1.0
        _, w, _ = lf.integrate(I, w0, period, samples=3)
        assert np.max(np.abs(w[-1] - w0)) < 1e-8
        _, w, _ = lf.integrate(I, w0, 0.5 * period, samples=3)
        assert np.max(np.abs(w[-1] - w0)) > 1e-3


def test_criterion_10_agrees_with_the_integration_even_near_the_separatrix():
    side = lf.polhode_side(I, 300, 7)
    assert side.samples == 300 and side.agreements == 300
    assert 0 < side.round_least < 300


def test_poinsot_geometry_holds_and_moves():
    examples = lf.poinsot_examples(I)
    n = examples._asdict()
    # Each is measured on the attitude integrated from Euler's equations (which know nothing of sections,
    # gyration ellipsoids or planes) against Lamb's closed form of Exx. X.1, X.4, X.5, X.22 written from
    # A, B, C, T and H alone: a fault in the integration or in either formula breaks the agreement, and the
    # ranges below show the motion is not a fixed point on which any formula would hold.
    for name in (
        "section_area_max_relative_deviation",
        "poinsot_sum_max_relative_deviation",
        "gyration_normal_angle_rad",
        "gyration_perpendicular_times_omega_drift",
        "plane_rate_max_relative_deviation",
    ):
        assert n[name] < 1e-11, name
    assert n["gyration_omega_range"] > 0.01 and n["plane_rate_range"] > 0.05  # the motion is not trivial
    out = Results("chandler", "t", "t")  # the real record: a value lost to None is refused where written
    lf._record_poinsot(out, examples)
    assert (
        out.numbers["gyration_normal_angle_rad"]["value"] < 1e-11
    )  # Ex. X.5: the normal there is along omega
    recorded = {k: v["value"] for k, v in out.numbers.items()}
    assert recorded.pop("poinsot_modulus_squared") == n["modulus_squared"] and 0 < n["modulus_squared"] < 1
    assert recorded == {k: n[k] for k in recorded}  # every other number under its own name
    # the differenced azimuth agrees to the differences' own error (second order in the step)
    assert n["plane_rate_differences_max_relative_deviation"] < 1e-4


def test_plate_turns_to_the_other_diagonal_after_half_a_period():
    a, b = 3.0, 1.0
    plate = lf.plate(a, b)
    assert abs(plate.other_diagonal_time / plate.half_period_closed_form - 1.0) < 1e-10
    assert plate.angle_from_other_diagonal_rad < 1e-10
    # The two numbers above compare the module's integration with the module's closed form, both from the
    # module's moments: a wrong plate would pass. So the half period again, from the rectangle's moments
    # M(2b)^2/12, M(2a)^2/12 and their sum (perpendicular axes), and Landau & Lifshitz §37 (L^2 < 2E I2):
    # omega_3 ~ sn(lambda t, k), zero again at 2K(k)/lambda.
    from scipy.special import ellipk

    I1, I2, I3 = b * b / 3, a * a / 3, (a * a + b * b) / 3
    w = np.array([a, b]) / np.hypot(a, b)
    E2, L2 = I1 * w[0] ** 2 + I2 * w[1] ** 2, (I1 * w[0]) ** 2 + (I2 * w[1]) ** 2
    lam = np.sqrt((I2 - I1) * (E2 * I3 - L2) / (I1 * I2 * I3))
    k2 = (I3 - I2) * (L2 - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2))
    assert plate.modulus_squared == pytest.approx(k2, rel=1e-12)
    assert plate.other_diagonal_time == pytest.approx(2 * ellipk(k2) / lam, rel=1e-10)
    # and the record writes those values under the names the report reads
    out = Numbers()
    lf._record_plate(out, plate)
    assert (
        out.numbers["plate_time_relative_error"]
        == plate.other_diagonal_time / plate.half_period_closed_form - 1
    )
    assert out.numbers["plate_other_diagonal_time"] == plate.other_diagonal_time


def test_constraining_couples_are_lambs_on_the_phase_average_only():
    couples = lf.constraining_couples(I, 50.0)
    assert couples.in_plane_deviation < 1e-10 and couples.perpendicular_deviation < 1e-12
    # over one turn from a given phase: near 2B/(A + B) and 2A/(A + B), not 1
    assert couples.one_turn_ratio["0"] == pytest.approx(2 * I[1] / (I[0] + I[1]), rel=1e-2)
    assert couples.one_turn_ratio["90"] == pytest.approx(2 * I[0] / (I[0] + I[1]), rel=1e-2)
    out = Numbers()
    lf._record_constraining_couples(out, couples)
    assert out.numbers["constraining_one_turn_ratio_chi0_90"] == couples.one_turn_ratio["90"]
    # a body symmetric about OC has no phase to average: one turn gives (A + B) v'/2 already
    symmetric = lf.constraining_couples(np.array([2.0, 2.0, 2.5]), 50.0)
    assert symmetric.one_turn_ratio["0"] == pytest.approx(1.0, rel=1e-2)


@pytest.mark.parametrize("moments, prograde", [((0.9, 0.9, 1.0), True), ((1.0, 1.0, 0.5), False)])
def test_notes_body_frequency_turns_at_minus_omega_b(moments, prograde):
    """Oblate: the pole turns with the spin; prolate: against it. Either way at -Omega_b, Omega_b = (I1 -
    I3)w3/I1."""
    Ib = np.array(moments)
    w3 = 1.0
    t, w, _ = lf.integrate(Ib, np.array([0.05, 0.0, w3]), 5.0, samples=501)
    rate = np.polyfit(t, np.unwrap(np.arctan2(w[:, 1], w[:, 0])), 1)[0]
    omega_b = (Ib[0] - Ib[2]) * w3 / Ib[0]
    assert rate / omega_b == pytest.approx(-1.0, rel=1e-9)
    assert (rate * w3 > 0) == prograde


def _scene(tmp_path, **free):
    data = yaml.safe_load((ROOT / "workflow" / "scenes" / "chandler" / "triaxial.yaml").read_text())
    data["analysis"]["lamb_free_body"].update(free)
    path = tmp_path / "scene.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True))
    return path


@pytest.mark.parametrize(
    "change, field",
    [
        ({"moments": [2.0, 1.0, 2.5]}, "lamb_free_body.moments"),
        ({"moments": [1.0, 1.2, 3.0]}, "lamb_free_body.moments"),
        ({"plate_half_sides": [1.0, 2.0]}, "lamb_free_body.plate_half_sides"),
    ],
)
def test_bad_free_body_is_refused_in_one_line(tmp_path, change, field):
    path = _scene(tmp_path, **change)
    with pytest.raises(SceneError) as error:
        validate("chandler", path)
    assert field in str(error.value) and "\n" not in str(error.value)


def test_art61_identities_and_the_torque_routine():
    from classical_dynamics.models import precession as prec
    from classical_dynamics.studies.precession import examples

    model = prec.assemble(
        0.00327,
        np.radians(23.45),
        prec.CONSTANTS["lamb1920"](),
        {"solar_torque": None, "lunar_torque": None, "lunar_inclination": None, "node_regression": None},
    )
    art61 = examples.lamb_art61(model, samples=20, seed=3)
    assert art61.solar_couple_residual == 0 and art61.triangle_residual == 0
    assert art61.mean_factor_residual == 0
    assert art61.torque_routine_deviation < 1e-14
    assert abs(art61.mean_factor_relative_deviation) < 1e-13
    assert art61.lunar_rate_over_formula == pytest.approx(1.0, rel=1e-13)
    # the record writes those values under the report's names
    out = Numbers()
    examples._record_lamb_art61(out, art61)
    assert out.numbers["solar_couple_torque_routine_deviation"] == art61.torque_routine_deviation
    assert out.numbers["lunar_rate_quadrature_over_formula"] == art61.lunar_rate_over_formula


@pytest.mark.parametrize("period_years", [17.3, 18.6, 20.1])
def test_node_period_is_fitted_not_assumed(period_years):
    """The long nutation's period is found by least squares: a synthetic obliquity series with a known period,
    a semi-annual term and a trend gives that period back, whatever it is."""
    from classical_dynamics.models import earth
    from classical_dynamics.studies.precession import full

    t = np.arange(0.0, 100.0 * earth.JULIAN_YEAR_DAYS, 1.0)
    P = period_years * earth.JULIAN_YEAR_DAYS
    semi = lambda x: 4.0 * np.pi * x / 365.2422 + 0.3
    eps = (
        1e-7 * t / t[-1]
        + 4.5e-5 * np.cos(2 * np.pi * t / P + 1.0)
        + 3e-6 * np.sin(semi(t))
        + 1e-7 * np.cos(4 * np.pi * t / P)
    )
    args = {"18.6 yr": lambda x: 2 * np.pi * x / (18.6 * 365.25), "semi-annual": semi}
    fitted, iau = full.node_period(t, eps, args)
    assert fitted == pytest.approx(period_years, rel=1e-6)
    assert iau == pytest.approx(18.613, rel=1e-4)


def test_a_free_body_needs_three_distinct_moments():
    """Lamb's free body is A < B < C: two equal moments (a symmetric body) are refused before any work."""
    spec = {"moments": [2.0, 2.0, 2.5], "samples": 10, "seed": 1, "tilt_deg": 1.0}
    with pytest.raises(ValueError, match="A < B < C"):
        lf.free_body(Numbers(), spec)


def test_the_free_body_records_every_part_of_lambs_chapter_with_its_numbers():
    """free_body with the triaxial scene's body (fewer random starts): every part recorded through a real
    Results, each checked where a closed form says what it must be: sympy's residuals 0, Art. 52's (10)
    deciding the side of every start, a modulus of Poinsot's example inside (0, 1)."""
    spec = yaml.safe_load((ROOT / "workflow/scenes/chandler/triaxial.yaml").read_text())["analysis"]
    spec = {**spec["lamb_free_body"], "samples": 200}
    results = Results("chandler", "t", "t")
    lf.free_body(results, spec)
    got = values(results)
    assert all(got[name] == 0 for name in got if name.startswith("sympy_"))
    assert got["polhode_side_agreements"] == got["polhode_side_samples"] == 200
    assert 0.0 < got["poinsot_modulus_squared"] < 1.0 and 0.0 < got["plate_modulus_squared"] < 1.0
    assert {name.split("_")[0] for name in got} >= {
        "constraining",
        "cylinder",
        "plate",
        "separatrix",
        "poinsot",
    }


def test_symmetric_earth_pole_turns_with_the_spin_at_euler_rate():
    """The rigid oblate Earth: the pole turns about the figure axis in the spin's sense at (C - A)/A n
    (Euler's free precession, Lamb Art. 50), n one turn a sidereal day; the recorded rate says its sign
    convention."""
    from classical_dynamics.models import earth, wobble
    from classical_dynamics.results import Results

    model = wobble.assemble(earth.H_MHB2000, {})
    values = lf.symmetric_earth(model, 0.1 * earth.ARCSEC, days=2.0)
    a = 1.0 - earth.H_MHB2000  # A/C
    n = 2 * np.pi / earth.sidereal_to_solar_days(1.0)
    assert values.body_rate == pytest.approx((1.0 - a) / a * n, rel=1e-6)
    results = Results("chandler", "x", "x")
    lf.record_symmetric_earth(results, values)
    note = results.numbers["body_rate_measured_rad_per_s"]["note"]
    assert "right-handed" in note and "positive" in note
