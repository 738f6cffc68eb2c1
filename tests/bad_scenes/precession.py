"""Bad scenes of the precession study (see __init__.py)."""

from functools import partial

from . import DELETE, case

CENTURY, MILLENNIUM, SUN, CYCLE, LAMB, SECULAR = (
    "full_century.yaml",
    "full_millennium.yaml",
    "full_sun.yaml",
    "averaged_cycle.yaml",
    "lamb_1920.yaml",
    "secular_modern.yaml",
)


_case = partial(case, "precession")

CASES = [
    # the cases: a step double precision cannot take; a span at the schema's limit with a small step
    _case("step-1e-30", "precision", "analysis.step_hours", SUN, analysis__step_hours=1e-30),
    _case(
        "step-1e-12-long",
        "precision",
        "analysis.step_hours",
        MILLENNIUM,
        analysis__span_years=100000,
        analysis__step_hours=1e-12,
    ),
    _case(
        "sweep-step-1e-300",
        "precision",
        "analysis.accuracy_cost.steps_hours.1",
        CENTURY,
        analysis__accuracy_cost__steps_hours=[24, 1e-300],
    ),
    _case(
        "tolerance-1e-300",
        "precision",
        "analysis.accuracy_cost.tolerances.0",
        CENTURY,
        analysis__accuracy_cost__tolerances=[1e-300],
    ),
    _case(
        "span-1e5-small-step",
        "cost",
        "analysis.step_hours",
        MILLENNIUM,
        analysis__span_years=100000,
        analysis__step_hours=0.1,
    ),
    _case("span-1e5", "cost", "analysis.span_years", MILLENNIUM, analysis__span_years=100000),
    _case(
        "aliasing-30000-years",
        "cost",
        "analysis.aliasing_windows_years",
        CENTURY,
        analysis__span_years=30000,
        analysis__aliasing_windows_years=[19.3, 30000.0],
    ),
    _case(
        "sweep-tiny-steps",
        "cost",
        "analysis.accuracy_cost.steps_hours",
        CENTURY,
        analysis__accuracy_cost__span_years=10,
        analysis__accuracy_cost__steps_hours=[0.001, 0.002],
    ),
    _case(
        "sweep-tight-scipy",
        "cost",
        "analysis.accuracy_cost.tolerances",
        CENTURY,
        analysis__accuracy_cost__span_years=10,
        analysis__accuracy_cost__tolerances=[2.3e-14] * 30,
    ),
    # finite ranges
    _case("span-1e300", "range", "analysis.span_years", CYCLE, analysis__span_years=1e300),
    _case("H-1e300", "range", "earth.H", CYCLE, earth__H=1e300),
    _case("obliquity-minus-1e300", "range", "earth.obliquity_deg", CYCLE, earth__obliquity_deg=-1e300),
    _case(
        "rate-1e300",
        "range",
        "analysis.inverse_problem.observed_rate_arcsec_per_year",
        SECULAR,
        analysis__inverse_problem__observed_rate_arcsec_per_year=1e300,
    ),
    _case(
        "radius-1e300",
        "range",
        "analysis.polhode_circle.earth_radius_cm",
        LAMB,
        analysis__polhode_circle__earth_radius_cm=1e300,
    ),
    _case(
        "spin-1e300",
        "range",
        "analysis.gyroscope_couple.spin_rev_per_s",
        LAMB,
        analysis__gyroscope_couple__spin_rev_per_s=1e300,
    ),
    _case("samples-1e9", "range", "analysis.lamb_art61.samples", LAMB, analysis__lamb_art61__samples=10**9),
    _case("step-48-hours", "range", "analysis.step_hours", SUN, analysis__step_hours=48),
    # the schema's shape
    _case("fidelity-unknown", "schema", "fidelity", CYCLE, fidelity="exact"),
    _case("constants-unknown", "schema", "constants", CYCLE, constants="iers2010"),
    _case("no-earth", "schema", "earth", CYCLE, earth=DELETE),
    _case("effect-unknown", "schema", "effects.planet_torque", CYCLE, effects={"planet_torque": None}),
    _case("H-text", "schema", "earth.H", CYCLE, earth__H="one over 305"),
    # physics
    _case(
        "no-couple",
        "physics",
        "effects",
        CYCLE,
        effects={"orbit_eccentricity": None},
        says="solar_torque or lunar_torque",
    ),
    _case(
        "full-without-step",
        "physics",
        "analysis.step_hours",
        SUN,
        analysis__step_hours=DELETE,
        says="a step in hours for the full",
    ),
    _case(
        "averaged-with-step",
        "physics",
        "analysis.step_hours",
        CYCLE,
        analysis__step_hours=3,
        says="no step below the full rung",
    ),
    _case(
        "iau-on-averaged",
        "physics",
        "analysis.compare_iau",
        CYCLE,
        analysis__compare_iau=True,
        says="fidelity: full",
    ),
    _case(
        "windows-past-span",
        "physics",
        "analysis.aliasing_windows_years",
        CENTURY,
        analysis__aliasing_windows_years=[19.3, 200.0],
        says="windows no longer than span_years = 100",
    ),
    # every refusal of check() has a scene that meets it (issue 38)
    _case(
        "inclination-without-moon",
        "physics",
        "effects.lunar_inclination",
        CYCLE,
        effects__lunar_torque=DELETE,
        says="lunar_torque as well",
    ),
    _case(
        "perigee-without-moon",
        "physics",
        "effects.lunar_perigee_advance",
        SUN,
        effects={"solar_torque": None, "orbit_eccentricity": None, "lunar_perigee_advance": None},
        says="lunar_torque as well",
    ),
    _case(
        "perigee-on-averaged",
        "physics",
        "effects.lunar_perigee_advance",
        CYCLE,
        effects__lunar_perigee_advance=None,
        says="the full rung",
    ),
    _case(
        "secular-inclination-fixed-node",
        "physics",
        "effects.lunar_inclination",
        SECULAR,
        effects__node_regression=DELETE,
        says="node_regression as well at the secular rung",
    ),
    _case(
        "averaged-without-span",
        "physics",
        "analysis.span_years",
        CYCLE,
        analysis__span_years=DELETE,
        says="a span in years for the averaged rung",
    ),
    _case(
        "inverse-on-averaged",
        "physics",
        "analysis.inverse_problem",
        CYCLE,
        analysis__inverse_problem={"observed_rate_arcsec_per_year": 50.4, "source": "IAU 2006"},
        says="fidelity: secular",
    ),
    _case(
        "gyroscope-radius-missing",
        "physics",
        "analysis.gyroscope_couple.radii_of_gyration_ft",
        LAMB,
        analysis__gyroscope_couple__radii_of_gyration_ft=[1.0],
        says="one radius of gyration for each weight",
    ),
]
