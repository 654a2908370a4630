"""Case section ``[friction]``: the friction-torque model of the nut and its parameters.

Every key has a default, so a case without the section is valid. Theory manual:
``docs/theory/friction.md``.

Example::

    [friction]
    model = "ball_model"        # or "catalogue" (default)
    traction = "skf"            # traction law of the ball model: "film" (default) or "skf"
    seals = 2                   # contacting seals / wiper rings of the nut
    seal_force = "5 N"          # friction force of one seal lip [GUESS], at the radius d_m/2
    hysteresis = 0.01           # hysteresis loss fraction α of the Hertz contacts [GUESS]
    ball_train = "ratio"        # force between adjacent balls: "ratio" (default), "return_push"
                                # or "speed_spread" (with loads.distribution = "elastic")
    ball_ball_load_ratio = 0.01 # force between adjacent balls / ball load, ratio [GUESS]
    return_friction = 0.1       # friction of a ball on the return wall, return_push [GUESS]
    return_fraction = 0.2       # balls in the return per loaded ball, return_push [GUESS]
    circuits = 2                # ball circuits (returns) per nut [GUESS]
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field

from ballscrew.case.base import Model, model_choice, quantity
from ballscrew.friction import CATALOGUE_ROLLING_FRICTION, DEFAULT_HYSTERESIS, FRICTION_MODELS
from ballscrew.friction.ball_train import (
    BALL_TRAIN_MODELS,
    DEFAULT_BALL_TRAIN,
    DEFAULT_RETURN_FRACTION,
    DEFAULT_RETURN_FRICTION,
)
from ballscrew.friction.nut_losses import (
    DEFAULT_BALL_BALL_FRICTION,
    DEFAULT_BALL_BALL_LOAD_RATIO,
    DEFAULT_CIRCUITS,
    DEFAULT_LUBRICANT_FILL,
)
from ballscrew.kinematics.traction_laws import TRACTION_LAWS

#: Friction force of one contacting seal lip on the screw [N]: GUESS inside the makers' ranges of
#: seal resistance of linear-guide blocks (NB: 2–5 N; THK A-372: 2–43 N by size).
DEFAULT_SEAL_FORCE = 5.0


class FrictionSpec(Model):
    """Options of the friction torque of the nut (``ballscrew.analyses.friction``)."""

    model: model_choice(
        FRICTION_MODELS,
        "friction model: catalogue (makers' preload torque) or ball_model (physics ball losses)",
    ) = "catalogue"
    rolling_friction: Annotated[
        float,
        Field(
            ge=0.0,
            lt=1.0,
            description="effective friction coefficient μ of the efficiency η = tanλ/tan(λ+atan μ)"
            " (THK: 0.003)",
        ),
    ] = CATALOGUE_ROLLING_FRICTION
    seals: Annotated[int, Field(ge=0, le=8, description="contacting seals or wipers")] = 0
    seal_force: quantity(
        "force",
        "friction force of one seal lip, acting at the radius d_m/2 [GUESS 5 N]",
        ge=0,
        le=1e4,
    ) = DEFAULT_SEAL_FORCE
    seal_torque: (
        quantity("torque", "torque of one seal; None = seal_force × d_m/2", ge=0, le=1e3) | None
    ) = None
    hysteresis: Annotated[
        float,
        Field(
            ge=0.0,
            le=1.0,
            description="hysteresis loss fraction α of the Hertz contacts [GUESS 0.01]",
        ),
    ] = DEFAULT_HYSTERESIS
    recirculation_torque: quantity(
        "torque", "ball-return (recirculation) loss; no published model, default 0", ge=0, le=1e3
    ) = 0.0
    boundary_friction: (
        Annotated[float, Field(ge=0.0, le=1.0, description="μ_b of the ball model")] | None
    ) = Field(None, description="boundary friction of the ball model; None = [kinematics] value")
    traction: model_choice(
        TRACTION_LAWS,
        "traction law of the ball model at both contacts: film (JGP share, limiting shear) or "
        "skf (SKF sliding weighting φ_bl, μ_bl 0.15, μ_EHL 0.05)",
    ) = "film"
    ball_train: model_choice(
        BALL_TRAIN_MODELS,
        "contact force between adjacent balls (ball model): ratio (a given fraction of the "
        "ball load), return_push (the loaded balls push the return balls) or speed_spread "
        "(balls of different free orbital speeds push each other and the return; per-ball "
        "states from loads.distribution = elastic, identical balls otherwise)",
    ) = DEFAULT_BALL_TRAIN
    ball_ball_load_ratio: Annotated[
        float,
        Field(
            ge=0.0,
            le=1.0,
            description="contact force between adjacent balls / ball load, F_B/Q (ball model, "
            "ball_train = ratio) [GUESS 0.01]",
        ),
    ] = DEFAULT_BALL_BALL_LOAD_RATIO
    return_friction: Annotated[
        float,
        Field(
            ge=0.0,
            le=1.0,
            description="friction coefficient of a ball on the wall of the ball return "
            "(ball_train = return_push or speed_spread) [GUESS 0.1]",
        ),
    ] = DEFAULT_RETURN_FRICTION
    return_fraction: Annotated[
        float,
        Field(
            ge=0.0,
            le=10.0,
            description="balls in the return per loaded ball of a circuit "
            "(ball_train = return_push or speed_spread) [GUESS 0.2]",
        ),
    ] = DEFAULT_RETURN_FRACTION
    ball_ball_friction: Annotated[
        float,
        Field(ge=0.0, le=1.0, description="friction coefficient between balls μ_bb [GUESS 0.1]"),
    ] = DEFAULT_BALL_BALL_FRICTION
    lubricant_fill: Annotated[
        float,
        Field(
            ge=0.0,
            le=1.0,
            description="volume fraction of lubricant in the nut for the drag of the balls "
            "[GUESS 0.1]",
        ),
    ] = DEFAULT_LUBRICANT_FILL
    circuits: Annotated[
        int, Field(ge=1, le=64, description="ball circuits (returns) per nut [GUESS 2]")
    ] = DEFAULT_CIRCUITS
