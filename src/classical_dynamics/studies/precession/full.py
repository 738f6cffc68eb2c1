"""Rung 3: the full torqued rigid Earth, spin resolved: precession, nutations, and their hard cases.

The integrator is the Strang splitting of the symmetric body's exact free flow with the torque kick
(the methods "symmetric-torqued2" and "4" of solvers.fixed_step). The precession is read off the angular
momentum L in space (the figure axis differs from it by the forced diurnal wobble, the Oppolzer terms,
reported).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.ticker import MaxNLocator

from ...figure_style import FULL_WIDTH_IN
from ...formatting import format_decimals, format_number, plural, shortest
from ...models import earth
from ...models import precession as prec
from ...results import subplots
from ...solvers import rigid_body
from ...solvers.fixed_step import FixedProblem, Save, solve_fixed
from ...solvers.timing import min_time
from . import averaged, fitting
from .secular import ARCSEC_PER_TURN

QUICK_SPAN_YEARS = 20.0
FREE_NUTATION_YEARS = 3.0
L_BOUND = 1e-12  # hard case: |L| kept over the run (relative); the torque is normal to e3
OBLIQUITY_RATE_BOUND = 1e-3  # ″ per century: no secular obliquity change against a fixed ecliptic
ALIASING_BOUND = 1e-4  # relative spread of the rate fitted with the periodic terms, over windows
FREE_NUTATION_STEP_HOURS = 0.75  # the diurnal forced wobble must be resolved to ~1 % to see the free one
NUTATION_TERMS = {
    "18.6 yr": "18p6yr",
    "9.3 yr": "9p3yr",
    "annual": "annual",
    "semi-annual": "semiannual",
    "122-day": "122day",
    "monthly": "monthly",
    "fortnightly": "fortnightly",
    "13.6-day": "13p6day",
    "9.1-day": "9p1day",
}


def integrate(model, span_days, step_days, order=2, sample_days=1.0, forced=True):
    """(t, m body, q) sampled every `sample_days` (a whole number of steps)."""
    n = int(round(span_days / step_days))
    h = span_days / n
    every = max(1, int(round(sample_days / h)))
    m0, q0 = prec.initial_state(model, forced)
    params = np.concatenate([[1.0 - model.H, 1.0], model.parameters()])  # A, C (units of C), the torque's
    problem = FixedProblem(rigid_body.packed(m0, q0), params, prec.torque_body)
    sol = solve_fixed(problem, f"symmetric-torqued{order}", h=h, n_steps=n, save=Save(every=every))
    return sol.t_eval, sol.y_eval[:, :3], sol.y_eval[:, 3:]


def angular_momentum_axis(ms, qs):
    return rigid_body.rotate_to_space(qs, ms)


def fit_series(model, t, psi, eps):
    """Rate and periodic terms of psi and eps; the arguments' rates need the precession rate: iterate once."""
    f = fitting.fit(t, psi, fitting.arguments(model, model.secular_rate()))
    args = fitting.arguments(model, f.rate)
    return fitting.fit(t, psi, args), fitting.fit(t, eps, args), args


class FullRun(NamedTuple):
    span_years: float
    step: float  # days
    order: int  # of the splitting
    steps: int
    seconds: float  # the run, minimum of repeats
    t: np.ndarray  # days, daily samples
    ms: np.ndarray  # angular momentum in the body
    qs: np.ndarray  # attitude quaternions
    psi: np.ndarray  # precession angles of L
    eps: np.ndarray
    fp: fitting.Fit  # psi's rate and periodic terms
    fe: fitting.Fit  # eps's
    args: dict  # the periodic terms' arguments
    averaged_rate: float  # the averaged equations' over the same span (rad/day)
    first_order: tuple  # (name, closed_psi, closed_eps) of the 18.6-year and semi-annual closed forms
    sidebands: tuple  # the Sun's annual and 122-day obliquity terms, first order in e' (() if e' = 0)
    figure_axis_offset: float  # largest angle between L and the figure axis (rad)


