"""Scene validation remembered between parses of the Snakefile.

A scene is validated again only when its bytes, its schema or the package's code change: Snakemake parses the
Snakefile for every command (a dry run, --unlock, each job on a cluster), and validating every scene each time cost
seconds. The record, {scene file: SHA-256 of scene, schema and code}, lives in .snakemake/; a scene that fails is
never recorded, so it fails again on the next parse.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Callable, Iterable

from .. import io
from .loader import read_bytes

PACKAGE = Path(__file__).resolve().parents[1]


def code_digest() -> str:
    """SHA-256 of every module of the package: the physical checks live in the studies' code."""
    digest = hashlib.sha256()
    for path in sorted(PACKAGE.rglob("*.py")):
        digest.update(path.relative_to(PACKAGE).as_posix().encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


def validate_all(scenes: Iterable[tuple[str, Path, Path]], validate: Callable, record: Path) -> None:
    """validate(study, scene, schema) for every scene not recorded as valid with its present bytes; the first
    SceneError propagates (the scenes validated before it are still recorded)."""
    try:
        known = json.loads(Path(record).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        known = {}
    code, schemas, valid = code_digest(), {}, {}
    try:
        for study, scene, schema in scenes:
            if schema not in schemas:
                schemas[schema] = hashlib.sha256(Path(schema).read_bytes()).hexdigest()
            key = Path(scene).as_posix()
            digest = hashlib.sha256(read_bytes(scene) + (schemas[schema] + code).encode()).hexdigest()
            if known.get(key) != digest:
                validate(study, scene, schema)
            valid[key] = digest
    finally:
        if valid != known:
            io.atomic_write_text(record, json.dumps(valid, indent=1, sort_keys=True) + "\n")
