"""Where a result came from: code version, software, machine, inputs, time."""

from __future__ import annotations

import hashlib
import os
import platform
import subprocess
import sys
from functools import lru_cache
from importlib import metadata
from pathlib import Path

from . import __version__

KEY_PACKAGES = (
    "numpy",
    "scipy",
    "numba",
    "llvmlite",
    "sympy",
    "mpmath",
    "matplotlib",
    "pandas",
    "jinja2",
    "pyyaml",
    "jsonschema",
    "snakemake",
    "weasyprint",
    "ziamath",
    "pyerfa",
    "astropy-iers-data",
)


def sha256_file(path: Path | str) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


@lru_cache(maxsize=1)
def package_versions() -> dict[str, str]:
    versions = {}
    for name in KEY_PACKAGES:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = "not installed"
    versions["classical-dynamics"] = __version__
    return versions


def git(root: Path | str, *args: str) -> str | None:
    """The output of one git command in the checkout at root, or None outside git."""
    try:
        return subprocess.run(
            ["git", *args], cwd=root, capture_output=True, text=True, check=True
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None


@lru_cache(maxsize=8)  # inputs: a tuple (hashable)
def git_state(inputs=None) -> dict[str, object]:
    """Commit and dirty flag of the checkout the code runs from ('unknown' outside git). inputs: the files a
    result depends on (its code and scene); then dirty says whether any of them differs from the commit or is
    not in it, so a result is marked only where the commit does not rebuild it. Without: the whole tree."""
    root = Path(__file__).resolve().parents[2]
    commit = git(root, "rev-parse", "HEAD")
    if commit is None:
        return {"commit": "unknown", "dirty": None}
    if inputs is None:
        return {"commit": commit, "dirty": bool(git(root, "status", "--porcelain", "--untracked-files=no"))}
    changed = git(root, "status", "--porcelain", "--untracked-files=all", "--", *map(str, inputs))
    return {"commit": commit, "dirty": bool(changed)}


def git_state_of(entries: tuple[str, ...], *files: Path) -> dict[str, object]:
    """git_state of a result made by the code its rule's digest covers (code_graph entries) from `files`: a
    tree with changes elsewhere (a template, another study) leaves a result the commit rebuilds unmarked."""
    from . import code_graph

    state = git_state()
    if not state["dirty"]:
        return state
    cache = Path(".snakemake/code-graph.json")  # the workflow's parse, when run from it: no second parse
    if cache.exists():
        code_graph.cache_parses_in(cache)
    return git_state((*files, *code_graph.files(*entries)))


@lru_cache(maxsize=1)
def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def machine() -> dict[str, object]:
    return {
        "python": sys.version.split()[0],
        "platform": platform.platform(),
        "cpu_model": cpu_model(),
        "cores": os.cpu_count(),
    }


def software_stamp() -> str:
    """One line for timing tables: CPU, cores and the versions that matter for speed."""
    v = package_versions()
    m = machine()
    return (
        f"{m['cpu_model']}, {m['cores']} cores; Python {m['python']}, numpy {v['numpy']}, "
        f"scipy {v['scipy']}, numba {v['numba']}"
    )
