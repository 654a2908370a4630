"""The time base of ``ballscrew duty``: the starter's "working cycle" is one hour, run
``duty_repeat`` times, and the report says how long the histories span (it used to say only
"2 segments run 1 times", under a title about a working day)."""

from __future__ import annotations

import tomllib

from typer.testing import CliRunner

from ballscrew.case import case_from_dict
from ballscrew.cli import app

runner = CliRunner()
SHEET = ["--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2", "--nuts", "2"]


def test_the_starter_states_its_one_hour_cycle_and_the_report_its_time_base(tmp_path) -> None:
    result = runner.invoke(app, ["init", *SHEET])
    assert result.exit_code == 0, result.output
    generated = result.stdout
    assert "duty_repeat = 1 " in generated and "A one-hour working cycle" in generated
    case = case_from_dict(tomllib.loads(generated))
    assert case.duty_repeat == 1 and sum(s.duration for s in case.duty) == 3600.0
    twice = generated.replace("duty_repeat = 1 ", "duty_repeat = 2 ")
    case_file = tmp_path / "twice.toml"
    case_file.write_text(twice.replace("cells_across = 32", "cells_across = 16"))
    out = tmp_path / "duty"
    run = runner.invoke(app, ["duty", str(case_file), "--out", str(out), "--model", "network"])
    assert run.exit_code == 0, run.output
    report = (out / "report.html").read_text(encoding="utf-8")
    assert "2 segments (1 h) run 2 times: 2 h in all" in report
