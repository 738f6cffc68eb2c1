"""Precession study, run functions on tiny configurations: each recorded number against something the study
did not compute (Lamb's closed forms written out here, pyerfa's IAU 2006 / 2000B values, scipy's solve_ivp on
the same right-hand side, published amplitudes from the reference digest, conservation laws)."""

import copy

import numpy as np
import pytest
import yaml
from scipy.integrate import solve_ivp

import classical_dynamics.studies.precession as study
from classical_dynamics.models import earth
from classical_dynamics.models import precession as prec
from classical_dynamics.results import Results
from classical_dynamics.studies import validate
from classical_dynamics.studies.precession import accuracy, averaged, examples, full, secular

from .conftest import ROOT, assert_refused

YEAR = earth.JULIAN_YEAR_DAYS
EPS0 = 84381.406 * earth.ARCSEC
ALL = ("solar_torque", "lunar_torque", "orbit_eccentricity", "lunar_inclination", "node_regression")
EARTH = {
    "H": earth.H_P03,
    "H_definition": "(C-A)/C",
    "H_source": "P03",
    "obliquity_deg": float(np.degrees(EPS0)),
    "obliquity_source": "IAU 2006",
}


def untimed(monkeypatch):
    """Wall time is not under test: each timed run once."""
    for module in (averaged, full, accuracy):
        monkeypatch.setattr(module, "min_time", lambda func, **_: (1.0, func(), 1))


def scene(tmp_path, fidelity, effects=ALL, constants="modern", **analysis):
    data = {
        "title": "t",
        "fidelity": fidelity,
        "constants": constants,
        "earth": dict(EARTH),
        "effects": {e: None for e in effects},
        "analysis": analysis,
    }
    path = tmp_path / f"{fidelity}.yaml"
    path.write_text(yaml.safe_dump(data))
    return validate("precession", path)


def value(results, name):
    return results.numbers[name]["value"]


def held(results):
    """The run's own verdicts on its hard cases (a figure it measured under a bound it states): what the
    report prints as holding, not a reference; each test's reference checks are its other assertions."""
    return {case["name"]: case["holds"] for case in results.stability}


# a name that ends in a unit carries that unit (the report prints the unit beside the number)
UNIT_OF_SUFFIX = {"_years": "yr", "_mas": "mas", "_arcsec_per_year": "″/yr", "_arcsec": "″", "_days": "d"}


def assert_units_follow_names(results):
    named = [(k, v["unit"]) for k, v in results.numbers.items()]
    named += [(c["name"], c.get("unit")) for c in results.stability]
    checked = 0
    for key, unit in named:
        suffix = next((s for s in UNIT_OF_SUFFIX if key.endswith(s)), None)
        if suffix:
            assert unit == UNIT_OF_SUFFIX[suffix], (key, unit)
            checked += 1
    assert checked, "no number named with its unit"


def psi_A_per_year():
    """IAU 2006 luni-solar precession at J2000, the linear coefficient of P03 (digest: 5038.481507"/cy)."""
    return 5038.481507 / 100.0


def solar_closed_form(eccentric=True):
    """Lamb Art. 61 (7), written out: (3/2)(GM/a^3)(1 - e'^2)^(-3/2) H cos(eps)/n, in arcsec per Julian year
    (e' = 0 for a circular orbit)."""
    o = prec.modern()
    e = o.sun_e if eccentric else 0.0
    rate = 1.5 * o.sun_gm_over_a3 * (1 - e**2) ** -1.5 * earth.H_P03 * np.cos(EPS0) / o.spin
    return rate * YEAR / earth.ARCSEC


# --- rung 2: the averaged equations, through the study's run ------------------------------------------------


