"""Atomic, deterministic writes; the one number format; claims; cross-references; bibliography."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pytest

from classical_dynamics import io
from classical_dynamics.formatting import format_number, shortest, sig_for_tolerance
from classical_dynamics.report import assets, claims
from classical_dynamics.report.bib import read_bib
from classical_dynamics.report.numbering import Numbering

# A write that fails after its first 4096 bytes are on disk, as on a full disk: the file-size limit makes the
# kernel refuse the rest (EFBIG; SIGXFSZ ignored). In a child, so the limit is not the test process's.
WRITE_PAST_A_SIZE_LIMIT = """
import resource, signal, sys
from classical_dynamics import io
signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
resource.setrlimit(resource.RLIMIT_FSIZE, (4096, resource.getrlimit(resource.RLIMIT_FSIZE)[1]))
try:
    io.atomic_write_bytes(sys.argv[1], b"x" * 100000)
except OSError as error:
    print(error.errno)
"""


def test_atomic_write_leaves_nothing_half_written(tmp_path):
    import errno
    import subprocess
    import sys

    from .conftest import ROOT, run_env

    target = tmp_path / "summary.json"
    io.write_json(target, {"a": 1})
    done = subprocess.run(
        [sys.executable, "-c", WRITE_PAST_A_SIZE_LIMIT, str(target)],
        env=run_env(ROOT),
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.stdout.strip() == str(errno.EFBIG), done.stderr  # it failed mid-write, bytes already out
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


def test_a_count_from_numpy_prints_exactly():
    """A table's integer column arrives as numpy.int64: 16, never 1.600 × 10¹, also beside powers of ten."""
    import numpy as np

    from classical_dynamics.formatting import format_column

    assert format_number(np.int64(16)) == "16"
    assert format_column([np.int64(16), 2.5e-5])[0] == "16"


@pytest.mark.parametrize(
    "value,sig,text",
    [
        (5.22548114733106, 4, "5.225"),
        (0.189791, 3, "0.190"),
        (1.5, 4, "1.500"),
        (9.99996, 4, "10.00"),
        (2.2e-16, 2, "2.2 × 10⁻¹⁶"),
        (-0.0237, 3, "−0.0237"),
        (123456.0, 3, "1.23 × 10⁵"),
        (True, 4, "yes"),
        (None, 4, "—"),
        (0, 4, "0"),
        (100000, 4, "100\u202f000"),
        (12, 4, "12"),
        # rounding decides the notation: five figures of 99 999.6 are 1.0000 × 10⁵, never 100000
        (99999.6, 5, "1.0000 × 10⁵"),
        (99999.4, 5, "99\u202f999"),
        (0.00099996, 4, "0.001000"),
        (0.00099994, 4, "9.999 × 10⁻⁴"),
        (-0.0, 4, "0"),
        (-1e-300, 2, "−1.0 × 10⁻³⁰⁰"),
        (12345.67, 6, "12\u202f345.7"),
        (-9.99999, 3, "−10.0"),
        # no figure beyond those asked for: 33 787 at two figures is 34 000 (a referee read "33 787")
        (33787.0, 2, "34\u202f000"),
        (5917.0, 2, "5900"),
        (-447.3, 2, "−450"),
        (float("inf"), 3, "∞"),
        (-7, 4, "−7"),
    ],
)
def test_number_format(value, sig, text):
    assert format_number(value, sig) == text.replace(" × ", "\u202f×\u202f")  # × never breaks a line


@pytest.mark.parametrize(
    "value,text",
    [
        (50.5, "50.5"),
        (306.0, "306"),
        (0.00327, "0.00327"),
        (2.18, "2.18"),
        (433.1, "433.1"),
        (-46.84, "−46.84"),
        (1.6e-10, "1.6 × 10⁻¹⁰"),
        (6.7575599248, "6.7575599"),
    ],
)
def test_source_values_keep_their_printed_digits(value, text):
    assert shortest(value) == text.replace(" × ", "\u202f×\u202f")


