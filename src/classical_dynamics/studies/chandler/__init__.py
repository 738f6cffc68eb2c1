"""Study: the Chandler wobble, from Euler's rigid Earth to the observed polar motion.

A scene is either a model Earth (`earth` + `effects`: triaxiality, elastic_yielding, dissipation,
excitation; none listed is the rigid symmetric Earth of Lamb Art. 47), an observation
(`observation`: a window of the IERS C04 series, fitted for the Chandler and annual wobbles), or a
symmetric `body` under the retarding couple of Lamb Ex. X.10.
"""

from __future__ import annotations

from pathlib import Path

from ...models.wobble import EFFECTS, b_minus_a_over_c
from ...scenes import Scene, SceneError
from ...scenes.cost import check_step
from .cost import DEFAULT_SPAN_YEARS, cost

__all__ = ["EFFECTS", "check", "cost", "run"]


def check(path: Path, data: dict) -> None:
    """Physical consistency the schema cannot express. Raises SceneError (one line)."""
    from ...models import earth

    kinds = [k for k in ("earth", "observation", "body") if k in data]
    if len(kinds) != 1:
        raise SceneError(
            path,
            "earth",
            "one of `earth` (a model), `observation` (the IERS series) or `body` (a "
            "symmetric body under a retarding couple)",
            kinds,
        )
    effects = data.get("effects") or {}
    analysis = data.get("analysis", {})
    if "body" in data:
        if effects or analysis:
            raise SceneError(
                path,
                "body",
                "no effects or analysis beside `body` (the couple is the scene)",
                sorted(set(effects) | set(analysis)),
            )
        body = data["body"]
        if not body["oblate_A_over_C"] < 1.0 < body["prolate_A_over_C"]:
            raise SceneError(
                path,
                "body",
                "oblate_A_over_C below 1 and prolate_A_over_C above 1 (C > A, C < A)",
                [body["oblate_A_over_C"], body["prolate_A_over_C"]],
            )
        if body["oblate_A_over_C"] < 0.5:
            raise SceneError(
                path,
                "body.oblate_A_over_C",
                "at least 0.5 (2A ≥ C: a physical body)",
                body["oblate_A_over_C"],
            )
        return
    if "observation" in data:
        if effects:
            raise SceneError(
                path,
                "effects",
                "no effects for an observation scene (the Earth supplies them)",
                sorted(effects),
            )
        if analysis:
            raise SceneError(path, "analysis", "no model analysis for an observation scene", sorted(analysis))
        _check_observation(path, data["observation"])
        return
    H = earth.h_over_c(data["earth"]["H"], data["earth"]["H_definition"])
    triaxial = effects.get("triaxiality")
    if triaxial is not None:
        delta = b_minus_a_over_c(triaxial, H)
        if not delta < 2 * H:
            raise SceneError(
                path,
                "effects.triaxiality.b_minus_a_over_c",
                f"a number below 2H = {2 * H:.6g} (B must stay below C)",
                delta,
            )
    elastic = effects.get("elastic_yielding")
    if elastic is not None:
        if ("k2" in elastic) == ("period_solar_days" in elastic):
            raise SceneError(
                path,
                "effects.elastic_yielding",
                "one of k2 or period_solar_days (with source)",
                sorted(elastic),
            )
        k_s = earth.secular_love_number()
        if "k2" in elastic and not elastic["k2"] < k_s:
            raise SceneError(
                path,
                "effects.elastic_yielding.k2",
                f"a Love number below the fluid value "
                f"k_s = {k_s:.4f} (at k_s the wobble stops: a fluid Earth has no free wobble)",
                elastic["k2"],
            )
        rigid = earth.sidereal_to_solar_days(earth.euler_period_sidereal_days(H))
        if "period_solar_days" in elastic and not elastic["period_solar_days"] > rigid:
            raise SceneError(
                path,
                "effects.elastic_yielding.period_solar_days",
                f"a period longer than the rigid Earth's {rigid:.2f} days (yielding lengthens it)",
                elastic["period_solar_days"],
            )
    if "dissipation" in effects and elastic is None:
        raise SceneError(
            path,
            "effects.dissipation",
            "elastic_yielding as well (a rigid body cannot dissipate: internal friction needs deformation)",
            sorted(effects),
        )
    random = (effects.get("excitation") or {}).get("random")
    if random is not None and not random["periods_days"][0] < random["periods_days"][1]:
        raise SceneError(
            path,
            "effects.excitation.random.periods_days",
            "[shortest, longest] with shortest < longest",
            random["periods_days"],
        )
    cost = analysis.get("accuracy_cost")
    if cost is not None:
        span_days = analysis.get("span_years", DEFAULT_SPAN_YEARS) * earth.JULIAN_YEAR_DAYS
        for i, h in enumerate(cost["steps"]):
            check_step(path, f"analysis.accuracy_cost.steps.{i}", h, span_days)
        if set(effects) - {"triaxiality"}:
            raise SceneError(
                path,
                "analysis.accuracy_cost",
                "a free rigid body (no effects but triaxiality): the "
                "work-precision reference is the closed form",
                sorted(effects),
            )
    if analysis.get("cones") and effects:
        raise SceneError(path, "analysis.cones", "the rigid symmetric Earth (no effects)", sorted(effects))
    if analysis.get("cone_rates") and effects:
        raise SceneError(
            path, "analysis.cone_rates", "the rigid symmetric Earth (no effects)", sorted(effects)
        )
    body = analysis.get("poinsot")
    if body is not None:
        A, B, C = body["moments"]
        if not A < B < C:
            raise SceneError(
                path, "analysis.poinsot.moments", "A < B < C (Lamb Art. 48's order)", body["moments"]
            )
        if not C <= A + B:
            raise SceneError(
                path, "analysis.poinsot.moments", "C ≤ A + B (a physical body, Lamb Art. 25)", body["moments"]
            )
    if analysis.get("lamb_symmetric") and effects:
        raise SceneError(
            path, "analysis.lamb_symmetric", "the rigid symmetric Earth (no effects)", sorted(effects)
        )
    free = analysis.get("lamb_free_body")
    if free is not None:
        A, B, C = free["moments"]
        if not (A < B < C and A + B >= C):
            raise SceneError(
                path,
                "analysis.lamb_free_body.moments",
                "A < B < C with A + B ≥ C (a physical body with three unequal moments)",
                free["moments"],
            )
        a, b = free["plate_half_sides"]
        if not a > b:
            raise SceneError(
                path,
                "analysis.lamb_free_body.plate_half_sides",
                "[a, b] with a > b",
                free["plate_half_sides"],
            )


