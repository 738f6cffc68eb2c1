"""Which of the package's modules a job runs, read from the sources: the import graph, and a digest of exactly
the modules a job's entry reaches. A job's code is derived, never listed by hand, so that a code edit reruns
exactly the jobs whose code it changes (the rules pass `code_digest(entry, ...)` as a params value, which
Snakemake compares with the one it recorded).

An edge is any import of a module of the package, anywhere in a module (inside functions too: code that runs
only sometimes still runs), `lazy_module("...")` and `import_module("...")` with a name known from the source,
and the packages above every module (importing a.b.c runs a/__init__ and a/b/__init__).

A module's part of the digest is its meaning, not its bytes: the parsed syntax tree without docstrings, so a
comment, a docstring, blank lines or reformatting rerun nothing, and any change to what the code does reruns
every job that reaches it.
"""

from __future__ import annotations

import ast
import hashlib
import json
from functools import lru_cache
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
NAME = PACKAGE.name  # classical_dynamics
# Calls that import the module their first argument names (a LazyLoader, importlib)
IMPORTING_CALLS = {"lazy_module", "import_module"}


def module_name(path: Path, package: Path = PACKAGE) -> str:
    parts = list(path.relative_to(package.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def modules(package: Path = PACKAGE) -> dict[str, Path]:
    """Every module of the package by its dotted name."""
    return {
        module_name(path, package): path
        for path in sorted(package.rglob("*.py"))
        if "__pycache__" not in path.parts
    }


def _called_name(node: ast.Call, package_name: str, module: str) -> str | None:
    """The module that `lazy_module(...)` or `import_module(...)` names, if the source says it plainly: a
    string, or an f-string of __package__ / __name__ and strings."""
    func = node.func
    called = func.id if isinstance(func, ast.Name) else getattr(func, "attr", None)
    if called not in IMPORTING_CALLS or not node.args:
        return None
    arg, known = node.args[0], {"__package__": package_name, "__name__": module}
    if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
        return arg.value
    if isinstance(arg, ast.JoinedStr):
        pieces = []
        for value in arg.values:
            if isinstance(value, ast.Constant):
                pieces.append(str(value.value))
            elif isinstance(value.value, ast.Name) and value.value.id in known:
                pieces.append(known[value.value.id])
            else:
                return None
        return "".join(pieces)
    return None


def meaning(tree: ast.Module) -> str:
    """SHA-256 of what a module does: its syntax tree (no comments, no positions) without the docstrings of
    the module, its classes and functions (text for a reader; no result depends on it)."""
    statements = [tree]  # a class or function is a statement, so only statements' bodies are visited
    while statements:
        node = statements.pop()
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                if isinstance(first.value.value, str):
                    node.body = node.body[1:] or [ast.Pass()]
        for field in ("body", "orelse", "finalbody", "handlers", "cases"):
            statements.extend(
                getattr(node, field, None) if isinstance(getattr(node, field, None), list) else ()
            )
    return hashlib.sha256(ast.dump(tree).encode()).hexdigest()


def imported(name: str, path: Path, known: dict[str, Path], tree: ast.Module | None = None) -> set[str]:
    """The package's modules that the module `name` (at `path`) imports, anywhere in it."""
    is_package = path.name == "__init__.py"
    package_name = name if is_package else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(tree or ast.parse(path.read_bytes(), str(path))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                here = package_name.split(".")
                base = ".".join(here[: len(here) - node.level + 1] + ([node.module] if node.module else []))
            # `from pkg import name`: the module pkg.name if there is one, else pkg itself
            for alias in node.names:
                found.add(f"{base}.{alias.name}" if f"{base}.{alias.name}" in known else base)
        elif isinstance(node, ast.Call):
            called = _called_name(node, package_name, name)
            if called:
                found.add(called)
    return {module for module in found if module in known and module != name}


def import_graph(package: Path = PACKAGE, cache: Path | None = None) -> dict[str, set[str]]:
    """{module: the package's modules it imports}, imports inside functions included."""
    return parse(package, cache)[0]


def parse(package: Path = PACKAGE, cache: Path | None = None) -> tuple[dict[str, set[str]], dict[str, str]]:
    """The import graph and each module's meaning (see meaning()). With `cache` (a JSON file), a module whose
    bytes and the package's module names are those of an earlier parse is not parsed again (parsing every
    module costs a Snakemake start 0.7 s)."""
    known = modules(package)
    names = hashlib.sha256("\n".join(known).encode()).hexdigest()
    try:
        saved = json.loads(cache.read_text()) if cache else {}
    except (OSError, ValueError):
        saved = {}
    graph, meanings, keys = {}, {}, {}
    for name, path in known.items():
        source = path.read_bytes()
        key = hashlib.sha256(names.encode() + source).hexdigest()
        found = saved.get(key)
        if not (isinstance(found, dict) and {"imports", "meaning"} <= set(found)):
            tree = ast.parse(source, str(path))
            found = {"imports": sorted(imported(name, path, known, tree)), "meaning": meaning(tree)}
        graph[name], meanings[name] = set(found["imports"]), found["meaning"]
        keys[key] = found
    if cache and keys != saved:
        from .io import atomic_write_text  # only when the cache is wanted: io imports numpy

        atomic_write_text(cache, json.dumps(keys, sort_keys=True))
    return graph, meanings


def reached(graph: dict[str, set[str]], entries) -> set[str]:
    """The modules that importing `entries` can run: what they import, transitively, and every package above
    each of those."""
    seen, todo = set(), list(entries)
    while todo:
        name = todo.pop()
        if name in seen or name not in graph:
            continue
        seen.add(name)
        todo.extend(graph[name])
        parent = name.rpartition(".")[0]
        if parent:
            todo.append(parent)
    return seen


_CACHE: list[Path | None] = [None]


def cache_parses_in(path: Path | str) -> None:
    """Keep what each module imports in the JSON file `path` (the workflow keeps it in .snakemake/)."""
    _CACHE[0] = Path(path)
    _graph.cache_clear()
    code_digest.cache_clear()


@lru_cache(maxsize=1)
def _graph() -> tuple[dict[str, set[str]], dict[str, Path], dict[str, str]]:
    graph, meanings = parse(cache=_CACHE[0])
    return graph, modules(), meanings


def digest_of(
    graph: dict[str, set[str]],
    paths: dict[str, Path],
    entries,
    package: Path = PACKAGE,
    meanings: dict[str, str] | None = None,
) -> str:
    """SHA-256 of the meanings (path and syntax tree) of every module that `entries` reach in `graph`."""
    unknown = [entry for entry in entries if entry not in graph]
    if unknown:
        raise KeyError(f"no module {', '.join(unknown)} in {package.name}")
    if meanings is None:
        meanings = parse(package)[1]
    digest = hashlib.sha256()
    for name in sorted(reached(graph, entries)):
        digest.update(paths[name].relative_to(package).as_posix().encode() + b"\0" + meanings[name].encode())
    return digest.hexdigest()


def job_entries(*entries: str) -> tuple[str, ...]:
    """The modules `python3 -m classical_dynamics.jobserver classical_dynamics.<entries[0]> ...` starts from
    (entries dotted below the package): what a rule's code digest covers (workflow/rules/common.smk)."""
    return (f"{NAME}.jobserver", *(f"{NAME}.{entry}" for entry in entries))


def scene_job_entries(study: str) -> tuple[str, ...]:
    """What a scene job of `study` starts from: one list for its rule's digest and its result's dirty flag."""
    return job_entries("scene_job", f"studies.{study}")


def files(*entries: str) -> list[Path]:
    """The source files of every module that the entry modules reach: the code a job's result depends on."""
    graph, paths, _ = _graph()
    return sorted(paths[name] for name in reached(graph, entries))


@lru_cache(maxsize=None)  # a parse asks for each study's digest once per job
def code_digest(*entries: str) -> str:
    """SHA-256 of the sources of every module that the entry modules (dotted names) reach: what a job's result
    depends on besides its inputs."""
    graph, paths, meanings = _graph()
    return digest_of(graph, paths, entries, meanings=meanings)
