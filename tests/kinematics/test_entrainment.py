"""Entrainment speed of the EHL contacts (E2.8): the rolling speed of the surfaces past each
contact, against the bearing closed form, and the ball-centre convention of the wear paper."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.kinematics import ball_model, run_kinematics
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.errors import InputError
from ballscrew.kinematics.motion import ball_motion, entrainment_speed

from .conftest import RPM

GAO = "examples/gao2019_tcr.toml"


@pytest.fixture(scope="module")
def gao():
    return ballscrew.load_case(GAO, {"numerics.cells_across": 16, "kinematics.speed_points": 2})


def test_level0_rolling_speed_is_the_bearing_closed_form_without_lead(ref_geometry):
    """Without lead the ball screw is an angular-contact bearing with the screw the inner race:
    u_e = (ω_s − ω_c) r_A = ω_c r_B = ω_s d_m (1 − γ²)/4, γ = D cosβ/d_m (Harris & Kotzalas
    2007), larger than the ball-centre speed V = ω_s d_m (1 − γ)/4 by 1 + γ."""
    flat = dataclasses.replace(ref_geometry, lead=1e-9)
    omega = 1000 * RPM
    motion = ball_motion(flat, omega)
    gamma = flat.ball_diameter * math.cos(flat.contact_angle) / flat.pitch_diameter
    u = omega * flat.pitch_diameter * (1 - gamma**2) / 4
    assert motion.entrainment_speed("screw") == pytest.approx(u, rel=1e-6)
    assert motion.entrainment_speed("nut") == pytest.approx(u, rel=1e-6)
    assert motion.entrainment_speed("screw") / motion.ball_speed == pytest.approx(1 + gamma)


def test_level0_rolling_speed_with_lead_is_the_same_at_both_contacts(gao):
    """With lead: pure rolling at A and B makes u_A = u_B; within 0.5 % of (ω_s − ω_c) r_A from
    the contact radii alone (the lead adds the axial parts): 1.034 m/s at 1000 rpm vs V = 0.933."""
    geometry = ScrewParameters.from_case(gao).geometry
    omega = 1000 * RPM
    motion = ball_motion(geometry, omega)
    r_a = float(np.hypot(*motion.screw_contact.origin[:2]))
    r_b = float(np.hypot(*motion.nut_contact.origin[:2]))
    u_a, u_b = motion.entrainment_speed("screw"), motion.entrainment_speed("nut")
    assert u_a == pytest.approx(u_b, rel=1e-9)
    assert u_a == pytest.approx((omega - motion.orbital_speed) * r_a, rel=5e-3)
    assert u_b == pytest.approx(motion.orbital_speed * r_b, rel=5e-3)
    assert motion.ball_speed == pytest.approx(0.9333, rel=1e-3)
    assert entrainment_speed(geometry, omega) == pytest.approx(u_a, rel=1e-12)
    assert entrainment_speed(geometry, -omega) == pytest.approx(-u_a, rel=1e-12)
    assert entrainment_speed(geometry, omega, "ball_centre") == pytest.approx(motion.ball_speed)


def test_unknown_entrainment_rule_names_the_case_key(ref_geometry):
    with pytest.raises(InputError, match=r"kinematics\.entrainment"):
        ball_motion(ref_geometry, 1.0).entrainment("screw", "mean")


def _hand_film(state, u_e: float, load: float) -> float:
    """Hamrock–Dowson (1977) central film at A of the reference screw by hand."""
    eta, alpha, e_prime = 0.06, 2.1e-8, 2 * 113.1868e9
    rx, ry = 1 / 354.507, 1 / 12.1139
    u, g, w = eta * u_e / (e_prime * rx), alpha * e_prime, load / (e_prime * rx**2)
    k = 1.0339 * (ry / rx) ** 0.636
    return rx * 2.69 * u**0.67 * g**0.53 * w**-0.067 * (1 - 0.61 * math.exp(-0.73 * k))


@pytest.mark.parametrize("rule", ["rolling", "ball_centre"])
def test_kinematics_film_at_a_uses_the_chosen_entrainment_speed(gao, rule):
    """Central film at contact A by hand at 1000 rpm: u_e = (ω_s − ω_c) r_A gives 0.271 µm;
    the wear paper's u_e = V gives 0.253 µm (−6.5 %), kept as ``kinematics.entrainment =
    "ball_centre"``."""
    case = ballscrew.case.with_overrides(gao, {"kinematics.entrainment": rule})
    run = run_kinematics(case, level=1)
    state = run.states[1]
    if rule == "rolling":
        r_a = float(np.hypot(*state.motion.screw_contact.origin[:2]))
        u_e = (case.operating.speed - state.orbital_speed) * r_a
    else:
        u_e = state.ball_speed
    nut = run.summary()["nuts"]["nut1"]
    film = nut["film_thickness_central"]["value"]
    assert film == pytest.approx(_hand_film(state, u_e, state.load_screw), rel=0.02)
    assert nut["entrainment_speed_screw"]["value"] == pytest.approx(u_e, rel=5e-3)


def test_kinematics_reports_the_film_at_the_nut_contact_b(gao):
    """B's film is reported beside A's; the nut raceway conforms (R_x larger), so it is thicker."""
    run = run_kinematics(gao, level=0)
    nut = run.summary()["nuts"]["nut1"]
    model = ball_model(gao)
    expected = model.film(run.states[1].load_nut, nut["entrainment_speed_nut"]["value"], "nut")
    assert nut["film_thickness_central_nut"]["value"] == pytest.approx(expected.central, rel=1e-3)
    assert nut["film_thickness_central_nut"]["value"] > nut["film_thickness_central"]["value"]
