"""Named lubricants and how a case picks its lubricant."""

from __future__ import annotations

import pytest

from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import load_case
from ballscrew.errors import InputError
from ballscrew.lubrication import LUBRICANTS, lubricant


def case_lubricant(case):
    """(η₀, α_p) of a case, as every analysis sees them."""
    lubrication = ScrewParameters.from_case(case).lubrication
    return lubrication.viscosity, lubrication.pressure_viscosity


def test_iso_grades_follow_iso_3448_midpoints():
    # η₀ = ρ ν with ν = grade mm²/s at 40 °C and ρ = 870 kg/m³.
    assert lubricant("iso_vg_68").viscosity == pytest.approx(870 * 68e-6)
    assert lubricant("iso_vg_68").pressure_viscosity == 2.1e-8  # wear reference screw
    for entry in LUBRICANTS.values():
        assert 1e-3 < entry.viscosity < 1.0 and 1e-8 < entry.pressure_viscosity < 3e-8
        assert entry.source


def test_unknown_name():
    with pytest.raises(InputError, match="iso_vg_68"):
        lubricant("motor oil")


def edited(path, tmp_path, old, new):
    text = path.read_text()
    assert old in text
    out = tmp_path / "case.toml"
    out.write_text(text.replace(old, new, 1))
    return load_case(out)


def test_medium_values_take_precedence_over_a_named_lubricant(tmp_path, wear_case_path):
    case = edited(
        wear_case_path,
        tmp_path,
        "[numerics]",
        '[kinematics]\nlubricant = "iso_vg_32"\n\n[numerics]',
    )
    assert case_lubricant(case) == (0.06, 2.1e-8)
    text = wear_case_path.read_text().replace('viscosity = "0.06 Pa*s"\n', "")
    text = text.replace("[numerics]", '[kinematics]\nlubricant = "iso_vg_32"\n\n[numerics]', 1)
    (tmp_path / "b.toml").write_text(text)
    eta, alpha = case_lubricant(load_case(tmp_path / "b.toml"))
    assert eta == pytest.approx(870 * 32e-6) and alpha == 2.1e-8
