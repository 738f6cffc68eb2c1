"""Wall time the way work-precision benchmarks take it: one warm-up, then the minimum of repeats."""

from __future__ import annotations

import time


def min_time(func, *, repeats: int = 10, budget_s: float = 2.0, warmup: bool = True):
    """(minimum wall time in s, result, runs). Repeats stop early once budget_s is spent."""
    result = func() if warmup else None
    best, runs, spent = float("inf"), 0, 0.0
    while runs < repeats and (runs == 0 or spent < budget_s):
        start = time.perf_counter()
        result = func()
        elapsed = time.perf_counter() - start
        best, runs, spent = min(best, elapsed), runs + 1, spent + elapsed
    return best, result, runs