@pytest.mark.parametrize(
    "check,value,figures",
    [
        ({"relative": 0.01}, 306.0, 3),
        ({"relative": 1e-12}, 1.0, 12),
        ({"absolute": 0.05}, 50.4, 4),
        ({"absolute": 1.0}, 433.0, 3),
    ],
)
def test_claim_digits_follow_the_check(check, value, figures):
    assert sig_for_tolerance(value, **check) == figures


@pytest.mark.parametrize(
    "check,value,figures",
    [
        ({"relative": 1e-8}, -1.0, 1),  # a sign: −1, not −1.0000000
        ({"absolute": 1e-6}, 60.0, 1),  # an angle met to round-off: 60 (one figure), not 60.000000
        ({"relative": 1e-8}, 1.2345678901, 6),  # met to round-off: six figures, the deviation says the rest
        ({"relative": 0.01}, 306.04, 3),
        (
            {"absolute": 1e-6},
            1.0e-7,
            2,
        ),  # a residual: 1.0 × 10⁻⁷, which an order of magnitude 1 × 10⁻⁷ is not
    ],
)
def test_a_claims_value_shows_no_string_of_zeros(check, value, figures):
    assert claims.shown_digits(a_claim(value, {"value": value}, check)) == figures


def a_claim(computed, source: dict, check: dict, deviation=0.0) -> claims.ClaimResult:
    """A claim that holds and must, with what these tests vary."""
    return claims.ClaimResult(
        "x", "s", "chains", "a", "p", computed, "", source, None, check, deviation, 0.0, True, True
    )


@pytest.mark.parametrize(
    "check,source,value,shown",
    [
        # the figures the check supports, one more only where they would read as the source's value rounded
        # alike: the deviation column, not a string of digits, says by how much
        ({"absolute": 0.3}, 4.0, 3.968, "3.97"),  # Lee's slope: not "4.0" beside a deviation of −3.2 × 10⁻²
        ({"absolute": 0.3}, 4.0, 4.0027, "4.003"),  # its +0.0027 reads back; not 4.0027 at ±0.3
        (
            {"absolute": 0.01},
            2.18,
            2.17924,
            "2.1792",
        ),  # Lamb's ratio: −7.6 × 10⁻⁴ reads back, not −1.0 × 10⁻³
        ({"absolute": 1.7}, 433.1, 432.61, "432.6"),  # not "433", which reads as 433.1 rounded
        ({"relative": 0.003}, 50.385, 50.4001, "50.40"),  # not "50.4", which would read as 50.385 rounded
        ({"relative": 0.02}, 300.0, 305.47, "305"),  # no whole figure rounded away (not 310)
        ({"relative": 0.005}, 0.5518, 0.54963, "0.5496"),  # −3.9 × 10⁻³ rel. reads back (0.550 reads −3.3)
        ({"relative": 0.005}, 0.5518, 0.55004, "0.550"),  # the figures its check supports, zeros and all
        ({"relative": 1e-8}, 1.0, -1.0, "−1"),  # a sign against the source's: −1, not −1.0000000
        ({"relative": 0.05}, 1 / 300, 0.0034609, "0.00346"),  # 0.0035 would read back as +5 %, not +3.8 %
        ({"absolute": 0.01}, 5.15, 5.14496, "5.145"),  # 5.14 would read back as −0.01, not −0.005
        ({"absolute": 0.1}, 6.3832, 6.3866, "6.387"),  # 6.39 would read back as +0.007, not +0.0034
        ({"relative": 1e-8}, 0.288675134594813, 0.28867513459485, "0.288675"),  # 1e-13: the column says it
        ({"at_most": 0.5}, 0.5, 0.49999992538819, "0.49999993"),  # under ½, not "0.5"
        ({"at_least": 10}, None, 9730.91, "9731"),  # far from its bound: the figures its check supports
    ],
)
def test_ours_never_reads_as_the_sources_value_when_it_differs(check, source, value, shown):
    bound = "at_most" in check or "at_least" in check  # a bound has no deviation
    claim = a_claim(value, {"value": source}, check, None if bound else value - source)
    assert format_number(value, claims.shown_digits(claim)) == shown


