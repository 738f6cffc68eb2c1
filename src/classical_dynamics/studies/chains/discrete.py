"""Discrete chains: n particles on light links or springs, and n uniform rigid links."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd
import scipy.linalg as sla

from ...figure_style import FULL_WIDTH_IN, legend_below
from ...formatting import format_number
from ...lazy import lazy_module
from ...models.chains import (
    RESTORING,
    continuum_frequencies,
    exact_discrete_frequencies,
    frequency_unit,
    particle_chain,
    rigid_links_matrices,
)
from ...provenance import software_stamp
from ...results import new_figure, subplots
from ...solvers import chain_eigen
from ...solvers.special import bessel_j0_zeros, laguerre_lowest_zero_asymptotic, laguerre_zero_mp
from ...solvers.timing import min_time
from . import small_oscillations as so

symbolic = lazy_module(f"{__package__}.symbolic")  # sympy, for the scenes that ask for a closed form


SOLVER_LIMITS = chain_eigen.SOLVER_LIMITS
QUICK_MAX_N = 1024  # a quick run's sweeps stop here: past it a dense solver takes seconds a size

# What the reader sees: each frequency unit typeset, each solver and scheme by name and in one colour in
# every figure (Okabe-Ito).
UNIT_MATH = {
    "sqrt_g_over_l": "$\\sqrt{g/l}$",
    "over_omega": "$\\omega$",
    "over_fundamental": "$(\\pi/l)\\sqrt{P/\\rho}$",
    "sqrt_k_over_m": "$\\sqrt{k/m}$",
}
SOLVERS = {
    "dense": ("dense (LAPACK)", "#56B4E9", "^"),
    "tridiagonal": ("tridiagonal (LAPACK)", "#CC79A7", "s"),
    "tridiagonal_select": ("tridiagonal, lowest only (LAPACK)", "#D55E00", "o"),
    "pliability": ("pliability (factored)", "#0072B2", "D"),
}
# scheme -> (legend label, colour, the order it should converge at: its reference slope)
SCHEMES = {
    "plain": (r"$l = na$", "#E69F00", 1),
    "end": (r"$l = (n + \frac{1}{2})a$", "#009E73", 2),
    "richardson": (r"Richardson, $n/2$ and $n$", "#000000", 4),
    "links": (r"rigid links, $l = na$", "#CC79A7", 2),
}


def _solver_line(ax, method, n, y):
    """One solver's line: its colour and marker in every figure; open markers show lines that coincide."""
    label, colour, marker = SOLVERS.get(method, (method, None, "o"))
    ax.loglog(
        n,
        y,
        marker=marker,
        ms=4.5 if marker == "^" else 3.5,
        mfc="none" if marker in "^s" else colour,
        color=colour,
        lw=1.0,
        label=label,
        zorder=3 if marker in "^s" else 2,  # an open marker over a filled one, where two solvers agree
    )


def _scheme(name: str) -> str:
    """The scheme a row or route belongs to, from its name."""
    lowered = name.lower()
    for key, words in (
        ("richardson", "richardson"),
        ("links", "links"),
        ("end", "+ 1/2"),
        ("end", "end-corrected"),
    ):
        if words in lowered:
            return key
    return "plain"


def _masses(chain, n):
    return np.asarray(chain["masses_kg"], float) if "masses_kg" in chain else np.full(n, chain["mass_kg"] / n)


def _relative(values, reference):
    reference = np.asarray(reference, float)
    out = np.full(len(values), np.nan)
    nonzero = reference > 0
    out[nonzero] = (np.asarray(values)[nonzero] - reference[nonzero]) / reference[nonzero]
    return [None if np.isnan(v) else float(v) for v in out]


def links_frequencies(n: int, k: int):
    """omega / sqrt(g/l) for n rigid links (l = n a), lowest k."""
    K, M = rigid_links_matrices(n)
    lam = sla.eigh(K, M, eigvals_only=True, subset_by_index=[0, min(k, n) - 1])
    return np.sqrt(lam * n)


def hanging_particles_scaled(n: int, k: int, method: str = "pliability"):
    """lambda = omega^2 a / g of the uniform hanging chain of n particles (g = a = m = 1)."""
    s = np.arange(n, 0, -1.0)
    return chain_eigen.lowest_eigenvalues(s, None, np.ones(n), "fixed-free", k, method)


class ZeroMode(NamedTuple):
    rigid_name: str  # the rigid motion the zero mode should be
    eigenvalue_relative: float  # |lambda_0|/lambda_max before clipping
    misalignment: float  # 1 - |cos| of the angle between the zero mode and the rigid motion


class Spectrum(NamedTuple):
    built: object | None  # the ParticleChain; None for rigid links
    effects: dict  # the effects the free frequencies see
    values: np.ndarray  # the frequencies (rad/s)
    unit: float
    unit_name: str
    unit_label: str
    exact: np.ndarray | None  # the discrete chain's closed form
    continuum: np.ndarray | None
    shapes: np.ndarray | None
    zero_mode: ZeroMode | None  # where the chain has a neutral motion


