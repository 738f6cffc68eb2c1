"""Direct unit tests of verify.py's reading and comparing (the archive round trips in test_verify.py are
pipeline tests, absent from the fast run): results folders written here by hand, each refusal one line naming
the file, and compare's changes and table against values worked out here."""

import json
import math

import pytest

from classical_dynamics import verify
from classical_dynamics.verify import MISSING, Change, VerifyError, compare


def write_summary(folder, study, scene, summary):
    path = folder / study / scene / "summary.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(summary) if not isinstance(summary, str) else summary)
    return path


def test_scenes_and_numbers_are_read_from_the_contract(tmp_path):
    write_summary(tmp_path, "b", "two", {"numbers": {"x": {"value": 2.0, "unit": "m"}}})
    write_summary(
        tmp_path,
        "a",
        "one",
        {
            "numbers": {"y": {"value": [1, 2], "unit": "1", "tolerance": 0.1}},
            "stability": [{"name": "hard", "measured": 3e-13, "bound": 1e-12, "unit": "rad"}],
        },
    )
    write_summary(tmp_path, "a", ".staging", {"numbers": {}})  # being written: not a scene
    write_summary(tmp_path, "a", "timings", {"numbers": {}})  # the timing tables: not a scene
    assert verify.scenes_of(tmp_path) == [("a", "one"), ("b", "two")]
    numbers = verify.read_numbers(tmp_path)
    assert numbers == {
        ("a", "one", "y"): {"value": [1, 2], "unit": "1", "tolerance": 0.1},
        ("a", "one", "hard_case:hard"): {"value": 3e-13, "unit": "rad"},
        ("b", "two", "x"): {"value": 2.0, "unit": "m"},
    }
    assert verify.read_numbers(tmp_path, [("b", "two")]) == {("b", "two", "x"): {"value": 2.0, "unit": "m"}}


def test_what_is_not_a_results_folder_is_refused(tmp_path):
    with pytest.raises(VerifyError, match="not a folder"):
        verify.scenes_of(tmp_path / "absent")
    (tmp_path / "a" / "one").mkdir(parents=True)
    with pytest.raises(VerifyError, match="not a results folder"):
        verify.scenes_of(tmp_path)


@pytest.mark.parametrize(
    "summary, message",
    [
        ("{not json", "unreadable or not JSON"),
        ([1, 2], "no 'numbers' object"),
        ({"numbers": [1]}, "no 'numbers' object"),
        ({"numbers": {"x": {"unit": "m"}}}, "number 'x' has no value"),
        ({"numbers": {"x": 1.0}}, "number 'x' has no value"),
        ({"numbers": {}, "stability": {"name": "x"}}, "'stability' is not a list"),
        ({"numbers": {}, "stability": [{"measured": 1.0}]}, "'stability' is not a list"),
    ],
)
def test_a_bad_summary_is_one_line_naming_the_file(tmp_path, summary, message):
    path = write_summary(tmp_path, "a", "one", summary)
    with pytest.raises(VerifyError) as error:
        verify.read_numbers(tmp_path)
    assert str(error.value).startswith(f"{path}: ") and message in str(error.value)
    assert "\n" not in str(error.value)


def test_provenance_is_read_or_refused(tmp_path):
    folder = tmp_path / "a" / "one"
    folder.mkdir(parents=True)
    with pytest.raises(VerifyError, match="provenance.json: missing"):
        verify.read_provenance(tmp_path, "a", "one")
    (folder / "provenance.json").write_text("[1]")
    with pytest.raises(VerifyError, match="not a provenance record"):
        verify.read_provenance(tmp_path, "a", "one")
    (folder / "provenance.json").write_text('{"commit": "abc"}')
    assert verify.read_provenance(tmp_path, "a", "one") == {"commit": "abc"}


@pytest.mark.parametrize("tolerance", [-1.0, True, "0.1", {"relative": -0.1}, {"percent": 1}, {}])
def test_a_malformed_tolerance_is_refused_naming_the_number(tolerance):
    old = {("s", "c", "x"): {"value": 1.0, "tolerance": tolerance}}
    with pytest.raises(VerifyError, match=r"^s/c x: tolerance .* is not a number >= 0"):
        compare(old, {("s", "c", "x"): {"value": 2.0}})


def test_compare_names_added_removed_and_nested_changes():
    old = {
        ("s", "c", "gone"): {"value": 1.0},
        ("s", "c", "d"): {"value": {"p": 1.0, "q": [1, 2]}},
        ("s", "c", "same"): {"value": 0.5},
    }
    new = {
        ("s", "c", "d"): {"value": {"p": 1.0, "q": [1, 3]}},
        ("s", "c", "same"): {"value": 0.5},
        ("t", "e", "new"): {"value": "yes"},
    }
    changes = compare(old, new)
    assert [(c.where, c.number, c.old, c.new) for c in changes] == [
        ("s/c", "d.q[1]", 2, 3),
        ("s/c", "gone", 1.0, MISSING),
        ("t/e", "new", MISSING, "yes"),
    ]
    assert changes[0].tolerance == "default"
    # exact (diff): the last rounding counts, a dict with other keys is one changed value
    moved = compare({("s", "c", "x"): {"value": 1.0}}, {("s", "c", "x"): {"value": 1.0 + 2**-52}}, exact=True)
    assert [(c.number, c.tolerance) for c in moved] == [("x", "exact")]
    shape = compare({("s", "c", "x"): {"value": {"p": 1}}}, {("s", "c", "x"): {"value": {"r": 1}}})
    assert [(c.number, c.old, c.new) for c in shape] == [("x", {"p": 1}, {"r": 1})]


def test_relative_change_and_the_table():
    assert Change("s/c", "x", 4.0, 5.0).relative == 0.25
    assert Change("s/c", "x", -4.0, -5.0).relative == -0.25  # against |old|
    assert Change("s/c", "x", 0.0, -1e-3).relative == -math.inf
    assert Change("s/c", "x", 2.0, 2.0).relative == 0.0
    assert Change("s/c", "x", "a", "b").relative is None and Change("s/c", "x", True, False).relative is None
    changes = [
        Change("s/c", "x", 4.0, 5.0, "rel 0.01"),
        Change("s/c", "gone", 1.0, MISSING, "default"),
        Change("t/e", "new", MISSING, "x" * 50, "default"),
        Change("t/e", "flag", True, False, "default"),
    ]
    lines = verify.table(changes, "old", "new", tolerance=True).splitlines()
    assert lines[0].split() == ["study/scene", "number", "old", "new", "relative", "change", "tolerance"]
    assert lines[1].split() == ["s/c", "x", "4", "5", "+2.500e-01", "rel", "0.01"]
    assert lines[2].split() == ["s/c", "gone", "1", "(none)", "removed", "default"]
    assert lines[3].split() == ["t/e", "new", "(none)", "x" * 39 + "…", "added", "default"]
    assert lines[4].split() == ["t/e", "flag", "true", "false", "—", "default"]
    # the columns line up: the rows' cells start where the header's do
    start = lines[0].index("number"), lines[0].index("relative")
    assert [(line[start[0] - 1], line[start[0] :].split()[0]) for line in lines[1:]] == [
        (" ", "x"),
        (" ", "gone"),
        (" ", "new"),
        (" ", "flag"),
    ]
    assert [line[start[1] :].split()[0] for line in lines[1:]] == ["+2.500e-01", "removed", "added", "—"]
    assert "tolerance" not in verify.table(changes, "old", "new", tolerance=False)
    assert (
        verify._count(changes) == "4 numbers in 2 scenes"
        and verify._count(changes[:1]) == "1 number in 1 scene"
    )
