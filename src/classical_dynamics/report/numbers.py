"""The one formatting rule for numbers in the report: significant figures, then units."""

from __future__ import annotations

import math

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def format_number(value, sig: int = 4) -> str:
    """4 significant figures by default; powers of ten outside [1e-3, 1e5)."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return f"{value:,}".replace(",", " ") if abs(value) >= 10000 else str(value)
    if isinstance(value, str):
        return value
    value = float(value)
    if not math.isfinite(value):
        return "∞" if value > 0 else ("−∞" if value < 0 else "NaN")
    if value == 0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    if -3 <= exponent < 5:
        decimals = max(sig - 1 - exponent, 0)
        text = f"{value:.{decimals}f}"
        rounded = float(text)
        if rounded != 0 and math.floor(math.log10(abs(rounded))) > exponent:   # 9.9996 -> 10.00
            text = f"{value:.{max(decimals - 1, 0)}f}"
        return text.replace("-", "−")
    mantissa, exp = f"{value:.{sig - 1}e}".split("e")
    return f"{mantissa.replace('-', '−')} × 10{str(int(exp)).translate(_SUPERSCRIPT)}"


def format_unit(unit: str | None) -> str:
    if unit in (None, "", "1", "bool"):
        return ""
    return unit
