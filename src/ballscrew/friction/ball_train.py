"""Contact force between adjacent balls of a circuit: the rival ball-train models.

The balls of a ball-screw circuit are not caged: the loaded balls and the balls in the return
form one closed train. The force F_B at a ball–ball contact sets the ball–ball friction of
:func:`ballscrew.friction.nut_losses.ball_ball_power` (Olaru, Puiu, Balan & Puiu 2005: the
"contact force between the balls" and its friction moment). Registered in
:data:`BALL_TRAIN_MODELS` (``friction.ball_train``):

* ``ratio`` (default): F_B = r Q, a given fraction of the ball load (GUESS r = 0.01).
* ``return_push``: the balls in the unloaded return path roll or slide on its wall and must be
  pushed through it by the loaded balls behind them. Along the train the contact force obeys
  the balance of each ball along the track, C_i = C_(i−1) + T_i (T_i the drive of the raceways
  on a loaded ball, minus the resistance f_r of a return ball): it rises over the n_l loaded
  balls of a circuit and falls to zero over its n_r return balls. With the drive shared
  equally by the loaded balls the mean force at their leading contacts is

      F_B = n_r f_r (n_l + 1)/(2 n_l),   f_r = μ_r m (g + V²/ρ_r) + F_v,

  m the ball mass, V the ball speed, ρ_r the radius of the return path, μ_r the friction
  coefficient of a ball on the return wall and F_v the drag of the ball in the lubricant.
  f_r takes every return ball as sliding (an upper bound: a ball rolling in the tube resists
  less) and the train as filled without pre-force (an over-filled or thermally tightened
  train adds an unknown C_0 > 0 to every contact). The
  same mechanism in a full-complement bearing: balls of different orbital speeds that cannot
  pass each other push one another (Gupta 1984, *Advanced Dynamics of Rolling Elements*; the
  MESYS ball-screw manual, "circumferential ball advance"). The return push is the one
  mechanism whose force follows from quantities the ball model has.
* ``speed_spread``: the loaded balls want different orbital speeds (their loads, contact angles
  and diameters differ along the nut) and cannot pass each other; each group of touching balls
  moves at the speed where the creep drives of its raceways balance, and the leading ball also
  pushes the return (:mod:`ballscrew.friction.speed_spread`). F_B is the mean contact force over
  the loaded balls of the given circuits; without per-ball states (identical balls) it is the
  ``return_push`` force.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.friction.speed_spread import TrainSpread, spread_forces
from ballscrew.registry import Registry
from ballscrew.validation import nonnegative, positive

__all__ = [
    "BALL_TRAIN_MODELS",
    "DEFAULT_BALL_BALL_LOAD_RATIO",
    "DEFAULT_BALL_TRAIN",
    "DEFAULT_RETURN_FRACTION",
    "DEFAULT_RETURN_FRICTION",
    "GRAVITY",
    "BallTrain",
    "TrainForces",
    "ball_ball_force",
    "return_resistance",
    "speed_spread_force",
    "train_forces",
]

#: Standard gravity [m/s²] (ISO 80000-3).
GRAVITY = 9.80665

DEFAULT_BALL_TRAIN = "ratio"
"""The ball-train model of a case without ``friction.ball_train``."""

DEFAULT_BALL_BALL_LOAD_RATIO = 0.01
"""F_B/Q, contact force between adjacent balls per ball–raceway load. GUESS: 0 for identical
balls rolling without slip (nothing pushes them together); up to the traction capacity μ_b Q when
a ball of another size is pushed by its neighbours into sliding at the raceways. 1 % of Q is a
tenth of that upper bound for μ_b = 0.1; no published value was found."""

DEFAULT_RETURN_FRICTION = 0.1
"""μ_r of a ball sliding on the wall of the return path (tube or deflector). GUESS: boundary
friction of lubricated steel, the value of ``ball_ball_friction`` (a plastic deflector is
lower)."""

DEFAULT_RETURN_FRACTION = 0.2
"""n_r/n_l, balls in the return per loaded ball of a circuit. GUESS from the geometry of a
tube-return circuit of 2.5 turns (about 9 balls in a tube spanning 2.5 leads and two bends, 52
loaded balls: 0.17) and of a one-turn internal deflector (2–3 of about 20: 0.12), rounded up."""


@dataclass(frozen=True)
class BallTrain:
    """One circuit of balls at one operating point (SI)."""

    load: float
    """Q, the ball–raceway load of a loaded ball [N]."""
    mass: float = 0.0
    """m, mass of a ball [kg]."""
    speed: float = 0.0
    """V, speed of the ball centres along the track [m/s]."""
    path_radius: float = 1.0
    """ρ_r, radius of curvature of the return path [m]."""
    loaded_balls: float = 1.0
    """n_l, loaded balls per circuit (> 0)."""
    return_fraction: float = DEFAULT_RETURN_FRACTION
    """n_r/n_l, balls in the return per loaded ball."""
    return_friction: float = DEFAULT_RETURN_FRICTION
    """μ_r of a return ball on the return wall."""
    drag_force: float = 0.0
    """F_v, drag of one ball in the lubricant [N]."""
    load_ratio: float = DEFAULT_BALL_BALL_LOAD_RATIO
    """r = F_B/Q of the ``ratio`` model."""
    spread: tuple[TrainSpread, ...] = ()
    """The loaded balls of circuits in their direction of travel (``speed_spread``; empty:
    identical balls)."""

    @property
    def return_balls(self) -> float:
        """n_r = (n_r/n_l) n_l."""
        return self.return_fraction * self.loaded_balls


@dataclass(frozen=True)
class TrainForces:
    """What a ball-train model gives for one circuit [N]."""

    contact: float
    """F_B, mean contact force at the leading contact of a loaded ball."""
    return_push: float = 0.0
    """n_r f_r, the force the loaded balls deliver to the return train (its power n_r f_r V is
    dissipated in the return; 0 where the model has no return)."""


BallTrainModel = Callable[[BallTrain], TrainForces]
BALL_TRAIN_MODELS: Registry[BallTrainModel] = Registry("ball-train model", "friction.ball_train")
"""Rival models of the contact force between adjacent loaded balls, name → :class:`TrainForces`."""


def return_resistance(train: BallTrain) -> float:
    """f_r = μ_r m (g + V²/ρ_r) + F_v [N]: the force that keeps one return ball moving.

    The wall carries the ball's weight (a horizontal screw, ASSUMED: the worst orientation) and
    the centripetal force of the bend; μ_r is Coulomb friction on it.
    """
    mu = nonnegative("friction.return_friction", train.return_friction)
    mass = nonnegative("ball_mass", train.mass, "kg")
    radius = positive("return_path_radius", train.path_radius, "m")
    drag = nonnegative("drag_force", train.drag_force, "N")
    return mu * mass * (GRAVITY + train.speed**2 / radius) + drag


def train_forces(drives: NDArray[np.float64]) -> NDArray[np.float64]:
    """Contact forces C_i [N] behind the balls of a closed train from their drives T_i [N].

    Ball i (in the direction of travel) is pushed by ball i−1 and pushes ball i+1, so its
    balance along the track is C_i = C_(i−1) + T_i; the contact behind the first ball carries
    C_0 = C_n = 0 (the train is slack there). The drives must balance, ΣT_i = 0 (steady
    motion). Returns C_1 … C_n (C_n = 0 by the balance).
    """
    t = np.asarray(drives, dtype=float)
    scale = float(np.sum(np.abs(t)))
    if abs(float(np.sum(t))) > 1e-12 * max(scale, 1.0):
        raise ValueError(f"the drives of a closed train sum to {np.sum(t):.3g} N, not 0")
    return np.cumsum(t)


@BALL_TRAIN_MODELS.register("ratio", "F_B = r Q, a given fraction of the ball load (GUESS 0.01)")
def ratio_force(train: BallTrain) -> TrainForces:
    """F_B = r Q (GUESS r; 0 for an unloaded ball); no return push."""
    nonnegative("friction.ball_ball_load_ratio", train.load_ratio)
    return TrainForces(train.load_ratio * max(train.load, 0.0))


@BALL_TRAIN_MODELS.register(
    "return_push",
    "loaded balls push the return balls against wall friction and drag: "
    "F_B = n_r f_r (n_l + 1)/(2 n_l)",
)
def return_push_force(train: BallTrain) -> TrainForces:
    """F_B = n_r f_r (n_l + 1)/(2 n_l): the mean over the loaded balls' leading contacts of the
    force ramp C_i = i n_r f_r/n_l (:func:`train_forces` with equal drives); push n_r f_r."""
    n_l = positive("loaded_balls", train.loaded_balls)
    nonnegative("friction.return_fraction", train.return_fraction)
    push = train.return_balls * return_resistance(train)
    return TrainForces(push * (n_l + 1.0) / (2.0 * n_l), push)


def ball_ball_force(model: str, train: BallTrain) -> TrainForces:
    """Contact forces of one circuit by the registered ball-train ``model``."""
    return BALL_TRAIN_MODELS.entry(model).model(train)


@BALL_TRAIN_MODELS.register(
    "speed_spread",
    "loaded balls of different free orbital speeds push each other (creep drives, "
    "pool-adjacent-violators) and the return",
)
def speed_spread_force(train: BallTrain) -> TrainForces:
    """F_B = the mean of the contact forces C_i ahead of the loaded balls over the circuits of
    ``train.spread`` (:func:`~ballscrew.friction.speed_spread.spread_forces`), the leading ball
    pushing n_r f_r into the return; identical balls: :func:`return_push_force`."""
    if not train.spread:
        return return_push_force(train)
    nonnegative("friction.return_fraction", train.return_fraction)
    push = train.return_balls * return_resistance(train)
    forces = np.concatenate([spread_forces(circuit, push)[0] for circuit in train.spread])
    return TrainForces(float(np.mean(forces)), push)
