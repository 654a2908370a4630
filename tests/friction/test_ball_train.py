"""Ball-train models of the contact force between adjacent balls: closed forms, the force
balance along the train, limits, and the models inside the friction torque."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.friction import BALL_TRAIN_MODELS
from ballscrew.friction.ball_train import (
    GRAVITY,
    BallTrain,
    TrainForces,
    ball_ball_force,
    return_resistance,
    train_forces,
)

# a 6.35 mm steel ball (1.05 g) in a 41.75 mm screw at about 1000 rpm
TRAIN = BallTrain(
    load=40.0,
    mass=1.05e-3,
    speed=1.1,
    path_radius=0.020875,
    loaded_balls=51.5,
    return_fraction=0.2,
    return_friction=0.1,
    drag_force=2e-3,
    load_ratio=0.01,
)


def test_registry_holds_the_guess_and_the_return_push():
    assert BALL_TRAIN_MODELS.names == ("ratio", "return_push", "speed_spread")
    with pytest.raises(InputError, match=r"^friction\.ball_train = 'nope'"):
        ball_ball_force("nope", TRAIN)


def test_ratio_model_is_the_given_fraction_of_the_ball_load():
    forces = ball_ball_force("ratio", TRAIN)
    assert forces.contact == pytest.approx(0.4, rel=1e-12) and forces.return_push == 0.0
    assert ball_ball_force("ratio", BallTrain(load=0.0)).contact == 0.0


def test_return_resistance_is_wall_friction_of_weight_and_bend_plus_drag():
    # 0.1 × 1.05 g × (9.80665 + 1.21/0.020875) + 2 mN, by hand
    assert return_resistance(TRAIN) == pytest.approx(
        0.1 * 1.05e-3 * (9.80665 + 1.21 / 0.020875) + 2e-3, rel=1e-12
    )
    at_rest = BallTrain(load=40.0, mass=1.05e-3, return_friction=0.1)
    assert return_resistance(at_rest) == pytest.approx(0.1 * 1.05e-3 * GRAVITY)
    frictionless = BallTrain(load=40.0, mass=1.05e-3, speed=3.0, return_friction=0.0)
    assert return_resistance(frictionless) == 0.0


def test_force_balance_along_a_closed_train():
    # 10 loaded balls share the push of 3 return balls, each resisting 0.2 N
    drives = np.array([0.06] * 10 + [-0.2] * 3)
    forces = train_forces(drives)
    assert np.diff(np.concatenate([[0.0], forces])) == pytest.approx(drives)  # C_i − C_(i−1) = T_i
    assert forces[9] == pytest.approx(0.6)  # the last loaded ball pushes the whole return
    assert forces[-1] == pytest.approx(0.0, abs=1e-15)  # slack behind the first loaded ball
    assert np.all(forces >= -1e-15)  # balls push, never pull
    with pytest.raises(ValueError, match="sum to"):
        train_forces(np.array([0.1, -0.05]))


@pytest.mark.parametrize("loaded", [1, 7, 52])
def test_return_push_is_the_mean_of_the_force_ramp_over_the_loaded_balls(loaded):
    train = BallTrain(
        load=40.0,
        mass=1e-3,
        speed=2.0,
        path_radius=0.02,
        loaded_balls=loaded,
        return_fraction=3.0 / loaded,
        return_friction=0.1,
    )
    f_r = return_resistance(train)
    drives = np.array([3 * f_r / loaded] * loaded + [-f_r] * 3)
    ramp = train_forces(drives)[:loaded]  # the leading contacts of the loaded balls
    forces = ball_ball_force("return_push", train)
    assert forces.contact == pytest.approx(float(np.mean(ramp)), rel=1e-12)
    assert forces.return_push == pytest.approx(3 * f_r, rel=1e-12)


def test_return_push_scales_with_the_return_and_vanishes_without_one():
    base = ball_ball_force("return_push", TRAIN).contact
    double = replace(TRAIN, return_fraction=0.4)
    assert ball_ball_force("return_push", double).contact == pytest.approx(2 * base)
    none = replace(TRAIN, return_fraction=0.0)
    assert ball_ball_force("return_push", none) == TrainForces(0.0, 0.0)
    # independent of the ball load: the push comes from the return, not the raceways
    heavy = replace(TRAIN, load=4000.0)
    assert ball_ball_force("return_push", heavy).contact == base


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({"return_friction": -0.1}, "friction.return_friction"),
        ({"mass": -1.0}, "ball_mass"),
        ({"path_radius": 0.0}, "return_path_radius"),
        ({"loaded_balls": 0.0}, "loaded_balls"),
        ({"return_fraction": math.nan}, "friction.return_fraction"),
    ],
)
def test_bad_train_inputs_name_the_field(change, field):
    with pytest.raises(InputError, match=rf"^{field} = "):
        ball_ball_force("return_push", replace(TRAIN, **change))
