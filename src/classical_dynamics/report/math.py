"""LaTeX equations as SVG paths (ziamath): no fonts, no network, identical in HTML and PDF."""

from __future__ import annotations

import base64
import hashlib
import re
from functools import lru_cache
from importlib.metadata import version
from pathlib import Path

from .. import io

SIZE_PX = 15.0  # the font size the SVG is set at
# Where each equation, once set, is kept between runs (keep_in): ziamath takes about a second for the report's
# thirty displays, nearly half of the HTML job, and an edited scene changes none of them.
_KEPT: list[Path | None] = [None]
TYPESETTING = ("ziamath", "ziafont", "latex2mathml")  # what sets an equation: a new release sets them anew


def keep_in(folder: Path | None) -> None:
    """Keep the equations' SVGs in folder/<the typesetting packages' versions>/ (None: keep none). The folder
    must be one for this code (the report job's is named by its code digest): the SVG of an equation is then a
    function of its LaTeX, its size and those versions alone, the key of its file."""
    if folder is not None:
        folder = Path(folder) / "-".join(f"{name}{version(name)}" for name in TYPESETTING)
    _KEPT[0] = folder
    _svg.cache_clear()
    latex_image.cache_clear()


@lru_cache(maxsize=None)
def _svg(latex: str, size: float) -> str:
    """The equation set once: its image and its width are read from the same SVG."""
    folder = _KEPT[0]
    if folder is not None:
        kept = folder / (hashlib.sha256(f"{size!r}\n{latex}".encode()).hexdigest() + ".svg")
        if kept.is_file():
            return kept.read_text(encoding="utf-8")
    import ziamath  # 0.1 s to import: not when every equation is kept

    svg = ziamath.Latex(latex, size=size).svg()
    if folder is not None:
        io.atomic_write_text(kept, svg)
    return svg


@lru_cache(maxsize=None)
def latex_image(latex: str, size: float = SIZE_PX) -> tuple[str, float]:
    """(data URI, height in em of the text it is set for): the screen scales the image with the text, so a
    display equation is as large as the body text around it (its own size is 15 px against 16 px)."""
    svg = _svg(latex, size)
    height = float(re.search(r'height="([0-9.]+)"', svg).group(1))
    uri = "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
    return uri, height / size


PHONE_EM = 22.0  # the widest display a 390 px phone shows whole (its text column, in em of the body text)


def stacked(latex: str) -> str | None:
    """The display with its side-by-side parts (separated by \\qquad at the top level) set one under the
    other, for a phone; None where there is nothing to stack. Only top-level \\qquad counts: one inside
    braces or a nested environment belongs to a single formula."""
    m = re.fullmatch(r"\\begin\{gathered\}(.*)\\end\{gathered\}", latex.strip(), re.S)
    body = m.group(1) if m else latex
    parts, depth, start, i = [], 0, 0, 0
    while i < len(body):
        if body.startswith("\\begin{", i):
            depth += 1
        elif body.startswith("\\end{", i):
            depth -= 1
        elif body[i] == "{" and (i == 0 or body[i - 1] != "\\"):
            depth += 1
        elif body[i] == "}" and (i == 0 or body[i - 1] != "\\"):
            depth -= 1
        elif depth == 0 and body.startswith("\\qquad", i):
            parts.append(body[start:i])
            start = i = i + len("\\qquad")
            continue
        i += 1
    if not parts:
        return None
    parts.append(body[start:])
    joined = r" \\ ".join(p.strip() for p in parts)
    return rf"\begin{{gathered}}{joined}\end{{gathered}}"


def width_em(latex: str, size: float = SIZE_PX) -> float:
    """The display's width in em of the text it is set for."""
    return float(re.search(r'width="([0-9.]+)"', _svg(latex, size)).group(1)) / size