def spectrum(chain, effects, k) -> Spectrum:
    """The lowest k free frequencies of the scene's chain, beside the continuum's and the closed form."""
    model, n = chain["model"], chain["n"]
    ends = chain.get("ends", "fixed-free")
    length = chain["length_m"]
    masses = _masses(chain, n)
    total = float(masses.sum())
    built, exact, shapes, zero = None, None, None, None
    if model == "links":
        omega_unit = np.sqrt(effects["gravity"]["g_m_per_s2"] / length)
        values = links_frequencies(n, k) * omega_unit
        unit, unit_name, unit_label = omega_unit, "sqrt_g_over_l", "√(g/l)"
    else:
        built = particle_chain(n, ends, length, masses, effects)
        # the free frequencies' effects
        effects = {name: p for name, p in effects.items() if name in RESTORING}
        lam, shapes = chain_eigen.modes(built.segment_stiffness, built.diagonal, built.masses, ends, k)
        zero_floor = 1e-12 * np.max(np.abs(lam)) if lam.size else 0.0
        clipped = np.where(np.abs(lam) <= zero_floor, 0.0, lam)
        if np.any(clipped < 0):
            raise RuntimeError(f"negative eigenvalue {clipped.min():.3g}: the chain is unstable")
        values = np.sqrt(clipped)
        unit, unit_name, unit_label = frequency_unit(
            effects, length, total, built.geometry.spacing_m, masses[0]
        )
        exact = exact_discrete_frequencies(built, effects, k)
        if np.any(np.abs(lam) <= zero_floor):
            # the neutral motion: a translation of a free chain, a rigid turn (y ~ r) of a whirling one
            rigid = built.geometry.positions_m if "rotation" in effects else np.ones(n)
            zero = zero_mode(
                lam,
                shapes,
                rigid,
                "rigid rotation ($y \\propto r$)" if "rotation" in effects else "rigid translation",
            )
    cont = continuum_frequencies(effects, ends, length, total, len(values), n=n)
    return Spectrum(built, effects, values, unit, unit_name, unit_label, exact, cont, shapes, zero)


def run(scene, results, quick):
    data = scene.data
    chain, analysis = data["chain"], data.get("analysis", {})
    model, n, k = chain["model"], chain["n"], analysis.get("modes", 5)
    ends = chain.get("ends", "fixed-free")
    masses = _masses(chain, n)
    results.number("n", n, model)
    found = spectrum(chain, data["effects"], k)
    built, effects, values, shapes = found.built, found.effects, found.values, found.shapes
    if found.zero_mode is not None:
        _record_zero_mode(results, found.zero_mode)
    _record_frequencies(results, found, n, model)
    if "closed_form" in analysis:
        name = analysis["closed_form"]
        _record_closed_form(results, closed_form(masses, built.segment_stiffness, ends, name, values))
        if name in symbolic.SOURCE_SHAPES:
            so.record_printed_shapes(results, so.printed_shapes(built, masses, name))
    if "closed_form" in analysis or "constraint" in analysis:
        so.record_orthogonality(results, so.orthogonality(built))
    if analysis.get("separation"):
        so.record_separation(results, so.separation(built))
    if analysis.get("rayleigh_symmetric"):
        so.record_rayleigh_symmetric(results, so.rayleigh_symmetric(built, masses))
    if "constraint" in analysis:
        spec = analysis["constraint"]
        so.record_constraint(results, so.constraint(built, spec["samples"], spec["seed"]))
    if "forced" in analysis:
        so.record_forced(results, so.forced(built, analysis["forced"]))
    if "friction" in analysis:
        so.record_friction(results, so.friction(built, analysis["friction"]))
        so.record_dissipation(results, so.dissipation(built, analysis["friction"]["aperiodic_scale"]))
    if analysis.get("parabola_type"):
        _record_parabola(results, float(symbolic.string_parabola_quotient()))
    if "continuum_limit" in analysis:
        n_values = analysis["continuum_limit"]["n_values"]
        _record_continuum_limit(results, continuum_limit(chain, effects, ends, n_values))
    if "initial_value" in analysis:
        so.record_initial_value(results, so.initial_value(built, analysis["initial_value"]))
    if analysis.get("stability"):
        from . import stability

        stability.record_equilibrium(results, stability.equilibrium(built))
        stability.record_ball_modes(results, stability.ball_modes())
    if analysis.get("revolving"):
        from . import stability

        stability.record_revolving(results, stability.revolving())
    if shapes is not None and analysis.get("mode_shapes") and "gravity" in effects:
        _record_mode_shapes(results, mode_shapes(shapes, n, k))
    if "convergence" in analysis:
        _record_convergence(results, convergence(model, analysis["convergence"]["n_values"], quick))
    if "accuracy_cost" in analysis:
        spec = analysis["accuracy_cost"]
        _record_accuracy_cost(results, accuracy_cost(spec["n_values"], spec.get("repeats", 10), quick))
        _record_cost_to_target(results, cost_to_target(spec["targets"], quick))
    if "large_n" in analysis:
        _record_large_n(results, large_n(analysis["large_n"]["n"], quick))
    if analysis.get("dispersion"):
        chain_dispersion = dispersion(built, values)
        if chain_dispersion is not None:
            _record_dispersion(results, chain_dispersion, found.unit, found.unit_name, found.unit_label)


def _record_frequencies(results, found: Spectrum, n, model):
    values, unit, unit_name, unit_label = found.values, found.unit, found.unit_name, found.unit_label
    cont, exact = found.continuum, found.exact
    results.number(f"frequencies_{unit_name}", values / unit, unit_label)
    results.number("frequencies_rad_per_s", values, "rad/s")
    if cont is not None:
        results.number("relative_error_vs_continuum", _relative(values, cont), "1")
    if exact is not None:
        results.number(
            "relative_error_vs_exact_discrete",
            _relative(values, exact),
            "1",
            note="against the closed form of the discrete chain",
        )
    table = {"mode": np.arange(1, len(values) + 1), f"omega_{unit_name}": values / unit}
    unit_math = UNIT_MATH.get(unit_name, unit_label)
    # a whirling chain: sigma in units of omega
    symbol = "$\\sigma$" if unit_name == "over_omega" else "$\\omega$"
    headers = {"mode": "mode", f"omega_{unit_name}": f"{symbol} ({unit_math})"}
    if cont is not None:
        table[f"continuum_{unit_name}"] = cont / unit
        headers[f"continuum_{unit_name}"] = f"continuum ({unit_math})"
    if exact is not None:
        table[f"exact_discrete_{unit_name}"] = exact / unit
        headers[f"exact_discrete_{unit_name}"] = f"closed form ({unit_math})"
    beside = [
        what
        for what, there in (
            ("the continuum's", cont is not None),
            ("the discrete chain's closed form", exact is not None),
        )
        if there
    ]
    results.table(
        "frequencies",
        pd.DataFrame(table),
        f"Frequencies {symbol} of the {n}-{'link' if model == 'links' else 'particle'} chain in units of "
        f"{unit_math}" + (f", beside {' and '.join(beside)}." if beside else "."),
        headers=headers,
    )


