"""LaTeX equations as SVG paths (ziamath): no fonts, no network, identical in HTML and PDF."""

from __future__ import annotations

import base64
from functools import lru_cache

import ziamath


@lru_cache(maxsize=None)
def latex_data_uri(latex: str, size: float = 15.0) -> str:
    svg = ziamath.Latex(latex, size=size).svg()
    return "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
