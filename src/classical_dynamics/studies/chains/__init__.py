"""Study: vibrations of chains (Lamb ch. XI-XII; handbook 2.6.1; lecture notes on normal modes).

run(scene, quick) -> Results. The scene's `chain` gives the discretization (continuum, n particles on
light links or springs, n rigid links), its `effects` the restoring physics (gravity, rotation,
tension, springs), and its `analysis` what to compute beyond the frequencies.
"""

from __future__ import annotations

from pathlib import Path

from ...models.chains import EFFECTS, segments_for
from ...scenes import Scene, SceneError
from .cost import cost

__all__ = ["EFFECTS", "check", "cost", "run"]  # the interface every study module exposes

# effect -> the ends it needs and the models it is written for
_EFFECT_ENDS = {"gravity": {"fixed-free"}, "rotation": {"fixed-free"}}
_LINKS_EFFECTS = {"gravity"}
_PARTICLE_ONLY_ANALYSES = {
    "accuracy_cost",
    "time_domain",
    "dispersion",
    "large_n",
    "separation",
    "rayleigh_symmetric",
    "constraint",
    "forced",
    "friction",
    "initial_value",
    "parabola_type",
    "ring_waves",
    "continuum_limit",
    "stability",
    "revolving",
}
# an analysis that needs an effect: the response needs a force, the decay a dissipation
_ANALYSIS_NEEDS = {"forced": "forcing", "friction": "friction"}
_NOT_RESTORING = {"forcing", "friction"}


def check(path: Path, data: dict) -> None:
    """Physical consistency the schema cannot express. Raises SceneError (one line)."""
    chain, effects = data["chain"], data["effects"]
    model, ends = chain["model"], chain.get("ends", "fixed-free")
    analysis = data.get("analysis", {})
    if model == "ring":
        _check_ring(path, chain, effects, analysis)
        return
    if model == "triangle":
        if set(effects) != {"springs"} or isinstance(effects["springs"]["k_n_per_m"], list):
            raise SceneError(
                path, "effects", "springs with one stiffness for a triangle of three atoms", sorted(effects)
            )
        if set(chain) - {"model", "length_m", "mass_kg"} or "mass_kg" not in chain or analysis:
            raise SceneError(
                path,
                "chain",
                "model, length_m (the perimeter) and mass_kg only, no analysis, for a triangle",
                sorted(chain),
            )
        return
    if model == "continuum":
        if "n" in chain:
            raise SceneError(
                path, "chain.n", "no n for a continuum (n is for particles or links)", chain["n"]
            )
    elif "n" not in chain:
        raise SceneError(path, "chain.n", f"a number of {model} (integer >= 1)")
    n = chain.get("n")
    for effect in effects:
        allowed = _EFFECT_ENDS.get(effect)
        if allowed and ends not in allowed:
            raise SceneError(path, "chain.ends", f"{' or '.join(sorted(allowed))} with effect {effect}", ends)
    if "gravity" in effects and "rotation" in effects:
        raise SceneError(
            path,
            "effects",
            "gravity or rotation, not both (they describe different set-ups)",
            sorted(effects),
        )
    if model == "links" and set(effects) - _LINKS_EFFECTS:
        raise SceneError(path, "effects", "only gravity for a chain of rigid links", sorted(effects))
    if model == "continuum" and "springs" in effects:
        raise SceneError(path, "effects.springs", "a discrete chain (springs join particles)", "continuum")
    if ends == "free-free" and n is not None and n < 2:
        raise SceneError(path, "chain.n", "at least 2 particles for a free-free chain", n)
    masses = chain.get("masses_kg")
    if masses is not None:
        if model != "particles":
            raise SceneError(
                path, "chain.masses_kg", "particles (a list of masses is for a particle chain)", model
            )
        if len(masses) != n:
            raise SceneError(path, "chain.masses_kg", f"a list of n = {n} masses", f"{len(masses)} masses")
    elif "mass_kg" not in chain:
        raise SceneError(path, "chain.mass_kg", "the total mass (or masses_kg, one per particle)")
    springs = effects.get("springs")
    if springs is not None and isinstance(springs["k_n_per_m"], list) and n is not None:
        want = segments_for(n, ends)
        if len(springs["k_n_per_m"]) != want:
            raise SceneError(
                path,
                "effects.springs.k_n_per_m",
                f"{want} spring constants for {n} particles, {ends}",
                len(springs["k_n_per_m"]),
            )
    if not set(effects) - _NOT_RESTORING:
        raise SceneError(
            path,
            "effects",
            "a restoring effect (gravity, rotation, tension or springs) besides forcing and friction",
            sorted(effects),
        )
    for name in sorted(_NOT_RESTORING & set(effects)):
        if model != "particles":
            raise SceneError(path, f"effects.{name}", "a particle chain (chain.model: particles)", model)
    for name, effect in _ANALYSIS_NEEDS.items():
        if name in analysis and effect not in effects:
            raise SceneError(path, f"analysis.{name}", f"the effect {effect} listed under effects")
    for name, field in (("friction", "b_kg_per_s"), ("forcing", "newton")):
        values = effects.get(name, {}).get(field)
        if isinstance(values, list) and n is not None and len(values) != n:
            raise SceneError(path, f"effects.{name}.{field}", f"one value per particle, {n}", len(values))
    if analysis.get("stability") and (set(effects) != {"springs"} or masses is not None):
        raise SceneError(
            path,
            "analysis.stability",
            "equal particles on springs only (the examples are built from their k and m)",
            sorted(effects),
        )
    if analysis.get("separation") and (n != 2 or masses is not None):
        raise SceneError(path, "analysis.separation", "two equal particles (Lamb Art. 90 Ex. 1)", n)
    if analysis.get("rayleigh_symmetric") and (n != 3 or ends != "fixed-fixed"):
        raise SceneError(
            path, "analysis.rayleigh_symmetric", "three particles, both ends fixed (Lamb Art. 94 Ex. 1)", n
        )
    for name in analysis:
        if name in _PARTICLE_ONLY_ANALYSES and model != "particles":
            raise SceneError(path, f"analysis.{name}", "a particle chain (chain.model: particles)", model)
    for name in ("rayleigh", "spectral_check", "galerkin", "membrane"):
        if name in analysis and (model != "continuum" or set(effects) != {"gravity"}):
            raise SceneError(
                path, f"analysis.{name}", "a continuous hanging chain (model continuum, gravity)", model
            )
    if ("accuracy_cost" in analysis or "large_n" in analysis or "time_domain" in analysis) and (
        set(effects) != {"gravity"} or masses is not None
    ):
        raise SceneError(
            path,
            "analysis",
            "a uniform hanging chain (gravity only, equal masses) for accuracy_cost, large_n and time_domain",
            sorted(effects),
        )
    if "galerkin" in analysis and max(analysis["galerkin"]["elements"]) > 100_000:
        raise SceneError(
            path,
            "analysis.galerkin.elements",
            "at most 100000 elements (a sparse solve each)",
            max(analysis["galerkin"]["elements"]),
        )
    if "membrane" in analysis and analysis["membrane"]["points"] % 2 == 0:
        raise SceneError(
            path,
            "analysis.membrane.points",
            "an odd number (no collocation point at the centre)",
            analysis["membrane"]["points"],
        )
    beta = analysis.get("rayleigh")
    if beta is not None and beta["beta_min"] >= beta["beta_max"]:
        raise SceneError(
            path, "analysis.rayleigh.beta_max", f"a number > beta_min = {beta['beta_min']}", beta["beta_max"]
        )


