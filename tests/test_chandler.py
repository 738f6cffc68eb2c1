"""The Chandler wobble: units, closed forms, the model's physics and hard cases, the fit, bad scenes."""

import numpy as np
import pytest
import yaml

from classical_dynamics.models import earth, wobble
from classical_dynamics.scenes import SceneError
from classical_dynamics.solvers import references as ref
from classical_dynamics.solvers.ode import Problem, solve
from classical_dynamics.studies import STUDIES, load_schema, validate
from classical_dynamics.studies.chandler import model as wobble_model
from classical_dynamics.studies.chandler import polar_motion as pm

from .conftest import ROOT

SCHEMA = STUDIES["chandler"].schema
YEAR = earth.JULIAN_YEAR_DAYS
AMP = 0.1 * earth.ARCSEC  # a 0.1" wobble, 5e-7 rad


def run_model(effects, span_days, amplitude=AMP, rtol=1e-12, samples=20001, H=earth.H_MHB2000):
    model = wobble.assemble(H, effects)
    t = np.linspace(0.0, span_days, samples)
    sol = wobble_model.integrate(model, amplitude, span_days, rtol, t)
    assert sol.status == "success"
    return model, t, sol.y_eval


# --- units: one test per conversion -------------------------------------------------------------


def test_sidereal_and_solar_days():
    # 366.2422 turns in 365.2422 solar days: a tropical year holds one more sidereal day than solar days
    assert earth.SIDEREAL_PER_SOLAR_DAY * earth.TROPICAL_YEAR_DAYS == pytest.approx(
        earth.TROPICAL_YEAR_DAYS + 1, abs=2e-4
    )
    assert earth.sidereal_to_solar_days(earth.solar_to_sidereal_days(433.0)) == pytest.approx(
        433.0, rel=1e-15
    )
    # the turn counted is the stellar day (Earth rotation angle), 86164.0989 s; the equinox-referred sidereal
    # day is 8.4 ms shorter (precession): the difference is 1e-7, far below anything compared here
    assert earth.sidereal_to_solar_days(1.0) * earth.SECONDS_PER_DAY == pytest.approx(86164.0989, abs=1e-4)


def test_julian_and_tropical_years():
    assert pm.ANNUAL_CPY == pytest.approx(1.0000214, abs=1e-7)  # one tropical year per Julian year


def test_arcseconds_and_milliarcseconds():
    assert earth.ARCSEC * 206264.80624709636 == pytest.approx(1.0, rel=1e-15)
    assert earth.MAS * 1000 == earth.ARCSEC


def test_ellipticity_definitions():
    assert earth.euler_period_sidereal_days(earth.h_over_c(0.00327, "(C-A)/A")) == pytest.approx(
        1 / 0.00327, rel=1e-13
    )
    assert earth.euler_period_sidereal_days(earth.H_MHB2000) == pytest.approx(
        1 / earth.H_MHB2000 - 1, rel=1e-14
    )


# --- closed forms ----------------------------------------------------------------------------------


def test_secular_love_number_from_j2_and_q():
    assert earth.centrifugal_parameter() == pytest.approx(3.4614e-3, rel=1e-4)
    assert earth.secular_love_number() == pytest.approx(0.938, abs=0.001)


def test_lamb_elastic_formula_and_its_inverse():
    H = earth.H_MHB2000
    beta = earth.elastic_beta_n2_over_c(0.30, H)
    a = 1 - H
    assert earth.elastic_wobble_frequency(H, beta) == pytest.approx((1 - a - beta) / (a + beta), rel=1e-14)
    back = earth.beta_n2_for_period(H, 433.1)
    period = 2 * np.pi / (earth.SPIN_RAD_PER_DAY * earth.elastic_wobble_frequency(H, back))
    assert period == pytest.approx(433.1, rel=1e-13)


