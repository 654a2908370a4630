"""``ballscrew wear`` run as a user would: results folder, units, interrupted run resumed."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.commands.wear import checkpoint_path

from .conftest import REF_PATH

runner = CliRunner()

SMALL_WEAR = """[wear]
model = "A"
coefficient = 1.304e-4
grid = [12, 48]
torque_sampling = 2.5e4

[[wear.programme]]
axial_load = "2000 N"
speed = "100 rpm"
revolutions = 5e4

[[wear.programme]]
axial_load = "4000 N"
speed = "100 rpm"
revolutions = 5e4
"""


def small_case(tmp_path: Path) -> Path:
    text = REF_PATH.read_text()
    path = tmp_path / "small.toml"
    path.write_text(text[: text.index("[wear]")] + SMALL_WEAR)
    return path


def test_wear_writes_a_complete_results_folder(tmp_path) -> None:
    out = tmp_path / "out"
    result = runner.invoke(app, ["wear", str(small_case(tmp_path)), "--out", str(out)])
    assert result.exit_code == 0, result.output
    names = {p.name for p in out.iterdir()}
    assert {"summary.json", "history.nc", "report.html", "state.npz"} <= names
    assert {"torque_preload.png", "wear_profiles.png"} <= names
    assert not checkpoint_path(out).exists()  # removed after success
    summary = json.loads((out / "summary.json").read_text())
    assert summary["analysis"] == "wear" and summary["complete"]
    assert summary["revolutions"] == pytest.approx(1e5)
    h = summary["max_wear_depth"]
    assert h["unit"] == "m" and 0.0 < h["value"] < 1e-6
    assert summary["final_preload"]["value"] < summary["initial_preload"]["value"]
    assert summary["wear_coefficient"]["value"] == pytest.approx(1.304e-4)
    # 1.304e-4 is the reference K of 'cell'; this case runs the default 'film'
    assert summary["wear_coefficient"]["source"] == "case file [wear] coefficient"
    with xr.open_dataset(out / "history.nc", engine="h5netcdf") as ds:
        assert ds["wear_depth"].attrs["units"] == "m"
        assert ds["preload"].attrs["units"] == "N"
        assert ds["wear_depth"].shape[1:] == (2, 48)
        np.testing.assert_allclose(ds["max_wear_depth"].values[-1], h["value"])
        samples = ds["revolutions"].values[ds["torque_sample"].values == 1]
        np.testing.assert_allclose(samples, [0.0, 2.5e4, 5e4, 7.5e4, 1e5])


def test_wear_resumes_a_stopped_run(tmp_path) -> None:
    from ballscrew import load_case, wear_life

    case_path = small_case(tmp_path)
    out = tmp_path / "out"
    state = checkpoint_path(out)
    wear_life(load_case(case_path), checkpoint=state, max_steps=3)  # "stopped" run
    result = runner.invoke(app, ["-v", "wear", str(case_path), "--out", str(out)])
    assert result.exit_code == 0, result.output
    fresh = wear_life(load_case(case_path))
    with xr.open_dataset(out / "history.nc", engine="h5netcdf") as ds:
        np.testing.assert_allclose(ds["preload"].values, fresh.preload, rtol=1e-9)


def test_wear_bad_case_exits_2(tmp_path) -> None:
    text = small_case(tmp_path).read_text().replace('model = "A"', 'model = "B"')
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    result = runner.invoke(app, ["wear", str(bad), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert "wear.model" in result.output


def test_checkpoint_of_another_case_is_replaced(tmp_path) -> None:
    from ballscrew import load_case, wear_life
    from ballscrew.case import with_overrides

    case_path = small_case(tmp_path)
    out = tmp_path / "out"
    other = with_overrides(load_case(case_path), {"wear.coefficient": 3e-4})
    wear_life(other, checkpoint=checkpoint_path(out), max_steps=2)
    result = runner.invoke(app, ["wear", str(case_path), "--out", str(out)])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["wear_coefficient"]["value"] == pytest.approx(1.304e-4)
    assert summary["complete"]


def test_wear_result_follows_the_result_protocol(tmp_path) -> None:
    from ballscrew import load_case, wear_life
    from ballscrew.results import write_results
    from protocol_check import assert_protocol_folder

    case_path = small_case(tmp_path)
    life = wear_life(load_case(case_path))
    summary = assert_protocol_folder(life, write_results(life, tmp_path / "out", case_path))
    assert summary["inputs"]["wear"]["grid"] == [12, 48]
    assert life.torque_samples[0][0] == 0.0 and life.level_boundaries[-1] == 1e5
    with pytest.raises(dataclasses.FrozenInstanceError):
        life.life.preload = life.preload  # results are immutable


@pytest.mark.parametrize("bad", [5, "case.toml", None])
def test_wear_life_refuses_what_is_not_a_case(bad) -> None:
    from ballscrew import wear_life
    from ballscrew.analyses.wear import wear_setup
    from ballscrew.errors import InputError

    for call in (wear_life, wear_setup):
        with pytest.raises(InputError, match="case"):
            call(bad)


@pytest.mark.parametrize(
    ("method", "balls"),
    [("oversized_balls", 54), ("offset_lead", 27)],
    ids=["four_point", "offset"],
)
def test_wear_of_a_preloaded_single_nut(tmp_path, method, balls) -> None:
    """``ballscrew wear --set screw.nuts=1 --set screw.preload_method=…``: the summary, history
    and report name the two loaded flanks "flank 1"/"flank 2", not nuts."""
    out = tmp_path / "out"
    sets = ["--set", "screw.nuts=1", "--set", f"screw.preload_method={method}"]
    result = runner.invoke(app, ["wear", str(small_case(tmp_path)), "--out", str(out), *sets])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["nut"] == {"nuts": 1, "preload_method": method, "balls_per_flank": balls}
    forces = summary["final_forces"]
    assert set(forces) == {"flank 1", "flank 2"}
    assert forces["flank 1"]["value"] - forces["flank 2"]["value"] == pytest.approx(4000.0)
    assert summary["final_preload"]["value"] < summary["initial_preload"]["value"]
    with xr.open_dataset(out / "history.nc", engine="h5netcdf") as ds:
        assert "nut_force" not in ds and list(ds["flank_force"].dims) == ["step", "loaded_flank"]
        assert ds["flank_force"].attrs["long_name"] == "axial force of flank 1 and flank 2"
    report = (out / "report.html").read_text()
    assert "flank 1 / flank 2" in report and "nut 1 / nut 2" not in report
    assert "A single nut preloaded by" in report


def test_double_nut_summary_names_the_nuts(tmp_path) -> None:
    out = tmp_path / "out"
    result = runner.invoke(app, ["wear", str(small_case(tmp_path)), "--out", str(out)])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert set(summary["final_forces"]) == {"nut 1", "nut 2"}
    assert summary["nut"] == {"nuts": 2, "preload_method": "spacer", "balls_per_flank": 54}
    assert "A single nut" not in (out / "report.html").read_text()


def test_single_nut_without_preload_exits_2(tmp_path) -> None:
    sets = ["--set", "screw.nuts=1", "--set", "operating.preload=0"]
    result = runner.invoke(
        app, ["wear", str(small_case(tmp_path)), "-o", str(tmp_path / "o"), *sets]
    )
    assert result.exit_code == 2
    assert "backlash" in result.output
