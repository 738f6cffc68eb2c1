"""The one rule for writing a number as text: significant figures, × 10ⁿ, real minus, grouped digits.

Used by the report (prose, tables, claims) and by the studies' captions, so a number reads the same
wherever it appears. Plain text out (Unicode), no markup: the report escapes and wraps it.
"""

from __future__ import annotations

import math
from numbers import Integral

MINUS = "\u2212"  # −
GROUP = "\u202f"  # narrow no-break space between groups of three digits
TIMES = "\u202f×\u202f"  # 1.6 × 10⁻¹⁰ never breaks across a line
SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
FIXED_RANGE = (-3, 5)  # decimal notation for 10⁻³ <= |x| < 10⁵, powers of ten outside


def _group(digits: str) -> str:
    """12345.678 -> 12 345.678; 9999 stays 9999 (groups only above 9 999)."""
    whole, _, frac = digits.partition(".")
    if len(whole) > 4:
        whole = f"{int(whole):,}".replace(",", GROUP)
    return whole + ("." + frac if frac else "")


def power_of_ten(exponent: int) -> str:
    return "10" + str(int(exponent)).translate(SUPERSCRIPT)


def format_number(value, sig: int = 4, *, fixed_range=FIXED_RANGE) -> str:
    """value to `sig` significant figures.

    The value is rounded first and its notation chosen from the rounded value, so 99 999.6 at five
    figures is 1.0000 × 10⁵, never 100000, and 9.9996 at four is 10.00. Integers (counts) print
    exactly; a float with more integer digits than figures is rounded (33 787 at two figures is 34 000).
    None prints as an em dash, booleans as yes/no, strings unchanged.
    """
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, Integral):  # a count (numpy's integers too) prints exactly
        value = int(value)
        text = _group(str(abs(value)))
        return (MINUS if value < 0 else "") + text
    if isinstance(value, str):
        return value
    value = float(value)
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "∞" if value > 0 else MINUS + "∞"
    if value == 0:
        return "0"
    sig = max(int(sig), 1)
    mantissa, exp = f"{abs(value):.{sig - 1}e}".split("e")
    exponent = int(exp)  # exponent of the rounded value
    sign = MINUS if value < 0 else ""
    low, high = fixed_range
    if low <= exponent < high:
        decimals = max(sig - 1 - exponent, 0)
        # digits beyond the figures asked for are zeros: 33 787 at two figures is 34 000, not 33 787
        return sign + _group(f"{float(mantissa + 'e' + exp):.{decimals}f}")
    return f"{sign}{mantissa}{TIMES}{power_of_ten(exponent)}"


def needs_power_of_ten(value, sig: int = 4) -> bool:
    """Whether format_number writes this value with a power of ten."""
    if isinstance(value, (bool, int, str)) or value is None:
        return False
    value = float(value)
    if not math.isfinite(value) or value == 0:
        return False
    exponent = int(f"{abs(value):.{max(int(sig), 1) - 1}e}".split("e")[1])
    return not FIXED_RANGE[0] <= exponent < FIXED_RANGE[1]


COLUMN_FIXED_RANGE = (-4, 5)  # a column reads 0.0002178 beside 9.226 before it writes 9.226 × 10⁰


def _whole(v) -> bool:
    """A float that holds a count (16.0 from a CSV column with a gap): printed as the count it is."""
    return isinstance(v, float) and math.isfinite(v) and v.is_integer() and abs(v) < 1e15


def _plain(v) -> bool:
    """A value no notation choice applies to: a count, a flag, a text, none, a non-finite number or zero."""
    return isinstance(v, (bool, Integral, str)) or v is None or not math.isfinite(float(v)) or v == 0


def exact_figures(value: float) -> int:
    """The significant figures of the shortest decimal that reads back as this float (0.25 -> 2)."""
    mantissa = repr(abs(value)).partition("e")[0]
    return max(len(mantissa.replace(".", "").lstrip("0").rstrip("0")), 1)