def _record_parabola(results, quotient):
    results.number(
        "parabola_sigma2_rho_l2_over_p",
        quotient,
        "1",
        note="$\\sigma^2\\rho l^2/P$ of the type $x(l - x)$ (Lamb Ex. XIV.12), derived with sympy",
    )
    results.number(
        "parabola_over_continuum",
        quotient / np.pi**2,
        "1",
        note="over the continuous string's exact $\\pi^2$: above 1, as Art. 94 requires",
    )


class ContinuumLimit(NamedTuple):
    n_values: list[int]
    order: float  # smallest fitted order of the lowest three frequencies' approach to the harmonics
    error_at_largest: float  # largest relative difference from the harmonics at the largest n


def continuum_limit(chain, effects, ends, n_values) -> ContinuumLimit:
    """The string of density rho = (mass)/l lumped into n particles of rho a each (Lamb's loaded string: the
    spacing a = l/(n + 1) carries its own mass): its lowest three frequencies tend to the continuous string's
    harmonics (s pi / l) sqrt(P / rho); the fitted order of the approach."""
    length, total = chain["length_m"], float(np.sum(_masses(chain, chain["n"])))
    errors, intervals = [], []
    for n in n_values:
        built = particle_chain(n, ends, length, np.full(n, total / (n + 1)), effects)
        lam, _ = chain_eigen.modes(built.segment_stiffness, built.diagonal, built.masses, ends, 3)
        errors.append(np.abs(np.sqrt(lam) / continuum_frequencies(effects, ends, length, total, 3, n=n) - 1))
        intervals.append(built.geometry.n_segments)
    errors = np.array(errors)
    orders = [-np.polyfit(np.log(intervals), np.log(errors[:, s]), 1)[0] for s in range(3)]
    return ContinuumLimit(n_values, float(min(orders)), float(errors[-1].max()))


def _record_continuum_limit(results, values: ContinuumLimit):
    n_values = values.n_values
    results.number(
        "continuum_limit_order",
        values.order,
        "1",
        note=f"fitted order in the number of intervals of the lowest three frequencies' approach to the "
        f"harmonics, $n$ = "
        f"{n_values[0]} to {n_values[-1]} (smallest of the three)",
    )
    results.number(
        "continuum_limit_error_at_largest",
        values.error_at_largest,
        "1",
        note=f"largest relative difference from the harmonics at $n$ = {n_values[-1]}",
    )
    results.number("continuum_limit_n_largest", int(n_values[-1]), "particles")


class ClosedForm(NamedTuple):
    derived: np.ndarray  # omega from the roots of the characteristic polynomial (sympy, 30 digits)
    squared_over_k_per_m: np.ndarray  # omega^2 over the softest spring (or P/a) over the first mass
    solver_vs_derived: float  # largest relative difference
    formula_exact: bool  # the printed formula equals the derived roots for every value of its symbols
    formula_vs_solver: float


def closed_form(masses, springs, ends, name, values) -> ClosedForm:
    """ω² derived with sympy (the characteristic polynomial's roots), against the eigensolver's numbers and
    against the source's printed formula, which must equal the derived roots for every value of its
    symbols."""
    _, roots, symbols = symbolic.derive(masses, springs, ends)
    derived = np.sqrt(np.clip(symbolic.evaluate(roots, symbols), 0.0, None))
    printed = symbolic.SOURCE_FORMULAS[name]
    from_source = np.sqrt(np.clip(symbolic.evaluate(printed, symbols), 0.0, None))
    scale = np.max(derived)  # zero modes compare on the scale of the largest frequency
    return ClosedForm(
        derived,
        derived**2 / (symbols[symbolic.k] / symbols[symbolic.m1]),
        float(np.max(np.abs(values - derived) / np.maximum(derived, scale))),
        symbolic.formula_is_exact(printed, roots),
        float(np.max(np.abs(values - from_source) / np.maximum(from_source, scale))),
    )


def _record_closed_form(results, values: ClosedForm):
    results.number(
        "closed_form_frequencies_rad_per_s",
        values.derived,
        "rad/s",
        note="roots of the characteristic polynomial derived with sympy, evaluated at 30 digits",
    )
    results.number(
        "closed_form_squared_over_k_per_m",
        values.squared_over_k_per_m,
        "k/m",
        note="$\\omega^2$ in units of the softest spring (or $P/a$) over the first mass",
    )
    results.number(
        "solver_vs_closed_form",
        values.solver_vs_derived,
        "1",
        note="largest relative difference, eigensolver against the sympy derivation",
    )
    results.number(
        "source_formula_exact",
        int(values.formula_exact),
        "1",
        note="1: the printed formula equals the derived roots for every value of its symbols",
    )
    results.number("source_formula_vs_solver", values.formula_vs_solver, "1")
    results.hard_case(
        "closed_form",
        "The eigensolver's frequencies against the roots of the characteristic "
        "polynomial derived with sympy (largest relative difference)",
        values.solver_vs_derived,
        1e-12,
    )


def zero_mode(lam, shapes, rigid, rigid_name) -> ZeroMode:
    zero = np.argmin(np.abs(lam))
    v = shapes[:, zero] / np.linalg.norm(shapes[:, zero])
    rigid = rigid / np.linalg.norm(rigid)
    return ZeroMode(rigid_name, abs(lam[zero]) / np.max(np.abs(lam)), float(1 - abs(v @ rigid)))


