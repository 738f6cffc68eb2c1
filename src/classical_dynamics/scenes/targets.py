"""Which scenes a Snakemake command needs, from its targets: a bad scene stops the commands that would run it
and no other (`snakemake chains` runs with a broken precession scene beside it; the report needs every
scene)."""

from __future__ import annotations

from pathlib import PurePosixPath
from typing import Callable, Iterable


def needed_scenes(
    targets: Iterable[str], target_jobs: Iterable, scenes: dict[str, set[str]]
) -> Callable[[str, str], bool]:
    """needed(study, scene) for a command with these targets (file paths or rule names, as typed) and target
    jobs (a cluster job's `--target-jobs rule:wildcards`); scenes = {study: scene names}. No target means the
    report."""
    targets, target_jobs = list(targets), list(target_jobs)
    if not targets and not target_jobs:
        return lambda study, scene: True
    studies, single = set(), set()
    for target in targets:
        parts = PurePosixPath(target.replace("\\", "/")).parts
        if target in scenes:  # the rule named after a study
            studies.add(target)
            continue
        if parts[:2] == ("results", "logs") and len(parts) >= 4:  # results/logs/<study>/<scene>.log
            parts = ("results", parts[2], PurePosixPath(parts[3]).stem)
        elif parts[:1] == ("results",) and len(parts) >= 3 and parts[2] == "timings":
            parts = parts[:2] + parts[3:]  # results/<study>/timings/<scene>
        if parts[:1] == ("results",) and len(parts) >= 2 and parts[1] in scenes:
            study = parts[1]
            if len(parts) >= 3 and parts[2] in scenes[study]:
                single.add((study, parts[2]))
            else:
                studies.add(study)  # a study-wide product
            continue
        return lambda study, scene: True  # the report, dist, verify, a rule name
    for spec in target_jobs:
        wildcards = dict(getattr(spec, "wildcards_dict", {}) or {})
        if getattr(spec, "rulename", None) == "scene" and {"study", "scene"} <= set(wildcards):
            single.add((wildcards["study"], wildcards["scene"]))
        else:
            return lambda study, scene: True
    return lambda study, scene: study in studies or (study, scene) in single
