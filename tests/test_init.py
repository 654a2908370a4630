"""``ballscrew init``: the generated case is complete (every command runs it), its ball count
follows the closed form, and a sheet that cannot be built is a one-line error, exit 2."""

from __future__ import annotations

import json
import math
import tomllib

import pytest
from typer.testing import CliRunner

from ballscrew.case import case_from_dict
from ballscrew.case.inputs import guessed_defaults
from ballscrew.case.starter import parse_turns
from ballscrew.cli import app

runner = CliRunner()
SHEET = ["--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2", "--nuts", "2"]


def init(*args: str):
    return runner.invoke(app, ["init", *args])


@pytest.fixture(scope="module")
def generated() -> str:
    result = init(*SHEET)
    assert result.exit_code == 0, result.output
    return result.stdout


SINGLE_BARE = ["--d0", "32", "--lead", "5", "--ball", "3.175", "--turns", "1x4", "--nuts", "1"]


@pytest.fixture(scope="module")
def bare_single() -> str:
    result = init(*SINGLE_BARE, "--preload", "0")
    assert result.exit_code == 0, result.output
    return result.stdout


def test_ball_count_is_the_closed_form(generated) -> None:
    """balls = circuits × (floor(turns π d_m/(D_w cos λ)) − 1): 2 × (floor(2.5 × 19.852) − 1)."""
    lam = math.atan(10.0 / (math.pi * 40.0))
    per_turn = math.pi * 40.0 / (6.35 * math.cos(lam))
    assert per_turn == pytest.approx(19.852, abs=1e-3)
    case = case_from_dict(tomllib.loads(generated))
    assert case.screw.balls_per_nut == 2 * (math.floor(2.5 * per_turn) - 1) == 96
    assert case.screw.pitch_diameter == pytest.approx(0.040)
    assert case.materials.ball.material == "100Cr6" and case.kinematics.lubricant == "iso_vg_68"
    assert case.design is not None and case.design.dynamic_load_rating is None


def test_every_value_not_on_the_sheet_is_labelled(generated) -> None:
    for line in ("screw_conformity", "contact_angle", "thermal_conductivity", "preload"):
        text = next(t for t in generated.splitlines() if t.startswith(line))
        assert "#" in text, text
    assert "[TYPICAL" in generated and "[ASSUMED" in generated and "[GUESS]" in generated
    assert '"40 mm"' in generated and '"6.35 mm"' in generated


def test_the_labelled_values_are_listed_with_the_guesses(generated) -> None:
    """The [assumed] table the starter writes reaches guessed_defaults; a preload from the sheet
    is not listed."""
    guesses = guessed_defaults(case_from_dict(tomllib.loads(generated)))
    for key in ("screw.pitch_diameter", "screw.contact_angle", "surface.G", "operating.preload"):
        assert guesses[key].endswith("[ASSUMED in the case file]"), key
    given = init(*SHEET, "--preload", "2 kN")
    assert given.exit_code == 0, given.output
    assert "operating.preload" not in tomllib.loads(given.stdout)["assumed"]


COMMANDS = [
    ("contact", []),
    ("tcr", []),
    ("thermal", []),
    ("operating-point", []),
    ("check", []),
    ("duty", ["--model", "network"]),
    ("kinematics", ["--speed", "1000 rpm"]),
]
"""Every command that reads a case, with the options it needs."""


@pytest.mark.parametrize("starter", ["generated", "bare_single"])
@pytest.mark.parametrize(("command", "options"), COMMANDS)
def test_every_command_accepts_the_generated_case(
    request, tmp_path, starter, command, options
) -> None:
    """The double nut of SHEET, and a single nut without preload (--preload 0)."""
    case_file = tmp_path / "my.toml"
    text = request.getfixturevalue(starter)
    fast = text.replace("cells_across = 32", "cells_across = 16")
    fast = fast.replace('duration = "1 h"', 'duration = "10 min"') + '[tcr]\ncell_size = "20 um"\n'
    case_file.write_text(fast)
    out = tmp_path / command
    result = runner.invoke(app, [command, str(case_file), "--out", str(out), *options])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    if command == "check" and starter == "bare_single":
        assert "lift_off" not in summary["margins"]
        assert summary["equivalent_loads"][1]["value"] == 0.0


def test_a_preload_above_the_makers_share_warns_in_the_summary(tmp_path) -> None:
    result = init(*SHEET, "--preload", "20 kN")
    assert result.exit_code == 0, result.output
    case_file = tmp_path / "heavy.toml"
    case_file.write_text(result.stdout)
    out = tmp_path / "check"
    assert runner.invoke(app, ["check", str(case_file), "--out", str(out)]).exit_code == 0
    summary = json.loads((out / "summary.json").read_text())
    assert any("preload vs its largest share of C_a" in w for w in summary["warnings"])
    assert summary["margins"]["preload"]["status"] == "red"
    assert "preload vs its largest share" in (out / "report.html").read_text()


