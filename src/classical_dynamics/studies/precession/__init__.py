"""Study: the precession of the equinoxes, from Lamb's secular formula to a spin-resolved Earth.

A scene chooses the rung (`fidelity`: secular, averaged, full), the constants (Lamb's or today's), the
Earth (H, obliquity) and the effects that act: solar_torque, lunar_torque, orbit_eccentricity,
lunar_inclination, node_regression, lunar_perigee_advance.
"""

from __future__ import annotations

from pathlib import Path

from ...models.earth import JULIAN_YEAR_DAYS
from ...models.precession import EFFECTS
from ...scenes import Scene, SceneError
from ...scenes.cost import check_step
from .cost import cost

__all__ = ["EFFECTS", "check", "cost", "run"]

MAX_STEP_HOURS = 24.0


def check(path: Path, data: dict) -> None:
    """Physical consistency the schema cannot express. Raises SceneError (one line)."""
    effects = data.get("effects") or {}
    analysis = data.get("analysis") or {}
    fidelity = data["fidelity"]
    if not {"solar_torque", "lunar_torque"} & set(effects):
        raise SceneError(
            path, "effects", "solar_torque or lunar_torque (nothing else exerts a couple)", sorted(effects)
        )
    for name, needs in (
        ("lunar_inclination", "lunar_torque"),
        ("node_regression", "lunar_inclination"),
        ("lunar_perigee_advance", "orbit_eccentricity"),
        ("lunar_perigee_advance", "lunar_torque"),
    ):
        if name in effects and needs not in effects:
            raise SceneError(path, f"effects.{name}", f"{needs} as well", sorted(effects))
    if "lunar_perigee_advance" in effects and fidelity != "full":
        raise SceneError(
            path,
            "effects.lunar_perigee_advance",
            "the full rung (the secular and averaged rungs average the perigee away)",
            fidelity,
        )
    if fidelity == "secular" and "lunar_inclination" in effects and "node_regression" not in effects:
        raise SceneError(
            path,
            "effects.lunar_inclination",
            "node_regression as well at the secular rung (Lamb's "
            "factor (3cos²i − 1)/2 is the average over the node's circuit)",
            sorted(effects),
        )
    if fidelity != "secular" and "span_years" not in analysis:
        raise SceneError(path, "analysis.span_years", f"a span in years for the {fidelity} rung")
    if fidelity == "full":
        step = analysis.get("step_hours")
        if step is None:
            raise SceneError(path, "analysis.step_hours", "a step in hours for the full (spin-resolved) rung")
        check_step(path, "analysis.step_hours", step, analysis["span_years"] * JULIAN_YEAR_DAYS * 24.0)
        if step > MAX_STEP_HOURS:
            raise SceneError(
                path,
                "analysis.step_hours",
                f"at most {MAX_STEP_HOURS:g} hours (the full rung resolves the daily spin)",
                step,
            )
    elif analysis.get("step_hours") is not None:
        raise SceneError(
            path,
            "analysis.step_hours",
            "no step below the full rung (the others are adaptive or closed forms)",
            analysis["step_hours"],
        )
    full_only = (
        "compare_iau",
        "free_nutation",
        "aliasing_windows_years",
        "effect_ladder",
        "accuracy_cost",
        "order",
    )
    for key in full_only:
        if key in analysis and fidelity != "full":
            raise SceneError(
                path, f"analysis.{key}", "fidelity: full (it studies the spin-resolved model)", fidelity
            )
    if "inverse_problem" in analysis and fidelity != "secular":
        raise SceneError(
            path,
            "analysis.inverse_problem",
            "fidelity: secular (H from the observed rate is read through the formula)",
            fidelity,
        )
    gyro = analysis.get("gyroscope_couple")
    if gyro and len(gyro["weights_lb"]) != len(gyro["radii_of_gyration_ft"]):
        raise SceneError(
            path,
            "analysis.gyroscope_couple.radii_of_gyration_ft",
            "one radius of gyration for each weight",
            gyro["radii_of_gyration_ft"],
        )
    spec = analysis.get("accuracy_cost")
    for i, h in enumerate(spec["steps_hours"] if spec else []):
        check_step(
            path, f"analysis.accuracy_cost.steps_hours.{i}", h, spec["span_years"] * JULIAN_YEAR_DAYS * 24.0
        )
    windows = analysis.get("aliasing_windows_years")
    if windows and max(windows) > analysis["span_years"]:
        raise SceneError(
            path,
            "analysis.aliasing_windows_years",
            f"windows no longer than span_years = {analysis['span_years']:g}",
            windows,
        )


def run(scene: Scene, quick: bool = False):
    from ...results import Results  # imported here so that validation stays light
    from . import accuracy, averaged, examples, full, secular

    results = Results("precession", scene.name, scene.title)
    model = secular.run(scene, results)
    examples.run(scene, model, results)
    fidelity = scene.data["fidelity"]
    if fidelity == "averaged":
        averaged.run(scene, model, results, quick)
    elif fidelity == "full":
        full.run(scene, model, results, quick)
        if "accuracy_cost" in scene.data.get("analysis", {}):
            accuracy.run(scene, model, results, quick)
    if scene.data["constants"] == "modern":
        rate = results.numbers["precession_rate_arcsec_per_year"]["value"]
        for key, reference, against in (
            ("psi_A", "iau2006_psi_A_rate_arcsec_per_year", "the IAU 2006 luni-solar precession"),
            (
                "r0",
                "p03_first_order_rate_arcsec_per_year",
                "P03's first-order luni-solar term $r_0$, the like one",
            ),
        ):
            results.number(
                f"rate_minus_{key}_relative",
                rate / results.numbers[reference]["value"] - 1.0,
                "1",
                note=f"this rung's rate against {against}",
            )
    return results
