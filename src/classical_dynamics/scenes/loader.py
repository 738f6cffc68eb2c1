"""Load a scene file and validate it completely before anything is computed.

A scene is data: YAML read with the safe loader (no tags, no code), checked against the
study's JSON schema, then against the study's physical checks. The first problem found is
raised as a SceneError whose message is one line: file, field, what was expected, what was found.
"""

from __future__ import annotations

import hashlib
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterable

import jsonschema
import yaml

SCENE_NAME = re.compile(r"^[a-z0-9_]+$")
RESERVED_NAMES = {"timings", "logs", "dist"}


class SceneError(ValueError):
    """A scene that cannot be run. str(error) is the one-line message shown to the user."""

    def __init__(self, path, field_name: str, expected: str, got=None, *, has_got: bool = True):
        self.path, self.field, self.expected = str(path), field_name, expected
        message = f"{path}: field '{field_name}': expected {expected}"
        if has_got:
            message += f", got {_show(got)}"
        super().__init__(message)


def _show(value) -> str:
    text = repr(value) if not isinstance(value, str) else repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


@dataclass(frozen=True)
class Scene:
    name: str
    study: str
    path: Path
    data: dict
    sha256: str
    effects: dict = field(default_factory=dict)

    @property
    def title(self) -> str:
        return self.data["title"]


class _UniqueKeyLoader(yaml.SafeLoader):
    """Safe loader that refuses a key given twice (PyYAML would silently keep the last)."""


def _construct_mapping(loader, node, deep=False):
    seen = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if key in seen:
            raise yaml.constructor.ConstructorError(
                None, None, f"key {key!r} is given twice", key_node.start_mark)
        seen.add(key)
    return yaml.SafeLoader.construct_mapping(loader, node, deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)

_TYPE_WORDS = {"number": "a number", "integer": "an integer", "string": "a string",
               "object": "a mapping", "array": "a list", "boolean": "true or false", "null": "nothing"}


def _type_words(kind) -> str:
    kinds = kind if isinstance(kind, list) else [kind]
    return " or ".join(_TYPE_WORDS.get(k, k) for k in kinds)


def _expected_from(error: jsonschema.ValidationError) -> tuple[str, str, object, bool]:
    """(field, expected, got, has_got) for the user, from a jsonschema error."""
    path = ".".join(str(p) for p in error.absolute_path) or "(top level)"
    v, value = error.validator, error.validator_value
    if v == "required":
        missing = next((name for name in value if name not in error.instance), value[0])
        where = f"{path}.{missing}" if error.absolute_path else missing
        return where, "a value (this field is required)", None, False
    if v == "additionalProperties":
        allowed = sorted(error.schema.get("properties", {}))
        extra = sorted(set(error.instance) - set(allowed))
        where = f"{path}.{extra[0]}" if error.absolute_path else extra[0]
        return where, "no such key; known keys: " + ", ".join(allowed), extra[0], False
    words = {
        "type": lambda: _type_words(value),
        "minimum": lambda: f"a number >= {value}",
        "exclusiveMinimum": lambda: f"a number > {value}",
        "maximum": lambda: f"a number <= {value}",
        "exclusiveMaximum": lambda: f"a number < {value}",
        "enum": lambda: "one of " + ", ".join(map(str, value)),
        "const": lambda: repr(value),
        "minItems": lambda: f"a list of at least {value} items",
        "maxItems": lambda: f"a list of at most {value} items",
        "uniqueItems": lambda: "a list without repeated items",
        "minProperties": lambda: f"at least {value} entries",
        "pattern": lambda: f"text matching {value}",
    }
    expected = words[v]() if v in words else error.message
    return path, expected, error.instance, True


def _reject_non_finite(data, path=""):
    if isinstance(data, float) and not math.isfinite(data):
        raise ValueError(path)
    if isinstance(data, dict):
        for key, item in data.items():
            _reject_non_finite(item, f"{path}.{key}" if path else str(key))
    elif isinstance(data, list):
        for i, item in enumerate(data):
            _reject_non_finite(item, f"{path}.{i}" if path else str(i))


def read_yaml(path: Path) -> object:
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneError(path, "(file)", "a readable UTF-8 YAML file", str(exc)) from None
    try:
        return yaml.load(text, Loader=_UniqueKeyLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else "(unknown line)"
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise SceneError(path, f"(YAML at {where})", "valid YAML", problem) from None


def load_scene(path: Path | str, study: str, schema: dict, known_effects: Iterable[str],
               check: Callable[[Path, dict], None] | None = None) -> Scene:
    """Read and fully validate one scene; raise SceneError on the first problem."""
    path = Path(path)
    name = path.stem
    if path.suffix != ".yaml" or not SCENE_NAME.match(name) or name in RESERVED_NAMES:
        raise SceneError(path, "(file name)",
                         "a name of lower-case letters, digits and _ ending in .yaml, not "
                         + ", ".join(sorted(RESERVED_NAMES)), path.name)
    data = read_yaml(path)
    if not isinstance(data, dict):
        raise SceneError(path, "(top level)", "a mapping of scene fields", data)
    try:
        _reject_non_finite(data)
    except ValueError as exc:
        field_name = str(exc)
        raise SceneError(path, field_name, "a finite number", _lookup(data, field_name)) from None
    known = sorted(known_effects)
    effects = data.get("effects")
    if isinstance(effects, dict):
        for effect in effects:
            if effect not in known:
                raise SceneError(path, f"effects.{effect}",
                                 "a known effect: " + ", ".join(known), effect, has_got=False)
    validator = jsonschema.Draft202012Validator(schema)
    error = jsonschema.exceptions.best_match(validator.iter_errors(data), key=_depth_first)
    if error is not None:
        field_name, expected, got, has_got = _expected_from(error)
        raise SceneError(path, field_name, expected, got, has_got=has_got)
    if check is not None:
        check(path, data)
    digest = hashlib.sha256(path.read_bytes()).hexdigest()
    return Scene(name=name, study=study, path=path, data=data, sha256=digest,
                 effects=dict(data.get("effects") or {}))


def _depth_first(error):
    # Prefer the most specific (deepest) error; then jsonschema's own relevance.
    return (-len(error.absolute_path), *jsonschema.exceptions.relevance(error))


def _lookup(data, dotted: str):
    for part in dotted.split("."):
        data = data[int(part)] if isinstance(data, list) else data[part]
    return data
