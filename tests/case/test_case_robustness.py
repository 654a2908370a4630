"""Case files and overrides that are malformed, huge or out of range: one-line CaseErrors."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, get_origin

import pytest

from ballscrew.case import Case, CaseError, case_from_dict, load_case
from ballscrew.case.loader import (
    MAX_FILE_BYTES,
    MAX_NESTING,
    MAX_PROBLEMS,
    _allowed_range,
    _members,
    _submodel,
    field_spec,
)


def one_line_error(path: Path, overrides: Any = None) -> str:
    with pytest.raises(CaseError) as info:
        load_case(path, overrides)
    message = str(info.value)
    assert "\n" not in message
    return message


def test_a_utf8_byte_order_mark_is_skipped(tmp_path: Path, gao_case_path: Path) -> None:
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + gao_case_path.read_bytes())
    assert load_case(path).screw == load_case(gao_case_path).screw


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("utf-16", "UTF-16 text"),
        ("latin-1", "not UTF-8 text"),
        ("binary", "not UTF-8 text"),
        ("arrays", f"nested deeper than {MAX_NESTING} levels"),
        ("tables", f"nested deeper than {MAX_NESTING} levels"),
        ("huge", f"larger than {MAX_FILE_BYTES} bytes"),
    ],
)
def test_unreadable_case_files_are_one_line_errors_naming_the_file(
    tmp_path: Path, gao_case_path: Path, content: str, message: str
) -> None:
    text = gao_case_path.read_text(encoding="utf-8")
    data = {
        "utf-16": lambda: text.encode("utf-16"),
        "latin-1": lambda: 'name = "café"\n'.encode("latin-1"),
        "binary": lambda: bytes(range(256)) * 4,
        "arrays": lambda: ("a = " + "[" * 5000 + "]" * 5000 + "\n").encode(),
        "tables": lambda: ("[" + ".".join(["t"] * 100) + "]\n").encode(),
        "huge": lambda: b"# padding\n" * (MAX_FILE_BYTES // 10 + 1),
    }[content]()
    path = tmp_path / f"{content}.toml"
    path.write_bytes(data)
    error = one_line_error(path)
    assert error.startswith(str(path)) and message in error


@pytest.mark.parametrize("special", ["/dev/zero", "directory"])
def test_non_regular_case_files_are_refused(tmp_path: Path, special: str) -> None:
    path = Path(special) if special.startswith("/") else tmp_path
    if not path.exists():
        pytest.skip(f"{path} does not exist here")
    assert "not a regular file" in one_line_error(path)


@pytest.mark.parametrize(
    ("overrides", "message"),
    [
        ({1: 2}, "override key 1 is not a dotted key string"),
        ({("screw", "lead"): 0.01}, "is not a dotted key string"),
        ([("screw.lead", 0.01)], "overrides must map dotted keys to values, not list"),
        ({"": 1}, "unknown key"),
        ({"screw..lead": 1}, "unknown key"),
    ],
)
def test_bad_override_shapes_are_case_errors(
    gao_case_path: Path, overrides: Any, message: str
) -> None:
    assert message in one_line_error(gao_case_path, overrides)


def test_a_case_that_is_no_table_is_a_case_error() -> None:
    with pytest.raises(CaseError, match="expected tables of keys, not list"):
        case_from_dict([1, 2])  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("overrides", "field", "allowed"),
    [
        ({"medium.viscosity": -1.0}, "medium.viscosity = -1.0", "(0, 1e+09] Pa*s"),
        ({"numerics.box_factor": 0.5}, "numerics.box_factor = 0.5", "[1.05, 5] ("),
        ({"numerics.box_factor": [1.2, 9.0]}, "numerics.box_factor.1 = 9.0", "[1.05, 5] ("),
        ({"numerics.cells": [2, 8]}, "numerics.cells.0 = 2", "[4, 8192] ("),
        ({"wear": {"grid": [4, 5000]}}, "wear.grid.1 = 5000", "[4, 4096] ("),
        (
            {"kinematics.speed_range": ["-1 rpm", "2 rpm"]},
            "speed_range.0 = '-1 rpm'",
            "[0, 100000]",
        ),
        (
            {"thermal.bearings": [{"position": 0.1, "torque": -1.0}]},
            "0.torque = -1.0",
            "[0, 100000]",
        ),
    ],
)
def test_allowed_range_of_optional_union_and_tuple_fields(
    gao_case_path: Path, overrides: dict[str, Any], field: str, allowed: str
) -> None:
    error = one_line_error(gao_case_path, overrides)
    assert f"{field} is not allowed: allowed range is {allowed}" in error
    assert "inf" not in error and "valid tuple" not in error and "valid number" not in error


def _numeric_locations(model: type = Case, prefix: tuple = ()) -> list[tuple]:
    """Error-like locations of every numeric field, tuple items and union members included."""
    found = []
    for name, info in model.model_fields.items():
        loc = (*prefix, name)
        members = _members(info.annotation)
        sub = _submodel(info.annotation)
        if sub is not None:
            listed = any(get_origin(m) is list for m in members)
            found += _numeric_locations(sub, loc + ((0,) if listed else ()))
            continue
        text = str(info.annotation)
        if not any(word in text for word in ("float", "int")) or "Literal" in text:
            continue
        if len(members) > 1:  # a number or a tuple of numbers
            found += [(*loc, "constrained-float"), (*loc, "tuple[...]", 1)]
        elif get_origin(members[0]) is tuple:
            found += [(*loc, 0), (*loc, 1)]
        elif get_origin(members[0]) is list:  # a list of numbers: its items
            found.append((*loc, 0))
        else:
            found.append(loc)
    return found


@pytest.mark.parametrize("loc", _numeric_locations(), ids=lambda loc: ".".join(map(str, loc)))
def test_every_numeric_field_has_a_finite_range(loc: tuple) -> None:
    text = _allowed_range(loc)
    assert "inf" not in text, f"{field_spec(loc).dotted}: {text}"


def _level(revolutions: float) -> dict[str, Any]:
    return {"wear": {"programme": [{"axial_load": 1, "speed": 1, "revolutions": revolutions}]}}


def _sensor(theta: object, model: str = "3d") -> dict[str, Any]:
    sensor = {"name": "s", "body": "nut", "r": 0.01, "z": 0.1, "theta": theta}
    return {"thermal": {"model": model, "sensors": [sensor]}}


@pytest.mark.parametrize(
    ("overrides", "field"),
    [
        (_level(math.inf), "wear.programme.0.revolutions"),
        (_level(1e13), "wear.programme.0.revolutions"),
        ({"wear": {"coefficient": 10.0}}, "wear.coefficient"),
        ({"wear": {"coefficient": 1e300}}, "wear.coefficient"),
        ({"wear": {"coefficient": 1.0}}, "wear.coefficient"),
        ({"wear": {"max_depth_step": 1e-15}}, "wear.max_depth_step"),
        ({"wear": {"torque_sampling": 1e-3}}, "wear.torque_sampling"),
        ({"wear": {"torque_sampling": 1.0}}, "wear.torque_sampling"),
        ({"wear": {"stroke": "1 nm"}}, "wear.stroke"),
        ({"surface.D": math.nan}, "surface.D"),
        ({"operating.speed": math.inf}, "operating.speed"),
        (_sensor(math.nan), "thermal.sensors.0.theta"),
        (_sensor("nan deg"), "thermal.sensors.0.theta"),
        (_sensor(math.inf, "axisymmetric"), "thermal.sensors.0.theta"),
        ({"thermal": {"bearings": [{"position": 0.1, "f1": math.nan}]}}, "thermal.bearings.0.f1"),
        ({"thermal": {"convection": {"air_prandtl": math.inf}}}, "convection.air_prandtl"),
    ],
)
def test_unbounded_or_non_finite_values_are_one_line_errors(
    gao_case_path: Path, overrides: dict[str, Any], field: str
) -> None:
    assert field in one_line_error(gao_case_path, overrides)


def test_quantity_fields_have_the_right_kind() -> None:
    kinds = {
        ("thermal", "convection", "temperature_difference"): "temperature_difference",
        ("thermal", "ambient_temperature"): "temperature",
        ("operating", "speed"): "angular_velocity",
        ("wear", "programme", 0, "speed"): "angular_velocity",
        ("kinematics", "speed_range", 0): "angular_velocity",
        ("screw", "contact_angle"): "angle",
        ("thermal", "sensors", 0, "theta"): "angle",
    }
    for loc, kind in kinds.items():
        assert field_spec(loc).kind == kind, loc


def test_thousands_of_problems_are_summarised(gao_case_path: Path) -> None:
    sensors = [_sensor(math.nan)["thermal"]["sensors"][0] | {"name": str(i)} for i in range(100)]
    with pytest.raises(CaseError) as info:
        load_case(gao_case_path, {"thermal": {"sensors": sensors}})
    lines = str(info.value).splitlines()
    assert len(lines) == MAX_PROBLEMS + 1 and lines[-1].endswith("and 80 more problems")
