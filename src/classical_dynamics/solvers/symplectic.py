"""Stormer-Verlet for separable systems q'' = a(q) (compiled), and Yoshida's fourth-order composition.

Symplectic and time-reversible: the energy error of a fixed step stays bounded over long times.
The acceleration is a numba function a(q, p, out), compiled by `accel_function`. Constrained chains use
rattle.py. The loop here is the kernel of the methods "stormer-verlet" and "yoshida4": call them through
fixed_step.solve_fixed.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types

from .rigid_body import YOSHIDA

F64, I64, VEC = types.float64, types.int64, types.float64[::1]
ACCEL_SIG = types.void(VEC, VEC, VEC)  # accel(q, p, out)
# The acceleration reaches the loop as a first-class function typed by its signature, so the loop is compiled
# once and cached on disk for every acceleration. Typed by the dispatcher itself, it would be keyed by that
# dispatcher's identity: a new cache entry in every process, an index that grows without end (130 entries
# were seen), and at last numba failing to save it ("underlying object has vanished").
ACCEL = types.FunctionType(ACCEL_SIG)


def accel_function(func):
    """Compile a(q, p, out) for the Stormer-Verlet methods (cached on disk)."""
    return njit(ACCEL_SIG, cache=True)(func)


@njit((ACCEL, VEC, VEC, VEC, F64, VEC), cache=True)
def _verlet(accel, p, q, v, h, a):
    for j in range(q.size):
        v[j] += 0.5 * h * a[j]
        q[j] += h * v[j]
    accel(q, p, a)
    for j in range(q.size):
        v[j] += 0.5 * h * a[j]


@njit(cache=True)
def _save(out, base, q, v):
    """out[base:base + 2d] <- (q, v)."""
    d = q.size
    for j in range(d):
        out[base + j] = q[j]
        out[base + d + j] = v[j]


@njit((ACCEL, VEC, VEC, VEC, F64, I64, I64, I64), cache=True)
def integrate(accel, p, q0, v0, h, n_steps, order, sample_every):
    """The kernel: the rows of the state (q, v) at steps 0, sample_every, 2 sample_every, ...; the final
    state. The rows go into one flat buffer, written in the loop itself: through a 2-d array, or through a
    call to _save, saving at every step cost a quarter more per step on a one-degree-of-freedom problem
    (numba does not inline the call; benchmarks/solver_speed.py --against)."""
    q, v = q0.copy(), v0.copy()
    a = np.empty_like(q)
    accel(q, p, a)
    weights = np.array([1.0]) if order == 2 else np.array([YOSHIDA[0], YOSHIDA[1], YOSHIDA[0]])
    n_samples = n_steps // sample_every + 1
    width = 2 * q.size
    out = np.empty(n_samples * width)
    _save(out, 0, q, v)
    k = 1
    for i in range(1, n_steps + 1):
        for w in weights:
            _verlet(accel, p, q, v, w * h, a)
        if i % sample_every == 0:
            base = k * width
            for j in range(q.size):  # written out here, not by _save: see above
                out[base + j] = q[j]
                out[base + q.size + j] = v[j]
            k += 1
    final = np.empty(width)
    _save(final, 0, q, v)
    return out.reshape((n_samples, width))[:k], final