@pytest.mark.parametrize(
    "text,check,value,shown",
    [
        # ours agrees with every figure the source prints: one figure past the source's, no more (the
        # deviation column says the rest), not 1.757095, which read as a claim of seven figures
        ("1.7571", {"absolute": 5e-5}, 1.7570954, "1.75710"),
        (".7655", {"absolute": 5e-5}, 0.76547979, "0.76548"),
        # ... and a source's figure that ours does not meet still shows where they part
        ("2.18", {"absolute": 0.01}, 2.17924, "2.1792"),
        # ... or where one more is needed for the deviation to read back (not 5.2251 beside 5.5 × 10⁻⁵)
        ("5.225", {"absolute": 5e-4}, 5.2250551, "5.22506"),
    ],
)
def test_ours_met_in_every_printed_figure_stops_one_past_them(text, check, value, shown):
    source = float(text)
    claim = a_claim(value, {"value": source, "text": text}, check, value - source)
    assert format_number(value, claims.shown_digits(claim)) == shown


def test_plural_and_units():
    from classical_dynamics.units import UnknownUnit, unit_text

    assert unit_text("periods", 1) == "\u202fperiod" and unit_text("periods", 2) == "\u202fperiods"
    assert unit_text("d", 1) == "\u202fd"  # a symbol is never pluralized
    assert unit_text("″/yr", 50.4) == "″/yr"  # closes up: 50.4″/yr
    assert unit_text("1") == "" and unit_text(None) == ""
    with pytest.raises(UnknownUnit):
        unit_text("furlongs/fortnight")


def test_failing_must_hold_claim_names_itself(tmp_path):
    spec = tmp_path / "c.yaml"
    spec.write_text(
        "- id: gravest\n  statement: s\n  kind: statement\n  source: {value: 5.225}\n"
        "  computed: {scene: a, number: p}\n  check: {absolute: 1.0e-6}\n  must_hold: true\n"
    )
    results = claims.evaluate("chains", spec, lambda study, scene, number: {"value": 5.2255, "unit": ""})
    assert not results[0].passed
    with pytest.raises(claims.ClaimFailure, match="claim 'gravest'"):
        claims.require(results)


def test_a_claim_that_does_not_say_whether_it_must_hold_is_refused(tmp_path):
    """Required of every rebuild, or allowed to fail with its reason: a claim says which (five round-off
    identities once defaulted to "may fail" without a word)."""
    spec = tmp_path / "c.yaml"
    spec.write_text(
        "- id: silent\n  statement: s\n  kind: statement\n  source: {value: 0}\n"
        "  computed: {scene: a, number: p}\n  check: {at_most: 1.0e-9}\n"
    )
    with pytest.raises(claims.ClaimFailure, match="silent: must_hold"):
        claims.evaluate("chains", spec, lambda *_: {"value": 0.0, "unit": ""})


@pytest.mark.parametrize(
    "fields,refusal",
    [
        ("", "kind None is not one of"),
        ("  kind: anecdote\n", "kind 'anecdote'"),
        ("  kind: limit\n", "omits"),
    ],
)
def test_a_claim_says_what_it_is(tmp_path, fields, refusal):
    """Every claim has one kind (a source's statement, an erratum, a limit of the model saying what it leaves
    out, an external reference, a regression), or the report refuses it."""
    spec = tmp_path / "c.yaml"
    spec.write_text(
        f"- id: x\n  statement: s\n{fields}  computed: {{scene: a, number: p}}\n  check: {{at_most: 1}}\n"
        "  must_hold: true\n"
    )
    with pytest.raises(claims.ClaimFailure, match=refusal):
        claims.evaluate("chains", spec, lambda *_: {"value": 0.5, "unit": ""})


def test_claim_on_missing_number_fails():
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "c.yaml"
        spec.write_text(
            "- id: x\n  statement: s\n  kind: statement\n  computed: {scene: a, number: p}\n"
            "  check: {at_most: 1}\n  must_hold: true\n"
        )

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
    entries = read_bib(assets.BIBLIOGRAPHY)
    for key in (
        "lamb1920",
        "lee1964",
        "chandler1891",
        "bizouard2019",
        "capitaine2003",
        "bernoulli1738",
        "rayleigh1877",
    ):
        assert key in entries and entries[key].get("year")