@pytest.mark.parametrize(
    ("args", "field"),
    [
        (["--ball", "12"], "--ball"),  # larger than the 10 mm lead allows
        (["--ball", "25"], "--ball"),
        (["--turns", "3.5x3", "--nut-length", "60"], "--turns"),  # 105 mm of turns, 60 mm nut
        (["--turns", "2.5x0"], "--turns"),
        (["--turns", "two"], "--turns"),
        (["--length", "100", "--turns", "3.5x2"], "--length"),  # two 90 mm nuts on 100 mm
        (["--nuts", "3"], "--nuts"),
        (["--lead", "-5"], "--lead"),
    ],
)
def test_a_sheet_that_cannot_be_built_is_one_line_exit_2(args, field) -> None:
    sheet = dict(zip(SHEET[::2], SHEET[1::2], strict=True)) | dict(
        zip(args[::2], args[1::2], strict=True)
    )
    result = init(*(item for pair in sheet.items() for item in pair))
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field} = "), result.output


@pytest.mark.parametrize(
    ("args", "field", "hint"),
    [
        (["--d0", "0.04"], "--d0", "did you mean 40 mm?"),  # d0 in metres: it blamed the ball
        (["--ball", "6350"], "--ball", "did you mean 6.35 mm?"),
        (["--ball", "30"], "--ball", None),  # too large, no other unit fits: no hint
    ],
)
def test_a_diameter_in_the_wrong_unit_is_blamed_on_its_option(args, field, hint) -> None:
    sheet = dict(zip(SHEET[::2], SHEET[1::2], strict=True)) | dict(
        zip(args[::2], args[1::2], strict=True)
    )
    result = init(*(item for pair in sheet.items() for item in pair))
    assert result.exit_code == 2 and result.output.startswith(f"error: {field} = ")
    assert ("did you mean" in result.output) == (hint is not None)
    assert hint is None or hint in result.output


def test_the_illustrative_duty_stays_below_the_lift_off_of_the_default_preload(tmp_path) -> None:
    """A preloaded single nut's starter ran its duty at 8 % of C_a against a lift-off load of
    2^1.5 × 2 % = 5.7 %: the check of the case init wrote was red on lift-off (now 4 %)."""
    for sheet in (SHEET, SINGLE_BARE):
        result = init(*sheet)
        assert result.exit_code == 0, result.output
        raw = tomllib.loads(result.stdout)
        case = case_from_dict(raw)
        assert case.duty[0].axial_load < 2.0**1.5 * case.operating.preload
        case_file = tmp_path / "starter.toml"
        case_file.write_text(result.stdout)
        out = tmp_path / f"check{case.screw.nuts}"
        assert runner.invoke(app, ["check", str(case_file), "--out", str(out)]).exit_code == 0
        summary = json.loads((out / "summary.json").read_text())
        assert summary["margins"]["lift_off"]["status"] != "red"


def test_turns_notation() -> None:
    assert parse_turns("2.5x2") == (2.5, 2)
    assert parse_turns("1×4") == (1.0, 4)
    assert parse_turns("3") == (3.0, 1)


def test_the_stated_load_rating_is_the_one_the_check_uses(generated) -> None:
    """The comment said 'here C_a = 60.5 kN' while ``ballscrew check`` computed 49.12 kN (the
    hardness and accuracy factors of the shaft steel and grade)."""
    import re

    from ballscrew.analyses.design_check import load_ratings
    from ballscrew.analyses.parameters import ScrewParameters

    case = case_from_dict(tomllib.loads(generated))
    ca, _, computed = load_ratings(case, ScrewParameters.from_case(case))
    assert "dynamic_load_rating" in computed
    stated = re.search(r"here C_a = ([\d.]+) kN", generated)
    assert stated is not None and float(stated.group(1)) == pytest.approx(ca * 1e-3, rel=2e-3)


def test_init_writes_the_preload_method() -> None:
    """A single nut's starter case names its preload (oversized balls unless told); a method that
    does not fit the nuts is refused by its option."""
    base = ["init", "--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2"]
    single = CliRunner().invoke(app, [*base, "--nuts", "1"])
    assert single.exit_code == 0 and 'preload_method = "oversized_balls"' in single.output
    offset = CliRunner().invoke(app, [*base, "--nuts", "1", "--preload-method", "offset_lead"])
    assert offset.exit_code == 0 and 'preload_method = "offset_lead"' in offset.output
    bad = CliRunner().invoke(app, [*base, "--preload-method", "oversized_balls"])
    assert bad.exit_code == 2 and "--preload-method" in bad.output and "spacer" in bad.output


