"""What a chains scene costs, from its fields (scenes/cost.py).

Rates measured here (2-core AMD EPYC, `python /tmp/tchains.py`-style timings of the functions the study
calls): the k lowest modes of n particles (LAPACK's tridiagonal select) 0.11 s at n = 10^5; the lowest mode by
the pliability form 2.4 s and by tridiagonal select 0.5 s at n = 10^6; the dense eigenproblem of n rigid links
0.12 s at n = 1024; sympy's damped-frequency shift for all modes of n particles 0.48, 1.3, 5.0, 21 s for n = 3
to 6.
"""

from __future__ import annotations

from ...scenes.cost import Work, count
from ...solvers.chain_eigen import SOLVER_LIMITS

MODES_S_PER_PARTICLE = 1.1e-6  # tridiagonal select, 5 modes
LOWEST_S_PER_PARTICLE = 3.0e-6  # pliability + tridiagonal select, one mode
DENSE_S_PER_N3 = 1.2e-10  # LAPACK eigh, dense n x n (0.12 s at 1024)
DENSE_CALL_S = 1e-4  # one small dense solve or eigenproblem, overhead
MB = 1e-6


def _dense(n: float) -> float:
    return DENSE_S_PER_N3 * n**3 + DENSE_CALL_S


def cost(data: dict) -> list[Work]:
    chain, analysis = data["chain"], data.get("analysis", {})
    model, n = chain["model"], float(chain.get("n", 1))
    k = float(analysis.get("modes", 5))
    works = [Work("chain", 1.0, 0.0, "the scene's fixed work")]
    if model == "particles":
        # 560 MB resident at n = 10^6, 10 modes: ~300 bytes a particle beyond the interpreter
        works.append(
            Work(
                "chain.n",
                MODES_S_PER_PARTICLE * n * (1 + k / 5),
                8 * n * (k + 30) * MB,
                count(n, "particles"),
            )
        )
        if (
            analysis.get("constraint")
            or analysis.get("forced")
            or analysis.get("friction")
            or analysis.get("initial_value")
            or analysis.get("closed_form")
        ):
            works.append(Work("chain.n", 20 * _dense(n), 8 * 6 * n * n * MB, count(n, "particles, dense")))
    elif model == "links":
        works.append(Work("chain.n", _dense(n), 8 * 3 * n * n * MB, count(n, "links, a dense eigenproblem")))
    elif model == "ring":  # a dense non-symmetric eigenproblem of order 4n
        works.append(Work("chain.n", 4 * _dense(4 * n), 8 * 4 * (4 * n) ** 2 * MB, count(4 * n, "unknowns")))
    if "constraint" in analysis:
        samples = analysis["constraint"]["samples"]
        works.append(
            Work(
                "analysis.constraint.samples",
                (samples + n) * 3 * _dense(n),
                0.0,
                count(samples + n, "constrained eigenproblems"),
            )
        )
    if "forced" in analysis:
        points = analysis["forced"]["points"]
        works.append(
            Work(
                "analysis.forced.points",
                (2 * points + 3001) * _dense(n),
                0.0,
                count(2 * points + 3001, "solves"),
            )
        )
    if "friction" in analysis:
        works.append(
            Work(
                "chain.n",
                0.5 * 4.3 ** (n - 3) * len(analysis["friction"]["scales"]) / 5,
                0.0,
                count(n, "particles in a sympy derivation"),
            )
        )
    if "initial_value" in analysis:  # DOP853 at rtol 1e-13: ~50 steps per fastest period
        steps = 50 * analysis["initial_value"]["periods"] * 2 * n
        works.append(
            Work(
                "analysis.initial_value.periods",
                steps * (1.5e-4 + 12 * 2e-9 * n * n),
                0.0,
                count(steps, "integration steps"),
            )
        )
    for name in ("convergence", "continuum_limit"):
        if name in analysis:
            sizes = [float(v) for v in analysis[name]["n_values"]]
            seconds = sum(_dense(v) if model == "links" else 3 * LOWEST_S_PER_PARTICLE * v for v in sizes)
            memory = max(8 * 3 * v * v if model == "links" else 8 * 20 * v for v in sizes) * MB
            works.append(Work(f"analysis.{name}.n_values", seconds, memory, count(max(sizes), "largest n")))
    if "accuracy_cost" in analysis:
        spec = analysis["accuracy_cost"]
        repeats = spec.get("repeats", 10)
        seconds, memory = 2**19 * LOWEST_S_PER_PARTICLE * 2, 0.0  # the cost-to-target sweep, n = 2 ... 2^18
        for v in map(float, spec["n_values"]):
            run = {
                "dense": _dense(v),
                "tridiagonal": 2e-9 * v * v,
                "tridiagonal_select": 0.6e-6 * v,
                "pliability": 2.4e-6 * v,
            }
            for method, limit in SOLVER_LIMITS.items():
                if v <= limit:
                    seconds += min(3.0, repeats * run[method]) + run[method]
                    memory = max(memory, (8 * 3 * v * v if method == "dense" else 8 * 20 * v) * MB)
        works.append(
            Work("analysis.accuracy_cost.n_values", seconds, memory, count(len(spec["n_values"]), "sizes"))
        )
    if "large_n" in analysis:
        big = float(analysis["large_n"]["n"])
        works.append(
            Work(
                "analysis.large_n.n", LOWEST_S_PER_PARTICLE * big, 8 * 30 * big * MB, count(big, "particles")
            )
        )
    if "time_domain" in analysis:
        spec = analysis["time_domain"]
        # RATTLE: the fastest mode of n particles is ~1.7 n times the gravest (Laguerre zeros); a step costs
        # ~0.4 n us (hanging_time_domain: 3.6e6 steps of 5 particles in 7.2 s)
        periods = 3 * 100 + spec["long_run_periods"] + 60 * len(spec["large_amplitudes_deg"])
        steps = periods * 1.7 * n * spec["steps_per_fastest_period"]
        works.append(
            Work(
                "analysis.time_domain.long_run_periods",
                steps * 0.5e-6 * n,
                0.0,
                count(steps, "integration steps"),
            )
        )
    if "galerkin" in analysis:
        elements = sum(analysis["galerkin"]["elements"])
        works.append(
            Work(
                "analysis.galerkin.elements",
                2e-5 * elements,
                8 * 50 * max(analysis["galerkin"]["elements"]) * MB,
                count(elements, "elements"),
            )
        )
    return works
