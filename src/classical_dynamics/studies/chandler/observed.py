"""The observed polar motion: the IERS C04 series fitted for the Chandler and annual wobbles."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...formatting import format_number, plural, shortest
from ...models import earth
from ...provenance import sha256_file
from ...results import new_figure
from . import polar_motion as pm
from .model import figure_path

VICENTE_WILSON_DAYS = (433.1, 1.7)
WINDOW_COLUMNS = [
    "centre_year",
    "chandler_mas",
    "chandler_phase_deg",
    "annual_prograde_mas",
    "annual_retrograde_mas",
]


class ObservedWobble(NamedTuple):
    """The C04 series (t in years from 2000, m in mas) fitted for the Chandler and annual wobbles."""

    fit: pm.WobbleFit  # the whole series
    thirds: list  # the samples' indices of each third
    period_by_thirds_days: list  # the Chandler period fitted on each third
    frequency_cpy: np.ndarray  # the periodogram
    power: np.ndarray
    chandler_peak_cpy: float  # the strongest peak between 0.7 and 1 cpy, either sign
    windows: pd.DataFrame  # amplitudes by window: a table's rows (WINDOW_COLUMNS)
    low: pd.Series  # the windows of least and greatest Chandler amplitude
    high: pd.Series


def analyse(t, m, window_years, step_years) -> ObservedWobble:
    """Fit the whole series and its thirds, find the periodogram's Chandler peak, and fit windows of
    window_years every step_years at the whole series' Chandler frequency."""
    fit = pm.fit(t, m)
    thirds = np.array_split(np.arange(t.size), 3)
    periods = [pm.fit(t[i], m[i]).chandler_period_days for i in thirds]
    # the sense of rotation, read from the data: the strongest peak near 0.85 cpy, either sign
    f, power = pm.periodogram(t, m)
    band = (np.abs(f) > 0.7) & (np.abs(f) < 1.0)
    peak = f[band][np.argmax(power[band])]
    windows = pm.windowed_amplitudes(t, m, fit.chandler_cpy, window_years, step_years)
    frame = pd.DataFrame(windows, columns=WINDOW_COLUMNS)
    low = frame.loc[frame.chandler_mas.idxmin()]
    high = frame.loc[frame.chandler_mas.idxmax()]
    return ObservedWobble(fit, thirds, periods, f, power, peak, frame, low, high)


def marked_periods(compare) -> tuple[float, float]:
    """The rigid Earth's and Lamb's elastic Earth's wobble periods (days) for the scene's H and k2."""
    rigid = earth.sidereal_to_solar_days(earth.euler_period_sidereal_days(compare["H"]))
    elastic = (
        2
        * np.pi
        / (
            earth.SPIN_RAD_PER_DAY
            * earth.elastic_wobble_frequency(
                compare["H"], earth.elastic_beta_n2_over_c(compare["k2"], compare["H"])
            )
        )
    )
    return rigid, elastic


