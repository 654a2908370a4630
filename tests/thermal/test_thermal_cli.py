"""``ballscrew thermal`` run as a user would: exit codes, summary.json, fields.nc, report."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from ballscrew.cli import app
from quick_cases import QUICK, run_cli, write_case

runner = CliRunner()


def run(*args: object):
    return runner.invoke(app, [str(a) for a in args])


def coarse_case(tmp_path: Path, source: Path, extra: tuple[tuple[str, str], ...] = ()) -> Path:
    """The example with a 5 mm mesh and 300 s steps, so the test stays fast."""
    text = source.read_text()
    for old, new in (
        ('size = "2 mm"', 'size = "5 mm"'),
        ('time_step = "60 s"', 'time_step = "300 s"'),
        *extra,
    ):
        assert old in text, f"{old!r} not in the example case"
        text = text.replace(old, new, 1)
    path = tmp_path / "case.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("model", ["axisymmetric", "network"])
def test_thermal_writes_a_complete_results_folder(tmp_path, gao_case_path, model):
    out = tmp_path / "out"
    result = run("thermal", coarse_case(tmp_path, gao_case_path), "--out", out, "--model", model)
    assert result.exit_code == 0, result.output
    names = {p.name for p in out.iterdir()}
    assert {"summary.json", "fields.nc", "report.html"} <= names
    assert {"temperature_map.png", "temperature_rise.png", "elongation.png"} <= names
    summary = json.loads((out / "summary.json").read_text())
    assert summary["analysis"] == "thermal" and summary["model"] == model
    assert summary["steady"]["elongation"]["unit"] == "m"
    assert summary["heat_balance"]["relative_error"] < 1e-6
    assert summary["heat_balance"]["transient_relative_error"] < 1e-6
    assert summary["heat_balance"]["heat_input"]["value"] == pytest.approx(51.15, abs=0.02)
    assert {s["name"] for s in summary["sensors"]} == {"nut 1", "spacer", "nut 2", "screw"}
    assert summary["transient"]["duration"]["value"] == pytest.approx(5400.0)
    assert "time_to_95" in summary["transient"]
    assert summary["convection"]["screw"]["value"]["value"] == pytest.approx(37.46, abs=0.02)
    with xr.open_dataset(out / "fields.nc", engine="h5netcdf") as fields:
        assert fields["sensor_temperature"].attrs["units"] == "K"
        assert fields["time"].attrs["units"] == "s"
        assert fields.sizes["time"] == 19
    html = (out / "report.html").read_text()
    assert "data:image/png;base64," in html and "Heat balance" in html
    assert "friction model): screw torque 0.4231 N·m, heat 44.31 W" in html  # 'torque' named


def test_case_without_thermal_section_exits_2(tmp_path, gao_case_path):
    text = gao_case_path.read_text()
    path = tmp_path / "case.toml"
    path.write_text(text[: text.index("[thermal]")])
    out = tmp_path / "out"
    result = run("thermal", path, "--out", out)
    assert result.exit_code == 2
    assert "thermal" in result.output and "[thermal]" in result.output
    assert not out.exists()


def test_bad_thermal_value_exits_2(tmp_path, gao_case_path):
    path = coarse_case(
        tmp_path, gao_case_path, (('ambient_temperature = "20 degC"', "ambient_temperature = 20"),)
    )
    out = tmp_path / "out"
    result = run("thermal", path, "--out", out)
    assert result.exit_code == 2
    assert "thermal.ambient_temperature = 20 is not allowed" in result.output
    assert not out.exists()


def test_3d_model_writes_its_folder(tmp_path, gao_case_path):
    coarse_3d = (
        (
            'size = "5 mm"',
            'size = "5 mm"\nsize_3d = "20 mm"\nfar_size_3d = "60 mm"\n'
            "divisions_3d = 16\nlayers_3d = 2",
        ),
        ('duration = "1.5 h"', 'duration = "900 s"'),
    )
    out = tmp_path / "o"
    result = run(
        "thermal", coarse_case(tmp_path, gao_case_path, coarse_3d), "--out", out, "--model", "3d"
    )
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["model"] == "3d"
    assert abs(summary["heat_balance"]["relative_error"]) < 1e-6


#: The example on the network model with a short duty: 20 min of strokes, then 10 min at rest.
SHORT_DUTY = QUICK | {
    "thermal.model": "network",
    "thermal.transient.time_step": "300 s",
    "duty_repeat": 1,
    "duty": [
        {
            "speed": "1500 rpm",
            "axial_load": "2 kN",
            "stroke": "400 mm",
            "dwell": "2 s",
            "duration": "20 min",
        },
        {"speed": 0, "duration": "10 min"},
    ],
}
#: What the results of one command say about its own run, not about the case's numbers.
RUN_KEYS = ("analysis", "warnings", "guessed_defaults", "inputs", "timing")


def _numbers(summary: dict) -> dict:
    return {k: v for k, v in summary.items() if k not in RUN_KEYS}


def test_thermal_follows_the_duty_cycle_as_ballscrew_duty_does(tmp_path):
    """A case with [[duty]]: ``ballscrew thermal`` writes the duty part, the numbers, histories
    and figure of ``ballscrew duty`` on the same case, next to the operating point's field."""
    case = write_case(tmp_path, "gao2019_tcr.toml", SHORT_DUTY)
    out = tmp_path / "thermal"
    result = run("thermal", case, "--out", out)
    assert result.exit_code == 0, result.output
    assert "duty cycle: peak elongation" in result.output
    ours = json.loads((out / "summary.json").read_text())
    theirs = run_cli("duty", case, "--out", tmp_path / "duty")
    assert ours["duty"] == _numbers(theirs)
    assert ours["duty"]["duration"]["value"] == 1800.0
    assert ours["transient"]["duration"]["value"] == 600.0  # the point's own transient
    assert {"duty_day.png", "temperature_map.png", "elongation.png"} <= set(
        p.name for p in out.iterdir()
    )
    with (
        xr.open_dataset(out / "fields.nc", engine="h5netcdf") as fields,
        xr.open_dataset(tmp_path / "duty" / "fields.nc", engine="h5netcdf") as day,
    ):
        for name in day.data_vars:
            np.testing.assert_array_equal(fields[f"duty_{name}"].values, day[name].values)
        np.testing.assert_array_equal(fields["duty_time"].values, day["time"].values)
        assert fields["duty_sensor_temperature"].dims == ("duty_time", "sensor")
        assert fields.sizes["time"] == 3 and fields.sizes["duty_time"] == 7
    html = (out / "report.html").read_text()
    assert "Temperatures and elongation over the day" in html
    assert "the sections after the heat balance follow the case&#x27;s [[duty]] cycle" in html