def test_exact_free_body_keeps_a_tiny_wobble():
    """E2 I3 - M2 ~ 1e-15 M2 for a 0.1" wobble: summed term by term, the elliptic solution keeps it."""
    a, b = earth.moments_over_c(earth.H_MHB2000, earth.b_minus_a_over_c())
    I = np.array([a, b, 1.0])
    w0 = earth.SPIN_RAD_PER_DAY * np.array([AMP, 0.0, 1.0])
    w = ref.free_rigid_body(I, I * w0, np.array([0.0]))[0]
    assert np.allclose(w / earth.SPIN_RAD_PER_DAY, [AMP, 0.0, 1.0], rtol=0, atol=1e-13 * AMP)


# --- the model's physics and its hard cases -----------------------------------------------------------


def test_tiny_wobble_period_to_1e6_over_a_century():
    model, t, y = run_model({}, 100 * YEAR)
    period = 2 * np.pi / wobble_model.phase_rate(t, y)
    expected = (1 / earth.H_MHB2000 - 1) / earth.SIDEREAL_PER_SOLAR_DAY  # A/(C-A) sidereal days
    assert abs(period / expected - 1) < 1e-6
    assert np.max(np.abs(np.hypot(y[:, 0], y[:, 1]) / AMP - 1)) < 1e-8  # the amplitude is kept