def run(scene, results, quick):
    obs = scene.data["observation"]
    path = pm.eop_file()
    end = np.inf if obs["end_year"] == "latest" else obs["end_year"]
    t, m = pm.read_eop(path, obs["start_year"], end)
    results.notes.append(
        f"Data: {path.name} (IERS EOP 20 C04, from astropy-iers-data), sha256 {sha256_file(path)}, "
        f"{format_number(int(t.size))} daily values from {format_number(t[0] + 2000, 7)} to "
        f"{format_number(t[-1] + 2000, 7)}."
    )
    results.number("first_year", float(t[0] + 2000.0), "yr")
    results.number("last_year", float(t[-1] + 2000.0), "yr")
    results.number("samples", int(t.size), "1")

    values = analyse(t, m, obs["window_years"], obs["step_years"])
    fit = values.fit
    results.number(
        "observed_chandler_period_days",
        fit.chandler_period_days,
        "d",
        note="least squares: trend + Chandler + annual (pro- and retrograde)",
    )
    results.number(
        "observed_chandler_period_formal_sigma_days",
        fit.chandler_period_sigma_days,
        "d",
        note="formal, inflated by the residuals' correlation length "
        f"({format_number(fit.correlation_samples, 3)} days)",
    )
    results.number(
        "observed_chandler_amplitude_mas", fit.chandler_amplitude_mas, "mas", note="mean over the span"
    )
    results.number(
        "observed_annual_amplitude_mas", fit.annual_prograde_mas, "mas", note="prograde annual term"
    )
    results.number("observed_annual_retrograde_mas", fit.annual_retrograde_mas, "mas")
    results.number("residual_rms_mas", fit.residual_rms_mas, "mas")
    results.number("mean_pole_drift_mas_per_year", abs(fit.drift_mas_per_year), "mas/yr")
    results.number(
        "mean_pole_drift_toward_longitude_deg",
        float(np.degrees(np.angle(fit.drift_mas_per_year))),
        "°E",
        note="direction of the mean pole's drift (negative: west longitudes)",
    )
    ref_days, ref_sigma = VICENTE_WILSON_DAYS
    results.number(
        "difference_from_vicente_wilson_sigmas",
        (fit.chandler_period_days - ref_days) / ref_sigma,
        "σ",
        note="(ours − 433.1 d) / 1.7 d",
    )

    thirds, periods = values.thirds, values.period_by_thirds_days
    results.table(
        "period_by_thirds",
        pd.DataFrame(
            {
                "from_year": [t[i[0]] + 2000 for i in thirds],
                "to_year": [t[i[-1]] + 2000 for i in thirds],
                "chandler_period_days": periods,
            }
        ),
        "The Chandler period fitted on each third of the series: the "
        "scatter between thirds, the wobble's own irregularity, is far larger than the formal error of the "
        "whole series' fit.",
        headers={
            "from_year": "from (year)",
            "to_year": "to (year)",
            "chandler_period_days": "Chandler period (d)",
        },
    )
    results.number(
        "period_spread_days",
        float(np.std(periods, ddof=1)),
        "d",
        note="standard deviation of the period over the three thirds: the wobble's own irregularity",
    )

    f, power, peak = values.frequency_cpy, values.power, values.chandler_peak_cpy
    results.number(
        "chandler_peak_cpy",
        float(peak),
        "cycles/yr",
        note="positive: prograde (counterclockwise seen from above the North Pole, as the spin)",
    )
    results.number("periodogram_step_cpy", float(f[1] - f[0]), "cycles/yr", note="the periodogram's grid")
    results.hard_case(
        "observed_prograde",
        "The observed Chandler peak is prograde, at positive frequency of $x - iy$ (1 if not)",
        0.0 if peak > 0 else 1.0,
        0.0,
    )
    _periodogram_figure(results, f, power, fit, obs["compare"])

    frame = values.windows
    window, step = obs["window_years"], obs["step_years"]
    results.table(
        "amplitude_by_window",
        frame,
        f"Chandler and annual amplitudes in {shortest(window)}-year windows "
        f"every {shortest(step)} {plural(step, 'year')} (the Chandler frequency held at the global fit), "
        "with the Chandler term's phase.",
        headers={
            "centre_year": "window centre (year)",
            "chandler_mas": "Chandler (mas)",
            "chandler_phase_deg": "Chandler phase (°)",
            "annual_prograde_mas": "annual, prograde (mas)",
            "annual_retrograde_mas": "annual, retrograde (mas)",
        },
    )
    low, high = values.low, values.high
    results.number(
        "window_amplitude_min_mas",
        float(low.chandler_mas),
        "mas",
        note=f"window centred on {format_number(low.centre_year, 5)}",
    )
    results.number("window_amplitude_min_year", float(low.centre_year), "yr")
    results.number(
        "window_amplitude_max_mas",
        float(high.chandler_mas),
        "mas",
        note=f"window centred on {format_number(high.centre_year, 5)}",
    )
    results.number("window_amplitude_max_year", float(high.centre_year), "yr")
    fig, ax = new_figure(5.6, 2.9)
    ax.plot(frame.centre_year, frame.chandler_mas, "o-", ms=2.5, color="C4", label="Chandler")
    ax.plot(frame.centre_year, frame.annual_prograde_mas, "s-", ms=2.5, color="C1", label="annual, prograde")
    ax.set_xlabel("centre of the window (year)")
    ax.set_ylabel("amplitude (mas)")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper right")
    results.figure(
        "amplitude",
        fig,
        f"Amplitude of the Chandler and the prograde annual wobbles in "
        f"{shortest(window)}-year windows (one beat period) every {shortest(step)} "
        f"{plural(step, 'year')}, plotted at the windows' centres. The annual wobble varies much less; the "
        f"Chandler wobble peaked near {int(round(high.centre_year))} at "
        f"{format_number(high.chandler_mas, 3)} mas and nearly vanished near {int(round(low.centre_year))} "
        f"({format_number(low.chandler_mas, 2)} mas).",
    )
    start, stop = obs.get("path_years", [t[-1] + 2000 - 13.0, t[-1] + 2000])
    keep = (t + 2000 >= start) & (t + 2000 <= stop)
    figure_path(
        results,
        "polar_path",
        t[keep] + 2000,
        m[keep],
        "The observed pole (IERS C04), in the same "
        f"right-handed frame as the model, from {_year(start)} to {_year(stop)}: its "
        "path with the trend removed (left) and its two coordinates against time (right). The Chandler and "
        "annual wobbles beat: the path swells and shrinks.",
        last_years=stop - start,
        time_label="year",
    )


