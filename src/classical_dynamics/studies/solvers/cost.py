"""What a solver-layer scene costs, from its fields (scenes/cost.py).

Rates measured here (2-core AMD EPYC) on the HNW rigid body (period 4.83): the compiled Lie-Poisson splittings
0.16 us (order 2) and 0.40 us (order 4) a step; the compiled DOP853 0.7-1.0 us a step, with 9.8, 30 and 73 steps a
period at rtol 1e-6, 1e-10 and 1e-13 (steps grow as rtol^(-1/8), the method's order); scipy's solve_ivp pays
Python's overhead on every step. The heavy top at 200 and 2000 nutations took 8.5 and 8.0 s: its sweep, not its
length, is what costs.
"""

from __future__ import annotations

from ...scenes.cost import Work, count

HNW_PERIOD = 4.8319
SWEEP_SPAN = 20.0                       # the sweeps run t in [0, 20]
SPLIT_S_PER_STEP = {2: 0.16e-6, 4: 0.40e-6}
# method -> (order, steps a unit of time at rtol 1e-6 on these problems, seconds a step)
ADAPTIVE = {
    "dop853": (8, 2.0, 1.0e-6), "dopri5": (5, 4.0, 0.7e-6),
    "scipy:DOP853": (8, 2.0, 1.2e-4), "scipy:RK45": (5, 4.0, 6e-5), "scipy:RK23": (3, 12.0, 5e-5),
    "scipy:Radau": (5, 3.0, 6e-4), "scipy:BDF": (4, 8.0, 3e-4), "scipy:LSODA": (4, 6.0, 2e-4),
}
CALL_S = 2e-4                           # one integration's fixed cost


def adaptive_steps(method: str, rtol: float, span: float) -> float:
    order, per_time, _ = ADAPTIVE[method]
    return span * per_time * (1e-6 / rtol) ** (1 / order)


def _timed(run_s: float, repeats: int, budget_s: float) -> float:
    """What timing.min_time spends: a warm-up, then runs until `repeats` or the budget is spent."""
    return run_s + min(repeats * run_s, budget_s + run_s)


def cost(data: dict) -> list[Work]:
    problem, numerics = data["problem"], data.get("numerics", {})
    works = [Work("problem", 1.0, 0.0, "the scene's fixed work")]
    if problem in ("hnw_rigid_body", "detest_b5"):
        repeats = numerics.get("repeats", 10)
        split = [0.0, 0.0]                  # seconds, steps: numerics.steps
        adapt = [0.0, 0.0]                  # numerics.tolerances
        for method in numerics["methods"]:
            if method.startswith("splitting"):
                for h in numerics.get("steps", []):
                    steps = SWEEP_SPAN / h
                    split[0] += _timed(steps * SPLIT_S_PER_STEP[4 if method.endswith("4") else 2] + CALL_S,
                                       repeats, 2.0)
                    split[1] += steps
                continue
            for rtol in numerics["tolerances"]:
                if method in ("scipy:Radau", "scipy:BDF") and rtol < 1e-10:
                    continue                                    # the sweep leaves these out (sweeps.py)
                steps = adaptive_steps(method, rtol, SWEEP_SPAN)
                adapt[0] += _timed(steps * ADAPTIVE[method][2] + CALL_S, repeats, 2.0)
                adapt[1] += steps
        works.append(Work("numerics.tolerances", adapt[0], 0.0, count(adapt[1], "integration steps")))
        if split[1]:
            works.append(Work("numerics.steps", split[0], 0.0, count(split[1], "splitting steps")))
    elif problem == "long_horizon":
        span = numerics["max_periods"] * HNW_PERIOD
        split_steps = span / numerics["step"]
        works.append(Work("numerics.step", split_steps * (SPLIT_S_PER_STEP[2] + SPLIT_S_PER_STEP[4]), 0.0,
                          count(2 * split_steps, "splitting steps")))
        dop_steps = adaptive_steps("dop853", numerics["rtol"], span)
        works.append(Work("numerics.rtol", dop_steps * ADAPTIVE["dop853"][2], 0.0,
                          count(dop_steps, "DOP853 steps")))
        works.append(Work("numerics.max_periods", 0.0, 60 * 20001 * 8e-6, count(20001, "samples")))
    elif problem == "heavy_top":
        top = data.get("top", {})
        works.append(Work("top.nutations", 2e-4 * top.get("nutations", 200), 0.0,
                          count(top.get("nutations", 200), "nutations")))
        repeats = numerics.get("repeats", 5)
        seconds = sum(_timed(adaptive_steps(method, rtol, 200.0) * ADAPTIVE[method][2] + CALL_S, repeats, 1.0)
                      for method in numerics.get("methods", ["dop853", "scipy:DOP853", "scipy:RK45"])
                      for rtol in numerics.get("tolerances", [1e-6, 1e-9, 1e-12]))
        works.append(Work("numerics.tolerances", seconds, 0.0, "the tolerance sweep"))
    elif problem == "hard_cases":
        works.append(Work("numerics.separatrix_one_minus_m", 6.0, 0.0, "the hard cases"))
    return works
