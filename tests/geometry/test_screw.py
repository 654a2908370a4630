"""ScrewGeometry: validation, derived helix quantities (G2), (G6), (G12), lead_angle contract.

Reference numbers: the TCR reference screw (examples/gao2019_tcr.toml, f = 0.52) and the wear
reference screw (examples/wear_step_stress.toml, f = 0.55).
"""

import math
from types import SimpleNamespace

import pytest

from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry, as_geometry, lead_angle

SPEC = {
    "pitch_diameter": 40.0e-3,
    "lead": 10.0e-3,
    "ball_diameter": 6.35e-3,
    "screw_conformity": 0.52,
    "nut_conformity": 0.52,
    "contact_angle": math.radians(45.0),
}
REFERENCE = ScrewGeometry(**SPEC)


def test_t_g1_lead_and_contact_helices() -> None:
    g = REFERENCE
    assert math.degrees(g.lead_angle) == pytest.approx(4.549865, rel=1e-6)
    assert g.screw_contact_radius == pytest.approx(17.75583e-3, rel=1e-6)
    assert g.nut_contact_radius == pytest.approx(22.24578e-3, rel=1e-6)
    assert math.degrees(g.screw_contact_lead_angle) == pytest.approx(5.12204, rel=1e-5)
    assert math.degrees(g.nut_contact_lead_angle) == pytest.approx(4.09219, rel=1e-5)
    assert g.curvature == pytest.approx(49.68536, rel=1e-6)
    assert g.torsion == pytest.approx(3.953836, rel=1e-6)


def test_g6_alternative_forms() -> None:
    g = REFERENCE
    cos_a, sin_a = math.cos(g.lead_angle), math.sin(g.lead_angle)
    assert g.curvature == pytest.approx(cos_a**2 / g.pitch_radius, rel=1e-13)
    assert g.torsion == pytest.approx(sin_a * cos_a / g.pitch_radius, rel=1e-13)
    assert math.tan(g.lead_angle) == pytest.approx(g.helix_parameter / g.pitch_radius, rel=1e-13)


def test_t1_1_lead_angle_kinematics_wear() -> None:
    g = ScrewGeometry(**{**SPEC, "screw_conformity": 0.55, "nut_conformity": 0.55})
    assert math.degrees(g.lead_angle) == pytest.approx(4.550, abs=5e-4)
    assert math.tan(g.lead_angle) == pytest.approx(0.07958, abs=5e-6)
    assert math.cos(g.lead_angle) == pytest.approx(0.99685, abs=5e-6)


def test_groove_radii() -> None:
    assert REFERENCE.screw_groove_radius == pytest.approx(3.302e-3, rel=1e-12)
    assert REFERENCE.groove_radius("nut") == pytest.approx(3.302e-3, rel=1e-12)


def test_lead_angle_accepts_geometry_spec_and_case() -> None:
    spec = SimpleNamespace(**SPEC)
    case = SimpleNamespace(screw=spec, name="reference")
    expected = math.atan(10.0 / (math.pi * 40.0))
    for obj in (REFERENCE, spec, case, SPEC, {"screw": SPEC}):
        assert lead_angle(obj) == pytest.approx(expected, rel=1e-14)
    assert as_geometry(case) == REFERENCE


def test_from_spec_missing_field_names_it() -> None:
    spec = SimpleNamespace(**{k: v for k, v in SPEC.items() if k != "lead"})
    with pytest.raises(InputError) as info:
        ScrewGeometry.from_spec(spec)
    assert info.value.field == "lead"


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("screw_conformity", 0.5),
        ("nut_conformity", 0.45),
        ("lead", -10.0e-3),
        ("pitch_diameter", 0.0),
        ("ball_diameter", -1.0e-3),
        ("contact_angle", 0.0),
        ("contact_angle", math.pi / 2),
        ("contact_angle", math.radians(90.0)),
        ("ball_diameter", 40.0e-3),
        ("ball_diameter", 50.0e-3),
        ("lead", math.nan),
        ("lead", "ten"),
    ],
)
def test_bad_input_names_the_field(field: str, value: object) -> None:
    with pytest.raises(InputError) as info:
        ScrewGeometry(**{**SPEC, field: value})
    assert info.value.field == field
    assert field in str(info.value)


def test_integers_are_coerced_to_float() -> None:
    g = ScrewGeometry(**{**SPEC, "pitch_diameter": 1, "lead": 1})
    assert isinstance(g.pitch_diameter, float)
