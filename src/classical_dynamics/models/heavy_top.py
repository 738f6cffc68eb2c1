"""The heavy symmetric top in the body frame, and its closed forms (the solvers study's
studies/solvers/heavy_top.py checks them).

Moments A, A, C about the fixed point, centre of gravity at h on the figure axis e3, weight Mg. The state is

    y = (omega_1, omega_2, omega_3,  gamma_1, gamma_2, gamma_3,  xi_1, xi_2, xi_3)

with omega the body angular velocity, gamma the upward vertical and xi a horizontal axis fixed in space, both
in body components. Euler's equations with the gravity couple N = Mgh (gamma_2, -gamma_1, 0), and for any
vector fixed in space v' = v x omega:

    A omega_1' = (A - C) omega_2 omega_3 + Mgh gamma_2,   A omega_2' = (C - A) omega_3 omega_1 - Mgh gamma_1,
    C omega_3' = 0.

Nothing is singular at the vertical (the sleeping top), unlike Euler's angles. Euler's angles (z-x-z: azimuth
phi of the axis, inclination theta, spin angle psi) are read back: gamma = (sin theta sin psi, sin theta cos
psi, cos theta), the axis in space k = (sin phi sin theta, -cos phi sin theta, cos theta).

The closed forms (lecture notes' names; Lamb writes psi for the azimuth, A omega^2 cos alpha - C n omega + Mgh
= 0) follow from the integrals J3 = C omega_3, Jz = A sin^2 theta phi' + J3 cos theta and E, with u = cos
theta:

    u'^2 = f(u) = (1 - u^2)(2/A)(E - J3^2/2C - Mgh u) - (Jz - J3 u)^2/A^2 = (2Mgh/A)(u - u1)(u - u2)(u - u3),

u(t) = u1 + (u2 - u1) sn^2(lambda t + t0 | m), lambda^2 = Mgh (u3 - u1)/(2A), m = (u2 - u1)/(u3 - u1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import integrate, optimize, special

from ..scenes import EffectRegistry
from ..solvers.runge_kutta import rhs_function

EFFECTS = EffectRegistry("solvers")


@EFFECTS.register(
    "gravity",
    "torque",
    "the weight $Mg$ at a height $h$ on the figure axis: the couple "
    "$Mgh\\,\\boldsymbol\\gamma \\times \\hat e_3$ about the fixed point (the heavy top)",
)
def _gravity(params, context):
    return float(params["Mgh"])


@rhs_function
def top_gravity(t, y, p, out):
    """The heavy symmetric top, p = (A, C, Mgh)."""
    A, C, mgh = p[0], p[1], p[2]
    w1, w2, w3 = y[0], y[1], y[2]
    out[0] = ((A - C) * w2 * w3 + mgh * y[4]) / A
    out[1] = ((C - A) * w3 * w1 - mgh * y[3]) / A
    out[2] = 0.0
    for k in (3, 6):
        out[k] = y[k + 1] * w3 - y[k + 2] * w2
        out[k + 1] = y[k + 2] * w1 - y[k] * w3
        out[k + 2] = y[k] * w2 - y[k + 1] * w1


@rhs_function
def apse(t, y, p, out):
    """theta' sin theta = omega_1 gamma_2 - omega_2 gamma_1: zero at the apses of the nutation."""
    out[0] = y[0] * y[4] - y[1] * y[3]


APSE_EVENTS_N = 1


