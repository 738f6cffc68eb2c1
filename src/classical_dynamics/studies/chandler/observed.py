"""The observed polar motion: the IERS C04 series fitted for the Chandler and annual wobbles."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...models import earth
from ...provenance import sha256_file
from ..results import new_figure
from . import polar_motion as pm
from .model import figure_path

VICENTE_WILSON_DAYS = (433.1, 1.7)


def run(scene, results, quick):
    obs = scene.data["observation"]
    path = pm.eop_file()
    end = np.inf if obs["end_year"] == "latest" else obs["end_year"]
    t, m = pm.read_eop(path, obs["start_year"], end)
    results.notes.append(f"Data: {path.name} (IERS EOP 20 C04, from astropy-iers-data), sha256 {sha256_file(path)}, "
                         f"{t.size} daily values from {t[0] + 2000:.3f} to {t[-1] + 2000:.3f}.")
    results.number("first_year", float(t[0] + 2000.0), "yr")
    results.number("last_year", float(t[-1] + 2000.0), "yr")
    results.number("samples", int(t.size), "1")

    fit = pm.fit(t, m)
    results.number("observed_chandler_period_days", fit.chandler_period_days, "d",
                   note="least squares: trend + Chandler + annual (pro- and retrograde)")
    results.number("observed_chandler_period_formal_sigma_days", fit.chandler_period_sigma_days, "d",
                   note=f"formal, inflated by the residuals' correlation length ({fit.correlation_samples:g} days)")
    results.number("observed_chandler_amplitude_mas", fit.chandler_amplitude_mas, "mas", note="mean over the span")
    results.number("observed_annual_amplitude_mas", fit.annual_prograde_mas, "mas", note="prograde annual term")
    results.number("observed_annual_retrograde_mas", fit.annual_retrograde_mas, "mas")
    results.number("residual_rms_mas", fit.residual_rms_mas, "mas")
    results.number("mean_pole_drift_mas_per_year", abs(fit.drift_mas_per_year), "mas/yr")
    results.number("mean_pole_drift_toward_longitude_deg",
                   float(np.degrees(np.angle(fit.drift_mas_per_year))), "°E",
                   note="direction of the mean pole's drift (negative: west longitudes)")
    ref_days, ref_sigma = VICENTE_WILSON_DAYS
    results.number("difference_from_vicente_wilson_sigmas", (fit.chandler_period_days - ref_days) / ref_sigma, "σ",
                   note="(ours − 433.1 d) / 1.7 d")

    thirds = np.array_split(np.arange(t.size), 3)
    periods = [pm.fit(t[i], m[i]).chandler_period_days for i in thirds]
    results.table("period_by_thirds", pd.DataFrame({
        "from_year": [t[i[0]] + 2000 for i in thirds], "to_year": [t[i[-1]] + 2000 for i in thirds],
        "chandler_period_days": periods}), "The Chandler period fitted on each third of the series.")
    results.number("period_spread_days", float(np.std(periods, ddof=1)), "d",
                   note="standard deviation of the period over the three thirds: the wobble's own irregularity")

    # the sense of rotation, read from the data: the strongest peak near 0.85 cpy, either sign
    f, power = pm.periodogram(t, m)
    band = (np.abs(f) > 0.7) & (np.abs(f) < 1.0)
    peak = f[band][np.argmax(power[band])]
    results.number("chandler_peak_cpy", float(peak), "cycles/yr",
                   note="positive: prograde (counterclockwise seen from above the North Pole, as the spin)")
    results.hard_case("observed_prograde", "The observed Chandler peak is prograde, at positive frequency of x − iy "
                      "(1 if not)", 0.0 if peak > 0 else 1.0, 0.0)
    _periodogram_figure(results, f, power, fit, obs["compare"])

    windows = pm.windowed_amplitudes(t, m, fit.chandler_cpy, obs["window_years"], obs["step_years"])
    frame = pd.DataFrame(windows, columns=["centre_year", "chandler_mas", "chandler_phase_deg", "annual_prograde_mas",
                                           "annual_retrograde_mas"])
    results.table("amplitude_by_window", frame, f"Chandler and annual amplitudes in {obs['window_years']:g}-year "
                  f"windows every {obs['step_years']:g} years (the Chandler frequency held at the global fit).")
    low = frame.loc[frame.chandler_mas.idxmin()]
    high = frame.loc[frame.chandler_mas.idxmax()]
    results.number("window_amplitude_min_mas", float(low.chandler_mas), "mas", note=f"window centred {low.centre_year:.1f}")
    results.number("window_amplitude_min_year", float(low.centre_year), "yr")
    results.number("window_amplitude_max_mas", float(high.chandler_mas), "mas", note=f"window centred {high.centre_year:.1f}")
    results.number("window_amplitude_max_year", float(high.centre_year), "yr")
    fig, ax = new_figure(6.0, 3.2)
    ax.plot(frame.centre_year, frame.chandler_mas, "o-", ms=2.5, label="Chandler")
    ax.plot(frame.centre_year, frame.annual_prograde_mas, "s-", ms=2.5, label="annual (prograde)")
    ax.set_xlabel("centre of the window (year)")
    ax.set_ylabel("amplitude (mas)")
    ax.legend(fontsize=8)
    results.figure("amplitude", fig, f"Amplitude of the Chandler and annual wobbles in {obs['window_years']:g}-year "
                   f"windows: the Chandler wobble peaked near {high.centre_year:.0f} at {high.chandler_mas:.0f} mas "
                   f"and nearly vanished near {low.centre_year:.0f} ({low.chandler_mas:.0f} mas).")
    start, stop = obs.get("path_years", [t[-1] + 2000 - 13.0, t[-1] + 2000])
    keep = (t + 2000 >= start) & (t + 2000 <= stop)
    figure_path(results, "polar_path", t[keep] + 2000, m[keep], f"Observed: the pole from {start:g} to {stop:g} "
                "(IERS C04), in the same right-handed frame as the model.", last_years=stop - start)


def _periodogram_figure(results, f, power, fit, compare):
    rigid = earth.sidereal_to_solar_days(earth.euler_period_sidereal_days(compare["H"]))
    elastic = 2 * np.pi / (earth.SPIN_RAD_PER_DAY * earth.elastic_wobble_frequency(
        compare["H"], earth.elastic_beta_n2_over_c(compare["k2"], compare["H"])))
    results.number("marked_rigid_period_days", rigid, "d", note=f"H = {compare['H']}")
    results.number("marked_elastic_period_days", elastic, "d", note=f"Lamb's model, k2 = {compare['k2']}")
    fig, ax = new_figure(6.4, 3.4)
    ax.semilogy(f, np.maximum(power, 1e-8), lw=0.7, color="0.2")
    marks = ((rigid, "rigid", "C3"), (elastic, "elastic (Lamb)", "C2"), (fit.chandler_period_days, "observed", "C0"))
    for period, label, colour in marks:
        ax.axvline(earth.JULIAN_YEAR_DAYS / period, color=colour, ls="--", lw=0.9, label=f"{label}: {period:.1f} d")
    ax.axvline(pm.ANNUAL_CPY, color="0.5", ls=":", lw=0.9, label="annual")
    ax.set_xlim(-1.6, 1.6)
    ax.set_ylim(1e-5, 2)
    ax.set_xlabel("frequency (cycles per year; positive = prograde)")
    ax.set_ylabel("power (peak = 1)")
    ax.legend(fontsize=7, loc="lower left")
    results.figure("periodogram", fig, "Periodogram of the observed polar motion (trend removed), prograde frequencies "
                   f"positive. The rigid Earth would wobble at {rigid:.1f} d, Lamb's elastic Earth at {elastic:.1f} d; "
                   f"the Earth wobbles at {fit.chandler_period_days:.1f} d.")