@pytest.mark.parametrize(
    "text,value,check,means",
    [
        ("$\\sqrt{7}$", 7**0.5, {"relative": 1e-12}, "2.64575"),  # a symbol gets the number it means
        ("9/11", 9 / 11, {"relative": 1e-9}, "0.818182"),  # a fraction stays a fraction, with its value
        ("50.385″/yr", 50.38481507, {"absolute": 0.05}, ""),  # a printed number is not repeated
        ("$360°/\\psi_\\mathrm{A}$ = 25 722 yr", 25722.0, {"relative": 0.01}, ""),
        ("stable", True, {"equals": True}, ""),  # a verdict means no number
        ("unstable", 1.0, {"at_least": 100.0}, ""),  # ... nor a flag checked by a bound on ours
        ("$5\\pi/3$", 5.235987755982988, {"relative": 1e-9}, "5.23599"),  # its 5 is no print of 5.236
        ("$J_3^{-2}$", -2.0, {"absolute": 0.1}, ""),
        (".7655", 0.76548, {"absolute": 1e-4}, ""),  # Lamb's decimals without their 0 are a print
        ("1/300", 1 / 300, {"relative": 0.02}, "0.003333"),  # four figures at least, not 0.0033
        ("a constant area", 0.0, {"absolute": 1e-9}, ""),  # words mean no number
        ("$Ma^2/2$", 0.5, {"relative": 1e-12}, "0.5"),  # a short exact decimal as it is, not 0.5000
        ("$\\Omega_\\mathrm{s} = J/I_1$", 1.0, {"relative": 1e-8}, "1"),  # the 1 of I₁ is no print of 1
    ],
)
def test_a_symbolic_source_value_shows_the_number_it_means(text, value, check, means):
    assert claims.source_means(a_claim(value, {"text": text, "value": value}, check)) == means


def test_a_value_no_source_prints_is_marked_evaluated():
    """A source value without printed text and with more figures than a 1920s or 1960s text prints, or whose
    row says it was evaluated (mpmath, sympy, a quadrature), is ours from the source's formula: marked so."""
    import re
    from pathlib import Path

    import yaml

    from classical_dynamics.studies.registry import STUDIES

    root = Path(claims.__file__).parents[1] / "studies"
    unmarked = []
    for study in STUDIES:
        for claim in yaml.safe_load((root / study / "claims.yaml").read_text(encoding="utf-8")):
            source, value = claim.get("source", {}), claim.get("source", {}).get("value")
            if "text" in source or not isinstance(value, float) or value == 0 or source.get("evaluated"):
                continue
            figures = len(f"{abs(value):.15g}".replace(".", "").lstrip("0").rstrip("0"))
            if figures > 8 or re.search(r"evaluat|mpmath|sympy|quadrature|derived", source.get("where", "")):
                unmarked.append(f"{study}/{claim['id']}")
    assert not unmarked, unmarked


def test_the_rigid_series_values_are_the_explanatory_supplements():
    """The rigid-Earth reference is Woolard's series as the Explanatory Supplement (1961) prints it, read from
    its transcription in Plan 9's astro (nutt.c: the coefficients to 0.0001 arcsec, no secular rates); the
    limit rows name the same value for their expected size. His 18.6-year amplitudes rest on the observed
    constant of nutation: no row takes them as a rigid Earth."""
    from pathlib import Path

    import yaml

    printed = {  # nutt.c's nutfp: 1.2730 (2L, longitude), .5519 (obliquity), .2037 and .0884 (2L')
        "semiannual_longitude": 1.2730,
        "semiannual_obliquity": 0.5519,
        "fortnightly_longitude": 0.2037,
        "fortnightly_obliquity": 0.0884,
    }
    rows = {
        c["id"]: c
        for c in yaml.safe_load(
            (Path(claims.__file__).parents[1] / "studies/precession/claims.yaml").read_text(encoding="utf-8")
        )
    }
    for cid, value in printed.items():
        for row, field in ((rows[cid], "expected"), (rows["woolard_" + cid], "source")):
            assert row[field]["value"] == value, cid
            assert row[field]["cite"] == "plan9astro", cid
            assert not row[field].get("evaluated"), cid
        assert rows["woolard_" + cid]["computed"] == rows[cid]["computed"], cid
    assert not any(c.get("expected") for c in rows.values() if c["id"].startswith("nutation_18p6"))
    assert not any(c["id"].startswith("woolard_nutation_18p6") for c in rows.values())


