"""Lamb's general theory of small oscillations (Higher Mechanics, Arts. 90-97) on the scenes' chains.

Each function checks one statement of the theory on a built ParticleChain and returns what it measures
(record_<name> beside it writes that to the results):
the printed mode shapes (Art. 90, Fig. 57), the separation of two roots by the diagonal values (Art. 90
Ex. 1), the stationary symmetric type (Art. 94 Ex. 1), interlacing under a constraint and orthogonality
(Arts. 91, 93), the forced response and its resonances (Art. 95), and small friction (Arts. 96-97). The
numbers come from the eigensolver or an integrator; sympy derives the references (symbolic.py).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd
import scipy.linalg as sla

from ...figure_style import FULL_WIDTH_IN
from ...lazy import lazy_module
from ...models import linear
from ...results import new_figure
from ...solvers.ode import Problem, solve

symbolic = lazy_module(f"{__package__}.symbolic")  # sympy, for the scenes that ask for a closed form


def _matrices(built):
    K = built.stiffness_matrix()
    return K, np.diag(built.masses)


def _modes(built):
    """All frequencies sigma (rad/s) and M-normalized shapes (columns) of the undamped chain."""
    K, M = _matrices(built)
    lam, phi = sla.eigh(K, M)
    return np.sqrt(np.clip(lam, 0.0, None)), phi


class PrintedShapes(NamedTuple):
    exact: bool  # each printed shape annulled by K - sigma^2 M at its printed sigma^2 (sympy)
    vs_solver: float  # largest 1 - |cos| between a printed shape and the eigensolver's
    vibration_momentum: float | None  # a free molecule's: largest |sum m_i X_i| over sum m_i max|X_i|


def printed_shapes(built, masses, name) -> PrintedShapes:
    """The source's mode shapes: exact eigenvectors (sympy) and the eigensolver's shapes against them."""
    K, M = symbolic.stiffness_and_mass(masses, built.segment_stiffness, built.geometry.ends)
    exact = symbolic.shapes_are_exact(K, M, symbolic.SOURCE_FORMULAS[name], symbolic.SOURCE_SHAPES[name])
    _, phi = _modes(built)
    _, _, values = symbolic.derive(masses, built.segment_stiffness, built.geometry.ends)
    printed = np.array(
        [symbolic.evaluate([symbolic.sp.sympify(x) for x in v], values) for v in symbolic.SOURCE_SHAPES[name]]
    ).T
    cosines = [
        abs(phi[:, i] @ printed[:, i]) / (np.linalg.norm(phi[:, i]) * np.linalg.norm(printed[:, i]))
        for i in range(printed.shape[1])
    ]
    momentum = None
    if built.geometry.ends == "free-free":  # a free molecule: its vibrations carry no momentum
        sigma, _ = _modes(built)
        moving = phi[:, sigma > 1e-6 * sigma.max()]
        momentum = np.abs(built.masses @ moving) / (built.masses.sum() * np.max(np.abs(moving), axis=0))
        momentum = float(momentum.max())
    return PrintedShapes(exact, float(max(1 - c for c in cosines)), momentum)


def record_printed_shapes(results, values: PrintedShapes):
    results.number(
        "source_shapes_exact",
        int(values.exact),
        "1",
        note="1: each printed shape is annulled by $K - \\sigma^2 M$ at its printed $\\sigma^2$ (sympy)",
    )
    results.number(
        "source_shapes_vs_solver",
        values.vs_solver,
        "1",
        note="largest $1 - |\\cos\\theta|$ between a printed shape and the eigensolver's",
    )
    if values.vibration_momentum is not None:
        results.number(
            "vibration_momentum",
            values.vibration_momentum,
            "1",
            note="largest $|\\sum m_iX_i|$ of a vibration over $\\sum m_i\\max|X_i|$",
        )


class Separation(NamedTuple):
    proved: bool  # sympy finds -h^2 at sigma^2 = a/m and at b/m
    margin: float  # not negative when the diagonal values separate the roots
    direction_residual: float  # of Lamb's (8)


def separation(built) -> Separation:
    """Art. 90 Ex. 1: the roots are separated by a/m and b/m (sympy shows f = -h^2 there), and the mode
    directions obey h (F^2 - G^2) = (a - b) F G; both on this scene's two-particle chain."""
    at_a, at_b, expected = symbolic.separation_by_diagonal()
    K, M = _matrices(built)
    if not np.allclose(np.diag(M), M[0, 0]):
        raise ValueError("separation (Lamb Art. 90 Ex. 1) is stated for equal masses")
    m = M[0, 0]
    (a, h), b = K[0], K[1, 1]
    sigma, phi = _modes(built)
    diagonal = sorted([a / m, b / m])
    margin = min(diagonal[0] - sigma[0] ** 2, sigma[1] ** 2 - diagonal[1]) / sigma[1] ** 2
    residual = max(abs(h * (F**2 - G**2) - (a - b) * F * G) / (abs(h) * (F**2 + G**2)) for F, G in phi.T)
    return Separation(at_a == expected and at_b == expected, float(margin), float(residual))