def test_averaged_run_sun_only_gives_lambs_rate_and_a_constant_obliquity(tmp_path, monkeypatch):
    untimed(monkeypatch)
    s = scene(tmp_path, "averaged", ("solar_torque", "orbit_eccentricity"), span_years=3000)
    r = study.run(s)
    rate = value(r, "precession_rate_arcsec_per_year")
    assert rate == pytest.approx(solar_closed_form(), rel=1e-8)
    assert value(r, "precession_period_years") == pytest.approx(1296000.0 / solar_closed_form(), rel=1e-8)
    assert value(r, "obliquity_range_arcsec") < 1e-6  # no torque out of the cone: eps constant
    assert abs(value(r, "mean_obliquity_offset_arcsec")) < 1e-6
    assert all(held(r).values())
    assert "precession_period_by_crossing_years" not in r.numbers  # 3000 yr: no whole turn
    # the modern constants' comparison with IAU 2006, formed here from pyerfa: the Sun alone is about 1/3
    assert value(r, "rate_minus_psi_A_relative") == pytest.approx(rate / psi_A_per_year() - 1, rel=1e-6)
    assert "cone" in r.figures and "cost" in r.timing_tables
    assert_units_follow_names(r)


def test_averaged_run_over_a_whole_cycle_against_iau_and_the_first_order_nutation(tmp_path, monkeypatch):
    untimed(monkeypatch)
    r = study.run(scene(tmp_path, "averaged", ALL, span_years=26000))
    psi_A = psi_A_per_year()
    # the secular rate with the node averaged is within 0.3 % of IAU 2006's luni-solar rate (digest P8)
    assert value(r, "precession_rate_arcsec_per_year") == pytest.approx(psi_A, rel=3e-3)
    # psi reaches 360 degrees within the run: the crossing and 360 deg / rate agree (the 17" nutation
    # moves the crossing by a third of a year at most)
    by_rate = value(r, "precession_period_years")
    assert value(r, "precession_period_by_crossing_years") == pytest.approx(by_rate, abs=0.5)
    assert by_rate == pytest.approx(1296000.0 / psi_A, rel=3e-3)
    # 18.6-yr nutation: IAU 2000 amplitudes -17.2064" sin(Om), 9.2052" cos(Om) (digest); rigid: 0.5 % above
    assert value(r, "nutation_longitude_18p6yr_arcsec") == pytest.approx(17.2064, rel=1e-2)
    assert value(r, "nutation_obliquity_18p6yr_arcsec") == pytest.approx(9.2052, rel=1e-2)
    assert value(r, "nutation_ratio_18p6yr") == pytest.approx(2 / np.tan(2 * EPS0), rel=3e-3)
    # the node's regression couples to the nutation only at second order: mas per century, not arcsec
    assert abs(value(r, "second_order_lunar_mas_per_century")) < 100.0
    assert abs(value(r, "obliquity_drift_arcsec")) < 0.1
    assert all(held(r).values())


def test_averaged_run_with_a_fixed_tilted_node_against_solve_ivp(tmp_path, monkeypatch):
    """The fixed node: no fit with the periodic terms, a bare line; scipy's DOP853 on the same right-hand side
    gives the obliquity's range and the slope independently."""
    untimed(monkeypatch)
    effects = ("solar_torque", "lunar_torque", "lunar_inclination")
    span_years = 4000
    r = study.run(scene(tmp_path, "averaged", effects, span_years=span_years))
    m = prec.assemble(earth.H_P03, EPS0, prec.modern(), {e: {} for e in effects})
    p = prec.averaged_parameters(m)

    def f(t, s):
        out = np.empty(3)
        prec.averaged_rhs(t, s, p, out)
        return out

    span = span_years * YEAR
    t = np.arange(0.0, span, averaged.SAMPLE_DAYS)
    s0 = prec.initial_axis(*prec.start(m, averaged=True))
    sol = solve_ivp(f, (0.0, span), s0, method="DOP853", rtol=1e-11, atol=1e-13, t_eval=t)
    psi, eps = prec.precession_angles(sol.y.T)
    eps_arcsec = eps / earth.ARCSEC
    assert value(r, "obliquity_range_arcsec") == pytest.approx(np.ptp(eps_arcsec), rel=1e-6)
    assert value(r, "obliquity_range_arcsec") > 3600.0  # the obliquity swings by degrees
    slope = np.polyfit(t, psi, 1)[0] * YEAR / earth.ARCSEC
    assert value(r, "precession_rate_arcsec_per_year") == pytest.approx(slope, rel=1e-7)
    assert "averaged_rate_matches_formula" not in held(r)  # not claimed for a tilted orbit
    assert "nutation_ratio_18p6yr" not in r.numbers


