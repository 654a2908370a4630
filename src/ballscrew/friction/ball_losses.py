"""Losses of the loaded balls: sliding and spin traction, EHL rolling and elastic hysteresis.

Per ball of each nut, from the quasi-static state of :mod:`ballscrew.kinematics`:

* sliding and spin traction at the screw contact A, integrated over the Hertz pressure grid
  (``docs/theory/kinematics.md`` (E3.3)). Its traction coefficient depends on the regime through
  the Johnson, Greenwood & Poon (1972) asperity share ψ, itself a function of the film parameter
  Λ = h/σ: boundary friction μ_b on the asperity-borne pressure ψ p, viscous film shear capped at
  the limiting shear stress Λ_L p (Bair & Winer 1979) on the rest; Λ → 0 is boundary
  (μ → μ_b), Λ ≳ 3 is full EHL (Hamrock 1994, ch. 1: Λ < 1 boundary, 1–3 mixed, > 3 full film);
* differential (Heathcote) slip at the nut contact B (:mod:`ballscrew.friction.groove_slip`):
  the kinematics holds B free of slip and spin at its centre, but the curved contact surface
  of the conforming groove slides on both sides of the two rolling lines (at A this slip is
  part of the sliding field of the traction grid);
* EHL rolling resistance at A and B (Harris & Kotzalas 2007; (E3.4));
* elastic hysteresis of the Hertz contacts A and B (Tabor 1955; Johnson 1985, *Contact
  Mechanics*, §9.2: a sphere rolling on a plane loses the fraction α of the elastic work,
  F_h = α (3/16) Q a/R per unit distance rolled). Applied with the semi-axis a along the
  rolling direction and the relative radius R_x of each contact (an ASSUMED extension to the
  elliptical contact), at the rolling speed u_e of each contact (E2.8);
* ball–ball friction, drag of the balls in the lubricant and the ball-return loss of
  :mod:`ballscrew.friction.nut_losses`.

Each loss is a torque of the screw, power/ω, so that its heat is the torque times ω. A loss at A
is shared equally by the screw and the ball (same steel on both sides; Blok 1937 partition for
equal bodies, ASSUMED); the ball's share, every loss at B and the losses of
:mod:`~ballscrew.friction.nut_losses` (balls, lubricant and returns inside the nut) reach the nut.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.friction.ball_train import BallTrain, TrainForces, ball_ball_force
from ballscrew.friction.groove_slip import differential_slip_power, heathcote_rate
from ballscrew.friction.nut_losses import (
    NutLossParameters,
    ball_ball_power,
    drag_power,
    recirculation_power,
)
from ballscrew.friction.speed_spread import (
    NutBalls,
    TrainSpread,
    circuit_trains,
    creep_stiffness,
    free_speed,
    traction_capacity,
)
from ballscrew.geometry.screw import SIDES
from ballscrew.kinematics.balance import BallState, solve_ball
from ballscrew.kinematics.model import BallModel
from ballscrew.kinematics.motion import BallMotion, ball_motion
from ballscrew.kinematics.torque import ball_drag
from ballscrew.kinematics.traction_laws import traction_weights
from ballscrew.lubrication import film_parameter

__all__ = ["BallLosses", "ball_losses", "hysteresis_force"]

FloatArray = NDArray[np.float64]

#: Hysteresis loss fraction α of hardened bearing steel in elastic rolling: GUESS of order 1 %
#: (Tabor 1955 and Johnson 1985 §9.2 report small fractions for hard metals; not read here).
DEFAULT_HYSTERESIS = 0.01

#: Share of a loss at the screw contact A that goes into the screw (Blok 1937, equal bodies).
SCREW_SHARE_AT_A = 0.5


def hysteresis_force(
    load: ArrayLike, semi_axis: ArrayLike, radius: ArrayLike, fraction: float
) -> float | FloatArray:
    """Rolling resistance of elastic hysteresis, F_h = α (3/16) Q a/R [N] (Johnson 1985 §9.2);
    0 where Q ≤ 0. Arrays broadcast (one value per ball and contact)."""
    q = np.asarray(load, dtype=float)
    force = fraction * 3.0 / 16.0 * np.maximum(q, 0.0) * np.asarray(semi_axis) / radius
    return float(force) if force.ndim == 0 else force


@dataclass(frozen=True)
class BallLosses:
    """Screw torques [N m] of the ball losses of all loaded balls, and where their heat goes."""

    sliding: float
    """Sliding and spin traction at A."""
    ehl_rolling: float
    """EHL rolling resistance at A and B."""
    hysteresis: float
    """Elastic hysteresis at A and B."""
    screw_share: float
    """Torque whose heat goes into the screw (the rest goes into the nut)."""
    film_parameter: float
    """Film parameter Λ = h_c/σ_Λ (E6.6) at A of the first loaded nut: the central film of its
    whole ball load Q_A at the rolling speed of A, over the raceway's composite roughness σ_Λ
    (0 dry or at rest)."""
    groove_slip: float = 0.0
    """Differential (Heathcote) slip at the nut contact B."""
    ball_ball: float = 0.0
    """Sliding friction between adjacent balls."""
    drag: float = 0.0
    """Drag of the balls in the lubricant of the nut."""
    recirculation: float = 0.0
    """Kinetic energy of the balls lost in the ball returns."""
    asperity_share: float = 1.0
    """JGP asperity share ψ(Λ) at A of the first loaded nut, the boundary weight of the ``film``
    traction law (1 dry or at rest)."""
    traction_coefficient: float = 0.0
    """μ = s μ_b + (1 − s) μ_f of the traction law at A of the first loaded nut: the friction
    coefficient of a sliding cell whose film shear has reached its cap (s = ψ or φ_bl; 0 when
    no ball is loaded)."""

    @property
    def total(self) -> float:
        return (
            self.sliding
            + self.groove_slip
            + self.ehl_rolling
            + self.hysteresis
            + self.ball_ball
            + self.drag
            + self.recirculation
        )


def _unit_motion(model: BallModel, state: BallState) -> BallMotion:
    """The ball's motion per unit screw speed (E2.4; the limit ω_s → 0⁺ at rest)."""
    if state.screw_speed != 0.0:
        return state.motion
    return ball_motion(
        model.geometry, 1.0, state.flank, angle_screw=state.angle_screw, angle_nut=state.angle_nut
    )


