"""The Sun's and Moon's torques on the oblate Earth, at three rungs of fidelity, from the listed effects.

Frame: the fixed ecliptic and equinox of J2000 (x to the equinox, z to the ecliptic pole); there is no
planetary precession, so the obliquity against this ecliptic is the IAU's omega_A and the motion of the
equator along it is the luni-solar precession psi_A. Time in mean solar days; the Earth's moments in
units of C with H = (C - A)/C, so C - A is never formed as a difference.

  secular   Lamb Art. 61 (7), (16): psi' = -(3/2)(GM/a^3)(1 - e^2)^(-3/2) P2(i) H cos(eps) / n per body
  averaged  the orbit-averaged torque on the spin axis s:  s' = -sum_b alpha_b (n_b . s)(n_b x s), where
            n_b is the body's orbit normal (the Moon's turns with its node); the 18.6-year nutation
            survives, the annual, semi-annual and monthly terms are averaged away
  full      Euler's equations and the attitude of a symmetric Earth spinning once a sidereal day, torqued
            by the Sun and the Moon as point masses on Keplerian orbits: N = 3 GM/r^3 (C - A) s3 (s x e3)

Effects: solar_torque, lunar_torque, orbit_eccentricity, lunar_inclination, node_regression,
lunar_perigee_advance. A body not
listed is not evaluated (its block of the compiled kernels is skipped, not multiplied by zero).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numba import njit

from ..formatting import format_number
from ..scenes import EffectRegistry
from ..solvers.runge_kutta import rhs_function
from . import earth

EFFECTS = EffectRegistry("precession")

# Parameter vector of the compiled kernels.
N_SPIN, H_ = 0, 1
SUN, SUN_K, SUN_E, SUN_N, SUN_L0, SUN_VARPI = 2, 3, 4, 5, 6, 7
MOON, MOON_K, MOON_E, MOON_N, MOON_L0, MOON_VARPI, MOON_I, NODE0, NODE_RATE = 8, 9, 10, 11, 12, 13, 14, 15, 16
PERIGEE_RATE = 17
N_PARAMS = 18


@dataclass(frozen=True)
class Orbits:
    """Mean orbital elements (J2000) and the strengths GM/a^3 of the Sun and the Moon, each with its
    source."""

    name: str
    year_days: float  # the Earth's orbital period (its mean motion n' = 2 pi / year_days)
    spin_turns_per_year: float  # n / n'
    sun_gm_over_a3: float  # per day^2
    moon_gm_over_a3: float  # per day^2
    sun_e: float
    moon_e: float
    moon_i_rad: float
    moon_n: float  # rad/day
    node_period_days: float
    perigee_period_days: float = np.inf  # the lunar perigee's circuit against the stars
    sun_L0: float = 0.0  # mean longitudes, perigees and node at J2000 (rad)
    sun_varpi: float = 0.0
    moon_L0: float = 0.0
    moon_varpi: float = 0.0
    node0: float = 0.0
    sources: tuple = ()

    @property
    def sun_n(self) -> float:
        return 2.0 * np.pi / self.year_days

    @property
    def spin(self) -> float:
        """n, rad per mean solar day."""
        return self.spin_turns_per_year * self.sun_n


def lamb1920() -> Orbits:
    """Lamb's constants (Art. 61 (9), (19)), as far as the OCR lets them be read (the digest marks guesses).

    He takes n/n' = 366.25 (sidereal days a year), E/M = 81.4 with the Moon's strength (M/E) n1^2 (not
    M/(E + M)), n1/n' = 13.4 and i = 5 deg 9'. Only ratios enter: the year is the sidereal year.
    """
    year = 365.256363
    n_sun = 2.0 * np.pi / year
    return Orbits(
        name="lamb1920",
        year_days=year,
        spin_turns_per_year=366.25,
        sun_gm_over_a3=n_sun**2,
        moon_gm_over_a3=(13.4 * n_sun) ** 2 / 81.4,
        sun_e=0.0,
        moon_e=0.0,
        moon_i_rad=np.radians(5.0 + 9.0 / 60.0),
        moon_n=13.4 * n_sun,
        node_period_days=18.6 * year,
        sources=(
            "Lamb (1920) Art. 61: n/n' = 366.25, E/M = 81.4, n1/n' = 13.4, i = 5°9′ (read from damaged OCR)",
        ),
    )


# Modern constants. IERS Conventions (2010) Table 1.1: GM_E, the Moon/Earth mass ratio and
# S/(E + M) = 328900.5596; the mean elements at J2000: Simon et al. (1994), the arguments of the
# IAU 2000 nutation; the mean Earth-Moon distance 384 400 km (ELP 2000-82: 384 399 km).
# The frame is fixed, so every period is sidereal: the node regresses 1934.1362891 deg per century
# against the moving equinox (the IAU's Omega), 1935.5331769 against the fixed one (plus p_A).
SIDEREAL_YEAR_DAYS = 365.256363
SIDEREAL_MONTH_DAYS = 27.321662
NODE_SIDEREAL_PERIOD_DAYS = 360.0 * 36525.0 / (1934.1362891 + 5028.796195 / 3600.0)
# The perigee: the Moon's mean longitude less its mean anomaly (the IAU's F + Omega - l, Simon et al. 1994)
# advances 1732564372.3047 - 1717915923.2178 ″ per century against the moving equinox.
PERIGEE_SIDEREAL_PERIOD_DAYS = 1296000.0 * 36525.0 / (1732564372.3047 - 1717915923.2178 - 5028.796195)
SUN_OVER_EARTH_MOON = 328900.5596
MOON_OVER_EARTH = 0.0123000371
MOON_DISTANCE_M = 384400.0e3


def modern() -> Orbits:
    n_sun = 2.0 * np.pi / SIDEREAL_YEAR_DAYS
    gm_moon = earth.GM_M3_PER_S2 * MOON_OVER_EARTH * earth.SECONDS_PER_DAY**2
    return Orbits(
        name="modern",
        year_days=SIDEREAL_YEAR_DAYS,
        spin_turns_per_year=earth.SPIN_RAD_PER_DAY / n_sun,
        # Kepler's third law for the Earth-Moon barycentre: GM_S / a'^3 = n'^2 S/(S + E + M)
        sun_gm_over_a3=n_sun**2 * SUN_OVER_EARTH_MOON / (1.0 + SUN_OVER_EARTH_MOON),
        moon_gm_over_a3=gm_moon / MOON_DISTANCE_M**3,
        sun_e=0.0167086,
        moon_e=0.0549,
        moon_i_rad=np.radians(5.145),
        moon_n=2.0 * np.pi / SIDEREAL_MONTH_DAYS,
        node_period_days=NODE_SIDEREAL_PERIOD_DAYS,
        perigee_period_days=PERIGEE_SIDEREAL_PERIOD_DAYS,
        sun_L0=np.radians(280.46646),
        sun_varpi=np.radians(102.93735),
        moon_L0=np.radians(218.31665),
        moon_varpi=np.radians(83.35324),
        node0=np.radians(125.04452),
        sources=(
            f"IERS Conventions (2010) Table 1.1: GM_E = {format_number(earth.GM_M3_PER_S2, 10)} m³ s⁻², "
            "M/E = 0.0123000371, S/(E+M) = 328900.5596",
            "sidereal year 365.256363 d, sidereal month 27.321662 d, node 6793.48 d and lunar perigee "
            "3232.6 d against the stars; mean elements at J2000 (Simon et al. 1994)",
            "e' = 0.0167086, e_Moon = 0.0549, i = 5.145°, a_Moon = 384 400 km",
        ),
    )


CONSTANTS = {"lamb1920": lamb1920, "modern": modern}


@dataclass
class PrecessionModel:
    """What the effects switch on; `parameters()` packs it for the compiled kernels."""

    H: float
    obliquity: float  # rad, at the start
    orbits: Orbits
    sun: bool = False
    moon: bool = False
    eccentric: bool = False
    inclined: bool = False
    regressing: bool = False
    advancing: bool = False  # the lunar perigee
    listed: list = field(default_factory=list)

    @property
    def n(self) -> float:
        return self.orbits.spin

    @property
    def sun_e(self) -> float:
        return self.orbits.sun_e if self.eccentric else 0.0

    @property
    def moon_e(self) -> float:
        return self.orbits.moon_e if self.eccentric else 0.0

    @property
    def moon_i(self) -> float:
        return self.orbits.moon_i_rad if self.inclined else 0.0

    @property
    def node_rate(self) -> float:
        """rad/day, negative: the node regresses."""
        return -2.0 * np.pi / self.orbits.node_period_days if self.regressing else 0.0

    @property
    def perigee_rate(self) -> float:
        """rad/day, positive: the lunar perigee advances (its mean anomaly turns in the anomalistic month)."""
        return 2.0 * np.pi / self.orbits.perigee_period_days if self.advancing else 0.0

    def parameters(self) -> np.ndarray:
        o = self.orbits
        p = np.zeros(N_PARAMS)
        p[N_SPIN], p[H_] = self.n, self.H
        if self.sun:
            p[SUN : SUN_VARPI + 1] = (1.0, 3.0 * o.sun_gm_over_a3, self.sun_e, o.sun_n, o.sun_L0, o.sun_varpi)
        if self.moon:
            p[MOON : NODE_RATE + 1] = (
                1.0,
                3.0 * o.moon_gm_over_a3,
                self.moon_e,
                o.moon_n,
                o.moon_L0,
                o.moon_varpi,
                self.moon_i,
                o.node0,
                self.node_rate,
            )
            p[PERIGEE_RATE] = self.perigee_rate
        return p

    # --- rung 1: the secular formula ---------------------------------------------------------------------
    def alphas(self) -> tuple[float, float]:
        """alpha_b = (3/2)(GM/a^3)(1 - e^2)^(-3/2) H / n (rad/day) of the averaged equations; 0 for a body
        not listed."""
        k = 1.5 * self.H / self.n
        sun = k * self.orbits.sun_gm_over_a3 * (1.0 - self.sun_e**2) ** -1.5 if self.sun else 0.0
        moon = k * self.orbits.moon_gm_over_a3 * (1.0 - self.moon_e**2) ** -1.5 if self.moon else 0.0
        return sun, moon

    def solar_rate(self) -> float:
        """Westward rate of the equinox from the Sun, rad/day (Lamb Art. 61 (7)): alpha_sun cos(eps)."""
        return self.alphas()[0] * np.cos(self.obliquity)

    def lunar_rate(self) -> float:
        """The Moon's part, with the node averaged out: the factor (3 cos^2 i - 1)/2 (Art. 61 (16))."""
        return self.alphas()[1] * 0.5 * (3.0 * np.cos(self.moon_i) ** 2 - 1.0) * np.cos(self.obliquity)

    def secular_rate(self) -> float:
        return self.solar_rate() + self.lunar_rate()

    def nutation_18p6yr(self) -> tuple[float, float]:
        """First-order amplitudes (rad) of the 18.6-year nutation in longitude and obliquity (digest §1.1):
        the Moon's precession rate about its own orbit pole, seen from the ecliptic as the pole circles it."""
        if not (self.moon and self.inclined and self.regressing):
            return 0.0, 0.0
        _, alpha = self.alphas()
        e, i, w = self.obliquity, self.moon_i, -self.node_rate
        k = alpha * np.sin(i) * np.cos(i)
        return k * np.cos(2 * e) / (np.sin(e) * w), k * np.cos(e) / w

    def nutation_at_start(self, semiannual: bool = True) -> tuple[float, float]:
        """(dpsi, deps) at t = 0 of the first-order 18.6-year and semi-annual terms, in the IAU's form
        dpsi = -A sin(arg), deps = B cos(arg): the scene's obliquity is the mean one, and starting the axis
        on the mean pole instead would leave a free offset of the mean obliquity of up to 9″. (The averaged
        equations have no semi-annual term: semiannual=False.)"""
        a_psi, a_eps = self.nutation_18p6yr()
        s_psi, s_eps = self.semiannual() if semiannual else (0.0, 0.0)
        node, sun = self.orbits.node0, 2.0 * self.orbits.sun_L0
        return (-a_psi * np.sin(node) - s_psi * np.sin(sun), a_eps * np.cos(node) + s_eps * np.cos(sun))

    def semiannual(self) -> tuple[float, float]:
        """First-order amplitudes (rad) of the Sun's semi-annual nutation in longitude and obliquity
        (Lamb Art. 61 (4): the couple's cos 2l and sin 2l parts, circular orbit)."""
        if not self.sun:
            return 0.0, 0.0
        half_cycle = 2.0 * self.orbits.sun_n
        return self.solar_rate() / half_cycle, self.solar_rate() * np.tan(self.obliquity) / half_cycle

    def solar_obliquity_sidebands(self) -> tuple[float, float]:
        """First-order amplitudes (rad) of the annual (2L - l') and 122-day (2L + l') terms in obliquity.

        The obliquity moves only with the couple's sin 2 lambda (lambda the Sun's true longitude); with
        (a/r)^3 = 1 + 3e cos l' and lambda = L + 2e sin l', (a/r)^3 sin 2 lambda = sin 2L
        + (7e/2) sin(2L + l') - (e/2) sin(2L - l'), and integrating over frequencies n' and 3n' against the
        semi-annual 2n' gives e and 7e/3 times the semi-annual amplitude. The term in l' alone has no
        obliquity part at this order."""
        semiannual_eps = self.semiannual()[1]
        return self.sun_e * semiannual_eps, 7.0 / 3.0 * self.sun_e * semiannual_eps