def test_period_by_crossing_is_the_time_psi_reaches_a_turn():
    rate = 2 * np.pi / 1234.5  # a line reaches 2 pi at 1234.5 exactly; linear interpolation is exact
    t = np.arange(0.0, 2000.0, 7.0)
    assert averaged._period_by_crossing(t, rate * t) == pytest.approx(1234.5, rel=1e-12)
    assert averaged._period_by_crossing(t[:100], rate * t[:100]) is None


# --- rung 3: the spin-resolved Earth, through the study's run -----------------------------------------------


def test_full_run_over_a_few_years_against_iau_and_conservation(tmp_path, monkeypatch):
    untimed(monkeypatch)
    s = scene(
        tmp_path,
        "full",
        ("solar_torque", "lunar_torque", "orbit_eccentricity"),
        span_years=4,
        step_hours=3,
        compare_iau=True,
        aliasing_windows_years=[1.3, 2.7, 4.0],
    )
    r = study.run(s, quick=True)
    m = prec.assemble(earth.H_P03, EPS0, prec.modern(), {e: {} for e in s.data["effects"]})
    # orbits in the ecliptic: the spin-resolved rate is Lamb's secular rate, written out here
    lunar = 1.5 * m.orbits.moon_gm_over_a3 * (1 - m.orbits.moon_e**2) ** -1.5 * m.H * np.cos(EPS0) / m.n
    closed = solar_closed_form() + lunar * YEAR / earth.ARCSEC
    assert value(r, "precession_rate_arcsec_per_year") == pytest.approx(closed, rel=2e-5)
    assert value(r, "averaged_rate_arcsec_per_year") == pytest.approx(closed, rel=2e-5)
    assert value(r, "steps") == round(4 * YEAR * 8)
    assert value(r, "lamb_psi_dot_sign") == -1
    # |L| is conserved (the couple is normal to the figure axis) and the obliquity has no secular part
    assert value(r, "angular_momentum_drift") < 1e-12
    assert abs(value(r, "obliquity_rate_arcsec_per_century")) < 1e-2
    # the semi-annual term against IAU 2000B's, evaluated here with pyerfa: rigid Earth, a few % below
    iau = value(r, "iau2000b_longitude_semiannual_arcsec")
    assert 0.9 < value(r, "nutation_longitude_semiannual_arcsec") / iau < 1.0
    assert iau == pytest.approx(1.3187, rel=0.02)  # IAU 2000 semi-annual term, -1.3187" sin 2L (digest)
    assert -0.1 < value(r, "obliquity_semiannual_over_iau_minus_one") < 0.0  # in obliquity too, in ″ both
    assert value(r, "step_hours") == 3  # the scene's step, as asked
    # the forced diurnal wobble: L and the figure axis part by |N|/(C n^2), at most (3/2)(K_s + K_m)H/n^2
    bound = 1.5 * (m.orbits.sun_gm_over_a3 * 1.07 + m.orbits.moon_gm_over_a3 * 1.2) * m.H / m.n**2
    assert 0 < value(r, "figure_axis_offset_mas") < bound / earth.MAS
    # aliasing: the bare line's rate depends on the window, the line with the periodic terms does not
    assert value(r, "aliasing_spread_line_only") > 100 * value(r, "aliasing_spread_with_terms")
    assert "nutation" in r.tables and "nutation" in r.figures and "aliasing" in r.tables
    assert value(r, "span_years") == 4  # the scene's span, as asked
    # every table and figure says what it shows: a caption, not None or empty
    for kind in (r.tables, r.figures, r.timing_tables, r.timing_figures):
        for name, (_, caption, *_) in kind.items():
            assert isinstance(caption, str) and caption.strip(), name


