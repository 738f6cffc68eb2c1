"""Load a scene file and validate it completely before anything is computed.

A scene is data: YAML read with the safe loader (no tags, no code), checked against the
study's JSON schema, then against the study's physical checks. The first problem found is
raised as a SceneError whose message is one line: file, field, what was expected, what was found.
"""

from __future__ import annotations

import functools
import hashlib
import math
import os
import re
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Callable, Iterable

import yaml

from ..inline_math import MathError, render_text

if TYPE_CHECKING:
    import jsonschema

# A name every file and folder made from it can take: results/<study>/<name>/ is staged as .<name>.XXXXXXXX
# and its log is <name>.log, all within the 255 bytes a file name may have.
SCENE_NAME = re.compile(r"^[a-z0-9_]{1,200}$")
# Names a folder of results/ or results/<study>/ already has: timings, logs, dist, measured (the benchmarks'
# data), gallery (a step of the self-excited study drawn from its scenes).
RESERVED_NAMES = {"timings", "logs", "dist", "measured", "gallery"}
MAX_BYTES = 1_000_000  # a scene is a page of YAML; a megabyte is already a mistake
MAX_DEPTH = 12  # the deepest scene nests 4 levels
# Files an editor or a merge leaves beside the scenes: never scenes, never an error.
LEFTOVER = re.compile(r"^(\.|#)|(~|\.sw[a-p]|\.bak|\.orig|\.tmp|\.rej)$")


def is_leftover(path: Path) -> bool:
    """An editor's swap or backup file, a hidden file: ignored where scenes are listed."""
    return bool(LEFTOVER.search(Path(path).name))


NOTHING = object()  # a refusal with nothing to show as what it got: a missing field, a file that is no file


class SceneError(ValueError):
    """A scene that cannot be run. str(error) is the one-line message shown to the user; it ends with what the
    scene gave ("got ...") unless there is nothing to show."""

    def __init__(self, path, field_name: str, expected: str, got=NOTHING):
        self.path, self.field, self.expected = str(path), field_name, expected
        message = f"{path}: field '{field_name}': expected {expected}"
        if got is not NOTHING:
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
    estimate: object = None  # scenes.cost.Estimate, once the study has costed the scene

    @property
    def title(self) -> str:
        return self.data["title"]


class _UniqueKeyLoader(yaml.SafeLoader):
    """Safe loader that refuses a key given twice (PyYAML would silently keep the last), any alias (`*name`: a
    scene needs none, and nine nested ones are an expansion bomb), and nesting deeper than MAX_DEPTH."""

    depth = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            event = self.peek_event()
            raise yaml.composer.ComposerError(
                None, None, f"an alias (*{event.anchor}): scenes take no aliases", event.start_mark
            )
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise yaml.composer.ComposerError(
                    None, None, f"nesting deeper than {MAX_DEPTH} levels", self.peek_event().start_mark
                )
            return super().compose_node(parent, index)
        finally:
            self.depth -= 1


def _construct_mapping(loader, node, deep=False):
    seen = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if key in seen:
            raise yaml.constructor.ConstructorError(
                None, None, f"key {key!r} is given twice", key_node.start_mark
            )
        seen.add(key)
    return yaml.SafeLoader.construct_mapping(loader, node, deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)

_TYPE_WORDS = {
    "number": "a number",
    "integer": "an integer",
    "string": "a string",
    "object": "a mapping",
    "array": "a list",
    "boolean": "true or false",
    "null": "nothing",
}


def _type_words(kind) -> str:
    kinds = kind if isinstance(kind, list) else [kind]
    return " or ".join(_TYPE_WORDS.get(k, k) for k in kinds)


