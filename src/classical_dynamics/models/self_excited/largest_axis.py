"""Torque along the largest axis (Lee §2): Euler's equations, the reduction to the plane (2.10), and that
plane's singular points, separatrices, invariants and limit cycles.

Lee's notation (thesis §2.1): principal moments A > B > C, inertia numbers a = (B - C)/A,
b = (A - C)/B, c = (A - B)/C (all positive, and a - b + c = abc), body rates (p, q, r).

Torque along the largest axis x (§2), of component M + mu0 |omega|^2: with m = M/A, mu = mu0/A,

    p' - a q r = m + mu |omega|^2,    q' + b r p = 0,    r' - c p q = 0,

the end of omega stays on the elliptic cylinder q^2/b + r^2/c = delta^2, and with
    R = sqrt(a^2 bc + mu^2 (b - c)^2),  sigma1 = arctan(mu (b - c)/(a sqrt(bc))),
    d = delta^2 sqrt(bc) R / 2,  phi1 = atan2(r/sqrt(c), q/sqrt(b)),  phi2 = 2 phi1 + sigma1,
    tau = sqrt(2d) t,  p1 = 2 sqrt(bc) p / sqrt(2d),
the motion reduces to the plane system (2.10)
    dp1/dtau = m1 + sin(phi2) + mu1 p1^2,  dphi2/dtau = p1,
    m1 = (2m + mu delta^2 (b + c)) / (delta^2 R),  mu1 = mu / (2 sqrt(bc)).
(The digest rebuilt these normalisations from OCR fragments; the tests check them against the full
equations, which is the point of the overlay in every portrait.)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...solvers.runge_kutta import rhs_function
from ...solvers.symplectic import accel_function
from .body import Body, InertiaNumbers


@dataclass(frozen=True)
class LargestAxis:
    """The §2 reduction for one elliptic cylinder (delta) of one body under m + mu |omega|^2 along x (body: a
    Body, or its swapped numbers with the state (r, q, p) for a torque along the smallest axis)."""

    body: Body | InertiaNumbers
    m: float
    mu: float
    delta: float

    @classmethod
    def with_plane_parameters(cls, body: Body, m1: float, mu1: float, delta: float) -> "LargestAxis":
        """The physical torque (m, mu) that gives the plane parameters (m1, mu1) on the cylinder delta."""
        b, c = body.b, body.c
        mu = 2.0 * np.sqrt(b * c) * mu1
        R = np.sqrt(body.a**2 * b * c + mu**2 * (b - c) ** 2)
        m = 0.5 * (m1 * delta**2 * R - mu * delta**2 * (b + c))
        return cls(body, m, mu, delta)

    @classmethod
    def for_scene(cls, body: Body, m1: float | None, mu1: float, delta: float) -> "LargestAxis":
        """A scene's reduction: the plane's m1 when it lists body_torque, else no constant torque (m = 0), and
        m1 follows from mu1 and the cylinder."""
        if m1 is None:
            return cls(body, 0.0, 2.0 * np.sqrt(body.b * body.c) * mu1, delta)
        return cls.with_plane_parameters(body, m1, mu1, delta)

    @property
    def R(self) -> float:
        b, c = self.body.b, self.body.c
        return np.sqrt(self.body.a**2 * b * c + self.mu**2 * (b - c) ** 2)

    @property
    def sigma1(self) -> float:
        b, c = self.body.b, self.body.c
        return np.arctan(self.mu * (b - c) / (self.body.a * np.sqrt(b * c)))

    @property
    def d(self) -> float:
        b, c = self.body.b, self.body.c
        return 0.5 * self.delta**2 * np.sqrt(b * c) * self.R

    @property
    def time_scale(self) -> float:
        """tau = time_scale * t."""
        return np.sqrt(2.0 * self.d)

    @property
    def m1(self) -> float:
        b, c = self.body.b, self.body.c
        return (2.0 * self.m + self.mu * self.delta**2 * (b + c)) / (self.delta**2 * self.R)

    @property
    def mu1(self) -> float:
        return self.mu / (2.0 * np.sqrt(self.body.b * self.body.c))

    def euler_parameters(self) -> np.ndarray:
        return np.array([self.body.a, self.body.b, self.body.c, self.m, self.mu])

    def to_plane(self, w: np.ndarray, phi2_start: float | None = None) -> np.ndarray:
        """Rows (p, q, r) -> rows (phi2, p1), phi2 continuous along the rows (the inverse map).

        (q, r) fix phi1 only modulo 2 pi, so phi2 modulo 4 pi: phi2_start picks the branch (the plane is not
        periodic in phi2 when m1 != 0 or mu1 != 0, so the branch matters)."""
        w = np.atleast_2d(w)
        b, c = self.body.b, self.body.c
        phi1 = np.unwrap(np.arctan2(w[:, 2] / np.sqrt(c), w[:, 1] / np.sqrt(b)))
        phi2 = 2.0 * phi1 + self.sigma1
        if phi2_start is not None:
            phi2 += 4.0 * np.pi * np.round((phi2_start - phi2[0]) / (4.0 * np.pi))
        return np.column_stack([phi2, 2.0 * np.sqrt(b * c) * w[:, 0] / self.time_scale])

    def from_plane(self, phi2: float, p1: float) -> np.ndarray:
        """(phi2, p1) -> (p, q, r) on this cylinder."""
        b, c = self.body.b, self.body.c
        phi1 = 0.5 * (phi2 - self.sigma1)
        return np.array(
            [
                self.time_scale * p1 / (2.0 * np.sqrt(b * c)),
                self.delta * np.sqrt(b) * np.cos(phi1),
                self.delta * np.sqrt(c) * np.sin(phi1),
            ]
        )


def cylinder(body: Body, w: np.ndarray) -> np.ndarray:
    """delta^2 = q^2/b + r^2/c of rows (p, q, r): constant for any torque along x."""
    w = np.atleast_2d(w)
    return w[:, 1] ** 2 / body.b + w[:, 2] ** 2 / body.c


@rhs_function
def euler_largest(t, w, p, out):
    """Lee (2.2): p' = a q r + m + mu |w|^2, q' = -b r p, r' = c p q; p = (a, b, c, m, mu)."""
    out[0] = p[0] * w[1] * w[2] + p[3]
    if p[4] != 0.0:  # the quadratic torque, only when the scene lists it
        out[0] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]


