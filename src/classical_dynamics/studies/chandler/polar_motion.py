"""Polar motion: the IERS C04 series, and the fit of the Chandler and annual wobbles to any series.

Coordinates: the IERS gives the pole (x, y) in arcseconds with x toward Greenwich and y toward 90° W.
m = x - i y is the pole in a right-handed frame (y toward 90° E), so that a motion in the sense of the
Earth's spin (counterclockwise seen from above the North Pole: prograde) has positive frequency.

Model, over a window, with t in Julian years from J2000 and f_a one cycle per tropical year:
    m(t) = c0 + c1 t + a_c e^{2 pi i f_c t} + a_+ e^{2 pi i f_a t} + a_- e^{-2 pi i f_a t}
The amplitudes enter linearly; f_c is found by minimizing the residual over it (variable projection).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...models import earth

MJD_J2000 = 51544.5
ANNUAL_CPY = earth.JULIAN_YEAR_DAYS / earth.TROPICAL_YEAR_DAYS  # cycles per Julian year


def eop_file() -> Path:
    """The EOP C04 series shipped by astropy-iers-data (no network)."""
    import astropy_iers_data

    return Path(astropy_iers_data.__file__).parent / "data" / "eopc04.1962-now"


def series_extent(path: Path) -> tuple[float, float]:
    """(first, last) epoch of the series in decimal years, read without parsing the whole file."""
    first = last = None
    with open(path, encoding="ascii") as handle:
        for line in handle:
            if line.strip() and not line.startswith("#"):
                if first is None:
                    first = line
                last = line
    if first is None:
        raise ValueError(f"{path}: no data records")
    return tuple(years_from_mjd(float(rec.split()[4])) + 2000.0 for rec in (first, last))


def years_from_mjd(mjd):
    return (np.asarray(mjd, float) - MJD_J2000) / earth.JULIAN_YEAR_DAYS


def read_eop(path: Path, start_year: float, end_year: float):
    """t (Julian years from J2000), m = x - i y (mas) inside [start_year, end_year)."""
    data = np.loadtxt(path, comments="#", usecols=(4, 5, 6))
    t = years_from_mjd(data[:, 0])
    keep = (t + 2000.0 >= start_year) & (t + 2000.0 < end_year)
    return t[keep], (data[keep, 1] - 1j * data[keep, 2]) * 1000.0


def _design(t, f_c):
    return np.stack(
        [
            np.ones_like(t),
            t,
            np.exp(2j * np.pi * f_c * t),
            np.exp(2j * np.pi * ANNUAL_CPY * t),
            np.exp(-2j * np.pi * ANNUAL_CPY * t),
        ],
        axis=1,
    ).astype(complex)


def _linear_fit(t, m, f_c):
    X = _design(t, f_c)
    coef, *_ = np.linalg.lstsq(X, m, rcond=None)
    return coef, m - X @ coef


@dataclass(frozen=True)
class WobbleFit:
    chandler_cpy: float
    chandler_period_days: float
    chandler_period_sigma_days: float  # formal, inflated by the residuals' correlation length
    chandler_amplitude_mas: float
    chandler_phase_deg: float  # of a_c at J2000
    annual_prograde_mas: float
    annual_retrograde_mas: float
    drift_mas_per_year: complex
    residual_rms_mas: float
    correlation_samples: float


def fit(t, m, search_cpy=(0.70, 1.0)) -> WobbleFit:
    """Least squares for f_c (grid on the residual, then a parabola through the minimum's neighbours)."""
    from scipy.optimize import minimize_scalar

    def cost(f):
        return float(np.sum(np.abs(_linear_fit(t, m, f)[1]) ** 2))

    span = t[-1] - t[0]
    grid = np.arange(search_cpy[0], search_cpy[1], 0.05 / span)  # 20 points per resolution element
    costs = _grid_costs(t, m, grid)
    i = int(np.argmin(costs))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    f_c = float(minimize_scalar(cost, bounds=(lo, hi), method="bounded", options={"xatol": 1e-10}).x)
    coef, resid = _linear_fit(t, m, f_c)
    # formal sigma of f_c from the curvature of the cost, with sigma^2 from the residuals; daily samples
    # are not independent, so the variance is inflated by the residuals' correlation length (in samples)
    df = 1e-4
    curvature = (cost(f_c + df) - 2 * cost(f_c) + cost(f_c - df)) / df**2
    n = t.size
    sigma2 = np.sum(np.abs(resid) ** 2) / (2 * n - 10)  # per real component
    corr = _correlation_length(resid)
    sigma_f = np.sqrt(2.0 * sigma2 * corr / curvature)
    period = earth.JULIAN_YEAR_DAYS / f_c
    return WobbleFit(
        f_c,
        period,
        period * sigma_f / f_c,
        abs(coef[2]),
        float(np.degrees(np.angle(coef[2]))),
        abs(coef[3]),
        abs(coef[4]),
        complex(coef[1]),
        float(np.sqrt(np.mean(np.abs(resid) ** 2))),
        corr,
    )


def _grid_costs(t, m, grid, chunk: int = 32) -> np.ndarray:
    """cost(f) of `fit` at every f of the grid, by projection. With Q an orthonormal basis of the four
    columns that do not depend on f, r0 = m less its projection on them and g the Chandler column, the
    least-squares residual is |r0|^2 - |g^H r0|^2 / (|g|^2 - |Q^H g|^2), |g|^2 being the number of samples.
    The same costs as one lstsq per point to round-off (they only pick the bracket that the bounded search
    refines with lstsq, so the fit is the same to the last bit), at a fifth of the time: a 19000 x 5 lstsq
    per point made a 53-year fit take 3 s."""
    Q, _ = np.linalg.qr(np.delete(_design(t, 0.0), 2, axis=1))
    Q_conj = Q.conj()
    r0 = m - Q @ (Q_conj.T @ m)
    total, r0_conj = float(np.sum(np.abs(r0) ** 2)), r0.conj()
    costs = np.empty(grid.size)
    for start in range(0, grid.size, chunk):
        phase = 2 * np.pi * np.outer(t, grid[start : start + chunk])
        G = np.empty(phase.shape, complex)
        G.real, G.imag = np.cos(phase), np.sin(phase)
        along = np.sum(np.abs(G.T @ Q_conj) ** 2, axis=1)  # |Q^H g|^2 for each f
        costs[start : start + chunk] = total - np.abs(r0_conj @ G) ** 2 / (t.size - along)
    return costs


def _correlation_length(resid) -> float:
    """Samples over which the residuals' autocorrelation falls to 1/e (at least 1)."""
    r = resid - resid.mean()
    n = r.size
    spectrum = np.fft.fft(r, 2 * n)
    acf = np.fft.ifft(spectrum * np.conj(spectrum))[:n].real
    acf /= acf[0]
    below = np.nonzero(acf < np.exp(-1.0))[0]
    return float(max(below[0] if below.size else n, 1))


BLOCK = 64  # frequencies per block of the periodogram


def periodogram(t, m, f_max_cpy=2.0, points=4001):
    """|DFT|^2 (normalized to 1 at the peak) of the detrended series at f in [-f_max, f_max] cpy."""
    X = np.stack([np.ones_like(t), t], axis=1)
    coef, *_ = np.linalg.lstsq(X, m, rcond=None)
    r = m - X @ coef
    f = np.linspace(-f_max_cpy, f_max_cpy, points)
    # exp(-2 pi i (f_j + k df) t) = exp(-2 pi i f_j t) exp(-2 pi i k df t): one table of the second serves
    # every block of BLOCK frequencies, so a block is one exp of the series and a product (4001 exps before)
    offsets = np.exp(-2j * np.pi * np.outer(np.arange(BLOCK) * (f[1] - f[0]), t))
    power = np.empty(points)
    for j in range(0, points, BLOCK):
        k = min(BLOCK, points - j)
        power[j : j + k] = np.abs(offsets[:k] @ (r * np.exp(-2j * np.pi * f[j] * t))) ** 2
    return f, power / power.max()


def windowed_amplitudes(t, m, f_c, window_years, step_years):
    """Chandler and annual amplitudes (mas) with f_c held fixed, in sliding windows; centre years."""
    rows = []
    start = t[0]
    while start + window_years <= t[-1] + 1e-9:
        keep = (t >= start) & (t < start + window_years)
        coef, _ = _linear_fit(t[keep], m[keep], f_c)
        rows.append(
            (
                start + 0.5 * window_years + 2000.0,
                abs(coef[2]),
                float(np.degrees(np.angle(coef[2]))),
                abs(coef[3]),
                abs(coef[4]),
            )
        )
        start += step_years
    return np.array(rows)
