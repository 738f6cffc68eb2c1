"""Bad scenes of the chains study (see __init__.py)."""

from . import DELETE, BadScene  # noqa: F401

CASES: list[BadScene] = []
