"""Bad scenes of the chains study (see __init__.py)."""

from functools import partial

from . import DELETE, case

HP, TD, RING, LINKS = (
    "hanging_particles.yaml",
    "hanging_time_domain.yaml",
    "rotating_ring.yaml",
    "hanging_links.yaml",
)
STR3, FORCED, FRICTION = (
    "three_particles_string.yaml",
    "three_particles_forced.yaml",
    "three_particles_friction.yaml",
)


OZONE, CONTINUUM = "ozone_molecule.yaml", "hanging_continuum.yaml"

_case = partial(case, "chains")

CASES = [
    # a count written as a float validated, then stopped the run inside numpy
    _case("n-as-float", "schema", "chain.n", "loaded_string.yaml", chain__n=10.0),
    # the cases: ten million particles or links, ~10^10 RATTLE steps
    _case("n-1e7-particles-50-modes", "cost", "chain.n", HP, chain__n=10_000_000, analysis__modes=50),
    _case("n-1e8", "range", "chain.n", "loaded_string.yaml", chain__n=100_000_000),
    _case("n-1e7-links", "cost", "chain.n", LINKS, chain__n=10_000_000),
    _case("large-n-1e8", "range", "analysis.large_n.n", HP, analysis__large_n__n=100_000_000),
    _case(
        "convergence-1e7",
        "cost",
        "analysis.convergence.n_values",
        LINKS,
        analysis__convergence__n_values=[1, 10_000_000],
    ),
    _case(
        "accuracy-cost-1e300",
        "range",
        "analysis.accuracy_cost.n_values.1",
        HP,
        analysis__accuracy_cost__n_values=[16, 10**300],
    ),
    _case(
        "time-domain-1e10-steps",
        "cost",
        "analysis.time_domain.long_run_periods",
        TD,
        analysis__time_domain__long_run_periods=1_000_000,
        analysis__time_domain__steps_per_fastest_period=10000,
    ),
    _case("time-domain-many-links", "cost", "analysis.time_domain.long_run_periods", TD, chain__n=2000),
    _case("ring-3000-beads", "physics", "chain.n", RING, chain__n=3000),
    _case(
        "constraint-big-n",
        "cost",
        "analysis.constraint.samples",
        STR3,
        chain__n=3000,
        analysis={"modes": 3, "constraint": {"samples": 200, "seed": 1}},
    ),
    _case(
        "friction-sympy-12",
        "cost",
        "chain.n",
        FRICTION,
        chain__n=12,
        effects__friction__b_kg_per_s=[0.5] + [0.0] * 11,
    ),
    _case(
        "forced-points-big-n",
        "cost",
        "analysis.forced.points",
        FORCED,
        chain__n=5000,
        effects__forcing__newton=[1.0] + [0.0] * 4999,
    ),
    _case(
        "initial-value-periods",
        "cost",
        "analysis.initial_value.periods",
        STR3,
        chain__n=300,
        analysis__constraint__samples=0,
        analysis__closed_form=DELETE,
        analysis__rayleigh_symmetric=DELETE,
        analysis__initial_value__periods=1000,
    ),
    # finite ranges
    _case("length-1e300", "range", "chain.length_m", HP, chain__length_m=1e300),
    _case("length-tiny", "range", "chain.length_m", HP, chain__length_m=1e-300),
    _case("mass-1e300", "range", "chain.mass_kg", HP, chain__mass_kg=1e300),
    _case("g-1e300", "range", "effects.gravity.g_m_per_s2", HP, effects__gravity__g_m_per_s2=1e300),
    _case(
        "omega-1e300",
        "range",
        "effects.rotation.omega_rad_per_s",
        "rotating_chain_in_plane.yaml",
        effects__rotation__omega_rad_per_s=1e300,
    ),
    _case(
        "springs-1e300",
        "range",
        "effects.springs.k_n_per_m",
        "spring_chain.yaml",
        effects__springs__k_n_per_m=1e300,
    ),
    _case(
        "tension-minus-1e300",
        "range",
        "effects.tension.newton",
        "loaded_string.yaml",
        effects__tension__newton=-1e300,
    ),
    _case(
        "forcing-1e300",
        "range",
        "effects.forcing.newton.0",
        FORCED,
        effects__forcing__newton=[1e300, 0.0, 0.0],
    ),
    _case(
        "beta-1e300",
        "range",
        "analysis.rayleigh.beta_max",
        "hanging_continuum.yaml",
        analysis__rayleigh__beta_max=1e300,
    ),
    _case("seed-huge", "range", "analysis.constraint.seed", STR3, analysis__constraint__seed=2**70),
    _case(
        "period-count-huge",
        "range",
        "analysis.time_domain.long_run_periods",
        TD,
        analysis__time_domain__long_run_periods=1e300,
    ),
    # the schema's shape
    _case("n-text", "schema", "chain.n", HP, chain__n="ten"),
    _case("n-float", "schema", "chain.n", HP, chain__n=10.5),
    _case("no-length", "schema", "chain.length_m", HP, chain__length_m=DELETE),
    _case("model-unknown", "schema", "chain.model", HP, chain__model="rope"),
    _case("modes-100", "schema", "analysis.modes", HP, analysis__modes=100),
    # physics
    _case("gravity-on-string", "physics", "chain.ends", HP, chain__ends="fixed-fixed"),
    _case(
        "masses-wrong-length", "physics", "chain.masses_kg", "two_unequal_masses.yaml", chain__masses_kg=[1.0]
    ),
    _case("ring-small", "physics", "chain.n", RING, chain__n=8),
    _case(
        "membrane-even",
        "physics",
        "analysis.membrane.points",
        "hanging_continuum.yaml",
        analysis__membrane__points=40,
    ),
    _case("forced-without-force", "physics", "analysis.forced", FORCED, effects__forcing=DELETE),
    # each of check()'s remaining refusals (studies/chains/__init__.py), one scene apiece
    _case("triangle-with-gravity", "physics", "effects", OZONE, effects__gravity={"g_m_per_s2": 9.81}),
    _case("triangle-springs-list", "physics", "effects", OZONE, effects__springs__k_n_per_m=[1.0, 1.0, 1.0]),
    _case("triangle-with-n", "physics", "chain", OZONE, chain__n=3),
    _case("triangle-with-analysis", "physics", "chain", OZONE, analysis={"modes": 3}),
    _case("particles-without-n", "physics", "chain.n", HP, chain__n=DELETE),
    _case("continuum-with-n", "physics", "chain.n", CONTINUUM, chain__n=10),
    _case(
        "gravity-and-rotation",
        "physics",
        "effects",
        "rotating_chain_in_plane.yaml",
        effects__gravity={"g_m_per_s2": 9.81},
    ),
    _case("links-on-springs", "physics", "effects", LINKS, effects={"springs": {"k_n_per_m": 1.0}}),
    _case(
        "continuum-on-springs",
        "physics",
        "effects.springs",
        CONTINUUM,
        effects={"springs": {"k_n_per_m": 1.0}},
        analysis={"modes": 5},
    ),
    _case(
        "free-free-one-particle",
        "physics",
        "chain.n",
        "spring_chain.yaml",
        chain__ends="free-free",
        chain__n=1,
        analysis={"modes": 1},
    ),
    _case(
        "masses-on-links",
        "physics",
        "chain.masses_kg",
        LINKS,
        chain__mass_kg=DELETE,
        chain__masses_kg=[0.1] * 10,
    ),
    _case("no-mass", "physics", "chain.mass_kg", HP, chain__mass_kg=DELETE),
    _case(
        "springs-list-short",
        "physics",
        "effects.springs.k_n_per_m",
        "spring_chain.yaml",
        effects__springs__k_n_per_m=[1.0] * 32,
    ),
    _case("friction-alone", "physics", "effects", FRICTION, effects__tension=DELETE, analysis={"modes": 3}),
    _case(
        "friction-on-continuum",
        "physics",
        "effects.friction",
        CONTINUUM,
        effects__friction={"b_kg_per_s": 0.5},
        analysis={"modes": 5},
    ),
    _case(
        "friction-values-short",
        "physics",
        "effects.friction.b_kg_per_s",
        FRICTION,
        effects__friction__b_kg_per_s=[0.5, 0.0],
    ),
    _case(
        "stability-unequal-masses",
        "physics",
        "analysis.stability",
        "two_masses_equal_springs.yaml",
        chain__mass_kg=DELETE,
        chain__masses_kg=[1.0, 2.0],
    ),
    _case(
        "separation-three", "physics", "analysis.separation", STR3, analysis={"modes": 3, "separation": True}
    ),
    _case("rayleigh-symmetric-four", "physics", "analysis.rayleigh_symmetric", STR3, chain__n=4),
    _case("dispersion-on-links", "physics", "analysis.dispersion", LINKS, analysis__dispersion=True),
    _case(
        "rayleigh-on-particles",
        "physics",
        "analysis.rayleigh",
        HP,
        analysis={"modes": 5, "rayleigh": {"beta_min": -3.0, "beta_max": 3.0}},
    ),
    _case(
        "accuracy-cost-on-springs",
        "physics",
        "analysis",
        HP,
        effects={"springs": {"k_n_per_m": 1.0}},
        analysis={"modes": 5, "large_n": {"n": 1000}},
    ),
    _case(
        "galerkin-too-many",
        "physics",
        "analysis.galerkin.elements",
        CONTINUUM,
        analysis__galerkin__elements=[1000, 200_000],
    ),
    _case(
        "beta-min-over-max",
        "physics",
        "analysis.rayleigh.beta_max",
        CONTINUUM,
        analysis__rayleigh__beta_min=3.0,
    ),
    _case("ring-with-gravity", "physics", "effects", RING, effects__gravity={"g_m_per_s2": 9.81}),
    _case("ring-with-ends", "physics", "chain", RING, chain__ends="fixed-free"),
    _case(
        "ring-springs-list",
        "physics",
        "effects.springs.k_n_per_m",
        RING,
        effects__springs__k_n_per_m=[1.0] * 400,
    ),
    _case(
        "ring-without-waves",
        "physics",
        "analysis",
        RING,
        analysis={"gyroscopic": {"beta": 3.0, "epsilon": 1.0e-4, "bowl_friction": 0.1}},
    ),
]
