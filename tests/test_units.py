import math

import pytest

from ballscrew.units import to_si


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        ("10 mm", "length", 0.01),
        ("6.35 mm", "length", 6.35e-3),
        ("0.9 nm", "length", 9e-10),
        ("1000 rpm", "angular_velocity", 1000 * 2 * math.pi / 60),
        ("45 deg", "angle", math.pi / 4),
        ("206 GPa", "pressure", 206e9),
        ("1.5 kN", "force", 1500.0),
        ("40 W/(m*K)", "thermal_conductivity", 40.0),
        ("0.06 Pa*s", "viscosity", 0.06),
        ("60 mPa*s", "viscosity", 0.06),
        ("2.1e-8 1/Pa", "inverse_pressure", 2.1e-8),
        ("3", "length", 3.0),
    ],
)
def test_strings_with_units_convert_to_si(text, kind, expected):
    assert to_si(text, kind) == pytest.approx(expected, rel=1e-12)


def test_numbers_are_taken_as_si():
    assert to_si(0.01, "length") == 0.01
    assert to_si(2, "force") == 2.0


@pytest.mark.parametrize(
    ("text", "kind", "message"),
    [
        ("10 kg", "length", "is not a length"),
        ("45 deg", "length", "is not a length"),
        ("5 mm", "angle", "is not an angle"),
        ("ten mm", "length", "cannot read"),
    ],
)
def test_wrong_dimension_or_garbage_is_rejected(text, kind, message):
    with pytest.raises(ValueError, match=message):
        to_si(text, kind)


def test_booleans_are_not_numbers():
    with pytest.raises(ValueError):
        to_si(True, "length")
