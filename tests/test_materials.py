"""The materials library and its use in a case: ``material = "100Cr6"`` with overrides."""

from __future__ import annotations

import copy
import math
import tomllib

import pytest

from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import CaseError, MaterialSpec, case_from_dict
from ballscrew.errors import InputError
from ballscrew.materials import MATERIALS, material, material_properties


@pytest.fixture
def gao_raw(gao_case_path):
    return tomllib.loads(gao_case_path.read_text())


@pytest.mark.parametrize("name", list(MATERIALS))
def test_every_entry_is_a_valid_case_material_with_a_source(name) -> None:
    spec = MaterialSpec(material=name)
    assert spec.properties == material_properties(name)
    assert all(math.isfinite(v) and v > 0 for v in spec.properties.values())
    assert MATERIALS[name].source


def test_ceramic_balls_are_stiffer_lighter_and_expand_less_than_bearing_steel() -> None:
    steel, si3n4 = material("100Cr6"), material("Si3N4")
    assert si3n4.youngs_modulus > 1.4 * steel.youngs_modulus
    assert si3n4.density < 0.45 * steel.density
    assert si3n4.thermal_expansion < 0.3 * steel.thermal_expansion
    assert material_properties("52100") == material_properties("100Cr6")
    assert material_properties("SCM440") == material_properties("42CrMo4")


def test_a_given_property_overrides_the_library(gao_raw) -> None:
    gao_raw["materials"]["ball"] = {"material": "Si3N4", "hardness": "15 GPa"}
    ball = case_from_dict(gao_raw).materials.ball
    assert ball.hardness == 15e9
    assert ball.youngs_modulus == MATERIALS["Si3N4"].youngs_modulus
    assert ball.density == MATERIALS["Si3N4"].density


def test_a_ceramic_ball_raises_the_contact_modulus(gao_raw) -> None:
    steel = ScrewParameters.from_case(case_from_dict(copy.deepcopy(gao_raw)))
    gao_raw["materials"]["ball"] = {"material": "Si3N4"}
    ceramic = ScrewParameters.from_case(case_from_dict(gao_raw))
    # 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂: 113 GPa steel on steel, 135 GPa Si3N4 on steel
    assert ceramic.contact_modulus("screw") / steel.contact_modulus("screw") == pytest.approx(
        1.19, abs=0.01
    )


def test_explicit_values_keep_their_numbers(gao_raw) -> None:
    """A case that writes every value (no name) is read exactly as before the library."""
    case = case_from_dict(gao_raw)
    assert case.materials.ball.material is None
    assert case.materials.screw.youngs_modulus == 206e9
    assert case.materials.nut.properties == {
        "youngs_modulus": 206e9,
        "poissons_ratio": 0.3,
        "hardness": 6.5e9,
        "yield_strength": 2.32e9,
        "thermal_conductivity": 40.0,
        "density": 7810.0,
        "specific_heat": 475.0,
        "thermal_expansion": 11.9e-6,
    }


def test_unknown_name_is_one_line_listing_the_names(gao_raw) -> None:
    gao_raw["materials"]["nut"] = {"material": "unobtainium"}
    with pytest.raises(CaseError) as info:
        case_from_dict(gao_raw)
    message = str(info.value)
    assert "\n" not in message
    assert "materials.nut.material = 'unobtainium' is not allowed" in message
    assert all(name in message for name in MATERIALS)
    with pytest.raises(InputError, match="one of 100Cr6"):
        material("unobtainium")