def full_run(model, span_years, step, order) -> FullRun:
    """The spin-resolved run over span_years at a step of `step` days, read as precession and nutations."""
    span = span_years * earth.JULIAN_YEAR_DAYS
    seconds, (t, ms, qs), _ = min_time(lambda: integrate(model, span, step, order), repeats=3, budget_s=3.0)
    steps = int(round(span / step))
    L = angular_momentum_axis(ms, qs)
    psi, eps = prec.precession_angles(L)
    fp, fe, args = fit_series(model, t, psi, eps)
    avg = averaged.integrate(model, span, t)
    a_psi, _ = prec.precession_angles(avg.y_eval)
    fa = fitting.fit(t, a_psi, args)
    first_order = (("18p6yr", *model.nutation_18p6yr()), ("semiannual", *model.semiannual()))
    sidebands = tuple(model.solar_obliquity_sidebands()) if model.sun_e else ()
    e3 = rigid_body.rotate_to_space(qs, np.array([0.0, 0.0, 1.0]))
    cosang = np.clip(np.sum(L * e3, axis=1) / np.linalg.norm(L, axis=1), -1.0, 1.0)
    return FullRun(
        span_years,
        step,
        order,
        steps,
        seconds,
        t,
        ms,
        qs,
        psi,
        eps,
        fp,
        fe,
        args,
        fa.rate,
        first_order,
        sidebands,
        float(np.max(np.arccos(cosang))),
    )


def run(scene, model, results, quick):
    analysis = scene.data["analysis"]
    span_years = min(analysis["span_years"], QUICK_SPAN_YEARS) if quick else analysis["span_years"]
    step = analysis["step_hours"] / 24.0
    order = analysis.get("order", 2)
    values = full_run(model, span_years, step, order)
    t, psi, eps, args = values.t, values.psi, values.eps, values.args
    _record_full_run(results, model, values)
    if "18.6 yr" in args:
        _record_node_period(results, node_period(t, eps, args))
    _record_invariants(results, invariants(values.ms, values.fe), span_years)
    results.number(
        "figure_axis_offset_mas",
        values.figure_axis_offset / earth.MAS,
        "mas",
        note="largest angle between $\\mathbf{L}$ and the figure axis (forced diurnal wobble, Oppolzer "
        "terms)",
    )
    if analysis.get("compare_iau"):
        _record_iau_nutation(results, iau_nutation(t, psi, eps, values.fp, values.fe, args))
    spread = None  # the rate's relative spread over the aliasing windows, if any
    if analysis.get("aliasing_windows_years"):
        windows = aliasing(t, psi, analysis["aliasing_windows_years"], args)
        _record_aliasing(results, windows)
        spread = windows.spread_with_terms
    if analysis.get("free_nutation"):
        _record_free_nutation(results, free_nutation(model, order))
    if analysis.get("effect_ladder"):
        _record_effect_ladder(
            results, effect_ladder(model, step, order, min(span_years, QUICK_SPAN_YEARS)), spread
        )


