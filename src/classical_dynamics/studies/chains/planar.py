"""Planar spring networks: a closed chain rotating in its own plane (Lamb Art. 98) and the triangle of three
equal atoms, the classical ozone molecule (lecture notes).

Both assemble the same stiffness: a spring between beads i and j, along the unit vector e, of length l under
tension T, adds k e e^T + (T/l)(1 - e e^T) (the stretched spring resists sideways motion by its tension).

The ring:
The chain is n beads of mass m on a circle of radius a, joined by stiff springs k (inextensible as k grows),
turning at omega with no external force. In the rotating frame the small motions obey
M x'' + G x' + (K - omega^2 M) x = 0, G = 2 m omega J the Coriolis terms, K the springs' stiffness about the
stretched equilibrium (the tension gives the transverse part). The quadratic eigenproblem is solved in state
form; each mode's wave number s is read from the discrete Fourier transform of its radial displacement, and
its pattern turns relative to the chain at -Im(lambda)/s. Lamb: relative speeds -omega and
omega (s^2 - 3)/(s^2 + 1), in space 0 and 2 omega (s^2 - 1)/(s^2 + 1); the steady tension is rho omega^2 a^2.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd
import scipy.linalg as sla
import sympy as sp


def equilibrium(n: int, radius_m: float, mass_kg: float, omega: float):
    """Bead positions on the circle and the tension that holds them there (the springs' natural length is
    whatever gives it: the stiffness about this state does not depend on it)."""
    theta = 2 * np.pi * np.arange(n) / n
    positions = radius_m * np.column_stack([np.cos(theta), np.sin(theta)])
    m = mass_kg / n
    tension = m * omega**2 * radius_m / (2 * np.sin(np.pi / n))  # two neighbours pull each bead inward
    return theta, positions, m, tension


def spring_stiffness(positions, edges, k: float, tension: float = 0.0):
    """Stiffness matrix (2n x 2n) of springs k along `edges` about the given positions, pretensioned by T."""
    n = len(positions)
    K = np.zeros((2 * n, 2 * n))
    for i, j in edges:
        d = positions[j] - positions[i]
        length = np.linalg.norm(d)
        e = d / length
        block = k * np.outer(e, e) + tension / length * (np.eye(2) - np.outer(e, e))
        for a, b, sign in ((i, i, 1), (j, j, 1), (i, j, -1), (j, i, -1)):
            K[2 * a : 2 * a + 2, 2 * b : 2 * b + 2] += sign * block
    return K


def matrices(positions, m, omega, k, tension):
    """M, G and the effective stiffness K - omega^2 M (rotating frame) of the ring, 2n coordinates."""
    n = len(positions)
    K = spring_stiffness(positions, [(i, (i + 1) % n) for i in range(n)], k, tension)
    M = m * np.eye(2 * n)
    J = np.kron(np.eye(n), np.array([[0.0, -1.0], [1.0, 0.0]]))
    return M, 2 * m * omega * J, K - omega**2 * M


def modes(theta, positions, M, G, K_eff):
    """Eigenvalues lambda (upper half plane) and each mode's signed wave number s."""
    n = len(theta)
    A = np.block([[np.zeros_like(M), np.eye(2 * n)], [-np.linalg.solve(M, K_eff), -np.linalg.solve(M, G)]])
    lam, vectors = np.linalg.eig(A)
    radial = positions / np.linalg.norm(positions, axis=1)[:, None]
    u = np.einsum("jc,jcm->jm", radial, vectors[: 2 * n].reshape(n, 2, -1))
    spectrum = np.fft.fft(u, axis=0)  # u_j ~ exp(i s theta_j): the peak at s
    s = np.fft.fftfreq(n, 1.0 / n).astype(int)[np.argmax(np.abs(spectrum), axis=0)]
    return lam, s


