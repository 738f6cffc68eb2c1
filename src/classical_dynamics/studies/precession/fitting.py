"""Secular rate and periodic terms of a precession series, fitted together.

A straight line fitted to psi(t) over a window that is not a whole number of the periodic terms'
periods (0.5 yr, 13.7 d, 18.6 yr) takes part of those terms into its slope: the rate then depends on
the window. Fitting the line together with the known periodic arguments removes that dependence.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...models import earth
from ...models.precession import PrecessionModel

TERMS = (
    "18.6 yr",
    "9.3 yr",
    "annual",
    "semi-annual",
    "122-day",
    "monthly",
    "fortnightly",
    "13.6-day",
    "9.1-day",
)


@dataclass
class Fit:
    offset: float
    rate: float  # per day
    sin: dict  # term -> coefficient of sin(argument)
    cos: dict
    residual_rms: float


def arguments(model: PrecessionModel, rate_rad_per_day: float) -> dict:
    """Each periodic term's argument as a function of t (days), in this model's own elements.

    The torque sees the Sun, the Moon and the node from the moving equinox, so each rate is the
    sidereal rate plus the precession rate (the node: minus, it regresses).
    """
    o = model.orbits
    terms = {}
    if model.moon and model.inclined and model.regressing:
        node = lambda t: o.node0 + (model.node_rate + rate_rad_per_day) * t
        terms["18.6 yr"] = node
        terms["9.3 yr"] = lambda t: 2.0 * node(t)
    L_sun = lambda t: o.sun_L0 + (o.sun_n + rate_rad_per_day) * t
    L_moon = lambda t: o.moon_L0 + (o.moon_n + rate_rad_per_day) * t
    l_sun = lambda t: o.sun_L0 - o.sun_varpi + o.sun_n * t
    l_moon = lambda t: o.moon_L0 - o.moon_varpi + (o.moon_n - model.perigee_rate) * t
    if model.sun:
        terms["semi-annual"] = lambda t: 2.0 * L_sun(t)
        if model.eccentric:
            terms["annual"] = l_sun
            terms["122-day"] = lambda t: 2.0 * L_sun(t) + l_sun(t)
    if model.moon:
        terms["fortnightly"] = lambda t: 2.0 * L_moon(t)
        if model.eccentric:
            terms["monthly"] = l_moon
            terms["9.1-day"] = lambda t: 2.0 * L_moon(t) + l_moon(t)
        if "18.6 yr" in terms:
            terms["13.6-day"] = lambda t: 2.0 * L_moon(t) - terms["18.6 yr"](t)
    return {k: terms[k] for k in TERMS if k in terms}


def iau_arguments() -> dict:
    """The same terms with the IAU 2000 fundamental arguments (pyerfa; Simon et al. 1994, t from J2000)."""
    import erfa

    cy = lambda t: np.asarray(t) / 36525.0
    Om = lambda t: erfa.faom03(cy(t))
    L_sun = lambda t: erfa.faf03(cy(t)) - erfa.fad03(cy(t)) + Om(t)
    L_moon = lambda t: erfa.faf03(cy(t)) + Om(t)
    l_sun = lambda t: erfa.falp03(cy(t))
    l_moon = lambda t: erfa.fal03(cy(t))
    return {
        "18.6 yr": Om,
        "9.3 yr": lambda t: 2.0 * Om(t),
        "annual": l_sun,
        "semi-annual": lambda t: 2.0 * L_sun(t),
        "122-day": lambda t: 2.0 * L_sun(t) + l_sun(t),
        "monthly": l_moon,
        "fortnightly": lambda t: 2.0 * L_moon(t),
        "13.6-day": lambda t: 2.0 * L_moon(t) - Om(t),
        "9.1-day": lambda t: 2.0 * L_moon(t) + l_moon(t),
    }


def fit(t: np.ndarray, y: np.ndarray, args: dict) -> Fit:
    """Least squares of y = offset + rate t + sum_k (s_k sin arg_k + c_k cos arg_k)."""
    scale = max(float(t[-1] - t[0]), 1.0)
    columns = [np.ones_like(t), (t - t[0]) / scale]
    for f in args.values():
        a = f(t)
        columns += [np.sin(a), np.cos(a)]
    X = np.column_stack(columns)
    coef, *_ = np.linalg.lstsq(X, y, rcond=None)
    residual = y - X @ coef
    names = list(args)
    return Fit(
        offset=float(coef[0] - coef[1] * t[0] / scale),
        rate=float(coef[1] / scale),
        sin={k: float(coef[2 + 2 * j]) for j, k in enumerate(names)},
        cos={k: float(coef[3 + 2 * j]) for j, k in enumerate(names)},
        residual_rms=float(np.sqrt(np.mean(residual**2))),
    )


def amplitude(f: Fit, term: str) -> float:
    return float(np.hypot(f.sin[term], f.cos[term]))


def per_year_arcsec(rate_rad_per_day: float) -> float:
    """rad/day to arcsec per Julian year (the IAU's unit is the Julian century of 36525 days)."""
    return rate_rad_per_day * earth.JULIAN_YEAR_DAYS / earth.ARCSEC
