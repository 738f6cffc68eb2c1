"""What a Chandler-wobble scene costs, from its fields (scenes/cost.py).

Rates measured here (2-core AMD EPYC), 200 years of the model Earth with the compiled DOP853: the rigid Earth
takes 21, 37 and 59 steps a year at rtol 1e-10, 1e-12 and 2.3e-14 (as rtol^(-1/8)) at 0.65 us a step; the
excited Earth (300 random terms, shortest period 20 days) 100, 177 and 281 steps a year at 50 us a step, the
sum over its terms costing ~0.16 us a term a step. Results are sampled every 2 days: ~150 bytes a sample held.
"""

from __future__ import annotations

from ...models.earth import JULIAN_YEAR_DAYS as YEAR_DAYS
from ...scenes.cost import Work, count

DEFAULT_SPAN_YEARS = 100.0  # a model run's span when its scene gives no analysis.span_years

SAMPLE_DAYS = 2.0
BYTES_PER_SAMPLE = 150.0
RIGID_STEPS_PER_YEAR = 37.0  # at rtol 1e-12
S_PER_STEP = 0.65e-6
S_PER_TERM_STEP = 0.16e-6
SCIPY_S_PER_STEP = 6e-5
MB = 1e-6


def _steps_per_year(data: dict, rtol: float) -> float:
    random = ((data.get("effects") or {}).get("excitation") or {}).get("random")
    per_year = RIGID_STEPS_PER_YEAR
    if random:  # the forcing's shortest period sets the step
        per_year = max(per_year, 10 * YEAR_DAYS / random["periods_days"][0])
    return per_year * (1e-12 / rtol) ** (1 / 8)


def _s_per_step(data: dict) -> float:
    random = ((data.get("effects") or {}).get("excitation") or {}).get("random")
    return S_PER_STEP + (S_PER_TERM_STEP * random["terms"] if random else 0.0)


def cost(data: dict) -> list[Work]:
    works = [Work("title", 0.5, 0.0, "the scene's fixed work")]
    analysis = data.get("analysis", {})
    if "earth" in data:
        span_years = analysis.get("span_years", DEFAULT_SPAN_YEARS)
        steps = span_years * _steps_per_year(data, analysis.get("rtol", 1e-12))
        run = steps * _s_per_step(data) + 1e-4
        seconds = 2 * run + min(5 * run, 1.0 + run)  # the sampled run, its timing (min of 5, 1 s)
        samples = span_years * YEAR_DAYS / SAMPLE_DAYS
        field = "analysis.span_years" if span_years > 100.0 or "rtol" not in analysis else "analysis.rtol"
        works.append(Work(field, seconds, samples * BYTES_PER_SAMPLE * MB, count(steps, "integration steps")))
        if "dissipation" in (data.get("effects") or {}):
            works.append(Work("effects.dissipation", 1.0, 0.0, "the energy and rate checks"))
    spec = analysis.get("accuracy_cost")
    if spec is not None:
        span_years = analysis.get("span_years", DEFAULT_SPAN_YEARS)
        repeats = spec.get("repeats", 5)
        split = adapt = 0.0
        for method in spec["methods"]:
            if method.startswith("splitting"):
                for h in spec["steps"]:
                    run = span_years * YEAR_DAYS / h * 0.4e-6
                    split += run + min(min(repeats, 3) * run, 2.0 + run)
                continue
            per_step = S_PER_STEP if not method.startswith("scipy:") else SCIPY_S_PER_STEP
            for rtol in spec["tolerances"]:
                run = (
                    span_years
                    * _steps_per_year(data, rtol)
                    * (3 if "dopri5" in method or "RK" in method or "LSODA" in method else 1)
                    * per_step
                )
                adapt += run + min(repeats * run, 1.0 + run)
        works.append(Work("analysis.accuracy_cost.tolerances", adapt, 0.0, "the work-precision sweep"))
        works.append(Work("analysis.accuracy_cost.steps", split, 0.0, "the splittings' steps"))
    if "observation" in data:
        obs = data["observation"]
        span = 2030.0 - obs["start_year"]
        windows = max(span - obs["window_years"], 0.0) / obs["step_years"]
        works.append(Work("observation.step_years", 2.0 + 3e-4 * windows, 0.0, count(windows, "windows")))
    if "body" in data:
        body = data["body"]
        seconds = 0.0
        for a in (body["oblate_A_over_C"], body["prolate_A_over_C"]):
            span = body["e_folds"] / abs(body["kappa_over_Cn"] * (1.0 / a - 1.0))
            seconds += 50 * span / 6.283 * S_PER_STEP * 10  # ~50 steps a turn at rtol 1e-12, with the samples
        works.append(Work("body.kappa_over_Cn", seconds, 0.0, "the two bodies' runs"))
    poinsot = analysis.get("poinsot")
    if poinsot is not None:
        works.append(
            Work(
                "analysis.poinsot.samples",
                0.5 + 1e-5 * poinsot["samples"] * (1 + poinsot["span"] / 100),
                poinsot["samples"] * 200 * MB,
                count(poinsot["samples"], "samples"),
            )
        )
    free = analysis.get("lamb_free_body")
    if free is not None:
        works.append(
            Work(
                "analysis.lamb_free_body.spin_over_turn",
                0.5 + 2e-4 * free["samples"] + 0.005 * free["spin_over_turn"],
                0.0,
                count(free["spin_over_turn"], "turns"),
            )
        )
    return works
