"""Pin every package, with hashes, in lock files: requirements/pipeline.lock (what `make report` and the
cluster's jobs need: pyproject's dependencies and what the editable install builds with), and for each extra
only what it adds (each starts with `-r pipeline.lock`): requirements/test.lock (the `test` extra) and
requirements/slurm.lock (the `slurm` extra: Snakemake's Slurm executor, for a cluster only). Then write
workflow/envs/pipeline.yaml, the conda environment of `snakemake --use-conda`, with the pipeline's pins
(tests/test_locks.py checks they agree).

    python tools/lock.py            # after changing dependencies in pyproject.toml (needs pip-tools)

pip-compile keeps the versions already pinned unless a dependency asks otherwise; `--upgrade` moves them on.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FOLDER = ROOT / "requirements"
OPTIONS = [
    "--quiet",
    "--generate-hashes",
    "--allow-unsafe",
    "--strip-extras",
    "--no-emit-index-url",
    "--no-emit-find-links",
    "--no-header",
]
HEADER = (
    "# {what}\n# Pinned with hashes for Python %d.%d by tools/lock.py (pip-compile); install with "
    "pip install -r {name}\n" % sys.version_info[:2]
)


def compile_(output: Path, *sources: str, extra: list[str] = (), upgrade: bool = False) -> None:
    command = [sys.executable, "-m", "piptools", "compile", *OPTIONS, *extra, "-o", str(output), *sources]
    subprocess.run(command + (["--upgrade"] if upgrade else []), cwd=ROOT, check=True)


def blocks(text: str) -> dict[str, str]:
    """{normalized name: its lines} of a pip-compile output (a pin, its hashes and its 'via' lines)."""
    found, name = {}, None
    for line in text.splitlines(keepends=True):
        match = re.match(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==", line)
        if match:
            name = re.sub(r"[-_.]+", "-", match.group(1)).lower()
            found[name] = ""
        if name and not line.startswith("#"):
            found[name] += line
    return found


def write_conda_environment(pins: dict[str, str]) -> None:
    """workflow/envs/pipeline.yaml: Python and WeasyPrint's system libraries and fonts from conda-forge, then
    the lock's pins with pip (without hashes: pip's hash mode refuses the editable install of this
    package)."""
    lines = (
        [ENVIRONMENT] + [f"      - {block.split()[0]}\n" for block in pins.values()] + ["      - -e ../..\n"]
    )
    (ROOT / "workflow" / "envs" / "pipeline.yaml").write_text("".join(lines))


ENVIRONMENT = """\
# The software every rule runs with under `snakemake --use-conda`: Python and WeasyPrint's system libraries
# and fonts from conda-forge, then the pins of requirements/pipeline.lock and this package. Written by
# tools/lock.py.
channels:
  - conda-forge
dependencies:
  - python=3.11
  - pip
  - pango
  - fonts-conda-forge
  - pip:
"""


def main() -> int:
    upgrade = "--upgrade" in sys.argv[1:]
    pipeline = FOLDER / "pipeline.lock"
    with tempfile.TemporaryDirectory() as scratch:
        draft = Path(scratch) / "pipeline.lock"
        if pipeline.exists():
            shutil.copy(pipeline, draft)  # pip-compile prefers the pins in its output file
        compile_(draft, "pyproject.toml", "requirements/build.in", upgrade=upgrade)
        pipeline.write_text(
            HEADER.format(
                what="What the pipeline runs with (make report, a cluster's jobs).",
                name="requirements/pipeline.lock",
            )
            + draft.read_text()
        )
        shared = blocks(draft.read_text())
        counts = []
        for extra, what in EXTRAS.items():
            added = extra_lock(Path(scratch), draft, shared, extra, what)
            counts.append(f"requirements/{extra}.lock: {added} more")
    write_conda_environment(shared)
    print(f"{pipeline.relative_to(ROOT)}: {len(shared)} packages; " + "; ".join(counts))
    return 0


EXTRAS = {
    "test": "What the tests add to the pipeline's packages (make test).",
    "slurm": "What running on a Slurm cluster adds to the pipeline's packages (make venv-slurm).",
}


def extra_lock(scratch: Path, draft: Path, shared: dict, extra: str, what: str) -> int:
    """requirements/<extra>.lock: only the packages the extra adds, at pins that agree with the pipeline's."""
    everything = scratch / f"{extra}-everything.lock"
    shutil.copy(draft, everything)
    compile_(everything, "pyproject.toml", "requirements/build.in", extra=["--extra", extra])
    together = blocks(everything.read_text())
    added = {name: lines for name, lines in together.items() if name not in shared}
    moved = [
        name
        for name, lines in together.items()
        if name in shared and lines.split()[0] != shared[name].split()[0]
    ]
    if moved:
        raise SystemExit(f"the {extra} extra moves pipeline pins: {', '.join(moved)}")
    (FOLDER / f"{extra}.lock").write_text(
        HEADER.format(what=what, name=f"requirements/{extra}.lock")
        + "-r pipeline.lock\n\n"
        + "".join(added.values())
    )
    return len(added)


if __name__ == "__main__":
    sys.exit(main())
