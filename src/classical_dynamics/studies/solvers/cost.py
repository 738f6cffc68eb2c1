"""What a solver-layer scene costs, from its fields (scenes/cost.py).

Every rate below was measured here (2-core AMD EPYC, warm, the study's own functions timed at two sizes or
more). An adaptive method takes steps = span x (steps a unit at rtol 1e-6) x (1e-6 / rtol)^(1/p); its run
costs a call plus seconds a step. A sweep's cell (sweeps.py, heavy_top.py) is a warm-up run, the timed runs of
timing.min_time (until `repeats` or its budget is spent: at most budget + one run), and the runs that record
the steps and the dense output (2.2 runs). The heavy top's runs are measured in radians of its fastest rate,
spin + sqrt(Mgh/A): DOP853 at rtol 1e-12 took 4.1-5.4 steps a radian over every top tried (A/C 0.5-200, spin
1.4-600, inclination 2-89 degrees).
"""

from __future__ import annotations

import math

from ...scenes.cost import Work, count
from ...solvers.references import HNW_PERIOD

SWEEP_SPAN = 20.0  # the sweeps run t in [0, 20]
CONSERVATIVE = 1.5  # on every sweep's and run's time: estimates above, not below, a build

# method -> (steps a unit of time at rtol 1e-6, order p of steps ~ rtol^(-1/p), seconds a step, seconds a
# call). HNW rigid body, t in [0, 20] (workprecision.adaptive(case, method).run and one sweep cell timed at
# each rtol): steps at rtol 1e-3...1e-12 fitted (dop853 44 -> 227 steps at 1e-6 -> 1e-12, dopri5 119 -> 1833,
# LSODA 402 -> 4075, Radau 329 -> 3288 at 1e-10, BDF 454 -> 1948 at 1e-10, RK23 1041 -> 106085); a step cost
# 0.6-3 us compiled, 42-51 us scipy:DOP853, 23-33 us RK45, 4.5-5.4 us LSODA, 94-130 us Radau, 52-69 us BDF,
# 15-19 us RK23 (the largest kept). DETEST B5 took fewer steps than these at every rtol.
SWEEP_METHODS = {
    "dop853": (2.2, 8, 1.0e-6, 5e-5),
    "dopri5": (6.0, 5, 0.7e-6, 5e-5),
    "scipy:DOP853": (2.2, 8, 51e-6, 5e-4),
    "scipy:RK45": (6.0, 5, 33e-6, 5e-4),
    "scipy:LSODA": (20.0, 6, 5.4e-6, 5e-4),
    "scipy:Radau": (16.5, 4, 130e-6, 1e-3),
    "scipy:BDF": (23.0, 6, 69e-6, 1e-3),
    "scipy:RK23": (52.0, 3, 19e-6, 5e-4),
}
# The heavy top (heavy_top.work_precision, one method and rtol at a time, shipped top: 20 nutations = 46.1
# time units at 7 rad a unit): steps a radian at rtol 1e-6 (dop853 5.92 steps a unit, dopri5 and RK45 28.6,
# LSODA 78, Radau 63, BDF 67, RK23 271, over 7 rad, times 1.13 for the tops that took 5.4 steps a radian), the
# same orders fitted (BDF 1598 -> 12853 steps from 1e-4 to 1e-10).
TOP_STEPS_PER_RAD = {
    "dop853": 0.96,
    "dopri5": 4.6,
    "scipy:DOP853": 0.96,
    "scipy:RK45": 4.6,
    "scipy:LSODA": 12.6,
    "scipy:Radau": 10.1,
    "scipy:BDF": 10.8,
    "scipy:RK23": 43.6,
}
READOUT_RUNS = 2.2  # the record and dense runs of a cell (measured: 2.0-2.3 runs)
EACH_SETTING = "integration steps, a run of each setting"

# The Lie-Poisson splittings (workprecision.splitting(...).run and its sweep cell at h = 1e-3 ... 1e-5, 2e4
# ... 2e6 steps): 155-158 ns a step (order 2) and 389-399 ns (order 4) unrecorded; the recording run 40 ns a
# step more; the exact solution and the errors at every step 0.3 us a step; 123-152 bytes a step of resident
# memory at the peak.
SPLIT_S_PER_STEP = {2: 0.16e-6, 4: 0.40e-6}
SPLIT_RECORD_EXTRA_S = 0.04e-6
SPLIT_CHECK_S_PER_STEP = 0.3e-6
SPLIT_BYTES_PER_STEP = 150.0
SWEEP_FIXED_S = 2.0  # first call, DOP853 at 1e-12, two figures and tables

