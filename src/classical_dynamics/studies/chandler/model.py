"""A model Earth's wobble: the closed forms, the integration of the listed effects, what each adds."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter

from ...figure_style import FULL_WIDTH_IN
from ...formatting import format_number, plural, shortest
from ...models import earth, wobble
from ...results import new_figure, subplots
from ...solvers import references as ref
from ...solvers import rigid_body
from ...solvers.fixed_step import FixedProblem, Save, solve_fixed
from ...solvers.ode import Problem, solve
from ...solvers.timing import min_time
from . import polar_motion
from .cost import DEFAULT_SPAN_YEARS

DEFAULT_RTOL = 1e-12
SAMPLE_DAYS = 2.0
PERIOD_BOUND = 1e-6  # the hard case: the wobble's period to 1e-6 relative over 100 years
Q_BOUND = 0.05  # the hard case: Q recovered from a damped series to 5 %
PATH_YEARS = 13.0  # the model's polar path: the last two beats of the wobble with the year
# the fitted period's figures, in the polar path's caption as in the chapter's num(..., sig=5) and Table
# "excited" (tests/test_report_typesetting.py reads the chapter's sig against this)
FITTED_PERIOD_SIG = 5


def arcsec_text(angle_rad) -> str:
    """An angle given in arcseconds, as given: 0.1″, not the float round trip's 0.10000000000000002."""
    return shortest(float(f"{angle_rad / earth.ARCSEC:.12g}"))


def setup(scene):
    """(H, amplitude rad, model) of a model scene."""
    H = earth.h_over_c(scene.data["earth"]["H"], scene.data["earth"]["H_definition"])
    amplitude = scene.data["earth"].get("wobble_arcsec", 0.1) * earth.ARCSEC
    return H, amplitude, wobble.assemble(H, scene.data.get("effects") or {})


def integrate(model, amplitude, span_days, rtol, t_eval, method="dop853"):
    y0 = np.array([amplitude, 0.0, 1.0])
    problem = Problem(wobble.liouville, y0, (0.0, span_days), model.parameters(), name="wobble")
    return solve(problem, method, rtol=rtol, atol=rtol * amplitude, t_eval=t_eval)


def phase_rate(t, y):
    """Mean angular rate (rad/day) of the pole p + iq about the figure axis, by a fit to the unwrapped
    phase."""
    phase = np.unwrap(np.angle(y[:, 0] + 1j * y[:, 1]))
    return float(np.polyfit(t, phase, 1)[0])


