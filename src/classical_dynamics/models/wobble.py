"""The Earth's free wobble: Euler-Liouville equations in the body frame, assembled from effects.

State y = omega / n (n the mean spin, rad per solar day), time in mean solar days, moments in units
of C. The angular momentum is l = L/(nC) = (J + c(t)) y + elastic(y), and in the body frame

    M(y) y' = n (l x y) - c'(t) y + n/(2Q) l x (l x y),        M = dl/dy,

the last term only with dissipation. Each effect a scene lists switches on its own block of the
compiled right-hand side (a flag in the parameter vector); an effect not listed is skipped, not
multiplied by zero:
  triaxiality       B != A                               (moments in the inertia J)
  elastic_yielding  Lamb Art. 71: quasi-static products of inertia beta omega_3 (omega_1, omega_2)
  dissipation       double-bracket internal friction: |L| is conserved exactly, the energy falls,
                    the wobble amplitude decays as exp(-sigma t / 2Q)
  excitation        products of inertia c13 + i c23 = H chi(t) from moving mass (annual + random),
                    chi the excitation function of the linear Liouville equation m + (i/sigma) m' = chi
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..scenes import EffectRegistry
from ..solvers.runge_kutta import rhs_function
from . import earth

EFFECTS = EffectRegistry("chandler")

# parameter vector layout
N_SPIN, A_C, B_C, ELASTIC, BETA, DISSIPATION, INV_2Q, H_EXC, N_TERMS, TERMS = range(10)


@dataclass
class WobbleModel:
    """What the effects set; `parameters()` packs it for the compiled right-hand side."""

    H: float  # (C - (A + B)/2)/C
    b_minus_a_over_c: float = 0.0
    beta_n2: float | None = None  # Lamb's beta n^2 in units of C (elastic_yielding)
    Q: float | None = None  # dissipation
    terms: list = field(default_factory=list)  # excitation: (amplitude rad, frequency rad/day, phase rad)
    n: float = earth.SPIN_RAD_PER_DAY

    def parameters(self) -> np.ndarray:
        a, b = earth.moments_over_c(self.H, self.b_minus_a_over_c)
        p = [
            self.n,
            a,
            b,
            float(self.beta_n2 is not None),
            self.beta_n2 or 0.0,
            float(self.Q is not None),
            0.5 / self.Q if self.Q else 0.0,
            self.H,
            float(len(self.terms)),
        ]
        for term in self.terms:
            p.extend(term)
        return np.array(p, dtype=float)

    def wobble_frequency(self) -> float:
        """Closed form, small amplitude, no excitation: sigma in units of n."""
        if self.beta_n2 is None:
            return earth.triaxial_wobble_frequency(self.H, self.b_minus_a_over_c)
        return earth.elastic_wobble_frequency(self.H, self.beta_n2, self.b_minus_a_over_c)

    def wobble_period_solar_days(self) -> float:
        return 2.0 * np.pi / (self.n * self.wobble_frequency())


@EFFECTS.register("triaxiality", "inertia", "$B \\ne A$: the equatorial ellipticity $(B - A)/C$")
def _triaxiality(params, model: WobbleModel):
    model.b_minus_a_over_c = b_minus_a_over_c(params, model.H)


def b_minus_a_over_c(params, H: float) -> float:
    """The triaxiality a scene asks for: a number, or 'C22' (the default) for today's Earth."""
    value = params.get("b_minus_a_over_c", "C22")
    return earth.b_minus_a_over_c(H) if value == "C22" else float(value)


@EFFECTS.register(
    "elastic_yielding",
    "deformation",
    "Lamb Art. 71: the centrifugal bulge follows the spin axis, "
    "products of inertia $-\\beta nq$, $-\\beta np$",
)
def _elastic(params, model: WobbleModel):
    if "k2" in params:
        model.beta_n2 = earth.elastic_beta_n2_over_c(params["k2"], model.H)
    else:
        model.beta_n2 = earth.beta_n2_for_period(model.H, params["period_solar_days"])


@EFFECTS.register(
    "dissipation",
    "dissipation",
    "internal friction with quality factor $Q$ "
    "(a double bracket: $|\\boldsymbol{L}|$ kept, the energy falls)",
)
def _dissipation(params, model: WobbleModel):
    model.Q = float(params["Q"])


@EFFECTS.register(
    "excitation",
    "excitation",
    "moving mass: an annual term and a seeded random process in the products of inertia",
)
def _excitation(params, model: WobbleModel):
    annual = params.get("annual")
    year = 2.0 * np.pi / earth.TROPICAL_YEAR_DAYS
    if annual:
        for sense, key in ((1.0, "prograde"), (-1.0, "retrograde")):
            if key in annual:
                amp, phase_deg = annual[key]["amplitude_mas"], annual[key]["phase_deg"]
                model.terms.append((amp * earth.MAS, sense * year, np.radians(phase_deg)))
    random = params.get("random")
    if random:
        rng = np.random.default_rng(random["seed"])
        k = random["terms"]
        shortest, longest = random["periods_days"]
        periods = np.exp(rng.uniform(np.log(shortest), np.log(longest), k))
        senses = rng.choice([-1.0, 1.0], k)
        phases = rng.uniform(0.0, 2.0 * np.pi, k)
        amp = random["rms_mas"] * earth.MAS / np.sqrt(k)
        for period, sense, phase in zip(periods, senses, phases):
            model.terms.append((amp, sense * 2.0 * np.pi / period, phase))


