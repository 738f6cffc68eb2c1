"""Lamb's Ex. XIV.18, two particles revolving on a string, as compiled right-hand sides for the integrators.

Apart from models/chains.py, whose effects and geometry a scene's validation reads: that stays free of numba
(0.6 s to import with the compiled loops), which only the stability study's integration needs.
"""

from __future__ import annotations

import math

from ..solvers.runge_kutta import rhs_function


@rhs_function
def revolving_pair(t, z, p, out):
    """Lamb's Ex. XIV.18, two particles revolving on a string: Lagrange's equations in phi1 and
    psi = phi2 - phi1 (no difference of two large angles: psi is small), z = (phi1, psi, phi1', psi'),
    p = (M, m, a, b)."""
    M, m, a, b = p[0], p[1], p[2], p[3]
    d = -z[1]
    rate1, rate2 = z[2], z[2] + z[3]
    m11, m12, m22 = (M + m) * a * a, m * a * b * math.cos(d), m * b * b
    f1 = -m * a * b * math.sin(d) * rate2 * rate2
    f2 = m * a * b * math.sin(d) * rate1 * rate1
    det = m11 * m22 - m12 * m12  # the 2 x 2 mass matrix solved by Cramer's rule
    acc1, acc2 = (f1 * m22 - m12 * f2) / det, (m11 * f2 - m12 * f1) / det
    out[0] = z[2]
    out[1] = z[3]
    out[2] = acc1
    out[3] = acc2 - acc1


@rhs_function
def revolving_pair_crossing(t, z, p, out):
    """The event: psi = phi2 - phi1 passes zero (counted upward)."""
    out[0] = z[1]
