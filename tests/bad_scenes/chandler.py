"""Bad scenes of the Chandler-wobble study (see __init__.py)."""

from functools import partial

from . import DELETE, case

OBSERVED, RIGID, EXCITED, TRIAXIAL, RETARDING, DAMPED = (
    "observed.yaml",
    "rigid_modern.yaml",
    "excited.yaml",
    "triaxial.yaml",
    "retarding.yaml",
    "damped.yaml",
)


_case = partial(case, "chandler")

CASES = [
    # the cases: windows stepped by 1e-30 years; a run at the schema's old limits
    _case("step-years-1e-30", "precision", "observation.step_years", OBSERVED, observation__step_years=1e-30),
    _case("step-years-1e-14", "precision", "observation.step_years", OBSERVED, observation__step_years=1e-14),
    _case(
        "splitting-step-1e-30",
        "precision",
        "analysis.accuracy_cost.steps.0",
        RIGID,
        analysis__accuracy_cost__steps=[1e-30, 0.01],
    ),
    _case("rtol-1e-20", "precision", "analysis.rtol", EXCITED, analysis__rtol=1e-20),
    _case(
        "tolerance-1e-300",
        "precision",
        "analysis.accuracy_cost.tolerances.1",
        RIGID,
        analysis__accuracy_cost__tolerances=[1e-6, 1e-300],
    ),
    _case(
        "excited-1e5-years-tight",
        "cost",
        "analysis.span_years",
        EXCITED,
        analysis__span_years=100000,
        analysis__rtol=2.3e-14,
    ),
    _case(
        "excited-2000-terms-long",
        "cost",
        "analysis.span_years",
        EXCITED,
        analysis__span_years=20000,
        effects__excitation__random__terms=2000,
    ),
    _case("step-years-1e-6", "cost", "observation.step_years", OBSERVED, observation__step_years=1e-6),
    _case(
        "accuracy-sweep-1e4-years",
        "cost",
        "analysis.accuracy_cost.tolerances",
        RIGID,
        analysis__span_years=10000,
    ),
    _case(
        "splitting-steps-tiny",
        "cost",
        "analysis.accuracy_cost.steps",
        RIGID,
        analysis__accuracy_cost__steps=[1e-6, 2e-6],
    ),
    _case(
        "kappa-tiny-many-e-folds",
        "cost",
        "body.kappa_over_Cn",
        RETARDING,
        body__kappa_over_Cn=1e-8,
        body__e_folds=20,
    ),
    _case(
        "spin-over-turn-huge",
        "range",
        "analysis.lamb_free_body.spin_over_turn",
        TRIAXIAL,
        analysis__lamb_free_body__spin_over_turn=1e300,
    ),
    # finite ranges
    _case("kappa-1e-300", "range", "body.kappa_over_Cn", RETARDING, body__kappa_over_Cn=1e-300),
    _case("Q-1e300", "range", "effects.dissipation.Q", DAMPED, effects__dissipation__Q=1e300),
    _case("k2-1e300", "range", "effects.elastic_yielding.k2", DAMPED, effects__elastic_yielding__k2=1e300),
    _case("start-year-1e300", "range", "observation.start_year", OBSERVED, observation__start_year=-1e300),
    _case("wobble-1e300", "range", "earth.wobble_arcsec", RIGID, earth__wobble_arcsec=1e300),
    _case("span-1e300", "range", "analysis.span_years", RIGID, analysis__span_years=1e300),
    _case(
        "omega-1e300",
        "range",
        "analysis.poinsot.omega.0",
        TRIAXIAL,
        analysis__poinsot__omega=[1e300, 0.3, 1.0],
    ),
    _case(
        "phase-1e300",
        "range",
        "effects.excitation.annual.prograde.phase_deg",
        EXCITED,
        effects__excitation__annual__prograde__phase_deg=1e300,
    ),
    _case(
        "terms-1e9",
        "range",
        "effects.excitation.random.terms",
        EXCITED,
        effects__excitation__random__terms=10**9,
    ),
    # the schema's shape
    _case("H-text", "schema", "earth.H", RIGID, earth__H="small"),
    _case("H-definition-unknown", "schema", "earth.H_definition", RIGID, earth__H_definition="C/A"),
    _case("series-unknown", "schema", "observation.series", OBSERVED, observation__series="bulletin_a"),
    _case("no-H-source", "schema", "earth.H_source", RIGID, earth__H_source=DELETE),
    # physics
    _case(
        "yielding-past-fluid",
        "physics",
        "effects.elastic_yielding.k2",
        DAMPED,
        effects__elastic_yielding__k2=2.0,
        says="below the fluid value k_s",
    ),
    _case(
        "dissipation-rigid",
        "physics",
        "effects.dissipation",
        DAMPED,
        effects__elastic_yielding=DELETE,
        says="elastic_yielding as well",
    ),
    _case(
        "end-before-start",
        "physics",
        "observation.end_year",
        OBSERVED,
        observation__end_year=1960.0,
        says="a year after start_year",
    ),
    _case(
        "window-longer-than-span",
        "physics",
        "observation.window_years",
        OBSERVED,
        observation__window_years=300.0,
        says="no longer than the span",
    ),
    _case(
        "poinsot-order",
        "physics",
        "analysis.poinsot.moments",
        TRIAXIAL,
        analysis__poinsot__moments=[2.5, 2.0, 1.0],
        says="A < B < C",
    ),
    _case(
        "two-kinds",
        "physics",
        "earth",
        OBSERVED,
        earth={"H": 0.00327, "H_definition": "(C-A)/C", "H_source": "s"},
        says="one of `earth`",
    ),
]
