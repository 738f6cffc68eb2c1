"""Wall time the way work-precision benchmarks take it: the minimum of repeated runs.

The repeats stop as soon as the minimum is confirmed: the two fastest runs agree within SPREAD. A run that is
slow only the first time (compilation, cold caches) is never among the two fastest once the later runs agree,
so the first run needs no separate warm-up; it is timed like the others. Runs too short for their sum to reach
MIN_SPENT_S keep repeating (they cost nothing) so that timer noise does not confirm a minimum by chance.
"""

from __future__ import annotations

import os
import time

ONCE = "CLASSICAL_DYNAMICS_TIME_ONCE"  # set (the tests set it): each timing is one run (values, not times)
SPREAD = 0.05  # the two fastest runs within 5 % of each other
MIN_SPENT_S = 0.05


def min_time(func, *, repeats: int = 10, budget_s: float = 2.0, warmup: bool = True):
    """(minimum wall time in s, result, runs timed).

    At most repeats runs, and one more standing for the warm-up (warmup=True; budget_s counts after it). Stops
    once the two fastest agree within SPREAD (and MIN_SPENT_S is spent) or budget_s is spent.
    """
    if os.environ.get(ONCE):
        repeats, warmup = 1, False
    first = 1 if warmup else 0  # runs before the budget starts counting
    times, result = [], None
    while len(times) < repeats + first:
        start = time.perf_counter()
        result = func()
        times.append(time.perf_counter() - start)
        fastest = sorted(times)[:2]
        confirmed = (
            len(fastest) == 2 and fastest[1] <= fastest[0] * (1 + SPREAD) and sum(times) >= MIN_SPENT_S
        )
        if len(times) > first and (confirmed or sum(times[first:]) >= budget_s):
            break
    return min(times), result, len(times)
