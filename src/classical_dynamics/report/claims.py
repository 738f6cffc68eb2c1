"""Claims: statements of the source texts checked against computed numbers, declared as data.

studies/<study>/claims.yaml lists a study's claims. Each names the source's value and where it stands,
the computed number (scene and name in that scene's summary.json), an optional modern value,
and a check: {absolute: tol}, {relative: tol} or {factor: f} (within a factor f) against the source value, or
{at_most: x} / {at_least: x} / {equals: x} on the computed value. A failing claim with must_hold: true fails
the build. Optional: headline: true puts a claim in the report's key results; explanation says why a claim
that may fail does (a failing claim without one fails the build: the report explains every failure it shows);
ours_is: input (or reference, or data) says that "ours" is a model input (or the reference's value, or our
fit to observed data), not a result of the model;
source: derived: true, that the source's own value or form is lost or never printed and was derived here.
A limit of the model says what the model omits (omits:) and may name a reference that omits the same
(expected: {value, cite, what, text}, a rigid-Earth series beside the non-rigid one, text as printed):
its distance from the source's value is the deviation a model without the effect is expected to show.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from ..formatting import exact_figures, format_number, needs_power_of_ten, sig_for_tolerance
from ..scenes.loader import project_yaml


class ClaimFailure(RuntimeError):
    pass


# What a claim is (one kind per claim, claims.yaml's `kind:`), as the report counts them: one, many. A check
# against the project's own earlier figures is no claim but a test (tests/), whatever its kind would be.
KINDS = {
    "statement": (
        "check of a source's statement or formula",
        "checks of the sources' statements and formulas",
    ),
    "erratum": ("erratum of a source", "errata of the sources"),
    # a slip found where the copy consulted is damaged is charged to the copy, not to its author
    "copy": ("possible error of the copy consulted", "possible errors of the copies consulted"),
    # a damaged or ambiguous passage read two ways: the reading not taken is shown failing beside the other
    "reading": ("reading of a source not taken", "readings of the sources not taken"),
    "limit": ("limit of the model", "limits of the model"),
    "reference": ("comparison with an external reference", "comparisons with external references"),
}
# kinds shown and expected not to be met: the source's slip, the copy's, or the reading not taken
SHOWN_NOT_MET = ("erratum", "copy", "reading")
# A claim whose input was fitted to the observable it is compared with tests consistency, not physics: the
# counts set it apart from its kind, so a reader never takes it for an independent check.
COUNTED = KINDS | {"consistency": ("consistency check", "consistency checks")}
# what a count's label leaves to be said, for one and for many
GLOSSES = {
    "copy": ("print or OCR, where it is damaged", "print or OCR, where they are damaged"),
    "reading": ("shown failing: why the other is taken", "shown failing: why the others are taken"),
    "consistency": (
        "an input fitted to what it is compared with",
        "an input fitted to what they are compared with",
    ),
}


# each counted kind in a word or two, for the ledger's columns (Table "by kind" says what each is)
SHORT = {
    "statement": ("statement", "statements"),
    "erratum": ("erratum", "errata"),
    "copy": ("copy's error", "copies' errors"),
    "reading": ("reading not taken", "readings not taken"),
    "limit": ("limit", "limits"),
    "reference": ("reference", "references"),
    "consistency": ("consistency check", "consistency checks"),
}


def count_briefly(claims) -> str:
    """ "21 statements, 6 limits, 5 references, 9 consistency checks": the kinds present, in a few words."""
    counts = [(kind, sum(1 for claim in claims if counted_kind(claim) == kind)) for kind in COUNTED]
    return ", ".join(f"{n} {SHORT[kind][n > 1]}" for kind, n in counts if n)


def counted_kind(claim) -> str:
    """The kind a claim is counted under: its own, or "consistency" where an input was fitted to its match."""
    return "consistency" if claim.consistency else claim.kind


def count_by_kind(claims) -> str:
    """ "330 checks of the sources' statements and formulas, 5 errata of the sources, ...": the kinds
    present, consistency checks counted apart, what each count needs said in one parenthesis."""
    parts = []
    for kind, (one, many) in COUNTED.items():
        of_kind = [claim for claim in claims if counted_kind(claim) == kind]
        n = len(of_kind)
        if not n:
            continue
        notes = [GLOSSES[kind][n > 1]] if kind in GLOSSES else []
        derived = sum(1 for claim in of_kind if claim.source.get("derived"))
        if derived:  # the source's own value or form is lost or was never printed: we derived what it implies
            notes.append(
                f"{derived} of them against a value or form derived here, the source's own being lost or "
                "never printed"
            )
        # a source's value set beside today's (ours_is: input or reference) checks no result of ours: say so
        beside = sum(1 for claim in of_kind if claim.ours_is)
        if beside:
            who = "it sets" if n == 1 else "they set" if beside == n else f"{beside} of them set"
            if beside == 1 and n > 1:
                who += "s"
            notes.append(f"{who} a source's value beside today's, with no result of our model")
        parts.append(f"{n} {one if n == 1 else many}" + (f" ({'; '.join(notes)})" if notes else ""))
    return ", ".join(parts)


def independent(claim) -> bool:
    """An independent check: a result of ours (not a source's value beside today's) against a value the source
    prints (not one derived here), judged, and no consistency check, erratum or reading shown."""
    return (
        counted_kind(claim) in ("statement", "limit", "reference")
        and not claim.source.get("derived")
        and not claim.ours_is
        and claim.judged
    )


def independent_checks(claims) -> list:
    return [claim for claim in claims if independent(claim)]


# what the abstract calls each kind shown and not met, for one and for many: the ledger's words, but a copy's
# error, which in a sentence is only a possible one
SHOWN_NAMES = {kind: SHORT[kind] for kind in SHOWN_NOT_MET} | {
    "copy": ("possible error of a copy", "possible errors of the copies")
}


def shown_not_met(claims) -> str:
    """ "The errata, the possible errors of the copies and the reading not taken are shown, not met" for the
    kinds present ("" if none)."""
    counts = [(kind, sum(1 for claim in claims if claim.kind == kind)) for kind in SHOWN_NOT_MET]
    names = [SHOWN_NAMES[kind][n > 1] for kind, n in counts if n]
    if not names:
        return ""
    names = [f"the {name}" for name in names]
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
    many = len(names) > 1 or any(n > 1 for _, n in counts)
    return f"{listed[0].upper()}{listed[1:]} {'are' if many else 'is'} shown, not met"


def by_kind(claims) -> list[dict]:
    """The ledger's rows by kind: each counted kind, then what part of it checks no result of ours or a value
    derived here; each row with its claims, how many hold, fail or are not judged."""

    def row(label, group, role=""):
        verdicts = [claim.verdict for claim in group]
        return {
            "label": label,
            "role": role,  # "part" (of the row above), "total", "independent" or "" (a kind)
            "claims": len(group),
            **{v: verdicts.count(v) for v in ("pass", "fail", "na")},
        }

    rows = []
    for kind, (one, many) in COUNTED.items():
        group = [claim for claim in claims if counted_kind(claim) == kind]
        if not group:
            continue
        rows.append(row(many, group))
        derived = [claim for claim in group if claim.source.get("derived")]
        if derived:
            rows.append(row("of them against a value or form derived here", derived, "part"))
        beside = [claim for claim in group if claim.ours_is]
        if beside:
            rows.append(row("of them a source's value beside today's, no result of ours", beside, "part"))
    rows.append(row("all kinds", list(claims), "total"))
    rows.append(
        row(
            "independent checks: a result of ours against a value a source prints",
            independent_checks(claims),
            "independent",
        )
    )
    return rows


@dataclass
class ClaimResult:
    id: str
    statement: str
    study: str
    scene: str
    number: str
    computed: object
    unit: str
    source: dict
    modern: dict | None
    check: dict
    deviation: float | None
    relative_deviation: float | None
    passed: bool
    must_hold: bool
    problem: str = ""
    headline: bool = False
    explanation: str = ""
    kind: str = "statement"
    omits: str = ""  # a limit: what the model leaves out, and its expected size
    consistency: str = ""  # an input fitted to the observable it is compared with: what the match tests
    ours_is: str = (
        ""  # "input", "reference" or "data": a model input, the reference's value or our fit to observed data
    )
    expected: dict | None = None  # a limit: a reference that leaves out what the model leaves out
    not_judged: str = (
        ""  # why a claim is shown and not judged: its reference too uncertain to decide anything
    )

    @property
    def expected_size(self) -> float | None:
        """The deviation a model that omits the effect is expected to show, in the deviation column's sense:
        (the reference that omits it - source) / source. None unless the limit names such a reference."""
        if not self.expected or not self.source.get("value"):
            return None
        return (self.expected["value"] - self.source["value"]) / self.source["value"]

    @property
    def judged(self) -> bool:
        """Whether its check decides anything: a limit whose expected size no source gives is shown with our
        bound (a guard against regressions) but neither holds nor fails for a reader; nor does a claim whose
        reference is too uncertain to decide anything (not_judged: says why)."""
        return not (self.kind == "limit" and not self.expected) and not self.not_judged

    @property
    def why_not_judged(self) -> str:
        return self.not_judged or (
            "" if self.judged else "no source gives the expected size: the bound is ours"
        )

    @property
    def verdict(self) -> str:
        """The row's class: pass, fail, or na (a limit not judged)."""
        return "na" if not self.judged else "pass" if self.passed else "fail"

    @property
    def anchor(self) -> str:
        return f"claim-{self.study}-{self.id}"

    @property
    def compares_a_printed_value(self) -> bool:
        """The source prints a number (not 0, not a statement) that ours is checked against. A statement
        checked as a flag of 1 or -1 (yes, a sign, a ratio to the source's own formula), with no text or with
        words or a formula without a figure ('exact', 'prograde', 'stable'), prints no number."""
        value = self.source.get("value")
        if not isinstance(value, (int, float)) or isinstance(value, bool) or value == 0:
            return False
        return not (abs(value) == 1 and not re.search(r"\d", str(self.source.get("text", ""))))

    @property
    def evaluated(self) -> bool:
        """The source value is the source's formula or construction evaluated by us (mpmath, sympy, a closed
        form, with the inputs the row names), not a number the source prints (source: evaluated: true)."""
        return bool(self.source.get("evaluated"))

    @property
    def brief_in_print(self) -> bool:
        """Counted, not listed, in the PDF: it holds, must hold, is no key result, and checks a formula or
        statement of the source (source value 0 or text) rather than a value the source prints."""
        return self.passed and self.must_hold and not self.headline and not self.compares_a_printed_value


