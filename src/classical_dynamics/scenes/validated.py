"""Scene validation remembered between parses of the Snakefile.

A scene is validated again only when its bytes, its schema, its study's code or the budget change: Snakemake
parses the Snakefile for every command (a dry run, --unlock, each job on a cluster), and validating every
scene each time cost seconds. The record, {scene file: {digest, estimated seconds and MB}}, lives in
.snakemake/; a scene that fails is never recorded, so it fails again on the next parse.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Callable, Iterable

from .. import io
from ..code_graph import NAME, code_digest
from .cost import Budget, Estimate
from .loader import SceneError, read_bytes


def validate_all(
    scenes: Iterable[tuple[str, Path, Path]],
    validate: Callable,
    record: Path,
    budget: Budget,
    optional: Callable[[str, Path], bool] = lambda study, scene: False,
) -> tuple[dict[str, Estimate], list[SceneError]]:
    """({scene file: Estimate}, errors) after validate(study, scene, budget) for every (study, scene, the
    study's schema file) not recorded as valid with its present bytes and schema. The first SceneError of a
    scene not optional(study, scene) propagates (the scenes validated before it are still recorded); those of
    optional scenes are returned."""
    try:
        known = json.loads(Path(record).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        known = {}
    # a study's code: the physical checks and cost estimates live in what its package imports
    schemas, valid, errors = {}, {}, []
    try:
        for study, scene, schema in scenes:
            if schema not in schemas:
                code = code_digest(f"{NAME}.studies.{study}")
                schemas[schema] = hashlib.sha256(Path(schema).read_bytes()).hexdigest() + code + repr(budget)
            key = Path(scene).as_posix()
            digest = hashlib.sha256(read_bytes(scene) + schemas[schema].encode()).hexdigest()
            entry = known.get(key)
            if not (isinstance(entry, dict) and entry.get("digest") == digest):
                try:
                    estimate = validate(study, scene, budget).estimate
                except SceneError as error:
                    if not optional(study, Path(scene)):
                        raise
                    errors.append(error)
                    continue
                entry = {"digest": digest, "seconds": estimate.seconds, "memory_mb": estimate.memory_mb}
            valid[key] = entry
    finally:
        merged = {**known, **valid}  # scenes not needed by this command keep their record
        merged = {key: entry for key, entry in merged.items() if Path(key).exists()}
        if merged != known:
            io.atomic_write_text(record, json.dumps(merged, indent=1, sort_keys=True) + "\n")
    return {key: Estimate(entry["seconds"], entry["memory_mb"]) for key, entry in valid.items()}, errors