def record_separation(results, values: Separation):
    results.number(
        "separation_proved",
        int(values.proved),
        "1",
        note="1: sympy finds $-h^2$ at $\\sigma^2 = a/m$ and at $b/m$",
    )
    results.number(
        "separation_margin",
        values.margin,
        "1",
        note="$\\min(\\min(a, b)/m - \\sigma_1^2,\\ \\sigma_2^2 - \\max(a, b)/m)/\\sigma_2^2$: "
        "not negative when the diagonal values separate the roots",
    )
    results.number(
        "mode_direction_residual",
        values.direction_residual,
        "1",
        note="largest $|h(F^2 - G^2) - (a - b)FG|$ over $|h|(F^2 + G^2)$, Lamb's (8)",
    )


class RayleighSymmetric(NamedTuple):
    stationary_theta: list[float]  # roots of d sigma^2/d theta for the type (theta, 1, theta)
    exact: bool  # the roots are exactly -+1/sqrt2
    vs_solver: float  # the quotient there against the eigensolver's sigma_1^2, sigma_3^2 (relative)


def rayleigh_symmetric(built, masses) -> RayleighSymmetric:
    """Art. 94 Ex. 1: y1 = y3 = theta y2 makes sigma^2 stationary at theta = +-1/sqrt2, where it is exact."""
    K, M = symbolic.stiffness_and_mass(masses, built.segment_stiffness, built.geometry.ends)
    theta, quotient, stationary = symbolic.rayleigh_symmetric_type(K, M)
    printed = [-1 / symbolic.sp.sqrt(2), 1 / symbolic.sp.sqrt(2)]
    exact = len(stationary) == 2 and all(
        symbolic.sp.simplify(s - p) == 0 for s, p in zip(stationary, printed)
    )
    sigma, _ = _modes(built)
    values = symbolic.evaluate(
        [quotient.subs(theta, s) for s in stationary],
        {symbolic.k: float(built.segment_stiffness.min()), symbolic.m1: float(masses[0])},
    )
    symmetric = np.sort(sigma[[0, 2]] ** 2)  # the two symmetric modes: (1, ±√2, 1)
    return RayleighSymmetric(
        [float(s) for s in stationary], exact, float(np.max(np.abs(np.sort(values) - symmetric) / symmetric))
    )


def record_rayleigh_symmetric(results, values: RayleighSymmetric):
    results.number(
        "rayleigh_stationary_theta",
        values.stationary_theta,
        "1",
        note="roots of $d\\sigma^2/d\\theta$ for the type $(\\theta, 1, \\theta)$ (sympy)",
    )
    results.number(
        "rayleigh_stationary_exact", int(values.exact), "1", note="1: the roots are exactly $\\pm1/\\sqrt2$"
    )
    results.number(
        "rayleigh_stationary_vs_solver",
        values.vs_solver,
        "1",
        note="the quotient at its stationary points against the eigensolver's $\\sigma_1^2$, $\\sigma_3^2$",
    )