def run(scene, results, quick):
    H, amplitude, model = setup(scene)
    effects = scene.data.get("effects") or {}
    analysis = scene.data.get("analysis", {})
    span_years = analysis.get("span_years", DEFAULT_SPAN_YEARS)
    rtol = analysis.get("rtol", DEFAULT_RTOL)
    span = span_years * earth.JULIAN_YEAR_DAYS
    t = np.arange(0.0, span + 0.5 * SAMPLE_DAYS, SAMPLE_DAYS)
    t = t[t <= span]

    euler_sidereal = earth.euler_period_sidereal_days(H)
    rigid_solar = earth.sidereal_to_solar_days(euler_sidereal)
    closed = model.wobble_period_solar_days()
    results.number("H_over_C", H, "1", note=scene.data["earth"]["H_source"])
    results.number(
        "euler_period_sidereal_days",
        euler_sidereal,
        "sidereal days",
        note="rigid symmetric Earth, A/(C − A) (Lamb Art. 47)",
    )
    results.number("euler_period_solar_days", rigid_solar, "d", note="the same in mean solar days")
    results.number(
        "wobble_period_closed_form_solar_days",
        closed,
        "d",
        note="closed form for the listed effects, small amplitude",
    )
    results.number("wobble_amplitude_arcsec", amplitude / earth.ARCSEC, "″")
    results.number("span_years", span_years, "yr")

    sol = integrate(model, amplitude, span, rtol, t)
    seconds, _, _ = min_time(lambda: integrate(model, amplitude, span, rtol, None), repeats=5, budget_s=1.0)
    results.timing_table(
        "cost",
        pd.DataFrame(
            [
                {
                    "effects": ", ".join(effects) or "none (rigid symmetric)",
                    "span_years": span_years,
                    "rtol": rtol,
                    "steps": sol.n_steps,
                    "evaluations": sol.nfev,
                    "seconds": seconds,
                }
            ]
        ),
        f"Cost of one {shortest(span_years)}-year integration with these effects (DOP853, minimum of "
        "repeats).",
        headers={
            "effects": "effects",
            "span_years": "span (yr)",
            "rtol": "rtol",
            "steps": "steps",
            "evaluations": "evaluations",
            "seconds": "wall time (s)",
        },
    )
    y = sol.y_eval
    m = (y[:, 0] + 1j * y[:, 1]) / earth.MAS  # the pole about the figure axis, mas

    if "excitation" in effects:
        excited = excited_fit(t, m, model, closed)
        _record_excited(results, excited, t, m)
        measured = excited.chandler_period_days
    else:
        rate = phase_rate(t, y)
        measured = 2.0 * np.pi / rate
        results.hard_case(
            "period_to_1e-6",
            f"A {arcsec_text(amplitude)}″ wobble on a daily spin followed "
            f"for {shortest(span_years)} {plural(span_years, 'year')}: its period against the closed "
            "form (relative)",
            measured / closed - 1.0,
            PERIOD_BOUND,
        )
        _record_sense(results, is_prograde(rate, y))
        _record_invariants(results, invariants(y, model))
        _polhode(results, t, m, measured, "dissipation" in effects, "triaxiality" in effects)
    results.number(
        "wobble_period_solar_days",
        measured,
        "d",
        note="measured from the integration"
        + (
            " (fit to the simulated series)"
            if "excitation" in effects
            else " (mean rate of the pole's phase)"
        ),
    )
    results.number("wobble_period_sidereal_days", earth.solar_to_sidereal_days(measured), "sidereal days")
    results.number(
        "period_change_from_effects_days",
        measured - rigid_solar,
        "d",
        note="against the rigid symmetric Earth of the same H",
    )
    results.number(
        "period_relative_error", measured / closed - 1.0, "1", note="integration against closed form"
    )

    if "triaxiality" in effects:
        _record_triaxial(results, model, triaxial(model, amplitude, sol, t, rigid_solar))
    if "elastic_yielding" in effects:
        _record_elastic(results, model, elastic(model, H, effects["elastic_yielding"]))
    if "dissipation" in effects and "excitation" not in effects:
        decay = damped(t, m, model, measured)
        _record_damped(results, t, model, decay)
        if "e_folding_at" in analysis:  # the measured Q at another period: the Earth's, not the model's
            at = analysis["e_folding_at"]
            results.number(
                "amplitude_e_folding_years_at_period",
                decay.Q_recovered * at["period_days"] / np.pi / earth.JULIAN_YEAR_DAYS,
                "yr",
                note=f"$QP/\\pi$, the measured $Q$ at $P$ = {shortest(at['period_days'])} d ({at['source']})",
            )
        _record_dissipation_structure(results, dissipation_structure(model))
    if analysis.get("cones"):
        _record_cones(results, model, amplitude, cones(model, amplitude))
        if not effects:
            _record_symmetric_integrals(results, symmetric_integrals(model))
    if analysis.get("lamb_symmetric"):
        from . import lamb_free

        lamb_free.record_symmetric_earth(results, lamb_free.symmetric_earth(model, amplitude))
    if "lamb_free_body" in analysis:
        from . import lamb_free

        lamb_free.free_body(results, analysis["lamb_free_body"])


def is_prograde(rate, y):
    """Prograde: the pole turns about the figure axis in the sense of the spin (sign of omega_3)."""
    return np.sign(rate) == np.sign(np.mean(y[:, 2]))


def _record_sense(results, prograde):
    results.number(
        "wobble_sense",
        1 if prograde else -1,
        "1",
        note="+1: the pole turns about the figure axis in the spin's sense (prograde)",
    )
    results.hard_case(
        "prograde",
        "The free wobble turns in the sense of the spin (1 if it does not)",
        0.0 if prograde else 1.0,
        0.0,
    )


class Invariants(NamedTuple):
    angular_momentum_drift: float  # largest relative change of |L|
    wobble_invariant_drift: float | None  # of 2CT - H^2; None on an elastic Earth


def invariants(y, model) -> Invariants:
    """|L| along the run. (At 0.1″ the wobble's share of |L| and of the energy is ~1e-15, below what a
    double can resolve, so the dissipation's structure is shown on a large wobble: dissipation_structure.)"""
    L, _ = wobble.invariants(y, model.parameters())
    drift = float(np.max(np.abs(L / L[0] - 1.0)))
    params = model.parameters()
    wobble_drift = None
    if not params[wobble.ELASTIC]:
        # the wobble's own invariant, resolvable where T and |L| are not: 2CT - H^2 = A(C - A)p^2 + B(C -
        # B)q^2 (Lamb Art. 48 (6), units C = 1, y = omega/n), formed from p and q so that nothing cancels
        a, b = params[wobble.A_C], params[wobble.B_C]
        D = a * (1.0 - a) * y[:, 0] ** 2 + b * (1.0 - b) * y[:, 1] ** 2
        wobble_drift = float(np.max(np.abs(D / D[0] - 1.0)))
    return Invariants(drift, wobble_drift)


