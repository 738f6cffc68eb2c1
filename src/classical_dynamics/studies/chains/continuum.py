"""The continuous chain: Bernoulli's J0 modes, Lamb's numbers, Rayleigh's estimate."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd
from scipy import special

from ...formatting import format_number
from ...models.chains import continuum_frequencies, frequency_unit
from ...results import new_figure
from ...solvers.special import bessel_j0_zeros
from ...solvers.spectral import hanging_chain_sigma


def rayleigh_quotient(beta):
    """sigma^2 l / g for the assumed type y = s + beta s^2 / l (s from the top; Lamb Art. 94 Ex. 2)."""
    beta = np.asarray(beta, float)
    return (15 + 20 * beta + 10 * beta**2) / (10 + 15 * beta + 6 * beta**2)


def rayleigh_ritz_2x2():
    """Ritz values (sigma^2 l / g) in the basis {s, s^2}: exact integrals of the two energies."""
    from scipy.linalg import eigh

    T = np.array([[1 / 3, 1 / 4], [1 / 4, 1 / 5]])  # integral of phi_i phi_j
    V = np.array([[1 / 2, 1 / 3], [1 / 3, 1 / 3]])  # integral of (1 - s) phi_i' phi_j'
    return eigh(V, T, eigvals_only=True)


class Frequencies(NamedTuple):
    computed: np.ndarray  # rad/s, by the collocation or the closed form
    relative_error: np.ndarray  # against the closed form
    method: str
    unit: float  # the scene's frequency unit (rad/s)
    unit_name: str
    unit_label: str
    sigma: np.ndarray | None  # the collocation's sigma tau_1 (tau_1 = 1); None without it


def frequencies(chain, effects, k, intervals=None) -> Frequencies:
    """The first k frequencies: Chebyshev collocation in tau = 2 sqrt(x/g) with `intervals` intervals
    (gravity only), else the closed form; each against the closed form."""
    length, mass = chain["length_m"], chain["mass_kg"]
    exact = continuum_frequencies(effects, chain.get("ends", "fixed-free"), length, mass, k)
    unit, unit_name, unit_label = frequency_unit(effects, length, mass, None, None)
    sigma = None
    if intervals is not None:
        sigma = hanging_chain_sigma(intervals, k)  # sigma tau_1 with tau_1 = 1
        computed = sigma / 2 * np.sqrt(effects["gravity"]["g_m_per_s2"] / length)
        method = f"Chebyshev collocation in $\\tau = 2\\sqrt{{x/g}}$, {intervals} intervals"
    else:
        computed = exact
        method = "closed form"
    rel = (computed - exact) / exact
    return Frequencies(computed, rel, method, unit, unit_name, unit_label, sigma)


class HangingModes(NamedTuple):
    j: np.ndarray  # the zeros j_0k of J0
    gravest_period_sqrt_l_over_g: float
    gravest_period_s: float
    node: float  # mode 2's node, x/l from the free end
    table: pd.DataFrame  # continuum_modes


def hanging_modes(k, length, g, relative_error) -> HangingModes:
    """The hanging chain's modes from the zeros of J0 (Bernoulli; Lamb Art. 90 (23))."""
    j = bessel_j0_zeros(k)
    table = pd.DataFrame(
        {
            "k": np.arange(1, k + 1),
            "j0k": j,
            "j0k_over_pi": j / np.pi,
            "sigma2_l_over_g": (j / 2) ** 2,
            "period_sqrt_l_over_g": 4 * np.pi / j,
            "spectral_relative_error": relative_error,
        }
    )
    return HangingModes(
        j, 4 * np.pi / j[0], 4 * np.pi / j[0] * np.sqrt(length / g), (j[0] / j[1]) ** 2, table
    )