# Each effect switches on one block of the kernels (a flag of the model); none takes parameters.
SWITCHES = {
    "solar_torque": ("sun", "torque", "the Sun's couple on the equatorial bulge (a point mass on its orbit)"),
    "lunar_torque": ("moon", "torque", "the Moon's couple on the equatorial bulge"),
    "orbit_eccentricity": (
        "eccentric",
        "orbit",
        "Keplerian ellipses for the Sun's and the Moon's orbits, with the scene's eccentricities",
    ),
    "lunar_inclination": ("inclined", "orbit", "the lunar orbit tilted to the ecliptic by the scene's $i$"),
    "node_regression": ("regressing", "orbit", "the lunar node regresses along the ecliptic"),
    "lunar_perigee_advance": ("advancing", "orbit", "the lunar perigee advances"),
}
for _name, (_flag, _kind, _summary) in SWITCHES.items():
    EFFECTS.register(_name, _kind, _summary)(lambda params, model, flag=_flag: setattr(model, flag, True))


def assemble(H: float, obliquity_rad: float, orbits: Orbits, effects: dict) -> PrecessionModel:
    model = PrecessionModel(H=H, obliquity=obliquity_rad, orbits=orbits, listed=list(effects))
    EFFECTS.assemble(effects, model)
    return model


