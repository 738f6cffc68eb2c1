"""The observed polar motion study (studies/chandler/observed.py): a series built here with a known Chandler
period, amplitudes and drift comes back from the whole study step; the real IERS series gives Vicente and
Wilson's period (433.1 +- 1.7 d, 1997)."""

import numpy as np
import pytest

from classical_dynamics.models import earth
from classical_dynamics.results import Results
from classical_dynamics.studies import validate
from classical_dynamics.studies.chandler import observed
from classical_dynamics.studies.chandler import polar_motion as pm

from .conftest import ROOT

SCENE = ROOT / "workflow/scenes/chandler/observed.yaml"


def run(scene):
    results = Results("chandler", scene.name, scene.title)
    observed.run(scene, results, quick=True)
    return {name: entry["value"] for name, entry in results.numbers.items()}, results


def _known_series(period_days=433.0, chandler=150.0, annual=90.0):
    """Daily, 1994 to 2018 (years from J2000): trend, Chandler, annual pro- and retrograde, 1 mas noise."""
    t = np.arange(-6.0, 18.0, 1.0 / 365.25)
    f_c = earth.JULIAN_YEAR_DAYS / period_days
    drift = 3.5 * np.exp(1j * np.radians(-80.0))  # mas/yr
    m = (
        40.0
        + drift * t
        + chandler * np.exp(2j * np.pi * f_c * t + 0.3j)
        + annual * np.exp(2j * np.pi * pm.ANNUAL_CPY * t)
        + 10.0 * np.exp(-2j * np.pi * pm.ANNUAL_CPY * t)
    )
    rng = np.random.default_rng(0)
    m = m + rng.normal(0.0, 1.0, t.size) + 1j * rng.normal(0.0, 1.0, t.size)  # 1 mas noise each
    return t, m


def test_analyse_finds_the_known_terms_without_a_results_object():
    period_days, chandler = 433.0, 150.0
    t, m = _known_series(period_days, chandler)
    wobble = observed.analyse(t, m, 6.0, 1.0)
    assert wobble.fit.chandler_period_days == pytest.approx(period_days, abs=0.05)
    assert wobble.chandler_peak_cpy == pytest.approx(earth.JULIAN_YEAR_DAYS / period_days, abs=0.05)
    np.testing.assert_allclose(wobble.period_by_thirds_days, period_days, atol=0.5)
    np.testing.assert_allclose(wobble.windows.chandler_mas, chandler, rtol=0.02)
    # the annual terms built in, each in its own column: 90 mas prograde, 10 mas retrograde
    np.testing.assert_allclose(wobble.windows.annual_prograde_mas, 90.0, rtol=0.02)
    np.testing.assert_allclose(wobble.windows.annual_retrograde_mas, 10.0, rtol=0.1)
    assert wobble.low.chandler_mas <= wobble.high.chandler_mas


def test_a_series_of_known_terms_comes_back(monkeypatch):
    period_days, chandler, annual = 433.0, 150.0, 90.0
    t, m = _known_series(period_days, chandler, annual)
    monkeypatch.setattr(pm, "read_eop", lambda path, start, end: (t, m))
    numbers, results = run(validate("chandler", SCENE))
    assert numbers["observed_chandler_period_days"] == pytest.approx(period_days, abs=0.05)
    assert numbers["observed_chandler_amplitude_mas"] == pytest.approx(chandler, rel=1e-3)
    assert numbers["observed_annual_amplitude_mas"] == pytest.approx(annual, rel=1e-3)
    assert numbers["observed_annual_retrograde_mas"] == pytest.approx(10.0, abs=0.05)
    assert numbers["mean_pole_drift_mas_per_year"] == pytest.approx(3.5, rel=1e-2)
    assert numbers["mean_pole_drift_toward_longitude_deg"] == pytest.approx(-80.0, abs=0.5)
    assert numbers["residual_rms_mas"] == pytest.approx(np.sqrt(2.0), rel=0.05)  # the noise put in
    assert numbers["samples"] == t.size and numbers["first_year"] == pytest.approx(1994.0)
    assert numbers["difference_from_vicente_wilson_sigmas"] == pytest.approx((433.0 - 433.1) / 1.7, abs=0.05)
    thirds = results.tables["period_by_thirds"][0]
    np.testing.assert_allclose(thirds.chandler_period_days, period_days, atol=0.5)
    # the thirds tile the series: each from where the last ended (a sample on), the first at its first
    # year, the last at its last, and about a third of its span each (t is in years from 2000)
    span = t[-1] - t[0]
    assert thirds.from_year.iloc[0] == pytest.approx(t[0] + 2000) and thirds.to_year.iloc[
        -1
    ] == pytest.approx(t[-1] + 2000)
    np.testing.assert_allclose(thirds.to_year - thirds.from_year, span / 3, rtol=0.01)
    np.testing.assert_allclose(
        thirds.from_year.iloc[1:].values, thirds.to_year.iloc[:-1].values, atol=2 * (t[1] - t[0])
    )


