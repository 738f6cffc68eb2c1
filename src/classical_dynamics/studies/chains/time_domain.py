"""The finite-amplitude hanging chain in time: RATTLE on n particles and rigid massless links."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ...formatting import format_number, shortest
from ...results import new_figure
from ...solvers import rattle
from ...solvers.fixed_step import FixedProblem, Save, solve_fixed
from ...solvers.special import laguerre_zeros


def _mode_angles(n: int, mode: int, amplitude_rad: float):
    """Link angles of linear mode `mode` (1-based), scaled so the largest angle is amplitude_rad."""
    from ...solvers.chain_eigen import modes

    s = np.arange(n, 0, -1.0)
    _, shapes = modes(s, None, np.ones(n), "fixed-free", mode)
    u = shapes[:, mode - 1]
    theta = np.diff(u, prepend=0.0)
    return theta * amplitude_rad / np.max(np.abs(theta))


def simulate(n, length, g, mode, amplitude_rad, periods, steps_per_fastest):
    a = length / n
    lam = laguerre_zeros(n)
    omega = np.sqrt(g * lam / a)
    h = 2 * np.pi / omega[-1] / steps_per_fastest
    n_steps = int(np.ceil(periods * 2 * np.pi / omega[mode - 1] / h))
    q0 = rattle.positions_from_angles(_mode_angles(n, mode, amplitude_rad), a)
    p0 = np.zeros_like(q0)
    sample = max(1, int(round(2 * np.pi / omega[0] / h / 4)))  # four energy samples per period
    chain = FixedProblem(
        np.concatenate([q0.ravel(), p0.ravel()]), np.concatenate([[a, g], np.full(n, 1.0 / n)])
    )
    sol = solve_fixed(chain, "rattle", h=h, n_steps=n_steps, save=Save(every=sample))
    return omega, h, sol.extra["tip_x"], sol.extra["energy"], sol.extra["constraint"], sample


class LongRun(NamedTuple):
    periods: int  # gravest periods run
    drift: np.ndarray  # (E - E0)/(E0 - E_rest) at each sample
    t_periods: np.ndarray  # the samples' times in gravest periods
    tenth: int  # samples in a tenth of the run
    constraint: float  # largest ||q_j - q_{j-1}| - a| (m)


def small_amplitude(n, length, g, amplitude_rad, steps, quick) -> pd.DataFrame:
    """The frequency read from the motion of a small-amplitude start in each of the first three modes,
    against the eigenvalue, in units of sqrt(g/l)."""
    unit = np.sqrt(g / length)
    rows = []
    for mode in range(1, min(3, n) + 1):
        omega, h, tip, _, _, _ = simulate(n, length, g, mode, amplitude_rad, 30 if quick else 100, steps)
        measured, cycles = rattle.crossing_frequency(tip, h)
        rows.append(
            {
                "mode": mode,
                "eigenvalue_omega_sqrt_g_over_l": omega[mode - 1] / unit,
                "measured_omega_sqrt_g_over_l": measured / unit,
                "cycles": cycles,
                "relative_difference": measured / omega[mode - 1] - 1,
            }
        )
    return pd.DataFrame(rows)


def long_run(n, length, g, amplitude_rad, periods, steps) -> LongRun:
    """The energy error of a mode-1 start over a long run, relative to the oscillation's own energy."""
    omega, h, tip, energies, constraint, sample = simulate(n, length, g, 1, amplitude_rad, periods, steps)
    rest = -g * length * (n + 1) / 2 / n * 1.0  # sum over particles of m g y at rest (total mass 1)
    scale = energies[0] - rest  # the oscillation's own energy
    drift = (energies - energies[0]) / scale
    t_periods = np.arange(energies.size) * sample * h * omega[0] / (2 * np.pi)
    tenth = max(2, energies.size // 10)
    return LongRun(periods, drift, t_periods, tenth, constraint)


def amplitude_shift(n, length, g, amplitudes_deg, steps, quick) -> pd.DataFrame:
    """The mean frequency of a mode-1 start against its initial amplitude, relative to the linear omega_1."""
    rows = []
    for deg in amplitudes_deg:
        omega, h, tip, _, _, _ = simulate(n, length, g, 1, np.radians(deg), 20 if quick else 60, steps)
        measured, _ = rattle.crossing_frequency(tip, h)
        rows.append({"amplitude_deg": deg, "omega_over_linear": measured / omega[0]})
    return pd.DataFrame(rows)


def run(scene, results, quick):
    data = scene.data
    n, length = data["chain"]["n"], data["chain"]["length_m"]
    g = data["effects"]["gravity"]["g_m_per_s2"]
    spec = data["analysis"]["time_domain"]
    steps = spec["steps_per_fastest_period"]
    # 1. small amplitude: the frequency read from the motion against the eigenvalue
    frame = small_amplitude(n, length, g, np.radians(spec["small_amplitude_deg"]), steps, quick)
    _record_small_amplitude(results, frame, spec["small_amplitude_deg"], steps)
    # 2. energy over a long run
    periods = min(spec["long_run_periods"], 1000) if quick else spec["long_run_periods"]
    values = long_run(n, length, g, np.radians(spec["long_run_amplitude_deg"]), periods, steps)
    _record_long_run(results, values, n, spec["long_run_amplitude_deg"])
    # 3. large amplitude: the frequency shift
    _record_amplitude_shift(
        results, amplitude_shift(n, length, g, spec["large_amplitudes_deg"], steps, quick)
    )


def _record_small_amplitude(results, frame, amplitude_deg, steps):
    results.table(
        "time_domain_small_amplitude",
        frame,
        "Frequencies read from the zero crossings of the free end "
        f"in RATTLE runs started in each linear mode at {shortest(amplitude_deg)}°, against "
        f"the eigenvalues ({steps} steps per period of the fastest mode), in units of $\\sqrt{{g/l}}$; "
        "they differ by the method's small phase error.",
        headers={
            "mode": "mode",
            "eigenvalue_omega_sqrt_g_over_l": "eigenvalue $\\omega$ ($\\sqrt{g/l}$)",
            "measured_omega_sqrt_g_over_l": "measured $\\omega$ ($\\sqrt{g/l}$)",
            "cycles": "cycles",
            "relative_difference": "relative difference",
        },
    )
    results.number(
        "time_domain_max_relative_frequency_difference",
        float(frame.relative_difference.abs().max()),
        "1",
        note=f"modes 1 to {len(frame)}, amplitude {shortest(amplitude_deg)}°",
    )


def _record_long_run(results, values: LongRun, n, amplitude_deg):
    periods, drift, t_periods, tenth = values.periods, values.drift, values.t_periods, values.tenth
    results.number("time_domain_periods", periods, "gravest periods")
    results.number(
        "time_domain_energy_error_max",
        float(np.max(np.abs(drift))),
        "1",
        note="largest $|E - E_0|/(E_0 - E_\\mathrm{rest})$ over the run",
    )
    results.number("time_domain_energy_error_first_tenth", float(np.max(np.abs(drift[:tenth]))), "1")
    results.number("time_domain_energy_error_last_tenth", float(np.max(np.abs(drift[-tenth:]))), "1")
    results.number(
        "time_domain_constraint_error_m", values.constraint, "m", note="largest $||q_j - q_{j-1}| - a|$"
    )
    results.hard_case(
        "energy_bounded",
        f"Energy error over {format_number(periods)} gravest periods does not "
        "grow: its largest value in the last tenth of the run over its largest in the first tenth",
        float(np.max(np.abs(drift[-tenth:])) / max(np.max(np.abs(drift[:tenth])), 1e-300)),
        2.0,
    )
    fig, ax = new_figure(5.2, 2.9)  # tall enough for its y-label: the panel spans more than the label
    running = np.maximum.accumulate(np.abs(drift))
    keep = t_periods > 0
    ax.loglog(t_periods[keep], running[keep], lw=1.2, color="C4")
    ax.set_xlabel("time (gravest periods)")
    ax.set_ylabel("running max of\n" r"$|E - E_0|/(E_0 - E_\mathrm{rest})$")
    ax.set_ylim(running[keep].max() / 100, running[keep].max() * 10)
    results.figure(
        "energy_error",
        fig,
        f"Energy error of RATTLE over {format_number(periods)} gravest periods "
        f"({n} particles, amplitude {shortest(amplitude_deg)}°): the running maximum of "
        "$|E - E_0|$ relative to the oscillation's energy $E_0 - E_\\mathrm{rest}$, sampled four times a "
        "period. It reaches its level within the first period and stays there (bounded, no drift).",
    )


def _record_amplitude_shift(results, shift):
    results.table(
        "amplitude_shift",
        shift,
        "Mean frequency $\\omega$ of the free end against the initial amplitude "
        "(largest link angle) of a mode-1 start, relative to the linear $\\omega_1$.",
        headers={"amplitude_deg": "amplitude (°)", "omega_over_linear": "$\\omega/\\omega_1$"},
    )
    fig, ax = new_figure(4.6, 2.5)
    ax.plot(shift.amplitude_deg, shift.omega_over_linear, "o-", color="C4")
    ax.set_xlabel("initial amplitude, largest link angle (°)")
    ax.set_ylabel(r"$\omega/\omega_1$")
    results.figure(
        "amplitude_shift",
        fig,
        "The frequency read from the motion of a mode-1 start, relative to the "
        "linear $\\omega_1$, against the initial amplitude (largest link angle): at large amplitude the "
        "chain swings more slowly.",
    )