# The long horizon (its two calls timed at 1e4 and 1e5 periods, h = 0.05): invariant_errors 155-171 ns a step
# (order 2) and 396-436 ns (order 4), both orders over the whole span; DOP853 with 20001 outputs 496-606 ns a
# step, 2.01, 6.30 and 15.05 steps a unit of time at rtol 1e-6, 1e-10, 1e-13 (the (1e-6/rtol)^(1/8) law to 1
# %).
LONG_SPLIT_S_PER_STEP = 0.17e-6 + 0.44e-6
LONG_DOP853_S_PER_STEP = 0.61e-6
LONG_DOP853_PER_TIME = 2.0
DOP853_MAX_STEPS = 1e8  # ode.solve stops there (status 'too many steps', NaN after)
LONG_FIXED_S = 3.0
LONG_MEMORY_MB = 20001 * 15 * 8 / 1e6  # 20001 outputs: times, states, invariant errors

# The heavy top (heavy_top's parts timed one by one): general records every step and reads its integrals,
# rates and apses: 2.7 us and 134 bytes a step (20000 and 100000 nutations: 4.25 and 21.0 s, 249 and 1038 MB,
# 1.55e6 and 7.75e6 steps); steady's recorded runs and their angles 1.1 us and 193 bytes a step (2.65e6
# steps: 2.9 s, 512 MB); the other compiled runs 1.5 us a step or less (the A/C = 200 top: gyroscope 4.6 s for
# about 3e6 steps).
TOP_RECORD_S_PER_STEP = 2.7e-6
TOP_RUN_S_PER_STEP = 1.5e-6
TOP_BYTES_PER_STEP = 200.0
TOP_DOP853_PER_RAD_1E12 = 5.4  # DOP853 steps a radian at rtol 1e-12 (4.1-5.4 measured)
TOP_FIXED_S = 1.5  # roots, quadratures, figures: 0.4 s measured

# Inertia (`classical_dynamics run` on the scene at nodes 24, 60, 120: 0.42, 0.97, 4.35 s, and 70, 670 MB
# above the interpreter at 60, 120): the sphere's and tori's grids hold 2 n^3 points: 2.3-2.9 us and 324-388
# bytes an n^3.
INERTIA_S_PER_N3 = 3.0e-6
INERTIA_BYTES_PER_N3 = 400.0
INERTIA_FIXED_S = 1.0  # 0.42 s measured at 24 nodes, 1.62 s on a loaded machine
HARD_CASES_S = 8.45 * CONSERVATIVE  # hard_cases: 8.45 s measured, nothing in it grows with a field


def adaptive_steps(method: str, rtol: float, span: float) -> float:
    per_time, order, _, _ = SWEEP_METHODS[method]
    return span * per_time * (1e-6 / rtol) ** (1.0 / order)


def _cell(run_s: float, repeats: float, budget_s: float) -> tuple[float, float]:
    """A sweep cell's (untimed, timed) seconds: warm-up and read-out runs; timing.min_time's runs."""
    return (1 + READOUT_RUNS) * run_s, min(repeats * run_s, budget_s + run_s)


def cost(data: dict) -> list[Work]:
    problem, numerics = data["problem"], data.get("numerics") or {}
    if problem in ("hnw_rigid_body", "detest_b5"):
        return _sweep(numerics)
    if problem == "long_horizon":
        return _long_horizon(numerics)
    if problem == "heavy_top":
        return _heavy_top(data, numerics)
    if problem == "inertia":
        n = float(numerics.get("nodes", 24))
        return [
            Work("problem", INERTIA_FIXED_S, 0.0, "the scene's fixed work"),
            Work(
                "numerics.nodes",
                n**3 * INERTIA_S_PER_N3,
                n**3 * INERTIA_BYTES_PER_N3 / 1e6,
                count(2 * n**3, "quadrature points a body"),
            ),
        ]
    return [Work("problem", HARD_CASES_S, 0.0, "the hard cases (fixed work)")]