def _periodogram_figure(results, f, power, fit, compare):
    rigid, elastic = marked_periods(compare)
    results.number("marked_rigid_period_days", rigid, "d", note=f"$H$ = {shortest(compare['H'])}")
    results.number(
        "marked_elastic_period_days", elastic, "d", note=f"Lamb's model, $k_2$ = {shortest(compare['k2'])}"
    )
    fig, ax = new_figure(6.0, 3.2)
    ax.semilogy(f, np.maximum(power, 1e-8), lw=0.7, color="0.25")
    marks = (
        (rigid, "rigid Earth", "#D55E00", (0, (4, 2))),
        (elastic, "elastic Earth (Lamb)", "#CC79A7", (0, (1, 1.5))),
        (fit.chandler_period_days, "observed", "#0072B2", "-"),
    )
    for period, label, colour, style in marks:
        ax.axvline(
            earth.JULIAN_YEAR_DAYS / period,
            color=colour,
            ls=style,
            lw=1.0,
            label=f"{label}: {format_number(period, 4)} d",
        )
    ax.axvline(pm.ANNUAL_CPY, color="0.5", ls=":", lw=0.9, label="annual")
    ax.set_xlim(-1.6, 1.6)
    ax.set_ylim(1e-5, 2)
    ax.set_xlabel("frequency (yr⁻¹), positive: prograde")
    ax.set_ylabel("power, peak = 1")
    ax.legend(loc="upper left")
    results.figure(
        "periodogram",
        fig,
        "Periodogram of the observed polar motion $x - iy$ (trend removed) against "
        "frequency in cycles per year, prograde frequencies positive; the lines mark the periods of the "
        f"models and of the fit. The rigid Earth would wobble in {format_number(rigid, 4)} d, Lamb's "
        f"elastic Earth in {format_number(elastic, 4)} d; the Earth wobbles in "
        f"{format_number(fit.chandler_period_days, 4)} d, prograde, beside the annual peaks.",
    )


def _year(value) -> str:
    """A calendar epoch: 1990 as 1990, a fraction of a year to a hundredth (2013.74)."""
    return format_number(int(value)) if float(value).is_integer() else format_number(float(value), 6)