def test_the_iers_series_gives_the_published_period(tmp_path):
    import yaml

    data = yaml.safe_load(SCENE.read_text())
    data["observation"]["start_year"] = 1994.0  # thirty years: five beats of the two wobbles, and quick
    (tmp_path / "observed.yaml").write_text(yaml.safe_dump(data))
    numbers, _ = run(validate("chandler", tmp_path / "observed.yaml"))
    # Vicente and Wilson (1997): 433.1 +- 1.7 d; three of their sigmas
    assert numbers["observed_chandler_period_days"] == pytest.approx(433.1, abs=3 * 1.7)
    assert numbers["first_year"] == pytest.approx(1994.0, abs=0.01)


def test_without_path_years_the_polar_path_shows_the_last_13_years(monkeypatch, tmp_path):
    """The scene's path_years is optional: without it the polar path shows the series' last 13 years (the
    known series here ends in 2018, so from 2005); the sigma number names Vicente and Wilson's published
    433.1 +- 1.7 d it is measured against."""
    import yaml

    t, m = _known_series()
    monkeypatch.setattr(pm, "read_eop", lambda path, start, end: (t, m))
    data = yaml.safe_load(SCENE.read_text())
    del data["observation"]["path_years"]
    (tmp_path / "observed.yaml").write_text(yaml.safe_dump(data))
    _, results = run(validate("chandler", tmp_path / "observed.yaml"))
    fig, _ = results.figures["polar_path"]
    years = fig.axes[1].lines[0].get_xdata()
    last = t[-1] + 2000
    assert years[-1] == pytest.approx(last) and years[0] == pytest.approx(last - 13.0, abs=2 / 365.25)
    note = results.numbers["difference_from_vicente_wilson_sigmas"]["note"]
    assert "433.1 d" in note and "1.7 d" in note


def test_the_grid_costs_are_the_least_squares_residuals_a_full_fit_leaves():
    """The projection shortcut against the plain route: at each frequency, lstsq of the whole design (numpy's,
    not the projection), its squared residual summed."""
    rng = np.random.default_rng(5)
    t = np.linspace(0.0, 12.0, 900)
    m = 0.2 * np.exp(2j * np.pi * 0.845 * t) + 0.08 * np.exp(2j * np.pi * t) + 0.01 * (1 + t)
    m = m + 0.01 * (rng.standard_normal(t.size) + 1j * rng.standard_normal(t.size))
    grid = np.linspace(0.75, 0.95, 11)
    plain = []
    for f in grid:
        X = pm._design(t, f)
        coef, *_ = np.linalg.lstsq(X, m, rcond=None)
        plain.append(np.sum(np.abs(m - X @ coef) ** 2))
    assert pm._grid_costs(t, m, grid, chunk=4) == pytest.approx(plain, rel=1e-9)


def test_an_epoch_prints_whole_or_to_a_hundredth():
    assert observed._year(1990.0) == "1990" and observed._year(2013.7412) == "2013.74"


def test_read_eop_keeps_the_years_asked_for_and_writes_m_as_x_minus_iy(tmp_path):
    """A file in the EOP 14 C04 layout (MJD in the fifth column, x and y in arcsec after it), one record every
    73.05 days from J2000 (MJD 51544.5): years -0.4 ... 1.4. [2000, 2001) keeps t = 0 ... 0.8, not 1.0; m in
    mas, x - i y (the IERS y axis points 90 degrees west)."""
    k = np.arange(-2, 8)
    x, y = 0.1 + 0.01 * k, -0.2 + 0.001 * k
    rows = [f"2000 1 1 0 {51544.5 + 73.05 * j:.2f} {xj:.6f} {yj:.6f} 0.1 0.0" for j, xj, yj in zip(k, x, y)]
    path = tmp_path / "eop.txt"
    path.write_text("# header\n" + "\n".join(rows) + "\n")
    t, m = pm.read_eop(path, 2000.0, 2001.0)
    assert t == pytest.approx([0.0, 0.2, 0.4, 0.6, 0.8], abs=1e-12)
    assert m == pytest.approx(1000.0 * (x[2:7] - 1j * y[2:7]), rel=1e-12)
    assert pm.read_eop(path, 1999.0, 2000.0)[0] == pytest.approx([-0.4, -0.2], abs=1e-12)
