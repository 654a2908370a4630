"""Differential (Heathcote) slip of the ball in the conforming nut groove: closed form and the
ball model's new part at the nut contact B."""

from __future__ import annotations

import importlib
import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_model
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.friction import ball_losses
from ballscrew.friction.groove_slip import (
    HEATHCOTE_COEFFICIENT,
    HEATHCOTE_ROLLING_LINE,
    differential_slip_power,
    heathcote_power,
)
from ballscrew.kinematics.balance import solve_ball
from ballscrew.kinematics.motion import ball_motion


def test_rolling_lines_halve_the_line_load_and_the_coefficient_is_johnsons_0_08():
    u = HEATHCOTE_ROLLING_LINE
    # q(y) ∝ 1 − u²: the load inside |u| < u_c is half the total (forward = backward friction)
    assert u - u**3 / 3.0 == pytest.approx(1.0 / 3.0, rel=1e-12)
    assert u == pytest.approx(0.3473, abs=1e-4)
    # k_H = (3/8) ∫ (1 − u²)|u² − u_c²| du, by quadrature
    grid = np.linspace(-1.0, 1.0, 400_001)
    integrand = (1.0 - grid**2) * np.abs(grid**2 - u**2)
    quadrature = (
        3.0 / 8.0 * float(np.sum(integrand[1:] + integrand[:-1]) * 0.5 * (grid[1] - grid[0]))
    )
    assert HEATHCOTE_COEFFICIENT == pytest.approx(quadrature, rel=1e-6)
    # Johnson (1985, ch. 8): full-slip Heathcote resistance F/W ≈ 0.08 μ (b/R)²
    assert HEATHCOTE_COEFFICIENT == pytest.approx(0.08, abs=0.001)


def test_grid_integral_is_the_closed_form_in_the_dry_limit():
    load, a, b, radius, rate, mu = 35.0, 4.1e-5, 3.6e-4, 2.43e-3, 20.0, 0.1
    closed = heathcote_power(load, b, radius, rate, mu)
    assert closed == pytest.approx(0.0806 * mu * load * rate * b * b / radius, rel=1e-3)
    grid = differential_slip_power(
        load, a, b, radius, rate, psi=1.0, boundary_friction=mu, limiting_shear=0.07, cells=64
    )
    assert grid == pytest.approx(closed, rel=2e-3)
    assert heathcote_power(0.0, b, radius, rate, mu) == 0.0
    assert (
        differential_slip_power(
            load, a, b, radius, 0.0, psi=1.0, boundary_friction=mu, limiting_shear=0.07
        )
        == 0.0
    )


def test_a_film_shears_at_most_at_its_limiting_stress_and_less_when_thicker():
    load, a, b, radius, rate = 35.0, 4.1e-5, 3.6e-4, 2.43e-3, 20.0

    def film(h: float) -> float:
        return differential_slip_power(
            load, a, b, radius, rate, psi=0.0, boundary_friction=0.1, limiting_shear=0.07,
            film_thickness=h, viscosity=0.06, pressure_viscosity=2.1e-8, cells=64,
        )  # fmt: skip

    cap = heathcote_power(load, b, radius, rate, 0.07)
    assert 0.5 * cap < film(1e-6) < film(1e-7) < film(1e-8) < cap * 1.002


def test_ball_model_counts_the_slip_at_the_nut_contact(wear_case_path):
    """Before this part the nut contact B was free of loss but for EHL rolling and hysteresis."""
    case = ballscrew.load_case(
        wear_case_path, {"friction.model": "ball_model", "operating.axial_load": 0.0}
    )
    model = ball_model(case)
    nuts = tuple((n.force, n.flank) for n in ScrewParameters.from_case(case).nuts)
    still = ball_losses(model, 0.0, nuts)
    # ω_s → 0⁺: dry, boundary friction μ_b; closed form per ball, summed over the nuts
    expected = 0.0
    for force, flank in nuts:
        state = solve_ball(model, 0.0, force, flank, 0)
        unit = ball_motion(
            model.geometry, 1.0, flank, angle_screw=state.angle_screw, angle_nut=state.angle_nut
        )
        rate = float(np.linalg.norm(np.cross(unit.angular_velocity, unit.nut_contact.z)))
        _, b = model.hertz_semi_axes("nut", state.load_nut)
        expected += model.balls * heathcote_power(
            state.load_nut, b, model.deformed_radius("nut"), rate, model.boundary_friction
        )
    assert still.groove_slip == pytest.approx(expected, rel=5e-3)
    assert still.total == pytest.approx(
        still.sliding
        + still.groove_slip
        + still.ehl_rolling
        + still.hysteresis
        + still.ball_ball
        + still.drag
        + still.recirculation
    )


def test_groove_slip_is_a_part_of_the_torque_and_heats_the_nut(wear_case_path, monkeypatch):
    """B is the nut's contact: against a run without the groove-slip part, its slip adds
    exactly M_gs ω to the nut's heat and nothing to the screw's."""
    case = ballscrew.load_case(
        wear_case_path, {"friction.model": "ball_model", "operating.axial_load": 0.0}
    )
    omega = 100.0
    r = friction_torque(case, speed=omega)
    assert 0.0 < r.parts["groove_slip"] < 0.1 * r.parts["sliding"]
    assert r.total == pytest.approx(sum(r.parts.values()))
    module = importlib.import_module("ballscrew.friction.ball_losses")
    monkeypatch.setattr(module, "_groove_slip_torque", lambda *_: 0.0)
    without = friction_torque(case, speed=omega)
    assert without.parts["groove_slip"] == 0.0
    gained = r.heat_to_nut - without.heat_to_nut
    assert gained == pytest.approx(r.parts["groove_slip"] * omega, rel=1e-9)
    assert r.heat_to_screw == pytest.approx(without.heat_to_screw, rel=1e-12)


def test_lead_angle_slip_at_the_screw_contact_is_omega_rb_tan_lambda(wear_case_path):
    """The screw's surface at r_A = r_m − r_b cosβ runs on a steeper helix than the ball centre:
    with B rolling, the ball slides across the groove at A by ω_s r_b tan λ (theory manual,
    *Friction*, breakdown)."""
    case = ballscrew.load_case(wear_case_path, {"operating.axial_load": 0.0})
    model = ball_model(case)
    geometry = model.geometry
    for force, flank in ((1500.0, 1), (1500.0, -1)):
        state = solve_ball(model, 100.0, force, flank, 0)
        axes = state.motion.screw_contact
        slip = state.motion.sliding_velocity(axes.origin)
        expected = 100.0 * geometry.ball_radius * math.tan(geometry.lead_angle)
        assert abs(float(slip @ axes.y)) == pytest.approx(expected, rel=0.01)
