"""Wall time the way work-precision benchmarks take it: the minimum of repeated runs.

The repeats stop as soon as the minimum is confirmed: the two fastest runs agree within SPREAD. A run that is
slow only the first time (compilation, cold caches) is never among the two fastest once the later runs agree,
so the first run needs no separate warm-up; it is timed like the others. Runs too short for their sum to reach
MIN_SPENT_S keep repeating (they cost nothing) so that timer noise does not confirm a minimum by chance.
"""

from __future__ import annotations

import time

SPREAD = 0.05           # the two fastest runs within 5 % of each other
MIN_SPENT_S = 0.05


def min_time(func, *, repeats: int = 10, budget_s: float = 2.0, warmup: bool = True):
    """(minimum wall time in s, result, runs timed).

    At most 1 + repeats runs (the first stands for the warm-up; warmup=False: at most repeats); after the first
    two, stops once the two fastest agree within SPREAD (and MIN_SPENT_S is spent) or budget_s is spent.
    """
    most = repeats + 1 if warmup else repeats
    times, result = [], None
    while len(times) < max(most, 2 if warmup else 1):
        start = time.perf_counter()
        result = func()
        times.append(time.perf_counter() - start)
        if len(times) < (2 if warmup else 1):
            continue
        spent = sum(times)
        first, second = sorted(times)[:2] if len(times) > 1 else (times[0], float("inf"))
        after_warmup = spent - times[0] if warmup else spent
        if (second <= first * (1 + SPREAD) and spent >= MIN_SPENT_S) or after_warmup >= budget_s:
            break
    return min(times), result, len(times)
