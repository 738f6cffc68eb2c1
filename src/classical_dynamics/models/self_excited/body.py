"""A rigid body as Lee takes it: principal moments A > B > C and his inertia numbers a, b, c."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Body:
    """Principal moments sorted so that A > B > C, and Lee's inertia numbers."""

    A: float
    B: float
    C: float

    @classmethod
    def from_moments(cls, moments) -> "Body":
        A, B, C = sorted((float(x) for x in moments), reverse=True)
        return cls(A, B, C)

    @property
    def a(self) -> float:
        return (self.B - self.C) / self.A

    @property
    def b(self) -> float:
        return (self.A - self.C) / self.B

    @property
    def c(self) -> float:
        return (self.A - self.B) / self.C

    def swapped(self) -> "InertiaNumbers":
        """Lee §2 for a torque along the smallest axis: the same reduction with p <-> r and a <-> c."""
        return InertiaNumbers(self.c, self.b, self.a)


@dataclass(frozen=True)
class InertiaNumbers:
    """(a, b, c) as the reductions use them; a Body's own, or swapped for the smallest axis."""

    a: float
    b: float
    c: float