def shown_digits(claim: ClaimResult) -> int:
    """The figures a claim's computed value is shown to. Met to round-off: what its check supports, less
    trailing zeros, six at most (the deviation column says how closely). A real difference: what its check
    supports (a whole number without its zeros: −1, not −1.0000000), and enough more that the deviation reads
    back from the figures shown to its first figure, at most three beyond the check's; where ours meets every
    figure the source prints, one past them unless more are needed to read the deviation back."""
    check = claim.check
    reference = claim.source.get("value")
    # At most 8: a tighter agreement than that is read from the deviation column, not from digits.
    if "relative" in check:
        digits = sig_for_tolerance(claim.computed, relative=check["relative"], cap=8)
    elif "absolute" in check:
        digits = sig_for_tolerance(
            reference if reference else claim.computed, absolute=check["absolute"], cap=8
        )
    elif "factor" in check:
        digits = 2
    else:  # a bound: three figures, two of a residual (6.0 × 10⁻¹³ under 10⁻¹⁰)
        digits = 2 if needs_power_of_ten(claim.computed, 2) else 3
    value = claim.computed
    if isinstance(value, float) and math.isfinite(value) and value != 0:
        supported = digits
        shown = _rounded(value, digits)
        trimmed = digits
        # −1, not −1.0000000; but a residual keeps two (1.0 × 10⁻⁷, not an order of magnitude 1 × 10⁻⁷)
        least = 2 if needs_power_of_ten(value, digits) else 1
        while trimmed > least and _rounded(value, trimmed - 1) == shown:
            trimmed -= 1
        # a real difference keeps the figures its check supports (0.550, 0.20), save a whole number's zeros
        real = isinstance(claim.deviation, float) and isinstance(reference, (int, float)) and bool(reference)
        real = real and abs(claim.deviation / reference) >= 1e-6
        digits = supported if real and not shown.is_integer() else trimmed
        printed = _printed_figures(claim)
        agrees = real and printed and _rounded(value, printed) == _rounded(reference, printed)
        if agrees:
            # ours agrees with every figure the source prints (1.757095 against Lamb's 1.7571): one figure
            # past the source's, at most one beyond what the check supports (the deviation says the rest)
            digits = max(min(printed + 1, supported + 1), trimmed if shown.is_integer() else 1)
        elif real:
            # a real difference shows: at least to the figure where ours and the source part (−1 against 1,
            # 0.0035 against 1/300), no more than one beyond what the check supports
            part = next((d for d in range(1, 9) if _rounded(value, d) != _rounded(reference, d)), 8)
            digits = max(digits, min(part, supported + 1, 8))
        if real:
            # ... and until the deviation reads back from the figures shown to its first figure (5.145
            # against 5.15 beside −0.0050, not 5.14; 2.1792 against 2.18 beside −7.6 × 10⁻⁴, not 2.179), or
            # the figures shown are the source's (1.75710: the deviation, under the last of them, says they
            # agree in all), at most three beyond the check's
            while (
                digits < min(supported + 3, 8)
                and not (agrees and _rounded(value, digits) == _rounded(reference, digits))
                and not _reads_back(claim, _rounded(value, digits), digits)
            ):
                digits += 1
        else:
            digits = min(digits, 6)  # met to round-off: the deviation column says how closely
        if not value.is_integer():
            digits = max(digits, math.floor(math.log10(abs(value))) + 1)  # 305, not 310: no whole figure lost
        # ... and a bound is visibly met: 0.49999993 under ½, not 0.5 (no deviation column says it)
        bound = check.get("at_most", check.get("at_least"))
        if isinstance(bound, (int, float)) and bound != value and math.isfinite(bound):
            needed = math.floor(math.log10(abs(value))) - math.floor(math.log10(abs(value - bound))) + 1
            digits = max(digits, min(needed, 8))
    return digits


