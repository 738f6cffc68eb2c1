"""Bad scenes of the solver-layer study (see __init__.py)."""

from . import DELETE, BadScene

HNW, DETEST, LONG, HARD, TOP, INERTIA = ("hnw_rigid_body.yaml", "detest_b5.yaml", "long_horizon.yaml",
                                         "hard_cases.yaml", "heavy_top.yaml", "inertia.yaml")


def _case(id_, kind, field, base, **set_):
    return BadScene(f"solvers-{id_}", "solvers", kind, field, base=base, set={k.replace("__", "."): v
                                                                              for k, v in set_.items()})


CASES = [
    # the cases: steps of 1e-30 (numba then failed with "Int value is too large"), 1 - m of 1e-300
    _case("sweep-step-1e-30", "precision", "numerics.steps.1", HNW, numerics__steps=[0.1, 1e-30]),
    _case("long-step-1e-30", "precision", "numerics.step", LONG, numerics__step=1e-30),
    _case("long-step-1e-13", "precision", "numerics.step", LONG, numerics__step=1e-13),
    _case("separatrix-1e-300", "precision", "numerics.separatrix_one_minus_m", HARD,
          numerics__separatrix_one_minus_m=1e-300),
    _case("separatrix-1e-16", "precision", "numerics.separatrix_one_minus_m", HARD,
          numerics__separatrix_one_minus_m=1e-16),
    _case("rtol-1e-20", "precision", "numerics.rtol", LONG, numerics__rtol=1e-20),
    _case("tolerance-1e-300", "precision", "numerics.tolerances.1", DETEST, numerics__tolerances=[1e-3, 1e-300]),
    # over the budget
    _case("sweep-step-1e-9", "cost", "numerics.steps", HNW, numerics__steps=[0.1, 1e-9]),
    _case("long-1e7-periods-small-step", "cost", "numerics.step", LONG, numerics__max_periods=1e7,
          numerics__step=0.001),
    _case("long-1e7-periods", "cost", "numerics.step", LONG, numerics__max_periods=1e7, numerics__step=0.02),
    _case("long-rtol-tight-1e7", "cost", "numerics.rtol", LONG, numerics__max_periods=1e7, numerics__rtol=1e-13),
    # finite ranges
    _case("A-1e300", "range", "top.A", TOP, top__A=1e300),
    _case("C-minus", "range", "top.C", TOP, top__C=-1.0),
    _case("spin-1e300", "range", "top.spin", TOP, top__spin=1e300),
    _case("Mgh-1e300", "range", "effects.gravity.Mgh", TOP, effects__gravity__Mgh=1e300),
    _case("nutations-1e9", "range", "top.nutations", TOP, top__nutations=10**9),
    _case("max-periods-1e300", "range", "numerics.max_periods", LONG, numerics__max_periods=1e300),
    _case("nodes-1e6", "range", "numerics.nodes", INERTIA, numerics__nodes=10**6),
    _case("repeats-1e6", "range", "numerics.repeats", HNW, numerics__repeats=10**6),
    _case("inclination-90", "range", "top.inclination_deg", TOP, top__inclination_deg=90.0),
    _case("too-many-tolerances", "range", "numerics.tolerances", DETEST, numerics__tolerances=[1e-6] * 31),
    # the schema's shape
    _case("problem-unknown", "schema", "problem", HNW, problem="kepler"),
    _case("method-unknown", "schema", "numerics.methods.0", HNW, numerics__methods=["euler"]),
    _case("tolerance-text", "schema", "numerics.tolerances.0", DETEST, numerics__tolerances=["tight", 1e-6]),
    _case("top-missing-spin", "schema", "top.spin", TOP, top__spin=DELETE),
    # physics
    _case("top-not-a-body", "physics", "top.C", TOP, top__C=3.0),
    _case("top-without-gravity", "physics", "effects.gravity", TOP, effects=DELETE),
    _case("effects-on-a-test-problem", "physics", "effects", HNW, effects={"gravity": {"Mgh": 1.0}}),
    _case("splitting-on-detest", "physics", "numerics.methods", DETEST, numerics__methods=["splitting2"],
          numerics__steps=[0.1, 0.05]),
    _case("splitting-without-steps", "physics", "numerics.steps", HNW, numerics__steps=DELETE),
]
