"""Named lubricants and how a case picks its lubricant: one library for every key."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.parameters import ScrewParameters, library_entry
from ballscrew.case import CaseError, load_case
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.lubrication import LUBRICANTS, lubricant
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY, library_lubricant


def case_lubricant(case):
    """(η₀, α_p) of a case, as every analysis sees them."""
    lubrication = ScrewParameters.from_case(case).lubrication
    return lubrication.viscosity, lubrication.pressure_viscosity


def test_the_40c_table_is_a_view_of_the_library():
    # The old table had η₀ = 870 kg/m³ × ν40 and a guessed α_p = 2.1e-8 1/Pa for VG 68; the view
    # takes both from the library's laws at 40 °C: ρ(40 °C) = 880 (1 − 6.4e-4 × 25) kg/m³ and
    # Gold et al. (2001) α_p = 9.904 ν^0.139 1/GPa.
    assert set(LUBRICANTS) == set(LUBRICANT_LIBRARY)
    vg68 = lubricant("iso_vg_68")
    assert vg68.viscosity == pytest.approx(880.0 * (1 - 6.4e-4 * 25.0) * 68e-6, rel=1e-9)
    assert vg68.pressure_viscosity == pytest.approx(9.904e-9 * 68**0.139, rel=1e-12)
    for key, entry in LUBRICANTS.items():
        state = library_lubricant(key).at(313.15)
        assert (entry.viscosity, entry.pressure_viscosity) == (
            state.viscosity,
            state.pressure_viscosity,
        )
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
    assert eta == pytest.approx(lubricant("iso_vg_32").viscosity) and alpha == 2.1e-8


def test_medium_lubricant_is_the_same_key_and_follows_the_inlet_temperature(
    tmp_path, wear_case_path
):
    text = wear_case_path.read_text().replace('viscosity = "0.06 Pa*s"\n', "")
    text = text.replace('pressure_viscosity = "2.1e-8 1/Pa"\n', 'lubricant = "iso_vg_68"\n')
    (tmp_path / "a.toml").write_text(text)
    eta40, alpha40 = case_lubricant(load_case(tmp_path / "a.toml"))
    assert eta40 == pytest.approx(865.92 * 68e-6, rel=1e-9)  # ρ(40 °C) ν40
    assert alpha40 == pytest.approx(9.904e-9 * 68**0.139, rel=1e-12)
    hot = text + '\n[lubrication]\ntemperature = "80 degC"\n'
    (tmp_path / "b.toml").write_text(hot)
    eta80, alpha80 = case_lubricant(load_case(tmp_path / "b.toml"))
    state = library_lubricant("iso_vg_68").at(353.15)
    assert (eta80, alpha80) == (state.viscosity, state.pressure_viscosity)
    assert eta80 < 0.3 * eta40


@pytest.mark.parametrize("section", ["medium", "kinematics"])
def test_unknown_lubricant_in_either_section_is_one_line_listing_the_library(
    tmp_path, wear_case_path, section
):
    text = wear_case_path.read_text()
    if section == "medium":
        text = text.replace("[medium]\n", '[medium]\nlubricant = "motor oil"\n', 1)
    else:
        text = text.replace("[numerics]", '[kinematics]\nlubricant = "motor oil"\n\n[numerics]')
    (tmp_path / "c.toml").write_text(text)
    with pytest.raises(CaseError) as err:
        load_case(tmp_path / "c.toml")
    message = str(err.value)
    assert "\n" not in message.strip()
    assert f"{section}.lubricant" in message and "iso_vg_460" in message
    assert "lithium_nlgi2_vg100" in message


def test_two_different_lubricants_are_refused(tmp_path, wear_case_path):
    text = wear_case_path.read_text().replace("[medium]\n", '[medium]\nlubricant = "iso_vg_46"\n')
    text = text.replace("[numerics]", '[kinematics]\nlubricant = "iso_vg_68"\n\n[numerics]')
    (tmp_path / "d.toml").write_text(text)
    with pytest.raises(CaseError, match="name one lubricant"):
        load_case(tmp_path / "d.toml")


def test_a_given_viscosity_sets_the_named_lubricant_at_its_temperature(tmp_path, wear_case_path):
    # Two routes to the same state: the inlet temperature of the case, or the viscosity the
    # operating point passes at its contact temperature.
    text = wear_case_path.read_text().replace('viscosity = "0.06 Pa*s"\n', "")
    text = text.replace('pressure_viscosity = "2.1e-8 1/Pa"\n', 'lubricant = "iso_vg_68"\n')
    text += '\n[friction]\nmodel = "ball_model"\n\n[lubrication]\nthermal = true\n'
    (tmp_path / "a.toml").write_text(text)
    (tmp_path / "b.toml").write_text(text + 'temperature = "70 degC"\n')
    cold, hot = load_case(tmp_path / "a.toml"), load_case(tmp_path / "b.toml")
    eta70 = library_lubricant("iso_vg_68").at(343.15).viscosity
    passed = friction_torque(cold, speed=100.0, viscosity=eta70)
    inlet = friction_torque(hot, speed=100.0)
    assert passed.film_parameter == pytest.approx(inlet.film_parameter, rel=1e-9)
    assert passed.total == pytest.approx(inlet.total, rel=1e-9)
    assert friction_torque(cold, speed=100.0).film_parameter > passed.film_parameter


def _unnamed_oil(tmp_path, wear_case_path, lines):
    text = wear_case_path.read_text().replace('viscosity = "0.06 Pa*s"\n', lines)
    text = text.replace('pressure_viscosity = "2.1e-8 1/Pa"\n', "")
    (tmp_path / "oil.toml").write_text(text)
    return load_case(tmp_path / "oil.toml")


def test_an_unnamed_oil_by_two_viscosities_follows_astm_d341(tmp_path, wear_case_path):
    # the same anchors as the library's VG 68 give the library's state, at 40 °C and at 70 °C
    lines = 'viscosity_40 = "68 mm^2/s"\nviscosity_100 = "8.6 mm^2/s"\ndensity_15 = "880 kg/m^3"\n'
    case = _unnamed_oil(tmp_path, wear_case_path, lines)
    vg68 = library_lubricant("iso_vg_68")
    state = vg68.at(313.15)
    assert case_lubricant(case) == (
        pytest.approx(state.viscosity, rel=1e-12),
        pytest.approx(state.pressure_viscosity, rel=1e-12),
    )
    entry = library_entry(case)
    assert entry.at(343.15).viscosity == pytest.approx(vg68.at(343.15).viscosity, rel=1e-12)


def test_an_oil_by_iso_grade_and_viscosity_index_finds_nu100_by_astm_d2270(
    tmp_path, wear_case_path
):
    # VG 68 with the VI of the library's VG 68 is that oil: the same ν100, the same state at 70 °C
    vg68 = library_lubricant("iso_vg_68")
    lines = f"viscosity_grade = 68\nviscosity_index = {vg68.viscosity_index!r}\n"
    case = _unnamed_oil(tmp_path, wear_case_path, lines + 'density_15 = "880 kg/m^3"\n')
    entry = library_entry(case)
    assert (entry.nu40, entry.nu100) == (
        pytest.approx(vg68.nu40, rel=1e-12),
        pytest.approx(vg68.nu100, rel=1e-9),
    )
    assert entry.at(343.15).viscosity == pytest.approx(vg68.at(343.15).viscosity, rel=1e-9)
    # ν40 given directly: the ASTM D2270 §6.1.4 example oil, VI 156.37 → ν100 = 5.05 mm²/s
    case = _unnamed_oil(
        tmp_path, wear_case_path, 'viscosity_40 = "22.83 mm^2/s"\nviscosity_index = 156.37\n'
    )
    assert case.medium.oil_viscosities()[1] == pytest.approx(5.05e-6, abs=5e-9)


@pytest.mark.parametrize(
    ("lines", "text"),
    [
        (
            "viscosity_grade = 65\nviscosity_index = 95\n",
            "viscosity_grade = 65 is not allowed: one of the ISO 3448 grades 2, 3, 5",
        ),
        ("viscosity_grade = 68\nviscosity_index = 500\n", "viscosity_index = 500"),
        (
            'viscosity_grade = 68\nviscosity_40 = "68 mm^2/s"\nviscosity_index = 95\n',
            "viscosity_grade = 68 is not allowed with viscosity_40: give nu40 one way",
        ),
        (
            'viscosity_grade = 68\nviscosity_100 = "8 mm^2/s"\nviscosity_index = 95\n',
            "viscosity_index = 95 is not allowed with viscosity_100: give nu100 one way",
        ),
        ("viscosity_grade = 68\n", "viscosity_100 or viscosity_index is missing"),
        ("viscosity_index = 95\n", "viscosity_40 or viscosity_grade is missing"),
        (
            'viscosity_grade = 68\nviscosity_index = 95\nlubricant = "iso_vg_68"\n',
            "give the oil one way",
        ),
        # VG 5 of VI 95 would have ν100 below 2 mm²/s, where VI is undefined
        ("viscosity_grade = 5\nviscosity_index = 95\n", "viscosity_index = 95.0 is not allowed"),
    ],
)
def test_bad_grade_or_viscosity_index_is_a_one_line_error(tmp_path, wear_case_path, lines, text):
    with pytest.raises(CaseError) as err:
        _unnamed_oil(tmp_path, wear_case_path, lines)
    assert text in str(err.value) and "\n" not in str(err.value).strip()


@pytest.mark.parametrize(
    ("lines", "text"),
    [
        ('viscosity_40 = "68 mm^2/s"\nviscosity_100 = "80 mm^2/s"\n', "falls with temperature"),
        ('viscosity_40 = "68 mm^2/s"\n', "viscosity_100 or viscosity_index is missing"),
        (
            'viscosity_40 = "68 mm^2/s"\nviscosity_100 = "8 mm^2/s"\nlubricant = "iso_vg_68"\n',
            "give the oil one way",
        ),
    ],
)
def test_bad_oil_viscosities_are_one_line_errors(tmp_path, wear_case_path, lines, text):
    with pytest.raises(CaseError) as err:
        _unnamed_oil(tmp_path, wear_case_path, lines)
    assert text in str(err.value) and "\n" not in str(err.value).strip()


@pytest.mark.parametrize(
    ("insert", "message"),
    [
        (
            'lubricant = "motor oil"\n',
            "medium.lubricant = 'motor oil' is not allowed: not a lubricant of the library; "
            "known: ",
        ),
        ('lubricant = "iso_vg_86"\n', "(did you mean 'iso_vg_68'?)"),
        (
            'viscosity_40 = "68 mm^2/s"\nviscosity_100 = "90 mm^2/s"\n',
            "(the viscosity falls with temperature)",
        ),
        (
            "viscosity_grade = 68\nviscosity_index = 600\n",
            "medium.viscosity_index = 600 is not allowed: allowed range is [-100, 400]",
        ),
    ],
)
def test_cli_refuses_a_bad_lubricant_in_one_line_with_exit_2(
    tmp_path, wear_case_path, insert, message
):
    text = wear_case_path.read_text().replace('viscosity = "0.06 Pa*s"\n', insert)
    (tmp_path / "case.toml").write_text(text)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["kinematics", str(tmp_path / "case.toml"), "--out", str(out)])
    assert result.exit_code == 2 and message in result.output
    assert len(result.output.strip().splitlines()) == 1 and not out.exists()
