"""The one registry of units: how each unit a result carries is written for a reader.

Results store a unit as a short key ("″/yr", "d", "rad/s", "particles"); the report writes it only
through `unit_text`, so a unit looks the same in prose, tables and claims, and a key nobody
registered stops the build instead of reaching the reader as typed. Typography follows the IAU
Style Manual and ISO 80000: symbols are never pluralized (3 d, 2 yr), words are (1 link, 2 links),
″ ′ ° close up to the number (50.4″/yr), every other unit follows a thin space.

Many results of this report are dimensionless or in the natural units of a scaled problem (times in
√(l/g), frequencies in √(g/l), Lee's τ): those keys name the scale, written as math.
"""

from __future__ import annotations

from dataclasses import dataclass

# Lee's τ is a dimensionless time: a value of τ carries no unit (the header names the variable).
DIMENSIONLESS = ("", "1", "bool", None, "τ", "1/τ")


@dataclass(frozen=True)
class Unit:
    symbol: str  # as the reader sees it, with $inline math$ where it is a symbol
    word: bool = False  # a counted noun: pluralized, singular for exactly 1
    close_up: bool = False  # ″, ′, °: no space before the unit
    singular: str | None = None


REGISTRY: dict[str, Unit] = {
    # time
    "s": Unit("s"),
    "h": Unit("h"),
    "d": Unit("d"),
    "yr": Unit("yr"),
    "cy": Unit("cy"),
    "sidereal days": Unit("sid.\u00a0d"),
    # angle and angular rates
    "rad": Unit("rad"),
    "°": Unit("°", close_up=True),
    "°E": Unit("°E", close_up=True),
    "″": Unit("″", close_up=True),
    "mas": Unit("mas"),
    "″/yr": Unit("″/yr", close_up=True),
    "mas/yr": Unit("mas/yr"),
    "mas/cy": Unit("mas/cy"),
    "″/cy": Unit("″/cy", close_up=True),
    "rad/s": Unit("rad s⁻¹"),
    "rad/d": Unit("rad d⁻¹"),
    "cycles/yr": Unit("cycles/yr"),
    # lengths
    "m": Unit("m"),
    "m/s²": Unit("m s⁻²"),
    "km": Unit("km"),
    "cm": Unit("cm"),
    "ft": Unit("ft"),
    # a couple in the British engineering units of Lamb's examples (foot-pound force)
    "ft-lb": Unit("ft·lb"),
    "slug ft²": Unit("slug ft²"),  # a moment of inertia in the same units
    # natural units of scaled problems
    "σ": Unit("$\\sigma$"),
    "time": Unit("time units"),
    "time units": Unit("time units"),
    "1/time": Unit("per time unit"),
    "rad/time": Unit("rad per time unit"),
    "1/time²": Unit("per time unit squared"),
    "g/l": Unit("$g/l$"),
    "√(g/l)": Unit("$\\sqrt{g/l}$"),
    "√(l/g)": Unit("$\\sqrt{l/g}$"),
    "√(k/m)": Unit("$\\sqrt{k/m}$"),
    "k/m": Unit("$k/m$"),
    "μ": Unit("$\\mu$"),
    "√(g/a)": Unit("$\\sqrt{g/a}$"),
    "a": Unit("$a$"),
    "k": Unit("$k$"),
    "Ω²": Unit("$\\Omega^2$"),
    "1/(A n)": Unit("$1/An$"),
    "√(T/σ)/a": Unit("$\\sqrt{T/\\sigma}/a$"),
    "x/l from the free end": Unit("of the length from the free end"),
    "ω": Unit("$\\omega$"),  # a whirling chain's frequencies, in units of its rate of turning
    "(π/l)√(P/ρ)": Unit("$(\\pi/l)\\sqrt{P/\\rho}$"),  # a string's fundamental
    "rad·time": Unit("rad × time units"),  # an angle times Lee's scaled time
    # counted things
    "particles": Unit("particles", word=True, singular="particle"),
    "links": Unit("links", word=True, singular="link"),
    "steps": Unit("steps", word=True, singular="step"),
    "periods": Unit("periods", word=True, singular="period"),
    "gravest periods": Unit("gravest periods", word=True, singular="gravest period"),
    "years": Unit("years", word=True, singular="year"),
    "days": Unit("days", word=True, singular="day"),
    "cycles": Unit("cycles", word=True, singular="cycle"),
    "turns": Unit("turns", word=True, singular="turn"),
}


class UnknownUnit(KeyError):
    pass


def lookup(key: str | None) -> Unit | None:
    if key in DIMENSIONLESS:
        return None
    try:
        return REGISTRY[key]
    except KeyError:
        raise UnknownUnit(f"unit {key!r} is not in the unit registry (classical_dynamics/units.py)") from None


def unit_text(key: str | None, value=None) -> str:
    """The unit as written after `value` (plural chosen by value), with its leading space; '' if none."""
    unit = lookup(key)
    if unit is None:
        return ""
    text = unit.symbol
    if unit.word and value is not None and value == 1 and unit.singular:
        text = unit.singular
    return text if unit.close_up else "\u202f" + text  # narrow no-break space: 303.6 d never splits


def header(quantity: str, key: str | None) -> str:
    """A table or axis header: "quantity (unit)", or the quantity alone when dimensionless."""
    unit = lookup(key)
    return quantity if unit is None or unit.word else f"{quantity} ({unit.symbol})"
