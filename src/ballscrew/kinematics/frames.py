"""Frames of the ball kinematics: Frenet frame at the ball centre and the contact frames at A, B.

``docs/theory/kinematics.md``, frames (sibling convention of Gao, Wang & Liu 2019; Wei, Lin & Horng
2009). All
vectors are in the nut frame O_W X_W Y_W Z_W (inertial: the nut translates at constant speed),
evaluated at the ball's orbital angle θ = 0, where

    c = (r_m, 0, 0),  t = (0, cosλ, sinλ),  n = (−1, 0, 0),  b = t × n = (0, −sinλ, cosλ).

Contact k (A on the screw, B on the nut) has the unit vector e_k from the ball centre to the
contact point, lying in the normal plane (n, b). Flank s = ±1 (the two nuts of a double nut):

    e_A = cosβ_A n + s sinβ_A b,     e_B = −(cosβ_B n + s sinβ_B b),

and the frame X_k = t, Z_k = −e_k (raceway normal, into the ball), Y_k = Z_k × X_k.
At β_A = β_B = β this is Y_A = t × e, Z_B = +e, Y_B = e × t.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.geometry import ScrewGeometry, frenet_frame
from ballscrew.geometry.screw import Side, flank_sign

__all__ = [
    "BallFrame",
    "ContactAxes",
    "ball_frame",
    "contact_axes",
    "contact_vector",
]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class BallFrame:
    """Ball-centre position and Frenet frame (t, n, b) at θ = 0, with the screw axis ẑ."""

    centre: FloatArray
    """c = (r_m, 0, 0) [m]."""
    t: FloatArray
    """Helix tangent, direction of ball travel relative to the nut."""
    n: FloatArray
    """Principal normal, towards the screw axis."""
    b: FloatArray
    """Binormal b = t × n."""
    axis: FloatArray
    """ẑ, the screw axis; ẑ = sinλ t + cosλ b."""
    lead_parameter: float
    """p = L/(2π), axial advance per radian [m/rad]."""
    ball_radius: float
    """r_b [m]."""


def ball_frame(geometry: ScrewGeometry) -> BallFrame:
    """The kinematics frame at θ = 0 for ``geometry``."""
    t, n, b = (np.asarray(v, dtype=float) for v in frenet_frame(geometry, 0.0))
    return BallFrame(
        centre=np.array([geometry.pitch_radius, 0.0, 0.0]),
        t=t,
        n=n,
        b=b,
        axis=np.array([0.0, 0.0, 1.0]),
        lead_parameter=geometry.helix_parameter,
        ball_radius=geometry.ball_radius,
    )


def contact_vector(frame: BallFrame, angle: float, flank: int, contact: Side) -> FloatArray:
    """Unit vector e_k from the ball centre to contact A (``"screw"``) or B (``"nut"``)."""
    s = flank_sign(flank)
    e = math.cos(angle) * frame.n + s * math.sin(angle) * frame.b
    if contact == "screw":
        return e
    if contact == "nut":
        return -e
    from ballscrew.errors import InputError

    raise InputError("contact", contact, "'screw' or 'nut'")


@dataclass(frozen=True)
class ContactAxes:
    """Contact frame at A or B: origin and the unit axes X (rolling), Y (across), Z (into ball)."""

    origin: FloatArray
    """Contact point, c + r_b e_k [m]."""
    x: FloatArray
    y: FloatArray
    z: FloatArray

    @property
    def direction(self) -> FloatArray:
        """e_k = −Z, from the ball centre to the contact point."""
        return -self.z

    @property
    def rotation(self) -> FloatArray:
        """3×3 matrix with rows X, Y, Z (global → local components)."""
        return np.stack([self.x, self.y, self.z])

    def point(self, x: ArrayLike, y: ArrayLike, w: ArrayLike = 0.0) -> FloatArray:
        """P = O + x X + y Y + w e_k for broadcast arrays x, y, w; shape (..., 3) [m]."""
        x, y, w = np.broadcast_arrays(
            np.asarray(x, dtype=float), np.asarray(y, dtype=float), np.asarray(w, dtype=float)
        )
        return (
            self.origin
            + x[..., None] * self.x
            + y[..., None] * self.y
            + w[..., None] * self.direction
        )


def contact_axes(
    frame: BallFrame, direction: ArrayLike, centre: ArrayLike | None = None
) -> ContactAxes:
    """Frame of the contact whose unit vector from the ball centre is ``direction`` (e_k).

    X = t, Z = −e_k, Y = Z × X. ``centre`` defaults to the nominal ball centre.
    """
    e = np.asarray(direction, dtype=float)
    e = e / np.linalg.norm(e)
    c = frame.centre if centre is None else np.asarray(centre, dtype=float)
    z = -e
    return ContactAxes(origin=c + frame.ball_radius * e, x=frame.t, y=np.cross(z, frame.t), z=z)
