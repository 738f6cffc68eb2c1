"""Rung 1: Lamb's secular formula (Art. 61), the IAU 2006 precession beside it, and the inverse problem."""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

import numpy as np

from ...models import earth
from ...models import precession as prec
from .fitting import per_year_arcsec

ARCSEC_PER_TURN = 1296000.0
# Capitaine, Wallace & Chapront (2003), Table 3: psi_A's rate is r0 - 2.223176″/cy, r0 the first-order
# luni-solar term (the quantity a first-order formula computes) and 2.223176″/cy the second-order, planetary,
# J4, non-linear and geodesic terms P03 adds to it.
P03_CORRECTIONS_ARCSEC_PER_YEAR = 2.223176 / 100.0


CONSTANTS_NAMES = {"lamb1920": "Lamb 1920", "modern": "modern values"}

# The constants' sources as the model states them, with their symbols typeset ($...$, the report's syntax).
_SYMBOLS = (
    ("S/(E+M)", "$S/(E + M)$"),
    ("GM_E", "$GM_\\mathrm{E}$"),
    ("M/E", "$M/E$"),
    ("E/M", "$E/M$"),
    ("n1/n'", "$n_1/n'$"),
    ("n/n'", "$n/n'$"),
    ("e_Moon", "$e_\\mathrm{Moon}$"),
    ("a_Moon", "$a_\\mathrm{Moon}$"),
    ("e' =", "$e'$ ="),
    ("i =", "$i$ ="),
    ("(read from damaged OCR)", "(as far as the damaged scan can be read)"),
    ("328900.5596", "328\u202f900.5596"),
)


def typeset_source(line: str) -> str:
    """A constants source line with its symbols in $...$, read left to right so that a replacement is never
    replaced again."""
    out, rest = [], line
    while rest:
        hits = [(rest.find(old), old, new) for old, new in _SYMBOLS if old in rest]
        if not hits:
            out.append(rest)
            break
        at, old, new = min(hits, key=lambda h: (h[0], -len(h[1])))
        out.append(rest[:at] + new)
        rest = rest[at + len(old) :]
    return "".join(out)


def setup(scene) -> prec.PrecessionModel:
    e = scene.data["earth"]
    H = earth.h_over_c(e["H"], e["H_definition"])
    orbits = prec.CONSTANTS[scene.data["constants"]]()
    return prec.assemble(H, np.radians(e["obliquity_deg"]), orbits, scene.data.get("effects") or {})


def iau2006_rates() -> dict:
    """Rates at J2000 of the IAU 2006 precession (pyerfa p06e), arcsec per Julian year, by central
    differences over +-1 year (the quadratic terms cancel)."""
    import erfa

    before, after = erfa.p06e(2451545.0, -365.25), erfa.p06e(2451545.0, 365.25)
    eps0 = erfa.p06e(2451545.0, 0.0)[0]
    rate = lambda k: (after[k] - before[k]) / 2.0 / earth.ARCSEC
    rates = {"psi_A": rate(1), "p_A": rate(12), "omega_A": rate(2), "eps0_arcsec": eps0 / earth.ARCSEC}
    return rates | {"r0": rates["psi_A"] + P03_CORRECTIONS_ARCSEC_PER_YEAR}


class SecularRates(NamedTuple):
    solar: float  # ″ per Julian year, Lamb Art. 61 (7)
    lunar: float  # (16)
    total: float  # westward, positive
    per_orbit: float  # ″ per revolution round the Sun (Lamb's 'per annum')


def secular_rates(model) -> SecularRates:
    solar, lunar = per_year_arcsec(model.solar_rate()), per_year_arcsec(model.lunar_rate())
    per_orbit = model.secular_rate() * model.orbits.year_days / earth.ARCSEC
    return SecularRates(solar, lunar, solar + lunar, per_orbit)


