"""The spin and sliding losses of the ball contacts against their closed forms (theory manual,
*Friction*, "Why the physics torque stays below the measured torques"): the traction grid's spin
moment is the Hertz-ellipse integral of Jones (1959) / Harris & Kotzalas (2007), the nut-raceway
control of the Level-2 balance stays within the friction the nut contact can carry, and the
sliding loss at the screw contact lies between its largest kinematic slip and the sum of all."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import ellipe

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_model
from ballscrew.friction.groove_slip import heathcote_power
from ballscrew.kinematics.balance import solve_ball
from ballscrew.kinematics.motion import BallMotion, ball_motion
from ballscrew.kinematics.traction import contact_traction, hertz_pressure_grid
from ballscrew.kinematics.traction_laws import traction_weights

RPM = 2.0 * math.pi / 60.0
OMEGA = 100.0 * RPM


def _spin_moment(load: float, semi_major: float, semi_minor: float, friction: float) -> float:
    """M_s = (3/8) μ Q b E(k), k² = 1 − (a/b)²: a Hertz ellipse spinning under full slip
    (Harris & Kotzalas 2007; E = π/2 gives the circle's 3π/16 μ Q a)."""
    return 3.0 / 8.0 * friction * load * semi_major * ellipe(1.0 - (semi_minor / semi_major) ** 2)


@pytest.fixture
def model(wear_case_path):
    case = ballscrew.load_case(wear_case_path, {"operating.axial_load": 0.0})
    return ball_model(case)


def test_grid_spin_moment_is_the_hertz_ellipse_integral(model):
    """A ball carried with the screw and spinning about e_A alone slides in pure spin at A;
    the grid's moment about the normal with boundary traction is (3/8) μ Q b E(k)."""
    unit = ball_motion(model.geometry, OMEGA, 1)
    frame, axes = unit.frame, unit.screw_contact
    centre_speed = unit.screw_velocity(frame.centre)
    assert np.linalg.norm(np.cross(centre_speed, frame.t)) < 1e-12  # along the ball's helix
    spin = 5.0
    motion = BallMotion(
        OMEGA,
        float(centre_speed @ frame.t),
        OMEGA * frame.axis + spin * axes.direction,
        1,
        frame,
        axes,
        unit.nut_contact,
    )
    load, mu = 40.0, 0.1
    a, b = model.hertz_semi_axes("screw", load)
    x, y, p = hertz_pressure_grid(a, b, load, model.traction_cells)
    traction = contact_traction(
        motion,
        x,
        y,
        p,
        psi=1.0,
        film_thickness=0.0,
        viscosity=None,
        pressure_viscosity=None,
        boundary_friction=mu,
        limiting_shear=0.07,
        deformed_radius=model.deformed_radius("screw"),
    )
    expected = _spin_moment(load, b, a, mu)
    assert abs(float(traction.moment @ axes.z)) == pytest.approx(expected, rel=5e-3)
    assert np.linalg.norm(traction.force) < 1e-3 * mu * load  # a pure couple
    assert traction.power_loss == pytest.approx(expected * spin, rel=0.01)


def _capped_friction(model, psi: float) -> float:
    law = traction_weights(model, psi, OMEGA)
    return law.share * law.boundary_friction + (1.0 - law.share) * law.film_friction


def test_nut_control_stays_within_the_friction_of_the_nut_contact(model):
    """Level 2 holds B free of slip and spin by a reaction traction and pivot moment; both are
    below what B's friction can carry (μ Q_B and the spin moment of its ellipse), so the
    nut-raceway control of Jones is consistent at this low speed."""
    for flank in (1, -1):
        state = solve_ball(model, OMEGA, 1500.0, flank, 2)
        a, b = model.hertz_semi_axes("nut", state.load_nut)
        u_e = model.entrainment_speed(state.motion, "nut")
        mu = _capped_friction(model, model.sharing(state.load_nut, u_e, "nut").psi)
        assert state.traction_coefficient_nut < mu
        assert abs(state.pivot_moment_nut) < _spin_moment(state.load_nut, b, a, mu)


def test_sliding_at_the_screw_contact_lies_between_its_largest_slip_and_their_sum(model):
    """The lateral (lead-angle) slip, uniform over A, and the spin add as vectors: the loss of
    the grid lies between the larger one alone and the sum of the three closed forms (lateral
    μ Q |Δv_Y|, spin M_s |ω_sp|, Heathcote (F3b))."""
    state = solve_ball(model, OMEGA, 1500.0, 1, 2)
    axes = state.motion.screw_contact
    mu = _capped_friction(model, state.sharing.psi)
    q = state.load_screw
    a, b = model.hertz_semi_axes("screw", q)
    lateral = mu * q * abs(float(state.motion.sliding_velocity(axes.origin) @ axes.y))
    spin = _spin_moment(q, b, a, mu) * abs(state.spin_screw)
    rate = abs(float((state.motion.angular_velocity - OMEGA * state.motion.frame.axis) @ axes.y))
    heathcote = heathcote_power(q, b, model.deformed_radius("screw"), rate, mu)
    loss = state.traction_screw.power_loss
    assert max(lateral, spin) < loss < lateral + spin + heathcote


@pytest.mark.parametrize(
    ("law", "boundary", "film"), [("film", 0.1, 0.07), ("skf", 0.15, 0.05)], ids=["film", "skf"]
)
def test_reported_traction_coefficient_follows_the_regime(wear_case_path, law, boundary, film):
    """Breakaway is boundary friction, full film the film's cap, the mixed regime in between;
    the catalogue model reports none. A raceway of σ_Λ = 50 nm runs mixed at 100 rpm."""
    case = ballscrew.load_case(
        wear_case_path,
        {
            "friction.model": "ball_model",
            "friction.traction": law,
            "operating.axial_load": 0.0,
            "tcr.rms_roughness": 50e-9,
            "tcr.rms_slope": 0.05,
        },
    )
    rest, mixed, fast = (friction_torque(case, speed=w) for w in (0.0, OMEGA, 3000.0 * RPM))
    assert rest.traction_coefficient == pytest.approx(boundary)
    assert film < mixed.traction_coefficient < boundary
    # Λ = h_c/σ_Λ (E6.6) and the traction's share ψ(Λ) read the same σ: mixed at 1 < Λ < 3,
    # the film's cap in full film (Λ > 3)
    assert 1.0 < mixed.film_parameter < 3.0 < fast.film_parameter
    assert fast.traction_coefficient == pytest.approx(film, abs=0.005)
    catalogue = ballscrew.load_case(wear_case_path, {"friction.model": "catalogue"})
    assert friction_torque(catalogue, speed=OMEGA).traction_coefficient is None
