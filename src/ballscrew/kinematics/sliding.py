"""Sliding-velocity field over the ball–screw contact A, on the contact-pressure grid.

``docs/theory/kinematics.md``, sliding field: the exact rigid-body form (E2.6) for any ball motion
(Level 0, 1 or 2) and the closed form (E2.7) of the nut-controlled, centre-rolling motion. Grid
convention of :mod:`ballscrew.contact`: x along the rolling direction X_A = t (axis 0), y across the
groove along Y_A (axis 1), origin at A, arrays of shape (len(x), len(y)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry
from ballscrew.geometry.screw import flank_sign
from ballscrew.kinematics.motion import BallMotion

__all__ = [
    "SlidingField",
    "deformed_radius",
    "sliding_field",
    "sliding_field_closed_form",
]

FloatArray = NDArray[np.float64]
Surface = Literal["deformed", "plane", "ball"]


def deformed_radius(groove_radius: float, ball_radius: float) -> float:
    """Radius of the deformed contact surface across the groove, R_d = 2 r_s r_b/(r_s + r_b), m.

    Harris & Kotzalas (2006); 3.326 mm for the reference screw of
    ``examples/wear_step_stress.toml`` (f = 0.55).
    """
    return 2.0 * groove_radius * ball_radius / (groove_radius + ball_radius)


@dataclass(frozen=True)
class SlidingField:
    """Tangential sliding velocity of the ball relative to the screw over the contact grid."""

    x: FloatArray
    """Cell centres along X_A [m]."""
    y: FloatArray
    """Cell centres along Y_A [m]."""
    along_x: FloatArray
    """Δv_X(x, y) [m/s], shape (len(x), len(y))."""
    along_y: FloatArray
    """Δv_Y(x, y) [m/s]."""

    @property
    def speed(self) -> FloatArray:
        """‖Δv‖ = √(Δv_X² + Δv_Y²) [m/s]."""
        return np.hypot(self.along_x, self.along_y)


def _grid(x: ArrayLike, y: ArrayLike) -> tuple[FloatArray, FloatArray]:
    x = np.atleast_1d(np.asarray(x, dtype=float))
    y = np.atleast_1d(np.asarray(y, dtype=float))
    if x.ndim != 1 or y.ndim != 1:
        raise InputError("x, y", (x.shape, y.shape), "1-D arrays of cell centres")
    return x, y


def _normal_offset(
    surface: Surface, xx: FloatArray, yy: FloatArray, radius: float, ball_radius: float
) -> FloatArray:
    if surface == "plane":
        return np.zeros_like(xx)
    if surface == "deformed":
        return -(yy**2) / (2.0 * radius)
    if surface == "ball":
        return np.sqrt(np.maximum(ball_radius**2 - xx**2 - yy**2, 0.0)) - ball_radius
    raise InputError("surface", surface, "'deformed', 'plane' or 'ball'")


def sliding_field(
    motion: BallMotion,
    x: ArrayLike,
    y: ArrayLike,
    *,
    surface: Surface = "deformed",
    radius: float | None = None,
) -> SlidingField:
    """Exact sliding field Δv = [V t + Ω × (P − c)] − [ω_s ẑ × P + ω_s p ẑ] at A, (E2.6), m/s.

    P = A + x X_A + y Y_A + w e_A on the contact surface: ``"deformed"`` (default) the Harris
    arc w = −y²/(2R_d) across the groove (``radius`` R_d, default the screw's from
    :func:`deformed_radius` — give it, it is not derived from the motion), ``"plane"`` the
    tangent plane (w = 0), ``"ball"`` the undeformed ball sphere. Only the X_A and Y_A components
    are kept. Valid for any ``motion`` (Level 0, 1 or 2) and either flank. Vectorised over the
    grid.
    """
    x, y = _grid(x, y)
    axes = motion.screw_contact
    r_b = motion.frame.ball_radius
    if surface == "deformed" and radius is None:
        raise InputError("radius", None, "the deformed-surface radius R_d for surface='deformed'")
    xx, yy = np.meshgrid(x, y, indexing="ij")
    w = _normal_offset(surface, xx, yy, 1.0 if radius is None else float(radius), r_b)
    dv = motion.sliding_velocity(axes.point(xx, yy, w))
    return SlidingField(x=x, y=y, along_x=dv @ axes.x, along_y=dv @ axes.y)


def sliding_field_closed_form(
    geometry: ScrewGeometry,
    screw_speed: float,
    x: ArrayLike,
    y: ArrayLike,
    flank: int = 1,
    *,
    curvature: bool = True,
) -> SlidingField:
    """Closed-form sliding field at A of the nut-controlled motion, (E2.7), m/s.

        Δv_X = −s ω_s sinβ cosλ · y − k_H y²/(2R_d)
        Δv_Y = −ω_s r_b sinλ + s ω_s sinβ cosλ · x + ω_s sinλ · y²/(2R_d)
        k_H  = (ω_s/2r_b)(r_m/cosλ + r_b cosβ cosλ),   R_d = 2 r_s r_b/(r_s + r_b)

    Terms: uniform transverse drift along −Y_A, spin sliding about the contact normal, and (with
    ``curvature``) the Heathcote terms of the deformed surface. Exact for the kinematics of
    (E2.1)/(E2.4) on the surface w = −y²/(2R_d) (the rigid-body field is affine in P), and equal
    to (E2.6) on any other contact surface to first order in x, y.
    """
    x, y = _grid(x, y)
    s = flank_sign(flank)
    omega = float(screw_speed)
    lam, beta = geometry.lead_angle, geometry.contact_angle
    r_b, r_m = geometry.ball_radius, geometry.pitch_radius
    spin = s * omega * math.sin(beta) * math.cos(lam)
    xx, yy = np.meshgrid(x, y, indexing="ij")
    vx = -spin * yy
    vy = -omega * r_b * math.sin(lam) + spin * xx
    if curvature:
        r_d = deformed_radius(geometry.screw_groove_radius, r_b)
        k_h = omega / (2.0 * r_b) * (r_m / math.cos(lam) + r_b * math.cos(beta) * math.cos(lam))
        bend = yy**2 / (2.0 * r_d)
        vx = vx - k_h * bend
        vy = vy + omega * math.sin(lam) * bend
    return SlidingField(x=x, y=y, along_x=vx, along_y=vy)
