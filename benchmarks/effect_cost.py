"""What each effect costs, study by study, side by side in one run (printed, not asserted).

For each study one model with all its listed effects, then the same model with one effect removed: the time
of the same integration (minimum of repeats after a warm-up), the right-hand side's evaluations, and the
ratio to the full model. An effect that is not listed is skipped, so removing one should never cost more;
how much less it costs says what its term weighs. (The physics of each removal is tested against closed forms
in tests/test_effects_remove_terms.py; times are never asserted.)

    python benchmarks/effect_cost.py
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from numba import njit

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))
from classical_dynamics.models import chains, earth, wobble
from classical_dynamics.models import heavy_top as top_model
from classical_dynamics.models import precession as prec
from classical_dynamics.models import self_excited as se
from classical_dynamics.models.viscous_medium import viscous_symmetric
from classical_dynamics.provenance import software_stamp
from classical_dynamics.solvers.ode import Problem, solve
from classical_dynamics.solvers.timing import min_time
from classical_dynamics.studies.self_excited import viscous


def _without(effects: dict, name: str | None) -> dict:
    return {k: v for k, v in effects.items() if k != name}


def _chandler(effects):
    model = wobble.assemble(earth.H_MHB2000, effects)
    problem = Problem(wobble.liouville, [1e-6, 0.0, 1.0], (0.0, 20 * 365.25), model.parameters())
    return problem, dict(rtol=1e-10, atol=1e-16)


CHANDLER = {
    "triaxiality": {},
    "elastic_yielding": {"k2": 0.30},
    "dissipation": {"Q": 179},
    "excitation": {"random": {"seed": 1, "terms": 100, "rms_mas": 20, "periods_days": [20, 4000]}},
}


def _precession(effects):
    model = prec.assemble(earth.H_P03, np.radians(23.44), prec.modern(), effects)
    s0 = np.array([0.0, np.sin(model.obliquity), np.cos(model.obliquity)])
    problem = Problem(prec.averaged_rhs, s0, (0.0, 2000 * 365.25), prec.averaged_parameters(model))
    return problem, dict(rtol=1e-12, atol=1e-15)


PRECESSION = {"solar_torque": {}, "lunar_torque": {}, "lunar_inclination": {}, "node_regression": {}}


def _plane(effects):
    m1, nu = se.plane_torque(effects)
    L = se.LargestAxis.for_scene(se.Body(3.0, 2.2, 1.2), m1, -nu, 1.0)
    problem = Problem(se.plane_largest, [0.3, 0.8], (0.0, 200.0), [L.m1, L.mu1, 1.0])
    return problem, dict(rtol=1e-12, atol=1e-14)


PLANE = {"body_torque": {"m1": 0.5}, "quadratic_torque": {"nu": 0.1}}


def _medium(effects):
    data = {"body": {"moments": [2.5, 2.5, 1.0]}, "viscous": {"omega0": [0.5, 0.8, 2.0]}, "effects": effects}
    V = viscous.medium(data)
    problem = Problem(viscous_symmetric, [0.5, 0.8, 2.0], (0.0, 60.0), V.parameters())
    return problem, dict(rtol=1e-12, atol=1e-14)


MEDIUM = {"body_torque": {"m": [0.4, -0.2, 0.3]}, "drag": {"nu": 0.3, "mu": 0.5}}


def _top(effects):
    mgh = top_model.EFFECTS.assemble(effects, None).get("gravity", 0.0)
    y0 = np.concatenate([[0.3, 0.0, 5.0], [0.2, 0.0, np.sqrt(1 - 0.04)], [1.0, 0.0, 0.0]])
    problem = Problem(top_model.top_gravity, y0, (0.0, 200.0), [1.0, 0.6, mgh])
    return problem, dict(rtol=1e-12, atol=1e-14)


TOP = {"gravity": {"Mgh": 0.8}}


def _chain(effects):
    return lambda: chains.particle_chain(400, "fixed-fixed", 1.0, 0.01, effects).stiffness_matrix(), None


CHAIN = {"tension": {"newton": 2.0}, "springs": {"k_n_per_m": 3.0}, "friction": {"b_kg_per_s": 0.1}}

STUDIES = [
    ("chandler (20 years of wobble, rtol 1e-10)", _chandler, CHANDLER),
    ("precession (2000 years, averaged equations)", _precession, PRECESSION),
    ("self_excited (Lee's plane, tau = 200)", _plane, PLANE),
    ("self_excited (Lee §5 medium, t = 60)", _medium, MEDIUM),
    ("solvers (the heavy top, t = 200)", _top, TOP),
    ("chains (400 beads: assembling K)", _chain, CHAIN),
]


@njit
def _call_many(rhs, y, p, out, n):
    """n calls of a compiled right-hand side at one state: what its terms cost, without the integrator."""
    for i in range(n):
        rhs(1e-3 * i, y, p, out)
    return out[0]


def _per_call_ns(problem) -> float:
    out, n = np.empty_like(problem.y0), 200_000
    _call_many(problem.rhs, problem.y0, problem.params, out, 1)  # compile for this right-hand side
    seconds, _, _ = min_time(lambda: _call_many(problem.rhs, problem.y0, problem.params, out, n), repeats=7)
    return seconds / n * 1e9


def main():
    print(f"machine: {software_stamp()}\n")
    print(
        "Removing an effect changes the motion, so the integrator takes other steps (the run's time and its"
        "\nright-hand-side calls); what the effect's term itself weighs is the time of one call of the"
        "\nright-hand side at the start (ns/call), timed in a compiled loop.\n"
    )
    head = f"  {'effect removed':<22s} {'run':>10s} {'/ all':>7s} {'RHS calls':>10s} {'/ all':>7s}"
    print(head + f" {'ns/call':>8s} {'/ all':>7s}")
    for title, build, effects in STUDIES:
        print(title)
        full = None
        for removed in [None, *effects]:
            problem, options = build(_without(effects, removed))
            if options is None:  # no right-hand side: the model's assembly is the work
                seconds, _, _ = min_time(problem, repeats=7, budget_s=2.0)
                calls = per_call = None
            else:
                seconds, result, _ = min_time(lambda: solve(problem, **options), repeats=7, budget_s=2.0)
                calls, per_call = result.nfev, _per_call_ns(problem)
            if removed is None:
                full = (seconds, calls, per_call)
            label = "(none: all listed)" if removed is None else removed
            row = f"  {label:<22s} {seconds * 1e3:>8.2f}ms {seconds / full[0]:>7.2f}"
            if calls:
                row += f" {calls:>10d} {calls / full[1]:>7.2f} {per_call:>8.1f} {per_call / full[2]:>7.2f}"
            print(row)
        print()


if __name__ == "__main__":
    main()