def test_every_limit_of_the_model_says_how_big_what_it_leaves_out_is():
    """A limit names what the model leaves out and its expected size: a reference that leaves out the same
    (expected:), or sizes in its text (a published estimate of each part)."""
    import re
    from pathlib import Path

    import yaml

    from classical_dynamics.studies.registry import STUDIES

    root = Path(claims.__file__).parents[1] / "studies"
    unsized = [
        f"{study}/{claim['id']}"
        for study in STUDIES
        for claim in yaml.safe_load((root / study / "claims.yaml").read_text(encoding="utf-8"))
        if claim["kind"] == "limit"
        and not claim.get("expected")
        and "not at hand from a source" not in claim["omits"]  # a gap declared to the reader, with why
        and not re.search(r"\d\s*(%|d\b|″|mas)", claim["omits"])  # a size: 30 d, 3 %, 0.1″; not MHB2000
    ]
    assert not unsized, unsized


def test_a_limits_expected_size_is_the_source_against_a_reference_that_omits_the_same(tmp_path):
    import yaml

    base = {"id": "x", "statement": "s", "kind": "limit", "omits": "the core."}
    base |= {"source": {"value": 1.25}, "computed": {"scene": "a", "number": "n"}}
    base |= {"check": {"relative": 0.1}, "must_hold": True}
    base["expected"] = {"value": 1.0, "what": "a rigid series", "cite": "woolard1953"}
    path = tmp_path / "claims.yaml"
    path.write_text(yaml.safe_dump([base]))
    (row,) = claims.evaluate("s", path, lambda *a: {"value": 1.2})
    assert row.expected_size == pytest.approx(-0.2)  # (1.0 - 1.25)/1.25: the deviation column's sense
    for broken in ({**base, "kind": "reference"}, {**base, "expected": {"value": 1.0}}):
        path.write_text(yaml.safe_dump([broken]))
        with pytest.raises(claims.ClaimFailure, match="expected"):
            claims.evaluate("s", path, lambda *a: {"value": 1.2})


def test_a_claim_says_when_ours_is_an_input_and_refuses_another_word(tmp_path):
    """A row whose "ours" is the model's input (or the reference's own value) says so beside the value; a
    misspelt ours_is stops the build rather than pass unmarked."""
    import yaml

    base = {"id": "x", "statement": "s", "kind": "reference", "source": {"value": 1.0}}
    base |= {"computed": {"scene": "a", "number": "n"}, "check": {"relative": 0.1}, "must_hold": True}
    lookup = lambda study, scene, number: {"value": 1.01, "unit": "1"}  # noqa: E731
    path = tmp_path / "claims.yaml"
    path.write_text(yaml.safe_dump([base | {"ours_is": "input"}]))
    (claim,) = claims.evaluate("chains", path, lookup)
    assert claim.ours_is == "input"
    path.write_text(yaml.safe_dump([base | {"ours_is": "inptu"}]))
    with pytest.raises(claims.ClaimFailure, match="ours_is"):
        claims.evaluate("chains", path, lookup)


def test_the_count_by_kind_says_how_many_set_a_sources_value_beside_todays():
    """A row whose "ours" is an input or the reference's value checks no result of ours: the abstract's count
    of comparisons says how many of them are such, or that all are."""

    def claim(kind, ours_is=""):
        c = a_claim(1.0, {"value": 1.0}, {"relative": 0.1})
        c.kind, c.ours_is = kind, ours_is
        return c

    rows = [claim("statement"), claim("statement"), claim("reference"), claim("reference", "input")]
    assert claims.count_by_kind(rows) == (
        "2 checks of the sources' statements and formulas, 2 comparisons with external references (1 of them "
        "sets a source's value beside today's, with no result of our model)"
    )
    assert claims.count_by_kind([claim("reference", "reference")]) == (
        "1 comparison with an external reference (it sets a source's value beside today's, with no result of "
        "our model)"
    )


