"""What a study run produces, and how it is written (the results contract of docs/design.md).

results/<study>/<scene>/summary.json, provenance.json, *.csv, *.svg     deterministic
results/<study>/timings/<scene>/*.csv, *.svg                            measured times
"""

from __future__ import annotations

import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from . import figure_style, io, units
from .figure_data import figure_data
from .figure_style import TEXT_WIDTH_IN

# One style for every figure of the report: applied once, when a study first imports this module. Figures
# are made without pyplot (bare_figure and subplots below): no backend is chosen for the importer, no window
# can open.
figure_style.use()


def _share_math_parses() -> None:
    """One cache of parsed $math$ labels for the whole process, not one per renderer.

    Matplotlib caches a parsed math string per parser object, and makes a parser for every renderer: a figure
    saved with a tight bounding box meets three (its layout, its bounding box, the SVG), so each log-axis tick
    label ($10^{-5}$) was parsed three times per figure, again in the next figure: half of the time spent
    saving figures (matplotlib#20821). A parse depends on the parser only through its output type, which this
    cache keys on with everything else matplotlib's own cache keys on; the figures are byte-identical.
    """
    from matplotlib import mathtext

    parse = getattr(mathtext.MathTextParser._parse_cached, "__wrapped__", None)
    if parse is None:
        return  # not matplotlib's lru_cache (another matplotlib than the one pinned, or replaced already)
    parsed = {}

    def parse_cached(self, s, dpi, prop, antialiased, load_glyph_flags):
        key = (self._output_type, s, dpi, prop, antialiased, load_glyph_flags)
        if key not in parsed:
            parsed[key] = parse(self, s, dpi, prop, antialiased, load_glyph_flags)
        return parsed[key]

    mathtext.MathTextParser._parse_cached = parse_cached


_share_math_parses()


def _check_headers(name, frame, headers) -> None:
    """Every column reaches the reader under a header: one left out would show its code name."""
    bare = [column for column in frame.columns if not headers or column not in headers]
    if bare:
        raise ValueError(f"table {name!r}: no header for its columns {bare}")


def _check_shown(kind, name, caption, fig=None) -> None:
    """Every table and figure reaches the reader with a caption, and a figure is a figure: a caption or a
    figure lost (None) stops the run where it was written, not in the report."""
    if not (isinstance(caption, str) and caption.strip()):
        raise ValueError(f"{kind} {name!r} needs a caption, not {caption!r}")
    if kind.endswith("figure") and not isinstance(fig, Figure):
        raise ValueError(f"{kind} {name!r} needs a matplotlib figure, not {type(fig).__name__}")


