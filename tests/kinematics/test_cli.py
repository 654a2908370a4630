"""``ballscrew kinematics``: the results folder and one-line errors, run as a user would."""

from __future__ import annotations

import json
import math

import pytest
import xarray as xr
from typer.testing import CliRunner

from ballscrew.cli import app

runner = CliRunner()


def run(*args):
    return runner.invoke(app, [str(a) for a in args])


def case_with(tmp_path, source, *edits):
    text = source.read_text()
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / "case.toml"
    path.write_text(text)
    return path


def test_writes_a_complete_results_folder(tmp_path, wear_case_path):
    case = case_with(
        tmp_path,
        wear_case_path,
        (
            "[numerics]",
            '[kinematics]\nlevel = 1\nspeed_range = ["0 rpm", "1500 rpm"]\nspeed_points = 4\n'
            "\n[numerics]",
        ),
        ("cells_across = 64", "cells_across = 32"),
    )
    out = tmp_path / "out"
    result = run("kinematics", case, "--out", out)
    assert result.exit_code == 0, result.output
    names = {p.name for p in out.iterdir()}
    assert {
        "summary.json",
        "fields.nc",
        "report.html",
        "sliding_low_speed.png",
        "sliding_high_speed.png",
        "loads_angles_vs_speed.png",
        "drag_torque.png",
    } <= names
    summary = json.loads((out / "summary.json").read_text())
    nut = summary["nuts"]["nut1"]
    assert summary["level"] == 1
    assert nut["ball_speed"]["value"] == pytest.approx(0.09333, rel=2e-3)  # β_A ≠ 45°
    assert nut["orbital_speed"]["value"] == pytest.approx(4.652, rel=2e-3)
    assert nut["spin_screw"]["value"] == pytest.approx(7.382, rel=1e-2)
    assert abs(nut["spin_nut"]["value"]) < 1e-9
    assert nut["load_screw"]["unit"] == "N" and nut["angle_nut"]["unit"] == "rad"
    # Λ = h_c/σ_Λ ≈ 0.04 (σ_Λ of the D = 1.4 raceway over the band): boundary, the asperities
    # carry (nearly) all of the load
    assert nut["film_parameter"]["value"] < 0.1 and nut["asperity_share"] > 0.99
    # h_c of the whole ball load at the rolling speed u_e ≈ V(1 + γ) of A (E2.8): 51.35 nm at V
    # and 68.69 N (Hamrock–Dowson by hand) × (1 + γ)^0.67 = 55.1 nm
    assert nut["film_thickness_central"]["value"] == pytest.approx(55.1e-9, rel=0.01)
    assert nut["separation"]["value"] > nut["film_thickness_central"]["value"]
    torque = summary["drag_torque"]
    assert torque["catalogue"]["value"] == pytest.approx(0.4231, rel=5e-4)
    assert 0 < torque["contact_losses"]["value"] < torque["catalogue"]["value"]
    assert torque["heat"]["value"] == pytest.approx(
        torque["contact_losses"]["value"] * 10 * math.pi / 3, rel=1e-9
    )
    assert len(summary["curves"]["load_screw"]["value"]) == 4
    assert summary["options"]["traction"] == "film"
    with xr.open_dataset(out / "fields.nc", engine="h5netcdf") as fields:
        for name in ("pressure", "sliding_x", "sliding_y", "sliding_speed", "asperity_pressure"):
            assert fields[name].dims == ("x", "y")
        assert fields["sliding_speed"].attrs["units"] == "m/s"
        psi = fields.attrs["asperity_share"]
        ratio = (fields["asperity_pressure"] / fields["pressure"]).where(fields["pressure"] > 0)
        assert float(ratio.max()) == pytest.approx(psi, rel=1e-12)
    assert "data:image/png;base64," in (out / "report.html").read_text()


@pytest.mark.parametrize(
    ("edits", "args", "message"),
    [
        ((), ("--speed", "-100 rpm"), "speed"),
        ((), ("--level", "5"), "level"),
        (
            (('viscosity = "0.06 Pa*s"\n', ""), ('pressure_viscosity = "2.1e-8 1/Pa"\n', "")),
            ("--level", "2"),
            "lubricant data",
        ),
        ((('viscosity = "0.06 Pa*s"', 'viscosity = "0 Pa*s"'),), (), "medium.viscosity"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(tmp_path, wear_case_path, edits, args, message):
    case = case_with(tmp_path, wear_case_path, *edits)
    out = tmp_path / "out"
    result = run("kinematics", case, "--out", out, *args)
    assert result.exit_code == 2, result.output
    assert message in result.output
    assert not out.exists()