def test_a_consistency_check_is_counted_apart_from_its_kind():
    """A reference row whose input was fitted to the observable it matches is no independent comparison: the
    counts (abstract, ledger) set it apart, so "external references" counts only independent ones."""
    rows = [a_claim(1.0, {"value": 1.0}, {"relative": 0.1}) for _ in range(3)]
    rows[0].kind = rows[1].kind = "reference"
    rows[1].consistency = "the input was fitted to this observable"
    rows[1].ours_is = "reference"
    rows[2].kind = "copy"  # a slip where the copy is damaged: the copy's, not the author's
    assert claims.counted_kind(rows[1]) == "consistency" and claims.counted_kind(rows[0]) == "reference"
    assert claims.count_by_kind(rows) == (
        "1 possible error of the copy consulted (print or OCR, where it is damaged), "
        "1 comparison with an external reference, 1 consistency check (an input fitted to what it is "
        "compared with; it sets a source's value beside today's, with no result of our model)"
    )


def test_a_ledger_maps_each_statement_to_one_thing_and_counts_them(tmp_path):
    """A tiny ledger written here: what it counts, and each way a statement can be mis-mapped refused."""
    import yaml

    from classical_dynamics.report import ledger

    claims_file = tmp_path / "claims.yaml"
    claims_file.write_text(yaml.safe_dump([{"id": "c1"}]))
    folder = tmp_path / "ledger"
    folder.mkdir()

    def write(statements):
        (folder / "src.yaml").write_text(
            yaml.safe_dump({"source": {"key": "k", "title": "T"}, "statements": statements})
        )
        return ledger.read_ledger(folder, {"chains": claims_file})

    (source,) = write(
        [
            {"id": "a", "claim": "chains/c1"},
            {"id": "b", "figure": "fig:x"},
            {"id": "c", "out_of_scope": "unreadable"},
        ]
    )
    assert (source.key, source.title, source.in_scope, source.covered) == ("k", "T", 2, 2)
    assert [s.study for s in source.statements] == ["chains", None, None]
    ledger.require_figures([source], {"fig:x"})
    with pytest.raises(ledger.LedgerError, match="maps to figure 'fig:x'"):
        ledger.require_figures([source], {"fig:y"})
    for statements, refusal in (
        ([{"id": "a", "claim": "chains/c1"}, {"id": "a", "claim": "chains/c1"}], "appears twice"),
        ([{"id": "a"}], "it maps to nothing"),
        ([{"id": "a", "claim": "chains/c1", "figure": "fig:x"}], "it maps to claim, figure"),
        ([{"id": "a", "claim": "chains/c9"}], "which no study's claims.yaml declares"),
    ):
        with pytest.raises(ledger.LedgerError, match=refusal):
            write(statements)


@pytest.mark.parametrize(
    "source,printed",
    [
        ({"value": 50.5}, True),
        ({"value": 2.18, "text": "2.18"}, True),
        ({"value": 0.31622776601683794, "text": "$2\\pi/\\sqrt{10}$"}, True),  # a symbol with a figure in it
        ({"value": 1.0032845478, "text": "$C/A$"}, True),  # a symbol that means a number
        ({"value": 1, "text": "exact"}, False),  # words, checked as a flag
        ({"value": -1, "text": "−"}, False),  # a sign
        (
            {"value": 1, "text": "$q_r = \\alpha_r(He^{\\lambda t} + Ke^{-\\lambda t})$"},
            False,
        ),  # a formula, a flag
        ({"value": 1}, False),  # a yes, or a ratio to the source's formula
        ({"value": 1, "text": "1"}, True),  # a 1 the source prints
        ({"value": 0}, False),
    ],
)
def test_a_flag_for_words_is_no_printed_value(source, printed):
    """Rows whose source states in words or a formula go to the formula tables, not beside printed values."""
    assert a_claim(1.0, source, {"relative": 0.1}).compares_a_printed_value is printed