def run(scene, results, quick):
    data = scene.data
    chain, effects, analysis = data["chain"], data["effects"], data.get("analysis", {})
    k = analysis.get("modes", 5)
    intervals = analysis["spectral_check"]["intervals"] if "spectral_check" in analysis else None
    values = frequencies(chain, effects, k, intervals)
    _record_frequencies(results, values, "gravity" in effects)
    if "gravity" not in effects:
        return
    modes = hanging_modes(k, chain["length_m"], effects["gravity"]["g_m_per_s2"], values.relative_error)
    _record_hanging_modes(results, modes, values.sigma)
    # the inputs of the period in seconds, so that the text can say what it is for
    results.number("length_m", chain["length_m"], "m", note="the scene's chain")
    results.number("g_m_per_s2", effects["gravity"]["g_m_per_s2"], "m/s²", note="the scene's gravity")
    _mode_shape_figure(results, modes.j)
    if "rayleigh" in analysis:
        spec = analysis["rayleigh"]
        _record_rayleigh(results, rayleigh(spec["beta_min"], spec["beta_max"], (modes.j[0] / 2) ** 2, quick))
    if "mcmahon_check" in analysis:
        _record_high_index_zeros(results, high_index_zeros(analysis["mcmahon_check"]["k_max"]))
    if "galerkin" in analysis:  # Lamb Art. 100: the same chain from Hamilton's principle
        from . import stability

        stability.record_hamilton_chain(results, stability.hamilton_chain(analysis["galerkin"]["elements"]))
    if "membrane" in analysis:  # the drum of the lecture notes: Bessel's equation again, all m
        from . import stability

        stability.record_drum(results, stability.drum(analysis["membrane"]["points"]))


def _record_frequencies(results, values: Frequencies, gravity):
    results.number("n", 0, "particles", note="0: the continuum")
    results.number(
        f"frequencies_{values.unit_name}",
        values.computed / values.unit,
        values.unit_label,
        note=values.method,
    )
    results.number("frequencies_rad_per_s", values.computed, "rad/s")
    results.number(
        "relative_error_vs_continuum",
        values.relative_error,
        "1",
        note="against the closed form (J0 zeros)" if gravity else "closed form itself",
    )


def _record_hanging_modes(results, modes: HangingModes, sigma):
    j = modes.j
    results.number(
        "gravest_period_sqrt_l_over_g",
        modes.gravest_period_sqrt_l_over_g,
        "√(l/g)",
        note="$2\\pi/\\omega_1 = 4\\pi/j_{01}$",
    )
    results.number("gravest_period_s", modes.gravest_period_s, "s")
    results.number("lamb_roots_over_pi", j / np.pi, "1", note="$\\sigma\\tau_1/\\pi$, Lamb Art. 90 (23)")
    results.number("frequency_ratio_2_to_1", j[1] / j[0], "1")
    # the first zero of J0 without a Bessel routine: the drum's coefficient too
    if sigma is not None:
        results.number(
            "first_zero_j0_collocation",
            float(sigma[0]),
            "1",
            note="$j_{0,1}$ from the collocation; a drum's lowest mode is "
            "$\\omega_{01} = j_{0,1}\\sqrt{T/\\sigma}/a$",
        )
    results.number(
        "second_mode_node_x_over_l",
        modes.node,
        "x/l from the free end",
        note="$J_0(j_{02}\\sqrt{x/l}) = 0$ where $j_{02}\\sqrt{x/l} = j_{01}$",
    )
    results.table(
        "continuum_modes",
        modes.table,
        "Modes of the continuous hanging chain: the zeros $j_{0k}$ of $J_0$, "
        "the frequencies $\\sigma^2 l/g = (j_{0k}/2)^2$, the periods, and the relative error of the "
        "collocation solution's frequencies.",
        headers={
            "k": "$k$",
            "j0k": "$j_{0k}$",
            "j0k_over_pi": "$j_{0k}/\\pi$",
            "sigma2_l_over_g": "$\\sigma^2 l/g$",
            "period_sqrt_l_over_g": "period ($\\sqrt{l/g}$)",
            "spectral_relative_error": "collocation, relative error",
        },
    )


