"""What Lee's generalized sine and cosine integrals cost, side by side in one run (printed, not asserted).

si(x, w) and ci(x, w) of Lee §5.4 for the digest's orders w = 1.3 + 0.4i and 2.7 + 0.5i (table T-D) at
x = 0.5, 2, 10 and 30: Lee's Taylor series (with the reduction (5.32)/(5.33)), his asymptotic expansion cut
at its smallest remainder bound, quadrature (scipy's QAWO plus the expansion's tail) and the automatic
choice si_ci, each with its error against the incomplete gamma function at 30 digits (mpmath), its error
bound and its time; the mpmath reference's own time for scale. Times are minima over repeated calls.

    python benchmarks/sine_cosine_integrals.py
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))
from classical_dynamics.provenance import software_stamp
from classical_dynamics.solvers import sine_cosine_integrals as sc
from classical_dynamics.solvers.timing import min_time

ORDERS = (1.3 + 0.4j, 2.7 + 0.5j)
POINTS = (0.5, 2.0, 10.0, 30.0)
METHODS = {
    "series": sc.series,
    "asymptotic": sc.asymptotic,
    "quadrature": sc.quadrature,
    "si_ci (auto)": sc.si_ci,
}


def main():
    print(software_stamp())
    print(f"{'w':>12} {'x':>5} {'method':>14} {'error':>9} {'bound':>9} {'time':>10}  vs mpmath")
    for w in ORDERS:
        for x in POINTS:
            si, ci = (complex(v) for v in sc.reference(x, w))
            scale = max(abs(si), abs(ci))
            t_ref, _, _ = min_time(lambda: sc.reference(x, w), repeats=3, budget_s=0.5)
            for name, method in METHODS.items():
                seconds, value, _ = min_time(lambda: method(x, w), repeats=20, budget_s=0.5)
                error = max(abs(value.si - si), abs(value.ci - ci)) / scale
                print(
                    f"{w!s:>12} {x:5g} {name:>14} {error:9.1e} {value.bound / scale:9.1e} "
                    f"{seconds * 1e6:8.1f} us  {t_ref / seconds:6.0f}x faster"
                )
            print(f"{'':>12} {'':>5} {'mpmath 30 dps':>14} {'':>9} {'':>9} {t_ref * 1e6:8.1f} us")


if __name__ == "__main__":
    main()