def _semi_axes(model: BallModel, loads: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Hertz semi-axes along and across the rolling direction [m] of the contacts A, B (columns)
    of the balls (rows; one per loaded nut, its Z balls share its state) at ``loads``:
    :meth:`BallModel.hertz_semi_axes` of each contact's column."""
    axes = [model.hertz_semi_axes(contact, loads[:, k]) for k, contact in enumerate(SIDES)]
    return np.column_stack([a for a, _ in axes]), np.column_stack([b for _, b in axes])


def _spread(
    model: BallModel, unit: BallMotion, balls: NutBalls | None, friction: float, circuits: int
) -> tuple[TrainSpread, ...]:
    """The circuits of one nut for ``speed_spread``: each ball's free speed from its contact
    angle and diameter, its creep stiffness and capacity at the traction coefficient μ and the
    spin at A of the nut's state, all per the state's screw speed (``unit``); () without
    per-ball states."""
    if balls is None:
        return ()
    g = model.geometry
    radii = g.ball_radius + 0.5 * balls.diameter_excess
    speeds = free_speed(0.5 * g.pitch_diameter, g.lead_angle, radii, balls.angles, unit.screw_speed)
    _, across = model.hertz_semi_axes("screw", balls.loads)
    stiffness = creep_stiffness(friction, balls.loads, unit.spin_screw, across)
    return circuit_trains(speeds, stiffness, traction_capacity(friction, balls.loads), circuits)


def _train(
    model: BallModel,
    state: BallState,
    nut: NutLossParameters,
    drag_force: float,
    spread: tuple[TrainSpread, ...] = (),
) -> TrainForces:
    """Contact forces of the ball train of one circuit of the nut of ``state``
    (:mod:`ballscrew.friction.ball_train`; the return path curves at the pitch radius, ASSUMED:
    an internal deflector follows the screw's circumference)."""
    train = BallTrain(
        load=state.load_screw,
        mass=model.mass,
        speed=state.ball_speed,
        path_radius=0.5 * model.geometry.pitch_diameter,
        loaded_balls=model.balls / nut.circuits,
        return_fraction=nut.return_fraction,
        return_friction=nut.return_friction,
        drag_force=drag_force,
        load_ratio=nut.ball_ball_load_ratio,
        spread=spread,
    )
    return ball_ball_force(nut.ball_train, train)


def _ball_ball_torque(
    model: BallModel, unit: BallMotion, nut: NutLossParameters, force: float
) -> float:
    """Screw torque of the friction of one ball against its leading neighbour (P_bb/ω_s) at the
    contact force F_B ``force``."""
    r_b = model.geometry.ball_radius
    surface = r_b * float(np.linalg.norm(np.cross(unit.angular_velocity, model.frame.t)))
    return ball_ball_power(force, nut.ball_ball_friction, surface) / unit.screw_speed


def _groove_slip_torque(
    model: BallModel, state: BallState, unit: BallMotion, semi_axes: tuple[float, float]
) -> float:
    """Screw torque of the differential slip at B of one ball (P_H/ω_s; dry at ω_s = 0), at the
    rolling rate about the axis across the groove, ω_r = Ω·Y_B (the nut is at rest)."""
    rate = heathcote_rate(unit.angular_velocity, unit.nut_contact)
    u_e = model.entrainment_speed(state.motion, "nut")
    sharing = model.sharing(state.load_nut, u_e, "nut")
    law = traction_weights(model, sharing.psi, state.screw_speed if u_e > 0.0 else 0.0)
    power = differential_slip_power(
        state.load_nut,
        *semi_axes,
        model.deformed_radius("nut"),
        rate,
        psi=law.share,
        boundary_friction=law.boundary_friction,
        limiting_shear=law.film_friction,
        film_thickness=sharing.separation,
        viscosity=model.viscosity if u_e > 0.0 else None,
        pressure_viscosity=model.pressure_viscosity,
        cells=model.traction_cells,
    )
    return power / unit.screw_speed


def _contact_losses(
    model: BallModel,
    state: BallState,
    unit: BallMotion,
    semi_nut: tuple[float, float],
    nut: NutLossParameters,
    balls: NutBalls | None = None,
    train: bool = True,
) -> tuple[tuple[float, ...], float, float]:
    """(sliding, rolling A, rolling B, ball–ball, drag, slip at B) torques of one ball, the
    torque of pushing the return train of one nut (ball returns) and the JGP asperity share ψ
    at A. ``train`` = False: the contact losses alone (ball–ball, drag and push 0), for a flank
    whose balls' train is counted on another."""
    drag = ball_drag(model, state)
    omega = state.screw_speed if state.screw_speed != 0.0 else 1.0
    sliding = drag.traction.power_loss / omega
    rolling = drag.dissipation_torque - sliding
    # the B film's force does work against the ball centre (zero at ω_s = 0: no film)
    rolling_b = -float(drag.rolling_nut @ (state.ball_speed * model.frame.t)) / omega
    slip = _groove_slip_torque(model, state, unit, semi_nut)
    if not train:
        return (sliding, rolling - rolling_b, rolling_b, 0.0, 0.0, slip), 0.0, drag.psi
    speed = abs(state.ball_speed)
    force = 0.0  # drag of one ball in the lubricant, F_v = P_v/V
    if model.lubricated and state.screw_speed != 0.0 and speed > 0.0:
        force = (
            drag_power(
                speed,
                model.geometry.ball_diameter,
                model.lubricant_density,
                model.viscosity,
                nut.lubricant_fill,
            )
            / speed
        )
    viscous = force * speed / omega
    spread = ()
    if nut.ball_train == "speed_spread":
        mu = _traction_coefficient(model, state, drag.psi)
        spread = _spread(model, unit, balls, mu, nut.circuits)
    forces = _train(model, state, nut, force, spread)
    # the push's power n_c n_r f_r V per screw speed: V/ω of the unit motion (ω_s → 0⁺ at rest)
    push = nut.circuits * forces.return_push * abs(unit.ball_speed / unit.screw_speed)
    ball_ball = _ball_ball_torque(model, unit, nut, forces.contact)
    return (sliding, rolling - rolling_b, rolling_b, ball_ball, viscous, slip), push, drag.psi


def _traction_coefficient(model: BallModel, state: BallState, psi: float) -> float:
    """s μ_b + (1 − s) μ_f of the traction law at A for the JGP share ψ (dry at rest: μ_b)."""
    law = traction_weights(model, psi, state.screw_speed if state.ball_speed != 0.0 else 0.0)
    return law.share * law.boundary_friction + (1.0 - law.share) * law.film_friction


def _recirculation_torque(model: BallModel, state: BallState, nut: NutLossParameters) -> float:
    """Screw torque of the ball-return loss of one nut (0 at rest)."""
    if state.screw_speed == 0.0:
        return 0.0
    power = recirculation_power(
        state.ball_speed,
        state.motion.rolling_speed,
        model.mass,
        model.inertia,
        model.geometry.ball_diameter,
        nut.circuits,
    )
    return power / state.screw_speed


def ball_losses(
    model: BallModel,
    speed: float,
    nuts: tuple[tuple[float, int], ...],
    *,
    level: int = 0,
    hysteresis: float = DEFAULT_HYSTERESIS,
    nut: NutLossParameters | None = None,
    balls: tuple[NutBalls | None, ...] | None = None,
    shared: bool = False,
) -> BallLosses:
    """Losses of every loaded ball of the nuts ``(axial force, flank)`` at screw speed ω_s.

    ω_s = 0 gives the ω_s → 0⁺ limit (dry breakaway: boundary traction, no film, hysteresis at
    the rolling speed of a slowly turning screw, ball–ball friction at its rolling speed, no drag
    or return loss). ``nut``: the parameters of :mod:`~ballscrew.friction.nut_losses` (default
    :class:`~ballscrew.friction.nut_losses.NutLossParameters`). ``balls``: per nut (aligned with
    ``nuts``) the per-ball states of :class:`~ballscrew.friction.speed_spread.NutBalls` that the
    ``speed_spread`` ball train needs (None: identical balls). ``shared``: the flanks are the two
    contact pairs of the same balls (a single nut preloaded by oversized balls): the contact
    losses count on every flank, the ball train's (ball–ball, drag, return push and
    recirculation) once, with the motion of the first loaded flank (an assumption: the
    four-point ball's own kinematics are not modelled).
    """
    nut = NutLossParameters() if nut is None else nut
    per_nut = (None,) * len(nuts) if balls is None else balls
    loaded = [(f, flank, b) for (f, flank), b in zip(nuts, per_nut, strict=True) if f > 0.0]
    states = [solve_ball(model, speed, force, flank, level) for force, flank, _ in loaded]
    if not states:
        return BallLosses(0.0, 0.0, 0.0, 0.0, 0.0)
    # once per ball (the Z balls of a nut share one state): its motion per unit screw speed and
    # the Hertz semi-axes at A and B
    units = [_unit_motion(model, state) for state in states]
    loads = np.array([(state.load_screw, state.load_nut) for state in states])
    along, across = _semi_axes(model, loads)
    sums = np.zeros(6)
    pushes = 0.0
    shares = []  # JGP asperity share ψ at A of each loaded nut
    for state, unit, a, b, (*_, own) in zip(
        states, units, along[:, 1], across[:, 1], loaded, strict=True
    ):
        # shared: the same balls on every flank, their train counted on the first one only
        torques, push, psi = _contact_losses(
            model, state, unit, (float(a), float(b)), nut, own, train=not shared or not shares
        )
        sums += torques
        pushes += push
        shares.append(psi)
    sliding, rolling_a, rolling_b, balls, drag, groove = model.balls * sums
    # hysteresis of every ball at A and B in one batch, at the rolling speed of each contact per
    # ω_s, u_e/ω_s (E2.8): the speed at which the surfaces pass through the contact
    rolling = np.array(
        [[model.entrainment_speed(unit, c) / unit.screw_speed for c in SIDES] for unit in units]
    )
    radii = np.array([model.curvature(contact).rx for contact in SIDES])
    hyst_a, hyst_b = model.balls * np.sum(
        hysteresis_force(loads, along, radii, hysteresis) * rolling, axis=0
    )
    trains = states[:1] if shared else states
    returns = pushes + sum(_recirculation_torque(model, state, nut) for state in trains)
    first = states[0]
    whole = model.film(first.load_screw, model.entrainment_speed(first.motion))
    film = film_parameter(whole.central, model.surface.film_roughness) if whole else 0.0
    return BallLosses(
        sliding=float(sliding),
        groove_slip=float(groove),
        ehl_rolling=float(rolling_a + rolling_b),
        hysteresis=float(hyst_a + hyst_b),
        ball_ball=float(balls),
        drag=float(drag),
        recirculation=float(returns),
        screw_share=float(SCREW_SHARE_AT_A * (sliding + rolling_a + hyst_a)),
        film_parameter=film,
        asperity_share=shares[0],
        traction_coefficient=_traction_coefficient(model, first, shares[0]),
    )