class Orthogonality(NamedTuple):
    mass: float  # largest |phi_i^T M phi_j - delta_ij|
    stiffness: float  # largest |phi_i^T K phi_j|, i != j, over sigma_n^2


def orthogonality(built) -> Orthogonality:
    """Art. 91: the modes are conjugate, orthogonal in T (the mass) and in V (the stiffness)."""
    K, M = _matrices(built)
    sigma, phi = _modes(built)
    lam, n = sigma**2, len(sigma)
    off = phi.T @ K @ phi - np.diag(lam)
    return Orthogonality(
        float(np.max(np.abs(phi.T @ M @ phi - np.eye(n)))), float(np.max(np.abs(off)) / lam.max())
    )


def record_orthogonality(results, values: Orthogonality):
    results.number(
        "orthogonality_mass", values.mass, "1", note="largest $|\\phi_i^T M \\phi_j - \\delta_{ij}|$"
    )
    results.number(
        "orthogonality_stiffness",
        values.stiffness,
        "1",
        note="largest $|\\phi_i^T K \\phi_j|$, $i \\ne j$, over $\\sigma_n^2$",
    )


class Constraint(NamedTuple):
    successive_minima_error: float  # held by phi_1^T M y = 0, the roots against sigma_2^2, ... (relative)
    stationary_order: float  # fitted order of the quotient's error for the type phi_1 + eps eta
    general_roots_imaginary: float  # largest |Im lambda|/|lambda| over random pairs T, V
    general_roots_not_positive: int
    constraints_tried: int
    interlacing_violations: int  # roots outside [sigma_k^2, sigma_{k+1}^2] after one constraint
    interlacing_margin: float  # smallest distance of a constrained root inside its interval, over sigma_n^2


def constraint(built, samples: int, seed: int) -> Constraint:
    """Arts. 91, 93: modes orthogonal in T and V; one constraint puts each new root between two old ones."""
    K, M = _matrices(built)
    sigma, phi = _modes(built)
    lam, n = sigma**2, len(sigma)
    # the constraints: each particle held fixed, then random linear relations c^T y = 0 (seeded)
    rng = np.random.default_rng(seed)
    relations = list(np.eye(n)) + list(rng.standard_normal((samples, n)))
    worst, violations = np.inf, 0
    for c in relations:
        basis = sla.null_space(c[None, :])  # y = basis z satisfies the constraint
        reduced = sla.eigh(basis.T @ K @ basis, basis.T @ M @ basis, eigvals_only=True)
        margin = np.minimum(reduced - lam[:-1], lam[1:] - reduced) / lam.max()
        worst = min(worst, float(margin.min()))
        violations += int(np.sum(margin < -1e-13))
    # Art. 93: held orthogonal (in T) to the gravest mode, the system's roots are the remaining ones exactly
    basis = sla.null_space((M @ phi[:, 0])[None, :])
    rest = sla.eigh(basis.T @ K @ basis, basis.T @ M @ basis, eigvals_only=True)
    successive = float(np.max(np.abs(rest - lam[1:]) / lam[1:]))
    # Art. 94: the quotient is stationary at a mode: a type off by epsilon errs by epsilon^2
    direction = rng.standard_normal(n)
    epsilons = np.array([1e-2, 1e-3, 1e-4])
    errors = []
    for eps in epsilons:
        y = phi[:, 0] + eps * direction
        errors.append(abs((y @ K @ y) / (y @ M @ y) - lam[0]) / lam[0])
    order = float(np.polyfit(np.log(epsilons), np.log(errors), 1)[0])
    # Art. 92: the roots of det(V - lambda T) are real for any symmetric T > 0 and V, and positive when V > 0;
    # asked of the general (non-symmetric) QZ solver, which could return complex roots
    worst_imaginary, negative = 0.0, 0
    for size in range(2, 11):
        for _ in range(20):
            a, b = rng.standard_normal((size, size)), rng.standard_normal((size, size))
            T, V = a @ a.T + 1e-3 * np.eye(size), b @ b.T + 1e-3 * np.eye(size)
            roots = sla.eig(V, T, right=False)
            worst_imaginary = max(worst_imaginary, float(np.max(np.abs(roots.imag) / np.abs(roots))))
            negative += int(np.sum(roots.real <= 0))
    return Constraint(successive, order, worst_imaginary, negative, len(relations), violations, worst)


