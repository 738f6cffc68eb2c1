"""Eigen-solvers for chains: K v = lambda M v with K = B^T diag(s) B + diag(d), M = diag(m).

Four ways to the lowest eigenvalues, compared in the report's "what accuracy costs":
  dense                scipy.linalg.eigh on the dense matrix (what one reaches for first)
  tridiagonal          LAPACK's tridiagonal solver, all eigenvalues
  tridiagonal_select   the same, only the k lowest (bisection + inverse iteration)
  pliability           subspace iteration on K^-1 = B^-1 diag(1/s) B^-T (Lamb's coefficients of
                       pliability, Art. 87-88: cumulative sums, no cancellation), finished with the
                       Rayleigh quotient in factored form sum s (B v)^2 / sum m v^2, a sum of positive
                       terms. It keeps *relative* accuracy for the lowest modes however large n is;
                       the other three lose it in proportion to lambda_max/lambda_min ~ n^2.
"""

from __future__ import annotations

import numpy as np

from ..lazy import lazy_module

# on first use: a scene's validation reads SOLVER_LIMITS (its cost) and needs none of it (0.3 s to import)
sla = lazy_module("scipy.linalg")

METHODS = ("dense", "tridiagonal", "tridiagonal_select", "pliability")
# the largest n each method is timed at in the accuracy-cost sweep (the dense one grows as n^3)
SOLVER_LIMITS = {"dense": 2048, "tridiagonal": 8192, "tridiagonal_select": 131072, "pliability": 131072}


def symmetric_tridiagonal(s, d, m, ends: str):
    """Diagonal and off-diagonal of M^-1/2 K M^-1/2 for a particle chain.

    Particles 0..n-1 from the fixed end; segment j joins particle j-1 and j (fixed-free).
    """
    s, m = np.asarray(s, float), np.asarray(m, float)
    n = m.size
    diag = np.zeros(n) if d is None else np.array(d, float)
    if ends == "fixed-free":  # segments 0..n-1; segment 0 to the support
        diag += s
        diag[:-1] += s[1:]
        off = -s[1:]
    elif ends == "fixed-fixed":  # segments 0..n; 0 and n to the supports
        diag += s[:-1] + s[1:]
        off = -s[1:-1]
    elif ends == "free-free":  # segments 0..n-2 between neighbours
        diag[:-1] += s
        diag[1:] += s
        off = -s.copy()
    else:
        raise ValueError(f"unknown ends {ends!r}")
    scale = 1.0 / np.sqrt(m)
    return diag * scale**2, off * scale[:-1] * scale[1:]


def lowest_eigenvalues(s, d, m, ends: str, k: int, method: str) -> np.ndarray:
    k = min(k, len(m))
    if method == "pliability":
        if ends != "fixed-free" or (d is not None and np.any(d)):
            raise ValueError("the pliability solver needs a fixed-free chain with no diagonal term")
        return pliability_lowest(s, m, k)[0]
    diag, off = symmetric_tridiagonal(s, d, m, ends)
    if method == "dense":
        dense = np.diag(diag) + np.diag(off, 1) + np.diag(off, -1)
        return sla.eigh(dense, eigvals_only=True, subset_by_index=[0, k - 1], driver="evr")
    if method == "tridiagonal":
        return sla.eigvalsh_tridiagonal(diag, off)[:k]
    if method == "tridiagonal_select":
        return sla.eigvalsh_tridiagonal(diag, off, select="i", select_range=(0, k - 1))
    raise ValueError(f"unknown method {method!r}; known: {', '.join(METHODS)}")


def modes(s, d, m, ends: str, k: int):
    """Lowest k eigenvalues and M-normalized mode shapes (columns), sign fixed: last entry > 0."""
    diag, off = symmetric_tridiagonal(s, d, m, ends)
    k = min(k, len(m))
    values, vectors = sla.eigh_tridiagonal(diag, off, select="i", select_range=(0, k - 1))
    shapes = vectors / np.sqrt(np.asarray(m, float))[:, None]
    signs = np.sign(shapes[-1])
    signs[signs == 0] = 1
    return values, shapes * signs


def _apply_pliability(x, s, sqrt_m):
    # M^1/2 K^-1 M^1/2 x with K^-1 = B^-1 S^-1 B^-T; B^-T is a reverse cumulative sum, B^-1 a cumulative sum.
    y = x * sqrt_m[:, None]
    y = np.cumsum(y[::-1], axis=0)[::-1]
    y /= s[:, None]
    y = np.cumsum(y, axis=0)
    return y * sqrt_m[:, None]


def pliability_lowest(s, m, k: int, *, tol: float = 1e-15, max_iter: int = 500):
    """Lowest k eigenvalues (and shapes) of a fixed-free chain to high relative accuracy."""
    s, m = np.asarray(s, float), np.asarray(m, float)
    n = m.size
    k = min(k, n)
    p = min(n, k + 4)
    sqrt_m = np.sqrt(m)
    rng = np.random.default_rng(12345)
    w = np.linalg.qr(rng.standard_normal((n, p)))[0]
    previous = np.full(p, np.inf)
    for _ in range(max_iter):
        z = _apply_pliability(w, s, sqrt_m)
        small = w.T @ z
        mu, y = np.linalg.eigh((small + small.T) / 2)
        order = np.argsort(mu)[::-1]
        mu, y = mu[order], y[:, order]
        w = np.linalg.qr(z @ y)[0]
        if np.all(np.abs(mu[:k] - previous[:k]) <= tol * np.abs(mu[:k])):
            break
        previous = mu
    shapes = w[:, :k] / sqrt_m[:, None]
    values = np.array([rayleigh_fixed_free(s, m, shapes[:, i]) for i in range(k)])
    order = np.argsort(values)
    return values[order], shapes[:, order]


def rayleigh_fixed_free(s, m, v) -> float:
    """sum s (B v)^2 / sum m v^2: both sums of positive terms, so no cancellation."""
    dv = np.diff(v, prepend=0.0)
    return float(np.sum(s * dv * dv) / np.sum(m * v * v))
