"""One reading of comma lists (``--fit``, ``--separate``, ``--export``, ``--vary`` values and
the Python ``fit=``/``shared=`` strings): items stripped, empty items dropped."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.units import split_list


@pytest.mark.parametrize(
    ("given", "items"),
    [
        ("a,b", ["a", "b"]),
        (" a , b ", ["a", "b"]),
        ("a,,b", ["a", "b"]),
        ("a,b,", ["a", "b"]),
        (",a", ["a"]),
        ("", []),
        (" , ,", []),
        ("single", ["single"]),
        (["a", " b ", ""], ["a", "b"]),
        (("a",), ["a"]),
    ],
)
def test_items_are_stripped_and_empty_items_dropped(given, items) -> None:
    assert split_list(given) == items


def test_order_and_repeats_are_kept_for_the_caller() -> None:
    """Repeats are the caller's to refuse or merge (a sweep refuses a value given twice)."""
    assert split_list("b,a,b") == ["b", "a", "b"]


def _error(*args: object) -> str:
    result = CliRunner().invoke(app, [str(a) for a in args])
    assert result.exit_code == 2, result.output
    return result.output.strip()


EXPORT_ALLOWED = "is not allowed: one of csv, xlsx, mat"


@pytest.mark.parametrize(
    ("formats", "message"),
    [
        ("csv,,pdf", f"error: --export = 'pdf' {EXPORT_ALLOWED}"),
        (" CSV , nc,", f"error: --export = 'nc' {EXPORT_ALLOWED}"),
        (",", "error: --export = ',' is not allowed: a comma-separated list of csv, xlsx, mat"),
    ],
)
def test_export_lists_keep_their_messages(gao_case_path, tmp_path, formats, message) -> None:
    out = tmp_path / "o"
    assert _error("operating-point", gao_case_path, "--export", formats, "--out", out) == message
    assert not out.exists()


@pytest.mark.parametrize(
    ("values", "message"),
    [
        ("surface.D=,", "error: sweep: --vary 'surface.D=,': the range is empty"),
        (
            "surface.D=1.4,,1.4,",
            "error: sweep: --vary 'surface.D=1.4,,1.4,': the value 1.4 (SI) is given twice; "
            "give each value once",
        ),
    ],
)
def test_vary_lists_keep_their_messages(gao_case_path, tmp_path, values, message) -> None:
    out = tmp_path / "o"
    assert _error("sweep", gao_case_path, "--vary", values, "--out", out) == message


FIT_ALLOWED = (
    "is not allowed: one or more of wear_coefficient, torque_scale, torque_offset, "
    "film_factor, running_in_depth, preload"
)


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (("--fit", "wear_coefficient,,torque_offsett"), f"--fit = 'torque_offsett' {FIT_ALLOWED}"),
        (("--fit", ","), f"--fit = '' {FIT_ALLOWED}"),
        (
            ("--separate", "torque_offset,"),
            "--separate = 'torque_offset,' is not allowed: only with two or more --measured "
            "files",  # the option as written
        ),
    ],
)
def test_calibrate_lists_keep_their_messages(
    wear_case_path, tmp_path: Path, options, message
) -> None:
    measured = tmp_path / "torque.csv"
    measured.write_text("revolutions,friction_torque [N*m]\n0,1.0\n1e6,1.1\n2e6,1.2\n")
    out = tmp_path / "o"
    args = ("calibrate", wear_case_path, "-m", measured, *options, "--out", out)
    assert _error(*args) == f"error: {message}"
    assert not out.exists()