def _record_zero_mode(results, values: ZeroMode):
    results.number(
        "zero_mode_eigenvalue_relative",
        values.eigenvalue_relative,
        "1",
        note="$|\\lambda_0|/\\lambda_\\mathrm{max}$ before clipping",
    )
    results.hard_case(
        "zero_mode",
        f"The zero mode is a {values.rigid_name}: $1 - |\\cos\\theta|$, $\\theta$ the angle between "
        "them; its eigenvalue is round-off, clipped to 0, not reported as an instability",
        values.misalignment,
        1e-12,
    )
    results.hard_case(
        "zero_mode_eigenvalue",
        "$|\\lambda_0|/\\lambda_\\mathrm{max}$ of the free chain's zero mode",
        float(values.eigenvalue_relative),
        1e-12,
    )


class ModeShapes(NamedTuple):
    n: int
    j: np.ndarray  # the first three zeros of J0
    height: np.ndarray  # each particle's height above the free end, x/l, the chain (n + 1/2)a long
    drawn: list[np.ndarray]  # each mode shown, scaled to the continuum at the lowest particle
    misfits: list[float]  # largest |particle - continuum| of each mode shown
    node: float | None  # mode 2's node, x/l from the free end (None when not found or not asked)


def mode_shapes(shapes, n, k) -> ModeShapes:
    """The lowest mode shapes against the continuum's J0(j_0k sqrt(x/l)), and mode 2's node."""
    from scipy import special

    j = bessel_j0_zeros(3)
    # Drawn as the chain the text compares with the continuum: counted (n + 1/2)a long, the end correction
    # that makes its frequencies converge at second order, so particle j (from the top) is (n + 1/2 - j)/(n +
    # 1/2) of the length above the free end. (At l = na the lowest particle would sit on the free end and
    # modes 2 and 3 would look several times further from the continuum than they are.)
    height = (n + 0.5 - np.arange(1, n + 1)) / (n + 0.5)
    drawn, misfits = [], []
    for idx in range(min(3, k, n)):
        # each mode scaled to the continuum's displacement at the lowest particle (no fit)
        at_particles = special.j0(j[idx] * np.sqrt(height))
        y = shapes[:, idx] / shapes[-1, idx] * at_particles[-1]
        misfits.append(float(np.max(np.abs(y - at_particles))))
        drawn.append(y)
    node = None
    if n >= 3 and k >= 2:
        y2 = shapes[:, 1]
        sign = np.nonzero(np.sign(y2[:-1]) != np.sign(y2[1:]))[0]
        if sign.size:
            i = sign[-1]
            lumped = 1 - np.arange(1, n + 1) / n  # heights with l = na, as this number has always been read
            h0, h1 = lumped[i], lumped[i + 1]
            node = h0 + (h1 - h0) * y2[i] / (y2[i] - y2[i + 1])
    return ModeShapes(n, j, height, drawn, misfits, node)


def _record_mode_shapes(results, values: ModeShapes):
    from scipy import special

    j, height, misfits, n = values.j, values.height, values.misfits, values.n
    shown = len(values.drawn)
    fig, ax = new_figure(4.4, 3.2)
    x = np.linspace(0, 1, 400)
    for idx, y in enumerate(values.drawn):
        cont = special.j0(j[idx] * np.sqrt(x))
        line = ax.plot(cont, x, lw=1, alpha=0.7)[0]
        ax.plot(y, height, "o", ms=3.5, color=line.get_color(), label=f"mode {idx + 1}")
    ax.axvline(0, color="0.2", lw=0.6)
    ax.set_xlabel("displacement (free end = 1)")
    ax.set_ylabel("height above the free end, $x/l$")
    ax.legend(loc="upper right")
    results.number(
        "mode_shape_misfit",
        misfits,
        "1",
        note="largest |particle - continuum| of modes 1 to 3 as drawn (free end = 1)",
    )
    misfit_text = ", ".join(format_number(m, 2) for m in misfits)
    results.figure(
        "mode_shapes",
        fig,
        f"The first {shown} mode shapes of the {n}-particle chain (points) over the continuum's modes "
        "$J_0(j_{0k}\\sqrt{x/l})$ (lines in the same colours, the free end moving 1). The particles stand at "
        "the heights of a chain counted $(n + \\tfrac12)a$ long, the end correction under which the "
        "frequencies converge at second order, each mode scaled to the continuum at the lowest particle. "
        f"The largest gap between particle and curve is {misfit_text} for modes 1 to {shown}.",
    )
    if values.node is not None:
        results.number(
            "second_mode_node_x_over_l",
            values.node,
            "x/l from the free end",
            note="linear interpolation between particles",
        )


def _fit_order(n_values, errors):
    n_values, errors = np.asarray(n_values, float), np.abs(np.asarray(errors, float))
    good = errors > 1e-15
    slope = np.polyfit(np.log(n_values[good]), np.log(errors[good]), 1)[0]
    return -slope


class Convergence(NamedTuple):
    model: str
    frame: pd.DataFrame  # omega_1 against n, each scheme, and its relative error
    exact: float  # the continuum's omega_1/sqrt(g/l)
    fitted: dict  # scheme -> (order, first n, last n) of the fit
    orders: list  # (name, order, first n, last n): the orders the report names
    all_on_one_side: bool  # links: all above the continuum; particles: l = na all below
    richardson_n: int | None  # particles: smallest n whose Richardson omega_1 is within 1e-10


