"""Stormer-Verlet for separable systems q'' = a(q) (compiled), and Yoshida's fourth-order composition.

Symplectic and time-reversible: the energy error of a fixed step stays bounded over long times.
The acceleration is a numba function a(q, p, out). Constrained chains use rattle.py. The loop here is the
kernel of the methods "stormer-verlet" and "yoshida4": call them through fixed_step.solve_fixed.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .rigid_body import YOSHIDA


@njit(cache=True)
def _verlet(accel, p, q, v, h, a):
    for j in range(q.size):
        v[j] += 0.5 * h * a[j]
        q[j] += h * v[j]
    accel(q, p, a)
    for j in range(q.size):
        v[j] += 0.5 * h * a[j]


@njit(cache=True)
def _save(rows, k, q, v):
    d = q.size
    for j in range(d):
        rows[k, j] = q[j]
        rows[k, d + j] = v[j]


@njit(cache=True)
def integrate(accel, p, q0, v0, h, n_steps, order, sample_every):
    """The kernel: the rows of the state (q, v) at steps 0, sample_every, 2 sample_every, ...; the final
    state."""
    q, v = q0.copy(), v0.copy()
    a = np.empty_like(q)
    accel(q, p, a)
    weights = np.array([1.0]) if order == 2 else np.array([YOSHIDA[0], YOSHIDA[1], YOSHIDA[0]])
    n_samples = n_steps // sample_every + 1
    rows = np.empty((n_samples, 2 * q.size))
    _save(rows, 0, q, v)
    k = 1
    for i in range(1, n_steps + 1):
        for w in weights:
            _verlet(accel, p, q, v, w * h, a)
        if i % sample_every == 0:
            _save(rows, k, q, v)
            k += 1
    final = np.empty(2 * q.size)
    final[: q.size], final[q.size :] = q, v
    return rows[:k], final