def run(scene, results) -> prec.PrecessionModel:
    model = setup(scene)
    data = scene.data
    rates = secular_rates(model)
    results.number("H_over_C", model.H, "1", note=data["earth"]["H_source"])
    results.number("obliquity_deg", np.degrees(model.obliquity), "°", note=data["earth"]["obliquity_source"])
    results.number(
        "spin_turns_per_year",
        model.orbits.spin_turns_per_year,
        "1",
        note="$n/n'$: sidereal turns of the Earth in its orbital period",
    )
    for line in model.orbits.sources:
        results.notes.append(
            f"Constants ({CONSTANTS_NAMES.get(model.orbits.name, model.orbits.name)}): "
            f"{typeset_source(line)}."
        )
    solar, lunar, total = rates.solar, rates.lunar, rates.total
    results.number(
        "secular_solar_rate_arcsec_per_year", solar, "″/yr", note="Lamb Art. 61 (7), per Julian year"
    )
    results.number("secular_lunar_rate_arcsec_per_year", lunar, "″/yr", note="Lamb Art. 61 (16)")
    results.number("secular_rate_arcsec_per_year", total, "″/yr", note="westward (retrograde), positive")
    if model.inclined:
        results.number(
            "lunar_inclination_deg",
            np.degrees(model.moon_i),
            "°",
            note="the lunar orbit's mean inclination to the ecliptic (an input of the constants)",
        )
    if model.sun and model.moon:
        results.number(
            "lunar_to_solar_ratio", lunar / solar, "1", note="from the secular rates of the effects included"
        )
    results.number(
        "secular_per_orbit_arcsec",
        rates.per_orbit,
        "″",
        note="per revolution of the Earth round the Sun (Lamb's 'per annum')",
    )
    if data["fidelity"] == "secular":
        results.number("precession_rate_arcsec_per_year", total, "″/yr", note="the secular formula")
        results.number(
            "precession_period_years", ARCSEC_PER_TURN / total, "yr", note="Julian years, 360°/rate"
        )
    inverse = data.get("analysis", {}).get("inverse_problem")
    if inverse:
        _record_inverse(
            results, inverse_problem(model, inverse["observed_rate_arcsec_per_year"]), inverse["source"]
        )
    if data["earth"]["H_definition"] == "(C-A)/A":  # the other reading of the same printed number, beside it
        other = secular_rates(replace(model, H=data["earth"]["H"]))
        results.number(
            "secular_solar_rate_read_as_H_over_C_arcsec_per_year",
            other.solar,
            "″/yr",
            note="the printed constant read as $(C - A)/C$ instead",
        )
        results.number(
            "secular_per_orbit_read_as_H_over_C_arcsec",
            other.per_orbit,
            "″",
            note="the printed constant read as $(C - A)/C$ instead; per revolution round the Sun",
        )
    if data["constants"] == "modern":
        _record_iau(results, iau_comparison(total))
        _record_kepler_distance(results, model, data.get("effects") or {})
    return model


def kepler_moon_distance_m(orbits) -> float:
    """The Moon's semi-major axis from Kepler's third law with its sidereal mean motion,
    a^3 = G(E + M)/n^2: the convention some theories adopt in place of the mean distance."""
    n = orbits.moon_n / earth.SECONDS_PER_DAY
    return (earth.GM_M3_PER_S2 * (1.0 + prec.MOON_OVER_EARTH) / n**2) ** (1.0 / 3.0)


def _record_kepler_distance(results, model, effects):
    """The first-order rate with the Moon at Kepler's distance: how much the lunar distance convention moves
    it (the size of one input's choice, set beside the residual against P03's r0)."""
    a = kepler_moon_distance_m(model.orbits)
    gm_moon = model.orbits.moon_gm_over_a3 * prec.MOON_DISTANCE_M**3
    kepler = replace(model.orbits, moon_gm_over_a3=gm_moon / a**3)
    total = secular_rates(prec.assemble(model.H, model.obliquity, kepler, effects)).total
    results.number(
        "kepler_moon_distance_km",
        a / 1e3,
        "km",
        note="the Moon's semi-major axis from Kepler's third law, $a^3 = G(E + M)/n^2$, sidereal month",
    )
    results.number(
        "secular_rate_kepler_moon_distance_arcsec_per_year",
        total,
        "″/yr",
        note="the secular formula with the Moon at Kepler's distance in place of 384 400 km",
    )
    results.number(
        "kepler_moon_distance_rate_change_relative",
        total / results.numbers["secular_rate_arcsec_per_year"]["value"] - 1.0,
        "1",
        note="what the lunar distance convention alone does to the rate",
    )


