"""Rung 2: the orbit-averaged spin-axis equations over a long span: the cone, the period, the obliquity."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...figure_style import FULL_WIDTH_IN
from ...formatting import format_number, plural, shortest
from ...models import earth
from ...models import precession as prec
from ...results import subplots
from ...solvers.ode import Problem, solve
from ...solvers.timing import min_time
from . import fitting
from .secular import ARCSEC_PER_TURN

RTOL = 1e-12
SAMPLE_DAYS = 0.25 * earth.JULIAN_YEAR_DAYS
# the obliquity's whole range, in the cone's caption as in the chapter's num(..., sig=3) (tests/
# test_report_typesetting.py reads the chapter's sig against this)
RANGE_SIG = 3
RATE_BOUND = 1e-9  # hard case: the averaged rate against the secular formula (exact without i)
MEAN_OBLIQUITY_BOUND_ARCSEC = (
    0.1  # hard case: the mean obliquity stays the scene's (start on the forced state)
)


def integrate(model, span_days, t_eval=None, rtol=RTOL):
    problem = Problem(
        prec.averaged_rhs,
        prec.initial_axis(*prec.start(model, averaged=True)),
        (0.0, span_days),
        prec.averaged_parameters(model),
        name="averaged spin axis",
    )
    return solve(problem, "dop853", rtol=rtol, atol=rtol, t_eval=t_eval)


class Averaged(NamedTuple):
    span_years: float
    t: np.ndarray  # days, every SAMPLE_DAYS
    s: np.ndarray  # the spin axis at t, (n, 3)
    steps: int  # DOP853's
    evaluations: int
    seconds: float  # one run, minimum of repeats
    psi: np.ndarray
    eps: np.ndarray
    norm_drift: float  # largest departure of |s| from 1
    rate: float  # fitted (rad/day)
    mean_obliquity_offset_arcsec: float | None  # fitted mean obliquity - the model's; None for a fixed node
    rate_minus_secular_relative: float
    second_order_mas_per_century: float | None  # averaged - secular, with the node regressing; else None
    crossing_period_days: float | None  # psi reaches 360°; None within the span
    obliquity_range_arcsec: float
    obliquity_drift_arcsec: float  # mean of the last twentieth minus the first's


def averaged(model, span_years) -> Averaged:
    """The averaged equations over span_years (cheap: a whole cycle takes 0.1 s, quick or not)."""
    span = span_years * earth.JULIAN_YEAR_DAYS
    t = np.arange(0.0, span, SAMPLE_DAYS)
    sol = integrate(model, span, t)
    seconds, _, _ = min_time(lambda: integrate(model, span), repeats=3, budget_s=2.0)
    psi, eps = prec.precession_angles(sol.y_eval)
    norm_drift = float(np.max(np.abs(np.linalg.norm(sol.y_eval, axis=1) - 1.0)))

    # A fixed lunar orbit tilted to the ecliptic: the axis precesses about the orbits' mean pole, not the
    # ecliptic's, and the obliquity swings; with the node regressing it averages to the ecliptic's.
    nodal = model.moon and model.inclined
    offset = second_order = None
    if nodal and not model.regressing:
        rate = np.polyfit(t, psi, 1)[0]
    else:
        args = fitting.arguments(model, model.secular_rate())
        rate = fitting.fit(t, psi, args).rate
        mean_eps = fitting.fit(t, eps, args).offset
        offset = (mean_eps - model.obliquity) / earth.ARCSEC
    if nodal and model.regressing:
        second_order = (rate - model.secular_rate()) * 36525.0 / earth.MAS
    eps_arcsec = eps / earth.ARCSEC
    k = max(1, len(t) // 20)
    return Averaged(
        span_years,
        t,
        sol.y_eval,
        sol.n_steps,
        sol.nfev,
        seconds,
        psi,
        eps,
        norm_drift,
        rate,
        offset,
        rate / model.secular_rate() - 1.0,
        second_order,
        _period_by_crossing(t, psi),
        float(eps_arcsec.max() - eps_arcsec.min()),
        float(np.mean(eps_arcsec[-k:]) - np.mean(eps_arcsec[:k])),
    )


def run(scene, model, results, quick):
    values = averaged(model, scene.data["analysis"]["span_years"])
    _record_averaged(results, model, values)
    if model.moon and model.inclined and model.regressing:
        _record_nutation(results, nutation(model, values.t, values.psi, values.eps))
    _cone_figure(results, model, values.s, values.t, values.eps / earth.ARCSEC, values.span_years)


def _record_averaged(results, model, values: Averaged):
    span_years, rate = values.span_years, values.rate
    results.timing_table(
        "cost",
        pd.DataFrame(
            [
                {
                    "rung": "averaged",
                    "effects": ", ".join(model.listed),
                    "span_years": span_years,
                    "steps": values.steps,
                    "evaluations": values.evaluations,
                    "seconds": values.seconds,
                }
            ]
        ),
        f"Cost of the averaged equations over {shortest(span_years)} {plural(span_years, 'year')} "
        f"(DOP853, rtol {shortest(RTOL)}; minimum of repeats).",
        headers={
            "rung": "rung",
            "effects": "effects",
            "span_years": "span (yr)",
            "steps": "steps",
            "evaluations": "evaluations",
            "seconds": "wall time (s)",
        },
    )
    results.number("span_years", span_years, "yr")
    results.hard_case(
        "unit_axis",
        "$|\\mathbf{s}| = 1$ kept by the averaged equations over the span (largest departure)",
        values.norm_drift,
        1e-9,
    )
    if values.mean_obliquity_offset_arcsec is not None:
        results.number(
            "mean_obliquity_offset_arcsec",
            values.mean_obliquity_offset_arcsec,
            "″",
            note="fitted mean obliquity − the model's (mean) obliquity",
        )
        results.hard_case(
            "start_on_forced_state",
            "The axis starts on the mean pole moved by the first-order "
            "nutation, so the mean obliquity is the model's (″)",
            values.mean_obliquity_offset_arcsec,
            MEAN_OBLIQUITY_BOUND_ARCSEC,
            "″",
        )
    if not (model.moon and model.inclined):
        results.hard_case(
            "averaged_rate_matches_formula",
            "The averaged equations' rate against the secular "
            "formula, exact for orbits in the ecliptic (relative)",
            values.rate_minus_secular_relative,
            RATE_BOUND,
        )
    elif values.second_order_mas_per_century is not None:
        results.number(
            "second_order_lunar_mas_per_century",
            values.second_order_mas_per_century,
            "mas/cy",
            note="averaged − secular: the node's regression couples to the nutation at second order",
        )
    rate_y = fitting.per_year_arcsec(rate)
    results.number("precession_rate_arcsec_per_year", rate_y, "″/yr", note="fitted to the integrated $\\psi$")
    results.number("precession_period_years", ARCSEC_PER_TURN / rate_y, "yr", note="360° / fitted rate")
    results.number("averaged_minus_secular_relative", values.rate_minus_secular_relative, "1")
    results.hard_case(
        "retrograde", "The equinox moves westward (1 if it moves eastward)", 0.0 if rate > 0 else 1.0, 0.0
    )
    if values.crossing_period_days is not None:
        results.number(
            "precession_period_by_crossing_years",
            values.crossing_period_days / earth.JULIAN_YEAR_DAYS,
            "yr",
            note="the time for $\\psi$ to reach 360°, read off the integration",
        )
    results.number(
        "obliquity_range_arcsec",
        values.obliquity_range_arcsec,
        "″",
        note="max − min of the obliquity over the span",
    )
    results.number(
        "obliquity_drift_arcsec",
        values.obliquity_drift_arcsec,
        "″",
        note="the mean of the last twentieth of the span minus the first's",
    )


def _period_by_crossing(t, psi):
    full = np.nonzero(psi >= 2.0 * np.pi)[0]
    if len(full) == 0:
        return None
    j = full[0]
    return float(np.interp(2.0 * np.pi, psi[j - 1 : j + 1], t[j - 1 : j + 1]))


class Nutation(NamedTuple):
    d_psi: float  # the 18.6-year term in longitude, fitted (rad)
    d_eps: float  # in obliquity
    closed_psi: float  # first order in the lunar inclination
    closed_eps: float
    two_cot_two_eps: float  # the first-order ratio d_psi/d_eps


def nutation(model, t, psi, eps) -> Nutation:
    """The 18.6-year nutation of the averaged model, fitted, against its first-order closed form."""
    window = t <= min(t[-1], 1000.0 * earth.JULIAN_YEAR_DAYS)  # a millennium: the cone's curvature is
    args = fitting.arguments(model, model.secular_rate())  # then negligible for a line fit
    fp = fitting.fit(t[window], psi[window], args)
    fe = fitting.fit(t[window], eps[window], args)
    d_psi, d_eps = fitting.amplitude(fp, "18.6 yr"), fitting.amplitude(fe, "18.6 yr")
    closed_psi, closed_eps = model.nutation_18p6yr()
    return Nutation(d_psi, d_eps, closed_psi, closed_eps, 2.0 / np.tan(2.0 * model.obliquity))


def _record_nutation(results, values: Nutation):
    d_psi, d_eps = values.d_psi, values.d_eps
    closed_psi, closed_eps = values.closed_psi, values.closed_eps
    results.number(
        "nutation_longitude_18p6yr_arcsec", d_psi / earth.ARCSEC, "″", note="fitted, averaged equations"
    )
    results.number(
        "nutation_obliquity_18p6yr_arcsec", d_eps / earth.ARCSEC, "″", note="fitted, averaged equations"
    )
    results.number(
        "nutation_longitude_18p6yr_first_order_arcsec",
        closed_psi / earth.ARCSEC,
        "″",
        note="first order in the lunar inclination $i$",
    )
    results.number("nutation_obliquity_18p6yr_first_order_arcsec", closed_eps / earth.ARCSEC, "″")
    results.number(
        "nutation_ratio_18p6yr",
        d_psi / d_eps,
        "1",
        note="$\\Delta\\psi/\\Delta\\varepsilon$; first order: $2\\cot 2\\varepsilon$",
    )
    results.number("two_cot_two_eps", values.two_cot_two_eps, "1")


def _cone_figure(results, model, s, t, eps_arcsec, span_years):
    years = t / earth.JULIAN_YEAR_DAYS
    fig, (ax, bx) = subplots(
        1, 2, figsize=(FULL_WIDTH_IN, 3.1), layout="constrained", gridspec_kw={"width_ratios": [1, 1.35]}
    )
    ax.plot(s[:, 0], s[:, 1], lw=0.6, color="C4")
    ax.plot([0], [0], "k+", ms=8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"$s_x$, toward the J2000 equinox")
    ax.set_ylabel(r"$s_y$")
    ax.set_title("spin axis seen from the ecliptic pole")
    # the 18.6-year nutation is far too fast to draw over a cycle: its band, and the mean through it
    bins = np.array_split(np.arange(len(years)), min(300, len(years)))
    mid = [years[b].mean() for b in bins]
    eps0_deg = np.degrees(model.obliquity)
    small = float(np.ptp(eps_arcsec)) < 360.0  # a swing below 0.1°: in ″ about the start
    shown = eps_arcsec - eps0_deg * 3600.0 if small else eps_arcsec / 3600.0
    bx.fill_between(
        mid,
        [shown[b].min() for b in bins],
        [shown[b].max() for b in bins],
        color="C4",
        alpha=0.3,
        lw=0,
        label="range in each bin",
    )
    bx.plot(mid, [shown[b].mean() for b in bins], lw=0.8, color="C4", label="mean in each bin")
    bx.margins(y=0.3)
    bx.legend(loc="upper center", ncol=2)
    if not small:
        bx.ticklabel_format(axis="y", useOffset=False)
    bx.set_xlabel("time from J2000 (yr)")
    bx.set_ylabel(r"$\varepsilon - \varepsilon_0$ (″)" if small else r"obliquity $\varepsilon$ (°)")
    bx.set_title("obliquity against the fixed ecliptic")
    bx.grid(True, alpha=0.25)
    ax.grid(True, alpha=0.25)
    bin_years = span_years / min(300, len(years))
    nodal = model.moon and model.inclined
    notice = (
        "the axis circles the mean pole of the ecliptic and the fixed, tilted lunar orbit, not the "
        "ecliptic's pole, so the obliquity swings by degrees"
        if nodal and not model.regressing
        else "the axis moves on a circle about the ecliptic pole and the obliquity keeps its mean"
    )
    effects = ", ".join(e.replace("_", " ") for e in model.listed)
    offset = (
        f" (shown as $\\varepsilon - \\varepsilon_0$, $\\varepsilon_0$ = {format_number(eps0_deg, 6)}°; "
        f"whole range {format_number(results.numbers['obliquity_range_arcsec']['value'], RANGE_SIG)}″)"
        if small
        else ""
    )
    results.figure(
        "cone",
        fig,
        f"Left: the spin axis $\\mathbf{{s}}$ projected on the ecliptic plane over "
        f"{shortest(span_years)} {plural(span_years, 'year')} of the averaged equations "
        f"({effects}), the ecliptic pole marked +; right: the obliquity against the fixed "
        f"ecliptic{offset}, its range and mean in bins of about {format_number(bin_years, 2)} "
        f"{plural(bin_years, 'year')}. Notice that {notice}.",
    )
