"""Hard cases of the solver layer, measured: separatrix, intermediate axis, blow-up, numerical damping."""

from __future__ import annotations

from typing import NamedTuple

import mpmath
import numpy as np
import pandas as pd
from scipy import special

from ...figure_style import legend_below
from ...formatting import format_number, power_of_ten, shortest
from ...models import linear
from ...models import rigid_body as rhs
from ...results import new_figure
from ...solvers import references as ref
from ...solvers import rigid_body
from ...solvers.fixed_step import FixedProblem, Save, solve_fixed
from ...solvers.ode import Problem, solve


def tenth_power(value) -> str:
    """1e-9 as 10⁻⁹ (a tolerance is a power of ten)."""
    return power_of_ten(round(np.log10(value)))


def run(scene, results, quick):
    numerics = scene.data.get("numerics", {})
    _record_separatrix(results, separatrix(numerics.get("separatrix_one_minus_m", 1e-10), quick))
    _record_intermediate_axis(results, intermediate_axis())
    _record_blow_up(results, blow_up())
    _record_lee_cases(results, lee_cases())
    _record_numerical_damping(results, numerical_damping())
    _record_energy_kept(results, energy_kept())
    _record_rotations(results, rotations())


class Separatrix(NamedTuple):
    one_minus_m: float
    ellipj_error_ours: float  # over [0, 4K] against mpmath at 30 digits
    ellipj_error_scipy: float  # scipy.special.ellipj as it is
    period: float
    dop853_energy_error: float  # rtol 1e-12, relative
    splitting_energy_error: float  # order 4, h = 0.005
    splitting_casimir_error: float
    casimir_over_brouwer: float  # the Casimir error over 10 sqrt(N) eps, N exact rotations
    reference_vs_dop853: float  # the reference against DOP853 at rtol 1e-13 over half a period (rad/s)


def separatrix(one_minus_m, quick) -> Separatrix:
    """I = (1, 2, 3), omega0 = (x, 0, 1): m = x^2 / 3, so x = sqrt(3 m) puts m = 1 - one_minus_m."""
    m = 1.0 - one_minus_m
    I = np.array([1.0, 2.0, 3.0])
    w0 = np.array([np.sqrt(3 * m), 0.0, 1.0])
    K = special.ellipk(m)
    u = np.linspace(0, 4 * K, 33)
    ours = np.stack(ref.ellipj(u, m)[:3], axis=1)
    raw = np.stack(special.ellipj(u, m)[:3], axis=1)
    with mpmath.workdps(30):
        exact = np.array(
            [
                [float(mpmath.ellipfun(f, mpmath.mpf(x), m=mpmath.mpf(m))) for f in ("sn", "cn", "dn")]
                for x in u
            ]
        )
    err_ours, err_raw = np.max(np.abs(ours - exact)), np.max(np.abs(raw - exact))
    # the body on the separatrix side: integrators stay on the energy surface over a few periods
    rate = np.sqrt((I[2] - I[1]) * (np.sum((I * w0) ** 2) - np.sum(I * w0 * w0) * I[0]) / np.prod(I))
    period = 4 * K / rate
    T = (2 if quick else 4) * period
    H0 = 0.5 * np.sum(I * w0 * w0)
    C0 = np.sum((I * w0) ** 2)
    sol = solve(
        Problem(rhs.euler_free, w0, (0.0, T), rhs.euler_coefficients(I)),
        "dop853",
        rtol=1e-12,
        atol=1e-15,
        record_steps=True,
    )
    dH = np.max(np.abs(0.5 * np.sum(I * sol.y_steps**2, axis=1) - H0)) / H0
    problem = FixedProblem(rigid_body.packed(I * w0), I)
    ms = solve_fixed(
        problem, "rigid-splitting4", h=0.005, n_steps=int(T / 0.005), save=Save(every=10)
    ).y_eval[:, :3]
    dC = np.max(np.abs(np.sum(ms * ms, axis=1) - C0)) / C0
    dHs = np.max(np.abs(0.5 * np.sum(ms * ms / I, axis=1) - H0)) / H0
    rotations = 15 * int(T / 0.005)
    # the reference itself against an independent integration, half a period (errors grow like e^{rate t})
    t = np.linspace(0, period / 2, 9)
    check = solve(
        Problem(rhs.euler_free, w0, (0.0, t[-1]), rhs.euler_coefficients(I)),
        "dop853",
        rtol=1e-13,
        atol=1e-16,
        t_eval=t,
    )
    return Separatrix(
        one_minus_m,
        err_ours,
        err_raw,
        period,
        dH,
        dHs,
        dC,
        dC / (10 * np.sqrt(rotations) * np.finfo(float).eps),
        float(np.max(np.abs(ref.free_rigid_body(I, I * w0, t) - check.y_eval))),
    )


