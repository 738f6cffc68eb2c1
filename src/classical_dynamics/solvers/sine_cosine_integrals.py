"""Lee's generalized sine and cosine integrals (thesis §5.4), for complex w with Re w > 0:

    si(x, w) = -int_x^inf sin(u) u^-w du,        ci(x, w) = -int_x^inf cos(u) u^-w du.

Three ways to compute them, each with its own error bound, and one reference:
  series      Taylor series of Si(x, w') = int_0^x sin u u^-w' du and Ci(x, w'), 0 < Re w' < 1 (Lee (5.38),
              (5.39)), lifted to w = K + w' by integration by parts (Lee's reduction (5.32)-(5.35), written as
              its two-term recursion); converges for every x, fast for small x, loses digits to cancellation
              for large x (terms grow like x^2n/(2n)!).
  asymptotic  repeated integration by parts of int_x^inf u^-w e^{isu} du (Lee (5.42)-(5.48)); diverges, so it
              is cut at its smallest remainder bound: good for large x only.
  quadrature  scipy's QAWO (oscillatory weight) over [x, 40], the asymptotic expansion beyond, in double
              precision.
  reference   the incomplete gamma function at 30 digits (mpmath):
              int_x^inf u^-w e^{isu} du = e^{is pi (1-w)/2} Gamma(1 - w, -isx).
Re w must not be an integer: the reduction needs 0 < Re w' < 1 (Lee: "nu/mu not an integer").
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import mpmath
import numpy as np
from scipy import integrate, special

EPS = np.finfo(float).eps


@dataclass(frozen=True)
class Value:
    """si and ci at one (x, w), and a bound on the error of each."""

    si: complex
    ci: complex
    bound: float
    terms: int


def split(w: complex) -> tuple[int, complex]:
    """w = K + w' with K >= 0 an integer and 0 < Re w' < 1."""
    w = complex(w)
    if not w.real > 0 or w.real == math.floor(w.real):
        raise ValueError(f"Re w must be positive and not an integer (got w = {w})")
    K = math.floor(w.real)
    return K, w - K


def A(w1: complex) -> complex:
    """int_0^inf sin(u) u^-w' du = pi / (2 Gamma(w') sin(w' pi/2)), Lee (5.37)."""
    return np.pi / (2.0 * special.gamma(w1) * np.sin(w1 * np.pi / 2.0))


def B(w1: complex) -> complex:
    """int_0^inf cos(u) u^-w' du = pi / (2 Gamma(w') cos(w' pi/2)), Lee (5.37)."""
    return np.pi / (2.0 * special.gamma(w1) * np.cos(w1 * np.pi / 2.0))


def _lift(x: float, w1: complex, K: int, S: complex, C: complex, bound: float):
    """From S = int_x^inf sin u^-w', C = int_x^inf cos u^-w' to w = w' + K, by parts:
    S(w) = [x^(1-w) sin x + C(w-1)]/(w-1),  C(w) = [x^(1-w) cos x - S(w-1)]/(w-1).
    The error bound is carried through the same divisions, with the round-off of each step added."""
    s, c = np.sin(x), np.cos(x)
    w = w1
    for _ in range(K):
        w = w + 1.0
        xp = x ** (1.0 - w)
        bound = (bound + 4.0 * EPS * (abs(xp) + abs(S) + abs(C))) / abs(w - 1.0)
        S, C = (xp * s + C) / (w - 1.0), (xp * c - S) / (w - 1.0)
    return S, C, bound


def series(x: float, w: complex, terms: int | None = None, tol: float = 1e-16) -> Value:
    """Taylor series (5.38)/(5.39) with `terms` terms each (or as many as the Lagrange bounds (5.40)/(5.41)
    need for tol relative to the result), lifted to w by the reduction."""
    K, w1 = split(w)
    alpha = w1.real
    xw = x ** (-w1)  # principal branch: x > 0 real, x^-w' = e^{-w' ln x}
    Si = Ci = 0.0j
    largest = 0.0  # the largest term: what round-off costs
    term_s = x * x * xw  # (-1)^(n+1) x^(2n-w') / (2n-1)!  for n = 1
    term_c = x * xw  # (-1)^n x^(2n+1-w') / (2n)!  for n = 0
    n = 0
    while True:
        Ci += term_c / (2 * n + 1 - w1)
        Si += term_s / (2 * n + 2 - w1)
        largest = max(largest, abs(term_c), abs(term_s))
        n += 1
        # Lagrange remainders after n terms, Si (5.40) and Ci (5.41), and the round-off of the sum
        truncation = max(
            math.exp((2 * n + 1 - alpha) * math.log(x) - math.lgamma(2 * n + 1)) / (2 * n + 1 - alpha),
            math.exp((2 * n - alpha) * math.log(x) - math.lgamma(2 * n)) / (2 * n - alpha),
        )
        bound = truncation + 2.0 * n * EPS * largest
        if terms is not None and n >= terms:
            break
        if terms is None and (truncation <= tol * max(abs(Si), abs(Ci), 1e-300) or n >= 150):
            break
        term_c *= -x * x / ((2 * n - 1) * (2 * n))
        term_s *= -x * x / ((2 * n) * (2 * n + 1))
    a, b = A(w1), B(w1)
    bound += 4.0 * EPS * (abs(a) + abs(b) + abs(Si) + abs(Ci))  # Gamma, the products and the subtraction
    S, C, bound = _lift(x, w1, K, a - Si, b - Ci, bound)
    return Value(si=-S, ci=-C, bound=bound, terms=n)


def _remainder_bounds(x: float, w: complex, most: int) -> np.ndarray:
    """Bound on the rest of the asymptotic series after N = 1..most terms: |(w)_N| x^(1 - N - Re w)/(N - 1 +
    Re w) (the rest is (-is)^N (w)_N int_x^inf u^-(w+N) e^{isu} du)."""
    N = np.arange(1, most + 1)
    log_poch = np.cumsum(np.log(np.abs(w + N - 1.0)))
    with np.errstate(over="ignore"):
        return np.exp(log_poch + (1.0 - N - w.real) * np.log(x)) / (N - 1.0 + w.real)


def _tail(x: float, w: complex, s: int, terms: int) -> tuple[complex, float]:
    """int_x^inf u^-w e^{isu} du ~ is e^{isx} x^-w sum_{n<terms} (-is)^n (w)_n x^-n, and the sum of the terms'
    moduli (for the round-off)."""
    total, term, moduli = 0.0j, x ** (-w), 0.0
    for n in range(terms):
        total += term
        moduli += abs(term)
        term *= (-1j * s) * (w + n) / x
    return 1j * s * np.exp(1j * s * x) * total, moduli


def asymptotic(x: float, w: complex, terms: int | None = None) -> Value:
    """The asymptotic series with `terms` terms, or cut where its remainder bound is smallest."""
    w = complex(w)
    split(w)
    bounds = _remainder_bounds(x, w, max(terms or 0, 200))
    if terms is None:
        terms = 1 + int(np.argmin(bounds))
    (Ep, moduli), (Em, _) = _tail(x, w, 1, terms), _tail(x, w, -1, terms)
    bp = float(bounds[terms - 1]) + 4.0 * EPS * terms * moduli  # truncation and summation round-off
    S, C = (Ep - Em) / 2j, (Ep + Em) / 2.0
    return Value(si=-S, ci=-C, bound=bp, terms=terms)


TAIL_START = 40.0  # beyond it the asymptotic expansion's bound is below 1e-16 for |w| up to a few


def quadrature(x: float, w: complex, epsabs: float = 1e-14) -> Value:
    """scipy's QAWO (Clenshaw-Curtis with the sine or cosine weight) over [x, X], X = max(x, 40), on the real
    and imaginary parts of u^-w = u^-alpha e^{-i beta ln u}, and the asymptotic expansion beyond X. (QAWF over
    [x, inf) alone reports error estimates of order 1 for some x while its values are right.)"""
    w = complex(w)
    split(w)
    alpha, beta = w.real, w.imag
    X = max(x, TAIL_START)
    tail = asymptotic(X, w)
    re = lambda u: u**-alpha * np.cos(beta * np.log(u))
    im = lambda u: -(u**-alpha) * np.sin(beta * np.log(u))
    parts, bound = {}, tail.bound
    for trig in ("sin", "cos"):
        values = [0.0, 0.0]
        for k, f in enumerate((re, im) if beta != 0.0 else (re,)):
            if X > x:
                with warnings.catch_warnings():  # QAWO's estimate stands as the bound
                    warnings.simplefilter("ignore", integrate.IntegrationWarning)
                    values[k], err = integrate.quad(
                        f, x, X, weight=trig, wvar=1.0, epsabs=epsabs, epsrel=0.0, limit=200
                    )
                bound += err
        parts[trig] = complex(values[0], values[1])
    return Value(si=-parts["sin"] + tail.si, ci=-parts["cos"] + tail.ci, bound=bound, terms=0)


def reference(x: float, w: complex, dps: int = 30) -> tuple:
    """(si, ci) as mpmath numbers at dps digits, from the incomplete gamma function."""
    with mpmath.workdps(dps):
        x, w = mpmath.mpf(x), mpmath.mpc(w)
        E = {
            s: mpmath.exp(1j * s * mpmath.pi * (1 - w) / 2) * mpmath.gammainc(1 - w, -1j * s * x)
            for s in (1, -1)
        }
        return -(E[1] - E[-1]) / 2j, -(E[1] + E[-1]) / 2


def reference_value(x: float, w: complex) -> Value:
    """The reference as a Value (rounded to double), for code that takes an `integrals` function."""
    si, ci = reference(x, w)
    return Value(si=complex(si), ci=complex(ci), bound=0.0, terms=0)


def si_ci(x: float, w: complex, rtol: float = 1e-12) -> Value:
    """The series for x <= 12 (its round-off stays below 1e-12 there); beyond, the asymptotic expansion if its
    bound meets rtol, else the smallest bound of series, expansion and quadrature (the gap between the two
    expansions, and large |w|, where the expansion diverges from its first term)."""
    if x <= 12.0:
        return series(x, w)
    candidates = [asymptotic(x, w)]
    if not candidates[0].bound <= rtol * max(abs(candidates[0].si), abs(candidates[0].ci)):
        candidates += [series(x, w), quadrature(x, w)]
    return min(candidates, key=lambda v: v.bound)
