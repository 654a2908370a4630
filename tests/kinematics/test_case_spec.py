"""The [kinematics] case section: defaults keep old cases valid, bad values are clear errors."""

from __future__ import annotations

import math

import pytest
from pydantic import ValidationError

from ballscrew.case import load_case
from ballscrew.case.kinematics_spec import KinematicsSpec


def test_defaults_leave_existing_cases_valid(gao_case_path, wear_case_path):
    for path in (gao_case_path, wear_case_path):
        spec = load_case(path).kinematics
        assert spec.level == 0 and spec.unsupported_length is None and spec.speed_warnings


def test_units_and_ranges():
    spec = KinematicsSpec(
        level=2,
        speed_range=["0 rpm", "3000 rpm"],
        unsupported_length="800 mm",
        micro_contact_size="8 um",
        lubricant="iso_vg_68",
    )
    assert spec.speed_range == pytest.approx((0.0, 100 * math.pi))
    assert spec.unsupported_length == pytest.approx(0.8)
    assert spec.micro_contact_size == pytest.approx(8e-6)


@pytest.mark.parametrize(
    ("fields", "message"),
    [
        ({"level": 3}, "level"),
        ({"lubricant": "castor oil"}, "not a lubricant of the library"),
        ({"speed_range": ["3000 rpm", "100 rpm"]}, "highest speed must exceed"),
        ({"speed_range": ["-1 rpm", "100 rpm"]}, "greater than or equal"),
        ({"mounting": "glued"}, "mounting"),
        ({"boundary_friction": -0.1}, "boundary_friction"),
        ({"speeed_range": [0, 1]}, "Extra inputs"),
    ],
)
def test_bad_values(fields, message):
    with pytest.raises(ValidationError, match=message):
        KinematicsSpec(**fields)


@pytest.mark.parametrize("name", ["ISO VG 68", "iso-vg-68", " Iso_VG_68 "])
def test_lubricant_names_ignore_case_spaces_and_hyphens(name):
    assert KinematicsSpec(lubricant=name).lubricant == "iso_vg_68"
