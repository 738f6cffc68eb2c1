"""RATTLE for a planar chain of particles on rigid massless links under gravity (compiled).

Cartesian positions q (n x 2), momenta p, masses m; link j joins particle j-1 (j = 0: the
suspension at the origin) and j with length a: c_j = |q_j - q_{j-1}|^2 - a^2 = 0. RATTLE is the
constrained Stormer-Verlet method: symplectic, time-reversible, second order, so the energy error
stays bounded over long times instead of drifting. The Lagrange multipliers solve tridiagonal
systems (each constraint touches two neighbours), so a step costs O(n).
"""

from __future__ import annotations

import numpy as np
from numba import njit

# Every array a step needs is allocated once per run (`_workspace`) and reused: allocating them in each step
# (a dozen arrays, more per Newton iteration) took more time than the arithmetic. The arithmetic is the same.


@njit(cache=True)
def _solve_tridiagonal(lower, diag, upper, rhs, c, x):
    """x <- the solution of the tridiagonal system (c: scratch)."""
    n = diag.size
    c[0] = upper[0] / diag[0] if n > 1 else 0.0
    x[0] = rhs[0] / diag[0]
    for i in range(1, n):
        denom = diag[i] - lower[i] * c[i - 1]
        if i < n - 1:
            c[i] = upper[i] / denom
        x[i] = (rhs[i] - lower[i] * x[i - 1]) / denom
    for i in range(n - 2, -1, -1):
        x[i] -= c[i] * x[i + 1]


@njit(cache=True)
def _links(q, d):
    """d <- the link vectors of configuration q."""
    n = q.shape[0]
    d[0] = q[0]
    for j in range(1, n):
        d[j] = q[j] - q[j - 1]


@njit(cache=True)
def _coupling(dl, dr, inv_m, lower, diag, upper):
    """(lower, diag, upper) <- the tridiagonal of G(q_l) M^-1 G(q_r)^T, given the link vectors of both."""
    n = dl.shape[0]
    lower[0] = 0.0
    upper[n - 1] = 0.0
    for j in range(n):
        w = inv_m[j] + (inv_m[j - 1] if j > 0 else 0.0)
        diag[j] = 4.0 * w * (dl[j, 0] * dr[j, 0] + dl[j, 1] * dr[j, 1])
        if j + 1 < n:
            upper[j] = -4.0 * inv_m[j] * (dl[j, 0] * dr[j + 1, 0] + dl[j, 1] * dr[j + 1, 1])
        if j > 0:
            lower[j] = -4.0 * inv_m[j - 1] * (dl[j, 0] * dr[j - 1, 0] + dl[j, 1] * dr[j - 1, 1])


@njit(cache=True)
def _add_constraint_force(p, d, lam, scale):
    # p -= scale * G(q)^T lam; G row j: +2 d_j on particle j, -2 d_j on particle j-1.
    n = d.shape[0]
    for j in range(n):
        p[j, 0] -= scale * 2.0 * lam[j] * d[j, 0]
        p[j, 1] -= scale * 2.0 * lam[j] * d[j, 1]
        if j > 0:
            p[j - 1, 0] += scale * 2.0 * lam[j] * d[j, 0]
            p[j - 1, 1] += scale * 2.0 * lam[j] * d[j, 1]


@njit(cache=True)
def _workspace(n):
    """(p_free, d0, d1, vectors): arrays of n x 2 (momenta, link vectors), and 9 rows of n for the rest."""
    return np.empty((n, 2)), np.empty((n, 2)), np.empty((n, 2)), np.empty((9, n))


