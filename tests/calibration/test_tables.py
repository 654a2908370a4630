"""Measured tables in memory (DataFrame, dict of columns) read with the CSV header rules, and
the messages of bad measured values (plain numbers, file, line, column)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ballscrew.calibration import as_measured, read_measured, read_table
from ballscrew.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "measured" / "step_stress_torque.csv"


def test_calibrate_reads_a_dataframe_of_the_example_csv() -> None:
    """``pandas.read_csv`` of the example gives the CSV reader's history, units included."""
    pd = pytest.importorskip("pandas")
    frame = pd.read_csv(EXAMPLE, comment="#")
    assert list(frame.columns)[1] == "friction_torque [N*m]"
    history = as_measured(frame)
    assert history.values[0] == pytest.approx(0.4814)
    expected = read_measured(EXAMPLE)
    np.testing.assert_array_equal(history.revolutions, expected.revolutions)
    np.testing.assert_array_equal(history.values, expected.values)


def test_a_dict_of_columns_follows_the_header_rules() -> None:
    history = as_measured({"revolutions [rev]": (0, 48000), "wear_depth [um]": [0.0, 1.5]})
    assert history.quantity == "wear_depth"
    np.testing.assert_allclose(history.values, [0.0, 1.5e-6], rtol=1e-12)
    scheduled = read_table(
        {
            "revolutions": [0, 10],
            "preload [kN]": [1.5, 1.4],
            "speed [rpm]": [600, 600],
            "axial_load [kN]": [1, 2],
        }
    )
    assert scheduled.values[0] == pytest.approx(1500.0)
    generated = read_table({"revolutions": (r for r in (0, 1)), "preload": (p for p in (9, 8))})
    np.testing.assert_allclose(generated.values, [9.0, 8.0])
    np.testing.assert_allclose(scheduled.schedule, [[20 * np.pi, 1e3], [20 * np.pi, 2e3]])


@pytest.mark.parametrize(
    ("table", "message"),
    [
        ({"revolutions": [0, 1], "torque": [1, 2]}, "dict: measured column .*exactly one of"),
        ({"revolutions": [0, 1], "preload [N*m]": [1, 2]}, "dict: column 'preload' .*force"),
        ({"revolutions": [0, 1], "preload": [1, "x"]}, r"dict: row 2, column 'preload' = 'x'"),
        ({"revolutions": [0, 1, 2], "preload": [1, 2]}, "dict: column lengths"),
        ({0: [0, 1], "preload": [1, 2]}, "dict: column name = 0"),
        ({"revolutions": [0, 1], "preload": [None, 2]}, "dict: row 1, column 'preload' = 'None'"),
        (object(), "measured = 'object' .*a pandas DataFrame or a dict of columns"),
        ({"revolutions": [0, 1], "preload": [True, 2]}, "dict: row 1, column 'preload' = True"),
    ],
)
def test_bad_tables_are_refused_in_one_line(table: object, message: str) -> None:
    with pytest.raises(InputError, match=message) as info:
        as_measured(table)
    assert "\n" not in str(info.value)


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "bench.csv"
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "# note\nrevolutions,friction_torque\n0,0.4\n1,nan\n",
            r"^bench.csv: friction_torque \(point 2\) = nan is not allowed: a finite .*\(line 4\)$",
        ),
        (
            "revolutions,friction_torque [N*m]\n0,0.4\n1,-0.01\n2,0.3\n",
            r"^bench.csv: friction_torque \(point 2\) = -0.01 is not allowed: ≥ 0 .*\(line 3\)$",
        ),
        (
            "revolutions,friction_torque\n0,0.4\n2,0.4\n2,0.3\n",
            r"^bench.csv: revolutions \(point 3\) = 2.0 .*strictly increasing.*\(line 4\)$",
        ),
    ],
)
def test_bad_values_name_file_line_column_and_plain_value(
    tmp_path: Path, text: str, message: str
) -> None:
    with pytest.raises(InputError, match=message) as info:
        read_measured(write(tmp_path, text))
    assert "np.float64" not in str(info.value)


def test_a_slightly_negative_value_near_zero_is_still_noise(tmp_path: Path) -> None:
    """A torque that has fallen to 0 (preload lost) scatters around 0: accepted there."""
    path = write(tmp_path, "revolutions,wear_depth [um]\n0,-0.01\n1,0.01\n2,0.5\n")
    assert read_measured(path).values[0] == pytest.approx(-1e-8)
    lost = write(tmp_path, "revolutions,friction_torque\n0,0.4\n1,0.01\n2,-0.005\n3,0.002\n")
    assert read_measured(lost).values[2] == -0.005


def test_numeric_array_columns_are_read_at_once_as_their_cells_would_be() -> None:
    """A NumPy column of ints or floats is converted as a whole (no cell-by-cell check): the
    same history as the same numbers given as a list; a boolean array is still refused."""
    revolutions = np.arange(0, 5000, 1000, dtype=np.int64)
    depth = np.array([0.0, 0.4, 0.7, 0.9, 1.0])
    fast = read_table({"revolutions": revolutions, "wear_depth [um]": depth})
    cells = read_table({"revolutions": revolutions.tolist(), "wear_depth [um]": depth.tolist()})
    np.testing.assert_array_equal(fast.revolutions, cells.revolutions)
    np.testing.assert_array_equal(fast.values, cells.values)
    assert fast.values[1] == pytest.approx(0.4e-6)
    flags = {"revolutions": revolutions[:2], "wear_depth": np.array([True, False])}
    with pytest.raises(InputError, match=r"dict: row 1, column 'wear_depth' = True"):
        read_table(flags)