def _record_full_run(results, model, values: FullRun):
    span_years, step, order, steps = values.span_years, values.step, values.order, values.steps
    fp, fe, args = values.fp, values.fe, values.args
    results.timing_table(
        "cost",
        pd.DataFrame(
            [
                {
                    "rung": "full",
                    "effects": ", ".join(model.listed),
                    "span_years": span_years,
                    "step_hours": step * 24,
                    "order": order,
                    "steps": steps,
                    "seconds": values.seconds,
                    "ns_per_step": values.seconds / steps * 1e9,
                }
            ]
        ),
        f"Cost of the spin-resolved run over {_years(span_years)} (splitting of order {order}, minimum of "
        "repeats).",
        headers={
            "rung": "rung",
            "effects": "effects",
            "span_years": "span (yr)",
            "step_hours": "step (h)",
            "order": "order",
            "steps": "steps",
            "seconds": "wall time (s)",
            "ns_per_step": "per step (ns)",
        },
    )
    results.number("span_years", span_years, "yr")
    results.number("step_hours", step * 24.0, "h")
    results.number("steps", steps, "1")
    rate_y = fitting.per_year_arcsec(fp.rate)
    results.number(
        "precession_rate_arcsec_per_year",
        rate_y,
        "″/yr",
        note="fitted to $\\psi$ of $\\mathbf{L}$ together with the periodic terms",
    )
    results.number("precession_period_years", ARCSEC_PER_TURN / rate_y, "yr", note="360° / fitted rate")
    results.number("full_minus_secular_relative", fp.rate / model.secular_rate() - 1.0, "1")
    results.number(
        "averaged_rate_arcsec_per_year",
        fitting.per_year_arcsec(values.averaged_rate),
        "″/yr",
        note="the averaged equations over the same span",
    )
    results.number("full_minus_averaged_relative", fp.rate / values.averaged_rate - 1.0, "1")
    results.hard_case(
        "retrograde", "The equinox moves westward (1 if it moves eastward)", 0.0 if fp.rate > 0 else 1.0, 0.0
    )
    results.number(
        "lamb_psi_dot_sign",
        -1 if fp.rate > 0 else 1,
        "1",
        note="the sign of $\\dot\\psi$ in Lamb's sense (Art. 61 (6)): −1, the axis moves retrograde",
    )
    for term, key in NUTATION_TERMS.items():
        if term in args:
            results.number(
                f"nutation_longitude_{key}_arcsec",
                fitting.amplitude(fp, term) / earth.ARCSEC,
                "″",
                note=f"{term} term of $\\Delta\\psi$, fitted",
            )
            results.number(
                f"nutation_obliquity_{key}_arcsec",
                fitting.amplitude(fe, term) / earth.ARCSEC,
                "″",
                note=f"{term} term of $\\Delta\\varepsilon$, fitted",
            )
    for name, closed_psi, closed_eps in values.first_order:
        if closed_psi:
            results.number(f"nutation_longitude_{name}_first_order_arcsec", closed_psi / earth.ARCSEC, "″")
            results.number(f"nutation_obliquity_{name}_first_order_arcsec", closed_eps / earth.ARCSEC, "″")
    for key, closed in zip(("annual", "122day"), values.sidebands):
        results.number(
            f"nutation_obliquity_{key}_first_order_arcsec",
            closed / earth.ARCSEC,
            "″",
            note="first order: e′ (annual) and 7e′/3 (122-day) times the semi-annual term",
        )
    results.number(
        "fit_residual_longitude_mas",
        fp.residual_rms / earth.MAS,
        "mas",
        note="rms of $\\psi$ after the line and the fitted terms",
    )


class NodePeriod(NamedTuple):
    fitted: float  # years
    iau: float  # 2 pi/|Omega'|, IAU 2000 (years)


def node_period(t, eps, args) -> NodePeriod:
    """Lamb Art. 61: "the angle chi goes through its phases in about 19 years". The period of the long
    nutation in obliquity fitted freely: the node's argument 2 pi t/P (and 2x it, and the 13.6-day term's
    2L_moon - node) with P found by least squares, the other terms at their own arguments; against the
    node's period from the IAU 2000 fundamental argument Omega (pyerfa)."""
    import erfa
    from scipy.optimize import minimize_scalar

    fixed = {k: f for k, f in args.items() if k not in ("18.6 yr", "9.3 yr", "13.6-day")}
    moon2 = None
    if "13.6-day" in args and "fortnightly" in args:
        moon2 = args["fortnightly"]  # 2 L_moon

    def terms(period_days):
        node = lambda x: 2.0 * np.pi * x / period_days
        free = dict(fixed, node=node, node2=lambda x: 2.0 * node(x))
        if moon2 is not None:
            free["lunar"] = lambda x: moon2(x) + node(x)
        return free

    def residual(period_years):
        return fitting.fit(t, eps, terms(period_years * earth.JULIAN_YEAR_DAYS)).residual_rms

    best = minimize_scalar(residual, bounds=(14.0, 24.0), method="bounded", options={"xatol": 1e-7})
    period = float(best.x)
    step = 1e-3  # Julian centuries
    omega = np.unwrap([erfa.faom03(-step), erfa.faom03(step)])
    iau = 2.0 * np.pi / abs(omega[1] - omega[0]) * 2.0 * step * 100.0
    return NodePeriod(period, iau)