def _record_separatrix(results, values: Separatrix):
    one_minus_m, err_ours, err_raw = values.one_minus_m, values.ellipj_error_ours, values.ellipj_error_scipy
    dH, dHs, dC = values.dop853_energy_error, values.splitting_energy_error, values.splitting_casimir_error
    results.number("separatrix_one_minus_m", one_minus_m, "1")
    results.number(
        "separatrix_ellipj_error_ours",
        err_ours,
        "1",
        note="largest absolute error of sn, cn, dn over [0, 4K] against mpmath, 30 digits",
    )
    results.number(
        "separatrix_ellipj_error_scipy",
        err_raw,
        "1",
        note="scipy.special.ellipj as it is (#8480): largest absolute error of sn, cn, dn",
    )
    distance = shortest(one_minus_m).removeprefix("1 × ")  # 10⁻¹⁰, not 1 × 10⁻¹⁰
    results.hard_case(
        "separatrix_reference",
        f"Jacobi's elliptic functions at $m$ = 1 − {distance} "
        f"against mpmath at 30 digits, largest error over a period (SciPy's own ellipj is off by "
        f"{format_number(err_raw, 2)} there)",
        err_ours,
        1e-13,
    )
    results.number("separatrix_period", values.period, "time units")
    results.number("separatrix_dop853_energy_error", dH, "1", note="rtol 1e-12")
    results.number("separatrix_splitting_energy_error", dHs, "1", note="order 4, h = 0.005")
    results.number("separatrix_splitting_casimir_error", dC, "1")
    results.hard_case(
        "separatrix_energy_surface",
        "Near the separatrix DOP853 (relative tolerance "
        f"{tenth_power(1e-12)}) stays on the energy surface (relative energy error)",
        dH,
        1e-10,
    )
    results.hard_case(
        "separatrix_casimir",
        "Near the separatrix the splitting keeps the Casimir $|\\mathbf{m}|^2$ "
        "to round-off: its relative error over $10\\sqrt{N}\\,\\varepsilon$ ($N$ exact rotations, "
        "$\\varepsilon$ the machine epsilon)",
        values.casimir_over_brouwer,
        1.0,
    )
    results.number(
        "separatrix_reference_vs_dop853",
        values.reference_vs_dop853,
        "rad/s",
        note="half a period; the separatrix amplifies any error like e^{rate t}",
    )


class IntermediateAxis(NamedTuple):
    measured: float  # growth rate of a perturbation, fitted in the linear regime (1/time)
    theory: float  # q0 sqrt((A - B)(B - C)/(AC))


