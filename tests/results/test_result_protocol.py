"""Every registered analysis returns one protocol: ``to_xarray()`` is one xarray Dataset and
``summary()`` is plain JSON (``json.dumps(..., allow_nan=False)``), a NaN being None with a
reason. The table of runs below must name every analysis of the registry, so a new analysis
cannot drift from the protocol unnoticed."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from functools import cache
from typing import Any

import numpy as np
import pytest
import xarray as xr

import ballscrew
from ballscrew.analyses.ball_contact import solve_ball_contacts
from ballscrew.analyses.catalog import ANALYSES
from ballscrew.analyses.duty_thermal import thermal_duty
from ballscrew.analyses.kinematics import run_kinematics
from ballscrew.analyses.result import AnalysisResult, json_ready, quantity
from ballscrew.analyses.surface import surface_characterisation
from ballscrew.case import with_overrides
from quick_cases import EXAMPLES, QUICK, QUICK_WEAR

PROFILE = EXAMPLES / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"


@cache
def gao() -> Any:
    return with_overrides(ballscrew.load_case(EXAMPLES / "gao2019_tcr.toml"), QUICK)


@cache
def wear_case() -> Any:
    case = ballscrew.load_case(EXAMPLES / "wear_step_stress.toml")
    return with_overrides(case, QUICK | QUICK_WEAR | {"wear.grid": [8, 32]})


def _calibration() -> Any:
    from ballscrew.calibration import fit_wear_coefficient, measured_history
    from calibration.conftest import MEASURED_AT, SyntheticModel, exact

    clean = exact(2.0e-4, MEASURED_AT).max_wear_depth
    noise = np.random.default_rng(0).normal(0.0, 3e-8, clean.size)
    data = measured_history(MEASURED_AT, clean + noise, "wear_depth", source="b.csv")
    return fit_wear_coefficient(SyntheticModel(), data)


def _joint_calibration() -> Any:
    from ballscrew.calibration.joint import fit_joint
    from calibration.test_joint_covariance import TRUE, data, joint_parts

    measured = [data(seed, *truth) for seed, truth in enumerate(TRUE, start=1)]
    return fit_joint(joint_parts(measured), ["wear_coefficient"])


#: analysis name → a quick run of it (the joint calibration is the second result of "calibrate")
RUNS: dict[str, Callable[[], Any]] = {
    "contact": lambda: solve_ball_contacts(gao()),
    "tcr": lambda: ballscrew.screw_tcr(gao()),
    "thermal": lambda: ballscrew.thermal_field(gao()),
    "thermal-network": lambda: ballscrew.thermal_field(gao(), model="network"),
    "thermal-fe": lambda: ballscrew.thermal_field(gao(), model="axisymmetric"),
    "operating-point": lambda: ballscrew.operating_point(gao()),
    "duty": lambda: thermal_duty(gao(), model="network"),
    "check": lambda: ballscrew.design_check(gao()),
    "kinematics": lambda: run_kinematics(gao(), level=0),
    "wear": lambda: ballscrew.wear_life(wear_case()),
    "calibrate": _calibration,
    "calibrate-joint": _joint_calibration,
    "surface": lambda: surface_characterisation(PROFILE, gamma=1.6, resolution=1e-6),
}


def test_every_registered_analysis_has_a_run_here():
    assert set(ANALYSES.names) <= set(RUNS), "add the new analysis to RUNS"


@pytest.mark.filterwarnings("ignore")
@pytest.mark.parametrize("name", RUNS)
def test_result_is_one_dataset_and_a_plain_json_summary(name):
    result = RUNS[name]()
    assert isinstance(result, AnalysisResult)
    data = result.to_xarray()
    assert type(data) is xr.Dataset
    assert data.data_vars, "the dataset of a result holds its fields or histories"
    numbers = [v for v in data.data_vars.values() if v.dtype.kind in "fiuc"]
    assert all("units" in v.attrs for v in numbers), [v.name for v in numbers]
    summary = result.summary()
    assert json.loads(json.dumps(summary, allow_nan=False)) == summary


def test_a_number_that_is_not_defined_is_none_with_its_reason():
    assert quantity(math.nan, "s", "not reached") == {
        "value": None,
        "unit": "s",
        "reason": "not reached",
    }
    assert quantity(np.float64(2.5), "m") == {"value": 2.5, "unit": "m"}
    plain = json_ready({"t": {"value": np.nan, "unit": "s"}, "x": np.arange(2), 3: (np.int64(1),)})
    assert plain["t"]["value"] is None and "finite" in plain["t"]["reason"]
    assert plain["x"] == [0, 1] and type(plain["x"][0]) is int
    assert plain["3"] == [1]


def test_an_infinite_number_says_it_is_infinite():
    """+∞ (a lifted-off nut's resistance) is not 'not defined': its reason says infinite."""
    plain = json_ready(
        {"r": {"value": math.inf, "unit": "K/W"}, "s": {"value": -np.inf, "unit": ""}}
    )
    assert plain["r"] == {"value": None, "unit": "K/W", "reason": "infinite (+∞): no limit"}
    assert plain["s"]["value"] is None and plain["s"]["reason"].startswith("infinite (−∞)")
    json.dumps(plain, allow_nan=False)