def _record_invariants(results, values: Invariants):
    drift = values.angular_momentum_drift
    results.number(
        "angular_momentum_drift",
        drift,
        "1",
        note="largest $|\\Delta|\\mathbf{L}||/|\\mathbf{L}|$ over the run",
    )
    results.hard_case("angular_momentum_kept", "$|\\mathbf{L}|$ kept over the run (relative)", drift, 1e-12)
    if values.wobble_invariant_drift is not None:
        results.number(
            "wobble_invariant_drift",
            values.wobble_invariant_drift,
            "1",
            note="largest relative change of $2CT - H^2 = A(C - A)p^2 + B(C - B)q^2$ over the run",
        )


class DissipationStructure(NamedTuple):
    tilt_deg: float
    periods: int
    L_drift: float  # largest relative change of |L|
    energy_fall: float  # relative fall of the energy
    energy_largest_rise: float  # largest rise between samples over the total fall


def dissipation_structure(model, tilt_deg=10.0, periods=20) -> DissipationStructure:
    """On a 10° wobble, where the wobble's energy is resolvable: |L| kept, the energy only falls."""
    y0 = np.array([np.sin(np.radians(tilt_deg)), 0.0, np.cos(np.radians(tilt_deg))])
    span = periods * model.wobble_period_solar_days()
    t = np.linspace(0.0, span, 4001)
    sol = solve(
        Problem(wobble.liouville, y0, (0.0, span), model.parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        t_eval=t,
    )
    L, E = wobble.invariants(sol.y_eval, model.parameters())
    fall = E[0] - E[-1]
    rise = float(max(np.max(np.diff(E)), 0.0))
    return DissipationStructure(
        tilt_deg, periods, float(np.max(np.abs(L / L[0] - 1.0))), float(fall / E[0]), rise / fall
    )


def _record_dissipation_structure(results, values: DissipationStructure):
    tilt_deg, periods = values.tilt_deg, values.periods
    results.number("large_wobble_tilt_deg", tilt_deg, "°")
    results.number(
        "large_wobble_L_drift", values.L_drift, "1", note=f"{shortest(tilt_deg)}° wobble, {periods} periods"
    )
    results.number("large_wobble_energy_fall", values.energy_fall, "1", note="relative fall of the energy")
    results.number(
        "large_wobble_energy_largest_rise",
        values.energy_largest_rise,
        "1",
        note="largest rise between samples / total fall (0: the energy only falls)",
    )
    results.hard_case(
        "dissipation_keeps_L",
        f"Internal dissipation on a {shortest(tilt_deg)}° wobble: "
        "$|\\mathbf{L}|$ kept (relative) while the energy falls",
        values.L_drift,
        1e-12,
    )
    results.hard_case(
        "dissipation_energy_falls",
        "… and the energy never rises (largest rise / total fall)",
        values.energy_largest_rise,
        1e-6,
    )


class SymmetricIntegrals(NamedTuple):
    tilt_deg: float
    periods: int
    deviation: float  # largest relative difference of A and w3 from T and L^2 against the run


def symmetric_integrals(model, tilt_deg=10.0, periods=20) -> SymmetricIntegrals:
    """Handbook (2.162)-(2.163): for the free symmetric body T = I1 A^2/2 + I3 w3^2/2 and L^2 = I1^2 A^2 +
    I3^2 w3^2, so the wobble's angular speed A and the spin w3 follow from T and L^2. On a 10 degree wobble
    (at 0.1 arcsec A^2 is below what T and L^2 resolve), against A = |(w1, w2)| and w3 along a DOP853 run."""
    params = model.parameters()
    I1, I3 = params[wobble.A_C], 1.0
    if params[wobble.B_C] != I1:
        raise ValueError("(2.162)-(2.163) are for a symmetric body")
    y0 = np.array([np.sin(np.radians(tilt_deg)), 0.0, np.cos(np.radians(tilt_deg))])
    span = periods * model.wobble_period_solar_days()
    sol = solve(
        Problem(wobble.liouville, y0, (0.0, span), params),
        "dop853",
        rtol=1e-13,
        atol=1e-16,
        t_eval=np.linspace(0.0, span, 2001),
    )
    y = sol.y_eval
    T = 0.5 * (I1 * y0[0] ** 2 + I1 * y0[1] ** 2 + I3 * y0[2] ** 2)
    L2 = (I1 * y0[0]) ** 2 + (I1 * y0[1]) ** 2 + (I3 * y0[2]) ** 2
    A = np.sqrt((2 * T * I3 - L2) / (I1 * (I3 - I1)))  # (2.162)-(2.163) solved for A and w3
    w3 = np.sqrt((L2 - 2 * T * I1) / (I3 * (I3 - I1)))
    wobble_speed = np.hypot(y[:, 0], y[:, 1])
    # np.max, not max(): a NaN (a root of a negative) must come through, not lose to the other term
    deviation = float(np.max(np.abs(np.concatenate([wobble_speed / A - 1, y[:, 2] / w3 - 1]))))
    return SymmetricIntegrals(tilt_deg, periods, deviation)


def _record_symmetric_integrals(results, values: SymmetricIntegrals):
    tilt_deg, periods = values.tilt_deg, values.periods
    results.number(
        "symmetric_T_L2_recovery",
        values.deviation,
        "1",
        note=f"$A$ and $\\omega_3$ from $T$ and $L^2$ by (2.162)-(2.163) against $|(\\omega_1, "
        f"\\omega_2)|$ and $\\omega_3$ along a {shortest(tilt_deg)}° wobble, {periods} periods "
        "(largest relative difference)",
    )


def _polhode(results, t, m, period, damped, triaxial=False):
    one = t <= (t[-1] if damped else period)
    if triaxial:
        fig, (ax, bx) = subplots(
            1, 2, figsize=(FULL_WIDTH_IN, 3.2), layout="constrained", gridspec_kw={"width_ratios": [1, 1.3]}
        )
    else:
        fig, ax = new_figure(3.6, 3.4)
    ax.plot(m.real[one], m.imag[one], lw=0.35 if damped else 0.8, color="C4")
    ax.plot(m.real[0], m.imag[0], "o", ms=3.5, color="C4")
    ax.plot([0], [0], "k+", ms=8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"$p/n$, toward Greenwich (mas)")
    ax.set_ylabel(r"$q/n$, toward 90° E (mas)")
    what = "spiralling in over the whole run" if damped else "over one period"
    caption = (
        f"The polhode: the rotation axis about the figure axis (+) in the body frame, {what}, from the "
        f"start (dot). Period {format_number(period, 4)} d; the motion is counterclockwise seen from above "
        "the "
        "North Pole (prograde)."
    )
    if triaxial:
        # the ellipse is too near a circle to see: its radius against the angle shows it
        angle = np.degrees(np.angle(m[one])) % 360.0
        radius = np.abs(m[one])
        order = np.argsort(angle)
        bx.plot(angle[order], radius[order] - np.mean(radius), lw=0.9, color="C4")
        bx.set_xlim(0, 360)
        bx.set_xticks(np.arange(0, 361, 90))
        bx.set_xlabel("angle from the $p$ axis (°)")
        bx.set_ylabel(r"$|m| - \overline{|m|}$ (mas)")
        bx.grid(True, alpha=0.25, linewidth=0.6)
        ax.set_title("polhode")
        bx.set_title("its radius less the mean radius")
        caption += (
            " Right: the polhode's radius against the angle about the figure axis, less its mean: the "
            "triaxial Earth's polhode is an ellipse, longer along $q$ (the axis of the middle moment $B$) "
            "by the ratio $\\sqrt{A(C - A)/(B(C - B))}$, too near a circle to see on the left."
        )
    results.figure("polhode", fig, caption)


class Triaxial(NamedTuple):
    elliptic_period_solar_days: float  # 4K(k)/lambda of the exact motion
    elliptic_modulus_squared: float
    triaxial_period_change_days: float  # against the symmetric Earth with the same (C - (A + B)/2)/C
    polhode_axis_ratio: float  # closed form sqrt(A(C - A)/(B(C - B)))
    polhode_axis_ratio_measured: float
    exact_solution_error: float  # relative to the wobble


def triaxial(model, amplitude, sol, t, rigid_solar) -> Triaxial:
    """Against the exact elliptic-function motion: the period 4K/rate, the polhode's ellipse."""
    a, b = earth.moments_over_c(model.H, model.b_minus_a_over_c)
    I = np.array([a, b, 1.0])
    w0 = model.n * np.array([amplitude, 0.0, 1.0])
    exact = ref.free_rigid_body(I, I * w0, t) / model.n
    err = float(np.max(np.abs(sol.y_eval - exact)[:, :2])) / amplitude
    period = ref.free_rigid_body_period(I, I * w0)
    y = sol.y_eval
    return Triaxial(
        elliptic_period_solar_days=period,
        elliptic_modulus_squared=float(ref.free_rigid_body_rate_and_parameter(I, I * w0)[1]),
        triaxial_period_change_days=period - rigid_solar,
        polhode_axis_ratio=np.sqrt(a * (1.0 - a) / (b * (1.0 - b))),
        polhode_axis_ratio_measured=float(np.max(np.abs(y[:, 1])) / np.max(np.abs(y[:, 0]))),
        exact_solution_error=err,
    )


def _record_triaxial(results, model, values: Triaxial):
    period, err = values.elliptic_period_solar_days, values.exact_solution_error
    results.number(
        "B_minus_A_over_C", model.b_minus_a_over_c, "1", note="$4C_{22}H/J_2$ (EGM2008, IERS 2010)"
    )
    results.number("elliptic_period_solar_days", period, "d", note="$4K(k)/\\lambda$ of the exact motion")
    results.number("elliptic_modulus_squared", values.elliptic_modulus_squared, "1")
    results.number(
        "triaxial_period_change_days",
        values.triaxial_period_change_days,
        "d",
        note="against the symmetric Earth with the same $(C - (A + B)/2)/C$",
    )
    results.number("triaxial_period_change_hours", 24.0 * values.triaxial_period_change_days, "h")
    results.number(
        "polhode_axis_ratio",
        values.polhode_axis_ratio,
        "1",
        note="$q_\\mathrm{max}/p_\\mathrm{max} = \\sqrt{A(C - A)/(B(C - B))}$: the polhode is an ellipse",
    )
    results.number("polhode_axis_ratio_measured", values.polhode_axis_ratio_measured, "1")
    results.number(
        "exact_solution_error",
        err,
        "1",
        note="largest $|\\omega - \\omega_\\mathrm{exact}|$ in $p$, $q$ over the run, relative to the wobble",
    )
    results.hard_case(
        "triaxial_exact",
        "Triaxial wobble against the elliptic-function solution over the run (relative to the wobble)",
        err,
        1e-6,
    )


ELASTIC_TARGETS = ((433.1, "433"), (427.0, "427"))  # wobble periods (d) and their names


class Elastic(NamedTuple):
    secular_love_number: float  # k_s = 3 J2/q
    beta_n2_over_A: float
    beta_n2_over_C_minus_A: float  # = k2/k_s
    excess_over_observed: float  # closed-form period / 433.1 d - 1
    love_number_k2: float
    love_number_source: str
    k2_for_period_days: dict  # {"433": k2, "427": k2}: the Love number a 433.1-day, 427-day wobble needs


def elastic(model, H, params) -> Elastic:
    """Lamb's elastic Earth: its beta n^2 as Love numbers, and the k2 a given period needs."""
    k_s = earth.secular_love_number()
    needed = {name: earth.beta_n2_for_period(H, target) / H * k_s for target, name in ELASTIC_TARGETS}
    return Elastic(
        secular_love_number=k_s,
        beta_n2_over_A=model.beta_n2 / (1.0 - H),
        beta_n2_over_C_minus_A=model.beta_n2 / H,
        excess_over_observed=model.wobble_period_solar_days() / 433.1 - 1.0,
        love_number_k2=params.get("k2", model.beta_n2 / H * k_s),
        love_number_source=params["source"],
        k2_for_period_days=needed,
    )


def _record_elastic(results, model, values: Elastic):
    k_s = values.secular_love_number
    results.number("secular_love_number", k_s, "1", note="$k_\\mathrm{s} = 3J_2/q$ (IERS 2010 constants)")
    results.number("beta_n2_over_C", model.beta_n2, "1", note="Lamb's $\\beta n^2$ in units of $C$")
    results.number("beta_n2_over_A", values.beta_n2_over_A, "1")
    results.number("beta_n2_over_C_minus_A", values.beta_n2_over_C_minus_A, "1", note="$= k_2/k_\\mathrm{s}$")
    results.number(
        "excess_over_observed",
        values.excess_over_observed,
        "1",
        note="closed-form period / 433.1 d (Vicente & Wilson 1997) − 1",
    )
    results.number("love_number_k2", values.love_number_k2, "1", note=values.love_number_source)
    for target, name in ELASTIC_TARGETS:
        results.number(
            f"k2_for_{name}_days",
            values.k2_for_period_days[name],
            "1",
            note=f"the Love number Lamb's model needs for a {shortest(target)}-day wobble",
        )


class Damped(NamedTuple):
    Q_recovered: float  # sigma/2 gamma, gamma the decay rate of the simulated amplitude
    amplitude_e_folding_years: float  # measured
    amplitude_e_folding_years_closed_form: float  # Q P/pi
    amplitude: np.ndarray  # |m| along the run
    sigma: float  # the wobble's angular frequency (rad/d)


def damped(t, m, model, period) -> Damped:
    """Q from the decay of the amplitude (a straight-line fit of log |m|), against the scene's Q."""
    amp = np.abs(m)
    slope = np.polyfit(t, np.log(amp), 1)[0]  # per day
    sigma = 2.0 * np.pi / period
    Q_fit = -sigma / (2.0 * slope)
    e_fold_years = -1.0 / slope / earth.JULIAN_YEAR_DAYS
    closed = model.Q * period / np.pi / earth.JULIAN_YEAR_DAYS
    return Damped(Q_fit, e_fold_years, closed, amp, sigma)


def _record_damped(results, t, model, values: Damped):
    """The numbers, the hard case and the decay figure of a damped run."""
    Q_fit, e_fold_years = values.Q_recovered, values.amplitude_e_folding_years
    amp, sigma = values.amplitude, values.sigma
    results.number("Q", model.Q, "1")
    results.number(
        "Q_recovered",
        Q_fit,
        "1",
        note="$\\sigma/2\\gamma$, $\\gamma$ the decay rate of the simulated amplitude",
    )
    results.number("Q_relative_error", Q_fit / model.Q - 1.0, "1")
    results.number("amplitude_e_folding_years", e_fold_years, "yr", note="measured")
    results.number(
        "amplitude_e_folding_years_closed_form",
        values.amplitude_e_folding_years_closed_form,
        "yr",
        note="$QP/\\pi$",
    )
    results.hard_case(
        "Q_recovered", "$Q$ recovered from the damped series (relative)", Q_fit / model.Q - 1.0, Q_BOUND
    )
    fig, ax = new_figure(5.2, 3.0)
    years = t / earth.JULIAN_YEAR_DAYS
    ax.semilogy(years, amp, lw=1.6, color="C4", label="simulated $|m|$")
    ax.semilogy(
        years,
        amp[0] * np.exp(-sigma * t / (2 * model.Q)),
        "k--",
        lw=0.9,
        label=f"$|m_0|\\,e^{{-\\sigma t/2Q}}$, $Q$ = {shortest(model.Q)}",
    )
    ax.set_xlabel("time (yr)")
    ax.set_ylabel("wobble amplitude $|m|$ (mas)")
    # less than a decade: ticks at 1, 2, 5 times powers of ten, written out (30, 50, 100)
    ax.yaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 3.0, 5.0)))
    ax.yaxis.set_major_formatter(ScalarFormatter())
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.legend(loc="upper right")
    results.figure(
        "decay",
        fig,
        f"The amplitude of a damped free wobble ($Q$ = {shortest(model.Q)}) on a "
        "logarithmic scale: simulated, and the closed form $e^{-\\sigma t/2Q}$ (dashed). The two lie on "
        f"one straight line: the amplitude falls by a factor $e$ in {format_number(e_fold_years, 3)} "
        f"years, and the fit recovers $Q$ = {format_number(Q_fit, 4)}.",
    )


