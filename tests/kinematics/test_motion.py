"""Ball motion (E2.1)–(E2.5), inertia (E3.1)–(E3.2): worked examples of the wear reference screw."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.kinematics import ball_motion
from ballscrew.kinematics.inertia import (
    ball_inertia,
    ball_mass,
    centrifugal_force,
    gyroscopic_moment,
)

from .conftest import OMEGA


def test_t2_1_speeds(ref_geometry):
    m = ball_motion(ref_geometry, OMEGA)
    assert m.ball_speed == pytest.approx(0.09333, rel=5e-4)
    assert m.orbital_speed == pytest.approx(4.652, rel=5e-4)
    assert m.rolling_speed == pytest.approx(29.40, rel=5e-4)
    assert m.rolling_speed == pytest.approx(m.ball_speed / ref_geometry.ball_radius, rel=1e-12)


@pytest.mark.parametrize("flank", [1, -1])
def test_t2_2_angular_velocity(ref_geometry, flank):
    m = ball_motion(ref_geometry, OMEGA, flank)
    f = m.frame
    omega = m.angular_velocity
    assert omega @ f.t == pytest.approx(0.0, abs=1e-12)
    assert omega @ f.n == pytest.approx(flank * 20.79, rel=5e-4)
    assert omega @ f.b == pytest.approx(-20.79, rel=5e-4)


@pytest.mark.parametrize("flank", [1, -1])
def test_t2_3_spins_and_drift(ref_geometry, flank):
    m = ball_motion(ref_geometry, OMEGA, flank)
    e = m.screw_contact.direction
    # The document's spin about e (centre → A); ours is about Z_A = −e.
    assert (m.angular_velocity - OMEGA * m.frame.axis) @ e == pytest.approx(
        -flank * 7.382, rel=5e-4
    )
    assert m.spin_screw == pytest.approx(flank * 7.382, rel=5e-4)
    assert m.spin_nut == pytest.approx(0.0, abs=1e-12)
    drift = m.sliding_velocity(m.screw_contact.origin) @ m.screw_contact.y
    assert drift == pytest.approx(-2.637e-3, rel=5e-4)


def test_e2_3_screw_surface_velocity_components(ref_geometry):
    g = ref_geometry
    m = ball_motion(g, OMEGA, 1)
    lam, beta, r_b = g.lead_angle, g.contact_angle, g.ball_radius
    v = m.screw_velocity(m.screw_contact.origin)
    a = m.screw_contact
    assert v @ a.x == pytest.approx(
        OMEGA * (g.pitch_radius / math.cos(lam) - r_b * math.cos(beta) * math.cos(lam)), rel=1e-12
    )
    assert v @ a.y == pytest.approx(OMEGA * r_b * math.sin(lam), rel=1e-12)
    assert v @ a.z == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("flank", [1, -1])
def test_no_slip_at_b_and_rolling_at_the_centre_of_a(ref_geometry, flank):
    m = ball_motion(ref_geometry, OMEGA, flank)
    np.testing.assert_allclose(m.ball_velocity(m.nut_contact.origin), 0.0, atol=1e-15)
    slip = m.sliding_velocity(m.screw_contact.origin)
    assert slip @ m.screw_contact.x == pytest.approx(0.0, abs=1e-15)
    assert np.linalg.norm(m.ball_velocity(m.screw_contact.origin)) == pytest.approx(
        2 * m.ball_speed
    )


def test_t2_7_transverse_sliding_distance_per_revolution(ref_geometry):
    m = ball_motion(ref_geometry, OMEGA)
    drift = -m.sliding_velocity(m.screw_contact.origin) @ m.screw_contact.y
    assert drift * 2 * math.pi / OMEGA == pytest.approx(1.582e-3, rel=5e-4)


def test_standstill_and_bad_speed(ref_geometry):
    m = ball_motion(ref_geometry, 0.0)
    assert m.ball_speed == 0.0 and m.spin_screw == 0.0
    with pytest.raises(InputError, match="speed"):
        ball_motion(ref_geometry, -1.0)


def test_t3_1_ball_mass_and_inertia():
    assert ball_mass(6.35e-3, 7850.0) == pytest.approx(1.0524e-3, rel=5e-5)
    assert ball_inertia(6.35e-3, 7850.0) == pytest.approx(4.2436e-9, rel=5e-5)


@pytest.mark.parametrize(
    ("omega", "f_c", "m_g"),
    [(OMEGA, 4.555e-4, 4.116e-7), (314.16, 0.4100, 3.705e-4)],
)
def test_inertia_forces(ref_geometry, omega, f_c, m_g):
    m = ball_motion(ref_geometry, omega)
    mass, inertia = ball_mass(6.35e-3, 7850.0), ball_inertia(6.35e-3, 7850.0)
    assert centrifugal_force(mass, ref_geometry.pitch_radius, m.orbital_speed) == pytest.approx(
        f_c, rel=5e-4
    )
    moment = gyroscopic_moment(inertia, m.orbital_speed, m.frame.axis, m.angular_velocity)
    assert np.linalg.norm(moment) == pytest.approx(m_g, rel=5e-4)
    if omega == OMEGA:  # E3.2: t-component s J ω_B ω_c cosλ sinβ = 4.090e-7 N m
        assert moment @ m.frame.t == pytest.approx(4.090e-7, rel=5e-4)


def test_t3_3_speeds_at_3000_rpm(ref_geometry):
    m = ball_motion(ref_geometry, 314.16)
    assert m.ball_speed == pytest.approx(2.800, rel=5e-4)
    assert m.orbital_speed == pytest.approx(139.56, rel=5e-4)
    assert m.rolling_speed == pytest.approx(881.9, rel=5e-4)