def intermediate_axis() -> IntermediateAxis:
    """Spin q0 about the middle axis: perturbations grow like exp(q0 sqrt((A-B)(B-C)/(AC)) t)."""
    A, B, C = 3.0, 2.0, 1.0
    q0 = 1.0
    theory = q0 * np.sqrt((A - B) * (B - C) / (A * C))
    w0 = np.array([1e-10, q0, 1e-10])
    t = np.linspace(0, 30, 601)
    sol = solve(
        Problem(rhs.euler_free, w0, (0.0, 30.0), rhs.euler_coefficients(np.array([A, B, C]))),
        "dop853",
        rtol=1e-12,
        atol=1e-20,
        t_eval=t,
    )
    size = np.hypot(sol.y_eval[:, 0], sol.y_eval[:, 2])
    window = (size > 1e-8) & (size < 1e-3)
    measured = np.polyfit(t[window], np.log(size[window]), 1)[0]
    return IntermediateAxis(measured, theory)


def _record_intermediate_axis(results, values: IntermediateAxis):
    measured, theory = values
    results.number(
        "intermediate_axis_growth_rate", measured, "1/time", note="fit of log|(w1, w3)| in the linear regime"
    )
    results.number("intermediate_axis_growth_theory", theory, "1/time", note="q0 sqrt((A-B)(B-C)/(AC))")
    results.hard_case(
        "intermediate_axis",
        "Spin about the middle axis: the measured growth rate of a "
        "perturbation against $q_0\\sqrt{(A - B)(B - C)/(AC)}$ (relative difference)",
        abs(measured / theory - 1),
        1e-3,
    )


def blow_up() -> pd.DataFrame:
    """p' = m + mu p^2 from four starts: where the run stops against the closed-form blow-up time."""
    rows = []
    for m, mu, p0 in ((1.0, 1.0, 0.0), (0.5, -0.2, -2.0), (-0.3, -0.5, 0.4), (0.0, 0.7, 1.5)):
        exact = ref.riccati_blow_up_time(m, mu, p0)
        sol = solve(Problem(rhs.riccati, [p0], (0.0, 2 * exact), [m, mu]), "dop853", rtol=1e-10, atol=1e-12)
        rows.append(
            {
                "m": m,
                "mu": mu,
                "p0": p0,
                "t_star_closed_form": exact,
                "t_star_measured": sol.t,
                "status": sol.status,
                "relative_difference": sol.t / exact - 1,
            }
        )
    return pd.DataFrame(rows)


def _record_blow_up(results, frame: pd.DataFrame):
    results.table(
        "blow_up",
        frame,
        "Finite-time blow-up of $\\dot p = m + \\mu p^2$ (Lee (2.4)): the time at "
        "which the run stops ($|p|$ passes 10¹²) against the closed form $t^*$, dop853 at relative "
        f"tolerance {tenth_power(1e-10)}. The stop comes about $1/(|\\mu|\\,10^{{12}})$ before $t^*$, "
        "within the tolerance's error; the claims' runs of Lee's cases, at relative tolerance "
        f"{tenth_power(1e-12)}, stop at slightly different times for the same reason.",
        headers={
            "m": "$m$",
            "mu": "$\\mu$",
            "p0": "$p_0$",
            "t_star_closed_form": "$t^*$, closed form",
            "t_star_measured": "$t^*$, measured",
            "status": "status",
            "relative_difference": "relative difference",
        },
    )
    worst = float(frame.relative_difference.abs().max())
    results.number("blow_up_worst_relative_difference", worst, "1")
    results.number(
        "blow_up_lee_case_t_star",
        float(frame.t_star_measured.iloc[1]),
        "time units",
        note="m = 0.5, mu = -0.2, p0 = -2",
    )
    results.hard_case(
        "blow_up",
        "Blow-up reported with its time (status “blow-up”, not NaN, not a hang): "
        "relative difference to the closed-form blow-up time $t^*$",
        worst,
        1e-9,
    )


# Lee (2.4): the six cases of p' = m + mu p^2 (q0 = r0 = 0), each start chosen inside its case.
LEE_CASES = (
    ("i", 0.6, 0.3, 0.5),
    ("ii", 0.5, -0.2, 0.3),
    ("iii_tanh", -0.4, 0.3, 0.2),
    ("iii", -0.4, 0.3, 2.0),
    ("iv", -0.3, -0.5, 0.4),
    ("v", 0.7, 0.0, -1.0),
    ("vi", 0.0, 0.7, 1.5),
)
LEE_CASE_SPAN = 3.0  # time units, or 0.9 t* where the case blows up sooner


