"""The data a figure plots, read back from its artists, so every figure ships a CSV a reader can replot.

A figure whose study saved a table of the same name has its data already; any other figure gets
<name>.csv from here: one row per plotted point, in long form (panel, series, x, y). Reading the
artists rather than asking each study to save its arrays means the CSV is what was drawn, no more
and no less.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.collections import Collection, PathCollection
from matplotlib.lines import Line2D


def _series_name(artist, kind: str, k: int) -> str:
    label = artist.get_label() or ""
    return label if label and not label.startswith("_") else f"{kind} {k}"


def _xy_blocks(ax):
    """(series, array of shape (n, 2)) for every line, marker set and curve collection of one panel."""
    k = 0
    for artist in ax.get_children():
        if isinstance(artist, Line2D):
            xy = np.asarray(artist.get_xydata(), dtype=float)
            kind = "line" if artist.get_linestyle() not in ("None", "", " ") else "points"
            if len(xy):
                k += 1
                yield _series_name(artist, kind, k), xy
        elif isinstance(artist, PathCollection):  # scatter: the offsets are the points
            xy = np.asarray(artist.get_offsets(), dtype=float).reshape(-1, 2)
            if len(xy):
                k += 1
                yield _series_name(artist, "points", k), xy
        elif isinstance(artist, Collection):  # contours, line collections, filled bands: each piece
            paths = artist.get_paths()
            levels = getattr(artist, "levels", None)  # a contour set: one path per level
            k += 1
            name = _series_name(artist, "curve", k)
            for i, path in enumerate(paths):
                if levels is not None and len(levels) == len(paths):
                    name_i = f"{name}, level {levels[i]:.15g}"
                else:
                    name_i = name if len(paths) == 1 else f"{name}, path {i + 1}"
                pieces = path.to_polygons(closed_only=False)
                for j, piece in enumerate(pieces):
                    if len(piece):
                        yield (
                            (f"{name_i}, piece {j + 1}" if len(pieces) > 1 else name_i),
                            np.asarray(piece, float),
                        )


def figure_data(fig) -> tuple[pd.DataFrame, list[dict]]:
    """The points a figure plots (panel, series, x, y) and each panel's axis labels."""
    rows, axes = [], []
    panels = [ax for ax in fig.get_axes() if ax.get_label() != "<colorbar>"]
    for panel, ax in enumerate(panels, start=1):
        axes.append({"panel": panel, "title": ax.get_title(), "x": ax.get_xlabel(), "y": ax.get_ylabel()})
        for series, xy in _xy_blocks(ax):
            frame = pd.DataFrame({"panel": panel, "series": series, "x": xy[:, 0], "y": xy[:, 1]})
            rows.append(frame)
    data = pd.concat(rows, ignore_index=True) if rows else pd.DataFrame(columns=["panel", "series", "x", "y"])
    return data, axes