def test_full_run_free_nutation_is_the_torque_over_n(tmp_path, monkeypatch):
    untimed(monkeypatch)
    s = scene(tmp_path, "full", ("solar_torque",), span_years=1, step_hours=3, free_nutation=True)
    r = study.run(s, quick=True)
    m = prec.assemble(earth.H_P03, EPS0, prec.modern(), {"solar_torque": {}})
    # the pole's start velocity over n, formed here from the couple of the torque routine:
    # |e3 x N|/(C n^2) with N/C the body torque at t = 0, in the start attitude
    _, q0 = prec.initial_state(m)
    torque = np.empty(3)
    prec.torque_body(0.0, q0, m.parameters(), torque)
    expected = np.hypot(torque[0], torque[1]) / m.n**2 / earth.MAS
    assert value(r, "free_wobble_expected_mas") == pytest.approx(expected, rel=1e-9)
    assert value(r, "free_wobble_axis_start_mas") == pytest.approx(expected, rel=0.05)
    assert value(r, "free_wobble_forced_start_mas") < 2 * m.orbits.sun_n / m.n * expected
    assert held(r)["forced_start"]


def test_effect_ladder_adds_one_effect_a_row(monkeypatch):
    untimed(monkeypatch)
    effects = ("solar_torque", "lunar_torque", "orbit_eccentricity", "lunar_inclination")
    m = prec.assemble(earth.H_P03, EPS0, prec.modern(), {e: {} for e in effects})
    ladder = full.effect_ladder(m, 0.125, 2, 2.0)
    frame = ladder.frame
    assert list(frame.adds) == [
        "solar_torque",
        "+ lunar_torque",
        "+ orbit_eccentricity",
        "+ lunar_inclination",
    ]
    assert frame.secular_formula[0] == pytest.approx(solar_closed_form(eccentric=False), rel=1e-12)
    # orbits in the ecliptic: each rung's fitted rate is its secular formula
    for k in range(3):
        assert frame.rate[k] == pytest.approx(frame.secular_formula[k], rel=2e-5)
    # a fixed tilted lunar orbit moves the rate by several arcsec per year, away from the node-averaged
    # formula, which does not apply to it and is not shown
    assert abs(frame.rate[3] - frame.rate[2]) > 1.0 and np.isnan(frame.secular_formula[3])
    assert frame.rate_change.sum() == pytest.approx(frame.rate[3], rel=1e-12)
    assert len(ladder.times) == 4
    # Lamb Art. 61: the Sun's couple goes as 1 - cos 2l, so the Sun alone (circular orbit) adds to psi the
    # semi-annual term of amplitude (secular rate)/(2 * 2 n_sun) = rate/(4 pi) per year, in arcsec
    assert frame.dpsi_semiannual[0] == pytest.approx(
        solar_closed_form(eccentric=False) / (4 * np.pi), rel=1e-4
    )
    # the record prints the rate change to d decimals, the largest d whose last place 10^-d is ten times the
    # fit's scatter (spread times rate) or more
    spread = 3e-5
    scatter = spread * abs(frame.rate.iloc[-1])
    r = Results("precession", "t", "t")
    full._record_effect_ladder(r, ladder, spread)
    d = value(r, "effect_ladder_rate_change_decimals")
    assert 10.0**-d >= 10 * scatter > 10.0 ** -(d + 1)
    assert value(r, "effect_ladder_rate_scatter_arcsec_per_year") == pytest.approx(scatter, rel=1e-12)
    # the caption names the effects whose change reads as zero at those decimals (below half the last place),
    # and no other (the eccentricity's 0.16″/yr reads 0.2 at one decimal: printed, not called zero)
    for spread in (3e-5, 3e-8):
        r = Results("precession", "t", "t")
        full._record_effect_ladder(r, ladder, spread)
        d = value(r, "effect_ladder_rate_change_decimals")
        caption = r.tables["effect_ladder"][1]
        for name, change in zip(frame.adds, frame.rate_change):
            shown = name.removeprefix("+ ").replace("_", " ") + ", "
            assert (shown in caption) == (abs(change) < 0.5 * 10.0**-d), (spread, name, change, d)