def _record_node_period(results, values: NodePeriod):
    period, iau = values
    results.number(
        "node_period_fitted_years",
        period,
        "yr",
        note="period of the long nutation in obliquity, fitted freely (least squares over the period)",
    )
    results.number(
        "node_period_iau_years", iau, "yr", note="$2\\pi/|\\dot\\Omega|$, IAU 2000 (pyerfa faom03)"
    )
    results.number("node_period_fitted_over_iau_minus_one", period / iau - 1.0, "1")


class Invariants(NamedTuple):
    angular_momentum_drift: float  # largest relative change of |L|
    obliquity_rate_arcsec_per_century: float  # the fitted obliquity's secular part


def invariants(ms, fe) -> Invariants:
    norms = np.linalg.norm(ms, axis=1)
    drift = float(np.max(np.abs(norms / norms[0] - 1.0)))
    return Invariants(drift, fe.rate * 36525.0 / earth.ARCSEC)


def _record_invariants(results, values: Invariants, span_years):
    drift, rate_cy = values
    results.number(
        "angular_momentum_drift",
        drift,
        "1",
        note="largest $|\\Delta|\\mathbf{L}||/|\\mathbf{L}|$ over the run",
    )
    results.hard_case(
        "angular_momentum_kept",
        f"$|\\mathbf{{L}}|$ over {_years(span_years)} of daily spin (relative; "
        "the couple is normal to the figure axis)",
        drift,
        L_BOUND,
    )
    results.number(
        "obliquity_rate_arcsec_per_century",
        rate_cy,
        "″/cy",
        note="secular part of the fitted obliquity; IAU 2006's −46.8″/cy comes from the moving ecliptic",
    )
    results.hard_case(
        "no_obliquity_drift",
        f"Secular obliquity change over {_years(span_years)} against the fixed ecliptic (″/cy)",
        rate_cy,
        OBLIQUITY_RATE_BOUND,
        "″/cy",
    )


class IauNutation(NamedTuple):
    rows: list  # per term: the full model's amplitudes and IAU 2000B's, fitted the same way (″)
    t: np.ndarray
    ours_psi: np.ndarray  # the full model's periodic parts, day by day (rad)
    ours_eps: np.ndarray
    d_psi: np.ndarray  # IAU 2000B's on the same days (rad)
    d_eps: np.ndarray
    rms_longitude_arcsec: float  # full model - IAU 2000B, day by day
    rms_obliquity_arcsec: float


def iau_nutation(t, psi, eps, fp, fe, args) -> IauNutation:
    """IAU 2000B nutation (pyerfa nut00b) on the same days, fitted with the IAU arguments, side by side."""
    import erfa

    d_psi, d_eps = erfa.nut00b(2451545.0, t)
    iau_args = {k: v for k, v in fitting.iau_arguments().items() if k in args}
    ip, ie = fitting.fit(t, d_psi, iau_args), fitting.fit(t, d_eps, iau_args)
    rows = []
    for term in args:
        rows.append(
            {
                "term": term,
                "longitude_arcsec": fitting.amplitude(fp, term) / earth.ARCSEC,
                "longitude_iau2000b_arcsec": fitting.amplitude(ip, term) / earth.ARCSEC,
                "obliquity_arcsec": fitting.amplitude(fe, term) / earth.ARCSEC,
                "obliquity_iau2000b_arcsec": fitting.amplitude(ie, term) / earth.ARCSEC,
            }
        )
    # the periodic parts, day by day
    ours_psi = psi - (fp.offset + fp.rate * t)
    ours_eps = eps - (fe.offset + fe.rate * t)
    return IauNutation(
        rows,
        t,
        ours_psi,
        ours_eps,
        d_psi,
        d_eps,
        float(np.sqrt(np.mean((ours_psi - d_psi) ** 2))) / earth.ARCSEC,
        float(np.sqrt(np.mean((ours_eps - d_eps) ** 2))) / earth.ARCSEC,
    )


