"""Bad scenes of the solver-layer study (see __init__.py)."""

from functools import partial

from . import DELETE, case

HNW, DETEST, LONG, HARD, TOP, INERTIA = (
    "hnw_rigid_body.yaml",
    "detest_b5.yaml",
    "long_horizon.yaml",
    "hard_cases.yaml",
    "heavy_top.yaml",
    "inertia.yaml",
)
ALL_ADAPTIVE = [
    "dop853",
    "dopri5",
    "scipy:DOP853",
    "scipy:RK45",
    "scipy:LSODA",
    "scipy:Radau",
    "scipy:BDF",
    "scipy:RK23",
]
THIRTY_TOLERANCES = [round(10.0 ** (-3 - 9 * i / 29), 14) for i in range(30)]  # 1e-3 ... 1e-12
SLENDER = {"top__A": 20.0, "top__C": 1.0, "effects__gravity__Mgh": 0.5, "top__spin": 30.0}  # A/C = 20


_case = partial(case, "solvers")

CASES = [
    # the cases: steps of 1e-30 (numba then failed with "Int value is too large"), 1 - m of 1e-300,
    # 1e7 periods at small steps, 1000 repeats of many tolerances, 100000 nutations
    _case("sweep-step-1e-30", "precision", "numerics.steps.1", HNW, numerics__steps=[0.1, 1e-30]),
    _case("long-step-1e-30", "precision", "numerics.step", LONG, numerics__step=1e-30),
    _case(
        "separatrix-1e-300",
        "precision",
        "numerics.separatrix_one_minus_m",
        HARD,
        numerics__separatrix_one_minus_m=1e-300,
    ),
    _case(
        "long-1e7-periods-small-step",
        "cost",
        "numerics.step",
        LONG,
        numerics__max_periods=1e7,
        numerics__step=0.001,
        numerics__rtol=1e-4,
    ),
    _case(
        "long-1e7-periods-dop853-limit",
        "physics",
        "numerics.max_periods",
        LONG,
        numerics__max_periods=1e7,
        numerics__step=0.001,
        says="periods at rtol 1e-10",
    ),
    _case(
        "repeats-1000-thirty-tolerances",
        "cost",
        "numerics.tolerances",
        TOP,
        numerics__repeats=1000,
        numerics__methods=ALL_ADAPTIVE,
        numerics__tolerances=THIRTY_TOLERANCES,
    ),
    _case("nutations-100000-slender", "cost", "top.nutations", TOP, top__nutations=100000, **SLENDER),
    # steps and tolerances double precision cannot honour
    _case("long-step-1e-13", "precision", "numerics.step", LONG, numerics__step=1e-13),
    _case("sweep-step-ulp", "precision", "numerics.steps.2", HNW, numerics__steps=[0.1, 0.05, 1e-15]),
    _case(
        "separatrix-1e-16",
        "precision",
        "numerics.separatrix_one_minus_m",
        HARD,
        numerics__separatrix_one_minus_m=1e-16,
    ),
    _case("rtol-1e-20", "precision", "numerics.rtol", LONG, numerics__rtol=1e-20),
    _case(
        "tolerance-1e-300", "precision", "numerics.tolerances.1", DETEST, numerics__tolerances=[1e-3, 1e-300]
    ),
    _case(
        "top-tolerance-1e-15", "precision", "numerics.tolerances.0", TOP, numerics__tolerances=[1e-15, 1e-6]
    ),
    _case("top-rtol-1e-16", "precision", "numerics.rtol", TOP, numerics__rtol=1e-16),
    # over the budget
    _case("sweep-step-1e-9", "cost", "numerics.steps", HNW, numerics__steps=[0.1, 1e-9]),
    _case("sweep-step-memory", "cost", "numerics.steps", HNW, numerics__steps=[0.1, 2e-7]),
    _case(
        "long-1e7-periods",
        "cost",
        "numerics.step",
        LONG,
        numerics__max_periods=1e7,
        numerics__step=0.02,
        numerics__rtol=1e-4,
    ),
    _case("long-step-1e-7", "cost", "numerics.step", LONG, numerics__step=1e-7),
    _case(
        "sweep-rk23-tight",
        "cost",
        "numerics.tolerances",
        HNW,
        numerics__methods=["scipy:RK23", "dop853"],
        numerics__tolerances=[1e-13, 5e-14, 2.3e-14] * 10,
    ),
    _case(
        "top-radau-tight",
        "cost",
        "numerics.tolerances",
        TOP,
        numerics__methods=["scipy:RK23", "scipy:Radau"],
        numerics__tolerances=[1e-13, 2.3e-14],
    ),
    _case(
        "top-slow-precession",
        "cost",
        "top.spin",
        TOP,
        top__A=1000.0,
        top__C=1000.0,
        top__spin=1000.0,
        effects__gravity__Mgh=1e-3,
    ),
    # finite ranges
    _case("A-1e300", "range", "top.A", TOP, top__A=1e300),
    _case("A-1e-300", "range", "top.A", TOP, top__A=1e-300),
    _case("C-minus", "range", "top.C", TOP, top__C=-1.0),
    _case("spin-1e300", "range", "top.spin", TOP, top__spin=1e300),
    _case("Mgh-1e300", "range", "effects.gravity.Mgh", TOP, effects__gravity__Mgh=1e300),
    _case("Mgh-minus-1e300", "range", "effects.gravity.Mgh", TOP, effects__gravity__Mgh=-1e300),
    _case("nutations-1e9", "range", "top.nutations", TOP, top__nutations=10**9),
    _case("inclination-90", "range", "top.inclination_deg", TOP, top__inclination_deg=90.0),
    _case("inclination-minus-1e300", "range", "top.inclination_deg", TOP, top__inclination_deg=-1e300),
    _case("max-periods-1e300", "range", "numerics.max_periods", LONG, numerics__max_periods=1e300),
    _case("step-minus-1e300", "range", "numerics.step", LONG, numerics__step=-1e300),
    _case("rtol-1e300", "range", "numerics.rtol", LONG, numerics__rtol=1e300),
    _case("nodes-1e6", "range", "numerics.nodes", INERTIA, numerics__nodes=10**6),
    _case("repeats-1e6", "range", "numerics.repeats", HNW, numerics__repeats=10**6),
    _case("steps-1e300", "range", "numerics.steps.0", HNW, numerics__steps=[1e300, 0.1]),
    _case(
        "tolerance-minus-1e300", "range", "numerics.tolerances.0", DETEST, numerics__tolerances=[-1e300, 1e-6]
    ),
    _case(
        "separatrix-1e300",
        "range",
        "numerics.separatrix_one_minus_m",
        HARD,
        numerics__separatrix_one_minus_m=1e300,
    ),
    _case("too-many-tolerances", "range", "numerics.tolerances", DETEST, numerics__tolerances=[1e-6] * 31),
    _case(
        "title-too-long", "range", "title", INERTIA, title="t" * 201, says="a text of at most 200 characters"
    ),
    # the schema's shape
    _case("problem-unknown", "schema", "problem", HNW, problem="kepler"),
    _case("method-unknown", "schema", "numerics.methods.0", HNW, numerics__methods=["euler"]),
    _case("tolerance-text", "schema", "numerics.tolerances.0", DETEST, numerics__tolerances=["tight", 1e-6]),
    _case("repeats-text", "schema", "numerics.repeats", HNW, numerics__repeats="ten"),
    _case("nodes-fraction", "schema", "numerics.nodes", INERTIA, numerics__nodes=24.5),
    _case("top-missing-spin", "schema", "top.spin", TOP, top__spin=DELETE),
    _case("long-missing-step", "schema", "numerics.step", LONG, numerics__step=DELETE),
    _case("sweep-missing-tolerances", "schema", "numerics.tolerances", HNW, numerics__tolerances=DELETE),
    # physics
    _case("top-not-a-body", "physics", "top.C", TOP, top__C=3.0, says="C <= A + B = 2A = 2 (a real body)"),
    _case(
        "top-without-gravity",
        "physics",
        "effects.gravity",
        TOP,
        effects=DELETE,
        says="the heavy top's weight",
    ),
    _case(
        "top-below-steady-precession", "physics", "top.spin", TOP, top__spin=1.0, says="a spin of at least"
    ),
    _case(
        "top-too-slender-at-spin-6",
        "physics",
        "top.C",
        TOP,
        top__C=0.2,
        top__spin=30.0,
        effects__gravity__Mgh=2.0,
        # by hand: sqrt(4 A Mgh cos 30°)/6 = sqrt(4 x 1 x 2 x 0.866025)/6 = 2.63215/6 = 0.4387 (Mgh != 1 and
        # A = 1: a slip between A and Mgh shows)
        says="C of at least sqrt(4 A Mgh cos 30)/6 = 0.4387",
    ),
    _case(
        "top-too-slender-at-spin-6-A-2",
        "physics",
        "top.C",
        TOP,
        top__A=2.0,
        top__C=0.2,
        top__spin=30.0,
        effects__gravity__Mgh=2.0,
        # by hand: sqrt(4 x 2 x 2 x 0.866025)/6 = sqrt(13.8564)/6 = 3.72242/6 = 0.6204 (A != 1: a slip of
        # 4 A into 4/A shows as 0.3102)
        says="C of at least sqrt(4 A Mgh cos 30)/6 = 0.6204",
    ),
    _case(
        "splitting-on-the-top",
        "physics",
        "numerics.methods",
        TOP,
        numerics__methods=["dop853", "splitting4"],
        says="splitting needs a free rigid body",
    ),
    _case(
        "effects-on-a-test-problem",
        "physics",
        "effects",
        HNW,
        effects={"gravity": {"Mgh": 1.0}},
        says="no effects",
    ),
    _case(
        "splitting-on-detest",
        "physics",
        "numerics.methods",
        DETEST,
        numerics__methods=["splitting2"],
        numerics__steps=[0.1, 0.05],
        says="splitting needs a free rigid body",
    ),
    _case(
        "splitting-without-steps",
        "physics",
        "numerics.steps",
        HNW,
        numerics__steps=DELETE,
        says="step sizes for the splitting methods",
    ),
    _case(
        "long-rtol-tight-1e7",
        "physics",
        "numerics.max_periods",
        LONG,
        numerics__max_periods=1e7,
        numerics__rtol=1e-13,
        says="periods at rtol 1e-13",
    ),
    # every refusal of check() has a scene that meets it (issue 38)
    _case("top-without-top", "physics", "top", TOP, top=DELETE, says="the top's moments A, C and its spin"),
]
