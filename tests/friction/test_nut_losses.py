"""Ball–ball friction, drag of the balls, the ball-return loss: closed forms and the ball model."""

from __future__ import annotations

import math

import pytest

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.case import CaseError
from ballscrew.errors import InputError
from ballscrew.friction.nut_losses import (
    ball_ball_power,
    drag_power,
    recirculation_power,
    sphere_drag_coefficient,
)


def test_ball_ball_power_is_friction_times_force_times_twice_the_surface_speed():
    # neighbours turning alike slide at 2 r_b |Ω × t|: μ_bb F_B 2 v
    assert ball_ball_power(0.35, 0.1, 0.084) == pytest.approx(0.1 * 0.35 * 2 * 0.084)
    assert ball_ball_power(0.0, 0.1, 0.084) == 0.0


def test_sphere_drag_coefficient_stokes_limit_and_newton_regime():
    assert sphere_drag_coefficient(1e-6) * 1e-6 == pytest.approx(24.0, rel=1e-3)  # Stokes
    assert sphere_drag_coefficient(1.0) == pytest.approx(24.0 * 1.15)
    assert sphere_drag_coefficient(5e3) == 0.44
    # the Schiller–Naumann fit meets the Newton value at Re = 1000 within 0.5 %
    assert sphere_drag_coefficient(999.999) == pytest.approx(0.44, rel=5e-3)


def test_drag_power_is_stokes_drag_times_speed_at_low_reynolds():
    eta, rho, d, v, fill = 0.06, 870.0, 4.7625e-3, 1e-4, 0.3
    re = rho * v * d / eta
    stokes = 3.0 * math.pi * eta * d * v * (1.0 + 0.15 * re**0.687)
    assert drag_power(v, d, rho, eta, fill) == pytest.approx(fill * stokes * v, rel=1e-12)
    assert drag_power(0.0, d, rho, eta, fill) == 0.0
    assert drag_power(v, d, rho, eta, 0.0) == 0.0


def test_recirculation_power_closed_form():
    m, i, d, v, omega = 4.4e-4, 1e-9, 4.7625e-3, 2.5, 1000.0
    expected = 3 * v / d * (0.5 * m * v * v + 0.5 * i * omega * omega)
    assert recirculation_power(v, omega, m, i, d, 3) == pytest.approx(expected)
    assert recirculation_power(0.0, 0.0, m, i, d, 3) == 0.0


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: ball_ball_power(-1.0, 0.1, 1.0), "ball_ball_force"),
        (lambda: drag_power(1.0, 1e-3, 870.0, 0.06, -0.1), "friction.lubricant_fill"),
        (lambda: sphere_drag_coefficient(0.0), "reynolds"),
    ],
)
def test_bad_inputs_name_the_field(call, field):
    with pytest.raises(InputError, match=rf"^{field} = "):
        call()


@pytest.fixture
def physics_case(wear_case_path):
    return ballscrew.load_case(
        wear_case_path, {"friction.model": "ball_model", "operating.axial_load": 0.0}
    )


def _with(case, **friction):
    return case.model_copy(update={"friction": case.friction.model_copy(update=friction)})


def test_ball_ball_part_is_proportional_to_the_contact_force_and_heats_the_nut(physics_case):
    base = friction_torque(_with(physics_case, ball_ball_load_ratio=0.01), speed=100.0)
    double = friction_torque(_with(physics_case, ball_ball_load_ratio=0.02), speed=100.0)
    none = friction_torque(_with(physics_case, ball_ball_load_ratio=0.0), speed=100.0)
    assert none.parts["ball_ball"] == 0.0 < base.parts["ball_ball"]
    assert double.parts["ball_ball"] == pytest.approx(2.0 * base.parts["ball_ball"], rel=1e-12)
    assert double.heat_to_screw == pytest.approx(base.heat_to_screw, rel=1e-12)
    assert double.heat - base.heat == pytest.approx(base.parts["ball_ball"] * 100.0, rel=1e-9)


def test_speed_dependent_losses_vanish_at_rest_and_grow_with_speed(physics_case):
    rest = friction_torque(physics_case, speed=0.0)
    slow = friction_torque(physics_case, speed=10.0)
    fast = friction_torque(physics_case, speed=300.0)
    assert rest.parts["drag"] == 0.0 and rest.parts["recirculation"] == 0.0
    assert rest.parts["ball_ball"] > 0.0  # sliding friction between balls at breakaway
    assert 0.0 < slow.parts["drag"] < fast.parts["drag"]
    assert 0.0 < slow.parts["recirculation"] < fast.parts["recirculation"]
    # the return loss per unit speed grows as ω² (kinetic energy × ball flux / ω)
    ratio = fast.parts["recirculation"] / slow.parts["recirculation"]
    assert ratio == pytest.approx(30.0**2, rel=0.05)


def test_given_recirculation_torque_adds_to_the_modelled_one(physics_case):
    base = friction_torque(physics_case, speed=100.0)
    more = friction_torque(_with(physics_case, recirculation_torque=0.01), speed=100.0)
    assert more.parts["recirculation"] == pytest.approx(base.parts["recirculation"] + 0.01)


def test_return_push_in_the_ball_model(physics_case):
    push = _with(physics_case, ball_train="return_push")
    ratio = friction_torque(physics_case, speed=100.0)
    slow = friction_torque(push, speed=100.0)
    fast = friction_torque(push, speed=300.0)
    rest = friction_torque(push, speed=0.0)
    # the contact losses do not see the ball-train model
    for part in ("sliding", "groove_slip", "ehl_rolling", "hysteresis", "drag"):
        assert slow.parts[part] == ratio.parts[part]
    # the bend's centripetal term grows with V²: more ball–ball torque per unit speed when faster
    assert 0.0 < rest.parts["ball_ball"] < slow.parts["ball_ball"] < fast.parts["ball_ball"]
    # pushing the return train is a loss of the returns; at rest its ω_s → 0⁺ limit remains
    # (the wall friction of the weight, n_c n_r μ_r m g V/ω_s, as the ball–ball part above),
    # below the moving value, which adds the bend's V² term and the rolling-return loss
    assert slow.parts["recirculation"] > ratio.parts["recirculation"]
    assert 0.0 < rest.parts["recirculation"] < slow.parts["recirculation"]
    # no return, no push: no ball–ball friction, the return loss of the ratio model
    none = friction_torque(_with(push, return_fraction=0.0), speed=100.0)
    assert none.parts["ball_ball"] == 0.0
    assert none.parts["recirculation"] == pytest.approx(ratio.parts["recirculation"], rel=1e-12)


@pytest.mark.parametrize(
    ("key", "value"),
    [
        ("friction.ball_ball_load_ratio", -0.1),
        ("friction.lubricant_fill", 2.0),
        ("friction.circuits", 0),
        ("friction.ball_train", "nope"),
        ("friction.return_friction", -0.1),
        ("friction.return_fraction", 11.0),
    ],
)
def test_bad_case_values_are_one_line_errors(wear_case_path, key, value):
    with pytest.raises(CaseError) as err:
        ballscrew.load_case(wear_case_path, {key: value})
    assert key.split(".")[1] in str(err.value) and "\n" not in str(err.value).strip()