class LeeCase(NamedTuple):
    name: str
    m: float
    mu: float
    p0: float
    span: float  # of the comparison
    difference: float  # largest |p - closed form|/max(|p|, |p0|, k)
    t_star: float | None  # where the run stops (inf if it does not blow up); None where p stays bounded


def lee_cases() -> list[LeeCase]:
    """Each closed form of Lee (2.4) against DOP853 (relative tolerance 1e-12) on 31 times of [0, min(3, 0.9
    t*)], the difference relative to max(|p|, |p0|, k) (p may pass zero); and where p leaves every bound, the
    time the run stops (|p| passes 1e12, within 1e-12 of the pole) as the measured blow-up time."""
    cases = []
    for name, m, mu, p0 in LEE_CASES:
        t_star = ref.riccati_blow_up_time(m, mu, p0)
        span = min(LEE_CASE_SPAN, 0.9 * t_star)
        t = np.linspace(0.0, span, 31)
        sol = solve(
            Problem(rhs.riccati, [p0], (0.0, span), [m, mu]), "dop853", rtol=1e-12, atol=1e-14, t_eval=t
        )
        closed = ref.riccati(m, mu, p0, t)
        k = np.sqrt(abs(m / mu)) if m and mu else 0.0
        scale = np.maximum(np.abs(closed), max(abs(p0), k))
        difference = float(np.max(np.abs(sol.y_eval[:, 0] - closed) / scale))
        stop = None
        if np.isfinite(t_star):
            run = solve(
                Problem(rhs.riccati, [p0], (0.0, 2 * t_star), [m, mu]), "dop853", rtol=1e-12, atol=1e-14
            )
            stop = run.t if run.status == "blow-up" else np.inf
        cases.append(LeeCase(name, m, mu, p0, span, difference, stop))
    return cases


def _record_lee_cases(results, cases: list[LeeCase]):
    worst = 0.0
    for name, m, mu, p0, span, difference, t_star in cases:
        worst = max(worst, difference)
        results.number(
            f"lee_case_{name}_closed_form_difference",
            difference,
            "1",
            note=(
                f"m = {m}, mu = {mu}, p0 = {p0}: largest |p − closed form|/max(|p|, |p0|, k) on [0, "
                f"{span:.4g}]"
            ),
        )
        if t_star is not None:
            results.number(
                f"lee_case_{name}_t_star",
                t_star,
                "time units",
                note=f"m = {m}, mu = {mu}, p0 = {p0}: where the run stops, |p| past 10^12",
            )
    results.number(
        "lee_cases_worst_difference", worst, "1", note="the largest of the seven runs' differences"
    )
    results.hard_case(
        "lee_cases",
        "The closed forms of Lee (2.4), cases (i)–(vi), against the integrated "
        "$\\dot p = m + \\mu p^2$ (largest relative difference)",
        worst,
        1e-10,
    )


def _apparent_q(change, periods):
    """The quality factor an energy change of `change` over `periods` would be mistaken for; negative where
    the method pumps energy in (the Chandler wobble's table counts it the same way)."""
    return -2 * np.pi * periods / change if change else np.inf


class Damping(NamedTuple):
    periods: int
    frame: pd.DataFrame  # per method and tolerance or step: the energy change and the Q it would be taken for


