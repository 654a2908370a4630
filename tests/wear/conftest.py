"""Fixtures of the wear tests: the reference case and a coarse, short variant of it."""

from __future__ import annotations

from pathlib import Path

import pytest

import ballscrew
from ballscrew.case import Case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
REF_PATH = EXAMPLES / "wear_step_stress.toml"
SPEED = 10.0 * 3.141592653589793 / 3.0  # 100 rpm [rad/s]


def short_programme(revolutions: float = 1.0e5) -> list[dict[str, object]]:
    """The three step-stress loads with ``revolutions`` each."""
    return [
        {"axial_load": load, "speed": SPEED, "revolutions": revolutions}
        for load in (2000.0, 3000.0, 4000.0)
    ]


@pytest.fixture(scope="session")
def ref_case() -> Case:
    """examples/wear_step_stress.toml: the wear reference screw and its step-stress
    programme, with the reference run's entrainment speed: the ball-centre speed V at the
    contact (the wear paper's simplification, E2.8), so that its published numbers hold."""
    return ballscrew.load_case(REF_PATH, {"kinematics.entrainment": "ball_centre"})


@pytest.fixture(scope="session")
def coarse_case() -> Case:
    """Reference case on a 12 × 48 grid, 1e5 rev per level, 2e4 rev torque sampling (fast)."""
    return ballscrew.load_case(
        REF_PATH,
        {
            "wear.grid": [12, 48],
            "wear.programme": short_programme(),
            "wear.torque_sampling": 2.0e4,
        },
    )