def _expected_from(error: jsonschema.ValidationError) -> tuple[str, str, object]:
    """(field, expected, got) for the user, from a jsonschema error (got NOTHING: nothing to show)."""
    path = ".".join(str(p) for p in error.absolute_path) or "(top level)"
    v, value = error.validator, error.validator_value
    if v == "required":
        missing = next((name for name in value if name not in error.instance), value[0])
        where = f"{path}.{missing}" if error.absolute_path else missing
        return where, "a value (this field is required)", NOTHING
    if v == "additionalProperties":
        allowed = sorted(error.schema.get("properties", {}))
        extra = sorted(set(error.instance) - set(allowed))
        where = f"{path}.{extra[0]}" if error.absolute_path else extra[0]
        moved = error.schema.get("x-moved", {})  # a field an older scene format had here
        if extra[0] in moved:
            return where, f"no such key here: it moved to {moved[extra[0]]}", NOTHING
        return where, "no such key; known keys: " + ", ".join(allowed), NOTHING
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
        "minProperties": lambda: f"at least {value} " + ("entry" if value == 1 else "entries"),
        "maxProperties": lambda: f"at most {value} " + ("entry" if value == 1 else "entries"),
        "pattern": lambda: f"text matching {value}",
        "minLength": lambda: f"a text of at least {value} characters",
        "maxLength": lambda: f"a text of at most {value} characters",
        "oneOf": lambda: " or ".join(_alternative_words(choice) for choice in value),
        "anyOf": lambda: " or ".join(_alternative_words(choice) for choice in value),
    }
    expected = words[v]() if v in words else error.message
    return path, expected, error.instance


def _alternative_words(schema: dict) -> str:
    """One alternative of a oneOf as a reader says it: 'nu_c', a number from 0 to 100, a list."""
    if "const" in schema:
        return repr(schema["const"])
    words = _type_words(schema.get("type", "value"))
    low = schema.get("minimum", schema.get("exclusiveMinimum"))
    high = schema.get("maximum", schema.get("exclusiveMaximum"))
    if low is not None and high is not None:
        return f"{words} from {low:g} to {high:g}"
    return words


def _reject_non_finite(data, path=""):
    if isinstance(data, float) and not math.isfinite(data):
        raise ValueError(path)
    if isinstance(data, dict):
        for key, item in data.items():
            _reject_non_finite(item, f"{path}.{key}" if path else str(key))
    elif isinstance(data, list):
        for i, item in enumerate(data):
            _reject_non_finite(item, f"{path}.{i}" if path else str(i))


def read_bytes(path: Path) -> bytes:
    """The scene's bytes, read once: a regular file (not a link, device or pipe) of at most MAX_BYTES."""
    try:
        info = os.lstat(path)
    except OSError as exc:
        raise SceneError(path, "(file)", "a readable file", exc.strerror) from None
    if stat.S_ISLNK(info.st_mode):
        raise SceneError(
            path, "(file)", "a regular file, not a symbolic link (copy the scene instead)", os.readlink(path)
        )
    if not stat.S_ISREG(info.st_mode):
        raise SceneError(path, "(file)", "a regular file, not a device, pipe or folder")
    if info.st_size > MAX_BYTES:
        raise SceneError(path, "(file)", f"at most {MAX_BYTES // 1000} kB of YAML", f"{info.st_size} bytes")
    try:
        with open(path, "rb") as handle:
            data = handle.read(MAX_BYTES + 1)
    except OSError as exc:
        raise SceneError(path, "(file)", "a readable file", exc.strerror) from None
    if len(data) > MAX_BYTES:  # grew since the stat
        raise SceneError(path, "(file)", f"at most {MAX_BYTES // 1000} kB of YAML", "more")
    return data


def project_yaml(path: Path | str) -> object:
    """One of the project's own YAML files (schemas, claims, ledgers, the study registry), read with libyaml's
    safe loader where PyYAML was built with it: the objects yaml.safe_load gives, several times faster (the
    report reads 0.34 MB of them). A user's scene goes through read_yaml, which refuses duplicate keys."""
    return yaml.load(
        Path(path).read_text(encoding="utf-8"), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    )


