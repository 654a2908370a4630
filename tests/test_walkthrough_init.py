"""Findings of a first-time user's walk through ``ballscrew init`` with a THK BNFN4010-5 double
nut (d0 = 40 mm, lead 10 mm, 6.35 mm balls, 2.5 turns x 2 circuits, preload 3000 N, 1500 mm
shaft; the sheet prints a ball-centre diameter of 41.75 mm and a root of 34.4 mm)."""

from __future__ import annotations

import tomllib

import pytest
from typer.testing import CliRunner

from ballscrew.case import case_from_dict
from ballscrew.case.inputs import guessed_defaults
from ballscrew.cli import app

runner = CliRunner()
SHEET = ["--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2", "--nuts", "2"]
THK = [*SHEET, "--preload", "3000", "--length", "1500", "--name", "BNFN4010-5"]


def run(*args: str):
    return runner.invoke(app, ["init", *(str(a) for a in args)])


def starter(*args: str) -> str:
    result = run(*args)
    assert result.exit_code == 0, result.output
    return result.stdout


@pytest.fixture(scope="module")
def thk() -> str:
    return starter(*THK)


def test_the_commented_load_ratings_land_in_design_when_uncommented(thk) -> None:
    """Uncommenting the ratings (as the comment invites) put them into [thermal.transient]:
    'thermal.transient.dynamic_load_rating: unknown key'."""
    text = thk.replace('#   dynamic_load_rating = "... kN"', 'dynamic_load_rating = "52.7 kN"')
    text = text.replace('#   static_load_rating = "... kN"', 'static_load_rating = "141.1 kN"')
    case = case_from_dict(tomllib.loads(text))
    assert case.design is not None
    assert case.design.dynamic_load_rating == pytest.approx(52.7e3)
    assert case.design.static_load_rating == pytest.approx(141.1e3)


@pytest.mark.parametrize(("lead", "meant"), [("0.01", "10 mm"), ("10 m", "10 mm"), ("1", None)])
def test_a_lead_in_the_wrong_unit_is_blamed_on_the_lead(lead, meant) -> None:
    """--lead 0.01 (metres meant) was blamed on --ball, --lead '10 m' on --length. A lead of
    1 mm under a 6.35 mm ball is below D_w/2 and no unit slip: no hint."""
    result = run(*SHEET[:2], "--lead", lead, *SHEET[4:])
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --lead = "), result.output
    assert ("did you mean" in lines[0]) is (meant is not None)
    if meant is not None:
        assert f"did you mean {meant}?" in lines[0]


def test_a_lead_steeper_than_45_degrees_is_blamed_on_the_lead() -> None:
    result = run("--d0", "10", "--lead", "40", "--ball", "3", "--turns", "1x1")
    assert result.exit_code == 2 and result.output.startswith("error: --lead = '40 mm'")
    assert "pi d_m = 31.4159 mm" in result.output


def test_the_circuits_on_the_sheet_are_not_a_guess(thk) -> None:
    case = case_from_dict(tomllib.loads(thk))
    assert "friction.circuits" not in guessed_defaults(case)
    one = case_from_dict(tomllib.loads(starter(*SHEET[:7], "1x4", "--nuts", "1")))
    assert one.friction.circuits == 4


def test_the_thermal_stroke_is_the_duty_stroke(thk) -> None:
    """The duty's 680 mm stroke (half the shaft left free by the two 70 mm nuts) was not
    written to [thermal.stroke]: the thermal model kept the nut standing still."""
    case = case_from_dict(tomllib.loads(thk))
    assert case.thermal is not None
    assert case.thermal.stroke.length == pytest.approx(0.68)
    assert case.thermal.stroke.length == case.duty[0].stroke
    assert "thermal.stroke.length" in guessed_defaults(case)


def test_the_ball_centre_and_root_diameters_of_the_sheet() -> None:
    """THK prints d_m = 41.75 mm and d_r = 34.4 mm for its 40 mm screw: --dp is the case's
    pitch diameter (then not assumed), --root the root diameter of [design] and [kinematics]."""
    text = starter(*THK, "--dp", "41.75", "--root", "34.4")
    case = case_from_dict(tomllib.loads(text))
    assert case.screw.pitch_diameter == pytest.approx(41.75e-3)
    assert case.design is not None and case.design.root_diameter == pytest.approx(34.4e-3)
    assert case.kinematics.root_diameter == pytest.approx(34.4e-3)
    assert "screw.pitch_diameter" not in guessed_defaults(case)
    assert case.screw.balls_per_nut == 2 * 50  # floor(2.5 π 41.75/(6.35 cos λ)) − 1 = 50
    default = case_from_dict(tomllib.loads(starter(*THK)))
    assert default.screw.pitch_diameter == pytest.approx(0.040)
    assert default.design is not None and default.design.root_diameter is None
    assert "screw.pitch_diameter" in guessed_defaults(default)


@pytest.mark.parametrize(
    ("args", "field", "shown"),
    [
        (["--dp", "0.04175"], "--dp", "did you mean 41.75 mm?"),
        (["--dp", "50"], "--dp", "33.65 mm to 46.35 mm"),
        (["--root", "41"], "--root", "d_m - 2 D_w = 27.3 mm"),
        (["--root", "0.0344"], "--root", "did you mean 34.4 mm?"),
        (["--root", "-3"], "--root", "> 0"),
    ],
)
def test_a_diameter_off_the_thread_is_one_line_exit_2(args, field, shown) -> None:
    result = run(*THK, *args)
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field} = "), result.output
    assert shown in lines[0]


def test_the_assumed_table_lists_what_is_not_on_the_sheet(thk) -> None:
    """The shaft steel, the oil, the speed, the required life, f_w and the accuracy grade were
    written without being listed; the named oil's density was a guess for 'an unnamed oil'."""
    case = case_from_dict(tomllib.loads(thk))
    guesses = guessed_defaults(case)
    for key in (
        "design.required_life",
        "materials.screw.material",
        "medium.name",
        "kinematics.lubricant",
        "operating.speed",
        "design.load_factor",
        "design.accuracy_grade",
    ):
        assert guesses[key].endswith("[ASSUMED in the case file]"), key
    assert "medium.density_15" not in guesses
    assert case.medium.density_15 == pytest.approx(880.0)
    assert "screw.balls_per_nut" not in guesses


def test_counts_are_pluralised() -> None:
    text = starter("--d0", "16", "--lead", "5", "--ball", "3.175", "--turns", "1x1", "--nuts", "1")
    assert 'description = "16 x 5 mm ball screw, 1 turn x 1 circuit, 1 nut"' in text
    assert "# 1 circuit x " in text
    result = run(*SHEET[:7], "1x1", "--nuts", "2", "--length", "15")
    assert "longer than 2 nuts of 30 mm" in result.output
    result = run(*SHEET[:7], "1x1", "--nuts", "1", "--length", "15", "--nut-length", "20")
    assert "longer than 1 nut of 20 mm" in result.output