def _mode_shape_figure(results, j):
    fig, ax = new_figure(4.4, 3.2)
    x = np.linspace(0, 1, 801)
    for idx, style in zip(range(3), ("-", "--", "-.")):
        y = special.j0(j[idx] * np.sqrt(x))
        ax.plot(
            y / np.max(np.abs(y)),
            x,
            style,
            label=f"mode {idx + 1}: $\\sigma^2 l/g$ = {format_number((j[idx] / 2) ** 2, 4)}",
        )
    node = (j[0] / j[1]) ** 2
    # named in the legend: every free place beside the line has a curve running through it
    ax.axhline(node, color="0.4", lw=0.8, label=f"node of mode 2, $x/l$ = {format_number(node, 4)}")
    ax.axvline(0, color="0.2", lw=0.6)
    ax.set_xlabel("horizontal displacement (largest = 1)")
    ax.set_ylabel("height above the free end, $x/l$")
    ax.set_ylim(0, 1)
    ax.legend(loc="upper right")
    results.figure(
        "mode_shapes",
        fig,
        "The first three modes of the hanging chain, $y \\propto J_0(2\\sigma"
        "\\sqrt{x/g})$ with $x$ the height above the free end, drawn as in Lamb's Fig. 58 (suspension at "
        "the top). Mode $k$ has $k - 1$ nodes; the node of mode 2 is marked.",
    )


class Rayleigh(NamedTuple):
    beta_min: float
    beta_max: float
    exact1: float  # the exact gravest sigma^2 l/g, (j01/2)^2
    beta: np.ndarray  # the scan
    f: np.ndarray  # the quotient on the scan
    beta_star: float  # the stationary beta
    ritz: np.ndarray  # Ritz values on {s, s^2}
    rigid_bar: float  # the quotient at beta = 0
    best: float  # the quotient at the stationary beta
    tau_substitution_exact: bool  # sympy: tau = 2 sqrt(x/g) turns (15) into (19)
    formula_exact: bool  # sympy: Lamb's quotient (11) is the one derived from T and V


def rayleigh(beta_min, beta_max, exact1, quick) -> Rayleigh:
    """Rayleigh's quotient for y = s + beta s^2/l over a scan of beta (Lamb Art. 94 Ex. 2)."""
    from . import symbolic

    beta = np.linspace(beta_min, beta_max, 241 if quick else 1201)
    f = rayleigh_quotient(beta)
    beta_star = (-2 + np.sqrt(34)) / 6  # root of 6 beta^2 + 4 beta - 5 = 0
    ritz = rayleigh_ritz_2x2()
    integral, membrane = symbolic.hanging_chain_tau()
    formula = symbolic.hanging_chain_quotient_is_printed()
    return Rayleigh(
        beta_min,
        beta_max,
        exact1,
        beta,
        f,
        beta_star,
        ritz,
        rayleigh_quotient(0.0),
        rayleigh_quotient(beta_star),
        bool(integral and membrane),
        formula,
    )