class Inverse(NamedTuple):
    observed: float  # the observed rate, as the scene gives it
    H: float  # (C - A)/C that reproduces it
    computed_over_observed_minus_one: float
    C_minus_A_over_A: float  # the same H as (C - A)/A


def inverse_problem(model, observed) -> Inverse:
    """Lamb's 'inverse process': the rate is proportional to H, so H = H_model x observed / computed."""
    # Lamb's 'per annum' is per revolution; a modern rate is per Julian year: compare like with like
    rate = model.secular_rate()
    computed = (
        rate * model.orbits.year_days / earth.ARCSEC
        if model.orbits.name == "lamb1920"
        else per_year_arcsec(rate)
    )
    H = model.H * observed / computed
    return Inverse(observed, H, computed / observed - 1.0, H / (1.0 - H))


def _record_inverse(results, values: Inverse, source):
    H = values.H
    results.number("inverse_observed_rate_arcsec_per_year", values.observed, "″/yr", note=source)
    results.number(
        "H_from_observed_rate",
        H,
        "1",
        note="$(C - A)/C$ that reproduces the rate inverted (the scene's source)",
    )
    results.number(
        "computed_over_observed_minus_one",
        values.computed_over_observed_minus_one,
        "1",
        note="the formula's rate against the rate inverted",
    )
    results.number(
        "C_minus_A_over_A_from_observed_rate", values.C_minus_A_over_A, "1", note="the same as $(C - A)/A$"
    )


class IauComparison(NamedTuple):
    rates: dict  # iau2006_rates()
    secular_minus_psi_A_relative: float
    period_years: float  # 360°/p_A


def iau_comparison(total) -> IauComparison:
    """The IAU 2006 rates beside this scene's secular rate `total` (″/yr)."""
    iau = iau2006_rates()
    return IauComparison(iau, total / iau["psi_A"] - 1.0, ARCSEC_PER_TURN / iau["p_A"])


def _record_iau(results, values: IauComparison):
    iau = values.rates
    results.number(
        "iau2006_psi_A_rate_arcsec_per_year",
        iau["psi_A"],
        "″/yr",
        note="luni-solar precession, IAU 2006 (pyerfa p06e), at J2000",
    )
    results.number(
        "iau2006_p_A_rate_arcsec_per_year",
        iau["p_A"],
        "″/yr",
        note="general precession in longitude, IAU 2006 (pyerfa p06e)",
    )
    results.number(
        "iau2006_omega_A_rate_arcsec_per_year",
        iau["omega_A"],
        "″/yr",
        note="obliquity against the J2000 ecliptic, IAU 2006 (pyerfa p06e)",
    )
    results.number("iau2006_eps0_arcsec", iau["eps0_arcsec"], "″", note="obliquity at J2000 (pyerfa p06e)")
    results.number(
        "p03_first_order_rate_arcsec_per_year",
        iau["r0"],
        "″/yr",
        note="P03's first-order luni-solar term $r_0$: $\\psi_\\mathrm{A}$ + 2.223176″/cy "
        "(Capitaine et al. 2003, Table 3)",
    )
    results.number(
        "secular_minus_psi_A_relative",
        values.secular_minus_psi_A_relative,
        "1",
        note="the first-order formula against the IAU 2006 luni-solar precession",
    )
    results.number("iau2006_period_years", values.period_years, "yr", note="360°/$p_A$")
