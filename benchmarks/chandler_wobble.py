"""What a century of Chandler wobble costs, side by side in one run (printed, not asserted).

A 0.1" wobble of the rigid symmetric Earth (H = 0.0032737949) over 100 years, error at the end against
the closed form p + iq = K e^{i lambda t}, relative to the wobble: this library's compiled DOP853 and
Dormand-Prince 5(4) against scipy's solve_ivp (DOP853, RK45, LSODA) at the same tolerances, and the
elastic, damped and excited models at rtol 1e-10 (what each effect costs). Then the fit of the IERS
C04 series. Times are minima over repeated runs after a warm-up.

    python benchmarks/chandler_wobble.py
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))
from classical_dynamics.models import earth, wobble
from classical_dynamics.provenance import software_stamp
from classical_dynamics.solvers.timing import min_time
from classical_dynamics.studies.chandler import model as wm
from classical_dynamics.studies.chandler import polar_motion as pm

AMP = 0.1 * earth.ARCSEC
T = 100 * earth.JULIAN_YEAR_DAYS
EFFECTS = {
    "rigid symmetric": {},
    "+ triaxiality": {"triaxiality": {}},
    "+ elastic_yielding": {"elastic_yielding": {"k2": 0.30}},
    "+ dissipation": {"elastic_yielding": {"k2": 0.30}, "dissipation": {"Q": 179}},
    "+ excitation (300 terms)": {
        "elastic_yielding": {"k2": 0.30},
        "dissipation": {"Q": 179},
        "excitation": {
            "annual": {"prograde": {"amplitude_mas": 12, "phase_deg": 0}},
            "random": {"seed": 1, "terms": 300, "rms_mas": 20, "periods_days": [20, 4000]},
        },
    },
}


def main():
    print(f"machine: {software_stamp()}\n")
    model = wobble.assemble(earth.H_MHB2000, {})
    exact = AMP * np.exp(1j * model.n * model.wobble_frequency() * T)
    print('100 years of a 0.1" wobble, rigid symmetric Earth: error / wobble, time (min of repeats)')
    print(
        f"  {'rtol':>7s}  "
        + "  ".join(f"{m:>24s}" for m in ("dop853", "scipy:DOP853", "dopri5", "scipy:RK45", "scipy:LSODA"))
    )
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
        cells = []
        for method in ("dop853", "scipy:DOP853", "dopri5", "scipy:RK45", "scipy:LSODA"):
            seconds, sol, _ = min_time(
                lambda: wm.integrate(model, AMP, T, rtol, None, method), repeats=5, budget_s=2.0
            )
            err = abs(sol.y[0] + 1j * sol.y[1] - exact) / AMP
            cells.append(f"{err:9.1e} {seconds * 1e3:9.3f} ms")
        print(f"  {rtol:7.0e}  " + "  ".join(f"{c:>24s}" for c in cells))
    print("\nWhat each effect costs: 100 years at rtol 1e-10 (compiled DOP853)")
    for label, effects in EFFECTS.items():
        m = wobble.assemble(earth.H_MHB2000, effects)
        seconds, sol, _ = min_time(lambda: wm.integrate(m, AMP, T, 1e-10, None), repeats=5, budget_s=2.0)
        print(f"  {label:26s} {sol.n_steps:6d} steps  {seconds * 1e3:9.2f} ms")
    start = time.perf_counter()
    t, m = pm.read_eop(pm.eop_file(), 1962.0, 2100.0)
    read = time.perf_counter() - start
    start = time.perf_counter()
    fit = pm.fit(t, m)
    print(
        f"\nIERS C04: read {t.size} days in {read:.3f} s; fit in {time.perf_counter() - start:.2f} s "
        f"(period {fit.chandler_period_days:.2f} d)"
    )


if __name__ == "__main__":
    main()