def convergence(model, n_values, quick) -> Convergence:
    """The gravest frequency against n: rigid links, or particles with l = na, l = (n + 1/2)a and
    Richardson's extrapolation from n/2 and n, against the continuum."""
    n_values = [n for n in n_values if not quick or n <= QUICK_MAX_N]
    exact = bessel_j0_zeros(1)[0] / 2  # omega_1 / sqrt(g/l)
    rows = []
    if model == "links":
        for n in n_values:
            w = links_frequencies(n, 1)[0]
            rows.append(
                {
                    "n": n,
                    "scheme": "rigid links, l = n a",
                    "omega1_sqrt_g_over_l": w,
                    "relative_error": w / exact - 1,
                }
            )
        order = _fit_order(n_values, [r["relative_error"] for r in rows])
        orders = [("links", order, n_values[0], n_values[-1])]
        fitted = {"links": (order, n_values[0], n_values[-1])}
        one_side = all(r["relative_error"] > 0 for r in rows)
        reach_n = None
    else:
        previous = None
        for n in n_values:
            lam = hanging_particles_scaled(n, 1)[0]
            plain = np.sqrt(n * lam)
            corrected = np.sqrt((n + 0.5) * lam)
            rows.append(
                {
                    "n": n,
                    "scheme": "particles, l = n a",
                    "omega1_sqrt_g_over_l": plain,
                    "relative_error": plain / exact - 1,
                }
            )
            rows.append(
                {
                    "n": n,
                    "scheme": "particles, l = (n + 1/2) a",
                    "omega1_sqrt_g_over_l": corrected,
                    "relative_error": corrected / exact - 1,
                }
            )
            if previous is not None:
                rich = _richardson(previous, (n, lam))
                rows.append(
                    {
                        "n": n,
                        "scheme": "Richardson, from n/2 and n",
                        "omega1_sqrt_g_over_l": rich,
                        "relative_error": rich / exact - 1,
                    }
                )
            previous = (n, lam)
        frame = pd.DataFrame(rows)
        fitted, orders = {}, []
        for scheme, name in (
            ("particles, l = n a", "plain"),
            ("particles, l = (n + 1/2) a", "end_corrected"),
            ("Richardson, from n/2 and n", "richardson"),
        ):
            part = frame[frame.scheme == scheme]
            tail = part[part.n >= 16] if name != "richardson" else part[(part.n >= 16) & (part.n <= 256)]
            order = _fit_order(tail.n, tail.relative_error)
            orders.append((name, order, int(tail.n.min()), int(tail.n.max())))
            fitted[_scheme(scheme)] = (order, int(tail.n.min()), int(tail.n.max()))
        rich = frame[frame.scheme == "Richardson, from n/2 and n"]
        reach = rich[np.abs(rich.relative_error) <= 1e-10]
        reach_n = int(reach.n.min()) if len(reach) else None
        one_side = bool((frame[frame.scheme == "particles, l = n a"].relative_error < 0).all())
    return Convergence(model, pd.DataFrame(rows), exact, fitted, orders, one_side, reach_n)


def _record_convergence(results, values: Convergence):
    if values.model == "links":
        ((_, order, first, last),) = values.orders
        results.number("links_convergence_order", order, "1", note=f"fitted over $n$ = {first} to {last}")
        results.number("links_all_above_continuum", values.all_on_one_side, "bool")
    else:
        for name, order, first, last in values.orders:
            results.number(
                f"{name}_convergence_order",
                order,
                "1",
                note=f"least-squares slope of $\\log|\\text{{error}}|$ against $\\log n$, $n$ = "
                f"{first} to {last}",
            )
        results.number(
            "richardson_n_for_1e-10",
            values.richardson_n,
            "particles",
            note="smallest $n$ (with $n/2$) whose Richardson value of $\\omega_1$ is within $10^{-10}$",
        )
        results.number("plain_all_below_continuum", values.all_on_one_side, "bool")
    frame = values.frame
    results.table(
        "convergence",
        frame,
        "Gravest frequency $\\omega_1$ of the discrete chain against $n$, with its "
        "relative error against the continuum's $(j_{01}/2)\\sqrt{g/l}$.",
        headers={
            "n": "$n$",
            "scheme": "scheme",
            "omega1_sqrt_g_over_l": "$\\omega_1$ ($\\sqrt{g/l}$)",
            "relative_error": "relative error",
        },
    )
    _convergence_figure(results, values.model, frame, values.exact, values.fitted)