def numerical_damping(periods: int = 100) -> Damping:
    """An undamped oscillator over `periods` periods: the energy each method loses, as a spurious Q."""
    T = periods * 2 * np.pi
    problem = Problem(rhs.oscillator, [1.0, 0.0], (0.0, T), [1.0])
    rows = []
    for method in (
        "dop853",
        "dopri5",
        "scipy:RK45",
        "scipy:DOP853",
        "scipy:Radau",
        "scipy:BDF",
        "scipy:LSODA",
    ):
        for rtol in (1e-6, 1e-9):
            sol = solve(problem, method, rtol=rtol, atol=rtol * 1e-3)
            change = 0.5 * (sol.y[0] ** 2 + sol.y[1] ** 2) / 0.5 - 1
            rows.append(
                {
                    "method": method,
                    "kind": "tolerance",
                    "setting": rtol,
                    "energy_change": change,
                    "spurious_Q": _apparent_q(change, periods),
                }
            )
    for h in (2 * np.pi / 20, 2 * np.pi / 100):
        n = int(round(T / h))
        oscillator = FixedProblem([1.0, 0.0], [1.0], linear.harmonic_force)
        q, v = solve_fixed(oscillator, "stormer-verlet", h=h, n_steps=n, save=Save(final=True)).y
        change = 0.5 * (q**2 + v**2) / 0.5 - 1
        rows.append(
            {
                "method": "Störmer–Verlet",
                "kind": "step",
                "setting": h,
                "energy_change": change,
                "spurious_Q": np.nan,  # its energy error is bounded and oscillates: no decay, no Q
            }
        )
    return Damping(periods, pd.DataFrame(rows))


def _record_numerical_damping(results, values: Damping):
    periods, frame = values
    results.table(
        "numerical_damping",
        frame,
        f"An undamped oscillator over {periods} periods: the relative change of its "
        "energy, and the quality factor it would be mistaken for, $Q = -2\\pi n/(\\Delta E/E)$ after $n$ "
        "periods (negative change: energy lost; negative $Q$: the method pumps energy in, as in the Chandler "
        "wobble's table). The adaptive methods at two relative tolerances, Störmer–Verlet at two steps "
        "$h$ (its energy error is bounded and oscillates, so it has no $Q$: the change is where the run "
        "ends).",
        headers={
            "method": "method",
            "kind": "setting",
            "setting": "rtol or step $h$",
            "energy_change": "$\\Delta E/E$",
            "spurious_Q": "apparent $Q$",
        },
    )
    bdf = frame[(frame.method == "scipy:BDF") & (frame.setting == 1e-6)].iloc[0]
    results.number("bdf_spurious_Q_rtol_1e-6", bdf.spurious_Q, "1")
    results.number("bdf_energy_change_rtol_1e-6", bdf.energy_change, "1")
    verlet = frame[frame.method == "Störmer–Verlet"]
    results.number(
        "verlet_worst_energy_change",
        float(verlet.energy_change.abs().max()),
        "1",
        note="bounded, oscillating; sampled at the end of the run",
    )
    fig, ax = new_figure(height=3.0)
    adaptive = frame[frame.method != "Störmer–Verlet"]
    methods = list(dict.fromkeys(adaptive.method))
    x = np.arange(len(methods))
    for (rtol, part), marker in zip(sorted(adaptive.groupby("setting"), key=lambda g: -g[0]), ("s", "o")):
        ax.semilogy(
            [methods.index(m) for m in part.method],
            np.abs(part.energy_change),
            marker,
            ms=4,
            color="0.15" if marker == "s" else "#E69F00",
            label=f"relative tolerance {tenth_power(rtol)}",
        )
    # named as in the table and every other solver figure: dop853, dopri5 (this library's compiled pairs) and
    # scipy:DOP853 ... (SciPy's solve_ivp), the prefix on a line of its own so the seven names stand apart
    ax.set_xticks(x, [m.replace("scipy:", "scipy:\n") for m in methods])
    ours = [not m.startswith("scipy:") for m in methods]
    split = ours.index(False) if False in ours else len(ours)
    if 0 < split < len(ours) and not any(ours[split:]):  # ours first, then SciPy's: a line between
        ax.axvline(split - 0.5, color="0.6", lw=0.6)
    ax.set_xlim(-0.5, len(methods) - 0.5)
    ax.set_ylabel("$|\\Delta E/E|$ after 100 periods")
    ax.grid(False, axis="x", which="both")
    legend_below(fig, ncol=2)  # below the axes: clear of the points and of the grey line
    results.figure(
        "numerical_damping",
        fig,
        "The relative energy change $|\\Delta E/E|$ of an undamped oscillator "
        "after 100 periods, by adaptive method, at two relative tolerances: left of the grey line this "
        "library's compiled pairs dop853 and dopri5, right of it SciPy's integrators (scipy:DOP853 is "
        "SciPy's own DOP853, not ours), named as in the table. Every method changes the "
        "energy, most of them by losing it; BDF loses the most. A physical quality factor $Q$ must be "
        "measured well above this numerical floor.",
    )


