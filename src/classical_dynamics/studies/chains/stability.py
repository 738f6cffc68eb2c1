"""Lamb's stability of equilibrium and of steady motion (Higher Mechanics, Arts. 85-92, 99, 100; Exs. XIV.9,
16, 18).

Each function checks one statement on a small system built from the scene's numbers and returns what it
measures (record_<name> beside it writes that to the results): an indefinite V gives a real root and
exponential growth (Arts. 85-89); equal roots of a symmetric system bring no secular terms, the first minors
vanishing (Art. 92); gyroscopic coupling can stabilize, and small dissipation then makes the slower mode grow
(Art. 99, secular instability), as for a particle in a rotating bowl (Art. 99, Ex. 2); Ball's normal modes of
a body about a point (Ex. XIV.9); circular orbits under e^{-r/a}/r^2 (Ex. XIV.16); two particles on a
revolving string (Ex. XIV.18); the hanging chain from Hamilton's principle by finite elements (Art. 100). The
numbers come from eigensolvers and integrators; the references from sympy (symbolic.py) or closed forms.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import scipy.linalg as sla

from ...formatting import format_number
from ...models import linear
from ...models.revolving import revolving_pair, revolving_pair_crossing
from ...solvers.ode import Events, Problem, solve
from . import symbolic


def _bisect(unstable, lo, hi, tol=1e-12):
    """The switch of a predicate, unstable(lo) != unstable(hi), by bisection to tol."""
    a, b = unstable(lo), unstable(hi)
    if a == b:
        raise ValueError(f"no switch between {lo} and {hi}")
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        if unstable(mid) == a:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


# --- Arts. 85-89 and 92: equilibrium ------------------------------------------------------------------------


class Equilibrium(NamedTuple):
    scene_smallest_eigenvalue: float  # this stable scene's smallest lambda of (K, M), over k/m
    indefinite_eigenvalues: list[float]  # K of springs k, -k, k, over k
    indefinite_root_vs_exact: float  # largest real root against sqrt(k/m) (relative)
    indefinite_growth_rate: float  # fitted rate of growth of |q| over sqrt(k/m)
    indefinite_growth_factor: float
    equal_roots: list[float]  # the ring's roots over k/m: 1 and 4 twice
    minors_vanish: bool  # every first minor of Delta zero at the double root (sympy)
    multiplicity: int
    periods: int
    equal_roots_growth: float  # largest |q| over `periods` periods over the first period's, less 1
    non_symmetric_growth: float  # the same ratio (not less 1) for a non-symmetric K with a double root


def equilibrium(built) -> Equilibrium:
    """Art. 85-89: springs k, -k, k between the walls give V indefinite (K's eigenvalues +-k): a real root
    lambda = sqrt(k/m), and a small start grows as exp(lambda t) (DOP853). Art. 92: three particles on a
    closed ring of springs k, each tied down by k, have a double root 4k/m; sympy finds every first minor of
    Delta zero there, and the motion over 10^4 periods stays bounded; a non-symmetric K with a double root
    grows as t."""
    K, M = built.stiffness_matrix(), np.diag(built.masses)
    k, m = float(np.min(built.segment_stiffness)), float(built.masses[0])
    smallest = float(sla.eigh(K, M, eigvals_only=True)[0]) / (k / m)
    Kind = np.array([[0.0, k], [k, 0.0]])  # springs k, -k, k: each diagonal k + (-k), the coupling -(-k)
    eig = np.linalg.eigvalsh(Kind)
    A = linear.state_matrix(Kind, m * np.eye(2))
    rate_exact = np.sqrt(k / m)
    lam = np.linalg.eigvals(A)
    rng = np.random.default_rng(85)
    z0 = 1e-8 * rng.standard_normal(4)
    t1, t2 = 15 / rate_exact, 30 / rate_exact
    run = solve(
        Problem(linear.linear_system, z0, (0.0, t2), linear.pack(A)),
        "dop853",
        t_eval=[t1, t2],
        rtol=1e-13,
        atol=1e-30,
    )
    q = run.y_eval[:, :2]
    fitted = np.log(np.linalg.norm(q[1]) / np.linalg.norm(q[0])) / (t2 - t1)

    # Art. 92: equal roots. Three particles on a ring, each tied down: K = k I + k L (L the triangle's
    # Laplacian).
    L = np.array([[2.0, -1, -1], [-1, 2, -1], [-1, -1, 2]])
    Kr, Mr = k * (np.eye(3) + L), m * np.eye(3)
    roots = sla.eigh(Kr, Mr, eigvals_only=True)
    minors_zero, multiplicity = symbolic.equal_root_minors()
    periods = 10_000
    T = 2 * np.pi / np.sqrt(roots[0])  # the roots 1 and 4: the motion has this period
    growth = _bounded(Kr, Mr, T, periods, rng)
    jordan = np.array([[k, k], [0.0, k]])  # a double root, not from a potential
    return Equilibrium(
        smallest,
        (eig / k).tolist(),
        float(abs(lam.real.max() - rate_exact) / rate_exact),
        float(fitted / rate_exact),
        float(np.linalg.norm(q[1]) / np.linalg.norm(z0[:2])),
        (roots / (k / m)).tolist(),
        minors_zero,
        multiplicity,
        periods,
        growth - 1,
        _bounded(jordan, m * np.eye(2), 2 * np.pi / np.sqrt(k / m), periods, rng),
    )


def record_equilibrium(results, values: Equilibrium):
    periods = values.periods
    results.number(
        "scene_smallest_stiffness_eigenvalue",
        values.scene_smallest_eigenvalue,
        "k/m",
        note="this stable scene's smallest $\\lambda$ of $(K, M)$: positive, $V$ a minimum",
    )
    results.number(
        "indefinite_V_eigenvalues_over_k",
        values.indefinite_eigenvalues,
        "k",
        note="springs $k, -k, k$: $K$ has the eigenvalues $\\pm k$, $V$ neither a minimum nor a maximum",
    )
    results.number(
        "indefinite_real_root_vs_exact",
        values.indefinite_root_vs_exact,
        "1",
        note="largest real root of the state matrix against $\\sqrt{k/m}$",
    )
    results.number(
        "indefinite_growth_rate_over_root",
        values.indefinite_growth_rate,
        "1",
        note="rate of growth of $|q|$ between $\\lambda t$ = 15 and 30 (DOP853, rtol $10^{-13}$) over "
        "$\\sqrt{k/m}$: Lamb's $He^{\\lambda t}$",
    )
    results.number("indefinite_growth_factor", values.indefinite_growth_factor, "1")
    results.number("equal_roots_over_k_per_m", values.equal_roots, "k/m", note="1 and 4 twice")
    results.number(
        "equal_roots_minors_vanish",
        int(values.minors_vanish),
        "1",
        note="1: every first minor of $\\Delta(\\lambda)$ is zero at the double root (sympy)",
    )
    results.number("equal_roots_multiplicity", values.multiplicity, "1")
    results.number(
        "equal_roots_amplitude_growth",
        values.equal_roots_growth,
        "1",
        note=f"largest $|q|$ over {format_number(periods)} periods (8 samples a period, exact propagator) "
        "over that of the first period, less 1",
    )
    results.number(
        "non_symmetric_amplitude_growth",
        values.non_symmetric_growth,
        "1",
        note="the same for $K = k[(1, 1), (0, 1)]$ (non-symmetric, a double root): grows as $t$",
    )
    results.hard_case(
        "equal_roots_bounded",
        "Equal roots (Lamb Art. 92): a symmetric system with a double "
        f"root stays bounded over {format_number(periods)} periods (largest amplitude over the first "
        "period's, less 1)",
        values.equal_roots_growth,
        1e-9,
    )


def _bounded(K, M, period, periods, rng, samples=8):
    A = linear.state_matrix(K, M)
    n = len(K)
    step = sla.expm(A * period / samples)
    z = np.concatenate([rng.standard_normal(n), rng.standard_normal(n)])
    first, largest = 0.0, 0.0
    for i in range(periods * samples):
        z = step @ z
        size = np.linalg.norm(z[:n])
        if i < samples:
            first = max(first, size)
        largest = max(largest, size)
    return float(largest / first)


class BallModes(NamedTuple):
    conjugate_inertia: float  # largest off-diagonal of Phi^T I Phi over its diagonal
    conjugate_potential: float  # the same of Phi^T V Phi
    axis_fixed: float  # largest component of theta(t) off its starting axis, unit start


def ball_modes(seed=9) -> BallModes:
    """Ex. XIV.9 (Ball): a body about a fixed point, I the inertia tensor and V the potential of small
    rotations (random, with gravity's m g h diag(1, 1, 0) for the centre of mass below the point): the
    generalized eigenvectors are conjugate in both (common conjugate diameters), and a start along one of them
    stays a rotation about that axis (DOP853)."""
    rng = np.random.default_rng(seed)
    a, b = rng.standard_normal((3, 3)), rng.standard_normal((3, 3))
    I = a @ a.T + 0.5 * np.eye(3)
    V = b @ b.T + 0.2 * np.eye(3) + 1.5 * np.diag([1.0, 1.0, 0.0])
    lam, phi = sla.eigh(V, I)
    off = lambda S: np.max(np.abs(S - np.diag(np.diag(S)))) / np.max(np.abs(np.diag(S)))
    A = linear.state_matrix(V, I)
    worst = 0.0
    for j in range(3):
        axis = phi[:, j] / np.linalg.norm(phi[:, j])
        span = 5 * 2 * np.pi / np.sqrt(lam[0])
        run = solve(
            Problem(linear.linear_system, np.concatenate([axis, 0 * axis]), (0.0, span), linear.pack(A)),
            "dop853",
            rtol=1e-13,
            atol=1e-15,
            t_eval=np.linspace(0, span, 401),
        )
        theta = run.y_eval[:, :3].T
        sideways = np.linalg.norm(theta - np.outer(axis, axis @ theta), axis=0)
        worst = max(worst, float(sideways.max()))
    return BallModes(float(off(phi.T @ I @ phi)), float(off(phi.T @ V @ phi)), worst)


def record_ball_modes(results, values: BallModes):
    results.number(
        "ball_conjugate_inertia",
        values.conjugate_inertia,
        "1",
        note="largest off-diagonal of $\\Phi^TI\\Phi$ over its diagonal",
    )
    results.number(
        "ball_conjugate_potential",
        values.conjugate_potential,
        "1",
        note="largest off-diagonal of $\\Phi^TV\\Phi$ over its diagonal",
    )
    results.number(
        "ball_mode_axis_fixed",
        values.axis_fixed,
        "1",
        note="largest component of $\\boldsymbol\\theta(t)$ off its starting axis, unit start, five "
        "gravest periods (DOP853): each mode is a rotation about a fixed axis",
    )


# --- Art. 99: kinetic stability ---------------------------------------------------------------------------


class Secular(NamedTuple):
    label: str  # the sign of c: "negative" or "positive"
    c: float
    real_parts: list[float]  # of the slower and the faster root
    first_order: list[float]  # Lamb's first-order rho at the same roots (sympy)
    deviation: float  # largest relative difference


class Gyroscopic(NamedTuple):
    polynomial_exact: bool  # the determinant is Lamb's (2) (sympy)
    condition_is_discriminant: bool  # Lamb's (3) is the discriminant of (2) in lambda^2 (sympy)
    switch_beta: float  # where the roots for c1 = c2 = -1 become imaginary (bisection)
    positive_c_unstable_count: int  # c1 = c2 = 1: values of beta with a growing root
    mixed_c_stable_count: int  # c1 = 1, c2 = -1: values of beta with no growing root
    epsilon: float
    beta: float
    secular: list[Secular]  # c = -1, then c = 1
    bowl: Bowl


def gyroscopic(spec) -> Gyroscopic:
    """Art. 99: a1 q1'' + beta q2' + c1 q1 = 0, a2 q2'' - beta q1' + c2 q2 = 0 (unit a1 = a2)."""
    discriminant_exact, polynomial_exact = symbolic.kinetic_stability()
    I2 = np.eye(2)
    J = np.array([[0.0, 1.0], [-1.0, 0.0]])

    def unstable(beta, c):
        lam = np.linalg.eigvals(linear.state_matrix(c * I2, I2, G=beta * J))
        return bool(np.max(lam.real) > 1e-7)

    switch = _bisect(lambda b: unstable(b, -1.0), 1.0, 3.0, 1e-13)
    betas = np.linspace(0.0, 5.0, 51)
    positive_unstable = int(sum(unstable(b, 1.0) for b in betas))
    mixed_stable = int(
        sum(
            not bool(
                np.max(np.linalg.eigvals(linear.state_matrix(np.diag([1.0, -1.0]), I2, G=b * J)).real) > 1e-7
            )
            for b in betas
        )
    )
    # Secular stability: a small dashpot eps on both coordinates.
    eps, beta = spec["epsilon"], spec["beta"]
    rho = symbolic.gyroscopic_first_order_rho()
    secular = []
    for c, label in ((-1.0, "negative"), (1.0, "positive")):
        lam = np.linalg.eigvals(linear.state_matrix(c * I2, I2, B=eps * I2, G=beta * J))
        upper = lam[lam.imag > 0]
        upper = upper[np.argsort(upper.imag)]  # slower, faster
        sigma = np.sort(np.abs(np.linalg.eigvals(linear.state_matrix(c * I2, I2, G=beta * J)).imag))[::2]
        first = np.array([float(rho.subs({"c": c, "beta": beta, "epsilon": eps, "sigma": s})) for s in sigma])
        secular.append(
            Secular(
                label,
                c,
                upper.real.tolist(),
                first.tolist(),
                float(np.max(np.abs(upper.real - first) / np.abs(first))),
            )
        )
    return Gyroscopic(
        polynomial_exact,
        discriminant_exact,
        switch,
        positive_unstable,
        mixed_stable,
        eps,
        beta,
        secular,
        bowl(spec["bowl_friction"]),
    )


def record_gyroscopic(results, values: Gyroscopic):
    results.number(
        "kinetic_polynomial_exact",
        int(values.polynomial_exact),
        "1",
        note="1: the determinant of the gyroscopic system is Lamb's (2) (sympy)",
    )
    results.number(
        "kinetic_condition_is_discriminant",
        int(values.condition_is_discriminant),
        "1",
        note="1: Lamb's condition (3) is the discriminant of (2) in $\\lambda^2$ (sympy)",
    )
    results.number(
        "kinetic_switch_beta",
        values.switch_beta,
        "1",
        note="$\\beta$ at which the state matrix's roots for $c_1 = c_2 = -1$ become imaginary "
        "(bisection): Lamb's (3) gives $\\beta^2 = 4$",
    )
    results.number(
        "kinetic_positive_c_unstable_count",
        values.positive_c_unstable_count,
        "1",
        note="$c_1 = c_2 = 1$: values of $\\beta$ in [0, 5] with a growing root (none)",
    )
    results.number(
        "kinetic_mixed_c_stable_count",
        values.mixed_c_stable_count,
        "1",
        note="$c_1 = 1$, $c_2 = -1$: values of $\\beta$ with no growing root (none: $c_1c_2 < 0$)",
    )
    eps, beta = values.epsilon, values.beta
    for label, c, real_parts, first, deviation in values.secular:
        results.number(
            f"secular_real_parts_c_{label}",
            real_parts,
            "1",
            note=f"$c_1 = c_2 = {int(c)}$, $\\beta$ = {beta}, $\\epsilon$ = {eps}: real parts of the slower "
            "and the faster root",
        )
        results.number(
            f"secular_first_order_c_{label}",
            first,
            "1",
            note="the first-order $\\rho$ (sympy, Lamb's (8)-(10)) at the same roots",
        )
        results.number(
            f"secular_vs_first_order_c_{label}", deviation, "1", note="largest relative difference"
        )
    _record_bowl(results, values.bowl)


class Bowl(NamedTuple):
    switch_omega: float  # omega/n where the largest real part changes sign, friction on (bisection)
    space_rates_frictionless: list[float]  # at omega = 2n: each circular vibration's angular speed in space
    growing_space_rate: float  # with friction: the growing vibration's angular speed in space
    growing_real_part: float
    conical_pendulum_exact: bool  # sympy's relative equilibrium cos(theta) = g/(a omega^2)


def bowl(friction) -> Bowl:
    """Art. 99 Ex. 2: a particle near the bottom of a spherical bowl (radius a) turning at omega, in axes
    turning with it: x'' - 2 omega y' + (n^2 - omega^2) x + k x' = 0 and y'' + 2 omega x' + (n^2 - omega^2) y
    + k y' = 0, n^2 = g/a, friction k times the velocity relative to the bowl. Units n = sqrt(g/a) = 1."""
    J = np.array([[0.0, -1.0], [1.0, 0.0]])
    I2 = np.eye(2)

    def roots(omega, k):
        A = linear.state_matrix((1 - omega**2) * I2, I2, B=k * I2, G=2 * omega * J)
        return np.linalg.eig(A)

    def growing(omega):
        return bool(np.max(roots(omega, friction)[0].real) > 0)

    switch = _bisect(growing, 0.5, 2.0, 1e-13)
    lam, vec = roots(2.0, 0.0)
    space = []
    for j in np.where(lam.imag > 0)[0]:
        x, y = vec[0, j], vec[1, j]
        ccw = np.imag(np.conj(x) * y) < 0  # (1, -i): counter-clockwise, the sense of omega
        space.append((1 if ccw else -1) * lam[j].imag + 2.0)
    lam, vec = roots(2.0, friction)
    j = int(np.argmax(lam.real))
    x, y = vec[0, j], vec[1, j]
    ccw = np.imag(np.conj(x) * y) * np.sign(lam[j].imag) < 0  # counter-clockwise in the turning axes
    relative = abs(lam[j].imag) * (1 if ccw else -1)
    return Bowl(
        switch,
        [float(v) for v in sorted(space)],
        float(relative + 2.0),
        float(lam[j].real),
        symbolic.bowl_relative_equilibrium(),
    )


def _record_bowl(results, values: Bowl):
    results.number(
        "bowl_switch_omega_over_n",
        values.switch_omega,
        "√(g/a)",
        note="$\\omega/n$ at which the largest real part changes sign, friction on (bisection): Lamb's "
        "$\\omega^2 = g/a$",
    )
    results.number(
        "bowl_space_rates_frictionless",
        values.space_rates_frictionless,
        "√(g/a)",
        note="$\\omega = 2n$, no friction: the angular speed in space of each circular vibration "
        "(positive: the sense of $\\omega$); Lamb's $\\pm n$",
    )
    results.number(
        "bowl_growing_mode_space_rate",
        values.growing_space_rate,
        "√(g/a)",
        note="$\\omega = 2n$ with friction: the angular speed in space of the growing circular "
        "vibration (positive: the sense of $\\omega$) and its real part",
    )
    results.number("bowl_growing_real_part", values.growing_real_part, "√(g/a)")
    results.number(
        "bowl_conical_pendulum_exact",
        int(values.conical_pendulum_exact),
        "1",
        note="1: sympy finds the relative equilibrium $\\cos\\theta = g/a\\omega^2$, a minimum of the "
        "effective potential when $\\omega^2 > g/a$ and the lowest point then a maximum",
    )


# --- Exs. XIV.16 and 18: steady motions -------------------------------------------------------------------


class Revolving(NamedTuple):
    force_bounds: list[float]  # sympy: d(r^3 f)/dr > 0 below these, f = e^{-r/a}/r^2 and e^{-r/a}/r
    force_switch: float  # where 3f/r + f' changes sign, f = e^{-r/a}/r^2 (bisection)
    force_switch_ocr: float  # the same for f = e^{-r/a}/r, the OCR's reading
    routh_is_printed: bool  # Routh's reduction (sympy) gives Lamb's sigma^2
    equal_case_over_omega2: float  # sympy's sigma^2/Omega^2 for M = m, a = b
    oscillations: int  # counted in the run
    sigma2_fitted_vs_formula: float  # relative


def revolving() -> Revolving:
    """Ex. XIV.16: circular orbits under f ~ e^{-r/a}/r^2 (units a = 1); Ex. XIV.18: two particles on a
    string."""
    r_printed, r_ocr = symbolic.exponential_force_bounds()

    def kappa2(r, power):
        """Radial frequency squared of the circular orbit at r: 3 f/r + f' (f' by the complex step)."""
        f = lambda x: np.exp(-x) / x**power
        h = 1e-30
        return 3 * f(r) / r + np.imag(f(r + 1j * h)) / h

    switch = _bisect(lambda r: kappa2(r, 2) < 0, 0.2, 3.0, 1e-13)
    switch_ocr = _bisect(lambda r: kappa2(r, 1) < 0, 0.2, 5.0, 1e-13)
    # Ex. XIV.18: M at a from O, m at a + b, rigid links, no gravity, the straight form turning at Omega.
    M, m, a, b, omega = 2.0, 1.0, 1.0, 0.7, 1.0
    sigma2, printed, five = symbolic.revolving_string()
    eps = 1e-5
    z0 = np.array([0.0, 0.0, omega, eps])  # phi1, psi = phi2 - phi1, and their rates
    mu = (M + m) * a**2 * omega + m * b**2 * (omega + eps) + m * a * b * (2 * omega + eps)
    expected = float(sigma2.subs(dict(zip(symbolic.REVOLVING, (M, m, a, b, mu)))))

    span = 30 * 2 * np.pi / np.sqrt(expected)
    run = solve(
        Problem(revolving_pair, z0, (0.0, span), [M, m, a, b]),
        "dop853",
        rtol=1e-13,
        atol=1e-16,
        events=Events(revolving_pair_crossing, 1, directions=(1,)),
    )
    times = run.event_t
    times = times[times > 1e-9]
    period = (times[-1] - times[0]) / (len(times) - 1)
    fitted = (2 * np.pi / period) ** 2
    return Revolving(
        [float(r_printed), float(r_ocr)],
        switch,
        switch_ocr,
        printed,
        float(five),
        len(times) - 1,
        float(abs(fitted - expected) / expected),
    )


def record_revolving(results, values: Revolving):
    results.number(
        "exponential_force_bound_sympy",
        values.force_bounds,
        "a",
        note="sympy: $d(r^3f)/dr > 0$ for $r$ below these, $f = e^{-r/a}/r^2$ and $e^{-r/a}/r$",
    )
    results.number(
        "exponential_force_switch",
        values.force_switch,
        "a",
        note="radius at which the radial frequency squared $3f/r + f'$ of the circular orbit changes "
        "sign, $f = e^{-r/a}/r^2$ (bisection, complex-step $f'$)",
    )
    results.number(
        "exponential_force_switch_ocr_reading",
        values.force_switch_ocr,
        "a",
        note="the same for $f = e^{-r/a}/r$, the OCR's reading",
    )
    results.number(
        "revolving_routh_is_printed",
        int(values.routh_is_printed),
        "1",
        note="1: Routh's reduction (sympy) gives $\\sigma^2 = \\mu^2/[Mab(Ma^2 + m(a + b)^2)]$",
    )
    results.number(
        "revolving_equal_case_over_omega2",
        values.equal_case_over_omega2,
        "Ω²",
        note="sympy's $\\sigma^2/\\Omega^2$ for $M = m$, $a = b$",
    )
    results.number(
        "revolving_sigma2_fitted_vs_formula",
        values.sigma2_fitted_vs_formula,
        "1",
        note=f"$M = 2m$, $b = 0.7a$: $\\sigma^2$ from the period of $\\phi_2 - \\phi_1$ over "
        f"{values.oscillations} oscillations (DOP853, nonlinear, disturbance $10^{{-5}}$) against "
        "$\\mu^2/[Mab(Ma^2 + m(a + b)^2)]$",
    )


# --- Art. 100: the hanging chain from Hamilton's principle -------------------------------------------------


class HamiltonChain(NamedTuple):
    elements: list[int]
    errors: list[float]  # each mesh's largest relative error of the lowest sigma^2 l/g
    order: float  # fitted order in the number of elements
    richardson_error: float  # the two finest meshes extrapolated


def hamilton_chain(elements_list, modes=5) -> HamiltonChain:
    """2T = rho int y'^2 ds, 2V = g rho int (l - s) y_s^2 ds, s from the top, y(0) = 0 and nothing imposed at
    s = l: linear finite elements (consistent mass), sigma^2 l/g against (j_0k/2)^2."""
    from scipy import sparse
    from scipy.sparse.linalg import eigsh
    from scipy.special import jn_zeros

    exact = (jn_zeros(0, modes) / 2) ** 2
    errors, finest = [], []
    for n in elements_list:
        h = 1.0 / n
        mid = (np.arange(n) + 0.5) * h
        stiff = (1.0 - mid) / h  # int (l - s) over an element / h^2
        main = np.zeros(n + 1)
        main[:-1] += stiff
        main[1:] += stiff
        K = sparse.diags([main, -stiff, -stiff], [0, 1, -1], format="csc")
        mm = np.full(n + 1, 4 * h / 6)
        mm[0] = mm[-1] = 2 * h / 6
        M = sparse.diags([mm, np.full(n, h / 6), np.full(n, h / 6)], [0, 1, -1], format="csc")
        K, M = K[1:, 1:], M[1:, 1:]  # the top held: y(0) = 0; the free end left free
        # a fixed start vector: ARPACK's random one moves the eigenvalues in the last digits from run to run
        lam = np.sort(eigsh(K, k=modes, M=M, sigma=0.0, which="LM", v0=np.ones(n), return_eigenvectors=False))
        errors.append(float(np.max(np.abs(lam - exact) / exact)))
        finest.append(lam)
    order = float(-np.polyfit(np.log(elements_list), np.log(errors), 1)[0])
    richardson = (4 * finest[-1] - finest[-2]) / 3  # the h^2 term removed (the mesh halved)
    return HamiltonChain(
        list(elements_list), errors, order, float(np.max(np.abs(richardson - exact) / exact))
    )


def record_hamilton_chain(results, values: HamiltonChain):
    results.number("galerkin_elements", values.elements, "1")
    results.number(
        "galerkin_relative_errors",
        values.errors,
        "1",
        note="largest relative error of the lowest five $\\sigma^2l/g$ against $(j_{0k}/2)^2$",
    )
    results.number("galerkin_finest_error", values.errors[-1], "1")
    results.number("galerkin_order", values.order, "1", note="fitted order in the number of elements")
    results.number(
        "galerkin_richardson_error",
        values.richardson_error,
        "1",
        note="the two finest meshes extrapolated, $(4\\lambda_{h/2} - \\lambda_h)/3$, against $(j_{0k}/2)^2$",
    )


# --- The membrane (lecture notes): the drum's modes -------------------------------------------------------


def _cheb(N):
    """Trefethen's cheb: differentiation matrix and points cos(j pi/N), j = 0..N."""
    x = np.cos(np.pi * np.arange(N + 1) / N)
    c = np.hstack([2.0, np.ones(N - 1), 2.0]) * (-1.0) ** np.arange(N + 1)
    X = np.tile(x, (N + 1, 1)).T
    dX = X - X.T
    D = np.outer(c, 1 / c) / (dX + np.eye(N + 1))
    return D - np.diag(D.sum(axis=1)), x


class Drum(NamedTuple):
    points: int  # on the diameter
    modes_mn: list  # (m, n) of each frequency, lowest first
    collocation: list[float]  # omega a sqrt(sigma/T) by collocation
    bessel_zeros: list[float]  # j_mn (scipy)
    collocation_vs_bessel: float  # largest relative difference
    scipy_vs_mpmath: float  # scipy's zeros against mpmath's at 30 digits
    overtone_ratios: list[float]  # each frequency over the gravest


def drum(N, m_max=2, n_max=2) -> Drum:
    """The membrane y_tt = (T/sigma) lap y on the disc r < a, y = 0 on the rim: in each Fourier mode cos m
    theta (and sin, the same radial problem: a double frequency for m >= 1), u'' + u'/r - m^2 u/r^2 = -k^2 u,
    solved by Chebyshev collocation on the diameter with u(-r) = (-1)^m u(r) (Trefethen, Program 28). Units a
    = 1."""
    import mpmath
    from scipy.special import jn_zeros

    D, r = _cheb(N)
    D2 = D @ D
    half = (N - 1) // 2
    rows = slice(1, half + 1)
    mirror = list(range(N - 1, N - 1 - half, -1))
    R = np.diag(1 / r[1 : half + 1])
    computed, reference, labels = [], [], []
    for m in range(m_max + 1):
        p = (-1) ** m
        E1, E2 = D2[rows, 1 : half + 1], D2[rows][:, mirror]
        F1, F2 = D[rows, 1 : half + 1], D[rows][:, mirror]
        L = (E1 + p * E2) + R @ (F1 + p * F2) - m**2 * R @ R
        k = np.sort(np.sqrt(-np.linalg.eigvals(L).real))[:n_max]
        computed.extend(k)
        reference.extend(jn_zeros(m, n_max))
        labels.extend([(m, n + 1) for n in range(n_max)])
    computed, reference = np.array(computed), np.array(reference)
    order = np.argsort(reference)
    with mpmath.workdps(30):
        mp = np.array([float(mpmath.besseljzero(m, n)) for m, n in labels])
    return Drum(
        N,
        [list(labels[i]) for i in order],
        computed[order].tolist(),
        reference[order].tolist(),
        float(np.max(np.abs(computed - reference) / reference)),
        float(np.max(np.abs(reference - mp) / mp)),
        (computed[order][1:] / computed[order][0]).tolist(),
    )


def record_drum(results, values: Drum):
    results.number("drum_modes_mn", values.modes_mn, "1", note="$(m, n)$ of each frequency")
    results.number(
        "drum_frequencies_collocation",
        values.collocation,
        "√(T/σ)/a",
        note=f"$\\omega a\\sqrt{{\\sigma/T}}$ from Chebyshev collocation, {values.points} points on the "
        "diameter",
    )
    results.number("drum_bessel_zeros", values.bessel_zeros, "1", note="$j_{m,n}$ (scipy jn_zeros)")
    results.number(
        "drum_collocation_vs_bessel", values.collocation_vs_bessel, "1", note="largest relative difference"
    )
    results.number(
        "drum_scipy_vs_mpmath",
        values.scipy_vs_mpmath,
        "1",
        note="scipy's zeros against mpmath's besseljzero at 30 digits",
    )
    results.number(
        "drum_overtone_ratios",
        values.overtone_ratios,
        "1",
        note="each frequency over the gravest: not whole numbers",
    )