def initial_axis(psi: float, obliquity: float) -> np.ndarray:
    """The spin axis at obliquity eps whose equinox has moved psi west of x: ecliptic longitude 90 deg -
    psi."""
    return np.array([np.sin(obliquity) * np.sin(psi), np.sin(obliquity) * np.cos(psi), np.cos(obliquity)])


def precession_angles(s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(psi, eps) of axes s (rows): psi the westward motion of the equinox along the fixed ecliptic
    (unwrapped, the IAU's psi_A), eps the obliquity against it (omega_A)."""
    s = np.atleast_2d(s)
    s = s / np.linalg.norm(s, axis=1)[:, None]
    equinox_longitude = np.unwrap(np.arctan2(-s[:, 0], s[:, 1]))
    return -equinox_longitude, np.arccos(np.clip(s[:, 2], -1.0, 1.0))


# --- rung 2: the averaged spin-axis equations ------------------------------------------------------------
@rhs_function
def averaged_rhs(t, y, p, out):
    """s' = -alpha_b (n_b . s)(n_b x s) for the Sun (n = z) and the Moon (n turning with its node).

    p: [alpha_sun, alpha_moon, i, node0, node_rate] (rad/day, rad); a zero alpha skips its body."""
    out[0] = 0.0
    out[1] = 0.0
    out[2] = 0.0
    if p[0] != 0.0:
        c = -p[0] * y[2]  # n = (0, 0, 1): n x s = (-s_y, s_x, 0)
        out[0] -= c * y[1]
        out[1] += c * y[0]
    if p[1] != 0.0:
        node = p[3] + p[4] * t
        si = np.sin(p[2])
        n0, n1, n2 = si * np.sin(node), -si * np.cos(node), np.cos(p[2])
        c = -p[1] * (n0 * y[0] + n1 * y[1] + n2 * y[2])
        out[0] += c * (n1 * y[2] - n2 * y[1])
        out[1] += c * (n2 * y[0] - n0 * y[2])
        out[2] += c * (n0 * y[1] - n1 * y[0])


def averaged_parameters(model: PrecessionModel) -> np.ndarray:
    a_sun, a_moon = model.alphas()
    return np.array([a_sun, a_moon, model.moon_i, model.orbits.node0, model.node_rate])


# --- rung 3: the full torqued rigid Earth ----------------------------------------------------------------
@njit(cache=True)
def _kepler(mean_anomaly, e):
    """(cos E, sin E) of Kepler's equation E - e sin E = M by Newton's method (e < 0.1 here)."""
    E = mean_anomaly + e * np.sin(mean_anomaly)
    for _ in range(4):
        E -= (E - e * np.sin(E) - mean_anomaly) / (1.0 - e * np.cos(E))
    return np.cos(E), np.sin(E)


@njit(cache=True)
def _body_position(t, p, k):
    """Unit vector (ecliptic frame) to the body whose block starts at p[k], and (a/r)^3."""
    e, n, L0, varpi = p[k + 2], p[k + 3], p[k + 4], p[k + 5]
    if k == MOON:
        varpi += p[PERIGEE_RATE] * t
    mean_anomaly = L0 + n * t - varpi
    if e != 0.0:
        cE, sE = _kepler(mean_anomaly, e)
    else:
        cE, sE = np.cos(mean_anomaly), np.sin(mean_anomaly)
    a_over_r = 1.0 / (1.0 - e * cE)
    # position in the orbit plane, x towards perigee, in units of r
    x = (cE - e) * a_over_r
    y = np.sqrt(1.0 - e * e) * sE * a_over_r
    if k == MOON and p[MOON_I] != 0.0:
        node = p[NODE0] + p[NODE_RATE] * t
        w = varpi - node  # argument of perigee
        cw, sw, cn, sn = np.cos(w), np.sin(w), np.cos(node), np.sin(node)
        ci, si = np.cos(p[MOON_I]), np.sin(p[MOON_I])
        u0, u1 = cw * x - sw * y, sw * x + cw * y  # in the orbit plane from the node
        return cn * u0 - sn * ci * u1, sn * u0 + cn * ci * u1, si * u1, a_over_r**3
    cv, sv = np.cos(varpi), np.sin(varpi)
    return cv * x - sv * y, sv * x + cv * y, 0.0, a_over_r**3


@rhs_function  # torque(t, q, p, out) has a right-hand side's signature: the symmetric-torqued methods'
def torque_body(t, q, p, out):
    """N/C in the body frame: sum_b 3 GM_b/r_b^3 H s3 (s2, -s1, 0), s the body-frame unit vector to b."""
    out[0] = 0.0
    out[1] = 0.0
    out[2] = 0.0
    w, x, y, z = q[0], q[1], q[2], q[3]
    for k in (SUN, MOON):
        if p[k] == 0.0:
            continue
        v0, v1, v2, a3 = _body_position(t, p, k)
        # space -> body: v_body = R(q)^T v
        s0 = (1 - 2 * (y * y + z * z)) * v0 + 2 * (x * y + w * z) * v1 + 2 * (x * z - w * y) * v2
        s1 = 2 * (x * y - w * z) * v0 + (1 - 2 * (x * x + z * z)) * v1 + 2 * (y * z + w * x) * v2
        s2 = 2 * (x * z + w * y) * v0 + 2 * (y * z - w * x) * v1 + (1 - 2 * (x * x + y * y)) * v2
        c = p[k + 1] * a3 * p[H_] * s2
        out[0] += c * s1
        out[1] -= c * s0


@rhs_function
def full_rhs(t, y, p, out):
    """Euler's equations and the attitude: y = (m body, in units of C rad/day; q body-to-space)."""
    tau = np.empty(3)
    torque_body(t, y[3:], p, tau)
    a = 1.0 - p[H_]
    w0, w1, w2 = y[0] / a, y[1] / a, y[2]
    out[0] = y[1] * w2 - y[2] * w1 + tau[0]
    out[1] = y[2] * w0 - y[0] * w2 + tau[1]
    out[2] = y[0] * w1 - y[1] * w0 + tau[2]
    qw, qx, qy, qz = y[3], y[4], y[5], y[6]
    out[3] = 0.5 * (-qx * w0 - qy * w1 - qz * w2)
    out[4] = 0.5 * (qw * w0 + qy * w2 - qz * w1)
    out[5] = 0.5 * (qw * w1 + qz * w0 - qx * w2)
    out[6] = 0.5 * (qw * w2 + qx * w1 - qy * w0)


def start(model: PrecessionModel, averaged: bool = False) -> tuple[float, float]:
    """(psi, eps) of the axis at t = 0: the mean pole (the scene's obliquity) moved by the nutation."""
    d_psi, d_eps = model.nutation_at_start(semiannual=not averaged)
    return d_psi, model.obliquity + d_eps


def initial_state(model: PrecessionModel, forced: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """(m body, q) with the figure axis on `start(model)`.

    forced: start on the forced motion, the figure axis already moving as the couple drives it: with
    L = Cn e3 + A omega_perp and L' = N, e3' = N/(Cn), so omega_perp = e3 x N/(Cn) (the precession and the
    nutations' velocities at t = 0); otherwise omega = n e3 exactly, which leaves a free wobble (the hard
    case).
    """
    psi, eps = start(model)
    # body-to-space: a turn by -eps about x puts e3 at (0, sin eps, cos eps), then -psi about z
    q = np.array(
        [
            np.cos(-psi / 2) * np.cos(-eps / 2),
            np.cos(-psi / 2) * np.sin(-eps / 2),
            np.sin(-psi / 2) * np.sin(-eps / 2),
            np.sin(-psi / 2) * np.cos(-eps / 2),
        ]
    )
    omega_body = np.array([0.0, 0.0, model.n])
    if forced:
        omega_body[:2] = forced_offset(model, q)
    I = np.array([1.0 - model.H, 1.0 - model.H, 1.0])
    return I * omega_body, q


def forced_offset(model: PrecessionModel, q: np.ndarray) -> np.ndarray:
    """omega_perp (body frame, rad/day) of the forced motion at t = 0: e3 x N/(Cn)."""
    tau = np.empty(3)
    torque_body(0.0, q, model.parameters(), tau)
    return np.array([-tau[1], tau[0]]) / model.n