def record_constraint(results, values: Constraint):
    results.number(
        "successive_minima_error",
        values.successive_minima_error,
        "1",
        note="constrained by $\\phi_1^TMy = 0$, the roots against $\\sigma_2^2, \\ldots$ (relative)",
    )
    results.number(
        "stationary_order",
        values.stationary_order,
        "1",
        note="fitted order of the quotient's error for the type $\\phi_1 + \\epsilon\\eta$, $\\eta$ random",
    )
    results.number(
        "general_roots_imaginary",
        values.general_roots_imaginary,
        "1",
        note=(
            "largest $|\\operatorname{Im}\\lambda|/|\\lambda|$ over 180 random pairs $T$, $V$ of sizes 2 to "
            "10"
        ),
    )
    results.number("general_roots_not_positive", values.general_roots_not_positive, "1")
    results.number("constraints_tried", values.constraints_tried, "1")
    results.number(
        "interlacing_violations",
        values.interlacing_violations,
        "1",
        note="roots outside $[\\sigma_k^2, \\sigma_{k+1}^2]$ after one constraint",
    )
    results.number(
        "interlacing_margin",
        values.interlacing_margin,
        "1",
        note="smallest distance of a constrained root inside its interval, over $\\sigma_n^2$",
    )


class Transient(NamedTuple):
    detuning: float
    integrator_vs_closed_form: float  # DOP853 against the product of sines, over the largest displacement
    difference_of_cosines_error: float  # the textbook form against the product of sines


class Forced(NamedTuple):
    direct_vs_normal: float  # largest relative difference away from the resonances
    static_limit: float  # the sum at sigma = 0 against K^{-1} F
    residue_slope: float  # fitted order of (sigma_1^2 - sigma^2) y's deviation from mode 1's term
    resonance: pd.DataFrame  # near the gravest resonance, against 50 digits
    transient: Transient
    sigma: np.ndarray  # the free frequencies (rad/s)
    fine: np.ndarray  # the drawn curve's forcing frequencies
    amplitude: np.ndarray  # |y_j|/|y_0| there, one column a particle


def forced(built, spec) -> Forced:
    """Art. 95: the response to F cos(sigma t), directly and in normal coordinates, and near resonance."""
    K, M = _matrices(built)
    F = built.force
    sigma, phi = _modes(built)
    modal_force = phi.T @ F  # Theta of each normal coordinate

    def direct(s):
        return np.linalg.solve(K - s**2 * M, F)

    def normal(s):
        return phi @ (modal_force / (sigma**2 - s**2))

    grid = np.linspace(0.0, spec["sigma_max_over_lowest"] * sigma[0], spec["points"])
    away = [s for s in grid if np.min(np.abs(sigma - s)) > 1e-3 * sigma[0]]
    deviation = max(np.linalg.norm(direct(s) - normal(s)) / np.linalg.norm(normal(s)) for s in away)
    static = np.linalg.solve(K, F)
    static_limit = float(np.linalg.norm(normal(0.0) - static) / np.linalg.norm(static))

    def detuned(delta):
        return detuned_response(sigma, phi, modal_force, delta)

    residue = phi[:, 0] * modal_force[0]
    exact_sigma1 = _exact_lowest(built)
    rows = []
    for d in np.logspace(-2, -10, 9):
        y, s = detuned(d)
        reference = _response_mp(built, exact_sigma1, d)
        rows.append(
            {
                "detuning": d,
                "amplitude_over_static": np.linalg.norm(y) / np.linalg.norm(static),
                "residue_deviation": np.linalg.norm(sigma[0] ** 2 * d * (2 - d) * y - residue)
                / np.linalg.norm(residue),
                "normal_error": np.linalg.norm(y - reference) / np.linalg.norm(reference),
                "direct_error": np.linalg.norm(direct(s) - reference) / np.linalg.norm(reference),
            }
        )
    frame = pd.DataFrame(rows)
    slope = float(np.polyfit(np.log(frame.detuning), np.log(frame.residue_deviation), 1)[0])
    # the figure's curve: the direct solve on a fine grid, over the statical displacement
    fine = np.linspace(grid[0], grid[-1], 3001)
    amplitude = np.array([np.abs(direct(s)) for s in fine]) / np.linalg.norm(static)
    return Forced(
        float(deviation),
        static_limit,
        slope,
        frame,
        transient(built, sigma, phi, modal_force, spec),
        sigma,
        fine,
        amplitude,
    )