def test_an_offset_lead_needs_an_even_ball_count() -> None:
    """d0 40, lead 20, 2.5 turns: 49 balls per circuit, which an offset lead cannot split into
    two equal halves; two circuits (98 balls) can."""
    base = ["init", "--d0", "40", "--lead", "20", "--ball", "6.35", "--nuts", "1"]
    offset = ["--preload-method", "offset_lead"]
    odd = CliRunner().invoke(app, [*base, "--turns", "2.5x1", *offset])
    assert odd.exit_code == 2, odd.output
    assert odd.output.startswith("error: --preload-method") and "gives 49" in odd.output
    even = CliRunner().invoke(app, [*base, "--turns", "2.5x2", *offset])
    assert even.exit_code == 0 and "balls_per_nut = 98" in even.output


def test_a_single_nut_without_preload_is_written_with_a_load(bare_single) -> None:
    """--preload 0 was refused ('a finite value > 0'), so no single nut without preload could be
    started; its case needs an axial load (no stiffness at 0 N), written as assumed. A double
    nut without preload stays one line, exit 2."""
    raw = tomllib.loads(bare_single)
    case = case_from_dict(raw)
    assert case.operating.preload == 0.0
    assert case.operating.axial_load == case.duty[0].axial_load > 0.0
    assert "operating.axial_load" in raw["assumed"]
    double = init(*SHEET, "--preload", "0")
    assert double.exit_code == 2 and double.output.count("\n") == 1
    assert double.output.startswith("error: --preload = '0 N'") and "--nuts 1" in double.output
    negative = init(*SINGLE_BARE, "--preload", "-1")
    assert negative.exit_code == 2 and ">= 0" in negative.output


@pytest.mark.parametrize(
    ("sheet", "outer_mm"),
    [
        (SHEET, 64.0),  # 1.6 d0; TBI SFNU04010 (DIN 69051-5 form B) prints D = 63 mm
        (["--d0", "32", "--lead", "5", "--ball", "3.175", "--turns", "2.5x2"], 51.2),  # TBI: 50
        (["--d0", "16", "--lead", "10", "--ball", "7.5", "--turns", "1x2", "--nuts", "1"], 31.0),
        # the least body of the d_m written to six digits (9.87655 mm), rounded up, not down
        # to 16.8765 mm below it (init refused its own case, blaming --d0)
        (["--d0", "8", "--dp", "9.876545", "--lead", "5", "--ball", "3.5", "--turns", "1x2",
          "--nuts", "1"], 16.8766),
    ],
)  # fmt: skip
def test_one_nut_one_outer_diameter(sheet, outer_mm) -> None:
    """The check's nut body ([loads]) and the thermal model's nut ([thermal]) are one nut: the
    starter wrote 1.75 d0 to [thermal] and left [loads] at d_m + 5 D_b (56 and 47.9 mm for a
    32 x 5 nut). 1.6 d0 lies within 2.5 % of DIN 69051-5 nuts of 32 and 40 mm; balls too large
    for it get the least body d_m + 2 D_b = 16 + 15 mm, which the case accepts."""
    result = init(*sheet)
    assert result.exit_code == 0, result.output
    case = case_from_dict(tomllib.loads(result.stdout))
    assert case.loads.nut_outer_diameter == pytest.approx(outer_mm * 1e-3)
    assert case.thermal is not None
    assert case.thermal.nut_outer_diameter == case.loads.nut_outer_diameter
    assert {"loads.nut_outer_diameter", "thermal.nut_outer_diameter"} <= set(case.assumed)
    # the file's comments name the DIN bodies only where the body is 1.6 d0
    typical = outer_mm == pytest.approx(1.6 * float(sheet[1]))
    lines = [ln for ln in result.stdout.splitlines() if ln.startswith("nut_outer_diameter")]
    assert [("DIN 69051" in ln) for ln in lines] == [typical, False]
    assert "TYPICAL" in lines[0] if typical else "ASSUMED: d_m + 2 D_b" in lines[0]


def test_a_red_life_on_the_illustrative_duty_says_the_duty_is_not_sized(generated) -> None:
    """Every double nut of `init` missed its own 20000 h (40 x 10: 11370 h) on a duty that is
    an illustration; the check now says so where the duty is in [assumed], and only there."""
    from ballscrew.analyses.design_check import design_check

    raw = tomllib.loads(generated)
    with pytest.warns(UserWarning):
        result = design_check(case_from_dict(raw))
    (life,) = [w for w in result.warnings if w.startswith("required life vs rating life")]
    assert "20000 h against 11370 h" in life
    assert "an illustrative cycle, not sized to this screw" in life
    assert "the required life is assumed too" in life
    del raw["assumed"]["duty"]
    with pytest.warns(UserWarning):
        result = design_check(case_from_dict(raw))
    (life,) = [w for w in result.warnings if w.startswith("required life vs rating life")]
    assert life == "required life vs rating life: 20000 h against 11370 h"