def _reads_back(claim: ClaimResult, shown: float, digits: int) -> bool:
    """The deviation a reader computes from ours as shown and the source's value as shown (one we evaluated is
    shown to as many figures as ours, four at least: evaluated_text) is the deviation column's to its first
    figure (within half a unit there), in the column's sense: relative or absolute."""
    reference, deviation = claim.source["value"], claim.deviation
    source = reference
    if claim.evaluated:
        source = _rounded(reference, min(max(digits, 4), exact_figures(float(reference))))
    if "relative" in claim.check:
        deviation, read = deviation / reference, shown / source - 1.0
    else:
        read = shown - source
    return deviation == 0 or abs(read - deviation) <= 0.5 * 10.0 ** math.floor(math.log10(abs(deviation)))


def _printed_figures(claim: ClaimResult) -> int:
    """The significant figures of the number the source prints alone ("1.7571": 5, ".7655": 4); 0 when its
    text is no bare number (a symbol, a formula, words)."""
    text = str(claim.source.get("text", "")).strip()
    if not _NUMBER.fullmatch(text):
        return 0
    return len(re.sub(r"\D", "", text).lstrip("0")) or 1


def _rounded(value: float, figures: int) -> float:
    """The value rounded to `figures` significant figures, as it would be shown."""
    return float(f"{value:.{figures - 1}e}")