class EnergyKept(NamedTuple):
    hamilton_exact: int  # 1: sympy reduces Hamilton's equations to m x'' + k x = 0 and dH/dt = 0
    midpoint_energy_change: dict  # lagrangian, hamiltonian -> largest relative change of E over 100 periods


def energy_kept() -> EnergyKept:
    """The oscillator's energy is a first integral (notes: L has no t; handbook Ex. 2.5: H has no t). The
    implicit midpoint rule keeps every quadratic first integral of a linear system exactly (up to rounding),
    so E, kept by it over 100 periods, is one; sympy checks Hamilton's equations give m x'' + k x = 0, dH/dt =
    0."""
    import sympy as sp

    x, p, m, k, t = sp.symbols("x p m k t", positive=True)
    H = p**2 / (2 * m) + k * x**2 / 2
    xdot, pdot = sp.diff(H, p), -sp.diff(H, x)
    newton = sp.simplify(m * sp.diff(xdot, p) * pdot + k * x) == 0  # m x'' = m (d/dt)(p/m) = p' = -k x
    conserved = sp.simplify(sp.diff(H, x) * xdot + sp.diff(H, p) * pdot) == 0 and sp.diff(H, t) == 0
    changes = {}
    mass, stiffness = 2.0, 3.0
    omega = np.sqrt(stiffness / mass)
    for name, A, z0, energy in (
        (
            "lagrangian",
            np.array([[0.0, 1.0], [-stiffness / mass, 0.0]]),
            np.array([1.0, 0.3]),
            lambda z: 0.5 * mass * z[1] ** 2 + 0.5 * stiffness * z[0] ** 2,
        ),
        (
            "hamiltonian",
            np.array([[0.0, 1 / mass], [-stiffness, 0.0]]),
            np.array([1.0, 0.6]),
            lambda z: z[1] ** 2 / (2 * mass) + 0.5 * stiffness * z[0] ** 2,
        ),
    ):
        h = 2 * np.pi / omega / 20
        step = np.linalg.solve(np.eye(2) - 0.5 * h * A, np.eye(2) + 0.5 * h * A)  # implicit midpoint
        z, e0, worst = z0.copy(), energy(z0), 0.0
        for _ in range(100 * 20):
            z = step @ z
            worst = max(worst, abs(energy(z) / e0 - 1))
        changes[name] = float(worst)
    return EnergyKept(int(newton and conserved), changes)


def _record_energy_kept(results, values: EnergyKept):
    results.number(
        "spring_hamilton_equations_exact",
        values.hamilton_exact,
        "1",
        note="1: Hamilton's equations of $H = p^2/2m + kx^2/2$ give $m\\ddot x + kx = 0$, and "
        "$dH/dt = \\partial H/\\partial t = 0$ (sympy)",
    )
    for name, worst in values.midpoint_energy_change.items():
        variables = "$x$, $\\dot x$" if name == "lagrangian" else "$x$, $p$"
        results.number(
            f"oscillator_{name}_midpoint_energy_change",
            worst,
            "1",
            note="largest relative change of $E$ over 100 periods, 20 implicit midpoint steps a period "
            f"({variables}; $m$ = 2, $k$ = 3)",
        )


