"""The self-excited rigid body (Lee 1964): Euler's equations under a torque fixed in the body.

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
from numba import njit

from ..scenes import EffectRegistry
from ..solvers.runge_kutta import rhs_function

EFFECTS = EffectRegistry("self_excited")


@EFFECTS.register("body_torque", "torque", "a constant torque M along a principal axis, fixed in the body")
def _body_torque(params, context):
    return params


@EFFECTS.register(
    "quadratic_torque",
    "torque",
    "the torque's part mu0 |omega|^2 along the same axis (Lee's "
    "perturbation: negative mu0 is a drag-like self-regulation)",
)
def _quadratic_torque(params, context):
    return params


@EFFECTS.register(
    "drag",
    "medium",
    "a viscous medium's resisting torque, -mu1 (p, q) equatorial and -mu0 r axial (Lee §5; both or neither)",
)
def _drag(params, context):
    return params


@dataclass(frozen=True)
class Body:
    """Principal moments sorted so that A > B > C, and Lee's inertia numbers."""

    A: float
    B: float
    C: float

    @classmethod
    def from_moments(cls, moments) -> "Body":
        A, B, C = sorted((float(x) for x in moments), reverse=True)
        return cls(A, B, C)

    @property
    def a(self) -> float:
        return (self.B - self.C) / self.A

    @property
    def b(self) -> float:
        return (self.A - self.C) / self.B

    @property
    def c(self) -> float:
        return (self.A - self.B) / self.C

    def swapped(self) -> "InertiaNumbers":
        """Lee §2 for a torque along the smallest axis: the same reduction with p <-> r and a <-> c."""
        return InertiaNumbers(self.c, self.b, self.a)


@dataclass(frozen=True)
class InertiaNumbers:
    """(a, b, c) as the reductions use them; a Body's own, or swapped for the smallest axis."""

    a: float
    b: float
    c: float


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
def euler_smallest(t, w, p, out):
    """Lee (2.1) with the torque along z: p' = a q r, q' = -b r p, r' = c p q + m + mu |w|^2; p = (a, b, c, m,
    mu)."""
    out[0] = p[0] * w[1] * w[2]
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1] + p[3]
    if p[4] != 0.0:
        out[2] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])


@rhs_function
def euler_largest_yz(t, w, p, out):
    """Lee §2.6: the torque along x is M + mu0 (q^2 + r^2): p' = a q r + m + mu (q^2 + r^2); p = (a, b, c, m,
    mu). q and r obey (2.5) as before, and p the conservative plane (2.8) (mu1 = 0) with the same m1."""
    out[0] = p[0] * w[1] * w[2] + p[3] + p[4] * (w[1] * w[1] + w[2] * w[2])
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]


@rhs_function
def euler_grammel(t, w, p, out):
    """Lee §2.6, Grammel's torque M - mu0 p^2 along x: p' = a q r + m - mu p^2; p = (a, b, c, m, mu), mu > 0.
    It reduces to the plane (2.25) with sigma1 = 0, mu1 = -mu/(2 sqrt(bc)), m1 = 2m/(delta^2 a sqrt(bc))."""
    out[0] = p[0] * w[1] * w[2] + p[3] - p[4] * w[0] * w[0]
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]


@rhs_function
def plane_largest(t, y, p, out):
    """Lee (2.10) in y = (phi2, p1), time tau; p = (m1, mu1, direction): direction -1 runs time backward."""
    out[0] = p[2] * y[1]
    out[1] = p[2] * (p[0] + np.sin(y[0]))
    if p[1] != 0.0:
        out[1] += p[2] * p[1] * y[1] * y[1]


@njit(cache=True)
def plane_largest_force(q, p, out):
    """The unperturbed (2.10) as phi2'' = a(phi2) = m1 + sin(phi2), p = (m1,), for symplectic.integrate."""
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