_NUMBER = re.compile(r"\d+(?:[ \u2009\u202f]\d{3})*(?:\.\d+)?|\.\d+")  # 25 722, 50.385, Lamb's .00327


def source_means(claim: ClaimResult) -> str:
    """The number a symbolic or verbal source value means ("√7" means 2.6457513), to the figures "ours" is
    shown to; "" when the source prints no value, or its text already prints that number (50.385″/yr)."""
    text, value = claim.source.get("text"), claim.source.get("value")
    if (
        not text
        or not isinstance(value, (int, float))
        or isinstance(value, bool)
        or not compares(claim.check)
    ):
        return ""  # a verdict ("stable", "no inflexion") checked by a bound on ours means no number
    if value == 0 or not re.search(r"[\d$\\√π/]", text):
        return ""  # words ("stable", "a constant area"), or a formula met to round-off: no number they mean
    # a subscript is no printed value (the 1 of J/I₁; an exponent may be: J₃⁻² for −2)
    for match in _NUMBER.findall(re.sub(r"_(\{[^}]*\}|\\[A-Za-z]+(\{[^}]*\})?|\w)", "", text)):
        printed = match.replace(" ", "").replace("\u2009", "").replace("\u202f", "")
        decimals = len(printed.partition(".")[2])
        figures = len(printed.replace(".", "").lstrip("0"))
        # a number of two figures or more met to its last place, or one equal to the value (J₃⁻² for −2);
        # the 5 of 5π/3 is no print of 5.236
        if abs(abs(value) - float(printed)) <= 0.5 * 10.0**-decimals and (
            figures > 1 or abs(value) == float(printed)
        ):
            return ""
    return evaluated_text(claim, value)


def prints_a_bare_number(claim: ClaimResult) -> bool:
    """The source's text is a number alone ("5.225", "1"), printed without the unit that ours carries: the
    source cell adds it, so that the two columns read in one unit."""
    return bool(_NUMBER.fullmatch(str(claim.source.get("text", "")).strip()))


def evaluated_text(claim: ClaimResult, value: float) -> str:
    """A number we evaluated from the source, to the figures of ours; a value with a short exact decimal
    as it is (½ means 0.5, not 0.5000)."""
    return format_number(value, min(means_digits(claim), exact_figures(float(value))))


def means_digits(claim: ClaimResult) -> int:
    """The figures a number evaluated from the source is shown to: as many as ours, and at least four
    (1/300 = 0.003333, not 0.0033, where a 2 % check gives ours two)."""
    return max(shown_digits(claim), 4)


