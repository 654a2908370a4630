"""Differential (Heathcote) slip of the ball in the conforming nut groove: closed form and the
ball model's new part at the nut contact B."""

from __future__ import annotations

import importlib
import math

import numpy as np
import pytest
from scipy.optimize import brentq

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
    heathcote_rate,
)
from ballscrew.kinematics.balance import solve_ball
from ballscrew.kinematics.frames import ContactAxes
from ballscrew.kinematics.motion import ball_motion

# a ball in a straight groove (X along the groove, Y across it in the contact plane, Z the normal
# into the ball), the frame turned arbitrarily in space so that no component is read off by index
_TURN = np.linalg.qr(np.array([[0.3, -1.2, 0.5], [0.9, 0.4, -0.7], [0.2, 0.8, 1.1]]))[0]
GROOVE = ContactAxes(origin=np.zeros(3), x=_TURN[:, 0], y=_TURN[:, 1], z=_TURN[:, 2])
R_B, R_D, B_SEMI, LOAD, MU = 2.4e-3, 2.35e-3, 1.5e-4, 30.0, 0.1
LATERAL = np.linspace(-B_SEMI, B_SEMI, 40_001)
"""y across the contact [m]; the contact surface is the circle of radius R_d through the
contact centre, its centre R_d and the ball centre r_b along Z."""


def _surface(y: np.ndarray) -> np.ndarray:
    """Local (x = 0, y, z) of the deformed contact surface across the groove (exact circle)."""
    z = R_D - np.sqrt(R_D * R_D - y * y)
    return np.stack([np.zeros_like(y), y, z], axis=-1)


def _ball_surface_velocity(omega_local: np.ndarray, centre_speed: float) -> np.ndarray:
    """v = V X + ω × (P − C) of the ball material on the contact surface, local components."""
    centre = np.array([0.0, 0.0, R_B])
    return np.array([centre_speed, 0.0, 0.0]) + np.cross(omega_local, _surface(LATERAL) - centre)


def _integral(f: np.ndarray) -> float:
    return float(np.sum(f[1:] + f[:-1]) * 0.5 * (LATERAL[1] - LATERAL[0]))


def test_rolling_about_the_axis_across_the_groove_gives_heathcote_slip_by_hand():
    """Ball rolling at Ω about the axis across the groove (Y): the surface point at y is
    R(y) = r_b − z(y) from that axis, so it slides along the groove at Ω (ρ − R(y)) for the
    rolling radius ρ = V/Ω; ρ puts the forward and backward friction in balance (traction μ p,
    Hertz line load q(y) = (3Q/4b)(1 − y²/b²)) and P = μ ∫ q |Δv| dy. Nothing here uses the
    closed form's rolling line or coefficient."""
    omega = 40.0
    q = 3.0 * LOAD / (4.0 * B_SEMI) * (1.0 - (LATERAL / B_SEMI) ** 2)

    def slip(rho: float) -> np.ndarray:
        return _ball_surface_velocity(np.array([0.0, omega, 0.0]), omega * rho)[:, 0]

    radius = R_B - _surface(LATERAL)[:, 2]
    assert slip(R_B) == pytest.approx(omega * (R_B - radius), abs=1e-12)  # Ω(ρ − R(y))
    rho = brentq(lambda r: _integral(q * np.sign(slip(r))), R_B - 0.01 * R_B, R_B, xtol=1e-14)
    lines = LATERAL[np.flatnonzero(np.diff(np.sign(slip(rho))))]
    assert np.abs(lines) / B_SEMI == pytest.approx(0.3473, abs=1e-3)  # two rolling lines ±c
    by_hand = MU * _integral(q * np.abs(slip(rho)))
    rate = heathcote_rate(omega * GROOVE.y, GROOVE)
    assert rate == pytest.approx(omega, rel=1e-12)
    # the closed form takes the parabola y²/2R_d for the circle: (b/2R_d)² = 0.1 % apart
    assert heathcote_power(LOAD, B_SEMI, R_D, rate, MU) == pytest.approx(by_hand, rel=3e-3)
    grid = differential_slip_power(
        LOAD, 0.2 * B_SEMI, B_SEMI, R_D, rate, psi=1.0, boundary_friction=MU,
        limiting_shear=0.07, cells=64,
    )  # fmt: skip
    assert grid == pytest.approx(by_hand, rel=5e-3)


def test_turning_about_the_groove_direction_or_the_normal_is_no_heathcote_slip():
    """A ball turning about the groove direction X (its centre held in the groove) slides
    sideways over the whole contact at about Ω r_b, one sign everywhere: no rolling lines, a
    gross slide, not Heathcote slip. Spin about Z slides linearly in the position. Only the
    turning about Y drives the differential slip; the old rate |ω × Z| took X's part as well."""
    omega = 40.0
    velocity = _ball_surface_velocity(np.array([omega, 0.0, 0.0]), 0.0)
    slope = LATERAL / np.sqrt(R_D * R_D - LATERAL**2)
    tangent = np.stack([np.zeros_like(LATERAL), np.ones_like(LATERAL), slope], axis=-1)
    across = np.sum(velocity * tangent, axis=-1) / np.linalg.norm(tangent, axis=-1)
    assert np.all(across > 0.0)  # no line of rolling inside the contact
    assert across == pytest.approx(omega * R_B, rel=1e-3)
    assert heathcote_rate(omega * GROOVE.x, GROOVE) == pytest.approx(0.0, abs=1e-12)
    assert heathcote_rate(omega * GROOVE.z, GROOVE) == pytest.approx(0.0, abs=1e-12)
    mixed = 30.0 * GROOVE.y + 40.0 * GROOVE.x + 5.0 * GROOVE.z
    assert heathcote_rate(mixed, GROOVE) == pytest.approx(30.0, rel=1e-12)
    assert heathcote_rate(mixed, GROOVE) < 0.7 * np.linalg.norm(np.cross(mixed, GROOVE.z))


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
        # the ball rolls on the nut at rest, its centre at V, r_b from B: ω_r = V/r_b
        rate = abs(unit.ball_speed) / model.geometry.ball_radius
        a, b = model.hertz_semi_axes("nut", state.load_nut)
        assert b > 2.0 * a  # Y_B, across the groove, is the major axis
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