class Excited(NamedTuple):
    fit: polar_motion.WobbleFit  # the simulated series fitted as the observations are
    chandler_period_days: float  # fitted
    beat_period_years: float  # 1/(f_annual - f_Chandler), fitted periods
    beat_period_closed_form_years: float  # from the model's closed-form period
    period_relative_error: float  # fitted against the closed form
    bound: float  # the resonance's width 1/Q (relative)


def excited_fit(t, m, model, closed) -> Excited:
    """Fit the simulated series the way the observations are fitted: the fitter checked on a known truth."""
    years = t / earth.JULIAN_YEAR_DAYS
    fit = polar_motion.fit(years, m)
    annual_period = earth.TROPICAL_YEAR_DAYS
    beat = 1.0 / abs(1.0 / annual_period - 1.0 / fit.chandler_period_days) / earth.JULIAN_YEAR_DAYS
    # a finite, randomly excited record fixes the period only to within the resonance's width, 1/Q relative
    return Excited(
        fit=fit,
        chandler_period_days=fit.chandler_period_days,
        beat_period_years=beat,
        beat_period_closed_form_years=1.0 / abs(1.0 / annual_period - 1.0 / closed) / earth.JULIAN_YEAR_DAYS,
        period_relative_error=fit.chandler_period_days / closed - 1.0,
        bound=1.0 / model.Q if model.Q else 1e-3,
    )


