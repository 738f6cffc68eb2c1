"""Atomic, deterministic writes; the one number format; claims; cross-references; bibliography."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from classical_dynamics import io  # noqa: E402
from classical_dynamics.report import claims  # noqa: E402
from classical_dynamics.report.bib import read_bib  # noqa: E402
from classical_dynamics.report.numbering import Numbering  # noqa: E402
from classical_dynamics.report.numbers import format_number  # noqa: E402

from .conftest import ROOT  # noqa: E402


def test_atomic_write_leaves_nothing_half_written(tmp_path):
    target = tmp_path / "summary.json"
    io.write_json(target, {"a": 1})

    class Boom:
        def __float__(self):
            raise RuntimeError("interrupted")
    with pytest.raises(Exception):
        io.atomic_write_bytes(target, Boom())           # fails mid-write
    assert io.read_json(target) == {"a": 1}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["summary.json"]
    assert oct(target.stat().st_mode & 0o777) != oct(0o600)


def test_svg_is_deterministic():
    def draw():
        fig, ax = plt.subplots()
        ax.plot([0, 1, 2], [0, 1, 4], label="x")
        ax.legend()
        data = io.svg_bytes(fig)
        plt.close(fig)
        return data
    assert draw() == draw()


@pytest.mark.parametrize("value,sig,text", [
    (5.22548114733106, 4, "5.225"), (0.189791, 3, "0.190"), (1.5, 4, "1.500"), (9.99996, 4, "10.00"),
    (2.2e-16, 2, "2.2 × 10⁻¹⁶"), (-0.0237, 3, "−0.0237"), (123456.0, 3, "1.23 × 10⁵"), (True, 4, "yes"),
    (None, 4, "—"), (0, 4, "0"), (100000, 4, "100 000"), (12, 4, "12")])
def test_number_format(value, sig, text):
    assert format_number(value, sig) == text


def test_failing_must_hold_claim_names_itself(tmp_path):
    spec = tmp_path / "c.yaml"
    spec.write_text("- id: gravest\n  statement: s\n  source: {value: 5.225}\n"
                    "  computed: {scene: a, number: p}\n  check: {absolute: 1.0e-6}\n  must_hold: true\n")
    results = claims.evaluate("chains", spec, lambda study, scene, number: {"value": 5.2255, "unit": ""})
    assert not results[0].passed
    with pytest.raises(claims.ClaimFailure, match="claim 'gravest'"):
        claims.require(results)


def test_claim_on_missing_number_fails():
    import tempfile
    from pathlib import Path
    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "c.yaml"
        spec.write_text("- id: x\n  statement: s\n  computed: {scene: a, number: p}\n  check: {at_most: 1}\n"
                        "  must_hold: true\n")

        def lookup(*_):
            raise KeyError("no such number")
        (result,) = claims.evaluate("chains", spec, lookup)
    assert not result.passed and "no computed value" in result.problem


def test_numbering_resolves_forward_references():
    numbering = Numbering()
    for _ in range(2):
        numbering.start_pass()
        early = numbering.ref("fig:b")
        numbering.label("fig:a")
        numbering.label("fig:b")
    assert early == "2" and not numbering.missing


def test_bibliography_has_the_required_sources():
    entries = read_bib(ROOT / "report" / "references.bib")
    for key in ("lamb1920", "lee1964", "chandler1891", "bizouard2019", "capitaine2003", "bernoulli1738",
                "rayleigh1877"):
        assert key in entries and entries[key].get("year")