@pytest.mark.parametrize("H,sense", [(earth.H_MHB2000, 1), (-0.01, -1)])
def test_sense_of_rotation_against_the_spin(H, sense):
    """Oblate (C > A): the axis goes round the figure axis with the spin; prolate: against it.

    Read geometrically, from (omega x omega') . e3 compared with omega . e3, not from a parameter's sign."""
    model = wobble.WobbleModel(H=H)
    t = np.linspace(0, 50.0, 201)
    sol = solve(
        Problem(wobble.liouville, np.array([AMP, 0.0, 1.0]), (0, 50.0), model.parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-20,
        t_eval=t,
    )
    y = sol.y_eval
    dy = np.gradient(y, t, axis=0)
    turning = y[:, 0] * dy[:, 1] - y[:, 1] * dy[:, 0]
    assert np.all(np.sign(turning * y[:, 2]) == sense)


def test_triaxial_motion_matches_the_elliptic_functions():
    effects = {"triaxiality": {}}
    model, t, y = run_model(effects, 100 * YEAR)
    a, b = earth.moments_over_c(model.H, model.b_minus_a_over_c)
    I = np.array([a, b, 1.0])
    w0 = model.n * np.array([AMP, 0.0, 1.0])
    exact = ref.free_rigid_body(I, I * w0, t) / model.n
    assert np.max(np.abs(y - exact)[:, :2]) < 1e-8 * AMP
    period = ref.free_rigid_body_period(I, I * w0)
    change = period / model.wobble_period_solar_days() - 1
    assert abs(change) < 1e-12
    # Linearised Euler equations, worked here from H and (B - A)/C alone: sigma = n sqrt((C-A)(C-B)/(AB))
    # for the triaxial body, n (C - A0)/A0 with A0 = (A + B)/2 = (1 - H) C for the symmetric one. The shift is
    # second order in (B - A)/(C - A), about 4e-6; the wobble's own amplitude moves it by AMP^2 ~ 1e-13 only.
    H, d = model.H, model.b_minus_a_over_c
    A, B = 1.0 - H - 0.5 * d, 1.0 - H + 0.5 * d
    linear = 2 * np.pi / (model.n * np.sqrt((1 - A) * (1 - B) / (A * B)))
    symmetric = 2 * np.pi * (1 - H) / (model.n * H)
    assert period == pytest.approx(linear, rel=1e-10)
    assert period / symmetric - 1 == pytest.approx(linear / symmetric - 1, rel=1e-4)
    assert linear / symmetric - 1 > 1e-6  # the check above sees the triaxiality


def test_elastic_integration_gives_lambs_period():
    effects = {"elastic_yielding": {"k2": 0.30}}
    model, t, y = run_model(effects, 30 * YEAR)
    H = earth.H_MHB2000
    beta = earth.elastic_beta_n2_over_c(0.30, H)
    sigma = (H - beta) / (1 - H + beta)  # Lamb (14) with moments in units of C
    assert 2 * np.pi / wobble_model.phase_rate(t, y) == pytest.approx(2 * np.pi / (model.n * sigma), rel=1e-9)


def test_dissipation_keeps_L_lowers_energy_and_gives_its_Q():
    Q = 50.0
    effects = {"elastic_yielding": {"k2": 0.30}, "dissipation": {"Q": Q}}
    model = wobble.assemble(earth.H_MHB2000, effects)
    tilt = np.radians(10.0)
    span = 10 * model.wobble_period_solar_days()
    t = np.linspace(0, span, 2001)
    sol = solve(
        Problem(wobble.liouville, np.array([np.sin(tilt), 0, np.cos(tilt)]), (0, span), model.parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        t_eval=t,
    )
    L, E = wobble.invariants(sol.y_eval, model.parameters())
    assert np.max(np.abs(L / L[0] - 1)) < 1e-12
    assert np.all(np.diff(E) <= 0) and E[-1] < E[0] * (1 - 1e-6)
    # a small wobble: Q recovered from the envelope to 5 %
    _, t, y = run_model(effects, 100 * YEAR, samples=5001)
    slope = np.polyfit(t, np.log(np.hypot(y[:, 0], y[:, 1])), 1)[0]
    Q_fit = -(2 * np.pi / model.wobble_period_solar_days()) / (2 * slope)
    assert abs(Q_fit / Q - 1) < 0.05


def test_dissipation_makes_a_prolate_spinner_tumble():
    """The major-axis rule (Explorer 1): with internal friction, spin about the least axis is lost."""
    effects = {"elastic_yielding": {"k2": 0.1}, "dissipation": {"Q": 5.0}}
    model = wobble.assemble(-0.05, effects)
    span = 40 * abs(model.wobble_period_solar_days())
    sol = solve(
        Problem(wobble.liouville, np.array([1e-3, 0.0, 1.0]), (0, span), model.parameters()),
        "dop853",
        rtol=1e-10,
        atol=1e-13,
    )
    assert np.hypot(sol.y[0], sol.y[1]) > 10 * 1e-3


def test_static_excitation_moves_the_mean_pole_to_chi():
    """Liouville at zero frequency: the pole circles round chi (the displaced figure axis) and averages to
    it."""
    chi_mas = 50.0
    model = wobble.WobbleModel(H=earth.H_MHB2000, terms=[(chi_mas * earth.MAS, 0.0, 0.0)])
    period = model.wobble_period_solar_days()
    t = np.linspace(0, 20 * period, 20001)
    sol = solve(
        Problem(wobble.liouville, np.array([0.0, 0.0, 1.0]), (0, t[-1]), model.parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-20,
        t_eval=t,
    )
    m = (sol.y_eval[:, 0] + 1j * sol.y_eval[:, 1]) / earth.MAS
    assert abs(np.mean(m) - chi_mas) < 1e-3 * chi_mas
    assert np.max(np.abs(np.abs(m - chi_mas) - chi_mas)) < 1e-3 * chi_mas


def test_annual_forcing_gives_the_liouville_response():
    """A prograde annual chi: the linearized Euler-Liouville equations of the elastic body give
    m + (i/sigma) m' = psi (1 + omega/n), psi = chi (C - A)/(C - A - beta n^2), so the forced pole is
    psi (1 + omega/n) sigma/(sigma - omega), sigma complex with Q (the rigid Liouville factor, times the
    elastic amplification 1/(1 - k2/k_s) of a mass load)."""
    chi_mas, Q = 10.0, 20.0
    effects = {
        "elastic_yielding": {"period_solar_days": 433.0},
        "dissipation": {"Q": Q},
        "excitation": {"annual": {"prograde": {"amplitude_mas": chi_mas, "phase_deg": 0.0}}},
    }
    model = wobble.assemble(earth.H_MHB2000, effects)
    span = 150 * YEAR  # free part decays e^-75 ... long gone
    t = np.arange(100 * YEAR, span, 2.0)
    sol = wobble_model.integrate(model, 1e-12, span, 1e-11, t)
    m = (sol.y_eval[:, 0] + 1j * sol.y_eval[:, 1]) / earth.MAS
    omega = 2 * np.pi / earth.TROPICAL_YEAR_DAYS
    forced = np.vdot(np.exp(1j * omega * t), m) / t.size
    sigma = 2 * np.pi / 433.0 * (1 + 0.5j / Q)
    H, beta = earth.H_MHB2000, model.beta_n2
    psi = chi_mas * H / (H - beta) * (1 + omega / model.n)
    assert abs(forced) == pytest.approx(abs(psi * sigma / (sigma - omega)), rel=1e-3)


# --- fitting the polar motion ------------------------------------------------------------------------


def test_fit_recovers_a_known_series():
    t = np.arange(0, 40, 1 / 365.25)
    f_c = 365.25 / 433.0
    m = (
        (3 + 2j)
        + (1 - 1j) * t
        + 150 * np.exp(2j * np.pi * f_c * t + 0.7j)
        + 90 * np.exp(2j * np.pi * pm.ANNUAL_CPY * t + 0.2j)
        + 5 * np.exp(-2j * np.pi * pm.ANNUAL_CPY * t)
    )
    fit = pm.fit(t, m)
    assert fit.chandler_period_days == pytest.approx(433.0, rel=1e-8)
    assert fit.chandler_amplitude_mas == pytest.approx(150.0, rel=1e-8)
    assert fit.annual_prograde_mas == pytest.approx(90.0, rel=1e-6)  # f_c found to xatol 1e-10
    assert fit.annual_retrograde_mas == pytest.approx(5.0, rel=1e-6)


def test_the_periodogram_is_the_dft_of_the_detrended_series_term_by_term():
    """Its blocks (one exp per block, then products) against the sum written out at every frequency, on an
    uneven series with a trend; a grid that does not fill its last block."""
    rng = np.random.default_rng(3)
    t = np.sort(rng.uniform(1962.0, 1990.0, 900))
    m = 3.0 + 0.5 * t + np.exp(2j * np.pi * 0.845 * t) + 0.2 * rng.normal(size=t.size)
    f, power = pm.periodogram(t, m, points=pm.BLOCK * 3 + 5)
    slope, intercept = np.polyfit(t, m, 1)
    r = m - (slope * t + intercept)
    direct = np.array([abs(np.sum(r * np.exp(-2j * np.pi * fk * t))) ** 2 for fk in f])
    np.testing.assert_allclose(power, direct / direct.max(), rtol=1e-9, atol=1e-12)
    assert f[np.argmax(power)] == pytest.approx(0.845, abs=f[1] - f[0])


def test_observed_series_shows_a_prograde_433_day_wobble():
    t, m = pm.read_eop(pm.eop_file(), 1962.0, 2015.0)
    assert t.size > 19000
    fit = pm.fit(t, m)
    assert 425 < fit.chandler_period_days < 440
    f, power = pm.periodogram(t, m, points=1201)
    band = (np.abs(f) > 0.7) & (np.abs(f) < 1.0)
    assert f[band][np.argmax(power[band])] > 0  # x - iy turns with the spin
    assert 60 < fit.annual_prograde_mas < 120


# --- scenes --------------------------------------------------------------------------------------------

GOOD = {
    "title": "t",
    "earth": {"H": 0.0032737949, "H_definition": "(C-A)/C", "H_source": "s"},
    "effects": {"elastic_yielding": {"k2": 0.3, "source": "s"}, "dissipation": {"Q": 100, "source": "s"}},
}
OBS = {
    "title": "o",
    "observation": {
        "series": "eopc04",
        "start_year": 1962,
        "end_year": 2020,
        "window_years": 6.4,
        "step_years": 1,
        "compare": {"H": 0.0032737949, "k2": 0.3},
    },
}


def scene(tmp_path, base, **changes):
    data = yaml.safe_load(yaml.safe_dump(base))
    for dotted, value in changes.items():
        *parents, last = dotted.split("__")
        target = data
        for p in parents:
            target = target[p]
        target[last] = value
    path = tmp_path / "scene.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True))
    return path


BAD = [
    (GOOD, {"effects": {"magnetism": {}}}, "effects.magnetism", "known effect"),
    (GOOD, {"earth__H": 0.0}, "earth.H", "> 0"),
    (GOOD, {"earth__H": -0.003}, "earth.H", "> 0"),
    (GOOD, {"effects__dissipation__Q": 0}, "effects.dissipation.Q", ">= 0.01"),
    (GOOD, {"effects__dissipation__Q": -5}, "effects.dissipation.Q", ">= 0.01"),
    (
        GOOD,
        {"effects": {"dissipation": {"Q": 100, "source": "s"}}},
        "effects.dissipation",
        "elastic_yielding",
    ),
    (GOOD, {"effects__elastic_yielding__k2": 0.95}, "effects.elastic_yielding.k2", "k_s"),
    (
        GOOD,
        {"effects": {"triaxiality": {"b_minus_a_over_c": 0.01}}},
        "effects.triaxiality.b_minus_a_over_c",
        "below 2H",
    ),
    (OBS, {"observation__start_year": 1950}, "observation.start_year", "inside the series"),
    (OBS, {"observation__end_year": 2100}, "observation.end_year", "not after the series ends"),
    (OBS, {"observation__window_years": 80}, "observation.window_years", "no longer than the span"),
    (OBS, {"effects": {"dissipation": {"Q": 1, "source": "s"}}}, "effects", "no effects for an observation"),
]


@pytest.mark.parametrize("base,changes,field,expected", BAD)
def test_bad_scene_one_line(tmp_path, base, changes, field, expected):
    path = scene(tmp_path, base, **changes)
    with pytest.raises(SceneError) as error:
        validate("chandler", path)
    message = str(error.value)
    assert "\n" not in message and str(path) in message
    assert f"field '{field}'" in message and expected in message


def test_an_observation_may_span_the_whole_series_and_not_a_day_beyond(tmp_path):
    """The series' own first and last epochs (read here from the file's first and last records) bound an
    observation: start at the first and end at the last are accepted; a day before the first, a start at the
    last, or an end a day after it is refused, naming its field."""
    from classical_dynamics.studies.chandler import polar_motion as pm

    mjd = np.loadtxt(pm.eop_file(), comments="#", usecols=4)
    first, last = (2000.0 + (float(d) - 51544.5) / earth.JULIAN_YEAR_DAYS for d in mjd[[0, -1]])
    day = 1.0 / earth.JULIAN_YEAR_DAYS
    window = {"observation__window_years": 1.0, "observation__step_years": 1.0}
    validate(
        "chandler", scene(tmp_path, OBS, observation__start_year=first, observation__end_year=last, **window)
    )
    for changes, field in (
        ({"observation__start_year": first - day}, "observation.start_year"),
        ({"observation__start_year": last, "observation__end_year": "latest"}, "observation.start_year"),
        ({"observation__start_year": first, "observation__end_year": last + day}, "observation.end_year"),
    ):
        with pytest.raises(SceneError, match=f"field '{field}'"):
            validate("chandler", scene(tmp_path, OBS, **{**window, **changes}))


def test_cli_refuses_a_window_outside_the_series_and_creates_nothing(tmp_path, capsys):
    """The command line's run, in this process (a Python of its own added a second of imports to a refusal
    made before anything is computed)."""
    from classical_dynamics.cli import main

    path = scene(tmp_path, OBS, observation__end_year=2100)
    out = tmp_path / "results" / "chandler" / "scene"
    capsys.readouterr()
    status = main(
        ["run", "chandler", str(path), str(out), str(tmp_path / "results" / "chandler" / "timings" / "scene")]
    )
    err = capsys.readouterr().err
    assert status != 0 and err.strip().count("\n") == 0, err
    assert "observation.end_year" in err
    assert not (tmp_path / "results").exists()


def test_shipped_scenes_are_valid_and_registry_matches_schema():
    for path in sorted((ROOT / "workflow" / "scenes" / "chandler").glob("*.yaml")):
        validate("chandler", path)
    schema = load_schema(SCHEMA)
    assert sorted(schema["properties"]["effects"]["properties"]) == wobble.EFFECTS.names()


def test_only_listed_effects_are_built(monkeypatch):
    called = []
    for name in wobble.EFFECTS.names():
        effect = wobble.EFFECTS[name]
        monkeypatch.setitem(
            wobble.EFFECTS._effects,
            name,
            effect.__class__(
                effect.name,
                effect.kind,
                effect.summary,
                lambda params, model, _build=effect.build, _name=name: (
                    called.append(_name) or _build(params, model)
                ),
            ),
        )
    model = wobble.assemble(earth.H_MHB2000, {"elastic_yielding": {"k2": 0.3}})
    assert called == ["elastic_yielding"]
    p = model.parameters()
    assert p[wobble.DISSIPATION] == 0 and p[wobble.N_TERMS] == 0 and p[wobble.A_C] == p[wobble.B_C]


def test_polar_path_time_axis_reads_calendar_years():
    """The observed path is drawn against calendar years as given (a time axis of 5.45-5.49 'year',
    calendar years divided again by 365.25, must not return)."""
    import numpy as np

    from classical_dynamics.results import Results
    from classical_dynamics.studies.chandler.model import figure_path

    years = np.linspace(1990.0, 2003.0, 2000)
    m = 100 * np.exp(2j * np.pi * years / 1.19)
    results = Results("chandler", "observed", "test")
    figure_path(results, "polar_path", years, m, "caption")
    low, high = results.figures["polar_path"][0].axes[1].get_xlim()
    assert 1989 < low < 1991 and 2002 < high < 2004
    polhode = results.figures["polar_path"][0].axes[0]
    assert polhode.get_aspect() == 1.0  # x and y in the same unit: equal aspect


def test_retarding_couple_lamb_x10():
    """Lamb Ex. X.10: under -kappa omega, tan(theta) falls at kappa(1/A - 1/C); it grows for a prolate
    body."""
    from classical_dynamics.studies.chandler.retarding import decay_rate

    for a in (2.0 / 3.0, 2.0):
        closed = 0.01 * (1.0 / a - 1.0)
        rate, L_ratio = decay_rate(a, 0.01, np.radians(1.0), 3.0 / abs(closed))
        assert rate == pytest.approx(closed, rel=1e-8)
        assert L_ratio < 1.0


def test_retarding_scene_needs_oblate_and_prolate(tmp_path):
    scene = yaml.safe_load((ROOT / "workflow" / "scenes" / "chandler" / "retarding.yaml").read_text())
    scene["body"]["prolate_A_over_C"] = 0.9
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(scene, allow_unicode=True))
    with pytest.raises(SceneError):
        validate("chandler", path)


def test_excited_fit_beats_the_fitted_chandler_period_against_the_tropical_year():
    """A series of known period 433 d fitted as the observations are: the beat is 1/|1/P_annual - 1/P_c| with
    the tropical year (365.24219 d) and 433 d written out here, in Julian years; the resonance width 1/Q."""
    t = np.arange(0.0, 40 * 365.25, 1.0)
    m = 150 * np.exp(2j * np.pi * t / 433.0) + 90 * np.exp(2j * np.pi * t / 365.24219)
    model = type("Model", (), {"Q": 100.0})()
    excited = wobble_model.excited_fit(t, m, model, 433.0)
    beat = 1.0 / abs(1.0 / 365.24219 - 1.0 / 433.0) / 365.25
    assert excited.chandler_period_days == pytest.approx(433.0, rel=1e-6)
    assert excited.beat_period_years == pytest.approx(beat, rel=1e-5)
    assert excited.beat_period_closed_form_years == pytest.approx(beat, rel=1e-5)
    assert abs(excited.period_relative_error) < 1e-6 and excited.bound == pytest.approx(0.01)
