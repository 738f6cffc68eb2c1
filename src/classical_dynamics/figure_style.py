"""One matplotlib style for every figure: the body's sans face, Okabe-Ito colours, text >= 7 pt in print.

Figures are drawn at the size the PDF prints them (the text block is 174 mm wide), so a font size
here is the size a reader meets on paper. Symbols in labels are written as $inline math$, the same
syntax the report's captions use, so a symbol looks the same in text and figure.
"""

from __future__ import annotations

import matplotlib
import matplotlib._mathtext
from cycler import cycler

TEXT_WIDTH_IN = 174 / 25.4  # A4 less 18 mm margins: the widest a figure prints
# a full-width figure: room for the saved SVG's pad and labels past the axes
FULL_WIDTH_IN = TEXT_WIDTH_IN - 0.2
MAX_HEIGHT_IN = 95 / 25.4  # print.css caps a figure's height at 95 mm
# ... and a grid of phase portraits (fig:self-excited-grid-*) at 150 mm: four rows of panels keep their text
GRID_MAX_HEIGHT_IN = 150 / 25.4
PAIR_WIDTH_IN = 0.4 * TEXT_WIDTH_IN  # print.css: a figure paired with a table (.pair) takes 40 % of the width
MIN_FONT_PT = 7.0  # the smallest text allowed at print size

# Okabe & Ito (2008), colour-blind safe; yellow last: it is faint on white.
OKABE_ITO = ["#000000", "#E69F00", "#56B4E9", "#009E73", "#0072B2", "#D55E00", "#CC79A7", "#F0E442"]

# The same method keeps its colour in every figure.
METHOD_COLOURS = {
    "dop853": "#0072B2",
    "rk45": "#56B4E9",
    "dopri5": "#56B4E9",
    "scipy:DOP853": "#D55E00",
    "scipy:RK45": "#E69F00",
    "scipy:LSODA": "#CC79A7",
    "scipy:Radau": "#009E73",
    "scipy:BDF": "#7F7F7F",
    "splitting2": "#000000",
    "splitting4": "#999933",
    "splitting": "#000000",  # olive: Radau has the green
}


def method_colour(method: str, fallback_index: int = 0) -> str:
    """A method's colour, looked up without case; unknown methods take the palette in order."""
    for name, colour in METHOD_COLOURS.items():
        if name.lower() == str(method).lower():
            return colour
    return OKABE_ITO[fallback_index % len(OKABE_ITO)]


STYLE = {
    "font.family": "sans-serif",
    "font.sans-serif": ["DejaVu Sans"],
    "mathtext.fontset": "dejavuserif",  # symbols as in the text: DejaVu Serif italic
    "font.size": 8.0,
    "axes.titlesize": 8.5,
    "axes.labelsize": 8.0,
    "xtick.labelsize": 7.5,
    "ytick.labelsize": 7.5,
    "legend.fontsize": 7.5,
    "legend.title_fontsize": 7.5,
    "figure.titlesize": 9.0,
    "axes.prop_cycle": cycler(color=OKABE_ITO),
    "axes.formatter.use_mathtext": True,  # 1.5 × 10⁻³, never 1.5e-3, on every axis
    "axes.unicode_minus": True,
    "axes.linewidth": 0.6,
    "lines.linewidth": 1.1,
    "lines.markersize": 3.5,
    "grid.linewidth": 0.5,
    "legend.frameon": False,
    "savefig.dpi": 150,
    "svg.fonttype": "path",
}

# Matplotlib sets sub- and superscripts at 0.7 of their text (its mathtext SHRINK_FACTOR, no rcParam): the
# exponent of a 7.5 pt tick label 10^{-3} would print at 5.3 pt. At 0.94 it prints at 7.05 pt.
SCRIPT_SHRINK = 0.94


def use() -> None:
    """Apply the style to every figure this process draws."""
    matplotlib.rcParams.update(STYLE)
    matplotlib._mathtext.SHRINK_FACTOR = SCRIPT_SHRINK


def legend_below(fig, handles=None, labels=None, ncol: int = 4):
    """A figure legend below the axes, in as many columns (at most ncol) as fit the figure's width."""
    if handles is None:
        handles, labels = fig.axes[0].get_legend_handles_labels()
    renderer = fig.canvas.get_renderer()
    for n in range(min(ncol, len(labels)), 0, -1):
        legend = fig.legend(handles, labels, loc="outside lower center", ncol=n)
        if n == 1 or legend.get_window_extent(renderer).width <= 0.93 * fig.bbox.width:  # SVG text runs wider
            return legend
        legend.remove()