def record_forced(results, values: Forced):
    results.number(
        "forced_direct_vs_normal",
        values.direct_vs_normal,
        "1",
        note="largest relative difference, $(K - \\sigma^2 M)^{-1}F$ against Lamb's sum over normal "
        "coordinates",
    )
    results.number(
        "forced_static_limit",
        values.static_limit,
        "1",
        note="the sum at $\\sigma = 0$ against the statical displacement $K^{-1}F$",
    )
    frame = values.resonance
    results.number(
        "resonance_residue_slope",
        values.residue_slope,
        "1",
        note="$(\\sigma_1^2 - \\sigma^2)y$ tends to the first mode's term as the detuning $\\delta$: "
        "fitted order of its deviation",
    )
    closest = frame.iloc[-1]
    results.number(
        "resonance_direct_error_at_closest",
        float(closest.direct_error),
        "1",
        note="$(K - \\sigma^2 M)^{-1}F$ in double precision at $\\delta = 10^{-10}$, against 50 digits",
    )
    results.hard_case(
        "resonance_normal",
        "Forced response $10^{-10}$ from the gravest resonance in normal "
        "coordinates, the detuning kept apart, against a 50-digit solve (mpmath)",
        float(frame.normal_error.max()),
        1e-12,
    )
    results.table(
        "resonance",
        frame,
        "Forced response near the gravest resonance (Lamb Art. 95): detuning "
        "$\\delta = 1 - \\sigma/\\sigma_1$, amplitude over the statical one, how far "
        "$(\\sigma_1^2 - \\sigma^2)y$ is from the first mode's term, and the relative error of the "
        "response in normal coordinates and by a direct solve, against 50 digits.",
        headers={
            "detuning": "$\\delta$",
            "amplitude_over_static": "$|y|/|y_0|$",
            "residue_deviation": "from mode 1",
            "normal_error": "normal coordinates",
            "direct_error": "direct solve",
        },
    )
    _record_transient(results, values.transient)
    _response_figure(results, values.fine, values.amplitude, values.sigma)


def detuned_response(sigma, phi, modal_force, delta):
    """Art. 95's sum over normal coordinates at sigma = sigma_1 (1 - delta): (response, sigma).

    Near the gravest resonance the response grows as 1/(sigma_1^2 - sigma^2), its shape the first mode's.
    sigma = sigma_1 (1 - delta) rounds sigma^2 to eps, so forming K - sigma^2 M loses eps/delta of the
    answer; in normal coordinates the detuning stays exact: sigma_1^2 - sigma^2 = sigma_1^2 delta (2 - delta).
    """
    s = sigma[0] * (1 - delta)
    gap = sigma**2 - s**2
    gap[0] = sigma[0] ** 2 * delta * (2 - delta)
    return phi @ (modal_force / gap), s


def _exact_lowest(built):
    """sigma_1 at 50 digits from the closed form the scene's chain has (sympy): the reference's resonance."""
    _, roots, values = symbolic.derive(built.masses, built.segment_stiffness, built.geometry.ends)
    exact = {symbol: symbolic.sp.Rational(value) for symbol, value in values.items()}  # a float: 15 digits
    return symbolic.sp.sqrt(roots[0].subs(exact)).evalf(60)