def test_node_period_fits_a_known_period_and_records_the_iau_nodes():
    """A synthetic obliquity with one term of period 18.0 years (40 years, daily): the free fit finds 18.0;
    the IAU node period is the published 2 pi/|dOmega/dt|, 1 296 000″ over 6 962 890.5431″/cy (IERS
    Conventions 2010, Table 5.2e's Omega), 18.613 years."""
    t = np.arange(0.0, 40 * YEAR)
    eps = EPS0 + 9.2 * earth.ARCSEC * np.cos(2 * np.pi * t / (18.0 * YEAR) + 0.3)
    values = full.node_period(t, eps, {})
    assert values.fitted == pytest.approx(18.0, rel=1e-6)
    published = 1296000.0 / 6962890.5431 * 100.0
    assert values.iau == pytest.approx(published, rel=1e-6)
    r = Results("precession", "t", "t")
    full._record_node_period(r, values)
    assert value(r, "node_period_fitted_years") == values.fitted
    assert value(r, "node_period_iau_years") == pytest.approx(published, rel=1e-6)
    assert value(r, "node_period_fitted_over_iau_minus_one") == pytest.approx(18.0 / published - 1, rel=1e-5)


# --- cost.py: what a scene costs, from its fields -----------------------------------------------------------


def test_cost_blames_the_span_for_a_long_run_and_the_step_for_a_fine_one():
    """scenes/cost.py names the field that costs most when a scene is refused: a millennium at 3-hour steps
    is too long a span, a year at 0.01-hour steps too fine a step; the run's steps are span/step (written out
    here) at the docstring's 4 us a step."""
    from classical_dynamics.studies.precession.cost import cost  # the package's `cost` is this function

    def run_work(span_years, step_hours):
        data = {"fidelity": "full", "analysis": {"span_years": span_years, "step_hours": step_hours}}
        works = cost(data)
        return next(w for w in works if w.field.startswith("analysis."))

    long = run_work(1000, 3.0)
    assert long.field == "analysis.span_years"
    assert long.seconds == pytest.approx(1000 * YEAR * 24 / 3.0 * 4e-6, rel=1e-12)
    fine = run_work(1, 0.01)
    assert fine.field == "analysis.step_hours"


# --- what accuracy costs ------------------------------------------------------------------------------------


def test_accuracy_run_orders_and_two_implementations_of_dop853(tmp_path, monkeypatch):
    untimed(monkeypatch)
    spec = {
        "span_years": 1,
        "steps_hours": [12, 6, 3],
        "tolerances": [1e-8],
        "methods": ["splitting2", "splitting4", "dop853", "scipy:DOP853"],
    }
    s = scene(
        tmp_path, "full", ("solar_torque", "lunar_torque"), span_years=0.1, step_hours=3, accuracy_cost=spec
    )
    r = Results("precession", s.name, s.title)
    m = secular.setup(s)
    accuracy.run(s, m, r, quick=True)
    frame = r.timing_tables["accuracy"][0]
    assert value(r, "accuracy_span_years") == accuracy.QUICK_SPAN_YEARS
    assert value(r, "reference_agreement_mas") < accuracy.REFERENCE_AGREEMENT_BOUND_MAS
    two = frame[frame.method == "splitting, order 2"].error_mas.to_numpy()
    # Strang splitting: halving the step divides the error by 4
    assert two[0] / two[1] == pytest.approx(4.0, rel=0.1) and two[1] / two[2] == pytest.approx(4.0, rel=0.1)
    four = frame[frame.method == "splitting, order 4"].error_mas.to_numpy()
    assert np.all(four < two / 50)
    # the compiled DOP853 and scipy's take the same steps and land on the same axis
    ours, peer = frame[frame.method == "dop853"].iloc[0], frame[frame.method == "scipy:DOP853"].iloc[0]
    assert abs(ours.steps - peer.steps) <= 2
    assert ours.error_mas == pytest.approx(peer.error_mas, rel=0.02)
    assert value(r, "resolution_mas") >= value(r, "reference_agreement_mas")
    assert set(frame.steps[frame.kind == "step"]) == {73, 146, 292}  # 36.5 days / h
    # the table shows a step in hours and a tolerance each in its own column, as the scene asked for them
    shown = r.tables["accuracy"][0]
    assert set(shown.step_hours.dropna()) == {12, 6, 3} and set(shown.rtol.dropna()) == {1e-8}
    # the hard case is the same measurement as the number: the same value in the same unit
    (case,) = [c for c in r.stability if c["name"] == "reference_agreement"]
    assert case["measured"] == value(r, "reference_agreement_mas") and case["unit"] == "mas"
    assert_units_follow_names(r)