def _sweep(numerics: dict) -> list[Work]:
    repeats = float(numerics.get("repeats", 10))
    untimed = timed = steps = 0.0
    split_s = split_steps = largest = 0.0
    for method in numerics.get("methods", []):
        if method.startswith("splitting"):
            rate = SPLIT_S_PER_STEP[4 if method.endswith("4") else 2]
            for h in numerics.get("steps", []):
                n = SWEEP_SPAN / h
                run = n * rate
                split_s += run + n * (rate + SPLIT_RECORD_EXTRA_S + SPLIT_CHECK_S_PER_STEP)
                timed += min(repeats * run, 2.0 + run)
                split_steps += n
                largest = max(largest, n)
            continue
        if method not in SWEEP_METHODS:
            continue
        for rtol in numerics.get("tolerances", []):
            if method in ("scipy:Radau", "scipy:BDF") and rtol < 1e-10:
                continue  # the sweep leaves these out (sweeps.py)
            n = adaptive_steps(method, rtol, SWEEP_SPAN)
            once, again = _cell(SWEEP_METHODS[method][3] + n * SWEEP_METHODS[method][2], repeats, 2.0)
            untimed += once
            timed += again
            steps += n
    works = [
        Work("problem", SWEEP_FIXED_S, 0.0, "the scene's fixed work"),
        Work("numerics.tolerances", CONSERVATIVE * untimed, 0.0, count(steps, EACH_SETTING)),
        Work("numerics.repeats", CONSERVATIVE * timed, 0.0, f"{repeats:g} timed runs a setting"),
    ]
    if split_steps:
        works.append(
            Work(
                "numerics.steps",
                CONSERVATIVE * split_s,
                largest * SPLIT_BYTES_PER_STEP / 1e6,
                count(split_steps, "splitting steps, a run of each step"),
            )
        )
    return works


def _long_horizon(numerics: dict) -> list[Work]:
    span = float(numerics.get("max_periods", 1e6)) * HNW_PERIOD
    split_steps = span / numerics.get("step", 0.05)
    dop_steps = min(
        span * LONG_DOP853_PER_TIME * (1e-6 / numerics.get("rtol", 1e-10)) ** (1 / 8), DOP853_MAX_STEPS
    )
    return [
        Work("problem", LONG_FIXED_S, 0.0, "the scene's fixed work"),
        Work(
            "numerics.step",
            CONSERVATIVE * split_steps * LONG_SPLIT_S_PER_STEP,
            0.0,
            count(2 * split_steps, "splitting steps"),
        ),
        Work(
            "numerics.rtol",
            CONSERVATIVE * dop_steps * LONG_DOP853_S_PER_STEP,
            0.0,
            count(dop_steps, "DOP853 steps"),
        ),
        Work("numerics.max_periods", 0.0, LONG_MEMORY_MB, count(20001, "samples of each curve")),
    ]


# --- the heavy top ------------------------------------------------------------------------------------------
def steady_roots(A: float, J3: float, Mgh: float, alpha: float):
    """models.heavy_top.steady_roots in plain floats: (slow, fast), or None below the threshold."""
    c = math.cos(alpha)
    disc = J3 * J3 - 4.0 * A * Mgh * c
    if disc < 0:
        return None
    q = 0.5 * (J3 + math.sqrt(disc))
    return Mgh / q, (q / (A * c) if c != 0 else math.inf)


def nutation_period(A: float, C: float, Mgh: float, spin: float, alpha: float) -> float:
    """The period of heavy_top._general's nutation (started at an apse, phi' at 0.3 of the slow root), from
    the study's own closed form; inf where it has none."""
    import numpy as np

    from ...models.heavy_top import Nutation

    roots = steady_roots(A, C * spin, Mgh, alpha)
    if roots is None:
        return math.inf
    rate, s, c = 0.3 * roots[0], math.sin(alpha), math.cos(alpha)
    J3 = C * spin
    Jz = A * rate * s * s + J3 * c
    E = 0.5 * A * (rate * s) ** 2 + 0.5 * C * spin * spin + Mgh * c
    try:
        with np.errstate(all="ignore"):
            period = float(Nutation.from_integrals(A, C, Mgh, J3, Jz, E).period)
    except (ArithmeticError, ValueError, RuntimeError, TypeError, np.linalg.LinAlgError):
        return math.inf
    return period if period > 0 else math.inf


def _top_steps(radians: float, rtol: float) -> float:
    """DOP853's steps over `radians` of the top's fastest rate at rtol."""
    return radians * TOP_DOP853_PER_RAD_1E12 * (1e-12 / rtol) ** (1 / 8)