def _response_mp(built, sigma1, delta):
    """(K - sigma^2 M)^{-1} F at 50 digits, sigma = sigma_1 (1 - delta) with sigma_1 exact."""
    import mpmath

    with mpmath.workdps(50):
        K, M = _matrices(built)
        s = mpmath.mpf(str(sigma1)) * (1 - mpmath.mpf(delta))
        A = mpmath.matrix(K.tolist()) - s**2 * mpmath.matrix(M.tolist())
        y = mpmath.lu_solve(A, mpmath.matrix(built.force.tolist()))
        return np.array([float(v) for v in y])


def transient(built, sigma, phi, modal_force, spec) -> Transient:
    """Started from rest at detuning delta, y(t) = sum phi_k Theta_k (cos sigma t - cos sigma_k t)/(sigma_k^2
    - sigma^2). Written so the difference of cosines cancels; the product of sines keeps every digit."""
    delta = spec["transient_detuning"]
    s = sigma[0] * (1 - delta)
    t = np.linspace(0.0, spec["transient_periods"] * 2 * np.pi / sigma[0], 401)

    def naive(t):
        q = modal_force[:, None] * (np.cos(s * t) - np.cos(sigma[:, None] * t)) / (sigma[:, None] ** 2 - s**2)
        return phi @ q

    def stable(t):
        half_sum, half_diff = (sigma[:, None] + s) / 2, (sigma[:, None] - s) / 2
        q = (
            modal_force[:, None]
            * 2
            * np.sin(half_sum * t)
            * np.sin(half_diff * t)
            / ((sigma[:, None] - s) * (sigma[:, None] + s))
        )
        return phi @ q

    K, M = _matrices(built)
    n = len(sigma)
    forcing = np.concatenate([np.zeros(n), np.linalg.solve(M, built.force)])
    params = linear.pack(linear.state_matrix(K, M), forcing, s)
    run = solve(
        Problem(linear.linear_system, np.zeros(2 * n), (0.0, t[-1]), params),
        "dop853",
        t_eval=t,
        rtol=1e-13,
        atol=1e-16,
    )
    scale = np.max(np.abs(stable(t)))
    return Transient(
        delta,
        float(np.max(np.abs(run.y_eval[:, :n].T - stable(t))) / scale),
        float(np.max(np.abs(naive(t) - stable(t))) / scale),
    )


def _record_transient(results, values: Transient):
    delta = values.detuning
    results.number("transient_detuning", delta, "1")
    results.number(
        "transient_integrator_vs_closed_form",
        values.integrator_vs_closed_form,
        "1",
        note="DOP853 (scipy, rtol $10^{-13}$) against the product-of-sines form",
    )
    results.number(
        "transient_difference_of_cosines_error",
        values.difference_of_cosines_error,
        "1",
        note="the textbook difference of cosines against the product of sines: the digits cancellation loses",
    )
    exponent = int(round(np.log10(delta)))
    results.hard_case(
        "resonance_transient",
        f"Started from rest at detuning $\\delta = 10^{{{exponent}}}$: the "
        "closed form as a product of sines against DOP853",
        values.integrator_vs_closed_form,
        1e-8,
    )


def _response_figure(results, fine, amplitude, sigma):
    fig, ax = new_figure(FULL_WIDTH_IN, 3.4)  # five decades need height: about 0.5 in each
    for j, style in enumerate(("-", "--", ":")):
        ax.semilogy(fine / sigma[0], amplitude[:, j], style, lw=1.0, label=f"particle {j + 1}")
    for s in sigma:
        ax.axvline(s / sigma[0], color="0.7", lw=0.6, zorder=0)
    ax.set_xlabel("$\\sigma/\\sigma_1$")
    ax.set_ylabel("$|y_j|/|y_0|$")
    ax.set_ylim(1e-2, 1e3)
    ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, frameon=False)
    results.figure(
        "forced_response",
        fig,
        "Amplitude of each particle under a force $F\\cos\\sigma t$ on the "
        "first, over the statical displacement $|y_0|$ (Lamb Art. 95); grey lines mark the free "
        "frequencies, where it is infinite.",
    )