def test_reference_axis_against_scipy_on_the_same_rhs():
    """accuracy's two references (DOP853 at rtol 1e-13, the order-4 splitting) against scipy's DOP853 on the
    model's right-hand side, called from Python."""
    m = prec.assemble(earth.H_P03, EPS0, prec.modern(), {e: {} for e in ALL})
    span = 2.0
    m0, q0 = prec.initial_state(m)
    p = m.parameters()

    def f(t, y):
        out = np.empty(7)
        prec.full_rhs(t, y, p, out)
        return out

    sol = solve_ivp(f, (0.0, span), np.concatenate([m0, q0]), method="DOP853", rtol=1e-12, atol=1e-12 * m.n)
    y = sol.y[:, -1]
    q = y[3:] / np.linalg.norm(y[3:])
    w, x, yq, z = q
    R = np.array(
        [
            [1 - 2 * (yq * yq + z * z), 2 * (x * yq - w * z), 2 * (x * z + w * yq)],
            [2 * (x * yq + w * z), 1 - 2 * (x * x + z * z), 2 * (yq * z - w * x)],
            [2 * (x * z - w * yq), 2 * (yq * z + w * x), 1 - 2 * (x * x + yq * yq)],
        ]
    )
    L = R @ y[:3]
    L /= np.linalg.norm(L)
    rk, steps = accuracy._axis_rk(m, span, "dop853", accuracy.REFERENCE_RTOL)
    assert steps > 0
    assert accuracy._angle_mas(rk, L) < 1e-4
    assert accuracy._angle_mas(accuracy._axis_splitting(m, span, 0.5, 4), L) < 1e-4
    # the angle itself: two unit vectors at a known angle
    a = np.array([1.0, 0.0, 0.0])
    b = np.array([np.cos(3 * earth.MAS), np.sin(3 * earth.MAS), 0.0])
    assert accuracy._angle_mas(a, b) == pytest.approx(3.0, rel=1e-9)


# --- Lamb's worked examples ---------------------------------------------------------------------------------


def test_examples_polhode_circle_moon_line_in_feet_and_maccullagh(tmp_path):
    s = validate("precession", ROOT / "workflow/scenes/precession/lamb_1920.yaml")
    m = secular.setup(s)
    a = s.data["analysis"]
    sub = copy.deepcopy(s)
    sub.data["analysis"] = {k: a[k] for k in ("polhode_circle", "moon_line_offset", "distant_mass_couple")}
    r = Results("precession", s.name, s.title)
    examples.run(sub, m, r)
    # Lamb Art. 29, Ex.: "about 27 cm"; Ex. VI.5: "about 475 ft" (digest)
    assert value(r, "polhode_circle_radius_cm") == pytest.approx(27.0, abs=0.5)
    assert value(r, "moon_line_offset_ft") == pytest.approx(475.0, rel=0.02)
    # sin(beta) = psi' sin(eps)/n: the angle in mas from the radius over R, formed here
    beta = np.arcsin(value(r, "polhode_circle_radius_cm") / 6.37e8)
    assert value(r, "polhode_cone_angle_mas") == pytest.approx(beta / earth.MAS, rel=1e-9)
    # MacCullagh's couple is the leading term; the next (J4-like) falls by (a/rho)^2 more. Independent: the
    # couple is a quadrature of Newton's attraction over the body's volume, which uses no moment of inertia;
    # the formula uses the moments only (C = 2a^2/4.5 for 2a^2/5 in the formula fails this)
    assert value(r, "maccullagh_difference_slope") == pytest.approx(2.0, abs=0.05)
    assert value(r, "maccullagh_relative_difference_far") < 1e-5
    # B = A: no component about the symmetry axis (only quadrature round-off)
    assert value(r, "maccullagh_axial_component") < 1e-12


# --- scenes the study refuses -------------------------------------------------------------------------------

BASE = {
    "title": "x",
    "fidelity": "full",
    "constants": "modern",
    "earth": EARTH,
    "effects": {"solar_torque": None, "lunar_torque": None},
    "analysis": {"span_years": 10, "step_hours": 3},
}


def _set(**changes):
    def change(d):
        for dotted, v in changes.items():
            *parents, last = dotted.split("__")
            target = d
            for key in parents:
                target = target[key]
            if v is None:
                target.pop(last, None)
            else:
                target[last] = v

    return change


