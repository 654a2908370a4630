"""A working day of thermal error: the duty-cycle transient of the thermal model."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.duty_thermal import thermal_duty
from ballscrew.analyses.operating_point import operating_point
from ballscrew.analyses.result import AnalysisResult
from ballscrew.cli import app
from ballscrew.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
CYCLE = [
    {"speed": "1500 rpm", "axial_load": "2 kN", "stroke": "400 mm", "dwell": "2 s",
     "duration": "40 min"},
    {"speed": 0, "duration": "20 min"},
]  # fmt: skip


@pytest.fixture(scope="module")
def day():
    case = ballscrew.load_case(EXAMPLE, {"duty": CYCLE, "duty_repeat": 3})
    return thermal_duty(case, "network")


def test_energy_is_conserved_over_the_day(day):
    assert day.heat_balance_error < 1e-10
    assert isinstance(day, AnalysisResult)


def test_a_segment_heats_with_its_mean_friction_heat(day):
    # 1500 rpm, 10 mm lead: 0.25 m/s, a 400 mm stroke takes 1.6 s, then 2 s standstill
    case = ballscrew.case.with_overrides(day.case, {"operating.axial_load": 2000.0})
    point = operating_point(case, speed=1500 * 2 * np.pi / 60)
    assert day.segment_heat[0] == pytest.approx(point.heat * 1.6 / 3.6, rel=1e-6)
    assert day.segment_heat[1] == 0.0


def test_the_screw_grows_while_turning_and_shrinks_at_rest(day):
    hours = day.time / 3600.0
    turning = (hours > 0.1) & (hours < 2 / 3)
    resting = (hours > 2 / 3) & (hours < 1.0)
    assert np.all(np.diff(day.elongation[turning]) > 0)
    assert np.all(np.diff(day.elongation[resting]) < 0)
    assert day.elongation[-1] > 0 and day.elongation.max() > day.elongation[-1]


def test_network_and_axisymmetric_agree(day):
    case = day.case.model_copy(update={"duty_repeat": 1})
    fe = thermal_duty(case, "axisymmetric")
    one = thermal_duty(case, "network")
    assert fe.elongation.max() == pytest.approx(one.elongation.max(), rel=0.03)


def test_without_a_duty_list_it_is_a_clear_error():
    with pytest.raises(InputError, match="duty"):
        thermal_duty(ballscrew.load_case(EXAMPLE, {"duty": []}))


def test_command_line_writes_the_day(tmp_path):
    case = tmp_path / "case.toml"
    text = EXAMPLE.read_text()
    text = text.replace("duty_repeat = 8", "duty_repeat = 2", 1)
    case.write_text(text)
    out = tmp_path / "day"
    result = CliRunner().invoke(app, ["duty", str(case), "--out", str(out), "--model", "network"])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["analysis"] == "duty" and summary["duration"]["value"] == pytest.approx(7200)
    assert summary["segment_heat"][1]["value"] == 0.0
    assert (out / "duty_day.png").is_file() and (out / "fields.nc").is_file()


def test_a_cooled_shaft_records_its_coolant_outlet_over_the_day():
    """The outlet of the hollow shaft's coolant (inlet at ambient) is a history: at ambient at
    the start, warming while the screw turns, cooling at rest; the energy still balances, and
    it reaches the summary and the dataset (a solid shaft has neither)."""
    case = ballscrew.load_case(
        EXAMPLE,
        {
            "duty": CYCLE,
            "thermal.shaft_coolant.bore_diameter": "12 mm",
            "thermal.shaft_coolant.flow_rate": "2 L/min",
        },
    )
    cooled = thermal_duty(case, "network")
    outlet = cooled.coolant_outlet_temperature
    hours = cooled.time / 3600.0
    assert outlet[0] == pytest.approx(cooled.ambient_temperature)  # the day starts at ambient
    assert cooled.heat_balance_error < 1e-10
    assert np.all(np.diff(outlet[(hours > 0.1) & (hours < 2 / 3)]) > 0)
    assert np.all(np.diff(outlet[(hours > 2 / 3 + 0.05) & (hours < 0.9)]) < 0)
    assert cooled.ambient_temperature < outlet[-1] < outlet.max() < cooled.max_temperature.max()
    summary = cooled.summary()
    assert summary["peak_coolant_outlet_temperature"]["value"] == pytest.approx(outlet.max())
    assert "coolant_outlet_temperature" in cooled.to_xarray()
    solid = thermal_duty(ballscrew.load_case(EXAMPLE, {"duty": CYCLE}), "network")
    assert solid.coolant_outlet_temperature is None
    assert "peak_coolant_outlet_temperature" not in solid.summary()
