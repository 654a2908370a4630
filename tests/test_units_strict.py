"""Unit strings: one number and one unit, never arithmetic; dimensions checked strictly."""

from __future__ import annotations

import math
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballscrew.calibration import read_measured
from ballscrew.case import CaseError, load_case
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.surface.io._common import length_factor
from ballscrew.units import MAX_LENGTH, SI_UNITS, parse_quantity, registry, to_si

ADVERSARIAL = [
    "9**9**9 mm",
    "10**400 mm",
    "9^9^9 mm",
    "2**2**2**2**2**2 m",
    "(1+1) mm",
    "1+1 mm",
    "1e400 mm",
    "-1e400 mm",
    "nan mm",
    "inf mm",
    "-inf mm",
    "1 m^9^9^9",
    "1 m**99",
    "1 ((((((m))))))",
    "1 ((km^9)^9)^9/((m^9)^9)^9",
    "1 " + "m*" * 150 + "m",
    "1" * 150 + "e99999 mm",
    "1 mm 2 mm",
    "1 mm/2",
    "1 " + "(" * 100 + "m" + ")" * 100,
]


@pytest.fixture(autouse=True, scope="module")
def _warm_registry() -> None:
    to_si("1 m", "length")  # the registry's one-off start-up is not what the timing checks


@pytest.mark.parametrize("text", ADVERSARIAL)
def test_arithmetic_and_non_finite_strings_are_refused_at_once(text: str) -> None:
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r"cannot read|not a length|cannot be expressed"):
        to_si(text, "length")
    assert time.perf_counter() - start < 0.5


@pytest.mark.parametrize("text", ["9**9**9 N*m", "10**400 N*m", "1e400 N*m"])
def test_arithmetic_in_a_csv_header_unit_is_refused_at_once(tmp_path: Path, text: str) -> None:
    path = tmp_path / "bench.csv"
    path.write_text(f"revolutions, friction_torque [{text.split(' ', 1)[0]}]\n0, 1\n1, 2\n2, 3\n")
    start = time.perf_counter()
    with pytest.raises(InputError):
        read_measured(path)
    assert time.perf_counter() - start < 0.5


@pytest.mark.parametrize("unit", ["9**9**9 mm", "**9**9 mm", "%", "deg"])
def test_bad_profile_header_units_are_refused_at_once(unit: str) -> None:
    start = time.perf_counter()
    with pytest.raises(InputError):
        length_factor(unit, "profile.txt", "unit")
    assert time.perf_counter() - start < 0.5


@pytest.mark.parametrize("speed", ["9**9**9 rpm", "10**400 rpm", "nan", "1e400", "100 %"])
def test_kinematics_speed_option_refuses_bad_quantities(gao_case_path: Path, speed: str) -> None:
    start = time.perf_counter()
    result = CliRunner().invoke(app, ["kinematics", str(gao_case_path), "--speed", speed])
    assert result.exit_code == 2
    assert "--speed" in result.output
    assert time.perf_counter() - start < 5.0


def test_long_strings_are_refused_before_parsing() -> None:
    with pytest.raises(ValueError, match=f"longer than {MAX_LENGTH}"):
        to_si("1" + " " * MAX_LENGTH + "m", "length")


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, 10**400])
def test_non_finite_numbers_are_refused(value: float) -> None:
    with pytest.raises(ValueError, match="not a finite number"):
        to_si(value, "length")


DIMENSIONAL = [kind for kind in SI_UNITS if kind != "dimensionless"]


@pytest.mark.parametrize("kind", DIMENSIONAL)
@pytest.mark.parametrize("text", ["1 %", "5 ppm", "1 dimensionless", "45 deg deg", "1 kg*m^3/A"])
def test_every_dimensional_kind_refuses_a_unit_of_another_dimension(kind: str, text: str) -> None:
    with pytest.raises(ValueError, match=r"is not an? "):
        to_si(text, kind)