def _check_observation(path, obs):
    from .polar_motion import eop_file, series_extent

    first, last = series_extent(eop_file())
    start, end = obs["start_year"], obs["end_year"]
    end_value = last if end == "latest" else end
    if not first <= start < last:
        raise SceneError(
            path, "observation.start_year", f"a year inside the series ({first:.2f} to {last:.2f})", start
        )
    if not (start < end_value <= last + 1e-9):
        raise SceneError(
            path,
            "observation.end_year",
            f"a year after start_year and not after the series ends ({last:.2f}), or 'latest'",
            end,
        )
    if not obs["window_years"] <= end_value - start:
        raise SceneError(
            path,
            "observation.window_years",
            f"a window no longer than the span ({end_value - start:.2f} years)",
            obs["window_years"],
        )
    # windows start at calendar years
    check_step(path, "observation.step_years", obs["step_years"], end_value)
    if obs["compare"]["k2"] >= _k_s():
        raise SceneError(
            path, "observation.compare.k2", f"a Love number below k_s = {_k_s():.4f}", obs["compare"]["k2"]
        )


def _k_s():
    from ...models import earth

    return earth.secular_love_number()


def run(scene: Scene, quick: bool = False):
    from ...results import Results  # imported here so that validation stays light
    from . import accuracy, model, observed, retarding

    results = Results("chandler", scene.name, scene.title)
    if "body" in scene.data:
        retarding.run(scene, results, quick)
    elif "observation" in scene.data:
        observed.run(scene, results, quick)
    else:
        model.run(scene, results, quick)
        _poinsot(scene, results)
        if "accuracy_cost" in scene.data.get("analysis", {}):
            accuracy.run(scene, results, quick)
    return results


def _poinsot(scene, results):
    """Lamb Arts. 25, 30, 46-48: Poinsot's kinematics (poinsot.py), where the scene asks for it."""
    analysis = scene.data.get("analysis", {})
    if not ("poinsot" in analysis or analysis.get("cone_rates")):
        return
    from . import model, poinsot

    if "poinsot" in analysis:
        spec = analysis["poinsot"]
        body = poinsot.poinsot_body(spec["moments"], spec["omega"], spec["span"], spec["samples"])
        poinsot.record_poinsot_body(results, body, spec["source"])
        poinsot.record_conjugate_plane(results, poinsot.conjugate_plane(body.moments))
        poinsot.record_triangle_inequality(results, poinsot.triangle_inequality())
        poinsot.record_invariable_cone(results, poinsot.invariable_cone(body.moments))
    if analysis.get("cone_rates"):
        _, amplitude, earth_model = model.setup(scene)
        poinsot.record_cone_rates(results, poinsot.cone_rates(earth_model, amplitude))
