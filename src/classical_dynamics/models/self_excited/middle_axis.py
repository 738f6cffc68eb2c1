"""Torque along the middle axis (Lee §3), away from the planes of the separating polhodes: the reduction to
the four plane systems (sinh, cosh, exp, exp-) and the rare case (k1 = k2 = 0), their closed forms and
invariants."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...solvers.runge_kutta import rhs_function
from .body import Body


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
        """quadratic_torque.nu: a number, or 'nu_c', the critical drag mu_c/(2 sqrt(ac)) = b/(2(a + c))."""
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

    @classmethod
    def for_scene(
        cls, body: Body, m1: float | None, mu1: float, alpha1: float, alpha2: float
    ) -> "MiddleAxis":
        """A scene's reduction: the plane's m1 when it lists body_torque, else no constant torque (m = 0), and
        m1 follows from mu1 and the cylinder."""
        if m1 is None:
            return cls(body, 0.0, 2.0 * np.sqrt(body.a * body.c) * mu1, alpha1, alpha2)
        return cls.with_plane_parameters(body, m1, mu1, alpha1, alpha2)

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


@rhs_function
def euler_middle_phase(t, w, p, out):
    """Lee (3.1) with the phase phi = int q dt as a fourth state; p = (a, b, c, m, mu)."""
    out[0] = p[0] * w[1] * w[2]
    out[1] = -p[1] * w[2] * w[0] + p[3] + p[4] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    out[2] = p[2] * w[0] * w[1]
    out[3] = w[1]