# --- torque along the middle axis (Lee §3), away from the planes of the separating polhodes ---------------
@dataclass(frozen=True)
class MiddleAxis:
    """The §3 reduction for one hyperbolic cylinder p^2/a - r^2/c = alpha1^2 - alpha2^2 of one body under
    m + mu |omega|^2 along y:

        phi = int q dt, X = sqrt(ac) phi:
            p/sqrt(a) = alpha1 cosh X + alpha2 sinh X,  r/sqrt(c) = alpha1 sinh X + alpha2 cosh X,
        phi'' - mu phi'^2 = m0 + k1 sinh 2X + k2 cosh 2X,
    and, with phi2 = 2X + sigma, tau = sqrt(2 sqrt(ac) d) t, q1 = dphi2/dtau, mu1 = mu/(2 sqrt(ac)):
        |k1| > |k2| (|mu| below mu_c): k1 sinh + k2 cosh = eps d sinh(. + sigma),
            dq1/dtau = m1 + eps sinh phi2 + mu1 q1^2
        |k2| > |k1| (|mu| above mu_c): k1 sinh + k2 cosh = eps d cosh(. + sigma),
            dq1/dtau = m2 + eps cosh phi2 + mu1 q1^2
    with d = sqrt(|k1^2 - k2^2|), m1 (or m2) = m0/d.
    """

    body: Body
    m: float
    mu: float
    alpha1: float
    alpha2: float

    @property
    def m0(self) -> float:
        a, c = self.body.a, self.body.c
        return self.m + 0.5 * self.mu * (a - c) * (self.alpha1**2 - self.alpha2**2)

    @property
    def k1(self) -> float:
        a, b, c = self.body.a, self.body.b, self.body.c
        s = self.alpha1**2 + self.alpha2**2
        return self.mu * (a + c) * self.alpha1 * self.alpha2 - 0.5 * b * np.sqrt(a * c) * s

    @property
    def k2(self) -> float:
        a, b, c = self.body.a, self.body.b, self.body.c
        s = self.alpha1**2 + self.alpha2**2
        return 0.5 * self.mu * (a + c) * s - b * np.sqrt(a * c) * self.alpha1 * self.alpha2

    @property
    def form(self) -> str:
        """Which of Lee's reductions holds: 'sinh' (|k1| > |k2|, (3.12)), 'cosh' (|k2| > |k1|, (3.56)),
        'exp' (k1 = k2: plane I or |mu| = mu_c, (3.24)/(3.58)), 'exp-' (k1 = -k2: plane II, (3.25)/(3.59)) or
        'rare' (k1 = k2 = 0: plane II at nu = nu_c, (3.65), where no hyperbolic term is left)."""
        k1, k2 = self.k1, self.k2
        scale = max(abs(k1), abs(k2))
        if scale <= 1e-12 * self.body.b * np.sqrt(self.body.a * self.body.c) * (
            self.alpha1**2 + self.alpha2**2
        ):
            return "rare"
        if abs(k1 - k2) <= 1e-12 * scale:
            return "exp"
        if abs(k1 + k2) <= 1e-12 * scale:
            return "exp-"
        return "cosh" if abs(k2) > abs(k1) else "sinh"

    @property
    def cosh_form(self) -> bool:
        return self.form == "cosh"

    @property
    def d1(self) -> float:
        """d1 = sqrt(k1^2 - k2^2) (or d2 = sqrt(k2^2 - k1^2)); |k1| in the exponential forms; in the rare case
        1/(2 sqrt(ac)), which makes tau = t, so that q1 = 2 sqrt(ac) q and phi2 = 2 sqrt(ac) phi are Lee's (q,
        phi) scaled."""
        if self.form == "rare":
            return 0.5 / np.sqrt(self.body.a * self.body.c)
        if self.form in ("exp", "exp-"):
            return abs(self.k1)
        return np.sqrt(abs(self.k1**2 - self.k2**2))

    @property
    def sigma1(self) -> float:
        form = self.form
        if form in ("exp", "exp-", "rare"):
            return 0.0
        return np.arctanh(self.k1 / self.k2) if form == "cosh" else np.arctanh(self.k2 / self.k1)

    @property
    def eps1(self) -> float:
        """The sign of the hyperbolic or exponential term: sgn k1 (sinh), sgn k2 (cosh), sgn k1 (exp: k1 e^Y),
        -sgn k1 (exp-: k1 sinh Y - k1 cosh Y = -k1 e^-Y)."""
        form = self.form
        if form == "rare":
            return 0.0
        if form == "cosh":
            return float(np.sign(self.k2))
        return -float(np.sign(self.k1)) if form == "exp-" else float(np.sign(self.k1))

    @property
    def time_scale(self) -> float:
        return np.sqrt(2.0 * np.sqrt(self.body.a * self.body.c) * self.d1)

    @property
    def m1(self) -> float:
        """m1 (sinh form), m2 (cosh form) or m3 (exponential forms and the rare case): m0/d."""
        return self.m0 / self.d1

    @property
    def mu1(self) -> float:
        return self.mu / (2.0 * np.sqrt(self.body.a * self.body.c))

    def plane_parameters(self, direction: float = 1.0) -> list:
        """For plane_middle: (m1, m2 or m3, mu1, eps, direction, form code)."""
        return [self.m1, self.mu1, self.eps1, direction, float(FORMS.index(self.form))]

    @staticmethod
    def mu_c(body: Body) -> float:
        """|mu| at which k1 = k2: b sqrt(ac)/(a + c)."""
        return body.b * np.sqrt(body.a * body.c) / (body.a + body.c)

    @staticmethod
    def plane_nu(nu, body: Body) -> float:
        """A scene's plane.nu: a number, or 'nu_c', the critical drag mu_c/(2 sqrt(ac)) = b/(2(a + c))."""
        return body.b / (2.0 * (body.a + body.c)) if nu == "nu_c" else float(nu)

    @classmethod
    def with_plane_parameters(
        cls, body: Body, m1: float, mu1: float, alpha1: float, alpha2: float
    ) -> "MiddleAxis":
        """The torque (m, mu) that gives the plane (m1, mu1) on the cylinder of (alpha1, alpha2)."""
        mu = 2.0 * np.sqrt(body.a * body.c) * mu1
        trial = cls(body, 0.0, mu, alpha1, alpha2)
        m0 = m1 * trial.d1
        m = m0 - 0.5 * mu * (body.a - body.c) * (alpha1**2 - alpha2**2)
        return cls(body, m, mu, alpha1, alpha2)

    def euler_parameters(self) -> np.ndarray:
        return np.array([self.body.a, self.body.b, self.body.c, self.m, self.mu])

    def to_plane(self, w: np.ndarray) -> np.ndarray:
        """Rows (p, q, r) -> rows (phi2, q1): e^X = (p/sqrt a + r/sqrt c)/(alpha1 + alpha2) and e^-X = (p/sqrt
        a - r/sqrt c)/(alpha1 - alpha2). Each row takes the larger of the two: for X far below 0 the sum is a
        difference of two numbers of size e^|X| and would lose |X|/ln 10 digits. In plane I or II only one of
        them exists."""
        w = np.atleast_2d(w)
        a, c = self.body.a, self.body.c
        u, v = w[:, 0] / np.sqrt(a), w[:, 2] / np.sqrt(c)
        s_, d_ = self.alpha1 + self.alpha2, self.alpha1 - self.alpha2
        with np.errstate(divide="ignore", invalid="ignore"):
            up = (u + v) / s_ if s_ else np.full(len(w), np.nan)
            down = (u - v) / d_ if d_ else np.full(len(w), np.nan)
            X = np.where(np.isnan(down) | (up >= down), np.log(up), -np.log(down))
        return np.column_stack([2.0 * X + self.sigma1, 2.0 * np.sqrt(a * c) * w[:, 1] / self.time_scale])

    def plane_departure(self, w: np.ndarray) -> np.ndarray:
        """In plane I (alpha1 = alpha2) or II (alpha1 = -alpha2): the off-plane part of rows (p, q, r) against
        the in-plane part, |p/sqrt a -+ r/sqrt c| / |p/sqrt a +- r/sqrt c|; zeros off the planes. The planes
        are invariant, but the off-plane part grows like e^{|phi2 - phi2(0)|} relative to the in-plane part
        when phi2 runs away (to -infinity in plane I, +infinity in plane II): a rounding error leaves the
        plane for good."""
        w = np.atleast_2d(w)
        u, v = w[:, 0] / np.sqrt(self.body.a), w[:, 2] / np.sqrt(self.body.c)
        with np.errstate(divide="ignore", invalid="ignore"):
            if self.alpha1 == self.alpha2:
                return np.abs(u - v) / np.abs(u + v)
            if self.alpha1 == -self.alpha2:
                return np.abs(u + v) / np.abs(u - v)
        return np.zeros(len(w))

    def from_plane(self, phi2: float, q1: float) -> np.ndarray:
        a, c = self.body.a, self.body.c
        X = 0.5 * (phi2 - self.sigma1)
        return np.array(
            [
                np.sqrt(a) * (self.alpha1 * np.cosh(X) + self.alpha2 * np.sinh(X)),
                self.time_scale * q1 / (2.0 * np.sqrt(a * c)),
                np.sqrt(c) * (self.alpha1 * np.sinh(X) + self.alpha2 * np.cosh(X)),
            ]
        )