def _record_excited(results, values: Excited, t, m):
    """The fit's numbers, the hard case and the polar path figure."""
    fit, beat = values.fit, values.beat_period_years
    years = t / earth.JULIAN_YEAR_DAYS
    results.number("fitted_chandler_period_days", fit.chandler_period_days, "d")
    results.number("fitted_chandler_amplitude_mas", fit.chandler_amplitude_mas, "mas")
    results.number("fitted_annual_prograde_mas", fit.annual_prograde_mas, "mas")
    results.number("fitted_annual_retrograde_mas", fit.annual_retrograde_mas, "mas")
    results.number(
        "beat_period_years",
        beat,
        "yr",
        note="$1/(f_\\mathrm{annual} - f_\\mathrm{Chandler})$, fitted periods",
    )
    results.number(
        "beat_period_closed_form_years",
        values.beat_period_closed_form_years,
        "yr",
        note="from the model's closed-form period",
    )
    results.hard_case(
        "fitter_on_known_truth",
        "Fitting the simulated series recovers the model's period "
        "(relative; within the resonance width $1/Q$)",
        values.period_relative_error,
        values.bound,
    )
    shown = min(PATH_YEARS, float(years[-1] - years[0]))
    figure_path(
        results,
        "polar_path",
        years,
        m,
        "The model pole excited by an annual term and a seeded random "
        f"process: its path over the last {shortest(shown)} {plural(shown, 'year')} with the trend removed "
        "(left) and its two coordinates "
        "against time (right). The "
        f"{format_number(results.numbers['fitted_chandler_period_days']['value'], FITTED_PERIOD_SIG)}-day "
        "wobble beats with the "
        f"year every {format_number(beat, 3)} years, swelling and shrinking the path.",
        last_years=PATH_YEARS,
        time_label="time from the start (yr)",
    )