def _convergence_figure(results, model, frame, exact, fitted):
    """omega_1 against n (left) and its relative error with reference slopes and fitted orders (right)."""
    fig, (ax, bx) = subplots(1, 2, figsize=(FULL_WIDTH_IN, 3.3), layout="constrained")
    for scheme, part in frame.groupby("scheme", sort=False):
        key = _scheme(scheme)
        label, colour, _ = SCHEMES[key]
        ax.semilogx(part.n, part.omega1_sqrt_g_over_l, "o-", ms=3, lw=0.9, color=colour, label=label)
        error = np.abs(part.relative_error.to_numpy())
        shown = error > 0  # an exact zero has no place on a log axis
        order, n_lo, n_hi = fitted[key]
        bx.loglog(
            part.n[shown],
            error[shown],
            "o-",
            ms=3,
            lw=0.9,
            color=colour,
            label=f"{label}: fitted order {format_number(order, 3)}",
        )
    continuum = ax.axhline(exact, color="0.3", ls="--", lw=0.8, label=r"continuum, $j_{01}/2$ (left)")
    ax.set_xlabel("$n$")
    ax.set_ylabel(r"$\omega_1$ ($\sqrt{g/l}$)")
    # reference slopes over each scheme's fitted range, through its error at the range's middle, a third below
    for key, (order, n_lo, n_hi) in fitted.items():
        _, _, slope = SCHEMES[key]
        part = frame[frame.scheme.map(_scheme) == key]
        inside = part[(part.n >= n_lo) & (part.n <= n_hi)]
        if inside.empty:
            continue
        middle = inside.iloc[len(inside) // 2]
        ns = np.geomspace(n_lo, n_hi, 50)
        ref = abs(float(middle.relative_error)) / 3.0 * (ns / float(middle.n)) ** -slope
        bx.loglog(ns, ref, ls=(0, (4, 3)), lw=0.8, color="0.45")
        bx.annotate(
            f"$n^{{-{slope}}}$",
            (ns[25], ref[25]),
            xytext=(-4, -4),
            textcoords="offset points",
            ha="right",
            va="top",
            color="0.3",
        )
    bx.set_xlabel("$n$")
    bx.set_ylabel(r"|relative error| of $\omega_1$")
    # one legend for both panels (the colours are the schemes in each), below them: off the data
    handles, labels = bx.get_legend_handles_labels()
    legend_below(fig, handles + [continuum], labels + [continuum.get_label()], ncol=2)
    for axis in (ax, bx):
        axis.grid(True, which="both", alpha=0.25, linewidth=0.6)
    if model == "links":
        order, n_lo, n_hi = fitted["links"]
        caption = (
            "The gravest frequency $\\omega_1$ of $n$ uniform rigid links hanging from the top, against $n$ "
            "(left; dashed: the continuum's $j_{01}/2$), and its relative error against the continuum "
            "(right; "
            "dashed: the reference slope $n^{-2}$). The links converge from above at second order: fitted "
            f"order {format_number(order, 3)} over $n$ = {n_lo} to {n_hi}."
        )
    else:
        orders = {key: format_number(value[0], 3) for key, value in fitted.items()}
        caption = (
            "The gravest frequency $\\omega_1$ of $n$ particles hanging on a light string, against $n$ "
            "(left; dashed: the continuum's $j_{01}/2$), with the length taken as $l = na$, with the end "
            "correction $l = (n + \\tfrac12)a$, and after Richardson extrapolation from $n/2$ and $n$; "
            "right: the relative error against the continuum, with reference slopes $n^{-1}$, $n^{-2}$ and "
            "$n^{-4}$ (dashed). The fitted orders are first ("
            f"{orders['plain']}), second ({orders['end']}) and fourth ({orders['richardson']})"
        )
        rich = frame[frame.scheme.map(_scheme) == "richardson"]
        zero = rich[rich.relative_error == 0]
        caption += (
            f"; at $n$ = {format_number(int(zero.n.min()))} Richardson's error is exactly 0, at round-off, "
            "and is not drawn."
            if len(zero)
            else "."
        )
    results.figure("convergence", fig, caption)


def _richardson(coarse, fine):
    """Eliminate the 1/N^2 term of (n + 1/2) lambda_1(n), N = n + 1/2; return omega_1/sqrt(g/l)."""
    (n1, lam1), (n2, lam2) = coarse, fine
    N1, N2 = n1 + 0.5, n2 + 0.5
    e1, e2 = N1 * lam1, N2 * lam2
    return np.sqrt((N2**2 * e2 - N1**2 * e1) / (N2**2 - N1**2))


def exact_lambda1(n: int) -> float:
    """The lowest zero of L_n to 30 digits (mpmath Newton) for n <= 1024, else Tricomi's expansion."""
    guess = laguerre_lowest_zero_asymptotic(n)
    return float(laguerre_zero_mp(n, guess)) if n <= 1024 else float(guess)


def accuracy_cost(n_values, repeats, quick) -> pd.DataFrame:
    """Each solver's time for the lowest five eigenvalues of the hanging chain, its error in lambda_1 against
    the exact Laguerre zero, and the end-corrected omega_1's against the continuum."""
    n_values = [n for n in n_values if not quick or n <= QUICK_MAX_N]
    repeats = 3 if quick else repeats
    j1 = bessel_j0_zeros(1)[0] / 2
    rows = []
    for n in n_values:
        lam_exact = exact_lambda1(n)
        for method in chain_eigen.METHODS:
            if n > SOLVER_LIMITS[method]:
                continue
            seconds, lam, runs = min_time(
                lambda: hanging_particles_scaled(n, 5, method)[0],
                repeats=repeats,
                budget_s=1.0 if quick else 3.0,
            )
            rows.append(
                {
                    "n": n,
                    "solver": method,
                    "seconds": seconds,
                    "runs": runs,
                    "algebraic_relative_error": abs(lam / lam_exact - 1),
                    "discretization_relative_error": abs(np.sqrt((n + 0.5) * lam) / j1 - 1),
                }
            )
    return pd.DataFrame(rows)


def _record_accuracy_cost(results, frame):
    results.timing_table(
        "solver_cost",
        frame,
        "Lowest five eigenvalues of the hanging chain of $n$ particles, by "
        "solver: wall time (minimum over repeats), the relative error of $\\lambda_1$ against the "
        "exact Laguerre zero, and the relative error of $\\omega_1$ (end-corrected) against the "
        "continuum. The times are runs of their own, of five eigenvalues each: the cost-to-target table "
        "times the lowest alone, in fewer repeats, so its time at the same $n$ differs; compare times "
        f"within one table. {software_stamp()}.",
        headers={
            "n": "$n$",
            "solver": "solver",
            "seconds": "wall time (s)",
            "runs": "runs",
            "algebraic_relative_error": "error of $\\lambda_1$",
            "discretization_relative_error": "error of $\\omega_1$",
        },
    )
    fig, ax = new_figure(5.4, 2.5)
    for method, part in frame.groupby("solver", sort=False):
        _solver_line(ax, method, part.n, part.seconds)
    ax.set_xlabel("$n$")
    ax.set_ylabel("wall time (s)")
    legend_below(fig, ncol=2)  # off the data: the dense and tridiagonal lines cross the upper left
    results.timing_figure(
        "solver_cost",
        fig,
        "Wall time for the lowest five modes of the chain of $n$ particles "
        "against $n$, by solver (minimum over repeats). The dense solver's cost grows fastest, the "
        "full tridiagonal solver's next; the tridiagonal solver that computes only the lowest modes "
        "and the pliability solver grow about linearly and are the only ones run up to the "
        "largest $n$.",
    )
    fig, ax = new_figure(5.4, 2.7)
    for method, part in frame.groupby("solver", sort=False):
        _solver_line(ax, method, part.n, np.maximum(part.algebraic_relative_error, 1e-17))
    ns = np.array(sorted(frame.n.unique()), float)
    ax.loglog(
        ns,
        2.8 * ns**2 * np.finfo(float).eps,
        ls=(0, (4, 3)),
        color="0.45",
        lw=0.9,
        label=r"$2.8\,n^2\epsilon$: condition number × $\epsilon$",
    )
    ax.set_xlabel("$n$")
    ax.set_ylabel(r"relative error of $\lambda_1$")
    legend_below(fig, ncol=3)  # off the data: the lines fill the panel
    results.figure(
        "solver_accuracy",
        fig,
        "Relative error of the lowest eigenvalue $\\lambda_1$ of the chain of "
        "$n$ particles against the exact Laguerre zero, by solver (errors below "
        f"{format_number(1e-17, 1)} drawn at that floor); dashed: the condition number $2.8n^2$ times the "
        "machine $\\epsilon$. The standard solvers lose accuracy like $n^2\\epsilon$; the pliability "
        "solver keeps it.",
    )
    for method in chain_eigen.METHODS:
        part = frame[frame.solver == method]
        results.number(
            f"{method}_worst_relative_error_lambda1",
            float(part.algebraic_relative_error.max()),
            "1",
            note=f"$n$ up to {format_number(int(part.n.max()))}",
        )


# the schemes of the cost-to-target table, typeset as the chapter writes them
PLAIN, END_CORRECTED, RICHARDSON = (
    "plain ($l = na$)",
    r"end-corrected ($l = (n + \tfrac12)a$)",
    "Richardson ($n/2$ and $n$)",
)


class CostToTarget(NamedTuple):
    top: int  # the sweep's largest n is 2^top
    frame: pd.DataFrame  # each scheme and target: the n that reaches it and its time, or the n predicted
    errors: dict  # scheme -> {n: relative error of omega_1}
    costs: dict  # scheme -> {n: wall time (s)}
    lapack_errors: list[float]  # the end-corrected omega_1 by LAPACK's solver (floored at 1e-17)
    lapack_seconds: list[float]


def cost_to_target(targets, quick) -> CostToTarget:
    """Smallest n and the time to reach each target error by plain n, end-corrected n, Richardson."""
    j1 = bessel_j0_zeros(1)[0] / 2
    top = 12 if quick else 18
    ns = [2**p for p in range(1, top + 1)]
    lam, seconds = {}, {}
    for n in ns:
        seconds[n], lam[n], _ = min_time(lambda: hanging_particles_scaled(n, 1)[0], repeats=3, budget_s=0.5)
    errors = {
        PLAIN: {n: abs(np.sqrt(n * lam[n]) / j1 - 1) for n in ns},
        END_CORRECTED: {n: abs(np.sqrt((n + 0.5) * lam[n]) / j1 - 1) for n in ns},
        RICHARDSON: {n: abs(_richardson((n // 2, lam[n // 2]), (n, lam[n])) / j1 - 1) for n in ns[1:]},
    }
    cost = {
        PLAIN: lambda n: seconds[n],
        END_CORRECTED: lambda n: seconds[n],
        RICHARDSON: lambda n: seconds[n] + seconds[n // 2],
    }
    orders = {PLAIN: 1.0, END_CORRECTED: 2.0, RICHARDSON: 4.0}
    rows = []
    for scheme, err in errors.items():
        for target in targets:
            hit = [n for n in sorted(err) if err[n] <= target]
            if hit:
                n = hit[0]
                rows.append(
                    {
                        "scheme": scheme,
                        "target": target,
                        "n": n,
                        "n_predicted": None,
                        "error": err[n],
                        "seconds": cost[scheme](n),
                        "measured": True,
                    }
                )
            else:
                # beyond the sweep: extrapolate n from the largest run along the scheme's known order
                n_last = max(err)
                n_need = n_last * (err[n_last] / target) ** (1 / orders[scheme])
                rows.append(
                    {
                        "scheme": scheme,
                        "target": target,
                        "n": None,
                        # a prediction from a fitted law: two figures, not a count to the particle
                        "n_predicted": float(f"{n_need:.2g}"),
                        "error": None,
                        "seconds": None,
                        "measured": False,
                    }
                )
    # LAPACK's solver of the lowest mode alone, end-corrected, where it runs: the figure's floor
    lapack_err, lapack_time = [], []
    for n in [n for n in ns if n <= SOLVER_LIMITS["tridiagonal_select"]]:
        secs, lam_n, _ = min_time(
            lambda: hanging_particles_scaled(n, 1, "tridiagonal_select")[0], repeats=3, budget_s=0.5
        )
        lapack_err.append(max(abs(np.sqrt((n + 0.5) * lam_n) / j1 - 1), 1e-17))
        lapack_time.append(secs)
    costs = {scheme: {n: cost[scheme](n) for n in err} for scheme, err in errors.items()}
    return CostToTarget(top, pd.DataFrame(rows), errors, costs, lapack_err, lapack_time)


def _record_cost_to_target(results, values: CostToTarget):
    top, frame = values.top, values.frame
    _work_precision_figure(results, values)
    results.timing_table(
        "cost_to_target",
        frame,
        "What it costs to reach a given relative error of $\\omega_1$ "
        "against the continuum, with the pliability solver: the smallest $n = 2^p$ that reaches it "
        f"and its time; where no $n$ up to $2^{{{top}}}$ reaches it, the $n$ the error law predicts "
        "(to two figures; not run, no time). The times are runs of their own, of the lowest eigenvalue "
        "alone and in "
        "fewer repeats: the solver-cost table times five eigenvalues, so its time at the same $n$ "
        f"differs; compare times within one table. {software_stamp()}.",
        headers={
            "scheme": "scheme",
            "target": "target error",
            "n": "$n$",
            "n_predicted": "$n$ predicted",
            "error": "error reached",
            "seconds": "wall time (s)",
            "measured": "run",
        },
    )


def _work_precision_figure(results, values: CostToTarget):
    """Error of omega_1 against the time it took, one line per route (and LAPACK's floor)."""
    fig, ax = new_figure(5.6, 3.1)
    for scheme, err in values.errors.items():
        n_sorted = sorted(err)
        label, colour, _ = SCHEMES[_scheme(scheme)]
        ax.loglog(
            [max(err[n], 1e-17) for n in n_sorted],
            [values.costs[scheme][n] for n in n_sorted],
            "o-",
            ms=3,
            color=colour,
            label=f"{label}, pliability",
        )
    ax.loglog(
        values.lapack_errors,
        values.lapack_seconds,
        "o--",
        ms=3,
        color=SOLVERS["tridiagonal_select"][1],
        label=f"{SCHEMES['end'][0]}, LAPACK (lowest only)",
    )
    ax.set_xlabel(r"relative error of $\omega_1$ against the continuum")
    ax.set_ylabel("wall time (s)")
    ax.invert_xaxis()
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2)  # below the axes: off the lines
    results.timing_figure(
        "work_precision",
        fig,
        "Wall time against the relative error of the gravest frequency, "
        "$n$ = 2, 4, 8, … along each line (errors below "
        f"{format_number(1e-17, 1)} drawn at that floor; accuracy grows to the right). Richardson "
        "extrapolation buys six orders of magnitude over the end correction at equal time; with "
        "LAPACK's solver the end-corrected chain stalls where its $n^2\\epsilon$ error overtakes the "
        "discretization error.",
    )


class LargeN(NamedTuple):
    n: int
    relative_errors: dict  # solver -> |lambda_1/reference - 1|, the reference Tricomi's expansion
    reciprocity: float  # |Q.q' - Q'.q|/|Q||q'| for two random loads (Lamb Art. 87)


def large_n(n, quick) -> LargeN:
    """The lowest mode of a very long chain: relative accuracy survives only in the factored form."""
    n = min(n, 20000) if quick else n
    reference = laguerre_lowest_zero_asymptotic(n)  # error O(n^-5): below 1e-20 relative here
    measured = {}
    for method in ("tridiagonal_select", "pliability"):
        lam = hanging_particles_scaled(n, 1, method)[0]
        measured[method] = abs(lam / reference - 1)
    # Lamb Art. 87: the pliabilities are reciprocal, sum Q q' = sum Q' q, here for the long chain's factored
    # K^-1
    rng = np.random.default_rng(7)
    loads = rng.standard_normal((n, 2))
    q = chain_eigen._apply_pliability(loads, np.arange(n, 0, -1.0), np.ones(n))
    reciprocity = float(
        abs(loads[:, 0] @ q[:, 1] - loads[:, 1] @ q[:, 0])
        / (np.linalg.norm(loads[:, 0]) * np.linalg.norm(q[:, 1]))
    )
    return LargeN(n, measured, reciprocity)


def _record_large_n(results, values: LargeN):
    n, measured = values.n, values.relative_errors
    for method, error in measured.items():
        results.number(f"large_n_{method}_relative_error", error, "1", note=f"$n$ = {format_number(n)}")
    results.hard_case(
        "large_n_lowest_mode",
        f"Lowest mode of a chain of $n$ = {format_number(n)} particles to "
        "$10^{-12}$ relative (pliability solver against Tricomi's expansion of the Laguerre zero)",
        measured["pliability"],
        1e-12,
    )
    results.number(
        "reciprocity_relative",
        values.reciprocity,
        "1",
        note=f"$|Q\\cdot q' - Q'\\cdot q|/|Q||q'|$ for two random loads, $n$ = {format_number(n)}",
    )
    results.notes.append(
        f"At $n$ = {format_number(n)} LAPACK's tridiagonal solver gives $\\lambda_1$ to "
        f"{format_number(measured['tridiagonal_select'], 2)} relative: the $n^2\\epsilon$ loss the "
        "pliability form avoids."
    )


class Dispersion(NamedTuple):
    spacing: float  # a (m)
    sqrt_k_over_m: float  # (rad/s)
    q: np.ndarray  # the computed modes' wavenumbers s pi/((n + 1) a)
    values: np.ndarray  # the computed frequencies (rad/s)
    max_relative_deviation: float  # from omega = 2 sqrt(k/m) |sin(qa/2)|


def dispersion(built, values) -> Dispersion | None:
    """The chain of springs fixed at both ends against its dispersion law; None for other ends."""
    g = built.geometry
    if g.ends != "fixed-fixed":
        return None
    n, a = g.n, g.spacing_m
    stiffness, m = built.segment_stiffness[0], g.masses_kg[0]
    q = np.arange(1, n + 1) * np.pi / ((n + 1) * a)
    law = 2 * np.sqrt(stiffness / m) * np.abs(np.sin(q * a / 2))
    return Dispersion(
        a,
        np.sqrt(stiffness / m),
        q,
        values,
        float(np.max(np.abs(values - law[: len(values)]) / law[: len(values)])),
    )


def _record_dispersion(results, values: Dispersion, unit, unit_name, unit_label):
    a, q = values.spacing, values.q
    root = values.sqrt_k_over_m
    qq = np.linspace(0, np.pi / a, 300)
    fig, ax = new_figure(5.2, 3.2)
    ax.plot(
        qq * a / np.pi,
        2 * root * np.sin(qq * a / 2) / unit,
        color="C4",
        label=r"$\omega = 2\sqrt{k/m}\,|\sin(qa/2)|$",
    )
    ax.plot(
        qq * a / np.pi,
        qq * a * root / unit,
        "--",
        lw=0.9,
        color="0.4",
        label=r"continuum, $\omega = qa\sqrt{k/m}$",
    )
    ax.plot(
        q[: len(values.values)] * a / np.pi,
        values.values / unit,
        "o",
        ms=4,
        color="C5",
        label="computed modes",
    )
    ax.set_xlabel(r"wavenumber $qa/\pi$")
    ax.set_ylabel(f"$\\omega$ ({UNIT_MATH.get(unit_name, unit_label)})")
    ax.set_xlim(0, 1)
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper left")
    results.figure(
        "dispersion",
        fig,
        "Dispersion of the discrete chain of springs: frequency against wavenumber. "
        "The computed frequencies lie on $\\omega = 2\\sqrt{k/m}\\,|\\sin(qa/2)|$, below the "
        "continuum's line, up to the cut-off $2\\sqrt{k/m}$ at $qa = \\pi$.",
    )
    results.number("dispersion_max_relative_deviation", values.max_relative_deviation, "1")
    results.number("cutoff_over_unit", 2 * values.sqrt_k_over_m / unit, unit_label)