def dispersion():
    """Lamb's (44) for v ~ cos(s theta - sigma t): sigma^2 (s^2 + 1) + 4 omega s sigma - omega^2 s^2 (s^2 - 3)
    = 0; sympy's roots, and whether they are -s omega and s omega (s^2 - 3)/(s^2 + 1) exactly."""
    s, w = sp.symbols("s omega", positive=True)
    sigma = sp.Symbol("sigma", real=True)
    roots = sp.solve(sigma**2 * (s**2 + 1) + 4 * w * s * sigma - w**2 * s**2 * (s**2 - 3), sigma)
    printed = [-s * w, s * w * (s**2 - 3) / (s**2 + 1)]
    exact = len(roots) == 2 and all(any(sp.simplify(r - p) == 0 for r in roots) for p in printed)
    return roots, exact


class Ring(NamedTuple):
    n: int
    s_max: int
    stiffness_ratio: float  # k/(m omega^2)
    tension_ratio: float  # the steady tension over Lamb's rho omega^2 a^2
    largest_real_part: float  # max|Re lambda|/max|lambda| but the two defective roots
    defective_real_part: float  # the defective roots' |Re lambda|/omega
    waves: pd.DataFrame  # pattern speeds over omega, each wave number s
    dispersion_exact: bool  # sympy's roots of Lamb's (44) are his


def ring(chain, effects, s_max) -> Ring:
    """The rotating ring's waves (Lamb Art. 98): the gyroscopic eigenproblem about the turning circle."""
    n = chain["n"]  # 400 beads: a few seconds, quick or not
    radius = chain["length_m"] / (2 * np.pi)
    omega, k = effects["rotation"]["omega_rad_per_s"], float(effects["springs"]["k_n_per_m"])
    theta, positions, m, tension = equilibrium(n, radius, chain["mass_kg"], omega)
    rho = chain["mass_kg"] / chain["length_m"]
    M, G, K_eff = matrices(positions, m, omega, k, tension)
    lam, s = modes(theta, positions, M, G, K_eff)
    # Two roots are defective: s = 0 at zero (a change of spin: the ring's angle drifts in the rotating frame)
    # and s = 1 at omega (a displaced circle: the whole ring drifts, t exp(-i omega t)). Rounding splits each
    # by about sqrt(eps), into a real pair or a quartet. Every other root must be imaginary.
    defective = (np.abs(lam) < 1e-3 * omega) | (np.abs(np.abs(lam) - omega) < 1e-3 * omega)
    regular = ~defective
    rows = []
    for wave in range(1, s_max + 1):
        candidates = lam[s == wave]
        flexural = candidates[np.argsort(np.abs(candidates))[:2]]  # the stretching waves are far faster
        speeds = np.sort(-flexural.imag / wave / omega)
        expected = (-1.0, (wave**2 - 3) / (wave**2 + 1))
        rows.append(
            {
                "s": wave,
                "relative_1": speeds[0],
                "relative_2": speeds[1],
                "space_1": speeds[0] + 1,
                "space_2": speeds[1] + 1,
                "lamb_space_2": 2 * (wave**2 - 1) / (wave**2 + 1),
                "deviation": max(abs(speeds[0] - expected[0]), abs(speeds[1] - expected[1])),
            }
        )
    _, exact = dispersion()
    return Ring(
        n,
        s_max,
        k / (m * omega**2),
        tension / (rho * omega**2 * radius**2),
        float(np.max(np.abs(lam[regular].real)) / np.max(np.abs(lam))),
        float(np.max(np.abs(lam[defective].real)) / omega),
        pd.DataFrame(rows),
        exact,
    )


def run_ring(scene, results, quick):
    chain, effects = scene.data["chain"], scene.data["effects"]
    _record_ring(results, ring(chain, effects, scene.data["analysis"]["ring_waves"]["s_max"]))
    if "gyroscopic" in scene.data["analysis"]:  # Lamb Art. 99: kinetic stability, secular instability
        from . import stability

        stability.record_gyroscopic(results, stability.gyroscopic(scene.data["analysis"]["gyroscopic"]))