def _record_iau_nutation(results, values: IauNutation):
    rows, t = values.rows, values.t
    ours_psi, ours_eps, d_psi, d_eps = values.ours_psi, values.ours_eps, values.d_psi, values.d_eps
    frame = pd.DataFrame(rows)
    results.table(
        "nutation",
        frame,
        "Amplitudes of the nutation terms in longitude ($\\Delta\\psi$) and obliquity "
        "($\\Delta\\varepsilon$): the full model's, fitted, beside the IAU 2000B series evaluated on the "
        "same days and fitted the same way with the IAU arguments.",
        headers={
            "term": "term",
            "longitude_arcsec": "$\\Delta\\psi$ (″)",
            "longitude_iau2000b_arcsec": "$\\Delta\\psi$, IAU 2000B (″)",
            "obliquity_arcsec": "$\\Delta\\varepsilon$ (″)",
            "obliquity_iau2000b_arcsec": "$\\Delta\\varepsilon$, IAU 2000B (″)",
        },
    )
    for row in rows:
        key = NUTATION_TERMS[row["term"]]
        results.number(f"iau2000b_longitude_{key}_arcsec", row["longitude_iau2000b_arcsec"], "″")
        results.number(f"iau2000b_obliquity_{key}_arcsec", row["obliquity_iau2000b_arcsec"], "″")
        results.number(
            f"longitude_{key}_over_iau_minus_one",
            row["longitude_arcsec"] / row["longitude_iau2000b_arcsec"] - 1.0,
            "1",
            note="full model / IAU 2000B − 1",
        )
        results.number(
            f"obliquity_{key}_over_iau_minus_one",
            row["obliquity_arcsec"] / row["obliquity_iau2000b_arcsec"] - 1.0,
            "1",
            note="full model / IAU 2000B − 1",
        )
    results.number(
        "nutation_difference_rms_longitude_arcsec",
        values.rms_longitude_arcsec,
        "″",
        note="full model − IAU 2000B, day by day (rms)",
    )
    results.number("nutation_difference_rms_obliquity_arcsec", values.rms_obliquity_arcsec, "″")
    show = t <= 20.0 * earth.JULIAN_YEAR_DAYS
    years = 2000.0 + t[show] / earth.JULIAN_YEAR_DAYS
    fig, axes = subplots(
        3,
        1,
        figsize=(FULL_WIDTH_IN, 3.7),
        sharex=True,
        layout="constrained",
        gridspec_kw={"height_ratios": [1, 1, 0.8]},
    )
    for ax, ours, iau, name in (
        (axes[0], ours_psi, d_psi, r"$\Delta\psi$ (″)"),
        (axes[1], ours_eps, d_eps, r"$\Delta\varepsilon$ (″)"),
    ):
        # the model broad underneath, IAU 2000B thin on top: where they agree both stay visible (a broad grey
        # curve under the model was hidden by it everywhere)
        ax.plot(years, ours[show] / earth.ARCSEC, lw=1.8, color="C3", alpha=0.6, label="full model")
        ax.plot(years, iau[show] / earth.ARCSEC, color="k", lw=0.45, label="IAU 2000B")
        ax.set_ylabel(name)
        ax.margins(y=0.22)
        ax.grid(True, alpha=0.25)
    # the two curves agree to a fraction of an arcsecond: the difference is what shows the rigid Earth
    axes[2].plot(years, (ours_psi - d_psi)[show] / earth.ARCSEC, lw=0.5, color="C4", label=r"$\Delta\psi$")
    axes[2].plot(
        years, (ours_eps - d_eps)[show] / earth.ARCSEC, lw=0.5, color="C1", label=r"$\Delta\varepsilon$"
    )
    axes[2].set_ylabel("model − IAU (″)")
    axes[2].grid(True, alpha=0.25)
    # one legend above the panels, off the data (the curves fill each panel's width); each entry's name is its
    # line's own label, so that a name cannot slide onto another line
    handles, labels = axes[0].get_legend_handles_labels()
    differences = axes[2].get_legend_handles_labels()
    fig.legend(
        handles + differences[0],
        labels + [f"difference, {label}" for label in differences[1]],
        loc="outside upper center",
        ncol=4,
    )
    axes[2].set_xlabel("year")
    axes[2].xaxis.set_major_locator(MaxNLocator(integer=True, steps=[1, 2, 5, 10]))  # calendar years
    axes[2].xaxis.set_major_formatter("{x:.0f}")
    shown = int(round(t[show][-1] / earth.JULIAN_YEAR_DAYS))
    results.figure(
        "nutation",
        fig,
        "Nutation in longitude ($\\Delta\\psi$, top) and obliquity "
        "($\\Delta\\varepsilon$, bottom) from J2000: the full model's $\\psi$ and $\\varepsilon$ of "
        "$\\mathbf{L}$ less their fitted lines (broad, green) under the IAU 2000B series (thin, black) for "
        f"the first {format_number(shown)} {plural(shown, 'year')}, and below, their difference. The "
        "18.6-year term dominates and the black curve runs inside the green one; the difference is what the "
        "rigid Earth lacks, mostly the semi-annual and fortnightly terms that the real Earth's non-rigid "
        "response amplifies.",
    )


