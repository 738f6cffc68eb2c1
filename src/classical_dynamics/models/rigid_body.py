"""Right-hand sides of rigid-body and test problems, compiled: f(t, y, p, out)."""

from __future__ import annotations

import math

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


@rhs_function
def free_attitude_matrix(t, y, p, out):
    """Euler's equations and the attitude as a matrix: y = (omega_body, R by rows), R taking body vectors to
    space, so R' = R W with W the cross-product matrix of omega; p = (A, B, C)."""
    A, B, C = p[0], p[1], p[2]
    w0, w1, w2 = y[0], y[1], y[2]
    out[0] = (B - C) * w1 * w2 / A
    out[1] = (C - A) * w2 * w0 / B
    out[2] = (A - B) * w0 * w1 / C
    for i in range(3):  # row i of R W, W = [[0, -w2, w1], [w2, 0, -w0], [-w1, w0, 0]]
        r0, r1, r2 = y[3 + 3 * i], y[4 + 3 * i], y[5 + 3 * i]
        out[3 + 3 * i] = r1 * w2 - r2 * w1
        out[4 + 3 * i] = -r0 * w2 + r2 * w0
        out[5 + 3 * i] = r0 * w1 - r1 * w0


@rhs_function
def axis_component(t, y, p, out):
    """The event: the third body component of omega passes zero."""
    out[0] = y[2]


@rhs_function
def distant_attraction(t, y, p, out):
    """Lamb Ex. VI.4: a body turning under a distant mass fixed in space, I w' = Iw x w + k s x Is with
    s' = s x w the unit direction of the mass seen from the body; y = (w, s), p = (I1, I2, I3), k = 1."""
    I1, I2, I3 = p[0], p[1], p[2]
    w1, w2, w3, s1, s2, s3 = y[0], y[1], y[2], y[3], y[4], y[5]
    out[0] = (I2 - I3) * (w2 * w3 - s2 * s3) / I1
    out[1] = (I3 - I1) * (w3 * w1 - s3 * s1) / I2
    out[2] = (I1 - I2) * (w1 * w2 - s1 * s2) / I3
    out[3] = s2 * w3 - s3 * w2
    out[4] = s3 * w1 - s1 * w3
    out[5] = s1 * w2 - s2 * w1


@rhs_function
def heavy_top_euler_angles(t, z, p, out):
    """The heavy symmetric top in Euler angles and their momenta, z = (theta, phi, psi, p_theta, p_phi,
    p_psi), p = (A, C, Mgh): Hamilton's equations (Lamb Art. 107), independent of the body-frame model."""
    A, C, Mgh = p[0], p[1], p[2]
    th, p_th, p_ph, p_ps = z[0], z[3], z[4], z[5]
    s, c = math.sin(th), math.cos(th)
    u = p_ph - p_ps * c
    dphi = u / (A * s * s)
    out[0] = p_th / A
    out[1] = dphi
    out[2] = p_ps / C - c * dphi
    out[3] = -(u * p_ps / (A * s) - u * u * c / (A * s**3)) + Mgh * s
    out[4] = 0.0
    out[5] = 0.0


@rhs_function
def euler_free_many(t, y, p, out):
    """Euler's equations for many free bodies of the same moments p = (A, B, C) as one system:
    y = (p_1..p_m, q_1..q_m, r_1..r_m)."""
    A, B, C = p[0], p[1], p[2]
    m = y.size // 3
    for i in range(m):
        w0, w1, w2 = y[i], y[m + i], y[2 * m + i]
        out[i] = (B - C) * w1 * w2 / A
        out[m + i] = (C - A) * w2 * w0 / B
        out[2 * m + i] = (A - B) * w0 * w1 / C


@rhs_function
def retarded_euler(t, w, p, out):
    """p = (A/C, kappa/C): Euler's equations of the symmetric body with the couple -kappa omega (C = 1)."""
    a, k = p[0], p[1]
    out[0] = ((a - 1.0) * w[1] * w[2] - k * w[0]) / a
    out[1] = ((1.0 - a) * w[2] * w[0] - k * w[1]) / a
    out[2] = -k * w[2]