def test_a_limit_without_an_expected_size_is_shown_but_not_judged():
    """A limit row whose bound is ours (no source gives the size of what the model leaves out) neither holds
    nor fails for a reader: its verdict is n/a. With a source's expected size, it is judged."""
    row = a_claim(1.0, {"value": 1.0}, {"relative": 0.1})
    assert row.judged and row.verdict == "pass"
    row.kind = "limit"
    assert not row.judged and row.verdict == "na"
    row.expected = {"value": 0.9, "cite": "x", "what": "a rigid series"}
    assert row.judged and row.verdict == "pass"
    row.passed = False
    assert row.verdict == "fail"


def test_a_claim_too_uncertain_to_judge_says_why_and_counts_as_neither(tmp_path):
    """not_judged: a claim whose reference cannot decide anything is n/a with its reason; one that must hold
    cannot be so (it would hide a failure), and the reason must be words."""
    import yaml

    row = a_claim(1.0, {"value": 1.0}, {"relative": 0.1})
    row.not_judged = "the reference is known within a factor of three"
    assert not row.judged and row.verdict == "na" and row.why_not_judged == row.not_judged
    row.not_judged, row.kind = "", "limit"
    assert row.why_not_judged.startswith("no source gives the expected size")

    def evaluated(tmp_path, **extra):
        base = {"id": "x", "statement": "s", "kind": "statement", "source": {"value": 1.0}}
        base |= {"computed": {"scene": "a", "number": "n"}, "check": {"relative": 0.1}} | extra
        path = tmp_path / "claims.yaml"
        path.write_text(yaml.safe_dump([base]))
        return claims.evaluate("chains", path, lambda *_: {"value": 1.0, "unit": "1"})

    (ok,) = evaluated(tmp_path, must_hold=False, not_judged="why")
    assert ok.verdict == "na"
    for extra in ({"must_hold": True, "not_judged": "why"}, {"must_hold": False, "not_judged": 3}):
        with pytest.raises(claims.ClaimFailure, match="not_judged"):
            evaluated(tmp_path, **extra)


def test_the_ledger_by_kind_and_the_independent_checks():
    """Each kind with its hold/fail/n-a; the part that checks a derived value or no result of ours indented
    under it; the independent checks counted apart: a result of ours against a printed value, judged, and no
    consistency check, erratum or reading not taken."""
    rows = [a_claim(1.0, {"value": 1.0}, {"relative": 0.1}) for _ in range(7)]
    rows[1].source = {"value": 1.0, "derived": True}
    rows[2].kind, rows[2].passed = "erratum", False
    rows[3].kind, rows[3].ours_is = "reference", "input"
    rows[4].kind = "reference"
    rows[5].consistency = "fitted"
    rows[6].kind, rows[6].passed = "reading", False
    table = {
        (r["label"], r["role"]): (r["claims"], r["pass"], r["fail"], r["na"]) for r in claims.by_kind(rows)
    }
    many = {kind: plural for kind, (_, plural) in claims.COUNTED.items()}
    assert table[(many["statement"], "")] == (2, 2, 0, 0)
    assert table[("of them against a value or form derived here", "part")] == (1, 1, 0, 0)
    assert table[(many["erratum"], "")] == (1, 0, 1, 0) and table[(many["reading"], "")] == (1, 0, 1, 0)
    assert table[(many["reference"], "")] == (2, 2, 0, 0) and table[(many["consistency"], "")] == (1, 1, 0, 0)
    assert table[("all kinds", "total")] == (7, 5, 2, 0)
    assert [r for r in rows if claims.independent(r)] == [rows[0], rows[4]]
    assert claims.shown_not_met(rows) == "The erratum and the reading not taken are shown, not met"
    assert claims.shown_not_met(rows[:2]) == ""


def test_the_ledger_counts_each_chapter_in_a_few_words():
    rows = [a_claim(1.0, {"value": 1.0}, {"relative": 0.1}) for _ in range(4)]
    rows[1].kind, rows[2].kind, rows[3].consistency = "limit", "limit", "fitted"
    assert claims.count_briefly(rows) == "1 statement, 2 limits, 1 consistency check"
    assert claims.count_briefly([]) == ""
