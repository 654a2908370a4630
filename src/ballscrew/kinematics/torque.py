"""Screw drag torque from the ball model, (E3.7), next to the catalogue formula (E9.1).

``docs/theory/kinematics.md`` (E3.7): the torque the screw needs is the moment about its axis of the
forces the balls exert on it at A. In the nut frame the screw also advances p = L/2π per radian,
so at a given nut force the axial part of the contact forces is carried through the lead; the
torque that keeps the nut force fixed is the power the screw delivers over ω_s:

    T = Z Σ_A [ τ·(ẑ × P + p ẑ) ΔA ] + Z F_R,A·(ẑ × A + p ẑ)          per nut,

which is (E3.7) at fixed nut force, with the distributed traction τ of (E3.3) (its spin moment
included) and the EHL rolling force. The normal force does no work (v_screw(A)·e_A = 0, E2.3), so
the external load's reversible torque F_a L/2π is not in T: T is the drag (friction) torque,
and Q = T ω_s the heat it makes. At Level 2 the balance holds and T ω_s equals the dissipated
power exactly; at Levels 0/1 the traction is evaluated on the state's kinematics afterwards.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.kinematics.balance import BallState
from ballscrew.kinematics.model import BallModel
from ballscrew.kinematics.motion import ball_motion
from ballscrew.kinematics.traction import ContactTraction, contact_traction, hertz_pressure_grid
from ballscrew.kinematics.traction_laws import traction_weights

__all__ = ["BallDrag", "ball_drag", "efficiency_drag_torque"]

FloatArray = NDArray[np.float64]


def efficiency_drag_torque(
    preload: float, lead: float, lead_angle: float, rolling_friction: float = 0.003
) -> tuple[float, float]:
    """Efficiency-based preload torque T_p = (F_p L/2π)(1 − η²)/η and η, (E9.2).

    η = tanλ/tan(λ + ρ'), ρ' = atan μ_r (textbook form; much smaller than the catalogue E9.1).
    Reference screw of ``examples/wear_step_stress.toml``, μ_r = 0.003, F_p = 1500 N:
    η = 0.9634, T_p = 0.1779 N m.
    """
    eta = math.tan(lead_angle) / math.tan(lead_angle + math.atan(rolling_friction))
    return preload * lead / (2.0 * math.pi) * (1.0 - eta * eta) / eta, eta


@dataclass(frozen=True)
class BallDrag:
    """Drag of one ball: its traction at A, the EHL rolling forces and the screw torque."""

    traction: ContactTraction
    """Traction resultants at A on the ball, at the evaluation speed."""
    rolling_screw: FloatArray
    """EHL rolling force of the A film on the ball [N]."""
    rolling_nut: FloatArray
    """EHL rolling force of the B film on the ball [N]."""
    psi: float
    """JGP asperity load share ψ at A (the traction weight of the ``film`` law only; a film
    property, reported under every law)."""
    torque: float
    """Screw torque per ball, (E3.7) at fixed nut force [N m]; positive opposes the rotation."""
    dissipation_torque: float
    """Dissipated power per ball over ω_s (sliding at A, rolling resistance at A and B) [N m].

    Equal to ``torque`` when the balance includes the traction (Level 2)."""
    separation: float = 0.0
    """Mean separation h of the surfaces at A under the JGP load sharing [m] (0 dry)."""


def ball_drag(model: BallModel, state: BallState) -> BallDrag:
    """Drag of one ball in ``state`` (any level); zero for an unloaded ball.

    Levels 0/1: traction (E3.3) on the Hertz grid at Q_A with the state's kinematics and the JGP
    share at the entrainment speed u_e (E2.8), rolling forces (E3.4) at A and B. Level 2: the
    balance's own forces. At ω_s = 0 the limit ω_s → 0⁺ is returned (dry contact, directions of
    a slowly turning screw).
    """
    frame = model.frame
    if state.load_screw <= 0.0:
        zero = np.zeros(3)
        return BallDrag(ContactTraction(zero, zero, 0.0, 0.0), zero, zero, 1.0, 0.0, 0.0)
    motion = state.motion
    if state.screw_speed == 0.0:  # limit ω → 0⁺: the same directions at 1 rad/s
        motion = ball_motion(
            model.geometry,
            1.0,
            state.flank,
            angle_screw=state.angle_screw,
            angle_nut=state.angle_nut,
        )
    omega = motion.screw_speed
    u_e = model.entrainment_speed(state.motion, "screw")
    if state.traction_screw is not None:
        traction = state.traction_screw
        psi = state.sharing.psi if state.sharing is not None else 1.0
        separation = state.sharing.separation if state.sharing is not None else 0.0
        rolling_screw, rolling_nut = state.rolling_resistance_screw, state.rolling_resistance_nut
    else:
        sharing = model.sharing(state.load_screw, u_e)
        psi, separation = sharing.psi, sharing.separation
        a, b = model.hertz_semi_axes("screw", state.load_screw)
        x, y, p = hertz_pressure_grid(a, b, state.load_screw, model.traction_cells)
        law = traction_weights(model, psi, state.screw_speed if u_e > 0 else 0.0)
        traction = contact_traction(
            motion,
            x,
            y,
            p,
            psi=law.share,
            film_thickness=sharing.separation,
            viscosity=model.viscosity if u_e > 0 else None,
            pressure_viscosity=model.pressure_viscosity,
            boundary_friction=law.boundary_friction,
            limiting_shear=law.film_friction,
            deformed_radius=model.deformed_radius("screw"),
        )
        relative = motion.ball_speed - float(motion.screw_velocity(frame.centre) @ frame.t)
        f_a = model.rolling_resistance(state.load_screw, u_e, "screw")
        u_b = model.entrainment_speed(state.motion, "nut")
        f_b = model.rolling_resistance(state.load_nut, u_b, "nut")
        rolling_screw = -np.copysign(f_a, relative) * frame.t
        rolling_nut = -np.copysign(f_b, motion.ball_speed) * frame.t
    v_screw_a = motion.screw_velocity(motion.screw_contact.origin)
    v_centre = motion.ball_speed * frame.t
    torque = (traction.screw_power + float(rolling_screw @ v_screw_a)) / omega
    dissipated = (
        traction.power_loss
        + float(rolling_screw @ (v_screw_a - v_centre))
        - float(rolling_nut @ v_centre)
    )
    return BallDrag(
        traction, rolling_screw, rolling_nut, psi, torque, dissipated / omega, separation
    )