@dataclass
class Results:
    study: str
    scene: str
    title: str
    numbers: dict = field(default_factory=dict)
    tables: dict = field(default_factory=dict)
    figures: dict = field(default_factory=dict)
    stability: list = field(default_factory=list)
    timing_tables: dict = field(default_factory=dict)
    timing_figures: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    _drawn: dict = field(default_factory=dict, repr=False)  # figure_data per figure: read once, used twice

    def number(self, name, value, unit, *, reference=None, tolerance=None, note=None):
        """tolerance: how far a rebuild may move the value before `verify` fails, {"absolute": a},
        {"relative": r} or a bare number (absolute, in `unit`); none: verify's tight default (verify.py).
        A unit the registry does not know, or none given, stops the run here, where it is written, not in the
        report."""
        if not (isinstance(name, str) and name) or value is None:
            raise ValueError(f"a result needs a name and a value, not {name!r} = {value!r}")
        if unit is None:  # said, never left out: a lost unit would pass as a pure number
            raise ValueError(f"result {name!r} needs its unit ('1' for a pure number), not None")
        units.lookup(unit)
        entry = {"value": value, "unit": unit}
        if reference is not None:
            entry["reference"] = reference
        if tolerance is not None:
            entry["tolerance"] = tolerance
        if note:
            entry["note"] = note
        self.numbers[name] = entry

    def table(self, name, frame, caption, headers=None):
        """headers: column -> what the reader sees, "quantity (unit)" with $inline math$. Given, they head
        every column (a column left out would reach the reader as its code name); more may be given (a study's
        shared vocabulary)."""
        _check_headers(name, frame, headers)
        _check_shown("table", name, caption)
        self.tables[name] = (frame, caption, headers or {})

    def figure(self, name, fig, caption):
        _check_shown("figure", name, caption, fig)
        self.figures[name] = (fig, caption)

    def timing_table(self, name, frame, caption, headers=None):
        _check_headers(name, frame, headers)
        _check_shown("timing table", name, caption)
        self.timing_tables[name] = (frame, caption, headers or {})

    def timing_figure(self, name, fig, caption):
        _check_shown("timing figure", name, caption, fig)
        self.timing_figures[name] = (fig, caption)

    def hard_case(self, name, description, measured, bound, unit=""):
        """A numerically hard case: what was measured against the bound it must meet."""
        if not (isinstance(name, str) and name and isinstance(description, str) and description):
            raise ValueError(f"a hard case needs a name and a description, not {name!r}: {description!r}")
        units.lookup(unit)
        self.stability.append(
            {
                "name": name,
                "description": description,
                "measured": measured,
                "bound": bound,
                "unit": unit,
                "holds": bool(abs(measured) <= bound),
            }
        )

    def summary(self) -> dict:
        return {
            "study": self.study,
            "scene": self.scene,
            "title": self.title,
            "numbers": self.numbers,
            "tables": {
                k: {"file": f"{k}.csv", "caption": c, "columns": list(f.columns), "headers": h}
                for k, (f, c, h) in self.tables.items()
            },
            "figures": self._figure_entries(self.figures, self.tables),
            "timings": {
                "tables": {
                    k: {"file": f"{k}.csv", "caption": c, "headers": h}
                    for k, (_, c, h) in self.timing_tables.items()
                },
                "figures": self._figure_entries(self.timing_figures, self.timing_tables),
            },
            "stability": self.stability,
            "notes": self.notes,
        }

    def _plotted(self, figures, tables):
        """Data files of figures that have no table of their name: what they plot, read from the figure."""
        for name, (fig, _) in figures.items():
            if name not in tables and id(fig) not in self._drawn:
                self._drawn[id(fig)] = figure_data(fig)
        return {name: self._drawn[id(fig)] for name, (fig, _) in figures.items() if name not in tables}

    def _figure_entries(self, figures, tables):
        """Each figure's SVG, caption and data file (<name>.csv: its table, or the points it plots)."""
        extracted = self._plotted(figures, tables)
        entries = {}
        for name, (_, caption) in figures.items():
            entries[name] = {"file": f"{name}.svg", "caption": caption, "data": f"{name}.csv"}
            if name in extracted:
                entries[name]["axes"] = extracted[name][1]
        return entries

    def write(
        self,
        out_dir: Path,
        timings_dir: Path,
        provenance: dict,
        timing_rows: dict,
        inputs: dict | None = None,
    ) -> None:
        """Write everything into staging folders, then move both into place. `inputs` ({name: bytes}: the
        scene file as it was read) travel with the results, so that a copied or unpacked folder links its
        scene."""
        out_dir, timings_dir = Path(out_dir), Path(timings_dir)
        staged, writing = [], out_dir
        try:  # a failed write (a full disk) removes what it staged: the folders in place stay as they were
            for target, files in (
                (out_dir, self._result_files(provenance, inputs or {})),
                (timings_dir, self._timing_files(timing_rows)),
            ):
                writing = target
                target.parent.mkdir(parents=True, exist_ok=True)
                for leftover in target.parent.glob(f".{target.name}.*"):  # staged by a run that was killed
                    shutil.rmtree(leftover, ignore_errors=True)
                staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.", dir=target.parent))
                staged.append((staging, target))
                for name, data in files.items():
                    writing = target / name
                    io.write_new_file(staging / name, data)  # ordinary permissions: the folder is new
            for staging, target in staged:
                io.replace_directory(staging, target)
        except OSError as error:
            if io.no_space_line(error):  # named for the file it was to become, not the staged one removed
                raise OSError(error.errno, error.strerror, str(writing)) from None
            raise
        finally:
            for staging, _ in staged:
                shutil.rmtree(staging, ignore_errors=True)

    def _result_files(self, provenance, inputs):
        files = {"summary.json": io.dumps_json(self.summary()).encode(), **inputs}
        files.update({f"{k}.csv": io.csv_text(f).encode() for k, (f, _, _) in self.tables.items()})
        files.update({f"{k}.svg": io.svg_bytes(f) for k, (f, _) in self.figures.items()})
        if self.stability:  # the hard cases as a table too: the report links it
            import pandas as pd

            from .inline_math import plain_text

            # the CSV is read as it is: its descriptions as readable text (κ(1/A − 1/C)), not LaTeX source
            rows = [{**case, "description": plain_text(case["description"])} for case in self.stability]
            files["hard_cases.csv"] = io.csv_text(pd.DataFrame(rows)).encode()
        files.update(
            {
                f"{k}.csv": io.csv_text(data).encode()
                for k, (data, _) in self._plotted(self.figures, self.tables).items()
            }
        )
        # provenance.json carries every other file's checksum: readers refuse a folder that does not match it
        files["provenance.json"] = io.dumps_json({**provenance, "files": io.file_digests(files)}).encode()
        return files

    def _timing_files(self, timing_rows):
        import pandas as pd

        files = {f"{k}.csv": io.csv_text(f).encode() for k, (f, _, _) in self.timing_tables.items()}
        files.update({f"{k}.svg": io.svg_bytes(f) for k, (f, _) in self.timing_figures.items()})
        files.update(
            {
                f"{k}.csv": io.csv_text(data).encode()
                for k, (data, _) in self._plotted(self.timing_figures, self.timing_tables).items()
            }
        )
        files["run.csv"] = io.csv_text(pd.DataFrame([timing_rows])).encode()
        return files


def bare_figure(*, figsize, layout="constrained") -> Figure:
    """pyplot.figure without pyplot: a Figure on an Agg canvas of its own (which measures text, as layouts
    need), in no list of open figures; savefig still writes SVG."""
    fig = Figure(figsize=figsize, layout=layout)
    FigureCanvasAgg(fig)
    return fig


def subplots(nrows=1, ncols=1, *, figsize, layout="constrained", **kwargs):
    """pyplot.subplots without pyplot (see bare_figure); kwargs go to Figure.subplots (sharex, ...)."""
    fig = bare_figure(figsize=figsize, layout=layout)
    return fig, fig.subplots(nrows, ncols, **kwargs)


def new_figure(width=TEXT_WIDTH_IN * 0.85, height=3.4):
    fig, ax = subplots(figsize=(width, height))
    ax.grid(True, which="both", alpha=0.25, linewidth=0.6)
    return fig, ax


def new_figures(ncols, width=TEXT_WIDTH_IN, height=3.0):
    """A row of ncols panels, styled as new_figure."""
    fig, axes = subplots(1, ncols, figsize=(width, height))
    for ax in axes:
        ax.grid(True, which="both", alpha=0.25, linewidth=0.6)
    return fig, axes