@rhs_function
def pole_particle(t, y, p, out):
    """Lamb Art. 55: the pole k on the unit sphere as a particle of mass A under gravity and the deviating
    force Cn k x v, y = (k, v), p = (A, J3, Mgh): A k'' = Mgh ((k.e_z) k - e_z) + J3 k x v + A mu k.

    On the sphere the constraint force is mu = -|v|^2; off it (rounding) the unconstrained form drifts away
    exponentially, so mu also damps c = (|k|^2 - 1)/2 as c'' + 2c' + c = 0 (Baumgarte), which changes nothing
    on the sphere itself."""
    A, J3, mgh = p[0], p[1], p[2]
    k0, k1, k2, v0, v1, v2 = y[0], y[1], y[2], y[3], y[4], y[5]
    a0 = (mgh * k2 * k0 + J3 * (k1 * v2 - k2 * v1)) / A
    a1 = (mgh * k2 * k1 + J3 * (k2 * v0 - k0 * v2)) / A
    a2 = (mgh * (k2 * k2 - 1.0) + J3 * (k0 * v1 - k1 * v0)) / A
    kk = k0 * k0 + k1 * k1 + k2 * k2
    kv = k0 * v0 + k1 * v1 + k2 * v2
    mu = -(v0 * v0 + v1 * v1 + v2 * v2 + k0 * a0 + k1 * a1 + k2 * a2 + 2.0 * kv + 0.5 * (kk - 1.0)) / kk
    out[0] = v0
    out[1] = v1
    out[2] = v2
    out[3] = a0 + mu * k0
    out[4] = a1 + mu * k1
    out[5] = a2 + mu * k2


@dataclass(frozen=True)
class Top:
    A: float
    C: float
    Mgh: float

    rhs = staticmethod(top_gravity)

    @property
    def params(self):
        return np.array([self.A, self.C, self.Mgh])

    def state(self, theta, theta_dot, phi_dot, omega3, phi=0.0, psi=0.0):
        """The body-frame state from Euler's angles and rates (spin omega_3 = psi' + phi' cos theta)."""
        st, sp, cp = np.sin(theta), np.sin(psi), np.cos(psi)
        w = [phi_dot * st * sp + theta_dot * cp, phi_dot * st * cp - theta_dot * sp, omega3]
        R = rotation(phi, theta, psi)
        return np.array(w + list(R[2, :]) + list(R[0, :]))  # e_z and e_x in body components

    def integrals(self, y):
        """(J3, Jz, E) of states y (rows)."""
        y = np.atleast_2d(y)
        w, g = y[:, :3], y[:, 3:6]
        J3 = self.C * w[:, 2]
        Jz = self.A * (w[:, 0] * g[:, 0] + w[:, 1] * g[:, 1]) + J3 * g[:, 2]
        E = 0.5 * self.A * (w[:, 0] ** 2 + w[:, 1] ** 2) + 0.5 * self.C * w[:, 2] ** 2 + self.Mgh * g[:, 2]
        return J3, Jz, E


def rotation(phi, theta, psi):
    """Body to space, z-x-z: Rz(phi) Rx(theta) Rz(psi)."""

    def rz(a):
        return np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])

    rx = np.array(
        [[1.0, 0.0, 0.0], [0.0, np.cos(theta), -np.sin(theta)], [0.0, np.sin(theta), np.cos(theta)]]
    )
    return rz(phi) @ rx @ rz(psi)


def angles(y):
    """Euler's angles (theta, phi, psi) of body-frame states (rows); phi and psi unwrapped along the rows."""
    y = np.atleast_2d(y)
    g, xi = y[:, 3:6], y[:, 6:9]
    theta = np.arctan2(np.hypot(g[:, 0], g[:, 1]), g[:, 2])
    kx = xi[:, 2]
    ky = g[:, 0] * xi[:, 1] - g[:, 1] * xi[:, 0]  # (e_z x e_x) . e3 = e_y . e3
    phi = np.unwrap(np.arctan2(kx, -ky))
    psi = np.unwrap(np.arctan2(g[:, 0], g[:, 1]))
    return theta, phi, psi


def axis_in_space(y):
    """The figure axis k in space components, rows."""
    y = np.atleast_2d(y)
    g, xi = y[:, 3:6], y[:, 6:9]
    return np.stack([xi[:, 2], g[:, 0] * xi[:, 1] - g[:, 1] * xi[:, 0], g[:, 2]], axis=1)


def rates(top: Top, y):
    """phi' and psi' read from the body rates and the vertical (Euler's kinematic equations)."""
    y = np.atleast_2d(y)
    w, g = y[:, :3], y[:, 3:6]
    phi_dot = (w[:, 0] * g[:, 0] + w[:, 1] * g[:, 1]) / (1.0 - g[:, 2] ** 2)
    return phi_dot, w[:, 2] - phi_dot * g[:, 2]