class Aliasing(NamedTuple):
    frame: pd.DataFrame  # per window: the bare line's rate and the rate with the periodic terms (″/yr)
    spread_line_only: float  # (largest - smallest)/mean over the windows
    spread_with_terms: float


def aliasing(t, psi, windows_years, args) -> Aliasing:
    """The rate from windows of awkward lengths: a bare line against the line with the periodic terms."""
    rows = []
    for w in windows_years:
        inside = t <= w * earth.JULIAN_YEAR_DAYS
        if inside.sum() < 30:
            continue
        bare = np.polyfit(t[inside], psi[inside], 1)[0]
        with_terms = fitting.fit(t[inside], psi[inside], args).rate
        rows.append(
            {
                "window_years": w,
                "line_only_arcsec_per_year": fitting.per_year_arcsec(bare),
                "with_periodic_terms_arcsec_per_year": fitting.per_year_arcsec(with_terms),
            }
        )
    frame = pd.DataFrame(rows)
    spread = lambda col: float((frame[col].max() - frame[col].min()) / frame[col].mean())
    return Aliasing(frame, spread("line_only_arcsec_per_year"), spread("with_periodic_terms_arcsec_per_year"))


def _record_aliasing(results, values: Aliasing):
    results.table(
        "aliasing",
        values.frame,
        "The secular rate fitted over windows that are not whole periods of the "
        "nutations: a bare straight line, and a line fitted together with the periodic terms. The bare "
        "line's rate depends on the window; with the periodic terms it does not.",
        headers={
            "window_years": "window (yr)",
            "line_only_arcsec_per_year": "rate, line only (″/yr)",
            "with_periodic_terms_arcsec_per_year": "rate, line and periodic terms (″/yr)",
        },
    )
    results.number(
        "aliasing_spread_line_only",
        values.spread_line_only,
        "1",
        note="(largest − smallest)/mean of the bare line's rate over the windows",
    )
    results.number("aliasing_spread_with_terms", values.spread_with_terms, "1")
    results.hard_case(
        "aliasing",
        "The rate fitted with the periodic terms does not depend on the window (relative "
        "spread over the windows)",
        values.spread_with_terms,
        ALIASING_BOUND,
    )


def free_wobble_amplitude(model, step, order, forced, years=FREE_NUTATION_YEARS):
    """The Euler free wobble a start excites: the projection of the body-frame pole offset onto e^{i sigma t}
    over whole Euler periods (the forced terms are near-diurnal and average out)."""
    sigma = model.n * model.H / (1.0 - model.H)
    periods = max(1, int(years * earth.JULIAN_YEAR_DAYS * sigma / (2.0 * np.pi)))
    span = periods * 2.0 * np.pi / sigma
    t, ms, _ = integrate(model, span, step, order, sample_days=step, forced=forced)
    w = (ms[:, 0] + 1j * ms[:, 1]) / ((1.0 - model.H) * model.n)
    inner = w[:-1] * np.exp(-1j * sigma * t[:-1])  # the last sample repeats the first phase
    return float(abs(np.mean(inner)))


