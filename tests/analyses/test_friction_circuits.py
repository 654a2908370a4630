"""The circuits of an offset-lead nut: halved between its two preloaded halves, whole on the one
flank of the nut without preload (it then runs as any single nut of all its balls)."""

import warnings

import pytest

from ballscrew.analyses.friction import (
    FourPointContactWarning,
    friction_torque,
    nut_loss_parameters,
)
from ballscrew.case import load_case

UNLOADED = {
    "friction.model": "ball_model",
    "friction.circuits": 3,
    "operating.preload": 0.0,
    "operating.axial_load": "1000 N",
    "operating.speed": "1000 rpm",
    "screw.nuts": 1,
}


def test_offset_lead_without_preload_keeps_all_circuits_on_its_one_flank(wear_case_path):
    """No preload: the offset-lead and the four-point nut are the same one-flank nut of all its
    balls (same flank loads), so the same circuits and the same torque; an odd count is fine."""
    offset = load_case(wear_case_path, {**UNLOADED, "screw.preload_method": "offset_lead"})
    four = load_case(wear_case_path, UNLOADED)
    assert nut_loss_parameters(offset).circuits == 3 == nut_loss_parameters(four).circuits
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FourPointContactWarning)
        expected = friction_torque(four)
    got = friction_torque(offset)
    for part, value in expected.parts.items():
        assert got.parts[part] == pytest.approx(value, rel=1e-12, abs=1e-15), part
    preloaded = load_case(
        wear_case_path,
        {**UNLOADED, "screw.preload_method": "offset_lead", "friction.circuits": 4,
         "operating.preload": "500 N"},
    )  # fmt: skip
    assert nut_loss_parameters(preloaded).circuits == 2


def test_nut_balls_takes_the_earlier_params_argument(wear_case_path):
    """``nut_balls(case, params)`` as before: the same per-ball states as ``nut_balls(case)``."""
    from ballscrew.analyses.friction import nut_balls
    from ballscrew.analyses.parameters import ScrewParameters

    case = load_case(
        wear_case_path, {"loads.distribution": "elastic", "friction.ball_train": "speed_spread"}
    )
    alone = nut_balls(case)
    assert alone is not None and len(alone) == 2
    for old, new in zip(nut_balls(case, ScrewParameters.from_case(case)), alone, strict=True):
        assert old == new
