"""Findings of a first-time user's walk through the README with a THK BNFN4010-5 double nut
(d0 = 40 mm, lead 10 mm, 6.35 mm balls, 2.5 turns x 2 circuits, preload 3000 N, 1500 mm
shaft) about the operating point, kinematics, calibration, wear and speed inputs."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballscrew.case import case_from_dict, with_overrides
from ballscrew.case.plausibility import implausible_values
from ballscrew.cli import app
from ballscrew.units import to_si

runner = CliRunner()
SHEET = ["--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2", "--nuts", "2"]
THK = [*SHEET, "--preload", "3000", "--length", "1500", "--name", "BNFN4010-5"]


def run(*args: str | Path):
    return runner.invoke(app, [str(a) for a in args])


def starter(*args: str) -> str:
    result = run("init", *args)
    assert result.exit_code == 0, result.output
    return result.stdout


def fast(text: str) -> str:
    return text.replace("cells_across = 32", "cells_across = 16") + '[tcr]\ncell_size = "20 um"\n'


@pytest.fixture(scope="module")
def thk_case(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("thk") / "bnfn4010.toml"
    path.write_text(fast(starter(*THK)))
    return path


def test_operating_point_above_the_whirling_speed_warns(thk_case, tmp_path) -> None:
    """`check` gives 0.8 x critical speed = 2949 rpm for this case (design.unsupported_length =
    1350 mm, written by init); `operating-point --speed "4000 rpm"` (above even the bare
    critical speed, 3687 rpm) must warn about whirling, not only about d·n."""
    out = tmp_path / "op"
    result = run("operating-point", thk_case, "--speed", "4000 rpm", "--out", out)
    assert result.exit_code == 0, result.output
    warnings = json.loads((out / "summary.json").read_text())["warnings"]
    assert any("whirling" in w and "l = 1.35 m" in w for w in warnings), warnings


def test_the_console_friction_torque_is_the_friction(thk_case, tmp_path) -> None:
    """At 500 rpm and 5 kN the console printed 'friction torque 9.137 N·m' while the friction
    part is 1.18 N·m (heat 61.8 W = 1.18 N·m x 52.4 rad/s); 7.96 N·m is the work F_a L/2pi."""
    out = tmp_path / "op"
    result = run(
        "operating-point", thk_case, "--speed", "500 rpm", "--axial-load", "5 kN", "--out", out
    )
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    line = next(t for t in result.output.splitlines() if t.strip().startswith("friction torque"))
    shown = float(re.search(r"([0-9.]+) N·m", line).group(1))
    assert shown == pytest.approx(summary["friction_part"]["value"], rel=0.01), line
    screw = next(t for t in result.output.splitlines() if t.strip().startswith("screw torque"))
    assert "work on the load included" in screw
    total = float(re.search(r"([0-9.]+) N·m", screw).group(1))
    assert total == pytest.approx(summary["friction_torque"]["value"], rel=0.01)
    assert total - shown == pytest.approx(5e3 * 0.01 / (2 * 3.141592653589793), rel=0.01)


WEAR = """
[wear]
grid = [16, 64]
asperity_roughness = "cell"

[[wear.programme]]
axial_load = "2 kN"
speed = "100 rpm"
revolutions = 1e4

