"""What a precession scene costs, from its fields (scenes/cost.py).

Rates measured here (2-core AMD EPYC): the spin-resolved Earth (the torqued splitting) takes ~4 us a step with
its daily samples: 1000 years at 3-hour steps (2.9e6 steps) ran in 13 s with everything around it, a century
with the IAU comparison, the effect ladder, aliasing windows and the accuracy sweep in 8.8 s; the averaged
equations cross a whole 26 000-year cycle in 0.1 s. A daily sample of the full run holds ~300 bytes.
"""

from __future__ import annotations

from ...models.earth import JULIAN_YEAR_DAYS as YEAR_DAYS
from ...scenes.cost import Work, count

S_PER_STEP = 4e-6
BYTES_PER_SAMPLE = 300.0
RK_STEPS_PER_DAY = 8.0  # DOP853 on the spinning Earth at rtol 1e-8 (calibrated on full_century)
MB = 1e-6


def cost(data: dict) -> list[Work]:
    analysis, fidelity = data.get("analysis") or {}, data["fidelity"]
    works = [Work("fidelity", 1.0 + 0.1 * len(analysis), 0.0, "the scene's fixed work and its examples")]
    if fidelity == "averaged":
        works.append(Work("analysis.span_years", 1e-5 * analysis["span_years"], 0.0, "the averaged run"))
    if fidelity == "full":
        span_days = analysis["span_years"] * YEAR_DAYS
        steps = span_days * 24.0 / analysis["step_hours"]
        runs = 1 + 0.5 * bool(analysis.get("free_nutation")) + bool(analysis.get("aliasing_windows_years"))
        field = "analysis.step_hours" if analysis["step_hours"] < 1.0 else "analysis.span_years"
        works.append(
            Work(
                field,
                steps * S_PER_STEP * runs,
                span_days * BYTES_PER_SAMPLE * MB,
                count(steps, "integration steps"),
            )
        )
        windows = analysis.get("aliasing_windows_years")
        if windows:  # sampled at every step over the longest window
            works.append(
                Work(
                    "analysis.aliasing_windows_years",
                    0.0,
                    max(windows) * YEAR_DAYS * 24.0 / analysis["step_hours"] * 120 * MB,
                    count(max(windows), "years sampled at every step"),
                )
            )
        if analysis.get("effect_ladder") or analysis.get("compare_iau"):
            works.append(Work("analysis.effect_ladder", 3.0, 0.0, "the effect ladder and the IAU comparison"))
    spec = analysis.get("accuracy_cost")
    if spec is not None:
        span_days = spec["span_years"] * YEAR_DAYS
        repeats = spec.get("repeats", 3)
        split = adapt = 0.0
        for method in spec["methods"]:
            if method.startswith("splitting"):
                for h in spec["steps_hours"]:
                    run = span_days * 24.0 / h * S_PER_STEP * (2 if method.endswith("4") else 1)
                    split += run * (1 + repeats)
                continue
            scipy = method.startswith("scipy")
            for rtol in spec["tolerances"]:
                steps = span_days * RK_STEPS_PER_DAY * (1e-8 / rtol) ** (1 / (8 if "853" in method else 5))
                adapt += steps * (6e-5 if scipy else 2e-6) * (2 if scipy else 1 + repeats)
        works.append(Work("analysis.accuracy_cost.steps_hours", split, 0.0, "the splittings' steps"))
        works.append(
            Work("analysis.accuracy_cost.tolerances", adapt, 0.0, "the adaptive methods' tolerances")
        )
    return works