class Friction(NamedTuple):
    table: pd.DataFrame  # each scale and mode: frequency shift, decay against c_kk/2, 2nd-order remainder
    orders: dict  # each column's smallest fitted order in the scale over the modes
    frequency_shift_at_largest: float
    scale_largest: float


def friction(built, spec) -> Friction:
    """Arts. 96-97: a small dashpot changes each frequency at second order and sets the decay rate at first
    order, c_kk/2 in normal coordinates; sympy's second-order term leaves a third-order remainder."""
    K, M = _matrices(built)
    sigma, phi = _modes(built)
    n = len(sigma)
    C0 = phi.T @ np.diag(built.damping) @ phi  # the dissipation in normal coordinates, at scale 1
    shift = [symbolic.damped_frequency_shift(n, k) for k in range(n)]
    rows = []
    for eps in spec["scales"]:
        B = eps * np.diag(built.damping)
        lam = np.linalg.eigvals(linear.state_matrix(K, M, B))
        lam = np.sort_complex(lam[lam.imag > 0])
        lam = lam[np.argsort(lam.imag)]
        for k, (symbols, C, l1, l2) in enumerate(shift):
            values = {
                **dict(zip(symbols, sigma)),
                **{C[i, j]: eps * C0[i, j] for i in range(n) for j in range(n)},
            }
            first = complex(symbolic.sp.N(l1.subs(values)))
            second = complex(symbolic.sp.N(l2.subs(values)))
            rows.append(
                {
                    "scale": eps,
                    "mode": k + 1,
                    "frequency_shift": abs(lam[k].imag - sigma[k]) / sigma[k],
                    "decay_vs_first_order": abs(-lam[k].real - (-first.real)) / (-first.real),
                    "second_order_remainder": abs(lam[k] - (1j * sigma[k] + first + second)) / sigma[k],
                }
            )
    frame = pd.DataFrame(rows)
    orders = {}
    for column in ("frequency_shift", "decay_vs_first_order", "second_order_remainder"):
        slopes = [np.polyfit(np.log(g.scale), np.log(g[column]), 1)[0] for _, g in frame.groupby("mode")]
        orders[column] = float(min(slopes))
    return Friction(
        frame,
        orders,
        float(frame[frame.scale == max(spec["scales"])].frequency_shift.max()),
        float(max(spec["scales"])),
    )


def record_friction(results, values: Friction):
    for column, order in values.orders.items():
        results.number(
            f"{column}_order", order, "1", note="smallest fitted order in the friction scale over the modes"
        )
    results.number("frequency_shift_at_largest", values.frequency_shift_at_largest, "1")
    results.number("friction_scale_largest", values.scale_largest, "1")
    results.table(
        "friction",
        values.table,
        "Small friction (Lamb Arts. 96 and 97): at each scale of the dashpot, each "
        "mode's relative frequency change, its decay rate against the first-order $c_{kk}/2$, and what "
        "the second-order term derived with sympy leaves.",
        headers={
            "scale": "scale",
            "mode": "mode",
            "frequency_shift": "$|\\Delta\\sigma|/\\sigma$",
            "decay_vs_first_order": "decay rate vs $c_{kk}/2$",
            "second_order_remainder": "after 2nd order",
        },
    )


class InitialValue(NamedTuple):
    modal_vs_integrator: float  # largest difference over the largest displacement
    energy_sum_of_modes: float  # T + V against the sum of the modes' energies (relative)


