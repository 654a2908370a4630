"""The operating point coupled into the thermal field, the duty transient, TCR and kinematics."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.duty_thermal import thermal_duty
from ballscrew.analyses.kinematics import at_operating_temperature, ball_model
from ballscrew.analyses.operating_point import (
    _nut_and_screw,
    at_operating_point,
    operating_point,
)
from ballscrew.analyses.thermal import thermal_field
from ballscrew.case import with_overrides
from ballscrew.errors import InputError
from ballscrew.loads import DRAG_TORQUE_MODELS, DragTorqueInputs
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY

RPM = 2 * math.pi / 60
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
#: An ISO VG 68 oil whose viscosity follows the temperature, and a friction model that sees it.
OIL = {
    "medium.viscosity": None,
    "medium.pressure_viscosity": None,
    "kinematics.lubricant": "iso_vg_68",
    "friction.model": "ball_model",
    "thermal.mounting.kind": "free",  # a nut in still air: warm enough to thin the oil
}


@pytest.fixture(scope="module")
def case():
    return ballscrew.load_case(
        EXAMPLE,
        {"numerics.cells_across": 16, "thermal.mesh.size": "10 mm", **OIL},
    )


@pytest.fixture(scope="module")
def network(case):
    return thermal_field(case, "network", transient=False)


def _balls(field) -> tuple[float, float]:
    balls = [s for s in field.sources if "balls" in s.name]
    return sum(s.heat for s in balls), sum(s.into_screw for s in balls)


def test_thermal_field_takes_the_heat_of_the_operating_point(case, network):
    point = operating_point(case)
    heat, into_screw = _balls(network)
    assert network.coupling is not None
    assert heat == pytest.approx(point.heat, rel=1e-9)
    assert into_screw == pytest.approx(point.heat_to_screw, rel=1e-9)
    assert network.coupling.viscosity == pytest.approx(point.viscosity, rel=1e-12)
    oil = LUBRICANT_LIBRARY["iso_vg_68"]
    assert network.coupling.viscosity < oil.at(network.ambient_temperature).viscosity
    assert network.case is case  # the result reports the case as the user gave it


def test_a_fixed_heat_of_the_case_is_kept(case, network):
    fixed = with_overrides(
        case, {"thermal.drag_torque.source": "given", "thermal.drag_torque.torque": 0.2}
    )
    field = thermal_field(fixed, "network", transient=False)
    assert field.coupling is None
    assert _balls(field) == pytest.approx((0.2 * case.operating.speed, 0.1 * case.operating.speed))
    assert _balls(field)[0] != pytest.approx(_balls(network)[0], rel=1e-3)


@pytest.mark.parametrize(
    ("model", "friction"), [("axisymmetric", "ball_model"), ("3d", "catalogue")]
)
def test_every_model_is_at_its_own_fixed_point(case, network, model, friction):
    """The FE fields continue the network's fixed point: their own contact temperature gives
    the viscosity and hence the heat they were solved with."""
    coarse = with_overrides(
        case,
        {
            "friction.model": friction,
            "thermal.mesh.size_3d": "8 mm",
            "thermal.mesh.far_size_3d": "80 mm",
            "thermal.mesh.divisions_3d": 12,
            "thermal.mesh.layers_3d": 1,
        },
    )
    field = thermal_field(coarse, model, transient=False)
    coupling = field.coupling
    nut, screw = _nut_and_screw(field)
    assert 0.5 * (nut + screw) == pytest.approx(coupling.contact_temperature, abs=0.02)
    eta = LUBRICANT_LIBRARY["iso_vg_68"].at(coupling.contact_temperature).viscosity
    assert coupling.viscosity == pytest.approx(eta, rel=2e-3)  # 0.01 K of the fixed point
    assert _balls(field)[0] == pytest.approx(coupling.heat, rel=1e-9)
    if friction == "ball_model":  # the heat sees the viscosity: the FE model's own point
        assert coupling.heat != pytest.approx(network.coupling.heat, rel=1e-6)
    else:
        assert coupling.iterations == 1 and coupling.heat == operating_point(coarse).heat


def test_a_long_single_segment_ends_at_the_steady_operating_point(case):
    """Transient with the viscosity following the temperature: the oil thins as the screw
    warms, the heat falls, and after 8 h (≫ the time constants) the contact temperature is the
    steady coupled operating point's."""
    segment = {"speed": "1500 rpm", "axial_load": "0 N", "duration": "8 h"}
    long = {"duty": [segment], "duty_repeat": 1, "thermal.transient.time_step": "300 s"}
    day = thermal_duty(with_overrides(case, long), "network")
    point = operating_point(case, speed=1500 * RPM, axial_load=0.0)
    ambient = day.ambient_temperature
    rise = point.contact_temperature - ambient
    assert day.contact_temperature[-1] - ambient == pytest.approx(rise, rel=0.01)
    assert day.friction_heat[-1] == pytest.approx(point.heat, rel=0.01)
    assert day.friction_heat[0] > 1.05 * day.friction_heat[-1]  # cold, thick oil at the start
    assert np.all(np.diff(day.viscosity[1:]) <= 0.0)  # the oil only thins while heating
    assert day.heat_balance_error < 1e-10


