"""What the report is made from besides its code and the results: templates, styles and script, the sources'
ledgers and the bibliography in the checkout's report/ folder, each study's chapter and claims in its package
(studies/registry.py). The package reaches report/ as its `files` folder (a link in the checkout, real files
in the wheel), found through importlib.resources, so an installed package renders the report from any
directory (it is installed as files, not zipped: Jinja and the checks read real paths)."""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path

from ..studies import registry

# report/ of the checkout (through the link), or the wheel's copy: as real paths, so a checkout's inputs read
# report/templates/..., as a reader finds them
HERE = Path(str(files(__package__) / "files")).resolve()
# report.html.j2, _macros.html.j2, report.css, screen.css, print.css, report.js
TEMPLATES = HERE / "templates"
LEDGER = HERE / "ledger"  # <source>.yaml: every quantitative statement of a source
LEDGER_SHOWN = "report/ledger"  # where a reader of the report finds it in the checkout
BIBLIOGRAPHY = HERE / "references.bib"


def claims_file(study: str) -> Path:
    return registry.STUDIES[study].file("claims.yaml")


def chapter_template(study: str) -> str:
    """A study's chapter as the report's Jinja loader names it (its search path: TEMPLATES, then the
    studies)."""
    return f"{study}/chapter.html.j2"


def template_folders() -> list[str]:
    return [str(TEMPLATES), str(registry.HERE)]


def asset_files() -> list[Path]:
    """Every file the report reads besides the results and its code: a change to one rebuilds the report."""
    own = [path for path in HERE.rglob("*") if path.is_file()]
    return sorted(own) + registry.resource_files()
