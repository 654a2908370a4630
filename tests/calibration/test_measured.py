"""Reading measured histories: format, units and every error a user can make."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ballscrew.calibration import measured_history, read_measured
from ballscrew.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "measured" / "step_stress_torque.csv"


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "bench.csv"
    path.write_text(text)
    return path


def test_example_file_has_the_paper_sampling() -> None:
    data = read_measured(EXAMPLE)
    assert data.quantity == "friction_torque"
    assert data.unit == "N*m"
    assert len(data) == 31
    np.testing.assert_allclose(np.diff(data.revolutions), 4.8e4)
    assert data.revolutions[-1] == 1.44e6
    assert 0.0 < data.values.min() < data.values.max() < 1.0  # N·m, drag torque of a 40x10 nut


def test_units_in_brackets_are_converted(tmp_path: Path) -> None:
    path = write(
        tmp_path, "# bench 1\nrevolutions [rev], wear_depth [um] ,time\n0,0,a\n1e5,1.5,b\n"
    )
    data = read_measured(path)
    assert data.quantity == "wear_depth"
    np.testing.assert_array_equal(data.revolutions, [0.0, 1e5])
    np.testing.assert_allclose(data.values, [0.0, 1.5e-6], rtol=1e-12)


def test_kilonewton_preload_and_no_unit(tmp_path: Path) -> None:
    assert read_measured(write(tmp_path, "revolutions,preload [kN]\n0,1.5\n10,1.4\n")).values[
        0
    ] == pytest.approx(1500.0)
    assert read_measured(write(tmp_path, "revolutions,preload\n0,1500\n10,1400\n")).values[
        1
    ] == pytest.approx(1400.0)


@pytest.mark.parametrize(
    ("text", "field", "fragment"),
    [
        ("turns,preload\n0,1\n1,2\n", "header", "revolutions"),
        ("revolutions,torque\n0,1\n1,2\n", "measured column", "exactly one of"),
        ("revolutions,preload,wear_depth\n0,1,0\n1,2,0\n", "measured column", "exactly one"),
        ("revolutions,preload\n0,1\n1,abc\n", "line 3, column 'preload'", "a number"),
        ("revolutions,preload\n0,1\n1\n", "line 3, column 'preload'", "a number"),
        ("revolutions,preload\n0,1\n5,2\n5,3\n", "revolutions (point 3)", "strictly increasing"),
        ("revolutions,preload\n0,1\n5,2\n4,3\n", "revolutions (point 3)", "strictly increasing"),
        ("revolutions,preload\n-1,1\n5,2\n", "revolutions (point 1)", "≥ 0"),
        ("revolutions,preload\n0,1\n", "number of points", "at least 2"),
        ("revolutions,preload [N*m]\n0,1\n1,2\n", "column 'preload'", "force"),
        ("revolutions,preload [furlong]\n0,1\n1,2\n", "column 'preload'", "furlong"),
        ("revolutions [s],preload\n0,1\n1,2\n", "column 'revolutions'", "rev"),
        ("revolutions,preload\n0,1\n1,nan\n", "preload (point 2)", "finite"),
        ("# only a comment\n", "--measured", "header row"),
    ],
)
def test_errors_name_the_file_and_column(
    tmp_path: Path, text: str, field: str, fragment: str
) -> None:
    with pytest.raises(InputError) as info:
        read_measured(write(tmp_path, text))
    assert field in info.value.field
    assert fragment in str(info.value)
    if field != "--measured":
        assert info.value.field.startswith("bench.csv")


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="readable CSV"):
        read_measured(tmp_path / "nope.csv")


def test_fewer_points_than_parameters(tmp_path: Path) -> None:
    path = write(tmp_path, "revolutions,friction_torque\n0,0.4\n1e5,0.3\n")
    with pytest.raises(InputError, match="at least 3"):
        read_measured(path, min_points=3)


def test_arrays_are_read_only() -> None:
    data = measured_history([0.0, 1.0], [2.0, 3.0], "preload")
    with pytest.raises(ValueError, match="read-only"):
        data.values[0] = 1.0
    with pytest.raises(InputError, match="one of"):
        measured_history([0.0, 1.0], [2.0, 3.0], "torque")


def test_the_comment_lines_before_the_header_are_the_notes(tmp_path: Path) -> None:
    """Leading ``#`` lines (blank ones and bare ``#`` skipped) are what the file says about its
    data; a comment after the header is not."""
    path = tmp_path / "bench.csv"
    path.write_text(
        "# bench A, grease\n\n#\n#   two screws  \n"
        "revolutions,preload [N]\n# mid\n0,1500\n1e6,1400\n"
    )
    assert read_measured(path).notes == ("bench A, grease", "two screws")
    plain = tmp_path / "plain.csv"
    plain.write_text("revolutions,preload [N]\n0,1500\n1e6,1400\n")
    assert read_measured(plain).notes == ()
