"""A build's results as data: a scene's numbers, its tables as pandas DataFrames with their units, its
figures' data and its provenance, read from a scene folder, a results folder or a dist archive.

    from classical_dynamics.scene_results import load
    chain = load("results/chains/hanging_continuum")
    chain.number("gravest_period_s"), chain.table("modes").attrs["units"]

Everything is read through the results contract (docs/design.md) and only from whole results: a folder with a
file missing or changed against its provenance's checksums is refused (io.ResultError), an archive is checked
and unpacked within limits.py's bounds first (verify.unpack_archive). The report reads its results this way.
"""

from __future__ import annotations

import re
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from . import io

_UNIT = re.compile(r"\(([^()]*)\)\s*$")  # "period (s)" -> "s": a header's unit, as studies write them


@dataclass
class SceneResults:
    """One scene's results (results/<study>/<scene>/)."""

    study: str
    scene: str
    folder: Path
    summary: dict
    provenance: dict
    _tables: dict = field(default_factory=dict, repr=False)

    @property
    def title(self) -> str:
        return self.summary["title"]

    @property
    def numbers(self) -> dict[str, dict]:
        """{name: {"value", "unit", "note"?}}, as summary.json holds them."""
        return self.summary["numbers"]

    def number(self, name: str):
        """A number's value (its unit: unit(name))."""
        return self._entry(name)["value"]

    def unit(self, name: str) -> str:
        return self._entry(name).get("unit", "")

    def table(self, name: str, timing: bool = False):
        """A table as a DataFrame; attrs hold its caption, its columns' headers and their units (from the
        headers' "(unit)"). Measured times (timing=True) are read from the scene's timings folder."""
        import pandas as pd

        key = (name, timing)
        if key not in self._tables:
            meta = self._meta("tables", name, timing)
            frame = pd.read_csv(self._folder(timing) / meta["file"])
            headers = meta.get("headers") or {}
            frame.attrs = {
                "caption": meta.get("caption", ""),
                "headers": {c: headers.get(c, c) for c in frame.columns},
                "units": {c: _unit_of(headers.get(c, "")) for c in frame.columns},
            }
            self._tables[key] = frame
        return self._tables[key].copy()

    def figure_data(self, name: str, timing: bool = False):
        """The data a figure draws (its CSV), with the figure's caption in attrs; None when it has none."""
        import pandas as pd

        meta = self._meta("figures", name, timing)
        if not meta.get("data"):
            return None
        frame = pd.read_csv(self._folder(timing) / meta["data"])
        frame.attrs = {"caption": meta.get("caption", "")}
        return frame

    def figure_svg(self, name: str, timing: bool = False) -> bytes:
        return (self._folder(timing) / self._meta("figures", name, timing)["file"]).read_bytes()

    def _entry(self, name: str) -> dict:
        if name not in self.numbers:
            raise KeyError(f"{self.study}/{self.scene} has no number {name!r}")
        return self.numbers[name]

    def _meta(self, kind: str, name: str, timing: bool) -> dict:
        metas = self.summary["timings"][kind] if timing else self.summary[kind]
        if name not in metas:
            raise KeyError(f"{self.study}/{self.scene} has no {kind[:-1]} {name!r}")
        return metas[name]

    def _folder(self, timing: bool) -> Path:
        return self.folder.parent / "timings" / self.scene if timing else self.folder


class Results(dict):
    """{(study, scene): SceneResults} of a results folder or an archive (an archive's unpacked copy lives as
    long as this object)."""

    _keep = None  # the temporary folder an archive was unpacked into

    def scenes(self, study: str) -> list[str]:
        return sorted(scene for s, scene in self if s == study)


def load_scene(folder: Path | str, study: str | None = None) -> SceneResults:
    """One whole scene folder; io.ResultError if a file is missing or changed against its provenance."""
    folder = Path(folder)
    provenance = io.check_result_folder(folder)
    summary = io.read_json(folder / "summary.json")
    return SceneResults(study or folder.parent.name, folder.name, folder, summary, provenance)


def load_folder(results: Path | str, studies=None) -> Results:
    """Every whole scene of a results folder (results/<study>/<scene>/), of the given studies or of all."""
    results = Path(results)
    names = studies or sorted(p.name for p in results.iterdir() if p.is_dir())
    return Results(
        {
            (study, folder.name): load_scene(folder, study)
            for study in names
            for folder in io.result_folders(results / study)
        }
    )


def load(path: Path | str):
    """A scene folder (SceneResults), a results folder or a dist archive (Results: {(study, scene): ...})."""
    path = Path(path)
    if path.is_file():
        from .verify import unpack_archive

        keep = tempfile.TemporaryDirectory(prefix="classical-dynamics-")
        results = load_folder(unpack_archive(path, Path(keep.name)))
        results._keep = keep
        return results
    if (path / "summary.json").is_file():
        return load_scene(path)
    return load_folder(path)


def _unit_of(header: str) -> str:
    match = _UNIT.search(header or "")
    return match.group(1) if match else ""