class FreeNutation(NamedTuple):
    axis_start: float  # the free wobble left by starting on the figure axis (rad)
    expected: float  # |e3 x N|/(C n^2) at the start
    forced_start: float  # left by starting on the steady forced precession
    bound: float  # the fastest couple's nu/n


def free_nutation(model, order) -> FreeNutation:
    """The forced start e3 x N/(Cn) is first order: it neglects the couple's own rate of change, so it may
    leave a fraction of order nu/n of the axis start's wobble, nu the fastest couple (the Moon's fortnightly
    2 n1, or the Sun's semi-annual 2 n'): that fraction is the bound."""
    step = FREE_NUTATION_STEP_HOURS / 24.0
    axis = free_wobble_amplitude(model, step, order, forced=False)
    forced = free_wobble_amplitude(model, step, order, forced=True)
    fastest = 2.0 * (model.orbits.moon_n if model.moon else model.orbits.sun_n)
    _, q0 = prec.initial_state(model)
    expected = float(np.linalg.norm(prec.forced_offset(model, q0))) / model.n
    return FreeNutation(axis, expected, forced, fastest / model.n)


def _record_free_nutation(results, values: FreeNutation):
    axis, expected, forced, bound = values
    results.number(
        "free_wobble_axis_start_mas",
        axis / earth.MAS,
        "mas",
        note="Euler free wobble excited by starting with $\\omega$ along the figure axis",
    )
    results.number(
        "free_wobble_expected_mas",
        expected / earth.MAS,
        "mas",
        note="$|\\mathbf{e}_3 \\times \\mathbf{N}|/(Cn^2)$ at the start: the pole's velocity over $n$",
    )
    results.number(
        "free_wobble_forced_start_mas",
        forced / earth.MAS,
        "mas",
        note="starting on the steady forced precession",
    )
    results.hard_case(
        "forced_start",
        "The free wobble left by starting on the forced state, as a fraction of the "
        f"one left by starting on the figure axis (bound: the fastest couple's $\\nu/n$; step "
        f"{shortest(FREE_NUTATION_STEP_HOURS)} h)",
        forced / axis,
        bound,
    )


LADDER_DECIMALS = 3  # the ladder's rate change (″/yr) when no aliasing windows give the fit's scatter
LADDER = (
    "solar_torque",
    "lunar_torque",
    "orbit_eccentricity",
    "lunar_inclination",
    "node_regression",
    "lunar_perigee_advance",
)


class EffectLadder(NamedTuple):
    years: float  # the span of each run
    frame: pd.DataFrame  # per rung: the fitted rate, the secular formula's, two nutations, the rate change
    times: pd.DataFrame  # the same runs' wall times


def effect_ladder(model, step, order, years) -> EffectLadder:
    """The listed effects switched on one at a time: what each changes in the headline numbers and costs."""
    span = years * earth.JULIAN_YEAR_DAYS
    rows, times = [], []
    listed = [e for e in LADDER if e in model.listed]
    for k in range(1, len(listed) + 1):
        effects = {e: {} for e in listed[:k]}
        sub = prec.assemble(model.H, model.obliquity, model.orbits, effects)
        seconds, (t, ms, qs), _ = min_time(lambda: integrate(sub, span, step, order), repeats=3, budget_s=2.0)
        psi, eps = prec.precession_angles(angular_momentum_axis(ms, qs))
        fp, fe, args = fit_series(sub, t, psi, eps)
        added = ("" if k == 1 else "+ ") + listed[k - 1]
        rows.append(
            {
                "adds": added,
                "rate": fitting.per_year_arcsec(fp.rate),
                # a tilted orbit with its node fixed has no steady precession about the ecliptic pole (the
                # axis circles the orbits' mean pole): the node-averaged formula does not apply; none shown
                "secular_formula": (
                    np.nan
                    if sub.inclined and not sub.regressing
                    else fitting.per_year_arcsec(sub.secular_rate())
                ),
                "dpsi_18p6yr": fitting.amplitude(fp, "18.6 yr") / earth.ARCSEC if "18.6 yr" in args else 0.0,
                "dpsi_semiannual": fitting.amplitude(fp, "semi-annual") / earth.ARCSEC,
            }
        )
        steps = int(round(span / step))
        times.append(
            {
                "adds": added,
                "span_years": years,
                "steps": steps,
                "seconds": seconds,
                "ns_per_step": seconds / steps * 1e9,
            }
        )
    frame = pd.DataFrame(rows)
    frame["rate_change"] = frame.rate.diff().fillna(frame.rate)
    return EffectLadder(years, frame, pd.DataFrame(times))


