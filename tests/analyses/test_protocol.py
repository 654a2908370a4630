"""Each converted analysis returns an AnalysisResult; the generic writer makes its folder."""

from __future__ import annotations

import json
import math
import warnings
from collections.abc import Callable
from typing import Any

import pytest

import ballscrew
from ballscrew.analyses.kinematics import run_kinematics
from ballscrew.analyses.result import AnalysisResult
from ballscrew.analyses.screw_tcr import screw_tcr
from ballscrew.analyses.thermal import thermal_field
from ballscrew.results import write_results
from quick_cases import QUICK, write_case

#: analysis name → the composer that solves a case
COMPOSERS: dict[str, Callable[[Any], Any]] = {
    "tcr": screw_tcr,
    "thermal": thermal_field,
    "kinematics": run_kinematics,
}


@pytest.mark.parametrize("name", list(COMPOSERS))
def test_result_follows_the_protocol_and_writes_its_folder(tmp_path, name):
    case_file = write_case(tmp_path, "gao2019_tcr.toml", QUICK)
    result = COMPOSERS[name](ballscrew.load_case(case_file))
    assert isinstance(result, AnalysisResult)
    assert result.analysis == name
    assert isinstance(result.warnings, tuple)

    folder = write_results(result, tmp_path / "out", case_file)
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    assert summary["analysis"] == name
    assert summary["warnings"] == list(result.warnings)
    assert summary["inputs"] == json.loads((folder / "inputs.json").read_text(encoding="utf-8"))
    assert (folder / "case.toml").read_text(encoding="utf-8") == case_file.read_text(
        encoding="utf-8"
    )
    report = (folder / "report.html").read_text(encoding="utf-8")
    assert "<h2>Inputs</h2>" in report and "<table" in report
    for figure in result.figures():
        assert (folder / f"{figure.name}.png").is_file()


def test_kinematics_speed_limits_are_the_results_warnings(tmp_path):
    """The speed-limit text the analysis collects is its protocol warnings, still warned once."""
    from ballscrew.kinematics.limits import SpeedLimitWarning

    case = ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", QUICK))
    with pytest.warns(SpeedLimitWarning) as caught:
        result = run_kinematics(case, speed=942.5)
    assert len(result.warnings) == 2  # d·n, and whirling of the [design] shaft (0.9 m)
    assert "[kinematics] dn_limit" in result.warnings[0]
    assert "whirling" in result.warnings[1] and "l = 900 mm" in result.warnings[1]
    assert [str(w.message) for w in caught] == list(result.warnings)


def test_kinematics_warns_of_the_case_speed_not_the_curve_top(tmp_path):
    """Whirling at 2 m: 0.8 n_cr = 1267 rpm, between the case's 1000 rpm and the curves' top at
    the d·n limit (70000/40 = 1750 rpm). The case speed is not blamed; the curves are."""
    from ballscrew.kinematics import critical_speed, groove_root_diameter
    from ballscrew.kinematics.limits import SpeedLimitWarning

    overrides = QUICK | {"design.unsupported_length": 2.0, "thermal.shaft_length": 2.0}
    case = ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", overrides))
    params = ballscrew.analyses.parameters.ScrewParameters.from_case(case)
    root = groove_root_diameter(params.geometry)
    allowed = 0.8 * critical_speed(
        root, 2.0, params.screw.youngs_modulus, params.screw.density, "fixed-supported"
    )
    omega = case.operating.speed
    assert omega < allowed < 70000 / 40 * math.pi / 30  # the premise of the test
    with pytest.warns(SpeedLimitWarning) as caught:
        result = run_kinematics(case)
    assert len(result.warnings) == 1
    assert result.warnings[0].startswith(
        "the curves versus speed run to 1750 rpm, above the case speed 1000 rpm: speed 1750 rpm "
        "exceeds 0.8 × the whirling speed"
    )
    assert [str(w.message) for w in caught] == list(result.warnings)
    with warnings.catch_warnings():
        warnings.simplefilter("error", SpeedLimitWarning)  # the case speed alone: no warning
        ballscrew.ball_kinematics(case)