# --- closed forms ------------------------------------------------------------------------------------------
def steady_roots(A, J3, Mgh, alpha):
    """The two rates of steady precession at inclination alpha, A w^2 cos a - J3 w + Mgh = 0 (Lamb Art. 54
    (8)), each root in the form that does not cancel: (slow, fast); None below the threshold J3^2 < 4 A Mgh
    cos a."""
    c = np.cos(alpha)
    disc = J3 * J3 - 4.0 * A * Mgh * c
    if disc < 0:
        return None
    q = 0.5 * (J3 + np.copysign(np.sqrt(disc), J3))
    slow = Mgh / q  # = 2 Mgh / (J3 + sqrt(disc))
    fast = q / (A * c) if c != 0 else np.inf
    return slow, fast


def nutation_frequency(A, J3, alpha, omega):
    """Lamb Art. 57 (13): sigma^2 = omega^2 sin^2 alpha + (J3 - 2 A omega cos alpha)^2 / A^2."""
    return np.sqrt(omega**2 * np.sin(alpha) ** 2 + (J3 - 2 * A * omega * np.cos(alpha)) ** 2 / A**2)


@dataclass(frozen=True)
class Nutation:
    """The motion in u = cos theta from the integrals alone: the roots u1 < u2 < u3 of f, its period and the
    azimuth advanced between apses (the apsidal angle), by elliptic functions and quadrature."""

    u1: float
    u2: float
    u3: float
    period: float
    lam: float
    m: float
    A: float
    J3: float
    Jz: float
    Mgh: float

    @classmethod
    def from_integrals(cls, A, C, Mgh, J3, Jz, E):
        Ep = E - 0.5 * J3 * J3 / C

        def f(u):
            return (1 - u * u) * 2.0 / A * (Ep - Mgh * u) - (Jz - J3 * u) ** 2 / A**2

        coefficients = [
            2 * Mgh / A,
            -2 * Ep / A - J3 * J3 / A**2,
            -2 * Mgh / A + 2 * Jz * J3 / A**2,
            2 * Ep / A - Jz * Jz / A**2,
        ]
        guess = np.sort(np.roots(coefficients).real)
        roots = []
        for r in guess:  # polish each root on a bracket of its own
            width = 1e-6 * max(1.0, abs(r))
            lo, hi = r - width, r + width
            while f(lo) * f(hi) > 0 and width < 1:
                width *= 4
                lo, hi = r - width, r + width
            roots.append(
                optimize.brentq(f, lo, hi, xtol=1e-16, rtol=4 * np.finfo(float).eps, maxiter=200)
                if f(lo) * f(hi) <= 0
                else r
            )
        u1, u2, u3 = roots
        lam = np.sqrt(Mgh * (u3 - u1) / (2 * A))
        m = (u2 - u1) / (u3 - u1)
        period = 2 * special.ellipk(m) / lam
        return cls(u1, u2, u3, period, lam, m, A, J3, Jz, Mgh)

    def apsidal_angle(self) -> float:
        """The azimuth advanced from one apse to the next: the integral of phi'/u' du from u1 to u2, with
        u = u1 + (u2 - u1) sin^2 s taking out the square-root ends."""
        A, J3, Jz, Mgh, u1, u2, u3 = self.A, self.J3, self.Jz, self.Mgh, self.u1, self.u2, self.u3

        def advance(s):
            u = u1 + (u2 - u1) * np.sin(s) ** 2
            return (Jz - J3 * u) / (A * (1 - u * u)) * 2.0 / np.sqrt(2 * Mgh / A * (u3 - u))

        return integrate.quad(advance, 0.0, np.pi / 2, epsabs=1e-14, epsrel=1e-13, limit=200)[0]

    def cos_theta(self, t, u0):
        """u(t) from the apse u0 (u1 or u2) at t = 0."""
        from ..solvers.references import ellipj

        K = special.ellipk(self.m)
        shift = 0.0 if abs(u0 - self.u1) < abs(u0 - self.u2) else K
        sn = ellipj(self.lam * np.asarray(t, float) + shift, self.m)[0]
        return self.u1 + (self.u2 - self.u1) * sn * sn
