"""A number a caption shares with its chapter's text prints from the same result, at the same figures.

Cheap: the chapters' Jinja source is read for the figures each num(...) asks of a results key, and the study
module's constant that its caption formats that key with must agree.
"""

import re
from pathlib import Path

import pytest

from classical_dynamics.studies.chandler import model as chandler_model
from classical_dynamics.studies.precession import averaged

STUDIES = Path(__file__).resolve().parents[1] / "src" / "classical_dynamics" / "studies"

# (chapter, results key, the caption's figures)
SHARED = [
    ("precession", "obliquity_range_arcsec", averaged.RANGE_SIG),
    ("chandler", "fitted_chandler_period_days", chandler_model.FITTED_PERIOD_SIG),
]


def figures_in_text(study, key):
    text = (STUDIES / study / "chapter.html.j2").read_text()
    found = re.findall(r'num\(\s*\w+\s*,\s*"' + re.escape(key) + r'"\s*,\s*sig=(\d+)', text)
    assert found, f"{study}'s chapter prints no num(..., {key!r}, sig=...)"
    return {int(sig) for sig in found}


@pytest.mark.parametrize("study, key, caption_sig", SHARED)
def test_a_caption_prints_the_texts_number_at_its_figures(study, key, caption_sig):
    assert figures_in_text(study, key) == {caption_sig}


def test_the_captions_read_the_results_key_not_their_own_copy():
    """The captions format the stored number (results.numbers[key]), not a value computed beside it."""
    for module, key in (
        (averaged, "obliquity_range_arcsec"),
        (chandler_model, "fitted_chandler_period_days"),
    ):
        source = Path(module.__file__).read_text()
        assert f"results.numbers['{key}']['value']" in source, (module.__name__, key)