def hyperbola(body: Body, w: np.ndarray) -> np.ndarray:
    """p^2/a - r^2/c of rows (p, q, r): constant for any torque along y (Lee (3.32))."""
    w = np.atleast_2d(w)
    return w[:, 0] ** 2 / body.a - w[:, 2] ** 2 / body.c


@rhs_function
def euler_middle(t, w, p, out):
    """Lee (3.1): p' = a q r, q' = -b r p + m + mu |w|^2, r' = c p q; p = (a, b, c, m, mu)."""
    out[0] = p[0] * w[1] * w[2]
    out[1] = -p[1] * w[2] * w[0] + p[3]
    if p[4] != 0.0:
        out[1] += p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    out[2] = p[2] * w[0] * w[1]


FORMS = ("sinh", "cosh", "exp", "exp-", "rare")


@rhs_function
def plane_middle(t, y, p, out):
    """Lee (3.12), (3.56), (3.24)/(3.58) or (3.25)/(3.59) in y = (phi2, q1): dq1/dtau = m + eps f(phi2) + mu1
    q1^2, f = sinh, cosh, exp, exp(-.) or, in the rare case (3.65), 0; p = (m, mu1, eps, direction, form code:
    index in FORMS)."""
    out[0] = p[3] * y[1]
    if p[4] == 0.0:
        f = np.sinh(y[0])
    elif p[4] == 1.0:
        f = np.cosh(y[0])
    elif p[4] == 2.0:
        f = np.exp(y[0])
    elif p[4] == 3.0:
        f = np.exp(-y[0])
    else:
        f = 0.0
    out[1] = p[3] * (p[0] + p[2] * f)
    if p[1] != 0.0:
        out[1] += p[3] * p[1] * y[1] * y[1]


