"""``ballscrew thermal`` run as a user would: exit codes, summary.json, fields.nc, report."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import xarray as xr
from typer.testing import CliRunner

from ballscrew.cli import app

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
