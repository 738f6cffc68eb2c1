"""Direct test of report/build.py's _split_columns (a table's column holding different quantities by row,
shown as one column per kind; no fast test reached it): a frame written here and the columns worked out by
hand."""

import math

import pandas as pd

from classical_dynamics.report.build import _split_columns


def test_a_column_of_two_quantities_becomes_one_column_per_kind():
    frame = pd.DataFrame(
        {
            "method": ["dop853", "rk4", "dopri5", "rk4"],
            "setting": [1e-9, 0.01, 1e-6, 0.002],
            "kind": ["tolerance", "step", "tolerance", "step"],
            "error": [1.0, 2.0, 3.0, 4.0],
        }
    )
    split, columns = _split_columns(frame, ["method", "setting", "kind", "error"], {"setting": "kind"})
    # in the order the kinds first appear, where the column stood; "kind" itself no longer shown
    assert columns == ["method", "setting:tolerance", "setting:step", "error"]
    assert "setting" not in split and "kind" not in split
    tolerance, step = split["setting:tolerance"].tolist(), split["setting:step"].tolist()
    assert (
        [tolerance[0], tolerance[2]] == [1e-9, 1e-6] and math.isnan(tolerance[1]) and math.isnan(tolerance[3])
    )
    assert [step[1], step[3]] == [0.01, 0.002] and math.isnan(step[0]) and math.isnan(step[2])
    assert split["error"].tolist() == [1.0, 2.0, 3.0, 4.0] and split["method"].tolist() == list(frame.method)


def test_no_columns_given_means_all_of_them_and_no_split_changes_nothing():
    frame = pd.DataFrame({"a": [1, 2], "b": ["x", "y"], "c": [3.0, 4.0]})
    split, columns = _split_columns(frame, None, {"c": "b"})
    assert columns == ["a", "c:x", "c:y"]
    assert split["c:x"].tolist()[0] == 3.0 and math.isnan(split["c:x"].tolist()[1])
    same, columns = _split_columns(frame, None, {})
    assert columns == ["a", "b", "c"] and same.equals(frame)