class Rotations(NamedTuple):
    trace_identity: float  # largest |Tr R - (1 + 2 cos phi)|, also after R -> B R B^T
    orthogonality: float  # largest entry of R R^T - 1, the handbook's R (Ex. 2.2)
    axis_misalignment: float  # 1 - |cos| of its eigenvector of eigenvalue 1 against (1, 0, 1)/sqrt2
    rotvec_misalignment: float  # the same for scipy's rotation vector
    angle_deg: float  # scipy's rotation angle
    angle_from_trace_deg: float  # arccos((Tr R - 1)/2)


def rotations(seed=22) -> Rotations:
    """Handbook 2.2.1.1: Tr A = 1 + 2 cos phi in any axes; Ex. 2.2: the printed R, its axis and its angle.
    scipy's Rotation (quaternions) is the reference for the angle and the axis."""
    from scipy.spatial.transform import Rotation

    rotations = Rotation.random(1000, random_state=seed)
    others = Rotation.random(1000, random_state=seed + 1)
    R, B = rotations.as_matrix(), others.as_matrix()
    phi = rotations.magnitude()
    trace = np.trace(R, axis1=1, axis2=2)
    similar = np.trace(B @ R @ np.transpose(B, (0, 2, 1)), axis1=1, axis2=2)
    worst = float(
        max(np.max(np.abs(trace - (1 + 2 * np.cos(phi)))), np.max(np.abs(similar - (1 + 2 * np.cos(phi)))))
    )
    r6 = np.sqrt(6.0)
    printed = np.array([[3, r6, 1], [-r6, 2, r6], [1, -r6, 3]]) / 4
    lam, vectors = np.linalg.eig(printed)
    axis = np.real(vectors[:, np.argmin(np.abs(lam - 1))])
    expected = np.array([1.0, 0.0, 1.0]) / np.sqrt(2)
    rotvec = Rotation.from_matrix(printed).as_rotvec()
    return Rotations(
        worst,
        float(np.max(np.abs(printed @ printed.T - np.eye(3)))),
        float(1 - abs(axis @ expected) / np.linalg.norm(axis)),
        float(1 - abs(rotvec @ expected) / np.linalg.norm(rotvec)),
        float(np.degrees(Rotation.from_matrix(printed).magnitude())),
        float(np.degrees(np.arccos((np.trace(printed) - 1) / 2))),
    )


def _record_rotations(results, values: Rotations):
    results.number(
        "rotation_trace_identity",
        values.trace_identity,
        "1",
        note="largest $|\\mathrm{Tr}\\,R - (1 + 2\\cos\\varphi)|$ over 1000 random rotations, also "
        "after $R \\to BRB^{\\mathsf T}$ ($\\varphi$ from scipy's quaternions)",
    )
    results.number(
        "ex2_2_orthogonality",
        values.orthogonality,
        "1",
        note="largest entry of $RR^{\\mathsf T} - 1$, the handbook's $R$",
    )
    results.number(
        "ex2_2_axis_misalignment",
        values.axis_misalignment,
        "1",
        note="$1 - |\\cos|$ of the angle between the eigenvector of eigenvalue 1 and $(1, 0, 1)/\\sqrt2$",
    )
    results.number(
        "ex2_2_rotvec_misalignment",
        values.rotvec_misalignment,
        "1",
        note="the same for scipy's rotation vector",
    )
    results.number(
        "ex2_2_angle_deg", values.angle_deg, "°", note="scipy's rotation angle of the handbook's $R$"
    )
    results.number(
        "ex2_2_angle_from_trace_deg",
        values.angle_from_trace_deg,
        "°",
        note="$\\arccos((\\mathrm{Tr}\\,R - 1)/2)$",
    )
