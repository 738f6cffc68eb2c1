"""Lee §5: a symmetric body (A = B, axis z of moment C) about a fixed point, in a viscous medium, under a
constant torque fixed in the body. With h = (A - C)/A, the drag nu = mu1/A (equatorial) and mu = mu0/C
(axial), and the torque per unit moment m = (M1/A, M2/A, M3/C), Lee's (5.49):

    p' - h q r = m1 - nu p,    q' + h p r = m2 - nu q,    r' = m3 - mu r.

r is elementary; pi = p + i q obeys pi' + (nu + i h r) pi = m1 + i m2, so (5.7)
    pi(t) = e^{-nu t - i xi(t)} [pi0 + (m1 + i m2) J(t)],   J(t) = int_0^t e^{nu s + i xi(s)} ds,
with xi = int h r. J is elementary when xi is linear in t (Lee's Cases I, II without friction, IV, and
(5.30)); otherwise, with friction, u = |g| e^{-mu s} turns it into Lee's generalized sine and cosine
integrals of w = 1 + (nu + i g1)/mu ((5.22), (5.27)-(5.29)), and without friction (m3 != 0) into
Fresnel's, w = 1/2 (Bodewadt's form (5.17)).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..solvers import sine_cosine_integrals as sc
from ..solvers.runge_kutta import rhs_function


@rhs_function
def viscous_symmetric(t, w, p, out):
    """Lee (5.49); p = (h, nu, mu, m1, m2, m3)."""
    out[0] = p[0] * w[1] * w[2] + p[3] - p[1] * w[0]
    out[1] = -p[0] * w[0] * w[2] + p[4] - p[1] * w[1]
    out[2] = p[5] - p[2] * w[2]


@rhs_function
def viscous_modulated(t, w, p, out):
    """Lee (5.3) with a torque fixed in direction in the body whose modulus changes, F_i = m_i F(t) (5.4);
    p = (h, nu, mu, m1, m2, m3, kind, a, b): F = 1 + a sin(b t) (kind 0) or 1 - a e^{-b t} (kind 1)."""
    F = 1.0 + p[7] * np.sin(p[8] * t) if p[6] == 0.0 else 1.0 - p[7] * np.exp(-p[8] * t)
    out[0] = p[0] * w[1] * w[2] + p[3] * F - p[1] * w[0]
    out[1] = -p[0] * w[0] * w[2] + p[4] * F - p[1] * w[1]
    out[2] = p[5] * F - p[2] * w[2]


def modulation(kind: int, a: float, b: float):
    """F(t) of viscous_modulated, as a numpy function (for the quadratures)."""
    if kind == 0:
        return lambda t: 1.0 + a * np.sin(b * np.asarray(t, float))
    return lambda t: 1.0 - a * np.exp(-b * np.asarray(t, float))


def symmetric_axis(moments) -> tuple[float, float]:
    """(A, C) of a body with two equal moments A = B; C is the third (any order). None if none are equal."""
    m = [float(x) for x in moments]
    for k in range(3):
        others = [m[j] for j in range(3) if j != k]
        if others[0] == others[1]:
            return others[0], m[k]
    return None


@dataclass(frozen=True)
class ViscousMedium:
    h: float
    nu: float
    mu: float
    m: tuple  # (m1, m2, m3): the torque per unit moment
    omega0: tuple  # (p0, q0, r0)

    @classmethod
    def from_moments(cls, A: float, C: float, nu, mu, m, omega0) -> "ViscousMedium":
        return cls((A - C) / A, float(nu), float(mu), tuple(map(float, m)), tuple(map(float, omega0)))

    def parameters(self) -> np.ndarray:
        return np.array([self.h, self.nu, self.mu, *self.m])

    @property
    def friction(self) -> bool:
        return self.nu > 0.0 or self.mu > 0.0

    @property
    def g(self) -> float:
        """The amplitude of xi's exponential part, (h/mu)(r0 - m3/mu); 0 without friction."""
        return self.h / self.mu * (self.omega0[2] - self.m[2] / self.mu) if self.mu > 0 else 0.0

    @property
    def g1(self) -> float:
        """xi's final rate: h m3/mu with friction; h r0 without (and m3 = 0)."""
        return self.h * self.m[2] / self.mu if self.mu > 0 else self.h * self.omega0[2]

    @property
    def generalized(self) -> bool:
        """Whether J needs Lee's generalized integrals: friction, h != 0 and g != 0 (xi not linear in t)."""
        return self.mu > 0.0 and self.h != 0.0 and self.g != 0.0

    @property
    def w(self) -> complex:
        """Lee's w1 = 1 + (nu + i g1)/mu of (5.27) (a1 = 1 + nu/mu of (5.22) when g1 = 0)."""
        return 1.0 + complex(self.nu, self.g1) / self.mu

    @property
    def case(self) -> str:
        """Lee's cases of §5.3, by which J is computed."""
        h, (m3, r0) = self.h, (self.m[2], self.omega0[2])
        if h == 0.0:
            return "IV"
        if m3 == 0.0 and r0 == 0.0:
            return "I"
        if self.mu > 0.0:
            return "III (g = 0)" if self.g == 0.0 else ("II" if m3 == 0.0 else "III")
        return "II" if m3 == 0.0 else "III"

    def xi(self, t):
        t = np.asarray(t, float)
        if self.mu > 0.0:
            return self.g * (1.0 - np.exp(-self.mu * t)) + self.g1 * t
        return self.h * (self.omega0[2] * t + 0.5 * self.m[2] * t**2)

    def r(self, t):
        t = np.asarray(t, float)
        r0, m3 = self.omega0[2], self.m[2]
        if self.mu > 0.0:
            return (r0 - m3 / self.mu) * np.exp(-self.mu * t) + m3 / self.mu
        return r0 + m3 * t

    def J(self, t, integrals=sc.si_ci) -> tuple[np.ndarray, np.ndarray]:
        """int_0^t e^{nu s + i xi(s)} ds at the times t, and a bound on its error from the bounds on si and
        ci; `integrals(x, w)` gives si and ci (a Value). The integrals at the fixed end are computed once."""
        t = np.atleast_1d(np.asarray(t, float))
        if self.generalized:
            return self._J_generalized(t, integrals)
        if self.mu == 0.0 and self.m[2] != 0.0 and self.h != 0.0:
            return self._J_fresnel(t, integrals)
        rate = complex(self.nu, self.g1 if self.h != 0.0 else 0.0)  # xi linear in t: xi = g1 t
        J = t.astype(complex) if rate == 0 else (np.exp(rate * t) - 1.0) / rate
        return J, np.zeros(len(t))

    def _J_generalized(self, t, integrals):
        """(5.22)/(5.27): u = G e^{-mu s}, G = |g|, sigma = sgn g:
        J = e^{ig} G^{w-1}/mu {[ci(G) - ci(x_t)] - i sigma [si(G) - si(x_t)]},  x_t = G e^{-mu t}."""
        G, sigma, w = abs(self.g), np.sign(self.g), self.w
        top = integrals(G, w)
        bottoms = [integrals(x, w) for x in G * np.exp(-self.mu * t)]
        inner = np.array([(top.ci - b.ci) - 1j * sigma * (top.si - b.si) for b in bottoms])
        scale = G ** (w.real - 1.0) / self.mu  # |G^(w-1)|/mu: the bounds are magnified by it
        bound = scale * 2.0 * (top.bound + np.array([b.bound for b in bottoms]))
        return np.exp(1j * self.g) * G ** (w - 1.0) / self.mu * inner, bound

    def _J_fresnel(self, t, integrals):
        """Without friction, xi = a s + b s^2 (a = h r0, b = h m3/2): J = e^{-i a^2/(4b)} [F(v0 + t) - F(v0)],
        v0 = a/(2b), F(v) = int_0^v e^{i b v'^2} dv' = sgn(v)/(2 sqrt|b|) [Ci(U, 1/2) + i sgn(b) Si(U, 1/2)],
        U = |b| v^2, Ci = ci + B(1/2), Si = si + A(1/2)."""
        a, b = self.h * self.omega0[2], 0.5 * self.h * self.m[2]
        v0 = a / (2.0 * b)

        def F(v):
            U = abs(b) * v * v
            if U == 0.0:
                return 0.0j, 0.0
            value, scale = integrals(U, 0.5), 1.0 / (2.0 * np.sqrt(abs(b)))
            return (
                np.sign(v) * scale * (value.ci + sc.B(0.5) + 1j * np.sign(b) * (value.si + sc.A(0.5))),
                scale * 2.0 * value.bound,
            )

        F0, b0 = F(v0)
        Ft = [F(v0 + s) for s in t]
        J = np.exp(-1j * a * a / (4.0 * b)) * (np.array([f for f, _ in Ft]) - F0)
        return J, np.array([bt for _, bt in Ft]) + b0

    def closed_form(self, t, integrals=sc.si_ci) -> tuple[np.ndarray, np.ndarray]:
        """Rows (p, q, r) at the times t from Lee's quadratures, and a bound on the error of p + iq at each
        (from the bounds on si and ci; round-off in the elementary parts aside)."""
        t = np.atleast_1d(np.asarray(t, float))
        J, J_bound = self.J(t, integrals)
        decay = np.exp(-self.nu * t)
        torque = complex(self.m[0], self.m[1])
        pi = decay * np.exp(-1j * self.xi(t)) * (complex(self.omega0[0], self.omega0[1]) + torque * J)
        return np.column_stack([pi.real, pi.imag, self.r(t)]), decay * abs(torque) * J_bound

    def limit(self) -> np.ndarray | None:
        """Theorem 3: with friction, omega -> ((nu m1 + g1 m2), (nu m2 - g1 m1))/(nu^2 + g1^2), m3/mu."""
        if not (self.nu > 0.0 and self.mu > 0.0):
            return None
        (m1, m2, m3), g1 = self.m, self.g1
        d = self.nu**2 + g1**2
        return np.array([(self.nu * m1 + g1 * m2) / d, (self.nu * m2 - g1 * m1) / d, m3 / self.mu])

    def circle_center(self) -> np.ndarray | None:
        """Without friction and with m3 = 0 (Theorem 2): the circles' center (m2/(h r0), -m1/(h r0), r0)."""
        r0 = self.omega0[2]
        if self.friction or self.m[2] != 0.0 or self.h * r0 == 0.0:
            return None
        return np.array([self.m[1] / (self.h * r0), -self.m[0] / (self.h * r0), r0])

    def bounds(self) -> tuple | None:
        """Theorem 1 with friction: |p|, |q| < delta + |m1|/nu + |m2|/nu, |r| < |r0| + |m3|/mu."""
        if not (self.nu > 0.0 and self.mu > 0.0):
            return None
        delta = np.hypot(self.omega0[0], self.omega0[1])
        return (
            delta + (abs(self.m[0]) + abs(self.m[1])) / self.nu,
            abs(self.omega0[2]) + abs(self.m[2]) / self.mu,
        )