def _heavy_top(data: dict, numerics: dict) -> list[Work]:
    top, Mgh = (
        data.get("top") or {},
        float(((data.get("effects") or {}).get("gravity") or {}).get("Mgh", 1.0)),
    )
    A, C, spin = float(top.get("A", 1.0)), float(top.get("C", 0.5)), float(top.get("spin", 6.0))
    alpha = math.radians(top.get("inclination_deg", 60.0))
    rtol = float(numerics.get("rtol", 1e-12))
    wobble = math.sqrt(Mgh / A)  # the rate gravity alone sets
    rate = spin + wobble
    period = nutation_period(A, C, Mgh, spin, alpha)
    works = [Work("problem", TOP_FIXED_S, 0.0, "the scene's fixed work")]
    # _general: the nutating top over `nutations` periods, every step recorded
    nutations = float(top.get("nutations", 200))
    steps = _top_steps(nutations * period * rate, rtol)
    works.append(
        Work(
            "top.nutations",
            CONSERVATIVE * steps * TOP_RECORD_S_PER_STEP,
            steps * TOP_BYTES_PER_STEP / 1e6,
            count(steps, "integration steps"),
        )
    )
    # _steady: ten turns at each root, 30, 60, 120 degrees (the slow root's turn is the long one), recorded
    radians, longest = 0.0, 0.0
    for alpha_deg in (30.0, 60.0, 120.0):
        for turn in steady_roots(A, C * spin, Mgh, math.radians(alpha_deg)) or (0.0,):
            run = 20 * math.pi / abs(turn) * (spin + abs(turn) + wobble) if turn else math.inf
            radians += run
            longest = max(longest, run)
    radians += 20 * math.pi * 2  # the conical pendulum
    works.append(
        Work(
            "top.spin",
            CONSERVATIVE * _top_steps(radians, rtol) * TOP_RUN_S_PER_STEP,
            _top_steps(longest, rtol) * TOP_BYTES_PER_STEP / 1e6,
            count(_top_steps(radians, rtol), "steps of steady precession"),
        )
    )
    # _gyroscope (five turns recorded, 40 nutations), _oscillation (40 nutations at spin 6 at six roots),
    # _sleeping (2 x 1000 spin periods, 4000 samples upright), _descent (10 nutations, five spins),
    # _reciprocal
    J3 = 10.0 * math.sqrt(A * Mgh)
    n = J3 / C
    turn = Mgh / J3
    gyro = 10 * math.pi / turn * (n + wobble)
    sigma = math.sqrt(turn * turn + (J3 / A) ** 2)
    radians = gyro + 80 * math.pi / sigma * (n + wobble)
    for alpha_deg in (30.0, 60.0, 120.0):
        a = math.radians(alpha_deg)
        roots = steady_roots(A, 6.0 * C, Mgh, a)
        if roots is None:  # refused by check(); no estimate without the roots
            radians = math.inf
            break
        for turn in roots:
            sigma = math.sqrt((turn * math.sin(a)) ** 2 + (6.0 * C - 2 * A * turn * math.cos(a)) ** 2 / A**2)
            radians += 80 * math.pi / sigma * (6.0 + abs(turn) + wobble)
    radians += 2 * 2000 * math.pi * (1 + wobble * C / math.sqrt(4 * A * Mgh))
    radians += 200.0 * (math.sqrt(16 * A * Mgh) / C + wobble)
    radians += 5 * 20 * math.pi * A / C * 1.2
    # scipy, seven flows to 3
    reciprocal = _top_steps(7 * 3.0 * rate, 1e-13) * SWEEP_METHODS["scipy:DOP853"][2]
    works.append(
        Work(
            "top.C",
            CONSERVATIVE * (_top_steps(radians, rtol) * TOP_RUN_S_PER_STEP + reciprocal),
            _top_steps(gyro, rtol) * TOP_BYTES_PER_STEP / 1e6,
            count(_top_steps(radians, rtol), "steps of the fixed checks (A/C = " + f"{A / C:.3g})"),
        )
    )
    # _work_precision: 20 nutations by every method at every tolerance
    repeats = float(numerics.get("repeats", 5))
    radians = 20 * period * rate
    untimed = timed = steps = 0.0
    for method in numerics.get("methods", ["dop853", "scipy:DOP853", "scipy:RK45"]):
        if method not in SWEEP_METHODS:
            continue
        _, order, per_step, per_call = SWEEP_METHODS[method]
        for tol in numerics.get("tolerances", [1e-6, 1e-9, 1e-12]):
            n = radians * TOP_STEPS_PER_RAD[method] * (1e-6 / tol) ** (1 / order)
            once, again = _cell(per_call + n * per_step, repeats, 1.0)
            untimed += once
            timed += again
            steps += n
    works += [
        Work("numerics.tolerances", CONSERVATIVE * untimed, 0.0, count(steps, EACH_SETTING)),
        Work("numerics.repeats", CONSERVATIVE * timed, 0.0, f"{repeats:g} timed runs a setting"),
    ]
    return works
