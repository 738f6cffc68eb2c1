"""LaTeX equations as SVG paths (ziamath): no fonts, no network, identical in HTML and PDF."""

from __future__ import annotations

import base64
import re
from functools import lru_cache

import ziamath

SIZE_PX = 15.0  # the font size the SVG is set at


@lru_cache(maxsize=None)
def latex_image(latex: str, size: float = SIZE_PX) -> tuple[str, float]:
    """(data URI, height in em of the text it is set for): the screen scales the image with the text, so a
    display equation is as large as the body text around it (its own size is 15 px against 16 px)."""
    svg = ziamath.Latex(latex, size=size).svg()
    height = float(re.search(r'height="([0-9.]+)"', svg).group(1))
    uri = "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
    return uri, height / size
