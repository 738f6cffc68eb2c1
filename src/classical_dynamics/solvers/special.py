"""Exact references for chains: zeros of J0 and of the Laguerre polynomials, checked independently."""

from __future__ import annotations

import mpmath
import numpy as np
from scipy import special


def bessel_j0_zeros(k: int) -> np.ndarray:
    """First k zeros of J0 (scipy's Newton from McMahon; order 0 is safe, see scipy #4690)."""
    return special.jn_zeros(0, k)


def bessel_j0_zeros_mp(k: int, dps: int = 30) -> list:
    """The same zeros from mpmath at dps digits: the independent reference for tests."""
    with mpmath.workdps(dps):
        return [mpmath.besseljzero(0, i) for i in range(1, k + 1)]


def mcmahon_j0_zero(k) -> np.ndarray:
    """McMahon's asymptotic zero of J0: b + 1/(8b) - 31/(384 b^3), b = (k - 1/4) pi."""
    b = (np.asarray(k, float) - 0.25) * np.pi
    return b + 1 / (8 * b) - 31 / (384 * b**3)


def laguerre_zeros(n: int) -> np.ndarray:
    """All zeros of L_n (Golub-Welsch, scipy); exact within round-off for moderate n."""
    return special.roots_laguerre(n)[0]


def laguerre_lowest_zero_asymptotic(n):
    """x_{n,1} = j^2/(4n+2) [1 + (j^2 - 2)/(48 (n+1/2)^2)] + O(n^-5) (Tricomi-type expansion)."""
    j = special.jn_zeros(0, 1)[0]
    half = np.asarray(n, float) + 0.5
    return j**2 / (4 * half) * (1 + (j**2 - 2) / (48 * half**2))


def laguerre_zero_mp(n: int, guess: float, dps: int = 30):
    """A zero of L_n to dps digits: Newton on the three-term recurrence in mpmath."""
    with mpmath.workdps(dps):
        x = mpmath.mpf(guess)
        for _ in range(60):
            prev, cur = mpmath.mpf(1), 1 - x
            for k in range(1, n):
                prev, cur = cur, ((2 * k + 1 - x) * cur - k * prev) / (k + 1)
            derivative = n * (cur - prev) / x
            step = cur / derivative
            x -= step
            if abs(step) < mpmath.mpf(10) ** (-dps + 3) * abs(x):
                break
        return x