def test_the_operating_point_is_the_same_with_and_without_a_duty(tmp_path):
    """The duty part leaves the operating point's numbers alone; ``--no-duty`` and a case
    without [[duty]] write no duty part, and the report says when a duty was not run."""
    with_duty = write_case(tmp_path, "gao2019_tcr.toml", SHORT_DUTY)
    (tmp_path / "plain").mkdir()
    without = write_case(tmp_path / "plain", "gao2019_tcr.toml", SHORT_DUTY | {"duty": []})
    both = run_cli("thermal", with_duty, "--out", tmp_path / "both")
    skipped = run_cli("thermal", with_duty, "--no-duty", "--out", tmp_path / "skipped")
    plain = run_cli("thermal", without, "--out", tmp_path / "plain" / "out")
    assert "duty" not in skipped and "duty" not in plain
    point = {k: v for k, v in _numbers(both).items() if k != "duty"}
    assert point == _numbers(skipped) == _numbers(plain)
    assert skipped["warnings"] == plain["warnings"]
    for folder in (tmp_path / "skipped", tmp_path / "plain" / "out"):
        assert not (folder / "duty_day.png").exists()
        with xr.open_dataset(folder / "fields.nc", engine="h5netcdf") as fields:
            assert "duty_time" not in fields.dims
    html = (tmp_path / "skipped" / "report.html").read_text()
    assert "the case&#x27;s [[duty]] cycle was not run (--no-duty" in html
    assert (
        "the single [operating] point"
        not in (tmp_path / "plain" / "out" / "report.html").read_text()
    )


def test_a_duty_cycle_of_too_many_steps_is_refused_before_the_point_is_solved(
    tmp_path, monkeypatch
):
    """The short duty run 1000 times with 1 s steps is 1.8e6 steps, above a budget of 1e6: the
    one-line error names the [[duty]] cycle and its length (it said "over the duration"), exit
    2, nothing written, and the operating point is never solved (it was, first, in vain);
    --no-duty runs the point."""
    import ballscrew.analyses.thermal as thermal

    monkeypatch.setenv("BALLSCREW_MAX_STEPS", "1000000")
    case = write_case(
        tmp_path,
        "gao2019_tcr.toml",
        SHORT_DUTY | {"duty_repeat": 1000, "thermal.transient.time_step": "1 s"},
    )
    solved = []
    point = thermal._point_field
    monkeypatch.setattr(thermal, "_point_field", lambda *a: solved.append(a) or point(*a))
    out = tmp_path / "refused"
    result = run("thermal", case, "--out", out)
    assert result.exit_code == 2, result.output
    error = result.output.strip().splitlines()[-1]
    assert error.startswith("error: thermal.transient.time_step = 1.0 is not allowed")
    assert "over the [[duty]] cycle of 1.8e+06 s (1000 × the list)" in error
    assert not out.exists() and not solved
    skipped = run("thermal", case, "--no-duty", "--out", tmp_path / "point")
    assert skipped.exit_code == 0, skipped.output
    assert len(solved) == 1
