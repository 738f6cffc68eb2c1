"""Chebyshev collocation for the continuous hanging chain, independent of any Bessel routine.

With tau = 2 sqrt(x/g) (Lamb Art. 90) the chain obeys y_tt = y_tautau + y_tau / tau: the
axisymmetric membrane. On the even extension tau in [-1, 1] with y(+-1) = 0 the eigenvalues
sigma^2 of -(D2 + diag(1/tau) D1) are (j_0k)^2 (tau_1 = 1). An odd number of intervals keeps
tau = 0 off the grid; folding the even symmetry halves the problem (Trefethen, Spectral Methods
in MATLAB, Program 28).
"""

from __future__ import annotations

import numpy as np


def cheb(N: int):
    """Chebyshev differentiation matrix and points x_j = cos(pi j / N), j = 0..N."""
    x = np.cos(np.pi * np.arange(N + 1) / N)
    c = np.ones(N + 1)
    c[0] = c[-1] = 2.0
    c *= (-1.0) ** np.arange(N + 1)
    dx = x[:, None] - x[None, :]
    D = np.outer(c, 1.0 / c) / (dx + np.eye(N + 1))
    D -= np.diag(D.sum(axis=1))
    return D, x


def hanging_chain_sigma(N: int = 41, k: int = 5) -> np.ndarray:
    """The k lowest sigma with J0(sigma) = 0, by collocation on N (odd) intervals."""
    if N % 2 == 0:
        raise ValueError("N must be odd so that tau = 0 is not a grid point")
    D, x = cheb(N)
    D2 = D @ D
    half = (N - 1) // 2
    inner = np.arange(1, half + 1)  # the positive interior points
    mirror = N - inner  # their reflections (-tau)
    D1f = D[np.ix_(inner, inner)] + D[np.ix_(inner, mirror)]
    D2f = D2[np.ix_(inner, inner)] + D2[np.ix_(inner, mirror)]
    L = -(D2f + np.diag(1.0 / x[inner]) @ D1f)
    values = np.linalg.eigvals(L)
    values = np.sort(values.real[np.abs(values.imag) < 1e-8 * np.abs(values.real)])
    return np.sqrt(values[:k])
