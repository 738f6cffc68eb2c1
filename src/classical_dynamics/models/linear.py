"""Linear systems of small oscillations, z' = A z + F cos(s t), as right-hand sides for the solvers.

The state matrix A of M q'' + B q' + K q = F cos(s t) (z = (q, q')) comes from the chains' matrices; the
packing puts A, F and s in the parameter vector the compiled integrators take. Optionally one more state
component integrates a quadratic form of the state, z^T W z (the work done against friction, 2F of Art. 96),
so that an energy balance is checked along the same steps as the motion.
"""

from __future__ import annotations

import math

import numpy as np

from ..solvers.runge_kutta import rhs_function
from ..solvers.symplectic import accel_function


def pack(A, force=None, s: float = 0.0, work=None) -> np.ndarray:
    """The parameters of `linear_system`: (m, s, with work, A by rows, F, W by rows). With `work` the state
    has m + 1 components, the last the integral of z^T W z."""
    A = np.asarray(A, dtype=float)
    m = A.shape[0]
    F = np.zeros(m) if force is None else np.asarray(force, dtype=float)
    W = np.zeros((m, m)) if work is None else np.asarray(work, dtype=float)
    head = [float(m), float(s), 0.0 if work is None else 1.0]
    return np.concatenate([head, A.ravel(), F, W.ravel()])


@rhs_function
def linear_system(t, y, p, out):
    """z' = A z + F cos(s t) for the first m components; with work, the last integrates z^T W z."""
    m = int(p[0])
    c = math.cos(p[1] * t)
    a, f, w = 3, 3 + m * m, 3 + m * m + m
    for i in range(m):
        total = p[f + i] * c
        for j in range(m):
            total += p[a + i * m + j] * y[j]
        out[i] = total
    if p[2] != 0.0:
        quadratic = 0.0
        for i in range(m):
            for j in range(m):
                quadratic += y[i] * p[w + i * m + j] * y[j]
        out[m] = quadratic


@accel_function
def harmonic_force(q, p, out):
    """q'' = -omega^2 q, p = (omega,): the oscillator as an acceleration, for the Stormer-Verlet methods."""
    out[0] = -p[0] * p[0] * q[0]


def state_matrix(K, M, B=None, G=None) -> np.ndarray:
    """M q'' + (B + G) q' + K q = 0 as z' = A z, z = (q, q'): the quadratic eigenproblem linearized (B the
    friction, G the gyroscopic terms, either may be absent)."""
    n = len(K)
    C = np.zeros((n, n)) if B is None else np.array(B, float)
    if G is not None:
        C = C + G
    return np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