def read_yaml(path: Path, data: bytes | None = None) -> object:
    data = read_bytes(path) if data is None else data
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneError(
            path, "(file)", "UTF-8 text", f"byte {exc.start}: {data[exc.start : exc.start + 1]!r}"
        ) from None
    try:
        return yaml.load(text, Loader=_UniqueKeyLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else "(unknown line)"
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise SceneError(path, f"(YAML at {where})", "valid YAML", problem) from None
    except RecursionError:  # belt and braces: MAX_DEPTH stops nesting first
        raise SceneError(path, "(YAML)", f"nesting of at most {MAX_DEPTH} levels") from None


def load_scene(
    path: Path | str,
    study: str,
    schema: dict,
    known_effects: Iterable[str],
    check: Callable[[Path, dict], None] | None = None,
) -> Scene:
    """Read and fully validate one scene; raise SceneError on the first problem."""
    path = Path(path)
    name = path.stem
    if path.suffix != ".yaml" or not SCENE_NAME.match(name) or name in RESERVED_NAMES:
        raise SceneError(
            path,
            "(file name)",
            "a name of at most 200 lower-case letters, digits and _ ending in .yaml, not "
            + ", ".join(sorted(RESERVED_NAMES)),
            path.name,
        )
    raw = read_bytes(path)
    data = read_yaml(path, raw)
    if not isinstance(data, dict):
        raise SceneError(path, "(top level)", "a mapping of scene fields", data)
    known = sorted(known_effects)
    effects = data.get("effects")
    if isinstance(effects, dict):
        for effect in effects:
            if effect not in known:
                raise SceneError(path, f"effects.{effect}", "a known effect: " + ", ".join(known))
    import jsonschema  # here, not at import: 0.12 s that verify, diff and dist never need

    validator = _validator_class()(schema)
    error = jsonschema.exceptions.best_match(validator.iter_errors(data), key=_depth_first)
    if error is not None:
        raise SceneError(path, *_expected_from(error))
    # after the schema: a NaN where a text belongs is "a string", not "a finite number" (and NaN passes
    # every minimum and maximum, so the schema alone would let it through)
    try:
        _reject_non_finite(data)
    except ValueError as exc:
        field_name = str(exc)
        raise SceneError(path, field_name, "a finite number", lookup(data, field_name)) from None
    _check_math(path, data)
    if check is not None:
        try:
            check(path, data)
        except SceneError:
            raise
        except (ArithmeticError, ValueError, TypeError) as exc:  # e.g. 1e308 squared in a physical check
            raise SceneError(
                path, "(values)", "numbers the model can evaluate", f"{type(exc).__name__}: {exc}"
            ) from None
    digest = hashlib.sha256(raw).hexdigest()  # the bytes that were parsed
    return Scene(
        name=name, study=study, path=path, data=data, sha256=digest, effects=dict(data.get("effects") or {})
    )


@functools.cache
def _validator_class():
    """Draft 2020-12 with an integer that is an int, as the code that counts with it uses it: JSON Schema's
    "integer" also takes 10.0, which validated and then stopped the run inside numpy."""
    import jsonschema

    return jsonschema.validators.extend(
        jsonschema.Draft202012Validator,
        type_checker=jsonschema.Draft202012Validator.TYPE_CHECKER.redefine(
            "integer", lambda checker, value: isinstance(value, int) and not isinstance(value, bool)
        ),
    )


def _check_math(path: Path, data, where: str = "") -> None:
    """Every text of a scene that may reach a reader (a title, a description, a source) typesets: its
    $...$ math uses only what the report's typesetter knows, checked by that typesetter (render_text)."""
    if isinstance(data, dict):
        for key, value in data.items():
            _check_math(path, value, f"{where}.{key}" if where else str(key))
    elif isinstance(data, list):
        for index, value in enumerate(data):
            _check_math(path, value, f"{where}.{index}")
    elif isinstance(data, str) and "$" in data:
        try:
            render_text(data)
        except MathError as error:
            expected = "text whose $...$ math the report can typeset"
            raise SceneError(path, where, expected, str(error)) from None


def _depth_first(error):
    import jsonschema

    # Prefer the most specific (deepest) error; then jsonschema's own relevance.
    return (-len(error.absolute_path), *jsonschema.exceptions.relevance(error))


def lookup(data, dotted: str):
    """The value at a dotted field ("analysis.steps.0") of a scene, or None where there is none."""
    for part in dotted.split("."):
        try:
            data = data[int(part)] if isinstance(data, list) else data[part]
        except (KeyError, IndexError, ValueError, TypeError):
            return None
    return data
