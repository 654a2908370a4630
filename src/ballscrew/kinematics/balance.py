"""Quasi-static force and moment balance of a working ball, Levels 0, 1 and 2.

``docs/theory/kinematics.md``, quasi-static balance (E3.1)–(E3.6) (structure of Wei & Lin 2003 and
Wei, Lin & Horng 2009; groove geometry of Jones 1960 / Harris & Kotzalas 2006):

* Level 0 — static load, Q_A = Q_B = F/(Z sinβ₀ cosλ), β_A = β_B = β₀ (Q1), kinematics E2.1/E2.4.
* Level 1 — centrifugal force with the groove geometry (E3.5): unknowns (c_n, c_b, u), the
  ball-centre offset in the normal plane and the nut's axial displacement; equations the ball's
  force balance in n and b and the nut's equilibrium Z Q_B (e_B·ẑ)(−s) = F. V from E2.4 with
  the solved contact vectors.
* Level 2 — full balance (E3.6): unknowns X = [c_n, c_b, u, V, F_TB,X, F_TB,Y, M_B,Z]; the
  traction at A from the sliding field (E3.3) on the Hertz pressure grid with the JGP asperity
  share (E6.4), EHL rolling resistance at A and B (E3.4), centrifugal force and gyroscopic moment
  (E3.1–E3.2); the reaction traction and pivot moment at B hold no slip and no spin there.
  Equations E3.1 (3) + E3.2 (3) + nut equilibrium (1), solved by Newton–Raphson.

The ball-centre offset (µm) enters the contact geometry and loads; velocities are taken at the
nominal ball centre on the helix (relative error ~offset/r_m). The hydrodynamic rolling force is
applied at the ball centre: it is the resultant of the inlet pressure, which is normal to the
sphere and so passes through its centre (the document says "acts at the contact"; the line of
action changes only which traction carries the moment).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError
from ballscrew.geometry.screw import flank_sign
from ballscrew.kinematics.frames import contact_axes
from ballscrew.kinematics.groove import GrooveContacts, groove_contacts
from ballscrew.kinematics.inertia import centrifugal_force, gyroscopic_moment
from ballscrew.kinematics.model import BallModel
from ballscrew.kinematics.motion import (
    BallMotion,
    ball_motion,
    nut_controlled_spin_vector,
    rolling_ball_speed,
)
from ballscrew.kinematics.newton import newton_solve
from ballscrew.kinematics.traction import ContactTraction, contact_traction, hertz_pressure_grid
from ballscrew.kinematics.traction_laws import traction_weights
from ballscrew.loads import ball_load
from ballscrew.lubrication import LoadSharing

__all__ = ["LEVELS", "BallState", "full_balance", "groove_balance", "solve_ball", "static_balance"]

FloatArray = NDArray[np.float64]
LEVELS = (0, 1, 2)
_ZERO = np.zeros(3)


@dataclass(frozen=True)
class BallState:
    """Solved state of one ball of one nut at one screw speed."""

    level: int
    """Balance level 0, 1 or 2."""
    flank: int
    """s = ±1 (nut 1: +1, nut 2: −1)."""
    nut_force: float
    """Axial force of the nut [N]."""
    motion: BallMotion
    load_screw: float
    """Q_A [N]."""
    load_nut: float
    """Q_B [N]."""
    angle_screw: float
    """β_A [rad]."""
    angle_nut: float
    """β_B [rad]."""
    centre_offset: tuple[float, float] = (0.0, 0.0)
    """Ball-centre displacement (along n, along b) [m]."""
    nut_displacement: float = 0.0
    """Axial displacement u of the nut in the groove model [m]."""
    centrifugal_force: float = 0.0
    """F_c [N], outward."""
    gyroscopic_moment: FloatArray = field(default_factory=lambda: _ZERO.copy())
    """M_g on the ball [N m]."""
    traction_screw: ContactTraction | None = None
    """Traction resultants at A (Level 2)."""
    traction_nut: FloatArray = field(default_factory=lambda: _ZERO.copy())
    """Reaction traction at B on the ball [N] (Level 2)."""
    pivot_moment_nut: float = 0.0
    """Reaction moment about Z_B holding no spin at B [N m] (Level 2)."""
    rolling_resistance_screw: FloatArray = field(default_factory=lambda: _ZERO.copy())
    """EHL rolling force of the A film on the ball [N] (Level 2)."""
    rolling_resistance_nut: FloatArray = field(default_factory=lambda: _ZERO.copy())
    """EHL rolling force of the B film on the ball [N] (Level 2)."""
    sharing: LoadSharing | None = None
    """JGP load sharing at A (Level 2)."""
    iterations: int = 0
    """Newton iterations (0 for Level 0)."""
    residual: float = 0.0
    """Final scaled residual."""

    @property
    def screw_speed(self) -> float:
        """ω_s [rad/s]."""
        return self.motion.screw_speed

    @property
    def ball_speed(self) -> float:
        """V, ball-centre speed relative to the nut [m/s]."""
        return self.motion.ball_speed

    @property
    def orbital_speed(self) -> float:
        """ω_c [rad/s]."""
        return self.motion.orbital_speed

    @property
    def spin_screw(self) -> float:
        """Spin relative to the screw about Z_A [rad/s]."""
        return self.motion.spin_screw

    @property
    def spin_nut(self) -> float:
        """Spin relative to the nut about Z_B [rad/s]."""
        return self.motion.spin_nut

    @property
    def traction_coefficient_nut(self) -> float:
        """|F_TB|/Q_B: the friction coefficient the no-slip assumption at B needs (Level 2)."""
        return float(np.linalg.norm(self.traction_nut)) / self.load_nut if self.load_nut else 0.0


def _check(speed: float, nut_force: float) -> tuple[float, float]:
    omega, force = float(speed), float(nut_force)
    if not (math.isfinite(omega) and omega >= 0.0):
        raise InputError("speed", speed, "a screw speed >= 0 rad/s")
    if not (math.isfinite(force) and force >= 0.0):
        raise InputError("nut_force", nut_force, "an axial nut force >= 0 N")
    return omega, force


def static_balance(model: BallModel, speed: float, nut_force: float, flank: int = 1) -> BallState:
    """Level 0: Q_A = Q_B = F/(Z sinβ₀ cosλ), β_A = β_B = β₀, kinematics E2.1/E2.4."""
    omega, force = _check(speed, nut_force)
    g = model.geometry
    q = float(ball_load(force, model.balls, g.contact_angle, g.lead_angle))
    motion = ball_motion(g, omega, flank)
    return BallState(0, flank_sign(flank), force, motion, q, q, g.contact_angle, g.contact_angle)


def _initial_groove(model: BallModel, force: float, flank: int) -> FloatArray:
    """Level-0 start: c = c₀ + δ_A e₀, u = (δ_A + δ_B)/(sinβ cosλ) (E1.7)."""
    g = model.geometry
    q = float(ball_load(force, model.balls, g.contact_angle, g.lead_angle))
    d_a = model.hertz_constant("screw") * q ** (2.0 / 3.0)
    d_b = model.hertz_constant("nut") * q ** (2.0 / 3.0)
    beta = g.contact_angle
    return np.array(
        [
            d_a * math.cos(beta),
            flank * d_a * math.sin(beta),
            (d_a + d_b) / (math.sin(beta) * math.cos(g.lead_angle)),
        ]
    )


def _contacts(model: BallModel, flank: int, x: FloatArray) -> GrooveContacts:
    return groove_contacts(
        model.geometry,
        model.frame,
        flank,
        (float(x[0]), float(x[1])),
        float(x[2]),
        model.hertz_constant("screw"),
        model.hertz_constant("nut"),
    )


def _nut_axial(model: BallModel, flank: int, force_on_nut: FloatArray) -> float:
    """Axial force of one ball on the nut, counted positive in the loading direction (−s ẑ)."""
    return -flank * float(force_on_nut @ model.frame.axis)


def groove_balance(model: BallModel, speed: float, nut_force: float, flank: int = 1) -> BallState:
    """Level 1: centrifugal force and groove geometry (E3.5); Newton–Raphson on (c_n, c_b, u)."""
    omega, force = _check(speed, nut_force)
    s = flank_sign(flank)
    if force == 0.0:
        return static_balance(model, omega, 0.0, s)
    frame, g = model.frame, model.geometry
    scale_force = float(ball_load(force, model.balls, g.contact_angle, g.lead_angle))

    def orbital(c: GrooveContacts) -> tuple[float, float]:
        v = rolling_ball_speed(frame, omega, c.direction_screw, c.direction_nut)
        w_c = v * math.cos(g.lead_angle) / g.pitch_radius
        return v, centrifugal_force(model.mass, g.pitch_radius, w_c)

    def residual(x: FloatArray) -> FloatArray:
        c = _contacts(model, s, x)
        _, f_c = orbital(c)
        total = -c.load_screw * c.direction_screw - c.load_nut * c.direction_nut - f_c * frame.n
        nut = model.balls * _nut_axial(model, s, c.load_nut * c.direction_nut)
        return np.array(
            [total @ frame.n / scale_force, total @ frame.b / scale_force, nut / force - 1.0]
        )

    x0 = _initial_groove(model, force, s)
    result = newton_solve(
        residual, x0, np.full(3, abs(x0[2])), solver="Level-1 ball balance (E3.5)"
    )
    c = _contacts(model, s, result.x)
    v, f_c = orbital(c)
    motion = ball_motion(
        g, omega, s, angle_screw=c.angle_screw, angle_nut=c.angle_nut, ball_speed=v
    )
    return BallState(
        level=1,
        flank=s,
        nut_force=force,
        motion=motion,
        load_screw=c.load_screw,
        load_nut=c.load_nut,
        angle_screw=c.angle_screw,
        angle_nut=c.angle_nut,
        centre_offset=(float(result.x[0]), float(result.x[1])),
        nut_displacement=float(result.x[2]),
        centrifugal_force=f_c,
        iterations=result.iterations,
        residual=result.residual,
    )


@dataclass(frozen=True)
class _Forces:
    """Every force and moment on the ball for one Level-2 trial vector."""

    contacts: GrooveContacts
    motion: BallMotion
    traction: ContactTraction
    sharing: LoadSharing
    rolling_screw: FloatArray
    rolling_nut: FloatArray
    centrifugal: float
    gyroscopic: FloatArray
    traction_nut: FloatArray
    pivot_nut: float


def _level2_forces(model: BallModel, omega: float, s: int, x: FloatArray, dynamic: bool) -> _Forces:
    frame, g = model.frame, model.geometry
    c = _contacts(model, s, x)
    v = float(x[3])
    spin = nut_controlled_spin_vector(frame, v, c.direction_nut)
    motion = BallMotion(
        screw_speed=omega,
        ball_speed=v,
        angular_velocity=spin,
        flank=s,
        frame=frame,
        screw_contact=contact_axes(frame, c.direction_screw),
        nut_contact=contact_axes(frame, c.direction_nut),
    )
    u_a = model.entrainment_speed(motion, "screw") if dynamic else 0.0
    u_b = model.entrainment_speed(motion, "nut") if dynamic else 0.0
    q_a = c.load_screw
    sharing = model.sharing(q_a, u_a) if q_a > 0 else LoadSharing(1.0, 0.0, 0.0, None)
    if q_a > 0:
        a, b = model.hertz_semi_axes("screw", q_a)
        gx, gy, p = hertz_pressure_grid(a, b, q_a, model.traction_cells)
        law = traction_weights(model, sharing.psi, omega if dynamic else 0.0)
        traction = contact_traction(
            motion,
            gx,
            gy,
            p,
            psi=law.share,
            film_thickness=sharing.separation,
            viscosity=model.viscosity if dynamic else None,
            pressure_viscosity=model.pressure_viscosity,
            boundary_friction=law.boundary_friction,
            limiting_shear=law.film_friction,
            deformed_radius=model.deformed_radius("screw"),
        )
    else:
        traction = ContactTraction(_ZERO.copy(), _ZERO.copy(), 0.0, 0.0)
    # Rolling resistance on the ball, through its centre, against its motion over each raceway.
    relative_screw = v - float(motion.screw_velocity(frame.centre) @ frame.t)
    f_ra = -math.copysign(model.rolling_resistance(q_a, u_a, "screw"), relative_screw) * frame.t
    f_rb = -math.copysign(model.rolling_resistance(c.load_nut, u_b, "nut"), v) * frame.t
    w_c = v * math.cos(g.lead_angle) / g.pitch_radius
    f_c = centrifugal_force(model.mass, g.pitch_radius, w_c) if dynamic else 0.0
    m_g = gyroscopic_moment(model.inertia, w_c, frame.axis, spin) if dynamic else _ZERO.copy()
    nut_axes = motion.nut_contact
    return _Forces(
        contacts=c,
        motion=motion,
        traction=traction,
        sharing=sharing,
        rolling_screw=f_ra,
        rolling_nut=f_rb,
        centrifugal=f_c,
        gyroscopic=m_g,
        traction_nut=float(x[4]) * nut_axes.x + float(x[5]) * nut_axes.y,
        pivot_nut=float(x[6]),
    )


def full_balance(model: BallModel, speed: float, nut_force: float, flank: int = 1) -> BallState:
    """Level 2: full quasi-static balance (E3.1)–(E3.6) by Newton–Raphson.

    Needs lubricant data (η₀, α_p). At ω_s = 0 the state is the limit ω_s → 0⁺: dry contact
    (ψ = 1), no inertia or rolling resistance, traction directions of the slowly turning screw,
    and zero velocities.
    """
    omega, force = _check(speed, nut_force)
    s = flank_sign(flank)
    if not model.lubricated:
        raise InputError(
            "medium.viscosity",
            model.viscosity,
            "lubricant data (viscosity and pressure_viscosity in [medium], or [kinematics] "
            "lubricant) for a level-2 ball balance",
        )
    if force == 0.0:
        return static_balance(model, omega, 0.0, s)
    level1 = groove_balance(model, omega, force, s)
    dynamic = omega > 0.0
    w_eval = omega if dynamic else 1.0
    frame, r_b = model.frame, model.geometry.ball_radius
    q0 = level1.load_screw
    v0 = rolling_ball_speed(
        frame, w_eval, level1.motion.screw_contact.direction, level1.motion.nut_contact.direction
    )

    def residual(x: FloatArray) -> FloatArray:
        f = _level2_forces(model, w_eval, s, x, dynamic)
        c = f.contacts
        total = (
            -c.load_screw * c.direction_screw
            - c.load_nut * c.direction_nut
            + f.traction.force
            + f.traction_nut
            + f.rolling_screw
            + f.rolling_nut
            - f.centrifugal * frame.n
        )
        moment = (
            f.traction.moment
            + np.cross(r_b * c.direction_nut, f.traction_nut)
            + f.pivot_nut * f.motion.nut_contact.z
            + f.gyroscopic
        )
        on_nut = c.load_nut * c.direction_nut - f.traction_nut - f.rolling_nut
        nut = model.balls * _nut_axial(model, s, on_nut)
        return np.concatenate([total / q0, moment / (q0 * r_b), [nut / force - 1.0]])

    x0 = np.array([*level1.centre_offset, level1.nut_displacement, v0, 0.0, 0.0, 0.0], dtype=float)
    length = abs(level1.nut_displacement)
    scale = np.array([length, length, length, v0, q0, q0, q0 * r_b])
    result = newton_solve(residual, x0, scale, solver="Level-2 ball balance (E3.6)")
    f = _level2_forces(model, w_eval, s, result.x, dynamic)
    motion = f.motion
    if not dynamic:
        motion = BallMotion(
            0.0, 0.0, _ZERO.copy(), s, frame, motion.screw_contact, motion.nut_contact
        )
    c = f.contacts
    return BallState(
        level=2,
        flank=s,
        nut_force=force,
        motion=motion,
        load_screw=c.load_screw,
        load_nut=c.load_nut,
        angle_screw=c.angle_screw,
        angle_nut=c.angle_nut,
        centre_offset=(float(result.x[0]), float(result.x[1])),
        nut_displacement=float(result.x[2]),
        centrifugal_force=f.centrifugal,
        gyroscopic_moment=f.gyroscopic,
        traction_screw=f.traction,
        traction_nut=f.traction_nut,
        pivot_moment_nut=f.pivot_nut,
        rolling_resistance_screw=f.rolling_screw,
        rolling_resistance_nut=f.rolling_nut,
        sharing=f.sharing,
        iterations=result.iterations,
        residual=result.residual,
    )


def solve_ball(
    model: BallModel, speed: float, nut_force: float, flank: int = 1, level: int = 0
) -> BallState:
    """The ball state at ``level`` 0, 1 or 2 (see the module docstring)."""
    if level not in LEVELS or isinstance(level, bool):
        raise InputError("level", level, "0 (static), 1 (centrifugal + groove) or 2 (full)")
    solver = (static_balance, groove_balance, full_balance)[level]
    return solver(model, speed, nut_force, flank)