@pytest.mark.parametrize(
    "change,field",
    [
        (_set(effects={"solar_torque": None, "lunar_inclination": None}), "effects.lunar_inclination"),
        (
            _set(fidelity="secular", analysis={}, effects={"lunar_torque": None, "lunar_inclination": None}),
            "effects.lunar_inclination",
        ),
        (_set(fidelity="averaged", analysis={}), "analysis.span_years"),
        (_set(fidelity="averaged"), "analysis.step_hours"),
        (_set(fidelity="averaged", analysis={"span_years": 10, "compare_iau": True}), "analysis.compare_iau"),
        (_set(analysis__inverse_problem={"observed_rate_arcsec_per_year": 50.3, "source": "s"}), "inverse"),
        (
            _set(
                fidelity="secular",
                analysis={
                    "gyroscope_couple": {
                        "weights_lb": [300, 35],
                        "radii_of_gyration_ft": [1.0],
                        "spin_rev_per_s": 20,
                        "turn_period_s": 10,
                        "g_ft_per_s2": 32.2,
                        "transverse_over_axial": 0.3,
                        "source": "s",
                    }
                },
            ),
            "analysis.gyroscope_couple.radii_of_gyration_ft",
        ),
        (_set(analysis__aliasing_windows_years=[5, 20]), "analysis.aliasing_windows_years"),
        (
            _set(
                analysis__accuracy_cost={
                    "span_years": 1,
                    "steps_hours": [1e-12, 12],
                    "tolerances": [1e-8],
                    "methods": ["dop853"],
                }
            ),
            "analysis.accuracy_cost.steps_hours.0",
        ),
    ],
)
def test_inconsistent_scenes_name_the_field(tmp_path, change, field):
    data = copy.deepcopy(BASE)
    change(data)
    assert_refused(tmp_path, "precession", data, field)


def test_the_secular_rates_per_julian_year_and_per_orbit_are_one_rate_in_two_units(tmp_path):
    """Lamb's 'per annum' is per revolution round the Sun: the total rate (″ per Julian year of 365.25 d)
    times the orbit's length in Julian years; the total is the Sun's and the Moon's parts added."""
    s = scene(tmp_path, "secular", ("solar_torque", "lunar_torque"))
    m = secular.setup(s)
    rates = secular.secular_rates(m)
    arcsec = np.pi / (180 * 3600)
    assert rates.total == pytest.approx(m.secular_rate() * 365.25 / arcsec, rel=1e-14)
    assert rates.total == pytest.approx(rates.solar + rates.lunar, rel=1e-14)
    assert rates.per_orbit == pytest.approx(rates.total * m.orbits.year_days / 365.25, rel=1e-14)
    assert 45 < rates.per_orbit < 60  # of the order of the observed 50″ a year, in arcseconds


def test_the_nutation_figure_names_each_line_it_draws():
    """The IAU figure's one legend above its panels: each entry's name and colour are those of the line that
    draws that series (made-up series told apart by size), so a name cannot slide onto another line."""
    t = np.linspace(0.0, 5.0 * earth.JULIAN_YEAR_DAYS, 200)
    wave = np.sin(2 * np.pi * t / 6798.4) * earth.ARCSEC
    series = {"full model": (1.1, 0), "IAU 2000B": (1.0, 0), "difference, $\\Delta\\psi$": (0.1, 2)}
    series["difference, $\\Delta\\varepsilon$"] = (0.05, 2)
    values = full.IauNutation([], t, 1.1 * wave, 0.55 * wave, wave, 0.5 * wave, 0.0, 0.0)
    results = Results("precession", "t", "t")
    full._record_iau_nutation(results, values)
    fig = results.figures["nutation"][0]
    (legend,) = fig.legends
    names = [text.get_text() for text in legend.get_texts()]
    assert names == list(series)
    for name, handle in zip(names, legend.legend_handles):
        size, panel = series[name]
        (line,) = [
            ln for ln in fig.axes[panel].get_lines() if np.isclose(np.max(ln.get_ydata()), size, rtol=1e-3)
        ]
        assert handle.get_color() == line.get_color(), name