def test_the_duty_heat_follows_the_temperature_within_a_day(case):
    cycle = [
        {"speed": "1500 rpm", "axial_load": "2 kN", "duration": "40 min"},
        {"speed": 0, "duration": "20 min"},
    ]
    two = {"duty": cycle, "duty_repeat": 2, "thermal.transient.time_step": "300 s"}
    day = thermal_duty(with_overrides(case, two), "network")
    turning = day.friction_heat > 0
    first, second = day.friction_heat[1], day.friction_heat[turning][-1]
    assert second < first  # the second hour starts warm: thinner oil, less heat
    assert day.segment_heat[0] < first  # the steady point is hotter than the cold start
    assert day.heat_balance_error < 1e-10


def test_coupled_kinematics_take_the_operating_point_viscosity(case):
    coupled = with_overrides(
        case, {"operating.coupled": True, "kinematics.level": 2, "friction.model": "catalogue"}
    )
    resolved, point = at_operating_point(coupled)
    assert ball_model(resolved).viscosity == point.viscosity
    plain = ball_model(with_overrides(coupled, {"operating.coupled": False}))
    assert abs(plain.viscosity / point.viscosity - 1.0) > 0.1  # the 40 °C value of the case
    by_hand = with_overrides(
        coupled,
        {
            "operating.coupled": False,
            "medium.viscosity": point.viscosity,
            "medium.pressure_viscosity": resolved.medium.pressure_viscosity,
        },
    )
    film = ballscrew.ball_kinematics(coupled).sharing.separation
    assert film > 0 and film == pytest.approx(ballscrew.ball_kinematics(by_hand).sharing.separation)


def test_coupled_tcr_takes_the_medium_conductivity_at_the_operating_temperature(case):
    coupled = with_overrides(case, {"operating.coupled": True, "friction.model": "catalogue"})
    resolved, point = at_operating_point(coupled)
    conductivity = LUBRICANT_LIBRARY["iso_vg_68"].at(point.contact_temperature).conductivity
    assert resolved.medium.thermal_conductivity == pytest.approx(conductivity, rel=1e-12)
    assert conductivity != pytest.approx(case.medium.thermal_conductivity, rel=1e-3)
    by_hand = with_overrides(
        case, {"medium.thermal_conductivity": conductivity, "medium.viscosity": point.viscosity}
    )
    tcr = ballscrew.screw_tcr(coupled)
    assert tcr.resistance == pytest.approx(ballscrew.screw_tcr(by_hand).resistance, rel=1e-12)
    assert tcr.resistance != pytest.approx(ballscrew.screw_tcr(case).resistance, rel=1e-6)


def test_without_the_option_the_case_stays_as_given(case):
    assert not case.operating.coupled
    assert at_operating_temperature(case) is case


def test_the_operating_point_torque_is_solved_by_the_composer():
    inputs = DragTorqueInputs(1500.0, 0.01, 0.0794)
    with pytest.raises(InputError, match=r"thermal\.drag_torque\.source"):
        DRAG_TORQUE_MODELS["operating_point"](inputs)
    solved = DragTorqueInputs(1500.0, 0.01, 0.0794, given=0.25)
    assert DRAG_TORQUE_MODELS["operating_point"](solved) == 0.25