@rhs_function
def euler_largest_phase(t, w, p, out):
    """Lee (2.2) with Lee's auxiliary angle beside it, w = (p, q, r, phi), d phi = p dt; p = (a, b, c, m, mu,
    ...)."""
    out[0] = p[0] * w[1] * w[2] + p[3]
    if p[4] != 0.0:
        out[0] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]
    out[3] = w[0]


@rhs_function
def euler_largest_attitude(t, w, p, out):
    """Lee (2.2) and the attitude: w = (p, q, r, e0, e1, e2, e3), the unit quaternion e turning body vectors
    into space, de/dt = e * (0, omega)/2; p = (a, b, c, m, mu)."""
    out[0] = p[0] * w[1] * w[2] + p[3]
    if p[4] != 0.0:
        out[0] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]
    e0, e1, e2, e3, x, y, z = w[3], w[4], w[5], w[6], w[0], w[1], w[2]
    out[3] = 0.5 * (-e1 * x - e2 * y - e3 * z)
    out[4] = 0.5 * (e0 * x + e2 * z - e3 * y)
    out[5] = 0.5 * (e0 * y + e3 * x - e1 * z)
    out[6] = 0.5 * (e0 * z + e1 * y - e2 * x)


@rhs_function
def plane_largest(t, y, p, out):
    """Lee (2.10) in y = (phi2, p1), time tau; p = (m1, mu1, direction): direction -1 runs time backward."""
    out[0] = p[2] * y[1]
    out[1] = p[2] * (p[0] + np.sin(y[0]))
    if p[1] != 0.0:
        out[1] += p[2] * p[1] * y[1] * y[1]