@njit(cache=True)
def rattle_step(q, p, m, a, g, h, q_new, p_new, work, tol=1e-14, max_newton=50):
    """One step from (q, p) into (q_new, p_new); False if Newton's iteration for the positions failed."""
    n = q.shape[0]
    p_free, d0, d1, vectors = work
    inv_m, lam, residual, lower, diag, upper, delta, scratch, rhs = vectors
    for i in range(n):
        inv_m[i] = 1.0 / m[i]
    _links(q, d0)
    # Unconstrained half kick and drift, then Newton for the position multipliers.
    p_free[:] = p
    for i in range(n):
        p_free[i, 1] -= 0.5 * h * m[i] * g
    lam[:] = 0.0
    for _ in range(max_newton):
        p_new[:] = p_free  # the half-step momenta p_half, until the second half kick below
        _add_constraint_force(p_new, d0, lam, 0.5 * h)
        for i in range(n):
            q_new[i, 0] = q[i, 0] + h * inv_m[i] * p_new[i, 0]
            q_new[i, 1] = q[i, 1] + h * inv_m[i] * p_new[i, 1]
        _links(q_new, d1)
        worst = 0.0
        for j in range(n):
            residual[j] = d1[j, 0] ** 2 + d1[j, 1] ** 2 - a * a
            worst = max(worst, abs(residual[j]))
        if worst <= tol * a * a:
            break
        _coupling(d1, d0, inv_m, lower, diag, upper)
        # d c(q_new)/d lam = -(h^2/2) G(q_new) M^-1 G(q)^T
        _solve_tridiagonal(lower, diag, upper, residual, scratch, delta)
        for j in range(n):
            lam[j] += delta[j] / (0.5 * h * h)
    else:
        return False
    # Second half kick, with velocity multipliers making the velocities tangent to the constraints.
    for i in range(n):
        p_new[i, 1] -= 0.5 * h * m[i] * g
    _coupling(d1, d1, inv_m, lower, diag, upper)
    for j in range(n):
        vj0 = inv_m[j] * p_new[j, 0] - (inv_m[j - 1] * p_new[j - 1, 0] if j > 0 else 0.0)
        vj1 = inv_m[j] * p_new[j, 1] - (inv_m[j - 1] * p_new[j - 1, 1] if j > 0 else 0.0)
        rhs[j] = 2.0 * (d1[j, 0] * vj0 + d1[j, 1] * vj1)
    _solve_tridiagonal(lower, diag, upper, rhs, scratch, delta)  # the velocity multipliers mu
    _add_constraint_force(p_new, d1, delta, 1.0)
    return True


@njit(cache=True)
def energy(q, p, m, g):
    e = 0.0
    for i in range(q.shape[0]):
        e += 0.5 * (p[i, 0] ** 2 + p[i, 1] ** 2) / m[i] + m[i] * g * q[i, 1]
    return e


@njit(cache=True)
def _save(rows, k, q, p):
    """rows[k] <- (q, p) flattened particle by particle: (x_0, y_0, x_1, ...; px_0, py_0, ...)."""
    n = q.shape[0]
    for i in range(n):
        rows[k, 2 * i] = q[i, 0]
        rows[k, 2 * i + 1] = q[i, 1]
        rows[k, 2 * n + 2 * i] = p[i, 0]
        rows[k, 2 * n + 2 * i + 1] = p[i, 1]


@njit(cache=True)
def integrate(q0, p0, m, a, g, h, n_steps, sample_every):
    """The kernel of the method "rattle" (call it through fixed_step.solve_fixed): n_steps from (q0, p0).

    Returns the rows of the state (q, p) at steps 0, sample_every, 2 sample_every, ..., the final state, the
    bottom particle's x at every step, the energy at the rows, and the largest link-length error over the
    rows after the start."""
    q, p = q0.copy(), p0.copy()
    q_new, p_new = np.empty_like(q), np.empty_like(p)
    n = q.shape[0]
    work = _workspace(n)
    d = np.empty((n, 2))
    tip_x = np.empty(n_steps + 1)
    tip_x[0] = q[n - 1, 0]
    n_samples = n_steps // sample_every + 1
    rows = np.empty((n_samples, 4 * n))
    _save(rows, 0, q, p)
    energies = np.empty(n_samples)
    energies[0] = energy(q, p, m, g)
    constraint = 0.0
    k = 1
    for step in range(1, n_steps + 1):
        if not rattle_step(q, p, m, a, g, h, q_new, p_new, work):
            raise RuntimeError("RATTLE: Newton iteration for the link constraints did not converge")
        q, q_new = q_new, q
        p, p_new = p_new, p
        tip_x[step] = q[n - 1, 0]
        if step % sample_every == 0:
            _save(rows, k, q, p)
            energies[k] = energy(q, p, m, g)
            _links(q, d)
            for j in range(n):
                constraint = max(constraint, abs(np.sqrt(d[j, 0] ** 2 + d[j, 1] ** 2) - a))
            k += 1
    final = np.empty((1, 4 * n))
    _save(final, 0, q, p)
    return rows[:k], final[0], tip_x, energies[:k], constraint


def positions_from_angles(angles, a):
    """Hanging chain: link j makes angle theta_j with the downward vertical."""
    angles = np.asarray(angles, float)
    steps = a * np.column_stack([np.sin(angles), -np.cos(angles)])
    return np.cumsum(steps, axis=0)


def crossing_frequency(signal, h):
    """Angular frequency from upward zero crossings (linear interpolation) of a periodic signal."""
    s = np.asarray(signal)
    idx = np.nonzero((s[:-1] < 0) & (s[1:] >= 0))[0]
    if idx.size < 2:
        raise ValueError("fewer than two upward zero crossings: integrate longer")
    t = (idx + s[idx] / (s[idx] - s[idx + 1])) * h
    periods = (t[-1] - t[0]) / (idx.size - 1)
    return 2 * np.pi / periods, idx.size - 1