# |s - 2 mu1| below which middle_g takes the resonant form. At a distance delta the resonant form misses the
# equation by about delta phi2^2 e^{s phi2}, and the other form's 1/delta cancels against C with a loss of
# log10(1/delta) digits.
RESONANCE = 1e-8


def resonant(mu1: float, s: float) -> bool:
    """Whether the exponential e^{s phi2} of the torque resonates with the homogeneous solution e^{2 mu1
    phi2}."""
    return abs(s - 2 * mu1) < RESONANCE


def middle_g_terms(phi, m: float, mu1: float, eps: float, form: str) -> list:
    """The terms of g in q1^2 = C e^{2 mu1 phi2} + g(phi2), the solution of Lee's middle-axis planes dq1/dtau
    = m + eps f(phi2) + mu1 q1^2 (mu1 != 0), that is (q1^2)' - 2 mu1 q1^2 = 2m + 2 eps f: (3.14) sinh, (3.19)
    cosh, (3.27)/(3.28), (3.60), (3.62), (3.63) for f = e^{phi2} ('exp') or e^{-phi2} ('exp-'); (3.66) in the
    rare case (f = 0). Each exponential c e^{s phi2} of 2 eps f contributes c e^{s phi2}/(s - 2 mu1), or, at
    the resonance 2 mu1 = s (nu = 1/2 in the cosh form or in plane II, where Lee's 1/(1 - 4 mu1^2) and 2/(1 -
    2 nu) diverge), c phi2 e^{s phi2}."""
    exponentials = {
        "sinh": ((eps, 1.0), (-eps, -1.0)),
        "cosh": ((eps, 1.0), (eps, -1.0)),
        "exp": ((2 * eps, 1.0),),
        "exp-": ((2 * eps, -1.0),),
        "rare": (),
    }[form]
    terms = [-m / mu1 + 0.0 * phi]
    for c, s in exponentials:
        terms.append(c * phi * np.exp(s * phi) if resonant(mu1, s) else c * np.exp(s * phi) / (s - 2 * mu1))
    return terms


