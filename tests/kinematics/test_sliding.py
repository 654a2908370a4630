"""Sliding field at A, exact (E2.6) and closed form (E2.7): wear reference screw examples."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.kinematics import (
    ball_motion,
    deformed_radius,
    sliding_field,
    sliding_field_closed_form,
)

from .conftest import OMEGA

UM = 1e-6


def at(field, i=0, j=0):
    return field.along_x[i, j], field.along_y[i, j]


@pytest.mark.parametrize(
    ("flank", "x", "y", "vx", "vy"),
    [
        (1, 50, 0, 0.0, -2.268e-3),
        (1, 0, 200, -1.476e-3, -2.637e-3),
        (1, 30, -150, 1.107e-3, -2.416e-3),
        (-1, 50, 0, 0.0, -3.007e-3),
        (-1, 30, -150, -1.107e-3, -2.859e-3),
    ],
)
def test_flat_terms(ref_geometry, flank, x, y, vx, vy):
    closed = sliding_field_closed_form(
        ref_geometry, OMEGA, [x * UM], [y * UM], flank, curvature=False
    )
    exact = sliding_field(
        ball_motion(ref_geometry, OMEGA, flank), [x * UM], [y * UM], surface="plane"
    )
    for field in (closed, exact):
        gx, gy = at(field)
        assert gx == pytest.approx(vx, abs=5e-7)
        assert gy == pytest.approx(vy, rel=5e-4)


def test_t2_6_with_curvature(ref_geometry):
    r_d = deformed_radius(ref_geometry.screw_groove_radius, ref_geometry.ball_radius)
    assert r_d == pytest.approx(3.326e-3, rel=5e-4)
    motion = ball_motion(ref_geometry, OMEGA, 1)
    for (x, y), (vx, vy) in (
        ((0, 250), (-2.191e-3, -2.630e-3)),
        ((20, -250), (1.500e-3, -2.482e-3)),
    ):
        closed = sliding_field_closed_form(ref_geometry, OMEGA, [x * UM], [y * UM], 1)
        exact = sliding_field(motion, [x * UM], [y * UM], radius=r_d)
        for field in (closed, exact):
            assert at(field) == pytest.approx((vx, vy), rel=5e-4)


@pytest.mark.parametrize("flank", [1, -1])
def test_closed_form_is_exact_on_the_deformed_surface(ref_geometry, flank):
    # The rigid-body field is affine in P: E2.7 equals E2.6 on P = A + xX + yY − y²/(2R_d) e.
    x = np.linspace(-80e-6, 80e-6, 17)
    y = np.linspace(-400e-6, 400e-6, 41)
    r_d = deformed_radius(ref_geometry.screw_groove_radius, ref_geometry.ball_radius)
    exact = sliding_field(ball_motion(ref_geometry, OMEGA, flank), x, y, radius=r_d)
    closed = sliding_field_closed_form(ref_geometry, OMEGA, x, y, flank)
    scale = np.abs(exact.speed).max()
    np.testing.assert_allclose(closed.along_x, exact.along_x, atol=1e-12 * scale)
    np.testing.assert_allclose(closed.along_y, exact.along_y, atol=1e-12 * scale)


@pytest.mark.parametrize("flank", [1, -1])
def test_closed_form_equals_exact_to_first_order_on_the_ball(ref_geometry, flank):
    # On the undeformed ball sphere the flat closed form differs from E2.6 only at second order:
    # halving the patch quarters the largest difference.
    motion = ball_motion(ref_geometry, OMEGA, flank)
    errors = []
    for half in (400e-6, 200e-6, 100e-6):
        x = np.linspace(-half / 5, half / 5, 9)
        y = np.linspace(-half, half, 41)
        exact = sliding_field(motion, x, y, surface="ball")
        flat = sliding_field_closed_form(ref_geometry, OMEGA, x, y, flank, curvature=False)
        errors.append(np.hypot(exact.along_x - flat.along_x, exact.along_y - flat.along_y).max())
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.02)
    assert errors[1] / errors[2] == pytest.approx(4.0, rel=0.02)


def test_field_shape_follows_the_grid(ref_geometry):
    x, y = np.linspace(-1e-4, 1e-4, 7), np.linspace(-3e-4, 3e-4, 11)
    field = sliding_field_closed_form(ref_geometry, OMEGA, x, y)
    assert field.along_x.shape == field.speed.shape == (7, 11)
    # low speed: sliding along −Y_A everywhere near the centre (paper, Figure 4)
    assert np.all(field.along_y < 0)