def initial_value(built, spec) -> InitialValue:
    """Art. 91: any motion is the sum of the modes, each started by the mass-weighted projections of the
    initial state; Ex. XIV.1: its energy is the sum of the modes' energies. Against dop853 from a random start
    (seeded)."""
    K, M = _matrices(built)
    sigma, phi = _modes(built)
    n = len(sigma)
    rng = np.random.default_rng(spec["seed"])
    y0, v0 = rng.standard_normal(n), rng.standard_normal(n)
    a, b = phi.T @ M @ y0, phi.T @ M @ v0  # the normal coordinates and their rates at t = 0
    t = np.linspace(0.0, spec["periods"] * 2 * np.pi / sigma[0], 801)
    modal = phi @ (
        a[:, None] * np.cos(sigma[:, None] * t) + (b / sigma)[:, None] * np.sin(sigma[:, None] * t)
    )
    free = Problem(
        linear.linear_system, np.concatenate([y0, v0]), (0.0, t[-1]), linear.pack(linear.state_matrix(K, M))
    )
    run = solve(free, "dop853", t_eval=t, rtol=1e-13, atol=1e-14)
    energy = 0.5 * v0 @ M @ v0 + 0.5 * y0 @ K @ y0
    by_modes = float(np.sum(0.5 * b**2 + 0.5 * sigma**2 * a**2))
    return InitialValue(
        float(np.max(np.abs(run.y_eval[:, :n].T - modal)) / np.max(np.abs(modal))),
        abs(by_modes - energy) / energy,
    )


def record_initial_value(results, values: InitialValue):
    results.number(
        "initial_value_modal_vs_integrator",
        values.modal_vs_integrator,
        "1",
        note="the sum of modes against DOP853 (rtol $10^{-13}$), largest difference over the largest "
        "displacement",
    )
    results.number(
        "energy_sum_of_modes",
        values.energy_sum_of_modes,
        "1",
        note="$T + V$ against the sum of the modes' energies (relative)",
    )


class Dissipation(NamedTuple):
    balance: float  # T + V against its start less the work against friction (relative to the start)
    aperiodic_scale: float  # the dashpot raised past critical
    real_roots: int
    largest_real_root: float | None  # over the free sigma_1; None without a real root


def dissipation(built, scale) -> Dissipation:
    """Art. 96: the energy falls at the rate 2F, F = 1/2 q'^T B q' (Rayleigh's dissipation function), along a
    DOP853 run; Art. 97: past critical friction a root is real and negative, the motion aperiodic."""
    K, M = _matrices(built)
    sigma, _ = _modes(built)
    n = len(sigma)
    B = np.diag(built.damping)
    A = linear.state_matrix(K, M, B)
    t = np.linspace(0.0, 10 * 2 * np.pi / sigma[0], 401)
    work = np.zeros((2 * n, 2 * n))
    work[n:, n:] = B  # the last component integrates q'^T B q' = 2F: the work done against friction
    z0 = np.concatenate([np.ones(n), np.zeros(n), [0.0]])
    run = solve(
        Problem(linear.linear_system, z0, (0.0, t[-1]), linear.pack(A, work=work)),
        "dop853",
        t_eval=t,
        rtol=1e-13,
        atol=1e-14,
    )
    q, v, lost = run.y_eval[:, :n].T, run.y_eval[:, n:-1].T, run.y_eval[:, -1]
    energy = 0.5 * np.einsum("it,ij,jt->t", v, M, v) + 0.5 * np.einsum("it,ij,jt->t", q, K, q)
    lam = np.linalg.eigvals(linear.state_matrix(K, M, scale * B))
    real = lam[np.abs(lam.imag) <= 1e-12 * np.abs(lam).max()].real
    return Dissipation(
        float(np.max(np.abs(energy - (energy[0] - lost))) / energy[0]),
        scale,
        int(real.size),
        float(real.max()) / sigma[0] if real.size else None,
    )


def record_dissipation(results, values: Dissipation):
    results.number(
        "dissipation_balance",
        values.balance,
        "1",
        note="$T + V$ along DOP853 against its start less $\\int 2F\\,dt$ (relative to the start)",
    )
    results.number("aperiodic_scale", values.aperiodic_scale, "1", note="the dashpot raised past critical")
    results.number("aperiodic_real_roots", values.real_roots, "1")
    results.number(
        "aperiodic_largest_real_root",
        values.largest_real_root,
        "1",
        note="over the free $\\sigma_1$; negative: the displacements decay without oscillation",
    )