def _record_ring(results, values: Ring):
    results.number("n", values.n, "particles")
    results.number(
        "stiffness_ratio",
        values.stiffness_ratio,
        "1",
        note="$k/m\\omega^2$: large, the chain nearly inextensible",
    )
    results.number(
        "tension_over_rho_omega2_a2",
        values.tension_ratio,
        "1",
        note="the beads' steady tension against Lamb's $\\rho\\omega^2a^2$",
    )
    results.number(
        "largest_real_part",
        values.largest_real_part,
        "1",
        note="$\\max|\\operatorname{Re}\\lambda|/\\max|\\lambda|$ but the two defective roots: "
        "gyroscopic and stable, the roots imaginary",
    )
    results.number(
        "defective_real_part",
        values.defective_real_part,
        "1",
        note="the defective roots ($s$ = 0, 1) split by rounding, $|\\operatorname{Re}\\lambda|/\\omega$",
    )
    frame = values.waves
    waves = frame[frame.s >= 2]
    results.number(
        "stationary_wave_speed_max",
        float(waves.space_1.abs().max()),
        "1",
        note="largest $|$pattern speed in space$|/\\omega$ of the first wave, $s$ = 2 to "
        f"{values.s_max}: Lamb's 0",
    )
    results.number(
        "second_wave_deviation_max",
        float((waves.space_2 - waves.lamb_space_2).abs().max()),
        "1",
        note="largest deviation of the second wave's speed in space from $2\\omega(s^2 - 1)/(s^2 + 1)$, "
        "over $\\omega$",
    )
    one = frame[frame.s == 1].iloc[0]
    results.number(
        "s1_space_speeds",
        [float(one.space_1), float(one.space_2)],
        "1",
        note="$s = 1$: both waves at rest in space (the disturbed form is a displaced circle)",
    )
    results.number(
        "dispersion_roots_exact",
        int(values.dispersion_exact),
        "1",
        note="1: sympy's roots of (44) are $-s\\omega$ and $s\\omega(s^2 - 3)/(s^2 + 1)$ exactly",
    )
    results.hard_case(
        "ring_roots_imaginary",
        "Rotating ring: the gyroscopic eigenproblem's largest real part, "
        "relative, but the defective roots (rounding; a growing mode would be an instability)",
        values.largest_real_part,
        1e-9,
    )
    results.hard_case(
        "ring_defective_root",
        "Rotating ring: the defective double roots, a change of spin ($s$ = "
        "0) and a drifting ring ($s$ = 1), split by about $\\sqrt{\\epsilon}$, not by an instability: "
        "$|\\operatorname{Re}\\lambda|/\\omega$",
        values.defective_real_part,
        1e-3,
    )
    results.table(
        "waves",
        frame[["s", "relative_1", "relative_2", "space_2", "lamb_space_2", "deviation"]],
        "Waves on the rotating ring (Lamb Art. 98): pattern speeds over $\\omega$ relative to the chain "
        "and, for the second wave, in space beside Lamb's $2(s^2 - 1)/(s^2 + 1)$; the first wave is at "
        "rest in space. The deviation is the larger of the two waves' absolute differences from Lamb's "
        "relative speeds, in units of $\\omega$.",
        headers={
            "s": "$s$",
            "relative_1": "wave 1",
            "relative_2": "wave 2",
            "space_2": "wave 2 in space",
            "lamb_space_2": "Lamb",
            "deviation": "largest |deviation|",
        },
    )


# --- The triangle: three equal atoms on three equal springs ------------------------------------------------


def triangle_polynomial():
    """det(K - lambda M) of the equilateral triangle, factored by sympy (K exact: the corners' coordinates in
    sqrt(3)), and its roots with their multiplicities."""
    k, m, lam = sp.symbols("k m lambda", positive=True)
    corners = [sp.Matrix([0, 0]), sp.Matrix([1, 0]), sp.Matrix([sp.Rational(1, 2), sp.sqrt(3) / 2])]
    K = sp.zeros(6, 6)
    for i, j in ((0, 1), (1, 2), (2, 0)):
        e = corners[j] - corners[i]
        block = k * e * e.T  # unit sides, no tension
        for a, b, sign in ((i, i, 1), (j, j, 1), (i, j, -1), (j, i, -1)):
            K[2 * a : 2 * a + 2, 2 * b : 2 * b + 2] += sign * block
    polynomial = sp.factor((K - lam * m * sp.eye(6)).det())
    roots = sp.roots(sp.Poly(polynomial, lam))
    return polynomial, {sp.simplify(r * m / k): multiplicity for r, multiplicity in roots.items()}


