"""What a scene will cost, estimated from its fields before anything runs, and the budget it must fit.

Each study's `cost(data)` returns the Work its scene asks for: one term per field that sets a size (steps,
samples, a matrix's order, a span over a step), each with the seconds and megabytes that field will cost on
one core of the reference machine (2-core AMD EPYC, where the rates in the studies' cost modules were
measured). The estimate need not be exact: it is there to refuse the scene that would take hours or exhaust
memory, in a second and with the field named, and to give each job a time and memory limit with room to spare.

The budget is set in one place, `budget:` in workflow/config.yaml; a user with a bigger machine raises it
there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import yaml

from .loader import SceneError, lookup

EPS = 2.220446049250313e-16  # double precision: 1 + EPS is the next number after 1
BASE_MEMORY_MB = 1000  # the interpreter with numpy, scipy, numba and matplotlib loaded: 200-320 MB seen
TIME_MARGIN, MEMORY_MARGIN = 10, 2  # a job may take this many times its estimate before it is stopped
MIN_TIME_LIMIT_S = 300  # imports, numba compilation and a slow machine fit in this

SECONDS_PER_JULIAN_YEAR = 86400 * 365.25  # how an estimate is said; scenes sit below models (no import)


@dataclass(frozen=True)
class Work:
    """What one field of a scene asks for."""

    field: str  # dotted scene field, named when the scene is refused
    seconds: float  # estimated wall time, one core of the reference machine
    memory_mb: float = 0.0  # estimated peak memory above the interpreter's own
    what: str = ""  # the size in the field's own terms, e.g. "2.0e10 integration steps"


@dataclass(frozen=True)
class Budget:
    """The most one scene may cost: workflow/config.yaml, `budget:` (these defaults are its values)."""

    seconds: float = 900.0
    memory_mb: float = 6000.0

    @classmethod
    def from_config(cls, config: dict | None) -> "Budget":
        config = config or {}
        unknown = set(config) - {"seconds", "memory_mb"}
        if unknown:
            raise SceneError("workflow/config.yaml", f"budget.{sorted(unknown)[0]}", "seconds or memory_mb")
        values = {}
        for key, value in config.items():
            try:
                values[key] = float(value)
            except (TypeError, ValueError):
                values[key] = math.nan
            if not 0 < values[key] < math.inf:
                raise SceneError("workflow/config.yaml", f"budget.{key}", "a positive number", value)
        return cls(**values)

    @classmethod
    def from_file(cls, path: Path | str = "workflow/config.yaml") -> "Budget":
        path = Path(path)
        config = yaml.safe_load(path.read_text(encoding="utf-8")) if path.is_file() else {}
        return cls.from_config((config or {}).get("budget"))


@dataclass(frozen=True)
class Estimate:
    """A scene's estimated cost, and the limits its job runs under."""

    seconds: float
    memory_mb: float

    @property
    def time_limit_s(self) -> int:
        return int(max(MIN_TIME_LIMIT_S, TIME_MARGIN * self.seconds))

    @property
    def memory_limit_mb(self) -> int:
        return int(BASE_MEMORY_MB + MEMORY_MARGIN * self.memory_mb)


def check_budget(path, data: dict, works: list[Work], budget: Budget) -> Estimate:
    """The scene's Estimate; a SceneError naming the field that costs most if the total is over the budget."""
    for work in works:
        if not (math.isfinite(work.seconds) and math.isfinite(work.memory_mb)):
            raise SceneError(path, work.field, "a size the machine can hold", lookup(data, work.field))
    seconds = sum(w.seconds for w in works)
    memory_mb = max((w.memory_mb for w in works), default=0.0)
    if seconds > budget.seconds:
        worst = max(works, key=lambda w: w.seconds)
        raise SceneError(
            path,
            worst.field,
            f"a scene of at most {budget.seconds:g} s (budget.seconds in "
            f"workflow/config.yaml), not an estimated {_duration(seconds)}"
            + (f" ({worst.what})" if worst.what else ""),
            lookup(data, worst.field),
        )
    if memory_mb > budget.memory_mb:
        worst = max(works, key=lambda w: w.memory_mb)
        raise SceneError(
            path,
            worst.field,
            f"a scene of at most {budget.memory_mb:g} MB (budget.memory_mb in "
            f"workflow/config.yaml), not an estimated {_megabytes(memory_mb)}"
            + (f" ({worst.what})" if worst.what else ""),
            lookup(data, worst.field),
        )
    return Estimate(seconds=seconds, memory_mb=memory_mb)


def check_step(path, field: str, step: float, span: float) -> None:
    """Refuse a step that double precision cannot take: t + step == t well before the end of the span."""
    if not step > 64 * EPS * abs(span):
        raise SceneError(
            path,
            field,
            f"a step of at least {64 * EPS * abs(span):.3g} (64 ulp of the span "
            f"{span:g}: double precision cannot advance time by less)",
            step,
        )


def count(value: float, unit: str) -> str:
    """'2e10 integration steps', '400 samples': a size for the refusal line."""
    text = f"{value:.2g}" if value >= 1e5 else f"{value:.0f}"
    return f"{text.replace('e+0', 'e').replace('e+', 'e')} {unit}"


def _megabytes(mb: float) -> str:
    return f"{mb:.0f} MB" if mb < 1e4 else f"{mb / 1e3:.3g} GB".replace("e+0", "e").replace("e+", "e")


def _duration(seconds: float) -> str:
    if seconds < 3600:
        return f"{seconds:.0f} s"
    if seconds < 86400 * 365:
        return f"{seconds / 3600:.3g} h"
    return f"{seconds / SECONDS_PER_JULIAN_YEAR:.2g} years".replace("e+0", "e").replace("e+", "e")