[[wear.programme]]
axial_load = "2 kN"
speed = "1000 rpm"
revolutions = 1e4
"""


def without_duty(text: str) -> str:
    """The starter without its illustrative [[duty]] cycle (a wear programme of its own)."""
    head, rest = text.split("[[duty]]", 1)
    tail = rest[rest.index("[assumed]") :]
    return head + "\n".join(t for t in tail.splitlines() if not t.startswith('"duty"')) + "\n"


def test_a_level_that_wears_nothing_says_why(tmp_path) -> None:
    """100 rpm wore 2.4 µm, 1000 rpm then exactly 0 with no word why (full-film EHL: asperity
    share ~1e-10 on the asperities of one wear-grid cell, wear.asperity_roughness = "cell"; 1.2e-4
    since the cell's asperities have the 3-D G of the raceway's profile G, surface.G_convention,
    below the 1e-3 of the warning).
    The summary and report give Λ and ψ per level, and a warning names the level that wears
    practically nothing; the range warning says 'at 100 rpm', not '100–100 rpm'."""
    case_file = tmp_path / "wear.toml"
    case_file.write_text(without_duty(starter(*THK)) + WEAR)
    out = tmp_path / "wear"
    result = run("wear", case_file, "--out", out)
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    slow, fast_ = summary["lubrication"]
    # Λ = h/σ with σ over the roughness measurement's band (E6.6), ψ from the asperity model
    assert slow["part"] == "level 1" and 0.05 < slow["film_parameter"]["value"] < 1.0
    assert slow["asperity_share"]["value"] > 0.1
    # Hamrock & Dowson (1977): h_c ∝ u^0.67 Q^-0.067 at one viscosity; inlet heating,
    # starvation and a warmer lubricant only thin the faster film, so this ratio is its ceiling
    ceiling = 10.0**0.67 * (fast_["ball_load"]["value"] / slow["ball_load"]["value"]) ** -0.067
    ratio = fast_["film_parameter"]["value"] / slow["film_parameter"]["value"]
    assert 3.0 < ratio <= ceiling * (1 + 1e-9)
    assert fast_["asperity_share"]["value"] < 1e-3
    depth = [lv["max_wear_depth"]["value"] for lv in summary["levels"]]
    assert depth[0] > 0.0 and depth[1] - depth[0] < 1e-3 * depth[0]
    warnings = summary["warnings"]
    full_film = [w for w in warnings if "wears practically nothing" in w]
    assert len(full_film) == 1 and full_film[0].startswith("level 2 (1000 rpm"), warnings
    assert any("calibrated at 100 rpm and 2000–4000 N" in w for w in warnings), warnings
    assert not any("100–100" in w for w in warnings)
    assert "Film and asperity share by level" in (out / "report.html").read_text()


def test_a_boundary_level_wears_with_the_film_roughness(tmp_path) -> None:
    """The same programme with the default wear.asperity_roughness = "film": at 1000 rpm
    Λ = 0.79 < 1 (boundary) and the asperities of height σ_Λ keep most of the load (ψ = 0.855
    against 1.2e-4 with "cell"), so level 2 wears 86 nm after level 1's 101 nm (the wear law
    being per unit sliding distance) and no level is said to wear nothing."""
    case_file = tmp_path / "wear.toml"
    case_file.write_text(without_duty(starter(*THK)) + WEAR.replace('"cell"', '"film"'))
    out = tmp_path / "wear"
    result = run("wear", case_file, "--out", out)
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    slow, fast_ = summary["lubrication"]
    assert fast_["film_parameter"]["value"] < 1.0
    assert fast_["asperity_share"]["value"] > 0.5
    assert slow["asperity_share"]["value"] >= fast_["asperity_share"]["value"]
    depth = [lv["max_wear_depth"]["value"] for lv in summary["levels"]]
    assert depth[1] - depth[0] > 0.5 * depth[0]
    assert not any("wears practically nothing" in w for w in summary["warnings"])


def test_the_kinematics_torque_says_it_is_the_contact_losses(thk_case, tmp_path) -> None:
    """`kinematics --speed "1000 rpm"` called 0.2201 N·m the ball model's 'operating point'
    torque while `operating-point --set friction.model=ball_model` gives 0.4455 N·m (ball–ball
    friction, drag, ... added): the kinematics torque is named the ball contacts' losses, and
    the second sliding map (1677 rpm) says that its speed is the d·n limit's."""
    out = tmp_path / "kin"
    result = run("kinematics", thk_case, "--speed", "1000 rpm", "--out", out)
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    torque = summary["drag_torque"]
    assert "ball_model" not in torque
    line = next(t for t in result.output.splitlines() if "ball contacts' losses only" in t)
    shown = float(re.search(r"([0-9.]+) N·m", line).group(1))
    assert shown == pytest.approx(torque["contact_losses"]["value"], rel=1e-3)
    report = (out / "report.html").read_text()
    assert "ball–ball friction" in report
    caption = (
        r"(\d+) rpm, the top of the curves vs speed: the d·n limit 70000 mm·rpm / d_m = (\S+) mm"
    )
    rpm, pitch = re.search(caption, report).groups()
    assert float(rpm) == pytest.approx(70000 / float(pitch), abs=0.5)
    op = tmp_path / "op"
    args = ("--speed", "1000 rpm", "--set", "friction.model=ball_model", "--out", op)
    assert run("operating-point", thk_case, *args).exit_code == 0
    friction = json.loads((op / "summary.json").read_text())["friction_part"]["value"]
    assert friction > 1.2 * shown  # the full ball model adds ball–ball friction and drag


@pytest.mark.parametrize(
    ("speed", "hint"),
    [("1500", "did you mean '1500 rpm'?"), ("1500 rpm", None), ("90000", "")],
)
def test_a_speed_without_a_unit_hints_rpm(thk_case, speed, hint) -> None:
    """`--speed 1500` is 1500 rad/s = 14 324 rpm, d·n = 573 000 on this 40 mm screw, beyond any
    ball screw (about 200 000); 1500 rpm is plausible, so the case warning asks 'did you mean
    1500 rpm?'. 90 000 rad/s is implausible in rpm too: no unit hint."""
    case = case_from_dict(tomllib.loads(thk_case.read_text()))
    case = with_overrides(case, {"operating.speed": to_si(speed, "angular_velocity")})
    found = [m for m in implausible_values(case) if m.startswith("operating.speed")]
    assert bool(found) is (hint is not None), found
    if hint is not None:
        assert "above any ball screw's 200000" in found[0]
        if hint:
            assert found[0].endswith(f"if given without a unit (rad/s), {hint}"), found
        else:
            assert "did you mean" not in found[0]


def test_the_speed_option_without_a_unit_hints_rpm(thk_case, tmp_path) -> None:
    """`kinematics --speed 1500` (the option does not go into the case): the d·n warning asks
    'did you mean 1500 rpm?'."""
    out = tmp_path / "kin"
    result = run("kinematics", thk_case, "--speed", "1500", "--out", out)
    assert result.exit_code == 0, result.output
    warnings = json.loads((out / "summary.json").read_text())["warnings"]
    assert any("d·n" in w and w.endswith("did you mean '1500 rpm'?") for w in warnings), warnings