def middle_g(phi, m: float, mu1: float, eps: float, form: str):
    """g of middle_g_terms, summed."""
    return sum(middle_g_terms(phi, m, mu1, eps, form))


def middle_c1(y: np.ndarray, m: float, mu1: float, eps: float, form: str) -> np.ndarray:
    """C = e^{-2 mu1 phi2} (q1^2 - g(phi2)), constant along the plane's trajectories (see middle_g)."""
    y = np.atleast_2d(y)
    return np.exp(-2 * mu1 * y[:, 0]) * (y[:, 1] ** 2 - middle_g(y[:, 0], m, mu1, eps, form))


def middle_potential(phi, m: float, eps: float, form: str):
    """V(phi2) = -m phi2 - eps F(phi2), F' = f: the potential of the unperturbed planes (mu1 = 0),
    (3.42)-(3.48)."""
    F = {"sinh": np.cosh, "cosh": np.sinh, "exp": np.exp, "exp-": lambda x: -np.exp(-x)}[form](phi)
    return -m * phi - eps * F


def middle_energy(y: np.ndarray, m: float, eps: float, form: str = "sinh") -> np.ndarray:
    """E = q1^2/2 + V(phi2), constant when mu1 = 0."""
    y = np.atleast_2d(y)
    return 0.5 * y[:, 1] ** 2 + middle_potential(y[:, 0], m, eps, form)


def middle_invariant(y: np.ndarray, m: float, mu1: float, eps: float, form: str) -> np.ndarray:
    """The plane's first integral: C of middle_c1, or the energy when mu1 = 0."""
    return middle_c1(y, m, mu1, eps, form) if mu1 != 0.0 else middle_energy(y, m, eps, form)


def middle_invariant_spread(y: np.ndarray, m: float, mu1: float, eps: float, form: str) -> float:
    """Spread of middle_invariant along rows y, relative to the size of the terms that make it up."""
    y = np.atleast_2d(y)
    phi, q1 = y[:, 0], y[:, 1]
    values = middle_invariant(y, m, mu1, eps, form)
    if mu1 != 0.0:
        size = np.exp(-2 * mu1 * phi) * (
            q1**2 + sum(np.abs(t) for t in middle_g_terms(phi, m, mu1, eps, form))
        )
    else:
        size = 0.5 * q1**2 + np.abs(m * phi) + np.abs(middle_potential(phi, 0.0, eps, form))
    return float(np.ptp(values) / np.max(size))


def middle_series_period(m1: float, nu: float, eta: float, cosh_form: bool = False) -> float:
    """Lee (4.13): about the center of (3.52), T = 2 pi (1 + m1^2)^(-1/4)(1 + h2 eta^2 + h3 eta^3); (4.14) for
    the cosh form (3.56) with m2 > 1: sqrt(1 + m1^2) -> sqrt(m2^2 - 1), m1 -> m2."""
    k_sq = np.sqrt(m1**2 - 1.0) if cosh_form else np.sqrt(1.0 + m1**2)
    return lyapunov_period(k_sq, -m1, -k_sq, -nu, eta)


def lyapunov_period(k_sq: float, beta2: float, beta3: float, mu1: float, eta: float) -> float:
    """Lee (4.2), (4.6)-(4.8): the period 2 pi/k (1 + h2 eta^2 + h3 eta^3) of the Lyapunov system (4.1)."""
    h2 = (5 * beta2**2 + 10 * beta2 * k_sq * mu1 + 3 * beta3 * k_sq + 8 * k_sq**2 * mu1**2) / (48 * k_sq**2)
    h3 = -(beta2 + 4 * k_sq * mu1) / (3 * k_sq) * h2
    return 2.0 * np.pi / np.sqrt(k_sq) * (1.0 + h2 * eta**2 + h3 * eta**3)