def format_column(values, sig: int = 4) -> list[str]:
    """A table column in one notation: if any value needs a power of ten, every value is written as
    mantissa × 10ⁿ (n = 0 as the mantissa alone), so a column never mixes 0.0044 or 24.1 with 2.3 × 10⁻⁶
    (two readers of the report took 0.241 beside 5.01 × 10⁻¹ for a mixed column). A column of counts prints
    them exactly, and a column within 10⁻⁴ to 10⁵ stays in decimals (9.226 and 0.0002178)."""
    finite = [
        v
        for v in values
        if isinstance(v, (float, Integral)) and not isinstance(v, bool) and math.isfinite(float(v))
    ]
    if finite and all(isinstance(v, Integral) or _whole(float(v)) for v in finite):
        return [format_number(int(v)) if v in finite else format_number(v, sig) for v in values]
    # no figures a value does not have: a column of targets 10⁻⁶, 10⁻⁸ reads 1 × 10⁻⁶, not 1.000 × 10⁻⁶
    sig = min(sig, max((exact_figures(float(v)) for v in finite if v != 0), default=sig))

    def in_range(v) -> bool:
        if _plain(v):
            return True
        exponent = int(f"{abs(float(v)):.{max(int(sig), 1) - 1}e}".split("e")[1])
        return COLUMN_FIXED_RANGE[0] <= exponent < COLUMN_FIXED_RANGE[1]

    if all(in_range(v) for v in values):
        return [format_number(v, sig, fixed_range=COLUMN_FIXED_RANGE) for v in values]
    out = []
    for v in values:
        if _plain(v):
            out.append(format_number(v, sig))
        else:  # mantissa × 10ⁿ; at n = 0 the mantissa alone (2.22, not 2.22 × 10⁰: a factor of one)
            out.append(format_number(v, sig, fixed_range=(0, 1)))
    return out


def format_decimals(value, decimals: int) -> str:
    """A fixed number of decimals (a tolerance's place), with the same minus and grouping; a zero, exact
    (Lamb's speed of a wave at rest) or below half the last place (a change the resolution cannot see), is 0,
    not a string of zeros 0.000 nor −0.000."""
    text = f"{float(value):.{max(decimals, 0)}f}"
    if float(text) == 0:
        return "0"
    return (MINUS if text.startswith("-") else "") + _group(text.lstrip("-"))


def shortest(value, max_figures: int = 8) -> str:
    """A value as printed in a source: the shortest decimal that reads back as the same float,
    so 50.5 stays 50.5 and 306 stays 306 (no digits the source never had). A reference computed
    to more figures than a reader can use shows `max_figures`."""
    if isinstance(value, (bool, str)) or value is None:
        return format_number(value)
    if isinstance(value, int) or float(value).is_integer() and abs(value) < 1e15:
        return format_number(int(value))
    text = repr(float(value))
    mantissa, _, exp = text.partition("e")
    digits = len(mantissa.lstrip("-").replace(".", "").lstrip("0"))
    return format_number(float(value), min(digits, max_figures))


def sig_for_tolerance(value, *, relative=None, absolute=None, cap: int = 12, floor: int = 2) -> int:
    """Significant figures a check supports: a relative tolerance r supports about -log10(r) + 1
    figures (1 % -> 3), an absolute tolerance a the digits down to a's place."""
    if relative:
        figures = math.floor(-math.log10(abs(relative))) + 1
    elif absolute and value:
        figures = math.floor(math.log10(abs(value))) - math.floor(math.log10(abs(absolute))) + 1
    else:
        return 4
    return int(min(max(figures, floor), cap))


def plural(count, singular: str, plural_form: str | None = None) -> str:
    """1 year, 2 years, 1.5 years: only exactly one takes the singular."""
    return singular if count == 1 else (plural_form or singular + "s")


def measured_and_bound(measured, bound, sig: int = 2) -> tuple[str, str]:
    """A measured value beside the bound it must meet, in one notation (0.73 against 1, 2.3 × 10⁻¹² against
    1 × 10⁻⁹): the measured value to `sig` figures, the bound to its own (10⁻⁹, not 1.0 × 10⁻⁹)."""
    pair = [v for v in (measured, bound) if isinstance(v, (int, float)) and not isinstance(v, bool)]
    power = any(needs_power_of_ten(v, sig) for v in pair if not isinstance(v, Integral))
    fixed = (0, 1) if power else FIXED_RANGE

    def text(v, figures):
        if _plain(v):
            return format_number(v, figures)
        return format_number(v, figures, fixed_range=fixed)

    bound_figures = min(sig, exact_figures(float(bound))) if isinstance(bound, float) else sig
    return text(measured, sig), text(bound, bound_figures)