def _record_rayleigh(results, values: Rayleigh):
    beta, f, beta_star, ritz, exact1 = values.beta, values.f, values.beta_star, values.ritz, values.exact1
    rigid, best = values.rigid_bar, values.best
    results.number("rayleigh_rigid_bar_sigma2_l_over_g", rigid, "g/l", note="beta = 0")
    results.number("rayleigh_rigid_bar_period_sqrt_l_over_g", 2 * np.pi / np.sqrt(rigid), "√(l/g)")
    results.number(
        "tau_substitution_exact",
        int(values.tau_substitution_exact),
        "1",
        note="1: $\\int_0^x dx/\\sqrt{gx} = 2\\sqrt{x/g}$ and $x = g\\tau^2/4$ turns (15) into (19) (sympy)",
    )
    results.number(
        "rayleigh_formula_exact",
        int(values.formula_exact),
        "1",
        note="1: Lamb's quotient (11) equals the one sympy derives from $T$ and $V$ for every $\\beta$",
    )
    results.number(
        "rayleigh_best_beta", beta_star, "1", note="stationary point, $6\\beta^2 + 4\\beta - 5 = 0$"
    )
    results.number("rayleigh_best_sigma2_l_over_g", best, "g/l")
    results.number("rayleigh_best_period_sqrt_l_over_g", 2 * np.pi / np.sqrt(best), "√(l/g)")
    results.number(
        "rayleigh_best_relative_excess", best / exact1 - 1, "1", note="over the exact $(j_{01}/2)^2$"
    )
    results.number(
        "rayleigh_min_excess_over_scan",
        float(np.min(f - exact1)),
        "g/l",
        note=f"smallest over {beta.size} values of $\\beta$ from "
        f"{format_number(float(values.beta_min), 3)} to {format_number(float(values.beta_max), 3)}",
    )
    results.number("ritz_2x2_sigma2_l_over_g", ritz, "g/l", note="basis $s$, $s^2$")
    results.hard_case(
        "rayleigh_upper_bound",
        "Rayleigh's quotient never falls below the exact gravest "
        "$\\sigma^2$ (largest excess of the exact value over the quotient on the $\\beta$ scan, "
        "floored at 0)",
        float(max(0.0, np.max(exact1 - f))),
        0.0,
        "g/l",
    )
    results.table(
        "rayleigh_scan",
        pd.DataFrame({"beta": beta, "sigma2_l_over_g": f}),
        "Rayleigh's quotient for the assumed type $y = s + \\beta s^2/l$ over a range of $\\beta$.",
        headers={"beta": "$\\beta$", "sigma2_l_over_g": "$\\sigma^2 l/g$"},
    )
    fig, ax = new_figure(5.2, 3.2)
    ax.plot(beta, f, color="C4", label=r"Rayleigh quotient, $y = s + \beta s^2/l$")
    ax.axhline(
        exact1, color="k", lw=0.9, ls="--", label=f"exact $(j_{{01}}/2)^2$ = {format_number(exact1, 6)}"
    )
    ax.plot([0], [rigid], "o", color="C5", label=r"$\beta = 0$: rigid bar, 3/2")
    ax.plot(
        [beta_star], [best], "s", color="C3", label=f"stationary $\\beta$ = {format_number(beta_star, 5)}"
    )
    ax.set_xlabel(r"$\beta$")
    ax.set_ylabel(r"$\sigma^2 l/g$")
    ax.set_ylim(exact1 - 0.05, 2.0)
    ax.legend(loc="upper right")
    results.figure(
        "rayleigh",
        fig,
        "Rayleigh's estimate $\\sigma^2 l/g$ of the gravest frequency for the assumed "
        "type $y = s + \\beta s^2/l$ ($s$ from the top) as a function of $\\beta$: always above the exact "
        "value (dashed), closest to it at the stationary $\\beta$, "
        f"{format_number(best / exact1 - 1, 2)} above it in relative terms.",
    )


class HighIndexZeros(NamedTuple):
    k_max: int
    gap: float  # largest relative gap of SciPy's zeros from McMahon's, k >= 50
    bound: float  # McMahon's own error there is below it


def high_index_zeros(k_max) -> HighIndexZeros:
    """High-index J0 zeros: scipy's jn_zeros against McMahon's expansion (error ~ b^-5)."""
    k = np.arange(1, k_max + 1)
    zeros = bessel_j0_zeros(k_max)
    from ...solvers.special import mcmahon_j0_zero

    b = (k - 0.25) * np.pi
    gap = np.abs(zeros - mcmahon_j0_zero(k)) / zeros
    tail = k >= 50
    bound = float(np.max(0.3 / (b[tail] ** 5 * zeros[tail]))) + 1e-15  # next term 3779/(15360 b^5)
    return HighIndexZeros(k_max, float(np.max(gap[tail])), bound)


def _record_high_index_zeros(results, values: HighIndexZeros):
    results.hard_case(
        "high_index_j0_zeros",
        f"$J_0$ zeros $k$ = 50 to {format_number(int(values.k_max))}: SciPy's "
        "against McMahon's expansion (relative gap; McMahon's own error there is below the bound)",
        values.gap,
        values.bound,
    )
