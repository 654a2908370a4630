"""``friction.traction`` reaches every entry point that solves balls: the kinematics analysis,
the ball-model drag torque (thermal heat) and the friction analysis agree for one case."""

from __future__ import annotations

import math

import pytest

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_kinematics, computed_drag_torque

RPM = 2.0 * math.pi / 60.0
MIXED = 300.0 * RPM  # wear reference screw with σ_Λ = 50 nm: mixed under both laws (Λ ≈ 2.4)
# (film cap, boundary friction) of each traction law
LIMITS = {"film": (0.07, 0.1), "skf": (0.05, 0.15)}


def _case(path, law: str, level: int):
    return ballscrew.load_case(
        path,
        {
            "friction.model": "ball_model",
            "friction.traction": law,
            "operating.axial_load": 0.0,
            "kinematics.level": level,
            "tcr.rms_roughness": 50e-9,
            "tcr.rms_slope": 0.05,
        },
    )


def test_default_numbers_are_unchanged(gao_case_path, wear_case_path):
    # the film law's numbers before the traction law reached the kinematics (commit 4399cba), at
    # the entrainment speed of that time (the ball-centre speed V), with the JGP share on the
    # asperity heights of σ_Λ (E6.6) since; on the cell's σ (E5.3) the drag torques were
    # 0.11867 (gao, 1000 rpm) and 0.11369 N m (wear reference screw on its own raceway, 100 rpm)
    # and the Level-2 ball 0.094970 m/s, 12.7356 rad/s. The gao raceway's G is a profile G: its
    # asperities read the 3-D G of the same σ since surface.G_convention (drag torque 0.153082 N m
    # with the profile G read as a surface G); the wear screw gives its surface G (unchanged)
    old = {"kinematics.entrainment": "ball_centre"}
    gao = ballscrew.load_case(gao_case_path, old)
    state = ball_kinematics(gao)
    assert state.ball_speed == pytest.approx(0.9333272113362386, rel=1e-9)
    assert state.spin_screw == pytest.approx(73.81469929037536, rel=1e-9)
    assert computed_drag_torque(gao) == pytest.approx(0.15676986076780272, rel=1e-9)
    wear = ballscrew.load_case(
        wear_case_path,
        {
            "friction.model": "ball_model",
            "operating.axial_load": 0.0,
            "kinematics.level": 2,
            **old,
        },
    )
    assert computed_drag_torque(wear, 100.0 * RPM) == pytest.approx(0.12312884190315768, rel=1e-9)
    state = ball_kinematics(wear, 100.0 * RPM)
    assert state.ball_speed == pytest.approx(0.09513755169333539, rel=1e-9)
    assert state.spin_screw == pytest.approx(13.1421858901018, rel=1e-9)


@pytest.mark.parametrize("level", [1, 2])
def test_kinematics_and_friction_give_one_torque_under_skf(wear_case_path, level):
    torques = {}
    for law in ("film", "skf"):
        case = _case(wear_case_path, law, level)
        friction = friction_torque(case, speed=MIXED)
        # mixed in the traction: the asperity share ψ lies between 0 and 1
        assert LIMITS[law][0] < friction.traction_coefficient < LIMITS[law][1]
        # sliding at A and EHL rolling at A and B: the dissipation of the ball-model drag
        balls = friction.parts["sliding"] + friction.parts["ehl_rolling"]
        torques[law] = computed_drag_torque(case, MIXED)
        assert torques[law] == pytest.approx(balls, rel=1e-9)
    # SKF μ_sl ≈ 0.1 against the film law's lower mixed-regime coefficient
    assert torques["skf"] > 1.03 * torques["film"]


def test_skf_law_moves_the_level_2_ball(wear_case_path):
    film, skf = (ball_kinematics(_case(wear_case_path, law, 2), MIXED) for law in ("film", "skf"))
    assert skf.traction_screw.power_loss > 1.03 * film.traction_screw.power_loss
    assert skf.spin_screw != pytest.approx(film.spin_screw, rel=1e-6)