def figure_path(results, name, years, m, caption, last_years=13.0, time_label="year"):
    """The pole's path in the right-handed frame (x toward Greenwich, y toward 90° E) and x, y against time.

    years: the samples' times in years (calendar years or years from the start: time_label says which)."""
    keep = years >= years[-1] - last_years
    fig, (ax, bx) = subplots(
        1, 2, figsize=(FULL_WIDTH_IN, 3.0), layout="constrained", gridspec_kw={"width_ratios": [1, 1.45]}
    )
    centre = m[keep] - np.polyval(np.polyfit(years[keep], m[keep], 1), years[keep])
    ax.plot(centre.real, centre.imag, lw=0.5, color="C4")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"$x$, toward Greenwich (mas)")
    ax.set_ylabel(r"$-y$, toward 90° E (mas)")
    bx.plot(years[keep], centre.real, lw=0.6, color="C4", label=r"$x$")
    bx.plot(years[keep], centre.imag, lw=0.6, color="C5", label=r"$-y$")
    bx.set_xlabel(time_label)
    bx.set_ylabel("pole, trend removed (mas)")
    bx.margins(y=0.2)
    bx.legend(loc="upper right", ncol=2)
    for axis in (ax, bx):
        axis.grid(True, alpha=0.25, linewidth=0.6)
    results.figure(name, fig, caption)


