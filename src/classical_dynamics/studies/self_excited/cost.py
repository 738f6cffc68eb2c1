"""What a scene of this study costs, from its fields (scenes/cost.py). PLACEHOLDER: being written."""

from __future__ import annotations

from ...scenes.cost import Work


def cost(data: dict) -> list[Work]:
    return []