def _check_ring(path, chain, effects, analysis):
    """A closed chain turning in its plane (Lamb Art. 98): beads on stiff springs, spun; nothing else."""
    if set(effects) != {"rotation", "springs"}:
        raise SceneError(
            path,
            "effects",
            "rotation and springs for a ring (the springs keep it nearly inextensible)",
            sorted(effects),
        )
    if "ends" in chain or "masses_kg" in chain:
        raise SceneError(
            path, "chain", "n, length_m and mass_kg only for a ring (closed, equal beads)", sorted(chain)
        )
    if "mass_kg" not in chain or chain.get("n", 0) < 16:
        raise SceneError(path, "chain.n", "at least 16 beads, and mass_kg", chain.get("n"))
    if isinstance(effects["springs"]["k_n_per_m"], list):
        raise SceneError(
            path,
            "effects.springs.k_n_per_m",
            "one stiffness for every spring of the ring",
            effects["springs"]["k_n_per_m"],
        )
    if "ring_waves" not in analysis or set(analysis) - {"ring_waves", "gyroscopic"}:
        raise SceneError(path, "analysis", "ring_waves (and gyroscopic) only for a ring", sorted(analysis))
    if chain["n"] > 2000:
        raise SceneError(
            path, "chain.n", "at most 2000 beads (a dense eigenproblem of 4n unknowns)", chain["n"]
        )


def run(scene: Scene, quick: bool = False):
    from ...results import Results  # imported here so that validation stays light

    results = Results("chains", scene.name, scene.title)
    model = scene.data["chain"]["model"]
    if model == "continuum":
        from . import continuum

        continuum.run(scene, results, quick)
    elif model in ("ring", "triangle"):
        from . import planar

        (planar.run_ring if model == "ring" else planar.run_triangle)(scene, results, quick)
    else:
        from . import discrete

        discrete.run(scene, results, quick)
        if "time_domain" in scene.data.get("analysis", {}):
            from . import time_domain  # numba: only the scenes that integrate in time

            time_domain.run(scene, results, quick)
    return results
