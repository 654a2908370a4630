"""Friction torque of the nut of a ball screw, its parts, efficiency and heat.

1. :mod:`~ballscrew.friction.efficiency` — driving / back-driving efficiency and the torque of
   the working load (makers' formulas, THK General Catalog A-664 to A-666).
2. :mod:`~ballscrew.friction.ball_losses` — sliding and spin traction, EHL rolling and elastic
   hysteresis of the loaded balls (kinematics model; Johnson 1985 §9.2; JGP 1972).
3. :mod:`~ballscrew.friction.groove_slip` — differential (Heathcote) slip of the ball in the
   conforming nut groove (Heathcote 1921; Johnson 1985 ch. 8).
4. :mod:`~ballscrew.friction.nut_losses` — ball–ball friction (Olaru et al. 2005), drag of the
   balls in the lubricant (Harris & Kotzalas 2007) and the ball-return loss;
   :mod:`~ballscrew.friction.ball_train` — the contact force between adjacent balls
   (:data:`BALL_TRAIN_MODELS`).
5. :mod:`~ballscrew.friction.torque` — the parts together, the rival total models
   (:data:`FRICTION_MODELS`) and :func:`nut_friction_torque`.

The case-level composer is :func:`ballscrew.analyses.friction.friction_torque`.
"""

from ballscrew.friction.ball_losses import (
    DEFAULT_HYSTERESIS,
    BallLosses,
    ball_losses,
    hysteresis_force,
)
from ballscrew.friction.ball_train import BALL_TRAIN_MODELS
from ballscrew.friction.efficiency import (
    CATALOGUE_ROLLING_FRICTION,
    backdriving_efficiency,
    driving_efficiency,
    load_friction_torque,
    load_torque,
)
from ballscrew.friction.nut_losses import NutLossParameters
from ballscrew.friction.torque import (
    FRICTION_MODELS,
    FrictionInputs,
    FrictionTorque,
    nut_friction_torque,
)

__all__ = [
    "BALL_TRAIN_MODELS",
    "CATALOGUE_ROLLING_FRICTION",
    "DEFAULT_HYSTERESIS",
    "FRICTION_MODELS",
    "BallLosses",
    "FrictionInputs",
    "FrictionTorque",
    "NutLossParameters",
    "backdriving_efficiency",
    "ball_losses",
    "driving_efficiency",
    "hysteresis_force",
    "load_friction_torque",
    "load_torque",
    "nut_friction_torque",
]
