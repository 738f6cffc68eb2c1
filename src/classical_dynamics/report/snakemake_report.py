"""Snakemake's own report, `snakemake --report results/snakemake-report.zip`: every figure and table of
the results with its caption; one category per chapter of the report, numbered and titled as the report
numbers and titles it, and one subcategory per scene; the report itself under "Report".

The captions are in each scene's summary.json, written by its job: they are not known when the workflow is
read, and as a rule's params they would rerun the scenes. So the scene rule's output folders carry report()
flags only (a flag changes neither what a job writes nor what reruns it), whose category is a function made
by `category`: asked for a file's category, it writes that file's caption as RST to
.snakemake/report-captions/<the file's folder>/<its name>.rst, which the flag's caption template
(workflow/report/result.rst, timing.rst) includes. Snakemake asks every reported file's category before it
renders any caption (snakemake.report.auto_report), and only when it makes a report: no other command runs
any of this, and `--report-after-run` captions the build it has just made.
"""

from __future__ import annotations

import json
import re
from functools import lru_cache
from pathlib import Path

from ..inline_math import _INLINE, FUNCTIONS
from ..studies import STUDIES

# What of a results folder the report shows, and a Snakemake user looks for: its figures and tables.
PATTERNS = [r"{file,[^/]+\.(?:svg|csv)}"]
CAPTIONS = Path(".snakemake/report-captions")  # in the working directory, beside Snakemake's own records
REPORT = "Report"  # the category of report.html, report.pdf and the measured figures it shows
# The report's chapter 1 is its Introduction (report/templates/report.html.j2); the studies follow in the
# registry's order, as 2, 3, ... (report/navigation.py numbers them).
FIRST_STUDY_CHAPTER = 2
# What the report adds to a caption of measured times (report/build.py)
TIMING_NOTE = " Measured times: they vary from run to run."


def chapter(study: str) -> str:
    """A study's category: its chapter as the report titles it, "2 Precession of the equinoxes" (Snakemake
    lists categories sorted by name, so the number also keeps the report's order)."""
    return f"{list(STUDIES).index(study) + FIRST_STUDY_CHAPTER} {STUDIES[study].title}"


# --- captions ----------------------------------------------------------------------------------------------

_RST_SPECIAL = re.compile(r"([\\`*_|:<>\[\]])")
_DIGIT_FRACTION = re.compile(r"\\([dt]?frac)\s*(\d)\s*(\d)")  # \tfrac12: TeX's shorthand, not docutils'
_COMMAND = re.compile(r"\\([A-Za-z]+)")
# What may stand next to an inline role in RST with no escaped space between (of what _rst_prose leaves as is)
_BEFORE_ROLE = {"", " ", "(", "'", '"', "-", "/", "\u00a0", "\u202f"}
_AFTER_ROLE = {"", " ", ".", ",", ";", "!", "?", ")", "'", '"', "-", "/", "\u00a0", "\u202f"}


def _rst_prose(text: str) -> str:
    """Plain text, every character RST could read as markup escaped."""
    return _RST_SPECIAL.sub(r"\\\1", text.replace("\\$", "$").replace("\n", " "))


def _rst_math(body: str) -> str:
    """One $...$ body as RST's math role, in the TeX docutils renders: \\tfrac12 with braces, function names
    (si, ci, ln, ...; inline_math's list) through \\operatorname, which docutils knows all of."""
    body = _DIGIT_FRACTION.sub(r"\\\1{\2}{\3}", body.strip())
    body = _COMMAND.sub(lambda m: rf"\operatorname{{{m[1]}}}" if m[1] in FUNCTIONS else m[0], body)
    return f":math:`{body}`"


def rst(text: str) -> str:
    """A caption as the studies write it (plain text, $...$ inline math) as one RST paragraph."""
    text, out, last = text.strip(), [], 0
    for match in _INLINE.finditer(text):
        before, after = text[match.start() - 1 : match.start()], text[match.end() : match.end() + 1]
        out += [
            _rst_prose(text[last : match.start()]),
            # a role next to a letter ("$n$th", "10$^3$") stands apart by an escaped space, not printed
            "" if before in _BEFORE_ROLE else "\\ ",
            _rst_math(match[1]),
            "" if after in _AFTER_ROLE else "\\ ",
        ]
        last = match.end()
    out.append(_rst_prose(text[last:]))
    paragraph = "".join(out)
    # a paragraph opening with "1." or "- " would be a list: its first character is escaped too (unless
    # escaped already, or a role's opening)
    opens_list = paragraph[:1] and not paragraph[0].isalpha() and paragraph[0] not in "\\:"
    return "\\" + paragraph if opens_list else paragraph


def caption(summary: dict, name: str, timing: bool = False) -> str:
    """The caption of the file `name` (convergence.svg, frequencies.csv) of a results folder, or of its
    timings folder, from the folder's summary: a figure's or a table's own caption, as the report prints
    it."""
    part = summary.get("timings", {}) if timing else summary
    note = TIMING_NOTE if timing else ""
    figures, tables = part.get("figures", {}).values(), part.get("tables", {}).values()
    for meta in figures if name.endswith(".svg") else tables:
        if meta["file"] == name:
            return meta["caption"] + note
    for meta in figures:
        if meta.get("data") == name:
            return f"The data of {meta['file']}: {meta['caption']}{note}"
    if name == "hard_cases.csv" and not timing:
        return (
            "The scene's hard cases, checks that must hold: what each measures, its bound, whether it holds."
        )
    if name == "run.csv" and timing:
        return "What the job cost: its wall and CPU time and peak memory, beside what was estimated."
    return f"A file of {summary['study']}/{summary['scene']}."


@lru_cache(maxsize=8)
def _summary(path: str, mtime_ns: int) -> dict:
    return json.loads(Path(path).read_text(encoding="utf-8"))


def write_caption(results: str, folder: str, name: str) -> Path:
    """Write the caption of `folder`/`name` (`folder` the results folder `results` or its timings folder) to
    .snakemake/report-captions/<folder>/<name>.rst, where the caption templates include it."""
    summary = Path(results, "summary.json")
    text = rst(caption(_summary(str(summary), summary.stat().st_mtime_ns), name, folder != results))
    target = CAPTIONS / folder / f"{name}.rst"
    target.parent.mkdir(parents=True, exist_ok=True)
    if not target.is_file() or target.read_text(encoding="utf-8") != text + "\n":
        target.write_text(text + "\n", encoding="utf-8")
    return target


def category(folder: str, study: str | None = None):
    """The category function of a report() flag on a rule's output folder `folder` ("results" or "timings",
    the output's name in the rule): the chapter of `study` (by default the job's own wildcard). Asked for a
    file's category, it writes that file's caption first (see above)."""

    def category(wildcards, output):
        write_caption(output.results, getattr(output, folder), wildcards.file)
        return chapter(study or wildcards.study)

    return category