class Cones(NamedTuple):
    """Lamb Art. 47 on the rigid symmetric Earth, over two days of attitude (angles in rad)."""

    alpha: float  # figure axis to L
    beta: float  # figure axis to omega
    C_over_A: float
    herpolhode_over_polhode: float  # measured
    herpolhode_radius_mas: float
    space_cone_period_sidereal_days: float
    angular_momentum: np.ndarray  # body-frame L along the run (units C n)
    omega_space: np.ndarray  # omega in space along the run
    invariable_line: np.ndarray  # L/|L| in space
    moments: np.ndarray  # A, B, C over C


def cones(model, amplitude) -> Cones:
    """Body and space cones (Lamb Art. 47): tan β = (C/A) tan α; the herpolhode is H times the polhode."""
    a = model.parameters()[wobble.A_C]
    I = np.array([a, a, 1.0])
    w0 = model.n * np.array([amplitude, 0.0, 1.0])
    m0 = I * w0
    alpha = np.arctan2(np.hypot(m0[0], m0[1]), m0[2])  # figure axis to L
    beta = np.arctan2(np.hypot(w0[0], w0[1]), w0[2])  # figure axis to omega
    # two days of attitude by the splitting (fourth order, exact rotations), the herpolhode in space
    h, days = 1e-3, 2.0
    steps = int(round(days / h))
    problem = FixedProblem(rigid_body.packed(m0), I)
    rows = solve_fixed(problem, "rigid-splitting4", h=h, n_steps=steps, save=Save(every=10)).y_eval
    ms, qs = rows[:, :3], rows[:, 3:]
    omega_space = rigid_body.rotate_to_space(qs, ms / I)
    L_hat = rigid_body.rotate_to_space(qs[:1], ms[:1])[0]
    L_hat /= np.linalg.norm(L_hat)
    off_L = omega_space - np.outer(omega_space @ L_hat, L_hat)
    herpolhode = np.linalg.norm(off_L, axis=1) / np.linalg.norm(omega_space, axis=1)
    polhode = np.hypot(ms[:, 0], ms[:, 1]) / I[0] / np.linalg.norm(ms / I, axis=1)
    ratio = float(np.mean(herpolhode) / np.mean(polhode))
    space_rate = np.linalg.norm(m0) / I[0]
    return Cones(
        alpha=alpha,
        beta=beta,
        C_over_A=1.0 / a,
        herpolhode_over_polhode=ratio,
        herpolhode_radius_mas=float(np.mean(herpolhode)) / earth.MAS,
        space_cone_period_sidereal_days=2 * np.pi / space_rate * earth.SIDEREAL_PER_SOLAR_DAY,
        angular_momentum=ms,
        omega_space=omega_space,
        invariable_line=L_hat,
        moments=I,
    )


