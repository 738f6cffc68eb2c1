"""Bad scenes of the self-excited-body study (see __init__.py)."""

from functools import partial

from . import DELETE, case

LARGEST, MIDDLE, VISCOUS = (
    "largest_perturbed_cycles.yaml",
    "middle_perturbed.yaml",
    "viscous_constant_torque.yaml",
)
EXCURSION = "middle_near_critical.yaml"
UNPERTURBED, PLANE_ONE = "largest_unperturbed.yaml", "middle_plane_one.yaml"


_case = partial(case, "self_excited")

CASES = [
    # the cases: tau_max and t_max of 1e15, a window of +-1e300, alpha of 1e308
    _case("tau-max-1e15", "range", "portrait.tau_max", LARGEST, portrait={"tau_max": 1e15}),
    _case("t-max-1e15", "range", "viscous.t_max", VISCOUS, viscous__t_max=1e15),
    _case(
        "phi2-range-1e300",
        "range",
        "portrait.phi2_range.1",
        LARGEST,
        portrait={"phi2_range": [-1e300, 1e300]},
    ),
    _case("alpha-1e308", "range", "plane.alpha.1", MIDDLE, plane__alpha=[1e308, 1e308]),
    _case("delta-1e300", "range", "plane.delta", LARGEST, plane__delta=1e300),
    _case("m1-1e300", "range", "effects.body_torque.m1", LARGEST, effects__body_torque__m1=1e300),
    _case("omega0-1e300", "range", "viscous.omega0.2", VISCOUS, viscous__omega0=[0.5, 0.8, 1e300]),
    _case(
        "torque-minus-1e300",
        "range",
        "effects.body_torque.m.0",
        VISCOUS,
        effects__body_torque__m=[-1e300, 0.0, 0.5],
    ),
    _case("moments-1e300", "range", "body.moments.0", LARGEST, body__moments=[1e300, 2.2, 1.2]),
    _case("q0-1e300", "range", "excursion.q0", MIDDLE, excursion={"q0": 1e300}),
    # over the budget
    _case(
        "tau-max-10000-fast",
        "cost",
        "portrait.tau_max",
        LARGEST,
        portrait={"tau_max": 10000.0, "p1_max": 100.0},
    ),
    _case(
        "wide-window-long",
        "cost",
        "portrait.tau_max",
        LARGEST,
        portrait={"phi2_range": [-100.0, 100.0], "tau_max": 1000.0, "p1_max": 50.0},
    ),
    _case("t-max-1e6", "cost", "viscous.t_max", VISCOUS, viscous__t_max=1e6),
    _case(
        "t-max-fast-spin",
        "cost",
        "viscous.t_max",
        VISCOUS,
        viscous__t_max=1e5,
        viscous__omega0=[0.5, 0.8, 1000.0],
    ),
    # the schema's shape
    _case("two-moments", "schema", "body.moments", LARGEST, body__moments=[3.0, 2.2]),
    _case("axis-unknown", "schema", "torque_axis", LARGEST, torque_axis="diagonal"),
    _case(
        "nu-text",
        "schema",
        "effects.quadratic_torque.nu",
        LARGEST,
        effects__quadratic_torque__nu="strong",
        says="a number from 0 to 100 or 'nu_c'",
    ),
    # the model is its effects: a parameter in its old place is refused, naming where it moved
    _case("m1-in-plane", "schema", "plane.m1", LARGEST, plane__m1=0.5),
    _case("drag-in-viscous", "schema", "viscous.nu", VISCOUS, viscous__nu=0.3),
    _case(
        "zero-medium-torque",
        "physics",
        "effects.body_torque.m",
        VISCOUS,
        effects__body_torque__m=[0.0, 0.0, 0.0],
        says="a torque that is not zero",
    ),
    _case(
        "zero-quadratic-torque",
        "physics",
        "effects.quadratic_torque.nu",
        LARGEST,
        effects__quadratic_torque__nu=0.0,
        says="nu != 0",
    ),
    _case(
        "medium-torque-in-plane",
        "physics",
        "effects.body_torque.m",
        LARGEST,
        effects__body_torque={"m": [0.1, 0.0, 0.0]},
        says="m1 in a phase-plane scene",
    ),
    _case(
        "plane-torque-in-medium",
        "physics",
        "effects.body_torque.m1",
        VISCOUS,
        effects__body_torque={"m1": 0.5},
        says="m in a viscous-medium scene",
    ),
    _case("no-moments", "schema", "body.moments", LARGEST, body__moments=DELETE),
    _case("negative-moment", "schema", "body.moments.2", LARGEST, body__moments=[3.0, 2.2, -1.2]),
    # physics
    _case(
        "not-a-body",
        "physics",
        "body.moments",
        LARGEST,
        body__moments=[4.0, 2.5, 1.0],
        says="each less than the sum of the other two",
    ),
    _case(
        "equal-moments-plane",
        "physics",
        "body.moments",
        LARGEST,
        body__moments=[3.0, 3.0, 1.2],
        says="three different moments",
    ),
    _case(
        "no-cylinder",
        "physics",
        "plane.delta",
        LARGEST,
        plane__delta=DELETE,
        says="the elliptic cylinder delta",
    ),
    _case(
        "alpha-both-zero",
        "physics",
        "plane.alpha",
        MIDDLE,
        plane__alpha=[0.0, 0.0],
        says="not both alpha zero",
    ),
    _case(
        "window-reversed",
        "physics",
        "portrait.phi2_range",
        LARGEST,
        portrait={"phi2_range": [3.0, -3.0]},
        says="low < high",
    ),
    _case(
        "viscous-not-symmetric",
        "physics",
        "body.moments",
        VISCOUS,
        # a body that can exist (1 + 2 > 2.5) but has no two moments equal: refused as not symmetric, not as
        # not a body ([1, 2, 3] was, on the triangle inequality, before the check this case is for)
        body__moments=[1.0, 2.0, 2.5],
        says="a symmetric body, two moments equal",
    ),
    _case(
        "excursion-on-largest",
        "physics",
        "excursion",
        LARGEST,
        excursion={"q0": 1.0},
        says="torque_axis: middle",
    ),
    # every refusal of check() has a scene that meets it (issue 38)
    _case(
        "no-torque-axis",
        "physics",
        "torque_axis",
        LARGEST,
        torque_axis=DELETE,
        says="torque_axis and plane (a phase-plane scene), or viscous",
    ),
    _case(
        "nu-c-on-largest",
        "physics",
        "effects.quadratic_torque.nu",
        LARGEST,
        effects__quadratic_torque__nu="nu_c",
        says="nu_c is the middle axis' critical drag",
    ),
    _case(
        "motion-in-space-without-F",
        "physics",
        "analysis.motion_in_space",
        LARGEST,
        # no drag-like part: no limit cycle F to start on
        effects__quadratic_torque=DELETE,
        says="a plane with the limit cycle F",
    ),
    _case(
        "motions-with-drag",
        "physics",
        "analysis.motions",
        UNPERTURBED,
        effects__quadratic_torque={"nu": 0.1},
        says="no quadratic_torque",
    ),
    _case(
        "zero-plane-torque",
        "physics",
        "effects.body_torque.m1",
        UNPERTURBED,
        # without the quadratic torque, m1 = 0 on the plane is M = 0 in the body
        effects__body_torque__m1=0.0,
        says="M = 0 here: leave it out",
    ),
    _case(
        "plane-one-alpha-negative",
        "physics",
        "plane.alpha",
        PLANE_ONE,
        plane__alpha=[-0.6, 0.6],
        says="alpha1 > 0 in the planes of the separating polhodes",
    ),
    _case(
        "alpha-sum-negative",
        "physics",
        "plane.alpha",
        MIDDLE,
        plane__alpha=[-0.8, 0.3],
        says="alpha1 + alpha2 > 0",
    ),
    _case(
        "excursion-above-critical",
        "physics",
        "excursion",
        EXCURSION,
        # nu_c = 0.409 for this body (the scene's source): nu = 1 is above it
        effects__quadratic_torque__nu=1.0,
        says="a plane below the critical drag",
    ),
    _case(
        "excursion-without-spin",
        "physics",
        "excursion.q0",
        EXCURSION,
        excursion__q0=0.0,
        says="a spin q0 != 0",
    ),
    _case(
        "quadratic-torque-in-medium",
        "physics",
        "effects.quadratic_torque",
        VISCOUS,
        effects__quadratic_torque={"nu": 0.1},
        says="body_torque and drag only (Lee §5)",
    ),
    _case(
        "plane-in-medium",
        "physics",
        "torque_axis",
        VISCOUS,
        torque_axis="largest",
        says="no phase plane in a viscous-medium scene",
    ),
    _case(
        "no-axial-drag",
        "physics",
        "effects.drag.mu",
        VISCOUS,
        effects__drag__mu=0.0,
        says="both drags positive (the medium resists equatorial and axial turning alike), got [0.3, 0.0]",
    ),
    _case(
        "drag-ratio-integer",
        "physics",
        "effects.drag.nu",
        VISCOUS,
        # nu/mu = 0.5/0.5 = 1 where Lee's generalized integrals are needed (h = 0.6, r0 = 2 != m3/mu = 0.6)
        effects__drag__nu=0.5,
        says="nu/mu not an integer",
    ),
]
