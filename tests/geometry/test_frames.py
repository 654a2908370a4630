"""Helix and Frenet frame (G1)–(G7), contact points (G8), raceways (G9)–(G11), contact frames
(G13)/(G14)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.errors import InputError
from ballscrew.geometry import (
    ScrewGeometry,
    contact_direction,
    contact_frame,
    contact_point,
    frenet_frame,
    frenet_matrix,
    groove_profile,
    helix_point,
    raceway_surface,
)

REFERENCE = ScrewGeometry(40.0e-3, 10.0e-3, 6.35e-3, 0.52, 0.52, math.radians(45.0))
SIDES = ("screw", "nut")
FLANKS = (1, -1)

angles = st.floats(-20.0, 20.0)
leads = st.floats(1.0e-3, 60.0e-3)
contact_angles = st.floats(math.radians(5.0), math.radians(85.0))


def geometry(lead: float = 10.0e-3, beta: float = math.radians(45.0)) -> ScrewGeometry:
    return ScrewGeometry(40.0e-3, lead, 6.35e-3, 0.52, 0.54, beta)


def assert_rotation(matrix: np.ndarray) -> None:
    """Rows orthonormal and right-handed (row 0 × row 1 = row 2)."""
    np.testing.assert_allclose(matrix @ matrix.T, np.eye(3), atol=1e-14)
    np.testing.assert_allclose(np.cross(matrix[0], matrix[1]), matrix[2], atol=1e-14)


@settings(max_examples=40, deadline=None)
@given(theta=angles, lead=leads)
def test_frenet_frame_orthonormal_right_handed(theta: float, lead: float) -> None:
    assert_rotation(frenet_matrix(geometry(lead), theta))


@settings(max_examples=25, deadline=None)
@given(theta=angles, lead=leads)
def test_frenet_serret_equations_by_finite_differences(theta: float, lead: float) -> None:
    """(G3) t = C'/|C'| and (G7) dt/ds = κ n, dn/ds = −κ t + τ b, db/ds = −τ n (κ, τ from (G6))."""
    g = geometry(lead)
    r_m, p_h = 20.0e-3, lead / (2.0 * math.pi)
    speed = math.hypot(r_m, p_h)
    kappa, tau = r_m / speed**2, p_h / speed**2
    eps = 1e-5
    t, n, b = frenet_frame(g, theta)
    (t_p, n_p, b_p), (t_m, n_m, b_m) = frenet_frame(g, theta + eps), frenet_frame(g, theta - eps)
    derivative = (helix_point(g, theta + eps) - helix_point(g, theta - eps)) / (2 * eps)
    np.testing.assert_allclose(derivative / speed, t, atol=1e-9)
    np.testing.assert_allclose((t_p - t_m) / (2 * eps * speed), kappa * n, atol=1e-7 * kappa)
    np.testing.assert_allclose(
        (n_p - n_m) / (2 * eps * speed), -kappa * t + tau * b, atol=1e-7 * kappa
    )
    np.testing.assert_allclose((b_p - b_m) / (2 * eps * speed), -tau * n, atol=1e-7 * kappa)
    np.testing.assert_allclose(n[:2], -np.array([math.cos(theta), math.sin(theta)]), atol=1e-15)


def test_frenet_vectorised_shapes() -> None:
    theta = np.linspace(0.0, 1.0, 12).reshape(3, 4)
    assert helix_point(REFERENCE, theta).shape == (3, 4, 3)
    assert frenet_matrix(REFERENCE, theta).shape == (3, 4, 3, 3)
    assert contact_frame(REFERENCE, "nut", theta=theta).rotation.shape == (3, 4, 3, 3)


def test_g8_contact_points_on_g12_helices() -> None:
    """|A_xy| = r_A, |B_xy| = r_B at any θ; A and B advance one lead per turn."""
    theta = np.linspace(-3.0, 3.0, 7)
    a = contact_point(REFERENCE, "screw", theta=theta)
    b = contact_point(REFERENCE, "nut", theta=theta)
    np.testing.assert_allclose(np.hypot(a[:, 0], a[:, 1]), 17.75583e-3, rtol=1e-6)
    np.testing.assert_allclose(np.hypot(b[:, 0], b[:, 1]), 22.24578e-3, rtol=1e-6)
    turn = contact_point(REFERENCE, "screw", theta=theta + 2 * math.pi) - a
    np.testing.assert_allclose(turn, np.broadcast_to([0, 0, 10.0e-3], turn.shape), atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm(a - b, axis=-1), 6.35e-3, rtol=1e-14)
    # Axial component of the contact normal is s·sinβ·cosα (G8).
    e_a = contact_direction(REFERENCE, theta, flank=-1)
    np.testing.assert_allclose(e_a[:, 2], -math.sin(math.pi / 4) * math.cos(REFERENCE.lead_angle))


@pytest.mark.parametrize("side", SIDES)
@pytest.mark.parametrize("flank", FLANKS)
def test_groove_profile_passes_through_contact_point(side: str, flank: int) -> None:
    theta = 0.7
    point = raceway_surface(REFERENCE, side, theta, REFERENCE.contact_angle, flank)
    np.testing.assert_allclose(
        point, contact_point(REFERENCE, side, flank, theta=theta), atol=1e-16
    )
    # The arc has radius r_g about a centre on the load line, (r_g − r_b) behind the ball centre.
    phi = np.linspace(0.2, 1.3, 5)
    profile = groove_profile(REFERENCE, side, phi, flank)
    sign = 1 if side == "screw" else -1
    e_a = np.array([0.0, math.cos(math.pi / 4), flank * math.sin(math.pi / 4)])
    centre = -sign * (3.302e-3 - 3.175e-3) * e_a
    np.testing.assert_allclose(np.linalg.norm(profile - centre, axis=-1), 3.302e-3, rtol=1e-13)


@settings(max_examples=40, deadline=None)
@given(beta=contact_angles, lead=leads, theta=angles)
def test_contact_frames_match_g13_g14(beta: float, lead: float, theta: float) -> None:
    g = geometry(lead, beta)
    frenet = frenet_matrix(g, theta)
    for side in SIDES:
        sign = 1 if side == "screw" else -1
        for s in FLANKS:
            frame = contact_frame(g, side, s, theta=theta)
            assert_rotation(frame.rotation)
            expected_tnb = sign * np.array(
                [
                    [sign, 0.0, 0.0],
                    [0.0, -s * math.sin(beta), math.cos(beta)],
                    [0.0, -math.cos(beta), -s * math.sin(beta)],
                ]
            )
            np.testing.assert_allclose(frame.rotation @ frenet.T, expected_tnb, atol=1e-14)
            # ẑ points from the contact point into the ball: the ball centre is O + r_b ẑ.
            np.testing.assert_allclose(
                frame.origin + g.ball_radius * frame.rotation[2],
                helix_point(g, theta),
                atol=1e-15,
            )


@settings(max_examples=30, deadline=None)
@given(beta=contact_angles, lead=leads, theta=angles)
def test_z_axis_is_surface_normal(beta: float, lead: float, theta: float) -> None:
    """∂S/∂θ and ∂S/∂φ of (G11) at the contact point are ⊥ ẑ; x̂ = t is tangent (G13)."""
    g = geometry(lead, beta)
    eps = 1e-6
    for side in SIDES:
        for s in FLANKS:
            z_axis = contact_frame(g, side, s, theta=theta).rotation[2]
            d_theta = raceway_surface(g, side, theta + eps, beta, s) - raceway_surface(
                g, side, theta - eps, beta, s
            )
            d_phi = raceway_surface(g, side, theta, beta + eps, s) - raceway_surface(
                g, side, theta, beta - eps, s
            )
            for tangent in (d_theta, d_phi):
                assert abs(tangent @ z_axis) <= 1e-8 * np.linalg.norm(tangent)
            # ∂S/∂θ = σ[(1 ∓ κ r_b cosβ) t + …]: its t component.
            t = frenet_frame(g, theta)[0]
            stretch = 1.0 - (1 if side == "screw" else -1) * g.curvature * g.ball_radius * math.cos(
                beta
            )
            assert d_theta @ t / (2 * eps) == pytest.approx(g.helix_speed * stretch, rel=1e-8)


def test_to_local_maps_origin_and_ball_centre() -> None:
    frame = contact_frame(REFERENCE, "screw", theta=1.1)
    np.testing.assert_allclose(frame.to_local(frame.origin), 0.0, atol=1e-18)
    centre = frame.to_local(helix_point(REFERENCE, 1.1))
    np.testing.assert_allclose(centre, [0.0, 0.0, REFERENCE.ball_radius], atol=1e-17)


@pytest.mark.parametrize(("side", "flank"), [("ball", 1), ("screw", 0), ("nut", 2), ("nut", True)])
def test_bad_side_or_flank(side: str, flank: int) -> None:
    with pytest.raises(InputError) as info:
        contact_frame(REFERENCE, side, flank)
    assert info.value.field in ("side", "flank")