def _record_effect_ladder(results, values: EffectLadder, spread=None):
    """spread: the rate's relative spread over the aliasing windows (aliasing(...).spread_with_terms), or
    None without them."""
    years, frame = values.years, values.frame
    # the change is printed to the decimals the fit resolves: its last place ten times the fit's own scatter
    # (the rate's spread over windows of awkward lengths) or more, so a change below the scatter reads 0.000
    scatter = spread * abs(float(frame.rate.iloc[-1])) if spread is not None else None
    decimals = int(np.floor(-np.log10(10.0 * scatter))) if scatter else LADDER_DECIMALS
    results.number(
        "effect_ladder_rate_change_decimals",
        decimals,
        "1",
        note="decimals of the ladder's rate change (″/yr): last place ten times the fit's scatter or more",
    )
    if scatter:
        results.number(
            "effect_ladder_rate_scatter_arcsec_per_year",
            scatter,
            "″/yr",
            note="the rate's spread over the aliasing windows (relative spread times the rate)",
        )
    unseen = [  # the effects whose change reads as zero, with what it is
        f"{name.removeprefix('+ ').replace('_', ' ')}, {format_number(float(change), 2)} ″/yr"
        for name, change in zip(frame.adds, frame.rate_change)
        if round(abs(change), decimals) == 0
    ]
    zero = format_decimals(0.0, decimals)
    below = f" (here: {'; '.join(unseen)})" if unseen else ""
    results.table(
        "effect_ladder",
        frame,
        f"The full model over {_years(years)} with the effects switched on one "
        "at a time (each row adds one to those above): the fitted rate beside the secular formula for the "
        "same effects (none with the lunar orbit tilted and its node fixed: the axis then circles the "
        "orbits' mean pole, not the ecliptic's), the 18.6-year and semi-annual nutations in longitude, and "
        "the change in the rate "
        "each effect brings. A tilted lunar orbit with a fixed node changes the rate by several ″/yr; "
        "with the node regressing the rate returns to the secular formula's. The change is printed to "
        f"{decimals} decimals"
        + (
            f", whose last place is ten times the fit's own scatter or more ({format_number(scatter, 2)} "
            "″/yr, the rate's spread over windows of awkward lengths)"
            if scatter
            else ""
        )
        + f": a change below half that place, as any below the scatter is, reads {zero}{below}.",
        headers={
            "adds": "effect added",
            "rate": "rate (″/yr)",
            "secular_formula": "secular formula (″/yr)",
            "dpsi_18p6yr": "$\\Delta\\psi$, 18.6 yr (″)",
            "dpsi_semiannual": "$\\Delta\\psi$, semi-annual (″)",
            "rate_change": "rate change (″/yr)",
        },
    )
    results.timing_table(
        "effect_ladder",
        values.times,
        "What each effect costs: the same runs, timed "
        "(minimum of repeats). An effect not listed is not evaluated.",
        headers={
            "adds": "effect added",
            "span_years": "span (yr)",
            "steps": "steps",
            "seconds": "wall time (s)",
            "ns_per_step": "per step (ns)",
        },
    )


def _years(value) -> str:
    """A span as a reader writes it: 1 year, 20 years, 0.1 years."""
    return f"{shortest(value)} {plural(value, 'year')}"