def _record_cones(results, model, amplitude, values: Cones):
    """The cones' numbers and figure: the polhode in the body, the herpolhode in space."""
    alpha, beta, ratio = values.alpha, values.beta, values.herpolhode_over_polhode
    ms, omega_space, L_hat, I = (
        values.angular_momentum,
        values.omega_space,
        values.invariable_line,
        values.moments,
    )
    results.number("tan_beta_over_tan_alpha", np.tan(beta) / np.tan(alpha), "1", note="Lamb: $C/A$")
    results.number("C_over_A", values.C_over_A, "1")
    results.number("herpolhode_over_polhode", ratio, "1", note="radii of the space and body cones, measured")
    results.number(
        "herpolhode_over_polhode_closed_form",
        np.sin(beta - alpha) / np.sin(beta),
        "1",
        note="sin(β − α)/sin β",
    )
    results.number("one_over_herpolhode_ratio", 1.0 / ratio, "1")
    results.number("herpolhode_radius_mas", values.herpolhode_radius_mas, "mas")
    results.number(
        "space_cone_period_sidereal_days",
        values.space_cone_period_sidereal_days,
        "sidereal days",
        note="$\\dot\\psi = |\\mathbf{L}|/A$: the plane of $\\omega$ and the "
        "figure axis turns about $\\mathbf{L}$ once a day",
    )
    fig, (ax, bx) = subplots(1, 2, figsize=(FULL_WIDTH_IN, 3.2), layout="constrained")
    # the body: two days are a short arc of the polhode, drawn on the whole circle (the closed form: a circle
    # of the wobble's radius about the figure axis) so that the arc's size can be judged
    p_body, q_body = ms[:, 0] / I[0] / model.n / earth.MAS, ms[:, 1] / I[1] / model.n / earth.MAS
    radius = float(np.mean(np.hypot(p_body, q_body)))
    turn = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(radius * np.cos(turn), radius * np.sin(turn), ls="--", lw=0.7, color="0.55")
    ax.plot(p_body, q_body, lw=2.6, color="C5", solid_capstyle="butt")
    middle = len(p_body) // 2
    ax.annotate(
        "two days",
        (p_body[middle], q_body[middle]),
        xytext=(0.45 * radius, 0.45 * radius),
        color="C5",
        ha="center",
        arrowprops={"arrowstyle": "->", "color": "C5", "lw": 0.8},
    )
    ax.annotate(
        "one period",
        (-radius / np.sqrt(2), -radius / np.sqrt(2)),
        xytext=(-0.35 * radius, -0.45 * radius),
        color="0.4",
        ha="center",
        arrowprops={"arrowstyle": "->", "color": "0.4", "lw": 0.8},
    )
    ax.plot([0], [0], "k+", ms=8)
    ax.set_title("body: polhode about the figure axis")
    ax.set_xlabel(r"$p/n$ (mas)")
    ax.set_ylabel(r"$q/n$ (mas)")
    e1 = np.cross(L_hat, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(L_hat, e1)
    space = omega_space / model.n
    ax_space = (space @ e1, space @ e2)
    bx.plot(ax_space[0] / earth.MAS, ax_space[1] / earth.MAS, lw=0.9, color="C4")
    bx.plot([0], [0], "k+", ms=8)
    bx.set_title(r"space: herpolhode about $\mathbf{L}$")
    bx.set_xlabel(r"$\omega_\xi/n$ (mas)")
    bx.set_ylabel(r"$\omega_\eta/n$ (mas)")
    for axis in (ax, bx):
        axis.set_aspect("equal", adjustable="datalim")
        axis.grid(True, alpha=0.25, linewidth=0.6)
    results.figure(
        "cones",
        fig,
        "The rotation axis over two days, in the body (left: $p$, $q$ about the figure "
        "axis, +) and in space (right: components normal to the invariable line $\\mathbf{L}$, +), in "
        "units of the spin $n$. In the body it moves along a short arc of the "
        f"{arcsec_text(amplitude)}″ polhode (dashed: the whole circle, one period); in space it "
        f"runs round the herpolhode twice, once a day, a circle {format_number(1 / ratio, 3)} times "
        "smaller. Both panels have equal scales on their two axes, not the same scale as each other.",
    )
