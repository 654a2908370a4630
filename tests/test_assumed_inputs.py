"""The ``[assumed]`` table: inputs a case writes with an assumed value are listed with the
guesses in summaries and reports, a key that names no input is a one-line error, and a value
written later by an override is no longer listed."""

from __future__ import annotations

import json
import tomllib

import pytest
from typer.testing import CliRunner

from ballscrew.case import case_from_dict, load_case
from ballscrew.case.inputs import guessed_defaults, input_rows, resolved_inputs
from ballscrew.case.loader import with_overrides
from ballscrew.cli import app

runner = CliRunner()
EXAMPLE = "examples/gao2019_tcr.toml"


def _with_assumed(table: str, tmp_path):
    path = tmp_path / "case.toml"
    path.write_text(open(EXAMPLE, encoding="utf-8").read() + "\n[assumed]\n" + table)
    return path


def test_declared_inputs_are_listed_with_their_reason(tmp_path) -> None:
    path = _with_assumed('"screw.contact_angle" = "Gothic arch standard"\n', tmp_path)
    guesses = guessed_defaults(load_case(path))
    assert guesses["screw.contact_angle"] == "Gothic arch standard [ASSUMED in the case file]"
    assert "screw.contact_angle" not in guessed_defaults(load_case(EXAMPLE))


def test_a_list_entry_is_listed_under_its_row_key() -> None:
    raw = tomllib.loads(open(EXAMPLE, encoding="utf-8").read())
    raw["assumed"] = {"duty.0.stroke": "half the travel"}
    case = case_from_dict(raw)
    rows = {key for key, _, _ in input_rows(resolved_inputs(case))}
    assert "duty[0].stroke" in guessed_defaults(case) and "duty[0].stroke" in rows


@pytest.mark.parametrize(
    ("key", "shown"),
    [
        ("screw.led", "did you mean 'lead'"),
        ("screws.lead", "did you mean 'screw'"),
        ("duty.first.speed", "duty is a list; name an entry"),
        ("assumed", "name an input, not the [assumed] table"),
    ],
)
def test_a_key_naming_no_input_is_one_line_exit_2(tmp_path, key, shown) -> None:
    path = _with_assumed(f'"{key}" = "why"\n', tmp_path)
    out = tmp_path / "out"
    result = runner.invoke(app, ["contact", str(path), "--out", str(out)])
    assert result.exit_code == 2
    assert result.output.count("\n") == 1 and f'assumed."{key}"' in result.output
    assert shown in result.output and not out.exists()


def test_a_value_written_by_an_override_is_no_longer_assumed(tmp_path) -> None:
    table = '"screw.contact_angle" = "standard"\n"surface.D" = "typical"\n'
    case = load_case(_with_assumed(table, tmp_path))
    new = with_overrides(case, {"screw.contact_angle": 0.75})
    assert set(new.assumed) == {"surface.D"} and "screw.contact_angle" not in guessed_defaults(new)


def test_the_summary_lists_the_declared_inputs(tmp_path) -> None:
    path = _with_assumed('"operating.preload" = "5 % of C_a, typical"\n', tmp_path)
    out = tmp_path / "out"
    result = runner.invoke(app, ["check", str(path), "--out", str(out)])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert "operating.preload" in summary["guessed_defaults"]
    assert "5 % of C_a, typical [ASSUMED in the case file]" in (out / "report.html").read_text()
