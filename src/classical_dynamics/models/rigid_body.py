"""Right-hand sides of rigid-body and test problems, compiled: f(t, y, p, out)."""

from __future__ import annotations

import numpy as np

from ..solvers.runge_kutta import rhs_function


def euler_coefficients(I) -> np.ndarray:
    """The parameters of euler_free: ((I2 - I3)/I1, (I3 - I1)/I2, (I1 - I2)/I3).

    Computed once: three divisions at every evaluation cost more than all the rest of a DOP853 step
    on this three-component system (measured: 168 against 115 us for the HNW body at rtol 1e-10).
    """
    I1, I2, I3 = np.asarray(I, dtype=float)
    return np.array([(I2 - I3) / I1, (I3 - I1) / I2, (I1 - I2) / I3])


@rhs_function
def euler_free(t, w, p, out):
    """Euler's equations for the body angular velocity w, p = euler_coefficients(I)."""
    out[0] = p[0] * w[1] * w[2]
    out[1] = p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]


@rhs_function
def detest_b5(t, y, p, out):
    """DETEST B5 (Hull et al. 1972): y1' = y2 y3, y2' = -y1 y3, y3' = -0.51 y1 y2."""
    out[0] = y[1] * y[2]
    out[1] = -y[0] * y[2]
    out[2] = -0.51 * y[0] * y[1]


@rhs_function
def oscillator(t, y, p, out):
    """x'' = -omega^2 x as a first-order system, p = (omega,)."""
    out[0] = y[1]
    out[1] = -p[0] * p[0] * y[0]


@rhs_function
def riccati(t, y, p, out):
    """p' = m + mu p^2 (Lee 1964, eq. 2.4), p = (m, mu)."""
    out[0] = p[0] + p[1] * y[0] * y[0]


@rhs_function
def free_attitude(t, y, p, out):
    """Euler's equations and the attitude of a free body: y = (omega_body, q), p = (I1, I2, I3).

    q is the unit quaternion taking body vectors to space (v_space = q v q*), so q' = q (0, omega)/2."""
    w0, w1, w2 = y[0], y[1], y[2]
    out[0] = (p[1] - p[2]) / p[0] * w1 * w2
    out[1] = (p[2] - p[0]) / p[1] * w2 * w0
    out[2] = (p[0] - p[1]) / p[2] * w0 * w1
    a, b, c, d = y[3], y[4], y[5], y[6]
    out[3] = 0.5 * (-b * w0 - c * w1 - d * w2)
    out[4] = 0.5 * (a * w0 + c * w2 - d * w1)
    out[5] = 0.5 * (a * w1 - b * w2 + d * w0)
    out[6] = 0.5 * (a * w2 + b * w1 - c * w0)