def assemble(H: float, effects: dict) -> WobbleModel:
    """The model from the listed effects only, through the registry (each sets its own fields of the model,
    none reads another's, so the scene's order does not matter)."""
    model = WobbleModel(H=H)
    EFFECTS.assemble(effects, model)
    return model


@rhs_function
def liouville(t, y, p, out):
    n = p[0]
    l0, l1, l2 = p[1] * y[0], p[2] * y[1], y[2]
    m00, m11, m22, m01, m02, m12 = p[1], p[2], 1.0, 0.0, 0.0, 0.0
    f0, f1, f2 = 0.0, 0.0, 0.0
    if p[3] != 0.0:
        # elastic: delta I = beta (omega omega^T - |omega|^2/3) minus its value at n e3 (in the reference
        # figure)
        be = p[4]
        w2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2]
        s = (2.0 / 3.0) * w2 + 1.0 / 3.0
        l0 += be * s * y[0]
        l1 += be * s * y[1]
        l2 += be * (s - 1.0) * y[2]
        d = be * s
        k = be * 4.0 / 3.0
        m00 += d + k * y[0] * y[0]
        m11 += d + k * y[1] * y[1]
        m22 += d + k * y[2] * y[2] - be
        m01 += k * y[0] * y[1]
        m02 += k * y[0] * y[2]
        m12 += k * y[1] * y[2]
    n_terms = int(p[8])
    if n_terms > 0:
        cx, cy, dcx, dcy = 0.0, 0.0, 0.0, 0.0
        for j in range(n_terms):
            amp, freq, phase = p[9 + 3 * j], p[10 + 3 * j], p[11 + 3 * j]
            arg = freq * t + phase
            c, s_ = np.cos(arg), np.sin(arg)
            cx += amp * c
            cy += amp * s_
            dcx -= amp * freq * s_
            dcy += amp * freq * c
        h = p[7]
        c13, c23 = h * cx, h * cy
        l0 += c13 * y[2]
        l1 += c23 * y[2]
        l2 += c13 * y[0] + c23 * y[1]
        m02 += c13
        m12 += c23
        f0 -= h * dcx * y[2]
        f1 -= h * dcy * y[2]
        f2 -= h * (dcx * y[0] + dcy * y[1])
    # n (l x y)
    x0 = l1 * y[2] - l2 * y[1]
    x1 = l2 * y[0] - l0 * y[2]
    x2 = l0 * y[1] - l1 * y[0]
    f0 += n * x0
    f1 += n * x1
    f2 += n * x2
    if p[5] != 0.0:
        g = n * p[6]  # l x (l x y), scaled: |l| is kept, the energy falls
        f0 += g * (l1 * x2 - l2 * x1)
        f1 += g * (l2 * x0 - l0 * x2)
        f2 += g * (l0 * x1 - l1 * x0)
    # solve the symmetric 3 x 3 system M y' = f by cofactors
    c00 = m11 * m22 - m12 * m12
    c01 = m02 * m12 - m01 * m22
    c02 = m01 * m12 - m02 * m11
    c11 = m00 * m22 - m02 * m02
    c12 = m01 * m02 - m00 * m12
    c22 = m00 * m11 - m01 * m01
    det = m00 * c00 + m01 * c01 + m02 * c02
    out[0] = (c00 * f0 + c01 * f1 + c02 * f2) / det
    out[1] = (c01 * f0 + c11 * f1 + c12 * f2) / det
    out[2] = (c02 * f0 + c12 * f1 + c22 * f2) / det


def invariants(y: np.ndarray, params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """|l| and the energy E = y.l - K(y) of samples y (rows), without excitation.

    l = grad K with K(y) = y.J y/2 + beta (|y|^4/6 - y3^2/2 + |y|^2/6): a Legendre pair, so E(l) is the
    Hamiltonian of the torque-free (elastic) body; dissipation makes it fall at fixed |l|.
    """
    J = np.array([params[A_C], params[B_C], 1.0])
    be = params[BETA] if params[ELASTIC] else 0.0
    w2 = np.sum(y * y, axis=1)
    l = y * J + be * (((2.0 / 3.0) * w2 + 1.0 / 3.0)[:, None] * y)
    l[:, 2] -= be * y[:, 2]
    K = 0.5 * np.sum(y * y * J, axis=1) + be * (w2 * w2 / 6.0 - 0.5 * y[:, 2] ** 2 + w2 / 6.0)
    return np.linalg.norm(l, axis=1), np.sum(y * l, axis=1) - K
