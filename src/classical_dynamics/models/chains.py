"""Chains of particles on light links or springs, and chains of uniform rigid links.

Small oscillations: M q'' + K q = 0 with K = B^T diag(s) B + diag(d), M = diag(m).
B takes particle displacements to segment stretches (differences); s is each segment's
stiffness (tension / length for a string, k for a spring); d is a direct restoring or
softening term per particle. Each effect listed in a scene adds to s or d; nothing else does.
Particles are numbered from the fixed end (the suspension, or the pivot of a rotating chain).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..scenes import EffectRegistry

EFFECTS = EffectRegistry("chains")


@dataclass(frozen=True)
class ChainGeometry:
    """What an effect may read: masses, spacing, positions along the chain, the ends."""

    n: int
    masses_kg: np.ndarray
    spacing_m: float
    ends: str
    n_segments: int
    positions_m: np.ndarray = field(repr=False)  # distance of each particle from the fixed end

    @property
    def mass_beyond(self) -> np.ndarray:
        """Mass carried by each segment (fixed-free: everything further from the fixed end)."""
        return np.cumsum(self.masses_kg[::-1])[::-1]


@dataclass(frozen=True)
class Contribution:
    segment_stiffness: np.ndarray | None = None  # N/m per segment
    diagonal: np.ndarray | None = None  # N/m per particle
    tension_n: np.ndarray | None = None  # the tension behind the stiffness, for the report
    damping: np.ndarray | None = None  # kg/s per particle: a dashpot to the frame (Rayleigh's F)
    force: np.ndarray | None = None  # N per particle: amplitude of a force varying as cos(sigma t)


def _require_fixed_free(name: str, geometry: ChainGeometry):
    if geometry.ends != "fixed-free":
        raise ValueError(f"effect {name} acts on a chain fixed at one end and free at the other")


@EFFECTS.register(
    "gravity", "tension", "the weight of the chain below each link: a tension $g$ × (the mass below)"
)
def _gravity(params, geometry: ChainGeometry) -> Contribution:
    _require_fixed_free("gravity", geometry)
    tension = params["g_m_per_s2"] * geometry.mass_beyond
    return Contribution(segment_stiffness=tension / geometry.spacing_m, tension_n=tension)


@EFFECTS.register(
    "rotation",
    "tension",
    "a steady rotation about the fixed end: a centrifugal tension; in-plane motion also feels $-m\\omega^2$",
)
def _rotation(params, geometry: ChainGeometry) -> Contribution:
    _require_fixed_free("rotation", geometry)
    omega = params["omega_rad_per_s"]
    moment = np.cumsum((geometry.masses_kg * geometry.positions_m)[::-1])[::-1]
    tension = omega**2 * moment
    diagonal = -geometry.masses_kg * omega**2 if params.get("motion", "out_of_plane") == "in_plane" else None
    return Contribution(segment_stiffness=tension / geometry.spacing_m, diagonal=diagonal, tension_n=tension)


@EFFECTS.register("tension", "tension", "a uniform tension $P$ along a string (the loaded string)")
def _tension(params, geometry: ChainGeometry) -> Contribution:
    tension = np.full(geometry.n_segments, float(params["newton"]))
    return Contribution(segment_stiffness=tension / geometry.spacing_m, tension_n=tension)


@EFFECTS.register("springs", "force", "longitudinal springs between neighbours (and to the walls)")
def _springs(params, geometry: ChainGeometry) -> Contribution:
    k = np.broadcast_to(np.asarray(params["k_n_per_m"], float), (geometry.n_segments,)).copy()
    return Contribution(segment_stiffness=k)


@EFFECTS.register(
    "friction",
    "dissipation",
    "dashpots from the particles to the frame: Rayleigh's dissipation function $F = \\sum b\\dot y^2/2$",
)
def _friction(params, geometry: ChainGeometry) -> Contribution:
    return Contribution(damping=_per_particle(params["b_kg_per_s"], geometry, "friction"))


@EFFECTS.register("forcing", "excitation", "a simple-harmonic force $F\\cos\\sigma t$ on chosen particles")
def _forcing(params, geometry: ChainGeometry) -> Contribution:
    return Contribution(force=_per_particle(params["newton"], geometry, "forcing"))


def _per_particle(values, geometry: ChainGeometry, name: str) -> np.ndarray:
    values = np.asarray(values, float)
    if values.ndim and values.size != geometry.n:
        raise ValueError(f"effect {name}: one value per particle ({geometry.n}), got {values.size}")
    return np.broadcast_to(values, (geometry.n,)).copy()


# Effects that restore (they set the free frequencies); friction and forcing act on a chain that has them.
RESTORING = ("gravity", "rotation", "tension", "springs")


def segments_for(n: int, ends: str) -> int:
    return {"fixed-free": n, "fixed-fixed": n + 1, "free-free": n - 1}[ends]


@dataclass(frozen=True)
class ParticleChain:
    geometry: ChainGeometry
    segment_stiffness: np.ndarray
    diagonal: np.ndarray | None
    contributions: dict
    damping: np.ndarray | None = None  # kg/s per particle, from friction
    force: np.ndarray | None = None  # N per particle, from forcing

    @property
    def masses(self) -> np.ndarray:
        return self.geometry.masses_kg

    def stiffness_matrix(self) -> np.ndarray:
        n, ends = self.geometry.n, self.geometry.ends
        B = difference_matrix(n, ends)
        K = B.T @ np.diag(self.segment_stiffness) @ B
        return K + np.diag(self.diagonal) if self.diagonal is not None else K


def difference_matrix(n: int, ends: str) -> np.ndarray:
    """Segment stretches from particle displacements (rows: segments, columns: particles)."""
    B = np.zeros((segments_for(n, ends), n))
    for j in range(B.shape[0]):
        right, left = (j + 1, j) if ends == "free-free" else (j, j - 1)
        if right < n:
            B[j, right] = 1.0
        if left >= 0:
            B[j, left] = -1.0
    return B


def particle_chain(n: int, ends: str, length_m: float, masses_kg, effects: dict) -> ParticleChain:
    """Assemble a particle chain from the listed effects only."""
    segments = segments_for(n, ends)
    if segments < 1 and ends == "free-free":
        raise ValueError("a free-free chain needs at least two particles")
    spacing = length_m / {"fixed-free": n, "fixed-fixed": n + 1, "free-free": max(n - 1, 1)}[ends]
    masses = np.broadcast_to(np.asarray(masses_kg, float), (n,)).copy()
    offset = 1.0 if ends != "free-free" else 0.0
    geometry = ChainGeometry(
        n=n,
        masses_kg=masses,
        spacing_m=spacing,
        ends=ends,
        n_segments=segments,
        positions_m=spacing * (np.arange(n) + offset),
    )
    components = EFFECTS.assemble(effects, geometry)
    stiffness = np.zeros(segments)
    diagonal = damping = force = None
    for part in components.values():
        if part.segment_stiffness is not None:
            stiffness = stiffness + part.segment_stiffness
        if part.diagonal is not None:
            diagonal = part.diagonal if diagonal is None else diagonal + part.diagonal
        damping = part.damping if part.damping is not None else damping
        force = part.force if part.force is not None else force
    return ParticleChain(geometry, stiffness, diagonal, components, damping, force)


def rigid_links_matrices(n: int):
    """Hanging chain of n uniform rigid links, angles from the top (units m a^2 and m g a).

    T = 1/2 m a^2 theta'^T M theta', M = C^T C + I/12, C lower-triangular ones with 1/2 on the diagonal;
    V = 1/2 m g a theta^T K theta, K = diag(n - i + 1/2). Eigenvalues are omega^2 a / g.
    """
    C = np.tril(np.ones((n, n)), -1) + 0.5 * np.eye(n)
    M = C.T @ C + np.eye(n) / 12.0
    K = np.diag(n - np.arange(n) - 0.5)
    return K, M


# --- Closed forms: the continuum limit and the exact discrete spectra -------------------------


def frequency_unit(effects: dict, length_m: float, mass_kg: float, spacing_m: float, mass_each_kg: float):
    """(value in rad/s, name, label) of the natural frequency unit of a chain with these effects."""
    if "gravity" in effects:
        return np.sqrt(effects["gravity"]["g_m_per_s2"] / length_m), "sqrt_g_over_l", "√(g/l)"
    if "rotation" in effects:
        return effects["rotation"]["omega_rad_per_s"], "over_omega", "ω"
    if "tension" in effects:
        rho = mass_kg / length_m
        return (
            np.pi / length_m * np.sqrt(effects["tension"]["newton"] / rho),
            "over_fundamental",
            "(π/l)√(P/ρ)",
        )
    k = np.asarray(effects["springs"]["k_n_per_m"], float).ravel()[0]
    return np.sqrt(k / mass_each_kg), "sqrt_k_over_m", "√(k/m)"


def _uniform(values) -> bool:
    values = np.asarray(values, float).ravel()
    return bool(np.all(values == values[0]))


def continuum_frequencies(
    effects: dict, ends: str, length_m: float, mass_kg: float, k: int, n: int | None = None
):
    """Frequencies (rad/s) of the continuous chain these effects describe, or None if no closed form.

    gravity, fixed-free    omega_k = (j_0k / 2) sqrt(g/l)                    (D. Bernoulli; Lamb Art. 90)
    rotation, fixed-free   sigma^2/Omega^2 = n(n+1)/2, n odd (-1 in plane)   (Southwell; Lamb Ex. XIV.20-21)
    tension, fixed-fixed   omega_s = (s pi / l) sqrt(P / rho)
    springs (uniform k)    the same wave equation with Y = k a, mu = m/a (fixed-fixed, or free-free
                           from s = 0)
    """
    from ..solvers.special import bessel_j0_zeros

    s = np.arange(1, k + 1)
    if set(effects) == {"gravity"} and ends == "fixed-free":
        return bessel_j0_zeros(k) / 2 * np.sqrt(effects["gravity"]["g_m_per_s2"] / length_m)
    if set(effects) == {"rotation"} and ends == "fixed-free":
        odd = 2 * s - 1
        shift = 1.0 if effects["rotation"].get("motion", "out_of_plane") == "in_plane" else 0.0
        return effects["rotation"]["omega_rad_per_s"] * np.sqrt(np.clip(odd * (odd + 1) / 2 - shift, 0, None))
    if set(effects) == {"tension"} and ends == "fixed-fixed":
        return s * np.pi / length_m * np.sqrt(effects["tension"]["newton"] / (mass_kg / length_m))
    if set(effects) == {"springs"} and n is not None and _uniform(effects["springs"]["k_n_per_m"]):
        kk = np.asarray(effects["springs"]["k_n_per_m"], float).ravel()[0]
        if ends == "fixed-fixed":
            return s * np.pi / (n + 1) * np.sqrt(kk / (mass_kg / n))
        if ends == "free-free":
            return (s - 1) * np.pi / n * np.sqrt(kk / (mass_kg / n))
    return None


def exact_discrete_frequencies(chain: ParticleChain, effects: dict, k: int):
    """Closed-form frequencies (rad/s) of the equal-particle chain, or None where there is none.

    gravity: omega^2 a / g are the zeros of the Laguerre polynomial L_n (Lamb Ex. XIV.11);
    uniform string or springs: the sine law 2 sqrt(s/m) sin(s pi / 2(n+1)) (Lagrange; Lamb Ex. XIV.10);
    rotation: exactly the continuum's n(n+1)/2 for the first n modes;
    the symmetric triatomic molecule m-M-m: 0, sqrt(k/m), sqrt(k (M + 2m) / (M m)).
    """
    from ..solvers.special import laguerre_zeros

    g = chain.geometry
    if (
        set(effects) == {"springs"}
        and g.ends == "free-free"
        and g.n == 3
        and _uniform(chain.segment_stiffness)
        and g.masses_kg[0] == g.masses_kg[2]
    ):
        # linear triatomic molecule m-M-m: 0, sqrt(k/m), sqrt(k (M + 2m) / (M m))
        (m, M), kk = g.masses_kg[:2], chain.segment_stiffness[0]
        return np.sqrt([0.0, kk / m, kk * (M + 2 * m) / (M * m)])[:k]
    if not _uniform(g.masses_kg):
        return None
    m, n = g.masses_kg[0], g.n
    k = min(k, n)
    s = np.arange(1, k + 1)
    if set(effects) == {"gravity"}:
        return np.sqrt(laguerre_zeros(n)[:k] * effects["gravity"]["g_m_per_s2"] / g.spacing_m)
    if set(effects) == {"rotation"}:
        return continuum_frequencies(effects, g.ends, g.spacing_m * n, m * n, k)
    if set(effects) in ({"tension"}, {"springs"}) and _uniform(chain.segment_stiffness):
        stiffness = chain.segment_stiffness[0]
        if g.ends == "fixed-fixed":
            return 2 * np.sqrt(stiffness / m) * np.sin(s * np.pi / (2 * (n + 1)))
        if g.ends == "free-free":
            return 2 * np.sqrt(stiffness / m) * np.sin((s - 1) * np.pi / (2 * n))
    return None