@accel_function
def plane_largest_force(q, p, out):
    """The unperturbed (2.10) as phi2'' = a(phi2) = m1 + sin(phi2), p = (m1,), for stormer-verlet."""
    out[0] = p[0] + np.sin(q[0])


@rhs_function
def plane_by_phase(phi2, y, p, out):
    """(2.10) with phi2 as the clock, y = (tau, p1), p = (m1, mu1): for motions with p1 of one sign."""
    out[0] = 1.0 / y[1]
    out[1] = (p[0] + np.sin(phi2) + p[1] * y[1] * y[1]) / y[1]


# --- singular points, separatrices and invariants of the plane (2.10) ----------------------------------
def singular_points(m1: float, mu1: float, phi_min: float, phi_max: float) -> list[dict]:
    """sin(phi2) = -m1, p1 = 0, in [phi_min, phi_max], typed by the linearization: the Jacobian
    [[0, 1], [cos phi2, 0]] (the mu1 p1^2 term is second order) has eigenvalues +-sqrt(cos phi2): a saddle
    if cos > 0, a center if cos < 0 (a true center even with mu1 != 0: the system is reversible under
    p1 -> -p1, tau -> -tau), degenerate (a cusp) if |m1| = 1. None if |m1| > 1."""
    if abs(m1) > 1.0:
        return []
    theta = np.arcsin(-m1)
    points = []
    for base, kind in ((theta, "saddle"), (np.pi - theta, "center")):
        if abs(abs(m1) - 1.0) < 1e-12:
            kind = "degenerate"
        k0, k1 = int(np.floor((phi_min - base) / (2 * np.pi))), int(np.ceil((phi_max - base) / (2 * np.pi)))
        for k in range(k0, k1 + 1):
            phi = base + 2 * np.pi * k
            if phi_min <= phi <= phi_max:
                points.append({"phi2": float(phi), "p1": 0.0, "type": kind})
    unique = {round(pt["phi2"], 12): pt for pt in points}  # at |m1| = 1 the pairs coincide
    return [unique[k] for k in sorted(unique)]


def energy(y: np.ndarray, m1: float) -> np.ndarray:
    """E = p1^2/2 - m1 phi2 + cos phi2, constant when mu1 = 0."""
    y = np.atleast_2d(y)
    return 0.5 * y[:, 1] ** 2 - m1 * y[:, 0] + np.cos(y[:, 0])


def lee_c1(y: np.ndarray, m1: float, mu1: float) -> np.ndarray:
    """C1 of (2.13), constant when mu1 != 0: e^{-2 mu1 phi2}[p1^2 + m1/mu1 + 2(2 mu1 sin + cos)/(1 + 4
    mu1^2)]."""
    y = np.atleast_2d(y)
    phi, p1 = y[:, 0], y[:, 1]
    return np.exp(-2 * mu1 * phi) * (
        p1**2 + m1 / mu1 + 2 * (2 * mu1 * np.sin(phi) + np.cos(phi)) / (1 + 4 * mu1**2)
    )


def invariant_spread(y: np.ndarray, m1: float, mu1: float) -> float:
    """Spread of E (mu1 = 0) or C1 along rows y, relative to the size of the terms that make it up (either
    may be near zero on a particular trajectory, where a relative spread would mean nothing)."""
    y = np.atleast_2d(y)
    phi, p1 = y[:, 0], y[:, 1]
    if mu1 == 0.0:
        values = energy(y, m1)
        size = 0.5 * p1**2 + abs(m1 * phi) + 1.0
    else:
        values = lee_c1(y, m1, mu1)
        size = np.exp(-2 * mu1 * phi) * (p1**2 + abs(m1 / mu1) + 2 * (2 * abs(mu1) + 1) / (1 + 4 * mu1**2))
    return float(np.ptp(values) / np.max(size))