class Triangle(NamedTuple):
    omega_squared: np.ndarray  # the solver's omega^2 over k/m
    sympy_roots: list[float]  # roots of det(K - omega^2 M) over k/m, each as often as it is multiple
    solver_vs_sympy: float
    zero_modes_vs_rigid: float  # largest principal angle (rad)
    breathing_vs_radial: float  # 1 - |cos| of the top mode against the radial breathing
    pair_angle: float  # largest principal angle between the degenerate pair and its plane (rad)


def triangle(chain, k) -> Triangle:
    """The ozone molecule of the notes: omega^2 = 0 three times (two translations, a rotation), 3k/2m twice
    (a degenerate pair) and 3k/m (the breathing mode)."""
    side, m = chain["length_m"] / 3, chain["mass_kg"] / 3
    angles = np.pi / 2 + 2 * np.pi * np.arange(3) / 3
    positions = side / np.sqrt(3) * np.column_stack([np.cos(angles), np.sin(angles)])
    K = spring_stiffness(positions, [(0, 1), (1, 2), (2, 0)], k)
    lam, shapes = np.linalg.eigh(K / m)
    scale = lam.max()
    lam = np.where(np.abs(lam) <= 1e-12 * scale, 0.0, lam)
    _, exact = triangle_polynomial()
    roots = [float(r) for r in sorted(exact) for _ in range(exact[r])]
    # The rigid motions span the zero modes: two translations and the turn about the centre (y ~ r x e_z).
    rigid = np.column_stack(
        [
            np.tile([1.0, 0.0], 3),
            np.tile([0.0, 1.0], 3),
            np.column_stack([-positions[:, 1], positions[:, 0]]).ravel(),
        ]
    )
    zero = shapes[:, :3]
    breathing = positions.ravel() / np.linalg.norm(positions)
    pair = shapes[:, 3:5]
    expected = sla.null_space(np.column_stack([rigid, breathing]).T)  # what is left: the degenerate plane
    return Triangle(
        lam / (k / m),
        roots,
        float(np.max(np.abs(lam / (k / m) - np.array(roots)))),
        float(np.max(sla.subspace_angles(zero, rigid))),
        float(1 - abs(shapes[:, 5] @ breathing)),
        float(np.max(sla.subspace_angles(pair, expected))),
    )


def run_triangle(scene, results, quick):
    k = float(scene.data["effects"]["springs"]["k_n_per_m"])
    _record_triangle(results, triangle(scene.data["chain"], k))


def _record_triangle(results, values: Triangle):
    results.number("omega_squared_over_k_per_m", values.omega_squared, "k/m")
    results.number(
        "sympy_roots_over_k_per_m",
        values.sympy_roots,
        "k/m",
        note="roots of $\\det(K - \\omega^2M)$, factored by sympy, with their multiplicities",
    )
    results.number("solver_vs_sympy", values.solver_vs_sympy, "1")
    results.number(
        "zero_modes_vs_rigid",
        values.zero_modes_vs_rigid,
        "rad",
        note="largest principal angle between the zero modes and the rigid motions",
    )
    results.number(
        "breathing_mode_vs_radial",
        values.breathing_vs_radial,
        "1",
        note="$1 - |\\cos\\theta|$: the top mode against the radial breathing",
    )
    results.number(
        "degenerate_pair_subspace",
        values.pair_angle,
        "rad",
        note="largest principal angle between the solver's pair and the plane orthogonal to the "
        "rigid motions and the breathing (vectors of a degenerate pair are not unique)",
    )
    results.hard_case(
        "degenerate_pair",
        "Ozone: the doubly degenerate pair compared as a plane (principal "
        "angles), not as vectors, which any rotation within it changes",
        values.pair_angle,
        1e-12,
        "rad",
    )
