"""What a self-excited-body scene costs, from its fields (scenes/cost.py).

The work is a phase portrait: a grid of starts across the window phi2_range (a few per period 2 pi of phi2, a
singular point per pi), each integrated both ways for tau_max with the compiled DOP853 at rtol 1e-12, about
1.5 us and 50 steps per unit of tau at unit rates (faster rates, sqrt|m1|, nu and the window's height p1_max,
take more); or, for Lee §5, one run of Euler's equations in the viscous medium to t_max at rtol 1e-13. Each
analysis adds a fixed piece. Measured here: every shipped scene takes 0.5 to 3.7 s; largest_perturbed_cycles
with tau_max 200 (16 times its own) took 2.0 s, estimated 6.3 s.
"""

from __future__ import annotations

import math

from ...scenes.cost import Work, count

S_PER_STEP = 1.5e-6
STEPS_PER_TAU = 50.0
STARTS_PER_PI = 3.0
ANALYSIS_S = 0.3


def cost(data: dict) -> list[Work]:
    works = [Work("body", 1.5, 0.0, "the scene's fixed work")]
    analyses = [name for name, value in data.get("analysis", {}).items() if value]
    if analyses:
        works.append(Work("analysis", ANALYSIS_S * len(analyses), 0.0, count(len(analyses), "analyses")))
    effects = data.get("effects") or {}
    if "viscous" in data:
        v = data["viscous"]
        drag = effects.get("drag") or {}
        rate = (
            1.0
            + max(abs(x) for x in v["omega0"])
            + math.sqrt(max(abs(x) for x in (effects.get("body_torque") or {}).get("m", [0.0])))
            + drag.get("nu", 0.0)
            + drag.get("mu", 0.0)
        )
        steps = 2 * v["t_max"] * rate * STEPS_PER_TAU * 4  # the run, and the analyses' reruns of it
        works.append(Work("viscous.t_max", steps * S_PER_STEP, 0.0, count(steps, "integration steps")))
        return works
    view = data.get("portrait", {})
    lo, hi = view.get("phi2_range", [-3 * math.pi, 3 * math.pi])
    p1_max, tau_max = view.get("p1_max", 3.0), view.get("tau_max", 12.0)
    m1 = (effects.get("body_torque") or {}).get("m1", 0.0)
    nu = (effects.get("quadratic_torque") or {}).get("nu", 0.0)
    rate = 1.0 + math.sqrt(abs(m1)) + (nu if isinstance(nu, (int, float)) else 1.0) + p1_max
    starts = STARTS_PER_PI * ((hi - lo) / math.pi + 1)
    steps = starts * 2 * tau_max * rate * STEPS_PER_TAU
    field = "portrait.tau_max" if tau_max > 12.0 else "portrait.phi2_range"
    works.append(Work(field, steps * S_PER_STEP, 0.0, count(steps, "integration steps")))
    return works