def separatrix_p1_squared(phi: np.ndarray, m1: float, mu1: float, phi_saddle: float) -> np.ndarray:
    """p1^2 along the curves through the saddle at phi_saddle: (2.23) for mu1 = 0, (2.13) with C1 fixed by
    p1 = 0 at the saddle otherwise. Negative values mark where the curve does not exist."""
    if mu1 == 0.0:
        return 2.0 * (m1 * (phi - phi_saddle) - np.cos(phi) + np.cos(phi_saddle))
    g = lambda x: -m1 / mu1 - 2.0 * (2 * mu1 * np.sin(x) + np.cos(x)) / (1 + 4 * mu1**2)
    C1 = -g(phi_saddle) * np.exp(-2 * mu1 * phi_saddle)
    return C1 * np.exp(2 * mu1 * phi) + g(phi)


def limit_cycle_p1(phi: np.ndarray, m1: float, nu: float) -> np.ndarray | None:
    """F (+) of (2.30) for mu1 = -nu < 0: p1 = sqrt(m1/nu + 2 sin(phi2 + sigma3)/sqrt(1 + 4 nu^2)),
    sigma3 = arctan(-1/(2 nu)); F1 is its mirror. None when the radicand is not positive everywhere."""
    if nu <= 0.0 or not m1 / nu > 2.0 / np.sqrt(1 + 4 * nu**2):
        return None
    sigma3 = np.arctan(-1.0 / (2.0 * nu))
    return np.sqrt(m1 / nu + 2.0 * np.sin(phi + sigma3) / np.sqrt(1 + 4 * nu**2))


def series_period(m1: float, nu: float, eta: float) -> float:
    """Lee §4.2: the period in tau of the oscillation about the center of (2.10) (mu1 = -nu) started at
    phi2c + eta with p1 = 0, T = 2 pi (1 - m1^2)^(-1/4) (1 + h2 eta^2 + h3 eta^3), from the Lyapunov system
    (4.1) with k^2 = sqrt(1 - m1^2), beta2 = m1, beta3 = sqrt(1 - m1^2), mu1 = -nu and (4.6)-(4.8)."""
    k2 = np.sqrt(1.0 - m1**2)
    beta2, beta3, mu1 = m1, k2, -nu
    h2 = (5 * beta2**2 + 10 * beta2 * k2 * mu1 + 3 * beta3 * k2 + 8 * k2**2 * mu1**2) / (48 * k2**2)
    h3 = -(beta2 + 4 * k2 * mu1) / (3 * k2) * h2
    return 2.0 * np.pi / np.sqrt(k2) * (1.0 + h2 * eta**2 + h3 * eta**3)


def limit_cycle_period(m1: float, nu: float) -> float:
    """The tau-period of p1 on F in Jacobi's form (digest §2.5): alpha = m1/nu, beta = 2/sqrt(1 + 4 nu^2),
    k^2 = 2 beta/(alpha + beta), p1 = sqrt(alpha + beta) dn(u, k), u = u0 - tau sqrt(alpha + beta)/2, so the
    period is 4 K(k)/sqrt(alpha + beta). omega's own period is twice that."""
    from scipy.special import ellipk

    alpha, beta = m1 / nu, 2.0 / np.sqrt(1.0 + 4.0 * nu**2)
    return 4.0 * ellipk(2.0 * beta / (alpha + beta)) / np.sqrt(alpha + beta)


def nu_star(m1: float) -> float:
    """The drag at which the limit cycles F, F1 vanish (0 < m1 < 1): m1 / (2 sqrt(1 - m1^2))."""
    return m1 / (2.0 * np.sqrt(1.0 - m1**2))


@rhs_function
def euler_largest_angles(t, w, p, out):
    """Lee (2.2) and the kinematic equations (1.2) solved for the angles: w = (p, q, r, psi, theta, phi)."""
    out[0] = p[0] * w[1] * w[2] + p[3]
    if p[4] != 0.0:
        out[0] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]
    s, c = np.sin(w[5]), np.cos(w[5])
    out[3] = (w[0] * s + w[1] * c) / np.sin(w[4])
    out[4] = w[0] * c - w[1] * s
    out[5] = w[2] - out[3] * np.cos(w[4])