@pytest.mark.parametrize("text", ["1 rad", "1 deg", "1 m", "1 Hz", "1 K"])
def test_dimensionless_kind_refuses_angles_and_dimensions(text: str) -> None:
    with pytest.raises(ValueError, match="is not a dimensionless"):
        to_si(text, "dimensionless")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("1 rad", 1.0),
        ("180 deg", math.pi),
        ("60 arcmin", math.pi / 180),
        ("3600 arcsec", math.pi / 180),
        ("1 turn", 2 * math.pi),
        ("0.5 revolution", math.pi),
    ],
)
def test_angle_units(text: str, expected: float) -> None:
    assert to_si(text, "angle") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("text", ["45 deg deg", "1 rad/s", "1 Hz", "1 %", "1 sr"])
def test_non_angles_are_refused_for_an_angle(text: str) -> None:
    with pytest.raises(ValueError, match="is not an angle"):
        to_si(text, "angle")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("100 Hz", 200 * math.pi),
        ("100 /s", 200 * math.pi),
        ("100 1/s", 200 * math.pi),
        ("100 rps", 200 * math.pi),
        ("6000 rpm", 200 * math.pi),
        ("100 rad/s", 100.0),
        ("180 deg/s", math.pi),
        ("1 turn/min", 2 * math.pi / 60),
    ],
)
def test_a_frequency_given_for_a_speed_is_revolutions_per_second(text: str, expected: float):
    assert to_si(text, "angular_velocity") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("text", ["1 m/s", "1 rad", "1 rad^2/s", "1 %/s"])
def test_non_speeds_are_refused_for_a_speed(text: str) -> None:
    with pytest.raises(ValueError, match="is not an angular velocity"):
        to_si(text, "angular_velocity")


@pytest.mark.parametrize(
    ("text", "expected"),
    [("10 degC", 10.0), ("10 delta_degC", 10.0), ("10 K", 10.0), ("9 degF", 5.0), ("10 °C", 10.0)],
)
def test_a_celsius_difference_is_a_difference(text: str, expected: float) -> None:
    assert to_si(text, "temperature_difference") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "expected"), [("20 degC", 293.15), ("68 degF", 293.15), ("300 K", 300.0)]
)
def test_absolute_temperatures_are_points_on_the_scale(text: str, expected: float) -> None:
    assert to_si(text, "temperature") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        ("10 W/(m^2*K)", "heat_transfer_coefficient", 10.0),
        ("1 m²", "area", 1.0),
        ("1 m**2", "area", 1.0),
        ("5 N·m", "torque", 5.0),
        ("5 N m", "torque", 5.0),
        ("12e-6 1/degC", "expansion", 12e-6),
        ("50 W/(m*degC)", "thermal_conductivity", 50.0),
        ("10mm", "length", 0.01),
        ("50 %", "dimensionless", 0.5),
        ("+.5 um", "length", 0.5e-6),
    ],
)
def test_unit_expressions_with_small_integer_exponents(text: str, kind: str, expected: float):
    assert to_si(text, kind) == pytest.approx(expected, rel=1e-12)


def test_parse_quantity_splits_number_and_unit() -> None:
    magnitude, unit = parse_quantity("2.5e3 W/(m^2*K)")
    assert magnitude == 2500.0
    assert unit == registry().parse_units("W/(m^2*K)")
    assert parse_quantity("3") == (3.0, None)


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ('lead = "10 mm"', 'lead = "1 %"', "screw.lead"),
        ('youngs_modulus = "206 GPa"', 'youngs_modulus = "5 ppm"', "youngs_modulus"),
        ('contact_angle = "45 deg"', 'contact_angle = "45 deg deg"', "screw.contact_angle"),
    ],
)
def test_case_values_with_wrong_dimensions_are_case_errors(
    tmp_path: Path, gao_case_path: Path, old: str, new: str, field: str
) -> None:
    text = gao_case_path.read_text()
    assert old in text
    path = tmp_path / "case.toml"
    path.write_text(text.replace(old, new, 1))
    with pytest.raises(CaseError, match=field) as info:
        load_case(path)
    assert "\n" not in str(info.value)


def test_case_speed_in_hz_and_convection_difference_in_celsius(gao_case_path: Path) -> None:
    case = load_case(
        gao_case_path,
        {"operating.speed": "10 Hz", "thermal.convection.temperature_difference": "10 degC"},
    )
    assert case.operating.speed == pytest.approx(20 * math.pi)
    assert case.thermal.convection.temperature_difference == pytest.approx(10.0)
