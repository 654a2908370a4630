"""Kinematics frames: orthonormal, right-handed, for both flanks and contacts (property tests)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.geometry import ScrewGeometry, contact_frame
from ballscrew.kinematics import ball_frame, contact_axes
from ballscrew.kinematics.frames import contact_vector

geometries = st.builds(
    ScrewGeometry,
    pitch_diameter=st.floats(0.01, 0.2),
    lead=st.floats(0.001, 0.05),
    ball_diameter=st.floats(0.001, 0.009),
    screw_conformity=st.floats(0.505, 0.6),
    nut_conformity=st.floats(0.505, 0.6),
    contact_angle=st.floats(0.1, 1.4),
)


@settings(max_examples=60, deadline=None)
@given(
    geometry=geometries,
    angle=st.floats(0.05, 1.5),
    flank=st.sampled_from([1, -1]),
    contact=st.sampled_from(["screw", "nut"]),
)
def test_contact_frames_are_orthonormal_and_right_handed(geometry, angle, flank, contact):
    frame = ball_frame(geometry)
    trihedron = np.stack([frame.t, frame.n, frame.b])
    np.testing.assert_allclose(trihedron @ trihedron.T, np.eye(3), atol=1e-12)
    np.testing.assert_allclose(np.cross(frame.t, frame.n), frame.b, atol=1e-12)
    lam = geometry.lead_angle
    np.testing.assert_allclose(
        math.sin(lam) * frame.t + math.cos(lam) * frame.b, frame.axis, atol=1e-12
    )
    e = contact_vector(frame, angle, flank, contact)
    axes = contact_axes(frame, e)
    r = axes.rotation
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(r) > 0.999_999_999
    np.testing.assert_allclose(np.cross(axes.x, axes.y), axes.z, atol=1e-12)
    np.testing.assert_allclose(axes.x, frame.t, atol=1e-15)  # X along the rolling direction
    np.testing.assert_allclose(axes.z, -e, atol=1e-15)  # Z from the contact into the ball
    np.testing.assert_allclose(axes.origin, frame.centre + geometry.ball_radius * e, atol=1e-15)


@settings(max_examples=30, deadline=None)
@given(geometry=geometries, flank=st.sampled_from([1, -1]))
def test_same_frames_as_the_geometry_package_at_the_nominal_angle(geometry, flank):
    frame = ball_frame(geometry)
    for contact in ("screw", "nut"):
        e = contact_vector(frame, geometry.contact_angle, flank, contact)
        mine = contact_axes(frame, e)
        theirs = contact_frame(geometry, contact, flank)
        np.testing.assert_allclose(mine.rotation, theirs.rotation, atol=1e-12)
        np.testing.assert_allclose(mine.origin, theirs.origin, atol=1e-15)


def test_document_components(ref_geometry):
    # Y_A = t × e = cosβ b − s sinβ n, Y_B = e × t, e_A = −e_B.
    frame = ball_frame(ref_geometry)
    beta = ref_geometry.contact_angle
    for s in (1, -1):
        e = math.cos(beta) * frame.n + s * math.sin(beta) * frame.b
        a = contact_axes(frame, contact_vector(frame, beta, s, "screw"))
        b = contact_axes(frame, contact_vector(frame, beta, s, "nut"))
        np.testing.assert_allclose(a.y, math.cos(beta) * frame.b - s * math.sin(beta) * frame.n)
        np.testing.assert_allclose(b.z, e)
        np.testing.assert_allclose(b.y, np.cross(e, frame.t))