def compares(check: dict) -> bool:
    """The check is against the source's value (a deviation from it means something), not a bound on ours."""
    return bool({"absolute", "relative", "factor"} & set(check))


def _pick(value, spec):
    if "index" in spec:
        return value[spec["index"]]
    if spec.get("reduce") == "max_abs":
        return max(abs(v) for v in value if v is not None)
    return value


def evaluate(study: str, claims_file: Path, lookup) -> list[ClaimResult]:
    """lookup(study, scene, number) -> (entry dict) or raises KeyError."""
    results = []
    for claim in project_yaml(claims_file) or []:
        spec, check, source = claim["computed"], claim["check"], claim.get("source", {})
        # required or allowed to fail, said every time: five round-off identities once went "may fail" unsaid
        if not isinstance(claim.get("must_hold"), bool):
            raise ClaimFailure(f"{claims_file}: claim {claim.get('id')}: must_hold must be true or false")
        problem, computed, unit = "", None, ""
        try:
            entry = lookup(study, spec["scene"], spec["number"])
            computed, unit = _pick(entry["value"], spec), entry.get("unit", "")
        except (KeyError, IndexError, TypeError) as exc:
            problem = f"no computed value ({exc})"
        deviation = relative = None
        passed = False
        if computed is not None:
            reference = source.get("value")
            if reference is not None and not isinstance(computed, bool) and compares(check):
                deviation = computed - reference
                relative = deviation / reference if reference else None
            if "absolute" in check:
                passed = abs(deviation) <= check["absolute"]
            elif "relative" in check:
                passed = relative is not None and abs(relative) <= check["relative"]
            elif "at_most" in check:
                passed = computed <= check["at_most"]
            elif "at_least" in check:
                passed = computed >= check["at_least"]
            elif "factor" in check:
                passed = (
                    reference is not None and 1 / check["factor"] <= computed / reference <= check["factor"]
                )
            elif "equals" in check:
                passed = computed == check["equals"]
            else:
                raise ValueError(f"claim {claim['id']}: unknown check {check}")
        results.append(
            ClaimResult(
                id=claim["id"],
                statement=claim["statement"],
                study=study,
                scene=spec["scene"],
                number=spec["number"],
                computed=computed,
                unit=claim.get("unit", unit),
                source=source,
                modern=claim.get("modern"),
                check=check,
                deviation=deviation,
                relative_deviation=relative,
                passed=passed,
                must_hold=claim["must_hold"],
                problem=problem,
                headline=bool(claim.get("headline", False)),
                explanation=claim.get("explanation", ""),
                kind=_kind(claim),
                omits=claim.get("omits", ""),
                consistency=claim.get("consistency", ""),
                ours_is=claim.get("ours_is", ""),
                expected=claim.get("expected"),
                not_judged=claim.get("not_judged", ""),
            )
        )
    return results


def _kind(claim: dict) -> str:
    kind = claim.get("kind")
    if kind not in KINDS:
        raise ClaimFailure(f"claim {claim.get('id')}: kind {kind!r} is not one of {', '.join(KINDS)}")
    if claim.get("ours_is", "") not in ("", "input", "reference", "data"):
        raise ClaimFailure(f"claim {claim.get('id')}: ours_is is input, reference or data")
    if kind == "limit" and not claim.get("omits"):
        raise ClaimFailure(f"claim {claim.get('id')}: a limit of the model says what it omits (omits:)")
    if claim.get("not_judged") is not None and (
        claim["must_hold"] or not isinstance(claim["not_judged"], str)
    ):
        raise ClaimFailure(f"claim {claim.get('id')}: not_judged: says why, on a claim that need not hold")
    expected = claim.get("expected")
    if expected is not None and (kind != "limit" or not {"value", "cite", "what"} <= set(expected)):
        raise ClaimFailure(
            f"claim {claim.get('id')}: expected: belongs to a limit and has a value, a cite and what it is"
        )
    return kind


def require(results: list[ClaimResult]) -> None:
    unexplained = [r for r in results if not r.passed and not r.must_hold and not r.explanation]
    if unexplained:
        raise ClaimFailure(
            "claims that fail without an explanation (add explanation: to the claim): "
            + ", ".join(f"{r.study}/{r.id}" for r in unexplained)
        )
    failed = [r for r in results if r.must_hold and not r.passed]
    if failed:
        lines = [
            f"claim '{r.id}' ({r.study}/{r.scene}: {r.number}) failed: computed {r.computed}, "
            f"source {r.source.get('value')}, check {r.check}{'; ' + r.problem if r.problem else ''}"
            for r in failed
        ]
        raise ClaimFailure("must-hold claims failed:\n  " + "\n  ".join(lines))
