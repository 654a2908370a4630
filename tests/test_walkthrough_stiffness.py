"""A first-time user's walk through `init` and `check` with a THK BNFN4010-5 style nut (d0 = 40 mm,
lead 10 mm, 6.35 mm balls, 2.5 turns x 2 circuits): the nut stiffness of a single nut, the
lift-off of a lightly preloaded double nut and what the stiffness headline includes."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from ballscrew.cli import app

runner = CliRunner()
SHEET = ["--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2", "--nuts", "2"]


def run(*args: object):
    return runner.invoke(app, [str(a) for a in args])


def check(tmp_path: Path, *init: str) -> tuple[dict, str]:
    """`init` with ``init``, then `check`: (summary.json, console output)."""
    started = run("init", *init)
    assert started.exit_code == 0, started.output
    case_file = tmp_path / "case.toml"
    case_file.write_text(started.stdout)
    out = tmp_path / "check"
    result = run("check", case_file, "--out", out)
    assert result.exit_code == 0, result.output
    return json.loads((out / "summary.json").read_text()), result.output


def test_a_single_nut_is_not_a_thousand_times_softer_than_its_contacts(tmp_path) -> None:
    """`init --nuts 1` then `check` gave 'Hertz contacts only 694.7 N/µm' but 'contacts and
    bodies 0.02042 N/µm': the elastic distribution balanced F_a = 0 N alone, without the
    single nut's preload. The bodies soften the contacts by tens of per cent, not 34 000 x."""
    summary, _ = check(tmp_path, *SHEET[:-1], "1", "--length", "1500")
    contacts = summary["contact_stiffness"]["value"]
    assert summary["nut_stiffness"]["value"] > 0.3 * contacts, summary["nut_stiffness"]
    assert not any("nut stiffness" in w for w in summary["warnings"]), summary["warnings"]


def test_check_warns_when_the_working_load_lifts_off_the_second_nut(tmp_path) -> None:
    """A preload typed as 3 (3 kN meant) gives 3 N; the duty load 4840 N is 570 x the lift-off
    load 2^1.5 F_p = 8.485 N, so nut 2 runs unloaded (backlash) the whole cycle."""
    summary, _ = check(tmp_path, *SHEET, "--preload", "3")
    margin = summary["margins"]["lift_off"]
    assert margin["status"] == "red"
    assert margin["capacity"]["value"] == 2.0**1.5 * 3.0
    lift = [w for w in summary["warnings"] if "lift-off" in w]
    assert lift == [
        "max axial load vs lift-off load 2^1.5 F_p: 4840 N against 8.485 N; above it the second "
        "nut carries no load and the nut runs with backlash; a preload of at least the largest "
        "load / 2^1.5 keeps both nuts loaded"
    ], summary["warnings"]


def test_the_stiffness_headline_says_what_it_includes(tmp_path) -> None:
    """'axial stiffness 124 N/µm' includes the shaft: an engineer compares it with the
    catalogue's nut rigidity. The console names the parts and shows the nut's own stiffness;
    the report says the supports are left out without design.bearing_stiffness."""
    summary, output = check(tmp_path, *SHEET, "--preload", "3000", "--length", "1500")
    assert "nut + shaft stiffness (supports rigid)" in output
    assert "nut stiffness alone (contacts + bodies)" in output
    assert summary["margins"]["lift_off"]["status"] == "green"  # 4840 N against 8485 N
    report = (tmp_path / "check" / "report.html").read_text()
    assert "support bearings are LEFT OUT" in report
