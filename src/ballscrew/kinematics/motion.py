"""Rigid-body motion of a ball: nut-raceway control, rolling closure, spins and orbital speed.

``docs/theory/kinematics.md``, ball motion (E2.1)–(E2.5): in the nut frame the screw performs a
screw motion (ω_s about ẑ, p ω_s along ẑ, p = L/2π) and the nut is at rest. The ball neither spins
nor slips at the nut contact B ("raceway control", Jones; Lin, Ravani & Velinsky 1994; Wei, Lin &
Horng 2009), and rolls without slip along t at the centre of the screw contact A (the closure E2.4).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry
from ballscrew.geometry.screw import Side, flank_sign
from ballscrew.kinematics.frames import (
    BallFrame,
    ContactAxes,
    ball_frame,
    contact_axes,
    contact_vector,
)

__all__ = [
    "ENTRAINMENT_RULES",
    "BallMotion",
    "ball_motion",
    "entrainment_speed",
    "nut_controlled_spin_vector",
    "rolling_ball_speed",
    "screw_velocity",
]

FloatArray = NDArray[np.float64]

ENTRAINMENT_RULES = {
    "rolling": "the rolling speed of the surfaces past each contact (BallMotion.entrainment_speed)",
    "ball_centre": "the ball-centre speed V at both contacts (the wear paper's simplification, "
    "smaller by about 1 + γ, γ = D cosβ/d_m)",
}
"""Entrainment speed of the EHL film, load sharing, traction and rolling resistance (E2.8)."""


def screw_velocity(frame: BallFrame, screw_speed: float, points: ArrayLike) -> FloatArray:
    """Velocity of screw material at ``points`` in the nut frame, ω_s(ẑ × P + p ẑ), (E2.3), m/s.

    ``points`` (..., 3) are measured from the origin on the screw axis.
    """
    p = np.asarray(points, dtype=float)
    return screw_speed * (np.cross(frame.axis, p) + frame.lead_parameter * frame.axis)


def nut_controlled_spin_vector(
    frame: BallFrame, ball_speed: float, nut_direction: ArrayLike
) -> FloatArray:
    """Ball angular velocity with no slip and no spin at B, Ω = (V/r_b) t × e_B, (E2.1), rad/s.

    From v_c + Ω × (r_b e_B) = 0 and Ω·e_B = 0. With e_B = −e this is Ω = −(V/r_b) Y_A,
    i.e. (V/r_b)(s sinβ n − cosβ b): the reference screw gives Ω_n = +20.79, Ω_b = −20.79 rad/s
    at 100 rpm.
    """
    e_b = np.asarray(nut_direction, dtype=float)
    return (ball_speed / frame.ball_radius) * np.cross(frame.t, e_b)


def rolling_ball_speed(
    frame: BallFrame, screw_speed: float, screw_direction: ArrayLike, nut_direction: ArrayLike
) -> float:
    """Ball-centre speed V from pure rolling along t at the centre of A, (E2.4), m/s.

    With Ω from (E2.1) the ball surface at A moves at V(1 − e_A·e_B) t, so
    V = v_s(A)·t / (1 − e_A·e_B). At e_A = −e_B = e this is the closed form
    V = (ω_s/2)(r_m/cosλ − r_b cosβ cosλ): 0.09333 m/s at 100 rpm for the reference screw of
    ``examples/wear_step_stress.toml``.
    """
    e_a = np.asarray(screw_direction, dtype=float)
    e_b = np.asarray(nut_direction, dtype=float)
    a = frame.centre + frame.ball_radius * e_a
    return float(screw_velocity(frame, screw_speed, a) @ frame.t / (1.0 - e_a @ e_b))


@dataclass(frozen=True)
class BallMotion:
    """Steady motion of one ball relative to the nut (the nut frame is inertial)."""

    screw_speed: float
    """ω_s, screw angular speed about +ẑ [rad/s]."""
    ball_speed: float
    """V, speed of the ball centre relative to the nut, along t [m/s]."""
    angular_velocity: FloatArray
    """Ω, ball angular velocity [rad/s] (global components)."""
    flank: int
    """s = ±1."""
    frame: BallFrame
    screw_contact: ContactAxes
    """Frame at A (X_A = t, Z_A = −e_A into the ball)."""
    nut_contact: ContactAxes
    """Frame at B (X_B = t, Z_B = −e_B into the ball)."""

    @property
    def orbital_speed(self) -> float:
        """ω_c = V cosλ / r_m, angular speed of the ball centre about the screw axis [rad/s].

        At the E2.4 closure ω_c = (ω_s/2)(1 − r_b cosβ cos²λ/r_m): 4.652 rad/s, reference screw.
        """
        radius = float(np.hypot(*self.frame.centre[:2]))
        return self.ball_speed * math.cos(self.lead_angle) / radius

    @property
    def lead_angle(self) -> float:
        """λ of the ball-centre helix [rad]."""
        return math.asin(float(self.frame.t @ self.frame.axis))

    @property
    def rolling_speed(self) -> float:
        """|Ω| [rad/s]; V/r_b at the nut-controlled motion (29.40 rad/s, reference screw)."""
        return float(np.linalg.norm(self.angular_velocity))

    @property
    def spin_screw(self) -> float:
        """Spin of the ball relative to the screw about Z_A, (Ω − ω_s ẑ)·Z_A, (E2.5), rad/s.

        s ω_s sinβ cosλ at Level 0: +7.382 rad/s for s = +1 at 100 rpm (the same spin
        written about e = −Z_A is (Ω − ω_s ẑ)·e = −7.382).
        """
        relative = self.angular_velocity - self.screw_speed * self.frame.axis
        return float(relative @ self.screw_contact.z)

    @property
    def spin_nut(self) -> float:
        """Spin of the ball relative to the nut about Z_B, Ω·Z_B (0 by nut-raceway control)."""
        return float(self.angular_velocity @ self.nut_contact.z)

    def ball_velocity(self, points: ArrayLike) -> FloatArray:
        """Velocity of ball material at ``points``, V t + Ω × (P − c), m/s."""
        p = np.asarray(points, dtype=float)
        return self.ball_speed * self.frame.t + np.cross(
            self.angular_velocity, p - self.frame.centre
        )

    def screw_velocity(self, points: ArrayLike) -> FloatArray:
        """Velocity of screw material at ``points``, ω_s(ẑ × P + p ẑ), (E2.3), m/s."""
        return screw_velocity(self.frame, self.screw_speed, points)

    def entrainment_speed(self, contact: Side = "screw") -> float:
        """Rolling (entrainment) speed u_e of contact A (``"screw"``) or B (``"nut"``), (E2.8), m/s.

        The contact point moves with the ball centre's helical frame, v_P = ω_c(ẑ × P + p ẑ);
        the two surfaces pass it at their mean velocity relative to it, projected on the rolling
        direction X = t: u_e = |(½(v_ball(P) + v_race(P)) − v_P)·t|, v_race = v_screw at A and
        0 at B (Harris & Kotzalas 2007, the rolling speed of a ball bearing's contacts). At
        Level 0 it is (ω_s − ω_c) r_A at A and ω_c r_B at B, ≈ V(1 + γ) with γ = D cosβ/d_m,
        not the ball-centre speed V: ≈ 1.04 m/s against V = 0.933 m/s at A at 1000 rpm for the
        reference screw (1.0374 m/s with its lead).
        """
        axes = self.screw_contact if contact == "screw" else self.nut_contact
        point = axes.origin
        race = self.screw_velocity(point) if contact == "screw" else np.zeros(3)
        frame = screw_velocity(self.frame, self.orbital_speed, point)
        mean = 0.5 * (self.ball_velocity(point) + race) - frame
        return abs(float(mean @ self.frame.t))

    def entrainment(self, contact: Side = "screw", rule: str = "rolling") -> float:
        """u_e of ``contact`` by ``rule`` of :data:`ENTRAINMENT_RULES`, m/s."""
        if rule not in ENTRAINMENT_RULES:
            raise InputError("kinematics.entrainment", rule, f"one of {list(ENTRAINMENT_RULES)}")
        if rule == "ball_centre":
            return abs(self.ball_speed)
        return self.entrainment_speed(contact)

    def sliding_velocity(self, points: ArrayLike) -> FloatArray:
        """Δv(P) = v_ball(P) − v_screw(P), ball relative to screw, (E2.6), m/s (3 components)."""
        return self.ball_velocity(points) - self.screw_velocity(points)


def ball_motion(
    geometry: ScrewGeometry,
    screw_speed: float,
    flank: int = 1,
    *,
    angle_screw: float | None = None,
    angle_nut: float | None = None,
    ball_speed: float | None = None,
) -> BallMotion:
    """Ball motion for screw speed ω_s: nut control (E2.1) and, by default, the closure (E2.4).

    ``angle_screw`` β_A and ``angle_nut`` β_B default to the nominal contact angle (Level 0);
    the quasi-static balance passes its own. ``ball_speed`` V overrides the rolling closure
    (Level 2 solves for it). ``screw_speed`` ≥ 0 rad/s.
    """
    omega = float(screw_speed)
    if not (math.isfinite(omega) and omega >= 0.0):
        raise InputError("speed", screw_speed, "a screw speed >= 0 rad/s")
    s = flank_sign(flank)
    frame = ball_frame(geometry)
    beta = geometry.contact_angle
    e_a = contact_vector(frame, beta if angle_screw is None else angle_screw, s, "screw")
    e_b = contact_vector(frame, beta if angle_nut is None else angle_nut, s, "nut")
    v = rolling_ball_speed(frame, omega, e_a, e_b) if ball_speed is None else float(ball_speed)
    return BallMotion(
        screw_speed=omega,
        ball_speed=v,
        angular_velocity=nut_controlled_spin_vector(frame, v, e_b),
        flank=s,
        frame=frame,
        screw_contact=contact_axes(frame, e_a),
        nut_contact=contact_axes(frame, e_b),
    )


def entrainment_speed(
    geometry: ScrewGeometry, screw_speed: float, rule: str = "rolling", contact: Side = "screw"
) -> float:
    """Entrainment speed u_e of ``contact`` at the Level-0 motion (E2.4), (E2.8), m/s, signed
    as ω_s.

    ``rule`` ``"rolling"``: the rolling speed of the surfaces past the contact
    (:meth:`BallMotion.entrainment_speed`; REF 100 rpm: 0.1037); ``"ball_centre"``: the
    ball-centre speed V = (ω_s/2)(r_m/cosλ − r_b cosβ cosλ) (0.09333).
    """
    return math.copysign(_level0_speed(geometry, abs(screw_speed), rule, contact), screw_speed)


@functools.lru_cache(maxsize=256)
def _level0_speed(geometry: ScrewGeometry, speed: float, rule: str, contact: Side) -> float:
    """|u_e| of :func:`entrainment_speed`, cached: every contact of every wear step asks it
    again for the same screw and speed, and a Level-0 motion costs ~0.4 ms."""
    return ball_motion(geometry, speed).entrainment(contact, rule)
